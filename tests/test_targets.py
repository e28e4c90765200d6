"""Several targets (issue 44, docs/model.md, Several targets): the engine against the slow
reference, one target bit for bit what it was, the mission's events from the targets', and
bad input."""

from __future__ import annotations

import hashlib
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from naive import mission_event, simulate_naive
from sarlink import ConfigError, Mission, simulate
from sarlink.cli import app
from sarlink.config import mission_hash
from sarlink.engine import many
from sarlink.engine.codes import SUCCESS_CODES
from sarlink.metrics import summarize
from sarlink.simulation import prepare
from sarlink.storage import run_table

BASE = {"drones": 4, "rc": 1000.0, "horizon": 600.0, "count": 3}
CASES = {  # a distributed rule with targets that stand and that walk, a route planner (one
    # rule: the kernel's targets are the same code under every rule, and each kernel of several
    # targets compiles for minutes; the walking one is the first-target test's below)
    "covb-still": {"planner": "covb"},
    "covb-walk-first": {"planner": "covb", "motion": "walk", "walk_speed": 2.0,
                        "delay": 60.0, "success": "first"},
    "parallel-still": {"planner": "parallel"},
}
RUNS = 6


def _times(values: np.ndarray) -> list[float | None]:
    return [None if math.isnan(v) else float(v) for v in values.tolist()]


@pytest.mark.parametrize("case", CASES)
def test_several_targets_agree_with_the_reference(case: str) -> None:
    """K = 3 targets flown by the kernel and by tests/naive.py: where the two fly every
    drone and every target the same (the others are knife edges, tests/test_reference.py),
    each target's detection, notification and detector and the mission's events agree."""
    mission = Mission.build(**BASE, **CASES[case])  # type: ignore[arg-type]
    routes = prepare(mission).steering.routes
    same = 0
    for k in range(RUNS):
        fast = simulate(mission, seed=2024, run=k, trajectory=True)
        slow = simulate_naive(mission, 2024, k, record=True, routes=routes)
        assert fast.targets is not None and slow.targets is not None
        np.testing.assert_allclose(fast.targets, np.array(slow.targets), rtol=0, atol=1e-9)
        assert fast.trajectory is not None
        if mission.target.motion != "still":
            assert fast.trajectory.target is not None and slow.tracks is not None
            np.testing.assert_allclose(fast.trajectory.target, np.array(slow.tracks),
                                       rtol=0.0, atol=1e-6)
        if not np.allclose(fast.trajectory.positions, np.array(slow.positions), rtol=0.0,
                           atol=1e-6):
            continue
        same += 1
        assert fast.t_detect_each is not None and fast.t_notify_each is not None
        assert _times(fast.t_detect_each) == slow.t_detect_each
        assert _times(fast.t_notify_each) == slow.t_notify_each
        assert fast.detector_each is not None
        assert fast.detector_each.tolist() == slow.detector_each
        assert (fast.t_detect, fast.t_notify) == (slow.t_detect, slow.t_notify)
        assert (-1 if fast.detector is None else fast.detector) == slow.detector
    assert same >= RUNS - 2


STILL_BEFORE = [  # covb, 4 drones, 300 s, seed 3: main at 36d00d6 (tests/test_target_motion)
    (None, None, "3ee8ed96d10f358896b3769d80260fe38da91efee95bb456f76ff1f4e75dd027"),
    (52.0, 52.0, "a659cdb952a48eb8546d556e5f75d3037e6bbd05818c6bfbc33e6a699dc9cac5"),
    (263.0, None, "5e6a986f63b21c46961cf2b803bb0fd4ef5b1feafb1c52a750c93476338c372e"),
]


def test_one_target_flies_the_runs_of_before() -> None:
    """``count = 1`` under either success gives the runs stored before several targets,
    with no per-target fields, and hashes as the mission without the new fields."""
    plain = Mission.build(planner="covb", drones=4, horizon=300.0)
    for success in ("all", "first"):
        one = plain.replace(count=1, success=success)
        for run, (t_detect, t_notify, positions) in enumerate(STILL_BEFORE):
            got = simulate(one, seed=3, run=run, trajectory=True)
            assert (got.t_detect, got.t_notify) == (t_detect, t_notify)
            assert got.trajectory is not None
            assert hashlib.sha256(got.trajectory.positions.tobytes()).hexdigest() == positions
            assert got.targets is None and got.t_detect_each is None
            assert got.row() == simulate(plain, seed=3, run=run).row()
    assert mission_hash(plain.replace(count=1, success="all")) == mission_hash(plain)
    assert mission_hash(plain.replace(count=2)) != mission_hash(plain)


def test_the_first_target_is_the_one_target_of_the_mission() -> None:
    """With sure looks and CovB (which flies the same whoever knows what), target 1 of three
    walks as the one walking target of the same run does, and is found and reported when it
    is: the others' draws come from a stream of their own."""
    one = Mission.build(planner="covb", drones=4, horizon=600.0, motion="walk", delay=60.0,
                        walk_speed=2.0)
    three = one.replace(count=3)
    for run in range(4):
        a = simulate(one, seed=5, run=run, trajectory=True)
        b = simulate(three, seed=5, run=run, trajectory=True)
        assert b.targets is not None and b.t_detect_each is not None
        assert b.t_notify_each is not None
        assert tuple(b.targets[0]) == a.target
        assert a.trajectory is not None and b.trajectory is not None
        assert a.trajectory.target is not None and b.trajectory.target is not None
        assert (b.trajectory.target[:, 0] == a.trajectory.target[:, 0]).all()
        assert (b.trajectory.positions == a.trajectory.positions).all()
        assert _times(b.t_detect_each[:1]) == [a.t_detect]
        assert _times(b.t_notify_each[:1]) == [a.t_notify]


@settings(max_examples=25, deadline=None)
@given(count=st.integers(2, 4), success=st.sampled_from(["all", "first"]),
       run=st.integers(0, 10_000), p_miss=st.sampled_from([0.0, 0.5]))
def test_the_missions_events_are_the_first_or_last_of_the_targets(
        count: int, success: str, run: int, p_miss: float) -> None:
    """The mission's detection and notification are the earliest (first) or the latest, once
    every target has one (all), of the targets'; no target is notified before it is
    detected; the counts of found and told targets are those times'."""
    mission = Mission.build(planner="covb", drones=4, horizon=600.0, rc=1000.0, count=count,
                            success=success, p_miss=p_miss)
    got = simulate(mission, seed=11, run=run)
    det, note = got.t_detect_each, got.t_notify_each
    assert det is not None and note is not None and got.detector_each is not None
    for j in range(count):
        if math.isnan(det[j]):
            assert math.isnan(note[j]) and got.detector_each[j] == -1
        else:
            assert math.isnan(note[j]) or note[j] >= det[j]
    for mine, each in ((got.t_detect, det), (got.t_notify, note)):
        if success == "first":
            expected = None if np.isnan(each).all() else float(np.nanmin(each))
        else:
            expected = None if np.isnan(each).any() else float(each.max())
        assert mine == expected
    assert got.found() == int(np.isfinite(det).sum())
    assert got.told() == int(np.isfinite(note).sum())
    assert got.immediate == (got.t_notify is not None and got.t_notify == got.t_detect)


@given(times=st.lists(st.one_of(st.none(), st.integers(0, 5).map(float)), min_size=1,
                      max_size=6), success=st.sampled_from(["all", "first"]))
def test_the_kernels_choice_of_event_is_the_references(times: list[float | None],
                                                        success: str) -> None:
    """The kernel's pick of the target whose time is the mission's, ties and all."""
    kernel = many.event(np.array([-1.0 if t is None else t for t in times]),
                        int(SUCCESS_CODES[success]))
    assert (None if kernel < 0 else kernel) == mission_event(times, success)


def test_several_targets_are_stored_and_summarized_per_target() -> None:
    """A run table of K = 3 keeps each target's position and events as list columns, and
    summarize counts the targets found and told within each t_d from them."""
    mission = Mission.build(planner="covb", drones=4, horizon=600.0, count=3)
    results = [simulate(mission, seed=1, run=k) for k in range(4)]
    table = run_table(mission, 1, results)
    columns = table.to_pydict()
    for k, r in enumerate(results):
        assert r.targets is not None and r.t_detect_each is not None
        assert columns["target_x_each"][k] == r.targets[:, 0].tolist()
        got = columns["t_detect_each"][k]
        assert [None if math.isnan(v) else v for v in got] == _times(r.t_detect_each)
    for td in (150.0, 600.0):
        row = summarize(table.to_pandas(), td=td, by=[]).iloc[0]
        assert row["found"] == pytest.approx(np.mean([r.found(td) for r in results]))
        assert row["told"] == pytest.approx(np.mean([r.told(td) for r in results]))
    one = Mission.build(planner="covb", drones=4, horizon=600.0)
    plain = run_table(one, 1, [simulate(one, seed=1, run=0)]).to_pandas()
    assert "found" not in summarize(plain, by=[]).columns


@pytest.mark.parametrize(("params", "expected"), [
    ({"count": 0}, "target.count: Input should be greater than or equal to 1 (got 0)"),
    ({"count": 1.5}, "target.count: Input should be a valid integer (got 1.5)"),
    ({"success": "most"}, "target.success: Input should be 'all' or 'first' (got 'most')"),
    ({"count": 3, "on_detect": "relay"}, "team.on_detect = 'relay' follows one target; with "
     "target.count = 3 it must be 'continue' (docs/model.md, Several targets)"),
])
def test_bad_input_is_one_line(params: dict[str, object], expected: str) -> None:
    with pytest.raises(ConfigError) as info:
        Mission.build(**params)  # type: ignore[arg-type]
    assert str(info.value) == expected


def test_the_cli_flies_several_walking_targets_and_refuses_none() -> None:
    """``simulate --targets 3 --target-motion walk --json``: each target's position and
    events; ``--targets 0``: one line naming what was typed."""
    runner = CliRunner()
    args = ["simulate", "--targets", "3", "--target-motion", "walk", "--drones", "4",
            "--td", "600", "--json"]
    out = runner.invoke(app, args)
    assert out.exit_code == 0, out.output
    got = json.loads(out.output)
    assert got["success"] == "all" and len(got["targets"]) == 3
    assert len(got["t_detect_each"]) == len(got["t_notify_each"]) == 3
    assert len(got["targets_at_end"]) == 3
    assert got["found"] == sum(t is not None for t in got["t_detect_each"])
    bad = runner.invoke(app, ["simulate", "--targets", "0"])
    assert bad.exit_code != 0
    lines = [line for line in bad.output.splitlines() if line.strip()]
    assert len(lines) == 1 and "target.count" in lines[0] and "(got 0)" in lines[0], bad.output


def test_replays_and_plots_draw_every_target(tmp_path) -> None:
    """Three walking targets: the replay's frames hold every track (float32) and decode to
    them, its scene names where the others were last seen and when each was found, and
    ``--plot``'s figure draws the others."""
    import matplotlib

    matplotlib.use("Agg")
    from sarlink.playback import replay
    from sarlink.playback.encoding import decode, encode
    from sarlink.playback.scene import scene
    from sarlink.plots.run import plot_run

    mission = Mission.build(planner="covb", drones=4, horizon=600.0, motion="walk",
                            delay=60.0, walk_speed=2.0, count=3)
    result = simulate(mission, seed=5, run=1, trajectory=True)
    traj = result.trajectory
    assert traj is not None and traj.target is not None and traj.target.shape[1] == 3
    back = decode(encode(traj)).target
    assert back is not None and back.shape == traj.target.shape
    np.testing.assert_allclose(back, traj.target, rtol=1e-6, atol=1e-3)
    panel = scene(result, mission)
    assert result.targets is not None and result.t_detect_each is not None
    assert panel["others"] == result.targets[1:].tolist()
    assert panel["othersDetect"] == _times(result.t_detect_each[1:])
    replay(result, mission).write(tmp_path / "three.html")
    labels = plot_run(result, mission).get_legend_handles_labels()[1]
    assert "the other targets" in labels


def test_a_design_for_several_targets_tries_drones_that_continue() -> None:
    """``sarlink design`` with several targets: the default options leave out reporting
    (refused with several); one target keeps both."""
    from sarlink.design.request import DesignRequest

    three = Mission.build(count=3)
    request = DesignRequest.from_dict({"mission": three, "td": 1800.0, "ps": 0.9})
    assert request.options == {"on_detect": ["continue"]}
    one = DesignRequest.from_dict({"mission": Mission(), "td": 1800.0, "ps": 0.9})
    assert one.options == {"on_detect": ["continue", "report"]}
