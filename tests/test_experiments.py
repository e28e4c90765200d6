"""Experiments: validation, grid expansion, and sweeps that give the same rows however they run.

The sweeps here share one small experiment; its uninterrupted single-worker sweep is the
reference every other way of running it must reproduce row for row.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pandas as pd
import pytest
from distributed import LocalCluster
from typer.testing import CliRunner

from sarlink import ConfigError, Experiment, Mission, load, prepare, sweep
from sarlink.cli import app
from sarlink.config import mission_hash
from sarlink.execution import _environment, _Local, start_workers

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "sweep.toml"

SMALL: dict[str, Any] = {
    "name": "small", "seed": 11, "runs": 100, "chunk": 5,
    "mission": {"team": {"drones": 8}, "timing": {"horizon": 2000.0}},
    "grid": {"planner": ["covb", "conb"], "rc": [500.0, 1000.0]},
}
SMALL_TOML = """\
name = "small"
seed = 11
runs = 100
chunk = 5

[mission.team]
drones = 8

[mission.timing]
horizon = 2000.0

[grid]
planner = ["covb", "conb"]
rc = [500, 1000]
"""


def small(**changes: Any) -> Experiment:
    return Experiment.from_dict({**SMALL, **changes})


@pytest.fixture(scope="module")
def reference(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, pd.DataFrame]:
    """The small experiment swept by one worker, uninterrupted."""
    out = tmp_path_factory.mktemp("reference")
    return out, sweep(small(), out, workers=1, progress=False)


# -- the experiment object ---------------------------------------------------------------------


@pytest.mark.parametrize(("changes", "expected"), [
    ({"grid": {"dronez": [1, 2]}}, ["grid", "'dronez'", "known:", "drones"]),
    ({"grid": {"drones": []}}, ["grid", "'drones'", "no values"]),
    ({"grid": {"drones": 4}}, ["grid.drones", "list"]),
    ({"runs": 0}, ["runs", "greater than or equal to 1"]),
    ({"runs": -5}, ["runs"]),
    ({"chunk": 0}, ["chunk"]),
    ({"seed": -1}, ["seed"]),
    ({"name": ""}, ["name"]),
    ({"sed": 1}, ["sed", "Extra inputs"]),
    ({"mission": {"team": {"drones": 0}}}, ["mission.team.drones"]),
    ({"grid": {"drones": [4, 0]}}, ["grid point drones=0", "team.drones"]),
    ({"grid": {"rc": [500, 500.0]}}, ["rc=500.0", "same mission"]),
])
def test_invalid_experiments_name_the_field(changes: dict[str, Any], expected: list[str]) -> None:
    with pytest.raises(ConfigError) as err:
        small(**changes)
    for part in expected:
        assert part in str(err.value)


def test_an_unknown_planner_is_refused_before_a_sweep_starts(tmp_path: Path) -> None:
    """Planner names are checked where work starts (plug-ins are loaded by then), naming the
    grid point, and nothing is written."""
    with pytest.raises(ConfigError, match=r"grid point planner='nope', rc=500\.0: "
                       r"team\.planner: unknown planner 'nope'"):
        sweep(small(grid={"planner": ["covb", "nope"], "rc": [500.0]}), tmp_path / "out")
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").rglob("*.parquet"))


def test_experiment_file_reads_like_the_dict(tmp_path: Path) -> None:
    path = tmp_path / "small.toml"
    path.write_text(SMALL_TOML)
    assert Experiment.from_toml(path) == small()


def test_broken_experiment_file_names_the_file(tmp_path: Path) -> None:
    path = tmp_path / "broken.toml"
    path.write_text("name = \n")
    with pytest.raises(ConfigError, match=r"broken\.toml"):
        Experiment.from_toml(path)


def test_points_are_the_cartesian_product_last_parameter_fastest() -> None:
    points = Experiment.from_toml(EXAMPLE).points()
    assert len(points) == 12
    assert [p for p, _ in points[:3]] == [
        {"planner": "covb", "drones": 4, "rc": 500.0},
        {"planner": "covb", "drones": 4, "rc": 1000.0},
        {"planner": "covb", "drones": 8, "rc": 500.0},
    ]
    params, mission = points[-1]
    assert params == {"planner": "concov", "drones": 8, "rc": 1000.0}
    assert mission == Mission.build(planner="concov", drones=8, rc=1000.0, horizon=2000.0)


def test_no_grid_is_one_point_the_base_mission() -> None:
    assert small(grid={}).points() == [({}, small().mission)]


def test_environment_is_set_then_restored(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("SARLINK_A", "before")
    monkeypatch.delenv("SARLINK_B", raising=False)
    with _environment({"SARLINK_A": "1", "SARLINK_B": "2"}):
        assert (os.environ["SARLINK_A"], os.environ["SARLINK_B"]) == ("1", "2")
    assert os.environ["SARLINK_A"] == "before" and "SARLINK_B" not in os.environ


def _worker(name: str) -> tuple[int, str | None]:
    return os.getpid(), os.environ.get(name)


def _in_worker(name: str) -> tuple[int, str | None]:
    """A fresh local pool's worker: its process id and its value of ``name``."""
    with start_workers(1) as pool:
        assert isinstance(pool, _Local)
        return pool.submit(_worker, name).result()


def test_a_second_sweep_finds_the_workers_of_the_first_unless_their_inputs_changed(
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("SARLINK_A", "before")
    first, value = _in_worker("SARLINK_A")
    assert value == "before" and _in_worker("NUMBA_NUM_THREADS") == (first, "1")
    monkeypatch.setenv("SARLINK_A", "after")  # a variable workers read: new workers
    second, value = _in_worker("SARLINK_A")
    assert value == "after" and second != first
    with pytest.raises(KeyboardInterrupt), start_workers(1):
        raise KeyboardInterrupt  # stopped: the next sweep starts new workers
    assert _in_worker("SARLINK_A")[0] != second


# -- sweeps ------------------------------------------------------------------------------------


def test_sweep_rows_are_the_engine_runs(reference: tuple[Path, pd.DataFrame]) -> None:
    _, df = reference
    assert len(df) == 4 * 100
    assert list(df[["planner", "rc"]].drop_duplicates().itertuples(index=False, name=None)) == [
        ("covb", 500.0), ("covb", 1000.0), ("conb", 500.0), ("conb", 1000.0)]
    assert (df.groupby("point")["run"].apply(list) == [list(range(100))] * 4).all()
    for point, run in [(0, 0), (1, 37), (3, 99)]:
        row = df[(df.point == point) & (df.run == run)].iloc[0]
        expected = prepare(Mission.build(drones=8, horizon=2000.0, planner=row.planner,
                                         rc=row.rc)).run(11, run).row()
        for name in ("target_x", "t_detect", "t_notify", "immediate", "detector", "t_reachable"):
            assert row[name] == pytest.approx(expected[name], nan_ok=True)
        assert list(row.reach_cum) == expected["reach_cum"]


def test_every_point_sees_the_same_targets(reference: tuple[Path, pd.DataFrame]) -> None:
    """Common random numbers: run k has one target at every grid point."""
    _, df = reference
    targets = df.pivot(index="run", columns="point", values="target_x")
    assert targets.nunique(axis=1).eq(1).all()
    assert targets[0].nunique() == 100


def test_two_workers_and_another_chunk_give_the_same_rows(
        reference: tuple[Path, pd.DataFrame], tmp_path: Path) -> None:
    df = sweep(small(chunk=8), tmp_path, workers=2, progress=False)
    pd.testing.assert_frame_equal(df, reference[1])
    pd.testing.assert_frame_equal(load(tmp_path), df)
    assert len(list(tmp_path.glob("points/*/*.parquet"))) == 4 * 13  # 100 runs in chunks of 8


def test_dask_gives_the_same_rows(reference: tuple[Path, pd.DataFrame], tmp_path: Path) -> None:
    """Half on a LocalCluster of the sweep's own (two workers), the rest on a running
    cluster's scheduler (one worker: the path, not the spread, is what it adds)."""
    sweep(small(runs=50, chunk=25), tmp_path, workers=2, dask_local=True, progress=False)
    with LocalCluster(n_workers=1, threads_per_worker=1, dashboard_address=None) as cluster:
        df = sweep(small(chunk=25), tmp_path, scheduler=cluster.scheduler_address,
                   progress=False)
    pd.testing.assert_frame_equal(df, reference[1])


def test_resume_after_sigkill_gives_the_rows_of_an_uninterrupted_sweep(
        reference: tuple[Path, pd.DataFrame], tmp_path: Path) -> None:
    experiment, out = tmp_path / "small.toml", tmp_path / "out"
    experiment.write_text(SMALL_TOML)
    command = [sys.executable, "-c", "from sarlink.cli import app; app()",
               "sweep", str(experiment), "--out", str(out), "--workers", "2", "--quiet"]
    proc = subprocess.Popen(command)
    try:
        deadline = time.monotonic() + 600  # a guard only: it goes on at the third file
        while len(list(out.glob("points/*/*.parquet"))) < 3:
            assert proc.poll() is None and time.monotonic() < deadline, "no results appeared"
            time.sleep(0.002)
    finally:
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
    done = list(out.glob("points/*/*.parquet"))
    assert 3 <= len(done) < 80, "the sweep must be killed half way"
    # resume with another chunk size: the stored runs are neither redone nor counted twice
    before = {path: path.stat().st_mtime_ns for path in done}
    df = sweep(small(chunk=7), out, workers=2, progress=False)
    pd.testing.assert_frame_equal(df, reference[1])
    assert all(path.stat().st_mtime_ns == t for path, t in before.items())
    assert not list(out.glob("points/*/.*.tmp"))


def test_damaged_file_is_redone_by_the_next_sweep(
        reference: tuple[Path, pd.DataFrame], tmp_path: Path) -> None:
    out = tmp_path / "out"
    sweep(small(runs=20), out, workers=1, progress=False)
    victim = sorted(out.glob("points/*/runs-000005-000010.parquet"))[0]
    victim.write_bytes(victim.read_bytes()[:-40])
    with pytest.warns(UserWarning, match="not loaded"):
        assert len(load(out)) == 4 * 20 - 5
    with pytest.warns(UserWarning, match="redone"):
        df = sweep(small(runs=20), out, workers=1, progress=False)
    pd.testing.assert_frame_equal(df, reference[1][reference[1].run < 20].reset_index(drop=True))


def test_invalid_sweep_arguments(tmp_path: Path) -> None:
    for kwargs, message in [({"workers": 0}, "workers"),
                            ({"scheduler": "tcp://x:1", "dask_local": True}, "exclude"),
                            ({"scheduler": "tcp://x:1", "workers": 2}, "dask worker")]:
        with pytest.raises(ConfigError, match=message):
            sweep(small(), tmp_path, progress=False, **kwargs)


# -- the command line --------------------------------------------------------------------------

runner = CliRunner()


def test_cli_summarize_formats(reference: tuple[Path, pd.DataFrame]) -> None:
    out, _ = reference
    table = runner.invoke(app, ["summarize", str(out), "--td", "1000", "--td", "2000"])
    assert table.exit_code == 0, table.output
    assert "planner=conb, rc=1000.0 (100 runs)" in table.stdout
    assert "t_d = 1000 s" in table.stdout and "mission success P_s" in table.stdout
    assert "BS's network depth (hops)" in table.stdout  # ConB's runs record their network
    records = json.loads(runner.invoke(app, ["summarize", str(out), "--json"]).stdout)
    assert len(records) == 4 and records[0]["td"] == 2000.0 and records[0]["runs"] == 100
    csv = runner.invoke(app, ["summarize", str(out), "--td", "500", "--csv"]).stdout
    assert csv.splitlines()[0].startswith("planner,rc,td,runs,") and len(csv.splitlines()) == 5


@pytest.mark.parametrize(("args", "message"), [
    (["summarize", "{out}", "--csv", "--json"], "one of --csv and --json"),
    (["summarize", "{out}", "--td", "5000"], "beyond the horizon"),
    (["summarize", "{missing}"], "not a sarlink results folder"),
    (["sweep", "{bad}", "--out", "{missing}"], "runs"),
])
def test_cli_errors_are_one_line(reference: tuple[Path, pd.DataFrame], tmp_path: Path,
                                 args: list[str], message: str) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text(SMALL_TOML.replace("runs = 100", "runs = 0"))
    paths = {"out": reference[0], "missing": tmp_path / "missing", "bad": bad}
    result = runner.invoke(app, [a.format(**paths) for a in args])
    assert result.exit_code == 2
    assert message in " ".join(result.output.split()) and "Traceback" not in result.output


# -- the relay count as a grid parameter -------------------------------------------------------

RELAYS_TOML = """\
seed = 5
runs = 2

[mission.team]
planner = "covb"
drones = 8

[mission.channel]
rc = 500.0

[mission.timing]
horizon = 900.0

[grid]
relays = [0, 1, 2, 3]
"""


def test_a_sweep_over_the_relay_count_stores_it_beside_the_runs(tmp_path: Path) -> None:
    """``sarlink sweep`` of a grid over ``relays``: a ``relays`` column, each row the engine's
    run of its point; the point without relays keeps the folder (the mission hash) that
    sarlink gave this mission before relays existed, so earlier results stay valid."""
    path = tmp_path / "relays.toml"
    path.write_text(RELAYS_TOML)
    out = runner.invoke(app, ["sweep", str(path), "--out", str(tmp_path / "out"), "--workers",
                              "1", "--quiet"])
    assert out.exit_code == 0, out.output
    df = load(tmp_path / "out")
    assert df.groupby("relays")["run"].apply(list).to_dict() == {k: [0, 1] for k in range(4)}
    for relays, run in [(0, 1), (3, 0)]:
        row = df[(df.relays == relays) & (df.run == run)].iloc[0]
        expected = prepare(Mission.build(planner="covb", drones=8, rc=500.0, horizon=900.0,
                                         relays=relays)).run(5, run).row()
        for name in ("t_detect", "t_notify", "detector", "t_reachable", "connected_fraction"):
            assert row[name] == pytest.approx(expected[name], nan_ok=True)
    folders = {mission_hash(m): p["relays"] for p, m in Experiment.from_toml(path).points()}
    assert {p.name for p in (tmp_path / "out" / "points").iterdir()} == folders.keys()
    assert folders["bfea8fbdf2ba1fa9"] == 0  # the hash computed by sarlink before relays
    table = runner.invoke(app, ["summarize", str(tmp_path / "out")])
    assert "relays=3 (2 runs)" in table.stdout, table.stdout  # counts, not 3.0 (2.0 runs)


def test_an_unknown_relay_strategy_is_refused_before_a_sweep_starts(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match=r"grid point relay_strategy='chain': "
                       r"team\.relay_strategy: unknown relay strategy 'chain'; known: tree"):
        sweep(small(grid={"relay_strategy": ["tree", "chain"]}), tmp_path / "out")
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").rglob("*.parquet"))
