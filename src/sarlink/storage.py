"""Results on disk: one folder per experiment, one Parquet file per finished task.

Layout of a results folder::

    experiment.json                              manifest: experiment, identity, grid points
    points/<point>/runs-000000-000050.parquet    runs 0 .. 49 of one grid point
    .lock                                        held by the sweep writing the folder

``<point>`` is a hash of the point's whole mission, and a file's name holds its run range, so
a rerun recognises finished work whatever the grid order, chunk size or number of workers.
Every file is written under a temporary name in its folder, flushed to disk and renamed, so a
file with a final name is complete; damage done to it later is caught when loaded (Parquet page
checksums, the point and seed in its metadata, the exact run indices) and such a file is
neither loaded nor counted as done.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import tempfile
import types
import typing
import warnings
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager, suppress
from dataclasses import dataclass, field
from functools import cache
from importlib.metadata import version
from pathlib import Path
from typing import IO, Any, Literal

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.parquet as pq

from sarlink.config import ConfigError, Experiment, Mission, mission_hash
from sarlink.config.mission import flat_groups
from sarlink.result import RunResult, result_columns

__all__ = ["MANIFEST", "Point", "Store", "load", "open_store", "read_manifest", "run_table"]

MANIFEST = "experiment.json"
"""The file of a results folder that holds its experiment, grid points and format."""
FORMAT = 1
"""Version of the folder layout, stored in the manifest."""

_FILE = re.compile(r"runs-(\d+)-(\d+)\.parquet")
_POINT_KEY = b"sarlink.point"
_SEED_KEY = b"sarlink.seed"
_COLUMNS_KEY = b"sarlink.columns"


def _file_name(runs: range) -> str:
    return f"runs-{runs.start:06d}-{runs.stop:06d}.parquet"


# -- tables ------------------------------------------------------------------------------------


@dataclass(frozen=True)
class _Column:
    type: pa.DataType
    optional: bool


def _column(annotation: Any) -> _Column:
    """The Parquet type of a parameter annotated ``annotation`` (None becomes a null)."""
    origin, args = typing.get_origin(annotation), typing.get_args(annotation)
    if origin in (typing.Union, types.UnionType) and type(None) in args:
        (inner,) = (a for a in args if a is not type(None))
        return _Column(_column(inner).type, optional=True)
    if origin is Literal:
        return _Column(pa.string(), optional=False)
    if origin is tuple:
        return _Column(pa.list_(_column(args[0]).type), optional=False)
    simple = {bool: pa.bool_(), int: pa.int64(), float: pa.float64(), str: pa.string()}
    if annotation not in simple:
        raise TypeError(f"no Parquet type for mission parameters annotated {annotation}")
    return _Column(simple[annotation], optional=False)


@cache
def _param_columns() -> dict[str, _Column]:
    """Every flat mission parameter and its column type, declared rather than inferred so that
    a parameter that is None in one file and set in another has one type in both."""
    columns = {}
    for model in flat_groups().values():
        for name, info in model.model_fields.items():
            columns[name] = _column(info.annotation)
    return columns


_REPEATED: dict[tuple[str, str, int], pa.Array] = {}


def _repeated(name: str, value: Any, n: int) -> pa.Array:
    """Parameter ``name``'s column of ``n`` rows of ``value``: the same for every task of a
    point, and for the points of a grid but one parameter, so built once (arrays are
    immutable; keyed by ``repr``, which tells ``-0.0`` from ``0.0``)."""
    key = (name, repr(value), n)
    column = _REPEATED.get(key)
    if column is None:
        if len(_REPEATED) >= 4096:
            _REPEATED.clear()
        column = _REPEATED[key] = pa.repeat(pa.scalar(value, _param_columns()[name].type), n)
    return column


def run_table(mission: Mission, seed: int, results: Sequence[RunResult]) -> pa.Table:
    """Runs of ``mission`` as one tidy table: seed, run, every flat parameter, the outcomes.

    The outcomes are the columns of :func:`sarlink.result.result_columns`, as
    :meth:`sarlink.RunResult.row` gives a row of them. The point's hash, the seed and the
    column names are kept in the schema metadata, so that a file can be checked against the
    folder it lies in and a damaged footer that renames columns is caught.
    """
    outcomes = {name: _arrow(column) for name, column in result_columns(results).items()}
    params = mission.params()
    clash = set(params) & set(outcomes)
    if clash:
        raise ValueError(f"run outcomes and mission parameters share names: {sorted(clash)}")
    n = len(results)
    columns = {
        "seed": outcomes.pop("seed"),
        "run": outcomes.pop("run"),
        **{name: _repeated(name, params[name], n) for name in _param_columns()},
        **outcomes,
    }
    meta = {_POINT_KEY: mission_hash(mission).encode(), _SEED_KEY: str(seed).encode(),
            _COLUMNS_KEY: json.dumps(list(columns)).encode()}
    return pa.table(columns).replace_schema_metadata(meta)


def _arrow(column: np.ndarray | list[np.ndarray]) -> pa.Array:
    """A column of :func:`~sarlink.result.result_columns` as Arrow: a 2-D array or a list
    of arrays as a column of lists of doubles, as ``Table.from_pylist`` types them."""
    if isinstance(column, list):
        lengths = np.array([len(row) for row in column], dtype=np.int32)
        values = np.concatenate(column) if column else np.empty(0)
    elif column.ndim == 2:
        lengths = np.full(column.shape[0], column.shape[1], dtype=np.int32)
        values = column.ravel()
    else:
        return pa.array(column)
    offsets = np.zeros(len(lengths) + 1, dtype=np.int32)
    np.cumsum(lengths, out=offsets[1:])
    return pa.ListArray.from_arrays(pa.array(offsets), pa.array(values.astype(float, copy=False)))


def _problem(table: pa.Table, point: str, seed: int, runs: range) -> str | None:
    """What makes ``table`` unfit to be runs ``runs`` of ``point`` under ``seed``, if anything."""
    meta = table.schema.metadata or {}
    if meta.get(_POINT_KEY) != point.encode():
        return "it belongs to another grid point"
    if meta.get(_SEED_KEY) != str(seed).encode():
        return "it was made with another seed"
    written = meta.get(_COLUMNS_KEY)  # absent in files of sarlink 0.1.0 before it was kept
    if written is not None and written != json.dumps(table.column_names).encode():
        return "its columns are not those it was written with"  # a damaged footer
    if not np.array_equal(table["run"].to_numpy(), np.arange(runs.start, runs.stop)):
        return f"it does not hold exactly runs {runs.start} to {runs.stop - 1}"
    return None


def _read(path: Path, point: str, seed: int, runs: range) -> pa.Table | str:
    """The table in ``path``, or why it cannot be used."""
    try:  # ParquetFile on one thread: half the time of read_table for files this small
        with pq.ParquetFile(path, page_checksum_verification=True) as parquet:
            table = parquet.read(use_threads=False)
    except (OSError, ValueError, pa.ArrowException) as exc:
        return f"it is unreadable ({exc})"
    problem = _problem(table, point, seed, runs)
    return table if problem is None else problem


def _scan(folder: Path, point: str, seed: int) -> Iterator[tuple[Path, range, pa.Table | str]]:
    """Every result file of a point, in run order, read and checked (temporary files ignored)."""
    found = []
    for path in folder.glob("runs-*.parquet"):
        match = _FILE.fullmatch(path.name)
        if match:
            found.append((range(int(match[1]), int(match[2])), path))
    found.sort(key=lambda f: (f[0].start, f[0].stop))
    stop = 0
    for runs, path in found:
        result = _read(path, point, seed, runs)
        if isinstance(result, pa.Table):
            if runs.start < stop:
                raise ConfigError(f"{path} overlaps another result file of its point; "
                                  "the folder was changed by hand, remove one of them")
            stop = runs.stop
        yield path, runs, result


# -- writing -----------------------------------------------------------------------------------


def _write_atomic(path: Path, write: Callable[[IO[bytes]], object]) -> None:
    """Write ``path`` whole or not at all: temporary file in the same folder, fsync, rename."""
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            write(fh)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        with suppress(FileNotFoundError):
            os.unlink(tmp)
        raise
    if os.name == "posix":  # make the rename itself durable
        folder = os.open(path.parent, os.O_RDONLY)
        try:
            os.fsync(folder)
        finally:
            os.close(folder)


_LEAN = {"use_dictionary": False, "write_statistics": False}
"""How result files are written beyond the defaults: no dictionary pages (a point's parameter
columns repeat one value, which snappy compresses as well) and no column statistics (nothing
filters on them): two fifths of a file's CPU at 50 rows, for files read back the same."""


@dataclass(frozen=True)
class Point:
    """One grid point of an experiment: its grid values, mission and folder name."""

    params: dict[str, Any]
    mission: Mission
    hash: str


_Stored = list[tuple[range, pa.Table]]
"""The valid files of one grid point, as (run range, table), in run order."""


@dataclass(frozen=True)
class Store:
    """A results folder opened by :func:`open_store` for one sweep.

    It keeps the tables it checks and writes, so that the sweep's results need not be read
    back from disk.
    """

    root: Path
    seed: int
    points: list[Point]
    _tables: dict[str, _Stored] = field(default_factory=dict)

    def missing(self, point: Point, runs: int) -> list[range]:
        """The run ranges of ``0 .. runs-1`` that ``point`` has no valid file for.

        Unusable files are moved aside to ``<name>.damaged`` (with a warning) so that their
        runs are done again and nothing is deleted.
        """
        kept: _Stored = []
        gaps, start = [], 0
        for path, span, result in _scan(self.root / "points" / point.hash, point.hash,
                                        self.seed):
            if isinstance(result, str):
                aside = path.with_name(path.name + ".damaged")
                warnings.warn(f"{path} is redone: {result}; the file is moved to {aside.name}",
                              stacklevel=2)
                path.replace(aside)
                continue
            kept.append((span, result))
            if span.start > start:
                gaps.append(range(start, min(span.start, runs)))
            start = max(start, span.stop)
        gaps.append(range(start, runs))
        self._tables[point.hash] = kept
        return [gap for gap in gaps if gap]

    def write(self, point: Point, runs: range, table: pa.Table) -> None:
        """Store runs ``runs`` of ``point`` atomically."""
        problem = _problem(table, point.hash, self.seed, runs)
        if problem is not None:  # a worker with another sarlink version, or a bug
            raise RuntimeError(f"a task for runs {runs.start}..{runs.stop - 1} of grid point "
                               f"{point.params} returned a wrong table: {problem}")
        folder = self.root / "points" / point.hash
        folder.mkdir(parents=True, exist_ok=True)
        _write_atomic(folder / _file_name(runs),
                      lambda fh: pq.write_table(table, fh, compression="snappy",
                                                write_page_checksum=True, **_LEAN))
        self._tables.setdefault(point.hash, []).append((runs, table))

    def frame(self, runs: int) -> pd.DataFrame:
        """Runs ``0 .. runs-1`` of every point that this store checked or wrote, as
        :func:`load` returns them."""
        return _frame([sorted(self._tables.get(p.hash, []), key=lambda s: s[0].start)
                       for p in self.points], runs)


@contextmanager
def _locked(root: Path) -> Iterator[None]:
    """Hold the folder's lock, so that two sweeps never write one folder at once.

    The operating system releases it when the process ends, however it ends.
    """
    with open(root / ".lock", "w") as fh:
        if os.name == "posix":
            import fcntl

            try:
                fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                raise ConfigError(f"{root} is being written by another sweep; wait for it to "
                                  "finish or choose another output folder") from None
        yield


def _identity(seed: int, points: Sequence[Point], staircase: bool = False) -> str:
    """What the rows depend on: the seed and each grid point's mission, in grid order, and
    whether they carry the staircase (named only when they do, as folders before it)."""
    data = json.dumps({"seed": seed, "points": [p.hash for p in points],
                       **({"staircase": True} if staircase else {})})
    return hashlib.sha256(data.encode()).hexdigest()[:16]


@contextmanager
def open_store(out_dir: str | Path, experiment: Experiment) -> Iterator[Store]:
    """Open ``out_dir`` for a sweep of ``experiment``, creating it or resuming it.

    A folder holding a different experiment (another seed or other grid points) is refused;
    the same experiment with another name, number of runs or chunk size resumes, and its
    manifest is updated.
    """
    root = Path(out_dir)
    for folder in (root, root / "points"):
        if folder.exists() and not folder.is_dir():
            raise ConfigError(f"{folder} is a file, where sarlink keeps a folder of results")
    root.mkdir(parents=True, exist_ok=True)
    points = [Point(params, mission, mission_hash(mission))
              for params, mission in experiment.points()]
    manifest = {
        "format": FORMAT,
        "identity": _identity(experiment.seed, points, experiment.staircase),
        "sarlink": version("sarlink"),
        "experiment": experiment.model_dump(mode="json"),
        "points": [{"hash": p.hash, "params": p.params} for p in points],
    }
    with _locked(root):
        if (root / MANIFEST).exists():
            old = read_manifest(root)
            if old["identity"] != manifest["identity"]:
                raise ConfigError(
                    f"{root} holds the results of another experiment "
                    f"({old['experiment']['name']!r}: other seed, mission or grid); "
                    "use another output folder"
                )
        for stale in root.glob("points/*/.*.tmp"):  # left by a killed sweep; we hold the lock
            stale.unlink()
        text = json.dumps(manifest, indent=2).encode()
        _write_atomic(root / MANIFEST, lambda fh: fh.write(text))
        yield Store(root, experiment.seed, points)


# -- loading -----------------------------------------------------------------------------------


def read_manifest(out_dir: str | Path) -> dict[str, Any]:
    """The manifest of a results folder (see the module docstring)."""
    path = Path(out_dir) / MANIFEST
    if not path.exists():
        raise FileNotFoundError(f"{out_dir} is not a sarlink results folder (no {MANIFEST})")
    try:
        manifest = json.loads(path.read_text())
    except ValueError as exc:  # not JSON, or not UTF-8
        raise ConfigError(f"{path} is damaged: {exc}; if the folder holds only this "
                          "experiment's runs, delete the file and run its sweep again") from None
    problem = _manifest_problem(manifest)
    if problem is not None:
        raise ConfigError(f"{path} {problem}")
    return typing.cast(dict[str, Any], manifest)


def _manifest_problem(manifest: Any) -> str | None:
    """Why ``manifest`` cannot be read by this sarlink, if it cannot."""
    if not isinstance(manifest, dict):
        return "is damaged: it holds no JSON object"
    ours = version("sarlink")
    theirs = manifest.get("sarlink", "an unknown version")
    layout = manifest.get("format")
    if isinstance(layout, int) and layout > FORMAT:
        return (f"was written by sarlink {theirs} in layout format {layout}; this sarlink "
                f"{ours} reads format {FORMAT}: upgrade sarlink to read it")
    if layout != FORMAT:
        return f"has layout format {layout}, this sarlink reads format {FORMAT}"
    try:
        Experiment.from_dict(manifest["experiment"])
        if not isinstance(manifest["identity"], str):
            raise TypeError("identity is not a string")
        for point in manifest["points"]:
            if not (isinstance(point["hash"], str) and isinstance(point["params"], dict)):
                raise TypeError("a grid point has no hash or parameters")
    except (ConfigError, KeyError, TypeError) as exc:
        return (f"is damaged or was written by another sarlink ({theirs}; this is {ours}): "
                f"{exc if not isinstance(exc, KeyError) else f'no {exc}'}")
    return None


def load(out_dir: str | Path) -> pd.DataFrame:
    """Every stored run of a results folder, one row per run, in grid order then run order.

    Columns: ``point`` (the grid point's index), ``seed``, ``run``, every flat mission
    parameter (``bs`` as a tuple or None, ``min_cells`` as a nullable integer), then the
    outcomes of :meth:`sarlink.RunResult.row`. Runs beyond the manifest's ``runs`` are left
    out; unusable files are skipped with a warning (a sweep in the folder redoes them).
    """
    root = Path(out_dir)
    manifest = read_manifest(root)
    stored = []
    for point in manifest["points"]:
        kept: _Stored = []
        for path, span, result in _scan(root / "points" / point["hash"], point["hash"],
                                        manifest["experiment"]["seed"]):
            if isinstance(result, str):
                warnings.warn(f"{path} is not loaded: {result}", stacklevel=2)
            else:
                kept.append((span, result))
        stored.append(kept)
    return _frame(stored, manifest["experiment"]["runs"])


def _with_checkpoints(table: pa.Table) -> pa.Table:
    """A table of one point with its ``checkpoints`` column, which files written before the
    engine stored it lack: the grid the engine used for the point's timing."""
    if "checkpoints" in table.column_names or table.num_rows == 0:
        return table
    timing = {name: table[name][0].as_py() for name in ("dt", "ts", "horizon", "checkpoint")}
    mission = Mission.build(**timing)
    times = [k * mission.timing.dt for k in mission.checkpoint_steps()]
    return table.append_column("checkpoints", pa.array([times] * table.num_rows))


def _hashable(value: Any) -> Any:
    """A list column's value as nested tuples (``bs``, a forcing table's rows), None kept."""
    if value is None:
        return None
    if isinstance(value, (np.ndarray, list, tuple)):
        return tuple(_hashable(v) for v in value)
    return value


def _frame(stored: Sequence[_Stored], runs: int) -> pd.DataFrame:
    """One DataFrame of runs ``0 .. runs-1`` from the valid files of each point, in order."""
    tables = []
    for index, files in enumerate(stored):
        for span, table in files:
            if span.start < runs:
                part = _with_checkpoints(table.slice(0, runs - span.start))
                tables.append(part.add_column(0, "point", pa.repeat(pa.scalar(index),
                                                                    part.num_rows)))
    if not tables:
        return pd.DataFrame(columns=["point", "seed", "run", *_param_columns()])
    df = pa.concat_tables(tables, promote_options="default").to_pandas()
    firsts = np.flatnonzero(np.diff(df["point"].to_numpy(), prepend=-1))
    for name, col in _param_columns().items():
        if name not in df:  # a parameter newer than the files
            continue
        if pa.types.is_list(col.type):  # hashable values, so that one can group by them
            heads = df[name].iloc[firsts]
            df[name] = df["point"].map(
                {p: _hashable(v) for p, v in zip(df["point"].iloc[firsts], heads, strict=True)})
        elif col.optional and pa.types.is_integer(col.type):
            df[name] = df[name].astype("Int64")
    return df
