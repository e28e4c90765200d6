"""The ``sarlink`` command line, driven as a user would."""

from __future__ import annotations

import fcntl
import json
import os
import select
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
from typer.testing import CliRunner

from sarlink import Mission, simulate
from sarlink.cli import app

runner = CliRunner()


def test_simulate_json_reports_the_run_of_the_api() -> None:
    out = runner.invoke(app, ["simulate", "--planner", "concov", "--drones", "10", "--rc", "1000",
                              "--seed", "7", "--alpha", "0.3", "--td", "3000", "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    expected = simulate(Mission.build(planner="concov", drones=10, rc=1000.0, alpha=0.3,
                                      horizon=3000.0), seed=7)
    assert data["t_detect"] == expected.t_detect
    assert data["t_notify"] == expected.t_notify
    assert data["immediate"] is expected.immediate
    assert data["t_reachable"] == expected.t_reachable()
    # the BS's network, over the run's checkpoints
    assert data["depth_max"] == max(expected.depth) >= 1
    assert data["farthest_max"] == max(expected.farthest) > 0


def test_simulate_json_has_null_when_nothing_happened() -> None:
    out = runner.invoke(app, ["simulate", "--planner", "covb", "--drones", "1", "--td", "10",
                              "--seed", "1", "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    assert data["t_notify"] is None and data["immediate"] is False


def test_simulate_summary_and_plot(tmp_path) -> None:
    png = tmp_path / "mission.png"
    out = runner.invoke(app, ["simulate", "--planner", "conb", "--plot", str(png)])
    assert out.exit_code == 0, out.output
    assert "BS notified at" in out.stdout and "ConB" in out.stdout
    assert "BS's network, deepest" in out.stdout and "farthest connected drone" in out.stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_simulate_with_relays_reports_them_and_draws_their_legs(tmp_path) -> None:
    """The issue's command: the JSON is the API's run of the team with relays, the summary
    names them, and the figure draws each relay's legs in the relaying mode apart."""
    flags = ["simulate", "--planner", "covb", "--drones", "8", "--relays", "3", "--rc", "500"]
    out = runner.invoke(app, [*flags, "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    mission = Mission.build(planner="covb", drones=8, relays=3, rc=500.0)
    expected = simulate(mission, trajectory=True)
    assert (data["drones"], data["relays"]) == (8, 3)
    assert (data["t_detect"], data["t_notify"], data["connected_fraction"]) == (
        expected.t_detect, expected.t_notify, expected.connected_fraction())
    png = tmp_path / "relays.png"
    out = runner.invoke(app, [*flags, "--plot", str(png)])
    assert "CovB: 8 drones, 3 of them relays, r_c = 500 m" in out.stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    import matplotlib.pyplot as plt

    from sarlink.engine.codes import Mode
    from sarlink.plots import plot_run

    ax = plot_run(expected, mission)
    traj = expected.trajectory
    assert traj is not None and "N = 8 (3 relays)" in ax.get_title()
    legs = [line for line in ax.get_lines() if line.get_label() == "relays, holding the link"]
    (first,) = legs  # one legend entry for the three
    relaying = traj.mode[:, 5] == Mode.RELAYING
    assert relaying.any() and not relaying.all()  # it flies home at the end of its budget
    drawn = np.asarray(first.get_xydata())
    np.testing.assert_array_equal(np.isnan(drawn[:, 0]), ~relaying)
    np.testing.assert_array_equal(drawn[relaying], traj.positions[relaying, 5])
    plt.close(ax.figure)


def test_simulate_reads_a_mission_file_and_flags_override_it(tmp_path) -> None:
    cfg = tmp_path / "m.toml"
    cfg.write_text('[team]\nplanner = "conb"\ndrones = 4\n[timing]\nhorizon = 500\n')
    out = runner.invoke(app, ["simulate", "--config", str(cfg), "--drones", "5", "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    assert (data["planner"], data["drones"], data["td"]) == ("conb", 5, 500.0)


def test_bad_input_is_one_clear_line_and_exit_code_2() -> None:
    out = runner.invoke(app, ["simulate", "--drones", "0"])
    assert out.exit_code == 2
    assert "team.drones" in out.output and "greater than or equal to 1" in out.output
    assert "Traceback" not in out.output


def test_simulate_stopped_at_notification_reports_null_reachability() -> None:
    flags = ["simulate", "--planner", "covb", "--drones", "10", "--rc", "2000", "--seed", "2"]
    full = json.loads(runner.invoke(app, [*flags, "--json"]).stdout)
    out = runner.invoke(app, [*flags, "--stop", "notified", "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    assert data["t_notify"] == full["t_notify"] is not None
    assert data["t_reachable"] is None and full["t_reachable"] > 0
    summary = runner.invoke(app, [*flags, "--stop", "notified"])
    assert "not recorded (the run stopped when notified)" in summary.stdout


def test_a_long_error_stays_one_line_when_stderr_is_not_a_terminal() -> None:
    out = runner.invoke(app, ["simulate", "--planner", "mtsp", "--drones", "100"])
    assert out.exit_code == 2
    line = next(t for t in out.output.splitlines() if t.startswith("error:"))
    assert len(line) > 80 and line.endswith("got 100")


def test_output_into_a_closed_pipe_ends_quietly() -> None:
    """``sarlink reproduce --help | head``: the reader leaves while sarlink writes, and
    sarlink stops without an error line. The pipe holds one page, less than the help, so
    sarlink waits on a write once it is full; the reader closes it then."""
    read, write = os.pipe()
    fcntl.fcntl(read, fcntl.F_SETPIPE_SZ, 4096)
    child = subprocess.Popen([str(Path(sys.executable).parent / "sarlink"), "reproduce",
                              "--help"], stdout=write, stderr=subprocess.PIPE, text=True)
    os.close(write)
    assert select.select([read], [], [], 60)[0]
    time.sleep(1)  # sarlink has filled the pipe and waits to write the rest
    assert child.poll() is None
    os.close(read)
    stderr = child.communicate(timeout=60)[1]
    assert stderr == ""
    assert child.returncode == 1


def test_a_single_simulation_does_not_load_pandas() -> None:
    """``import sarlink`` and the CLI leave the sweep layer's pandas and pyarrow for later."""
    code = ("import sys, sarlink, sarlink.cli\n"
            "assert 'pandas' not in sys.modules and 'pyarrow' not in sys.modules\n"
            "assert sarlink.sweep.__module__ == 'sarlink.execution'\n"
            "assert 'pandas' in sys.modules\n")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_plugins_lists_every_kind_and_planners_is_the_same_listing() -> None:
    from sarlink.registry import KINDS

    text = runner.invoke(app, ["plugins"])
    assert text.exit_code == 0, text.output
    for registry in KINDS.values():
        assert f"{registry.plural} ({registry.group})" in text.output
    assert "relay strategies (sarlink.relays)" in text.output
    data = json.loads(runner.invoke(app, ["plugins", "--json"]).output)
    assert data.keys() == {f"{kind}s" for kind in KINDS} | {"broken"}
    assert [p["name"] for p in data["planners"]][:5] == ["mtsp", "covb", "conb", "mtsp-conb",
                                                         "concov"]
    assert {r["name"]: r["origin"] for r in data["radios"]} == {"disc": "sarlink",
                                                                "shadowing": "sarlink"}
    assert data["relays"] == [{"name": "tree", "origin": "sarlink"}]
    assert json.loads(runner.invoke(app, ["planners", "--json"]).output) == data
