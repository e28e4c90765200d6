"""The replay's encoding, events and page, and the commands that write it (no browser here)."""

from __future__ import annotations

import html
import json
import re

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from typer.testing import CliRunner

import sarlink
from sarlink import Mission, Trajectory, planner_names, simulate
from sarlink.cli import app
from sarlink.engine.codes import Mode
from sarlink.playback import compare, replay
from sarlink.playback.encoding import (
    HEADING_LEVELS,
    decode,
    encode,
    frame_bytes,
    position_error_bound,
)
from sarlink.playback.events import events

runner = CliRunner()


@pytest.fixture(scope="module")
def shadowed():
    """ConB with shadowing (reading sarlink-1): detected at 3337 s, the BS told 35 s later,
    then drones return."""
    mission = Mission.build(reading="sarlink-1", planner="conb", drones=10, rc=500.0, sigma=3.0)
    return simulate(mission, seed=3, run=2, trajectory=True), mission


def _assert_same(decoded: Trajectory, traj: Trajectory, keep: np.ndarray, enc) -> None:
    np.testing.assert_array_equal(decoded.t, traj.t[keep])
    error = np.abs(decoded.positions - traj.positions[keep])
    bound = position_error_bound(enc, float(np.abs(traj.positions).max()))
    assert (error <= bound).all()
    turn = np.angle(np.exp(1j * (decoded.headings - traj.headings[keep])))
    assert np.abs(turn).max() <= np.pi / HEADING_LEVELS * (1 + 1e-9)
    np.testing.assert_array_equal(decoded.mode, traj.mode[keep])
    np.testing.assert_array_equal(decoded.knows, traj.knows[keep])
    np.testing.assert_array_equal(decoded.bs_route, traj.bs_route[keep])
    np.testing.assert_array_equal(decoded.links, traj.links[keep])


def test_a_run_round_trips_within_the_stated_precision(shadowed) -> None:
    result, mission = shadowed
    traj = result.trajectory
    enc = encode(traj)
    assert enc.stride == 1 and enc.frames == len(traj.t)
    assert max(enc.quantum) <= mission.area.size / 65535
    # in a mission's area the rounding term is negligible: the bound is half a grid step
    half = np.array(enc.quantum) / 2
    assert (position_error_bound(enc, mission.area.size) <= half * (1 + 1e-9)).all()
    _assert_same(decode(enc), traj, np.arange(len(traj.t)), enc)


def test_over_the_budget_every_stride_th_step_and_the_last_are_kept(shadowed) -> None:
    traj = shadowed[0].trajectory
    budget = 200 * frame_bytes(traj.positions.shape[1])
    enc = encode(traj, budget)
    keep = np.append(np.arange(0, len(traj.t), enc.stride), len(traj.t) - 1)
    assert enc.stride == 21 and enc.frames == len(keep)
    _assert_same(decode(enc), traj, keep, enc)


def _trajectory(positions: np.ndarray, seed: int) -> Trajectory:
    rng = np.random.default_rng(seed)
    steps, drones = positions.shape[:2]
    links = rng.random((steps, drones + 2, drones + 2)) < 0.3
    links = np.triu(links, 1)
    return Trajectory(
        t=np.arange(steps) * 0.5, positions=positions,
        headings=rng.uniform(-10, 10, (steps, drones)),
        knows=rng.random((steps, drones)) < 0.5, bs_route=rng.random((steps, drones)) < 0.5,
        mode=rng.integers(0, len(Mode), (steps, drones)).astype(np.int8),
        links=links | links.transpose(0, 2, 1))


@given(steps=st.integers(1, 30), drones=st.integers(1, 9),
       low=st.floats(-1e5, 1e5), span=st.sampled_from([0.0, 1e-3, 1.0, 4000.0, 1e6]),
       seed=st.integers(0, 2**32 - 1))
def test_any_trajectory_round_trips(steps, drones, low, span, seed) -> None:
    rng = np.random.default_rng(seed)
    positions = low + span * rng.random((steps, drones, 2))
    traj = _trajectory(positions, seed)
    enc = encode(traj)
    _assert_same(decode(enc), traj, np.arange(steps), enc)


def test_events_are_the_run_s_detection_notification_and_mode_changes(shadowed) -> None:
    result, _ = shadowed
    traj = result.trajectory
    found = events(result)
    assert [e.t for e in found] == sorted(e.t for e in found)
    by_kind = {e.kind: e for e in found if e.kind in ("detect", "notify")}
    assert by_kind["detect"].t == result.t_detect and by_kind["detect"].drone == result.detector
    assert by_kind["notify"].t == result.t_notify
    assert "35 s after detection" in by_kind["notify"].text
    changes = {(e.drone, e.t, e.kind) for e in found if e.drone is not None and e.kind != "detect"}
    expected = set()
    for i in range(traj.mode.shape[1]):
        for k in range(1, len(traj.t)):
            if traj.mode[k, i] != traj.mode[k - 1, i]:
                expected.add((i, traj.t[k], Mode(traj.mode[k, i]).name.lower()))
    assert changes == expected
    assert {kind for _, _, kind in expected} == {"returning", "landed"}


def _data(page: str) -> dict:
    block = re.search(r'<script type="application/json" id="sarlink-data">(.*?)</script>',
                      page, re.S)
    assert block is not None
    return json.loads(block.group(1))


def test_the_page_is_self_contained_and_holds_the_run(shadowed) -> None:
    result, mission = shadowed
    page = replay(result, mission, title="a </script> title").html()
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", page)
    assert page.count("</script>") == 2
    data = _data(page)
    assert data["title"] == "a </script> title"
    assert [m["name"] for m in data["modes"]] == [m.name.lower() for m in Mode]
    (panel,) = data["panels"]
    assert (panel["tDetect"], panel["tNotify"]) == (result.t_detect, result.t_notify)
    assert panel["target"] == list(result.target) and panel["tours"] == []


def test_compare_flies_the_same_run_with_each_planner_and_draws_mtsp_tours() -> None:
    mission = Mission.build(drones=8, rc=500.0, stop="notified")
    page = compare(mission, ["covb", "mtsp-conb"], seed=3, run=0)
    assert [p.mission.team.planner for p in page.panels] == ["covb", "mtsp-conb"]
    for p in page.panels:
        again = simulate(p.mission, seed=3, run=0)
        assert (p.result.target, p.result.t_notify) == (again.target, again.t_notify)
    panels = _data(page.html())["panels"]
    routes = sarlink.get_planner("mtsp-conb").steering(page.panels[1].mission).routes
    assert len(panels[1]["tours"]) == sum(len(r) > 0 for r in routes) == mission.team.nr
    assert panels[1]["tours"][0][0] == [2000.0, 2000.0]


def test_a_replay_displays_itself_in_jupyter(shadowed) -> None:
    page = replay(*shadowed)
    shown = re.fullmatch(r'<iframe srcdoc="([^"]*)" style="[^"]*"></iframe>', page._repr_html_())
    assert shown is not None and html.unescape(shown.group(1)) == page.html()


def test_replay_needs_a_trajectory() -> None:
    mission = Mission.build(drones=2, horizon=10.0)
    with pytest.raises(ValueError, match="trajectory=True"):
        replay(simulate(mission, seed=0), mission)


def test_cli_replay_writes_the_comparison(tmp_path) -> None:
    out = tmp_path / "compare.html"
    res = runner.invoke(app, ["replay", "--planners", "covb,conb", "--drones", "4", "--rc", "500",
                              "--td", "600", "--seed", "1", "--run", "0", "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert "CovB:" in res.stdout and "ConB:" in res.stdout and "replay written" in res.stdout
    assert [p["planner"] for p in _data(out.read_text())["panels"]] == ["covb", "conb"]


def test_cli_simulate_writes_a_replay(tmp_path) -> None:
    out = tmp_path / "mission.html"
    res = runner.invoke(app, ["simulate", "--planner", "conb", "--drones", "3", "--td", "300",
                              "--html", str(out), "--json"])
    assert res.exit_code == 0, res.output
    (panel,) = _data(out.read_text())["panels"]
    assert panel["planner"] == "conb" and panel["end"] == 300.0


@pytest.mark.parametrize(("args", "message"), [
    (["--planners", "covb,foo"], f"planners must be among {', '.join(planner_names())}; "
                                 "got 'foo'"),
    (["--planners", ","], "got none"),
    (["--rc", "-5"], "channel.rc"),
])
def test_cli_replay_bad_input_is_one_line_and_exit_2(tmp_path, args, message) -> None:
    res = runner.invoke(app, ["replay", *args, "--out", str(tmp_path / "x.html")])
    assert res.exit_code == 2
    assert message in res.output and "Traceback" not in res.output
    assert len(res.output.strip().splitlines()) == 1
    assert not (tmp_path / "x.html").exists()
