"""Experiments: a base mission, a grid over its parameters, many runs per grid point.

Common random numbers: every grid point uses the experiment's one seed and the run indices
``0 .. runs-1``, and run ``k`` draws its target and take-off from ``(seed, k)`` alone. So run
``k`` of every grid point searches for the same target, differences between points are not
blurred by different targets, and no row depends on how the runs were cut into tasks or spread
over workers.

:func:`sweep` cuts each point's missing runs into tasks of ``chunk`` runs, runs them in a local
process pool or on a Dask cluster, and writes each finished task as one Parquet file
(:mod:`sarlink.storage`); a sweep started again skips what is stored.
"""

from __future__ import annotations

import itertools
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Generator, Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from contextlib import ExitStack, closing, contextmanager
from pathlib import Path
from typing import Any, NamedTuple, Self

import pandas as pd
import pyarrow as pa
from pydantic import Field, field_validator, model_validator
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    ProgressColumn,
    Task,
    TextColumn,
    TimeRemainingColumn,
)
from rich.text import Text

from sarlink import storage
from sarlink.config import Checked, ConfigError, Mission, param_groups
from sarlink.engine import prepare

__all__ = ["Experiment", "sweep"]


def _label(params: dict[str, Any]) -> str:
    return ", ".join(f"{k}={v!r}" for k, v in params.items()) or "(the base mission)"


class Experiment(Checked):
    """A base mission, a grid of parameter values, and ``runs`` runs of every grid point.

    ``grid`` maps flat mission parameters (``planner``, ``drones``, ``rc``, ``p_miss``, ...; see
    :meth:`Mission.params`) to the values to try; the grid points are their cartesian product.
    ``Experiment.from_toml`` reads ``name``, ``seed``, ``runs``, ``chunk``, ``[mission.*]``
    (the tables of :class:`Mission`) and ``[grid]``.
    """

    name: str = Field(min_length=1, description="a name for people; not part of the identity")
    seed: int = Field(ge=0, description="the one seed of every run of every grid point")
    runs: int = Field(ge=1, description="runs per grid point, indices 0 .. runs-1")
    chunk: int = Field(100, ge=1, description="runs per task; results do not depend on it")
    mission: Mission = Field(default_factory=Mission, description="the base mission")
    grid: dict[str, list[Any]] = Field(default_factory=dict,
                                       description="flat parameter -> values to try")

    @field_validator("grid")
    @classmethod
    def _known_parameters(cls, grid: dict[str, list[Any]]) -> dict[str, list[Any]]:
        known = param_groups()
        for name, values in grid.items():
            if name not in known:
                raise ValueError(f"unknown mission parameter {name!r}; "
                                 f"known: {', '.join(sorted(known))}")
            if not values:
                raise ValueError(f"{name!r} lists no values")
        return grid

    @model_validator(mode="after")
    def _valid_points(self) -> Self:
        self.points()
        return self

    def points(self) -> list[tuple[dict[str, Any], Mission]]:
        """Every grid point, in grid order (the last parameter varies fastest).

        Each point is its grid values, as the mission holds them (``rc = 500`` reads ``500.0``),
        and its mission. Raises ``ValueError`` naming the point if one is not a valid mission
        or two points are the same mission.
        """
        names = list(self.grid)
        points: list[tuple[dict[str, Any], Mission]] = []
        seen: dict[str, dict[str, Any]] = {}
        for values in itertools.product(*self.grid.values()):
            raw = dict(zip(names, values, strict=True))
            try:
                mission = self.mission.replace(**raw)
            except ConfigError as exc:
                raise ValueError(f"grid point {_label(raw)}: {exc}") from None
            flat = mission.params()
            params = {name: flat[name] for name in names}
            key = storage.mission_hash(mission)
            if key in seen:
                raise ValueError(f"grid points {_label(seen[key])} and {_label(params)} are the "
                                 "same mission")
            seen[key] = params
            points.append((params, mission))
        return points


# -- tasks and their execution -----------------------------------------------------------------


class _Task(NamedTuple):
    point: storage.Point
    runs: range


_Results = Generator[tuple[_Task, pa.Table], None, None]
"""Finished tasks and their tables, in order of completion."""


def _plan(store: storage.Store, runs: int, chunk: int) -> list[_Task]:
    """Tasks for every run not stored yet, first chunks of all points first.

    Planning from the stored run indices rather than from a fixed cut makes a resume with
    another chunk size neither redo nor double any run; the order lets a summary of a sweep
    half done cover every grid point.
    """
    tasks = [_Task(point, range(start, min(start + chunk, gap.stop)))
             for point in store.points
             for gap in store.missing(point, runs)
             for start in range(gap.start, gap.stop, chunk)]
    order = {point.hash: i for i, point in enumerate(store.points)}
    return sorted(tasks, key=lambda t: (t.runs.start, order[t.point.hash]))


def _run_chunk(mission_json: str, seed: int, start: int, stop: int) -> pa.Table:
    """A task: runs ``start .. stop-1`` of one mission, as a table (in a worker process)."""
    mission = Mission.model_validate_json(mission_json)
    prepared = prepare(mission)
    return storage.run_table(mission, seed, [prepared.run(seed, k).row()
                                             for k in range(start, stop)])


def _calls(tasks: Sequence[_Task], seed: int) -> list[tuple[str, int, int, int]]:
    texts = {t.point.hash: t.point.mission.model_dump_json() for t in tasks}
    return [(texts[t.point.hash], seed, t.runs.start, t.runs.stop) for t in tasks]


def _exit_with(parent: int) -> None:
    while os.getppid() == parent:
        time.sleep(1.0)
    os._exit(1)


def _init_worker(parent: int) -> None:
    """Leave Ctrl-C to the parent, which stops the queue, and end if the parent is killed.

    A pool worker otherwise outlives a parent killed by SIGKILL, waiting for work forever.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    threading.Thread(target=_exit_with, args=(parent,), daemon=True).start()


_WORKER_ENV = {"NUMBA_NUM_THREADS": "1"}
"""One core per worker process: parallelism comes from the processes."""


@contextmanager
def _environment(env: dict[str, str]) -> Iterator[None]:
    """Set ``env`` while the pool starts its processes, which inherit it before importing Numba."""
    saved = {name: os.environ.get(name) for name in env}
    os.environ.update(env)
    try:
        yield
    finally:
        for name, value in saved.items():
            if value is None:
                del os.environ[name]
            else:
                os.environ[name] = value


def _pool(tasks: Sequence[_Task], seed: int, workers: int) -> _Results:
    """Run ``tasks`` in a local process pool; yield each as it finishes."""
    # spawn: workers start from a clean interpreter (no forked threads or locks), with the
    # environment of the moment they start
    context = multiprocessing.get_context("spawn")
    with _environment(_WORKER_ENV), ProcessPoolExecutor(
            workers, mp_context=context, initializer=_init_worker,
            initargs=(os.getpid(),)) as pool:
        futures = {pool.submit(_run_chunk, *call): task
                   for call, task in zip(_calls(tasks, seed), tasks, strict=True)}
        try:
            for future in as_completed(futures):
                yield futures[future], future.result()
        finally:
            pool.shutdown(cancel_futures=True)


def _dask(tasks: Sequence[_Task], seed: int, scheduler: str | None,
          workers: int) -> _Results:
    """Run ``tasks`` on the Dask cluster at ``scheduler``, or on a new local one."""
    from distributed import Client, LocalCluster
    from distributed import as_completed as dask_completed

    with ExitStack() as stack:
        if scheduler is None:
            cluster = stack.enter_context(LocalCluster(
                n_workers=workers, threads_per_worker=1, processes=True,
                dashboard_address=None, env=_WORKER_ENV))
            client = stack.enter_context(Client(cluster))
        else:
            try:
                client = stack.enter_context(Client(scheduler))
            except OSError as exc:
                raise ConfigError(f"cannot reach the Dask scheduler {scheduler}: {exc}") from None
        futures = {client.submit(_run_chunk, *call, pure=False): task
                   for call, task in zip(_calls(tasks, seed), tasks, strict=True)}
        try:
            for future in dask_completed(futures):
                yield futures[future], future.result()
        finally:
            client.cancel(list(futures))


class _RunsPerSecond(ProgressColumn):
    def render(self, task: Task) -> Text:
        speed = task.finished_speed or task.speed
        return Text("? runs/s" if speed is None else f"{speed:,.0f} runs/s",
                    style="progress.data.speed")


def _progress_bar(enabled: bool) -> Progress:
    return Progress(
        TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TextColumn("runs"),
        _RunsPerSecond(), TimeRemainingColumn(), disable=not enabled,
    )


def sweep(experiment: Experiment, out_dir: str | Path, *, workers: int | None = None,
          scheduler: str | None = None, dask_local: bool = False,
          progress: bool = True) -> pd.DataFrame:
    """Run ``experiment`` into ``out_dir`` and return all its runs, as :func:`sarlink.load`
    would read them back.

    Runs already stored in ``out_dir`` are kept and not run again, so an interrupted sweep
    resumes where it stopped; the rows are the same whatever the workers or chunk size.

    Parameters
    ----------
    workers
        Worker processes of the local pool or of the ``dask_local`` cluster; default: one per
        core (``os.cpu_count()``).
    scheduler
        Address of a running Dask scheduler, ``tcp://host:port``, to run the tasks on its
        cluster. The results are written by this process, so workers need no shared disk.
    dask_local
        Start a Dask ``LocalCluster`` instead of the process pool.
    progress
        Show a progress bar (only when standard output is a terminal).
    """
    if scheduler is not None and dask_local:
        raise ConfigError("scheduler and dask_local exclude each other")
    if scheduler is not None and workers is not None:
        raise ConfigError("workers does not apply to a Dask scheduler's cluster; "
                          "start its workers with `dask worker`")
    if workers is not None and workers < 1:
        raise ConfigError(f"workers must be at least 1, got {workers}")
    with storage.open_store(out_dir, experiment) as store:
        tasks = _plan(store, experiment.runs, experiment.chunk)
        if tasks:
            n = min(workers or os.cpu_count() or 1, len(tasks))
            results = (_pool(tasks, experiment.seed, n) if scheduler is None and not dask_local
                       else _dask(tasks, experiment.seed, scheduler, n))
            total = experiment.runs * len(store.points)
            with _progress_bar(progress and sys.stdout.isatty()) as bar, closing(results):
                job = bar.add_task(experiment.name, total=total,
                                   completed=total - sum(len(t.runs) for t in tasks))
                for task, table in results:
                    store.write(task.point, task.runs, table)
                    bar.advance(job, len(task.runs))
        return store.frame(experiment.runs)
