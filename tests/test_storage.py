"""The results folder: layout, manifest, atomic files, damaged files, resume planning, loading.

Runs are written in-process here (no worker pool), as a sweep's parent process writes them.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pandas as pd
import pyarrow.parquet as pq
import pytest

from sarlink import ConfigError, Experiment, Mission, load, prepare
from sarlink.execution import _plan
from sarlink.metrics import summarize
from sarlink.storage import (
    MANIFEST,
    Point,
    Store,
    _write_atomic,
    open_store,
    read_manifest,
    run_table,
)


def experiment(**changes: object) -> Experiment:
    data = {"name": "tiny", "seed": 5, "runs": 12, "chunk": 6,
            "mission": {"team": {"drones": 3}, "timing": {"horizon": 300.0}},
            "grid": {"planner": ["covb", "conb"]}}
    return Experiment.from_dict({**data, **changes})


def write(store: Store, point: Point, runs: range, seed: int | None = None) -> None:
    """Runs of ``point`` computed here and stored as a sweep stores them."""
    seed = store.seed if seed is None else seed
    prepared = prepare(point.mission)
    results = [prepared.run(seed, k) for k in runs]
    store.write(point, runs, run_table(point.mission, seed, results))


def fill(out: Path, exp: Experiment) -> None:
    with open_store(out, exp) as store:
        for point in store.points:
            for start in range(0, exp.runs, exp.chunk):
                write(store, point, range(start, min(start + exp.chunk, exp.runs)))


def files(out: Path) -> list[Path]:
    return sorted(out.glob("points/*/*.parquet"))


def test_layout_manifest_and_load_order(tmp_path: Path) -> None:
    exp = experiment()
    with open_store(tmp_path, exp) as store:
        covb, conb = store.points
        for point, start in [(conb, 6), (covb, 6), (conb, 0), (covb, 0)]:  # any order
            write(store, point, range(start, start + 6))
    assert [p.relative_to(tmp_path).as_posix() for p in files(tmp_path)] == sorted(
        f"points/{p.hash}/runs-{a:06d}-{a + 6:06d}.parquet" for p in (covb, conb) for a in (0, 6))
    manifest = read_manifest(tmp_path)
    assert manifest["experiment"] == exp.model_dump(mode="json")
    assert manifest["points"] == [{"hash": covb.hash, "params": {"planner": "covb"}},
                                  {"hash": conb.hash, "params": {"planner": "conb"}}]
    df = load(tmp_path)
    assert list(df.point) == [0] * 12 + [1] * 12 and list(df.run) == list(range(12)) * 2
    assert list(df.planner.unique()) == ["covb", "conb"]
    assert df.columns[:4].tolist() == ["point", "seed", "run", "size"]


def test_parameters_keep_one_type_when_none_in_some_files(tmp_path: Path) -> None:
    exp = experiment(runs=2, grid={"bs": [None, [1000.0, 1500.0]], "coherence": [None, 4.0],
                                   "min_cells": [None, 3]})
    fill(tmp_path, exp)
    schemas = {pq.read_schema(path).remove_metadata() for path in files(tmp_path)}
    assert len(schemas) == 1
    df = load(tmp_path)
    assert set(df.bs) == {None, (1000.0, 1500.0)}
    assert df.coherence.isna().sum() == 8 and set(df.coherence.dropna()) == {4.0}
    assert df.min_cells.dtype == "Int64" and df.min_cells.isna().sum() == 8
    assert len(summarize(df)) == 8  # grouping by these columns keeps None as a group


def test_runs_beyond_the_manifest_are_not_loaded(tmp_path: Path) -> None:
    fill(tmp_path, experiment())
    with open_store(tmp_path, experiment(runs=8, name="renamed", chunk=3)):
        pass
    assert load(tmp_path).groupby("point").run.max().tolist() == [7, 7]
    with open_store(tmp_path, experiment()):
        pass
    assert len(load(tmp_path)) == 24


def test_another_experiment_in_the_folder_is_refused(tmp_path: Path) -> None:
    fill(tmp_path, experiment())
    for other in (experiment(seed=6), experiment(grid={"planner": ["conb", "covb"]}),
                  experiment(mission={"team": {"drones": 4}, "timing": {"horizon": 300.0}})):
        with pytest.raises(ConfigError, match="another experiment"), open_store(tmp_path, other):
            pass


def test_one_sweep_at_a_time(tmp_path: Path) -> None:
    with (open_store(tmp_path, experiment()), pytest.raises(ConfigError, match="another sweep"),
          open_store(tmp_path, experiment())):
        pass
    with open_store(tmp_path, experiment()):  # released
        pass


def test_damaged_files_are_not_loaded_and_are_planned_again(tmp_path: Path) -> None:
    exp = experiment(runs=24)
    fill(tmp_path, exp)
    intact = load(tmp_path)
    covb, conb = (tmp_path / "points" / p["hash"] for p in read_manifest(tmp_path)["points"])
    truncated, zeroed, renamed = (covb / f"runs-{a:06d}-{a + 6:06d}.parquet" for a in (0, 6, 12))
    truncated.write_bytes(truncated.read_bytes()[: truncated.stat().st_size // 2])
    data = bytearray(zeroed.read_bytes())
    data[len(data) // 5: len(data) // 2] = bytes(len(data) // 2 - len(data) // 5)
    zeroed.write_bytes(bytes(data))
    shutil.copy(covb / "runs-000018-000024.parquet", renamed)  # right point, wrong runs
    shutil.copy(covb / "runs-000018-000024.parquet", conb / "runs-000018-000024.parquet")

    with pytest.warns(UserWarning, match="not loaded") as caught:
        df = load(tmp_path)
    reasons = " ".join(str(w.message) for w in caught)
    for reason in ("unreadable", "exactly runs 12 to 17", "another grid point"):
        assert reason in reasons
    kept = (intact.point == 0) & (intact.run >= 18) | (intact.point == 1) & (intact.run < 18)
    pd.testing.assert_frame_equal(df, intact[kept].reset_index(drop=True))

    with open_store(tmp_path, exp) as store, pytest.warns(UserWarning, match="redone"):
        assert store.missing(store.points[0], 24) == [range(0, 18)]
        assert store.missing(store.points[1], 24) == [range(18, 24)]
    assert len(files(tmp_path)) == 4  # the damaged ones are gone


def test_resume_plans_only_missing_runs_whatever_the_chunk(tmp_path: Path) -> None:
    exp = experiment(runs=20, chunk=4)
    with open_store(tmp_path, exp) as store:
        covb, conb = store.points
        write(store, covb, range(0, 5))
        write(store, covb, range(10, 15))
        write(store, conb, range(0, 20))
        assert store.missing(covb, 20) == [range(5, 10), range(15, 20)]
        assert store.missing(covb, 12) == [range(5, 10)]
        assert store.missing(conb, 20) == []
        tasks = _plan(store, runs=20, chunk=4)
    assert [(t.point.hash, t.runs) for t in tasks] == [
        (covb.hash, range(5, 9)), (covb.hash, range(9, 10)),
        (covb.hash, range(15, 19)), (covb.hash, range(19, 20))]


def test_first_chunks_of_all_points_come_first(tmp_path: Path) -> None:
    with open_store(tmp_path, experiment(runs=12, chunk=6)) as store:
        tasks = _plan(store, runs=12, chunk=6)
    assert [(t.point.params["planner"], t.runs.start) for t in tasks] == [
        ("covb", 0), ("conb", 0), ("covb", 6), ("conb", 6)]


def test_overlapping_files_are_an_error_not_double_counted(tmp_path: Path) -> None:
    with open_store(tmp_path, experiment()) as store:
        write(store, store.points[0], range(0, 6))
        write(store, store.points[0], range(3, 9))
    with pytest.raises(ConfigError, match="overlaps"):
        load(tmp_path)


def test_a_wrong_table_is_never_written(tmp_path: Path) -> None:
    with open_store(tmp_path, experiment()) as store, pytest.raises(RuntimeError, match="seed"):
        write(store, store.points[0], range(0, 6), seed=99)
    assert files(tmp_path) == []


def test_atomic_write_leaves_nothing_when_it_fails(tmp_path: Path) -> None:
    def half_then_fail(fh: object) -> None:
        fh.write(b"PAR1 half a file")  # type: ignore[attr-defined]
        raise OSError("disk full")

    with pytest.raises(OSError, match="disk full"):
        _write_atomic(tmp_path / "runs-000000-000006.parquet", half_then_fail)
    assert list(tmp_path.iterdir()) == []


def test_temporary_files_are_ignored_then_cleaned(tmp_path: Path) -> None:
    fill(tmp_path, experiment())
    folder = files(tmp_path)[0].parent
    stale = folder / ".runs-000012-000018.parquet.x1y2.tmp"
    stale.write_bytes(b"PAR1 a killed writer's")
    assert len(load(tmp_path)) == 24
    with open_store(tmp_path, experiment()):
        assert not stale.exists()


def test_manifest_errors(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError, match="not a sarlink results folder"):
        load(tmp_path)
    (tmp_path / MANIFEST).write_text("{not json")
    with pytest.raises(ConfigError, match="damaged"):
        load(tmp_path)
    (tmp_path / MANIFEST).write_text(json.dumps({"format": 99}))
    with pytest.raises(ConfigError, match="format 99"):
        load(tmp_path)


def test_empty_folder_loads_as_no_rows(tmp_path: Path) -> None:
    with open_store(tmp_path, experiment()):
        pass
    df = load(tmp_path)
    assert df.empty and {"point", "run", "planner"} <= set(df.columns)


def test_renamed_column_is_caught_and_older_files_still_load(tmp_path: Path) -> None:
    """A damaged footer may rename a column yet read fine; a file written before a parameter
    existed lacks its column and still loads, with nulls there."""
    fill(tmp_path, experiment())
    first, second = files(tmp_path)[:2]
    table = pq.read_table(first)
    renamed = table.rename_columns(["chec\0point" if n == "checkpoint" else n
                                    for n in table.column_names])
    pq.write_table(renamed.replace_schema_metadata(table.schema.metadata), first)
    table = pq.read_table(second)
    meta = {**table.schema.metadata, b"sarlink.columns": json.dumps(
        [n for n in table.column_names if n != "altitude"]).encode()}
    pq.write_table(table.drop_columns(["altitude"]).replace_schema_metadata(meta), second)
    with pytest.warns(UserWarning, match="columns are not those it was written with"):
        df = load(tmp_path)
    assert len(df) == 24 - 6 and df.altitude.isna().sum() == 6


def test_files_written_before_checkpoints_were_stored_read_the_same(tmp_path: Path) -> None:
    """Older files lack the ``checkpoints`` column; loading gives the times the engine used,
    and the summary is the same as from the files that store them."""
    exp = experiment(mission={"team": {"drones": 3}, "timing": {"horizon": 420.0}})
    fill(tmp_path, exp)
    before = load(tmp_path)
    for path in files(tmp_path):
        table = pq.read_table(path)
        meta = {**table.schema.metadata, b"sarlink.columns": json.dumps(
            [n for n in table.column_names if n != "checkpoints"]).encode()}
        pq.write_table(table.drop_columns(["checkpoints"]).replace_schema_metadata(meta), path)
    after = load(tmp_path)
    assert [list(v) for v in after.checkpoints] == [list(v) for v in before.checkpoints]
    assert list(before.checkpoints.iloc[0])[-3:] == [350.0, 400.0, 420.0]
    pd.testing.assert_frame_equal(summarize(after, td=[100, 420]),
                                  summarize(before, td=[100, 420]))


def test_result_files_read_with_pandas_as_sarlink_loads_them(tmp_path: Path) -> None:
    """The files are plain Parquet (written without dictionary pages or statistics): pandas
    reads every one, each parameter column one value, the rows those ``load`` gives."""
    fill(tmp_path, experiment())
    frames = [pd.read_parquet(path) for path in files(tmp_path)]
    assert all(f["planner"].nunique() == 1 and f["drones"].eq(3).all() for f in frames)
    read = pd.concat(frames).sort_values(["planner", "run"]).reset_index(drop=True)
    loaded = load(tmp_path).sort_values(["planner", "run"]).reset_index(drop=True)
    assert len(read) == 24
    for name in ("run", "planner", "t_detect", "t_notify", "target_x"):
        pd.testing.assert_series_equal(read[name], loaded[name], check_dtype=False)


@pytest.mark.parametrize("staircase", [False, True])
def test_a_table_built_whole_equals_one_built_from_its_rows(staircase: bool) -> None:
    """run_table builds its outcome columns whole; Arrow's own conversion of the rows
    (``Table.from_pylist`` of :meth:`RunResult.row`, each with its own interpolation at the
    horizon) gives the same table, types included: runs stopped early (NaN records), never
    detected and with their staircases."""
    import pyarrow as pa

    mission = Mission.build(planner="covb", drones=4, horizon=900.0, stop="notified")
    prepared = prepare(mission)
    results = [r for k in range(8)
               for r in prepared.run_ranges(3, k, [150.0, 900.0], staircase=staircase)]
    assert any(r.t_notify is None for r in results) and any(r.t_notify for r in results)
    table = run_table(mission, 3, results)
    rows = pa.Table.from_pylist([
        {**r.row(), "t_reachable": r.t_reachable(), "connected_fraction": r.connected_fraction()}
        for r in results])
    outcomes = table.select(rows.column_names)
    assert outcomes.schema == rows.schema
    assert outcomes.to_pandas().equals(rows.to_pandas())
    assert ("notify_times" in table.column_names) is staircase
