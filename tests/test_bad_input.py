"""Every bad input gets one line on stderr naming what was wrong and what is allowed, exit
status 2, and no traceback; nothing finished is lost (issue 16).

The table drives the whole ``sarlink`` app as a user would. ``{d}`` in an argument is a folder
holding the files of :data:`FILES` and the results folders of :func:`workspace`.
"""

from __future__ import annotations

import errno
import fcntl
import json
import sys
from pathlib import Path

import pandas as pd
import pytest
from typer.testing import CliRunner

import sarlink.storage as storage
from sarlink import Experiment, load, planner_names
from sarlink.cli import app
from sarlink.storage import MANIFEST, open_store

runner = CliRunner()

OK = "seed = 1\nruns = 2\n[mission.timing]\nhorizon = 50\n[grid]\nplanner = ['covb', 'conb']\n"

FILES = {
    "ok.toml": OK,
    "binary.toml": b"\xff\xfe\x00 not text",
    "dup.toml": "[team]\ndrones = 3\ndrones = 4\n",
    "bool.toml": "[team]\ndrones = true\n",
    "float.toml": "[team]\ndrones = 2.0\n",
    "string.toml": "[team]\ndrones = 'ten'\n",
    "extra.toml": "[team]\nfoo = 1\n",
    "flat.toml": "drones = 3\n",
    "nan.toml": "[channel]\nrc = nan\n",
    "inf.toml": "[team]\nspeed = inf\n",
    "huge.toml": "[timing]\nhorizon = 1e300\n",
    "bs.toml": "[area]\nbs = [5000, 0]\n",
    "notable.toml": "team = 3\n",
    "drift.toml": "[target]\nmotion = 'drift'\ndrift_current = [[0, 0.1, 0], [600, 0.2]]\n",
    "griddrift.toml": "seed = 1\nruns = 1\n[grid]\ndrift_wind = [[8, 6], [[0, 8, 6], [0, 9, 0]]]\n",
    "records.toml": "[timing]\nhorizon = 4000000\ncheckpoint = 1\n",
    "noseed.toml": "runs = 2\n",
    "runs0.toml": "seed = 1\nruns = 0\n",
    "runsfloat.toml": "seed = 1\nruns = 2.5\n",
    "seedbig.toml": "seed = 9223372036854775807\nruns = 1\n[grid]\nseed = [1]\n",
    "seedneg.toml": "seed = -1\nruns = 1\n",
    "seedhuge.toml": "seed = 99999999999999999999\nruns = 1\n",
    "chunk0.toml": "seed = 1\nruns = 1\nchunk = 0\n",
    "noname-ok.toml": "name = ''\nseed = 1\nruns = 1\n",
    "gridunknown.toml": "seed = 1\nruns = 1\n[grid]\ndrone = [1]\n",
    "gridempty.toml": "seed = 1\nruns = 1\n[grid]\ndrones = []\n",
    "gridnotlist.toml": "seed = 1\nruns = 1\n[grid]\ndrones = 5\n",
    "gridbad.toml": "seed = 1\nruns = 1\n[grid]\nrc = [500, -1]\n",
    "gridnan.toml": "seed = 1\nruns = 1\n[grid]\np_miss = [nan]\n",
    "griddup.toml": "seed = 1\nruns = 1\n[grid]\ndrones = [2, 2]\n",
    "gridhuge.toml": "seed = 1\nruns = 1\n[grid]\nrc = " + str(list(range(1, 1001)))
                     + "\nalpha = " + str([k / 1000 for k in range(0, 1000)]) + "\n",
    "missionextra.toml": "seed = 1\nruns = 1\n[mission]\ndrones = 3\n",
    "missionbad.toml": "seed = 1\nruns = 1\n[mission.team]\nplanner = 'astar'\n",
    "afile": "not a folder\n",
}


@pytest.fixture(scope="module")
def workspace(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The files of :data:`FILES` and results folders damaged in every way the table needs."""
    d = tmp_path_factory.mktemp("bad-input")
    for name, content in FILES.items():
        path = d / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)
    (d / "afolder.png").mkdir()
    exp = Experiment.from_toml(d / "ok.toml")
    for name in ("empty", "truncated", "newer", "listed", "keyless", "other", "pointsfile",
                 "lockdir"):
        with open_store(d / name, exp.model_copy(update={"seed": 2}) if name == "other"
                        else exp):
            pass
    manifest = (d / "truncated" / MANIFEST).read_text()
    (d / "truncated" / MANIFEST).write_text(manifest[: len(manifest) // 2])
    newer = json.loads(manifest) | {"format": 2, "sarlink": "9.0.0"}
    (d / "newer" / MANIFEST).write_text(json.dumps(newer))
    (d / "listed" / MANIFEST).write_text("[]")
    (d / "keyless" / MANIFEST).write_text(json.dumps({"format": 1}))
    (d / "pointsfile" / "points").write_text("")
    (d / "lockdir" / ".lock").unlink()
    (d / "lockdir" / ".lock").mkdir()
    return d


ROWS: list[tuple[list[str], list[str]]] = [
    # -- simulate: options ------------------------------------------------------------------
    (["simulate", "--td", "0"], ["--td (timing.horizon)", "greater than 0", "got 0.0"]),
    (["simulate", "--td", "nan"], ["--td", "finite number"]),
    (["simulate", "--td", "inf"], ["--td", "finite number"]),
    (["simulate", "--td", "10.5"], ["--td", "multiple of timing.dt"]),
    (["simulate", "--td", "1e12"], ["--td", "at most 10,000,000 steps"]),
    (["simulate", "--drones", "0"], ["--drones (team.drones)", "greater than or equal to 1"]),
    (["simulate", "--drones", "5000"], ["--drones", "less than or equal to 1000"]),
    (["simulate", "--drones", "abc"], ["'--drones'", "valid integer", "sarlink simulate --help"]),
    (["simulate", "--rc", "-1"], ["--rc (channel.rc)", "greater than 0"]),
    (["simulate", "--alpha", "2"], ["--alpha", "less than or equal to 1"]),
    (["simulate", "--p-miss", "1.5"], ["--p-miss (sensing.p_miss)", "less than or equal to 1"]),
    (["simulate", "--shadowing-sigma", "31"], ["--shadowing-sigma (channel.sigma)", "30"]),
    (["simulate", "--pathloss-exponent", "0"], ["--pathloss-exponent", "greater than 0"]),
    (["simulate", "--look", "sometimes"], ["--look (sensing.look)", "'per-pass'"]),
    (["simulate", "--stop", "never"], ["--stop (timing.stop)", "'horizon'"]),
    (["simulate", "--planner", "astar"], ["--planner (team.planner)",
                                          ", ".join(planner_names())]),
    (["simulate", "--nr", "0"], ["--nr (team.nr)", "greater than or equal to 1"]),
    (["simulate", "--r", "0"], ["--r (sensing.r)", "greater than 0"]),
    (["simulate", "--battery-wh", "20", "--spares", "-1"],
     ["--spares (battery.spares)", "greater than or equal to 0"]),
    (["simulate", "--battery-wh", "20", "--swap-time", "0"],
     ["--swap-time (battery.swap_time)", "greater than 0"]),
    (["simulate", "--battery-wh", "20", "--energy-model", "frobnicate"],
     ["frobnicate", "zeng2019"]),
    (["simulate", "--target-motion", "run"], ["target.motion", "'run'", "still, walk"]),
    (["simulate", "--target-motion", "walk", "--walk-speed", "-1"],
     ["--walk-speed (target.walk_speed)", "greater than 0", "got -1"]),
    (["simulate", "--target-motion", "walk", "--delay", "0.5"],
     ["--delay (target.delay)", "multiple of timing.dt", "got 0.5"]),
    (["simulate", "--drift-object", "PIW-9"], ["--drift-object (target.drift_object)",
                                               "unknown Leeway object class 'PIW-9'",
                                               "known: PIW-1, PIW-2", "got 'PIW-9'"]),
    (["simulate", "--wind", "0,8,6;3600,9,0;1800,1,1"],
     ["--wind (target.drift_wind)", "times out of order (1800 s after 3600 s)",
      "got '0,8,6;3600,9,0;1800,1,1'"]),
    (["simulate", "--current", "east"], ["--current (target.drift_current)",
                                         "expected a pair east,north", "got 'east'"]),
    (["simulate", "--current", "0.1,nan"], ["--current", "expected a pair", "'0.1,nan'"]),
    (["simulate", "--relays", "-1"], ["--relays (team.relays)", "greater than or equal to 0",
                                      "got -1"]),
    (["simulate", "--relays", "8", "--drones", "8"], ["--relays (team.relays) = 8",
                                                      "--drones (team.drones) = 8",
                                                      "allowed: 0 to 7"]),
    (["simulate", "--relays", "10"], ["--relays (team.relays) = 10", "team.drones = 10",
                                      "allowed: 0 to 9"]),
    (["simulate", "--relay-strategy", "chain"], ["--relay-strategy (team.relay_strategy)",
                                                 "unknown relay strategy 'chain'; known: tree"]),
    (["simulate", "--relay-priority", "farthest"], ["--relay-priority (team.relay_priority)",
                                                    "'nearest-first', 'most-connected' or "
                                                    "'k-bottleneck'"]),
    (["simulate", "--seed", "-1"], ["'--seed'", "greater than or equal to 0"]),
    (["simulate", "--run", "-1"], ["'--run'", "greater than or equal to 0"]),
    (["simulate", "--planner", "mtsp", "--drones", "100"], ["1 to 64 drones", "got 100"]),
    (["simulate", "--bogus"], ["No such option: --bogus"]),
    # -- simulate: paths ---------------------------------------------------------------------
    (["simulate", "--plot", "{d}/missing/x.png"], ["--plot", "missing does not exist"]),
    (["simulate", "--plot", "{d}/afolder.png"], ["--plot", "is a folder"]),
    (["simulate", "--plot", "{d}/x.xyz"], ["--plot", "figure format", ".png", ".svg"]),
    (["simulate", "--plot", "{d}/noext"], ["--plot", "figure format"]),
    (["simulate", "--config", "{d}/missing.toml"], ["missing.toml", "no such file"]),
    (["simulate", "--config", "{d}"], ["is a folder", "TOML file is expected"]),
    (["simulate", "--config", "{d}/binary.toml"], ["binary.toml", "UTF-8"]),
    (["simulate", "--config", "{d}/dup.toml"], ["dup.toml", "not valid TOML", "line 3"]),
    # -- mission files -----------------------------------------------------------------------
    (["simulate", "--config", "{d}/bool.toml"], ["bool.toml: team.drones", "valid integer"]),
    (["simulate", "--config", "{d}/float.toml"], ["team.drones", "valid integer", "2.0"]),
    (["simulate", "--config", "{d}/string.toml"], ["team.drones", "valid integer", "'ten'"]),
    (["simulate", "--config", "{d}/extra.toml"], ["team.foo", "allowed here: drones, speed"]),
    (["simulate", "--config", "{d}/flat.toml"], ["drones", "allowed here: area, team"]),
    (["simulate", "--config", "{d}/nan.toml"], ["channel.rc", "finite number"]),
    (["simulate", "--config", "{d}/inf.toml"], ["team.speed", "finite number"]),
    (["simulate", "--config", "{d}/huge.toml"], ["timing.horizon", "10,000,000 steps"]),
    (["simulate", "--config", "{d}/records.toml"], ["timing.checkpoint", "1,000,000 records"]),
    (["simulate", "--config", "{d}/bs.toml"], ["bs must lie inside the area"]),
    (["simulate", "--config", "{d}/notable.toml"], ["team", "valid dictionary"]),
    (["simulate", "--config", "{d}/drift.toml"],
     ["drift.toml: target.drift_current", "expected a pair east,north", "[600, 0.2]"]),
    # -- plan --------------------------------------------------------------------------------
    (["plan", "--solver", "lkh"], ["--solver (mtsp.solver)", "'ga' or 'ortools'"]),
    (["plan", "--objective", "mean"], ["--objective (mtsp.objective)", "'minsum'"]),
    (["plan", "--min-cells", "0"], ["--min-cells (mtsp.min_cells)", "greater than or equal"]),
    (["plan", "--drones", "6", "--min-cells", "11"], ["mtsp.min_cells must be at most 10"]),
    (["plan", "--drones", "65"], ["1 to 64 drones"]),
    (["plan", "--population", "7"], ["--population (mtsp.population)", "8"]),
    (["plan", "--iterations", "0"], ["--iterations", "greater than or equal to 1"]),
    (["plan", "--seed", "-1"], ["--seed (mtsp.plan_seed)", "greater than or equal to 0"]),
    (["plan", "--size", "0"], ["--size (area.size)", "greater than 0"]),
    (["plan", "--size", "1e9", "--r", "1"], ["at most 10,000 cells", "at most 100"]),
    (["plan", "--speed", "0"], ["--speed (team.speed)", "greater than 0"]),
    (["plan", "--plot", "{d}/missing/p.png"], ["--plot", "does not exist"]),
    # -- sweep: files and options ------------------------------------------------------------
    (["sweep", "{d}/missing.toml", "--out", "{d}/o"], ["missing.toml", "no such file"]),
    (["sweep", "{d}", "--out", "{d}/o"], ["is a folder", "TOML file is expected"]),
    (["sweep", "{d}/ok.toml"], ["Missing option '--out'"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/afile"], ["--out", "afile is a file"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/o", "--workers", "0"],
     ["'--workers'", "greater than or equal to 1"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/o", "--workers", "100000"], ["'--workers'", "1024"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/o", "--scheduler", "tcp://h:1", "--dask-local"],
     ["exclude each other"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/o", "--scheduler", "nonsense"],
     ["cannot reach the Dask scheduler nonsense"]),
    # -- experiment files --------------------------------------------------------------------
    (["sweep", "{d}/noseed.toml", "--out", "{d}/o"], ["seed: Field required", "integer >= 0"]),
    (["sweep", "{d}/seedneg.toml", "--out", "{d}/o"], ["seed", "greater than or equal to 0"]),
    (["sweep", "{d}/seedhuge.toml", "--out", "{d}/o"], ["seed", "9223372036854775807"]),
    (["sweep", "{d}/runs0.toml", "--out", "{d}/o"], ["runs", "greater than or equal to 1"]),
    (["sweep", "{d}/runsfloat.toml", "--out", "{d}/o"], ["runs", "valid integer"]),
    (["sweep", "{d}/chunk0.toml", "--out", "{d}/o"], ["chunk", "greater than or equal to 1"]),
    (["sweep", "{d}/noname-ok.toml", "--out", "{d}/o"], ["name", "at least 1 character"]),
    (["sweep", "{d}/seedbig.toml", "--out", "{d}/o"], ["unknown mission parameter 'seed'"]),
    (["sweep", "{d}/gridunknown.toml", "--out", "{d}/o"],
     ["unknown mission parameter 'drone'", "drones"]),
    (["sweep", "{d}/gridempty.toml", "--out", "{d}/o"], ["'drones' lists no values"]),
    (["sweep", "{d}/gridnotlist.toml", "--out", "{d}/o"], ["grid.drones", "valid list"]),
    (["sweep", "{d}/gridbad.toml", "--out", "{d}/o"], ["grid point rc=-1", "greater than 0"]),
    (["sweep", "{d}/gridnan.toml", "--out", "{d}/o"], ["grid point p_miss=nan", "finite"]),
    (["sweep", "{d}/griddup.toml", "--out", "{d}/o"], ["same mission"]),
    (["sweep", "{d}/griddrift.toml", "--out", "{d}/o"],
     ["grid point drift_wind=[[0, 8, 6], [0, 9, 0]]", "times out of order (0 s after 0 s)"]),
    (["sweep", "{d}/gridhuge.toml", "--out", "{d}/o"], ["1,000,000 points", "at most 100,000"]),
    (["sweep", "{d}/missionextra.toml", "--out", "{d}/o"],
     ["mission.drones", "allowed here: area, team"]),
    (["sweep", "{d}/missionbad.toml", "--out", "{d}/o"], ["mission.team.planner", "covb"]),
    # -- results folders ---------------------------------------------------------------------
    (["sweep", "{d}/ok.toml", "--out", "{d}/truncated"], ["experiment.json is damaged"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/newer"], ["sarlink 9.0.0", "upgrade sarlink"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/other"], ["another experiment", "another output"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/pointsfile"], ["points is a file"]),
    (["sweep", "{d}/ok.toml", "--out", "{d}/lockdir"], [".lock", "is a folder"]),
    (["summarize", "{d}/missing"], ["not a sarlink results folder"]),
    (["summarize", "{d}/afile"], ["not a sarlink results folder"]),
    (["summarize", "{d}/truncated"], ["damaged", "delete the file"]),
    (["summarize", "{d}/newer"], ["layout format 2", "upgrade sarlink"]),
    (["summarize", "{d}/listed"], ["damaged", "no JSON object"]),
    (["summarize", "{d}/keyless"], ["written by another sarlink", "no 'experiment'"]),
    (["summarize", "{d}/empty"], ["no runs to summarise"]),
    (["summarize", "{d}/empty", "--csv", "--json"], ["choose one of --csv and --json"]),
    (["summarize", "{d}/empty", "--td", "-5"], ["--td", "> 0", "got -5"]),
    (["summarize", "{d}/empty", "--td", "nan"], ["--td", "finite"]),
    # -- reproduce and the app ---------------------------------------------------------------
    (["reproduce", "--figures", "13", "--out", "{d}/r"], ["figures must be among 1, 2"]),
    (["reproduce", "--figures", "one", "--out", "{d}/r"], ["--figures", "like 1,3,7"]),
    (["reproduce", "--runs", "0", "--out", "{d}/r"], ["runs must be at least 1"]),
    (["reproduce", "--out", "{d}/afile"], ["--out", "afile is a file"]),
    (["reproduce", "--workers", "0"], ["'--workers'", "greater than or equal to 1"]),
    (["frobnicate"], ["No such command 'frobnicate'"]),
    (["--bogus"], ["No such option: --bogus"]),
]


@pytest.mark.parametrize(("args", "words"), ROWS, ids=[" ".join(a) for a, _ in ROWS])
def test_bad_input_is_one_line_with_exit_status_2(workspace: Path, args: list[str],
                                                  words: list[str]) -> None:
    out = runner.invoke(app, [a.replace("{d}", str(workspace)) for a in args])
    assert out.exit_code == 2, out.output
    lines = [line for line in out.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), out.output
    for word in words:
        assert word in lines[0]
    assert out.stdout == ""


def test_there_are_at_least_60_rows() -> None:
    assert len(ROWS) >= 60


def test_an_experiment_file_without_a_name_is_named_after_the_file(workspace: Path) -> None:
    assert Experiment.from_toml(workspace / "ok.toml").name == "ok"


# -- failures that are not the user's ---------------------------------------------------------


def test_an_unexpected_error_is_one_line_with_a_hint_and_debug_shows_it(
        monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(*args: object, **kwargs: object) -> None:
        raise ZeroDivisionError("the planner divided by zero")

    # the module, not the command function that sarlink.cli exports under the same name
    monkeypatch.setattr(sys.modules["sarlink.cli.simulate"], "run_simulation", broken)
    out = runner.invoke(app, ["simulate", "--td", "10"])
    assert out.exit_code == 1
    assert out.stderr.strip().splitlines() == [
        "error: unexpected ZeroDivisionError: the planner divided by zero. This is a bug in "
        "sarlink or an input it does not check yet; run the command again with --debug "
        "(sarlink --debug ...) for the traceback, and report it"]
    debug = runner.invoke(app, ["--debug", "simulate", "--td", "10"])
    assert isinstance(debug.exception, ZeroDivisionError)


def test_a_sweep_into_a_folder_another_sweep_writes_is_refused(workspace: Path,
                                                               tmp_path: Path) -> None:
    out = tmp_path / "busy"
    with open_store(out, Experiment.from_toml(workspace / "ok.toml")):  # holds the lock
        result = runner.invoke(app, ["sweep", str(workspace / "ok.toml"), "--out", str(out)])
    assert result.exit_code == 2
    assert "being written by another sweep" in result.stderr
    with open(out / ".lock", "w") as fh:  # the lock is flock: the OS frees it with the process
        fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)


def test_a_full_disk_mid_sweep_keeps_what_was_finished(workspace: Path, tmp_path: Path,
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    """The second file fails as a full disk does; the first stays, and a rerun completes the
    sweep with the rows of a sweep that never failed."""
    toml = workspace / "ok.toml"
    out = tmp_path / "full"
    real = storage.pq.write_table
    calls: list[int] = []

    def filling(table: object, where: object, **kwargs: object) -> None:
        calls.append(1)
        if len(calls) > 1:
            raise OSError(errno.ENOSPC, "No space left on device", str(where))
        real(table, where, **kwargs)

    monkeypatch.setattr(storage.pq, "write_table", filling)
    args = ["sweep", str(toml), "--out", str(out), "--workers", "1", "-q"]
    failed = runner.invoke(app, args)
    assert failed.exit_code == 1
    (line,) = failed.stderr.strip().splitlines()
    assert "no space left on the device" in line and "run the same command again" in line
    assert not list(out.glob("points/*/.*.tmp"))  # no partial file left behind
    kept = load(out)
    assert len(kept) == 2  # one grid point's two runs were written before the disk filled

    monkeypatch.setattr(storage.pq, "write_table", real)
    assert runner.invoke(app, args).exit_code == 0
    clean = tmp_path / "clean"
    assert runner.invoke(app, ["sweep", str(toml), "--out", str(clean), "--workers", "1",
                               "-q"]).exit_code == 0
    pd.testing.assert_frame_equal(load(out), load(clean))
