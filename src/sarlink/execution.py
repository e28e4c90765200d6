"""Running an experiment (:class:`~sarlink.config.Experiment`).

:func:`sweep` cuts each point's missing runs into tasks of ``chunk`` runs, runs them in a local
process pool or on a Dask cluster, and writes each finished task as one Parquet file
(:mod:`sarlink.storage`); a sweep started again skips what is stored. :func:`sweep_all` does
the same for several experiments on one set of workers, which :func:`start_workers` can keep
across calls (``sarlink design`` sweeps its candidates in rounds).

Tasks that may share their flights are one job (:mod:`sarlink.engine.sharing`), with the same
rows as flying each: the same runs, with the same seed, of the points of a team that may fly
the same at every range (a route planner, a rule declared ``range_free`` such as CovB, drones
that do not report: see :attr:`sarlink.engine.run.Prepared.range_free`) that differ only in
``rc``, each run flown once and scanned at every range (:mod:`sarlink.engine.critical_ranges`);
and of a mission with drones that report and the same mission without reporting, whose runs
the former are taken from wherever no drone reports, in whichever folders they are (the
paper's ``main`` and ``report``). A job of one range flies as before, unless the experiment
asks for the notification staircase (``Experiment.staircase``): a flight scanned at several
ranges costs more than a plain one, which only a job of several ranges earns back.
"""

from __future__ import annotations

import dataclasses
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Generator, Iterator, Sequence
from concurrent.futures import Executor, Future, as_completed
from contextlib import ExitStack, closing, contextmanager
from pathlib import Path
from typing import Any, NamedTuple, Protocol

import pandas as pd
import pyarrow as pa
from loky import get_reusable_executor

from sarlink import storage
from sarlink.compile_times import Part, compile_estimate, describe_parts, record_compile
from sarlink.config import ConfigError, Experiment, Mission
from sarlink.config.experiment import MAX_WORKERS
from sarlink.engine.build import on_disk
from sarlink.engine.hooks import radio_identity
from sarlink.engine.radios import get_radio
from sarlink.engine.sharing import fly
from sarlink.planners import MTSP_PLANNERS, get_planner
from sarlink.progress import progress as progress_bars
from sarlink.simulation import (
    Plugins,
    adopt_plugins,
    check_mission,
    plugins_in_code,
    prepare,
)

__all__ = ["Workers", "start_workers", "sweep", "sweep_all"]


# -- tasks and their execution -----------------------------------------------------------------


class _Task(NamedTuple):
    store: storage.Store
    point: storage.Point
    runs: range
    staircase: bool = False


_Job = tuple[_Task, ...]
"""Tasks run together: one, or tasks of the same runs that may share their flights (the
points of a team that may fly the same at every range, differing only in ``rc``; a mission
with drones that report and the same without)."""

_Results = Generator[tuple[_Job, list[pa.Table]], None, None]
"""Finished jobs and their tables (one per task), in order of completion."""


def _plan(store: storage.Store, runs: int, chunk: int, staircase: bool = False) -> list[_Task]:
    """Tasks for every run not stored yet, first chunks of all points first.

    Planning from the stored run indices rather than from a fixed cut makes a resume with
    another chunk size neither redo nor double any run; the order lets a summary of a sweep
    half done cover every grid point.
    """
    tasks = [_Task(store, point, range(start, min(start + chunk, gap.stop)), staircase)
             for point in store.points
             for gap in store.missing(point, runs)
             for start in range(gap.start, gap.stop, chunk)]
    order = {point.hash: i for i, point in enumerate(store.points)}
    return sorted(tasks, key=lambda t: (t.runs.start, order[t.point.hash]))


def _may_share(mission: Mission) -> bool:
    """Whether ``mission``'s team may fly the same at every range, from its planner and radio
    alone (the worker checks the routes: :mod:`sarlink.engine.sharing`)."""
    rule = get_planner(mission.team.planner).rule
    return (get_radio(mission.radio).range_free and mission.team.on_detect == "continue"
            and (rule is None or rule.range_free or get_planner(mission.team.planner).kind
                 == "hybrid"))


def _flight(mission: Mission) -> str:
    """What the tasks of one job have in common: ``mission`` without reporting, and at no
    particular range if its team may fly the same at every range."""
    base = mission.replace(on_detect="continue", reporters="knowers", stop="horizon")
    return (base.replace(rc=1.0) if _may_share(base) else base).model_dump_json()


def _jobs(tasks: Sequence[_Task]) -> list[_Job]:
    """The tasks as jobs: those of the same seed and runs whose missions may share their
    flights (:func:`_flight`) together, in the order of their first task."""
    groups: dict[tuple[Any, ...], list[_Task]] = {}
    jobs: list[_Job | None] = []
    flights: dict[str, str] = {}  # by point: a point's tasks have one mission
    for task in tasks:
        if task.point.hash not in flights:
            flights[task.point.hash] = _flight(task.point.mission)
        key = (task.store.seed, task.runs.start, task.runs.stop, flights[task.point.hash])
        if key not in groups:
            groups[key] = []
            jobs.append(None)  # a placeholder, keeping the order of the tasks
        groups[key].append(task)
    grouped = iter(groups.values())
    return [job if job is not None else tuple(next(grouped)) for job in jobs]


def _run_chunk(mission_jsons: list[str], staircase: list[bool], seed: int, start: int,
               stop: int, plugins: Plugins) -> list[pa.Table]:
    """A job: runs ``start .. stop-1`` of each mission, as a table each (in a worker process,
    with the plug-ins its caller registered in code), sharing the flights they share
    (:func:`sarlink.engine.sharing.fly`; ``staircase``: each mission's rows carry it)."""
    adopt_plugins(plugins)
    missions = [Mission.model_validate_json(text) for text in mission_jsons]
    rows = fly([prepare(mission) for mission in missions], staircase, seed, range(start, stop))
    return [storage.run_table(m, seed, r) for m, r in zip(missions, rows, strict=True)]


def _calls(jobs: Sequence[_Job]
           ) -> list[tuple[list[str], list[bool], int, int, int, Plugins]]:
    texts = {t.point.hash: t.point.mission.model_dump_json() for job in jobs for t in job}
    plugins = plugins_in_code()
    return [([texts[t.point.hash] for t in job], [t.staircase for t in job], job[0].store.seed,
             job[0].runs.start, job[0].runs.stop, plugins) for job in jobs]


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

_IDLE_SECONDS = 300
"""How long a local pool's workers wait for the next sweep before they exit."""

_INHERITED = ("SARLINK_", "NUMBA_", "XDG_", "HOME")
"""The environment variables a worker reads (sarlink's cache, Numba's settings)."""

_last_pool: list[object] = [None]


def _local_pool(count: int) -> Executor:
    """``count`` worker processes, the same ones as the last sweep's when nothing they took
    from this process has changed since: the search path, the plug-ins registered in code
    and the environment variables they read. Starting a worker costs seconds (imports, the
    kernels loaded from Numba's cache); a caller that sweeps again (a notebook, ``reproduce``'s
    stages, a test suite) finds them warm. loky's reusable executor keeps them; they start
    as ``spawn`` starts them (a clean interpreter that imports the caller's main module, where
    a script's plug-ins live), when a task is submitted (:meth:`_Local.submit`)."""
    inherited = {k: v for k, v in os.environ.items() if k.startswith(_INHERITED)}
    key = (tuple(sys.path), plugins_in_code(), inherited)
    reuse = key == _last_pool[0]
    _last_pool[0] = key
    return get_reusable_executor(
        count, context="loky_init_main", timeout=_IDLE_SECONDS,
        reuse="auto" if reuse else False, initializer=_init_worker, initargs=(os.getpid(),))


def _compile(part: Part, plugins: Plugins) -> float:
    """Compile one Numba part in this worker, or load it from Numba's cache, and return the
    seconds it took.

    On a fresh machine every worker would otherwise compile each part at its first task;
    compiled once, the parts spread over the workers, the others then load them from the cache.
    """
    start = time.perf_counter()
    adopt_plugins(plugins)
    part.compile()
    return time.perf_counter() - start


def _compiled(part: Part) -> bool:
    """Whether Numba's disk cache already holds ``part``'s machine code (it then loads in a
    second or so)."""
    if part.kind == "mtsp":
        from sarlink.mtsp.ga import _ga_kernel

        return on_disk(_ga_kernel)
    if part.kind == "ranges":
        from sarlink.engine.critical_ranges import critical

        return on_disk(critical)
    return on_disk(part.kernel())


def _parts(jobs: Sequence[_Job]) -> list[Part]:
    """The compiled parts ``jobs`` need, in the order to compile them: the first kernel, the
    GA if they plan with it (no kernel needed: it runs beside the first), the other kernels
    (one per rule, radio model and seams), and the scan of the staircase if a job asks for it
    whose team may fly once for every range (after the kernels, whose first compile also
    compiles what they share; the others' rows have no staircase)."""
    missions = {t.point.hash: t.point.mission for job in jobs for t in job}.values()
    kernels: dict[tuple[object, ...], Part] = {}
    for m in missions:
        part = Part.kernel_of(m)
        seams = dataclasses.replace(part, planner="", radio="")
        kernels.setdefault((get_planner(m.team.planner).rule,
                            radio_identity(get_radio(m.radio)), seams), part)
    ga = any(m.team.planner in MTSP_PLANNERS and m.mtsp.solver == "ga" for m in missions)
    shared = next((t.point.mission for job in jobs for t in job
                   if t.staircase and _may_share(t.point.mission)), None)
    order = list(kernels.values())
    return [*order[:1], *([Part("mtsp")] if ga else []), *order[1:],
            *([Part("ranges", shared.team.planner, shared.radio)] if shared else [])]


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


class Workers(Protocol):
    """Worker processes started once (:func:`start_workers`) that run the tasks of any
    number of sweeps, so that a caller sweeping in rounds starts them only once."""

    def results(self, jobs: Sequence[_Job]) -> _Results:
        """Run ``jobs``; yield each with its tables as it finishes."""
        ...


class _Local:
    """A local process pool."""

    def __init__(self, pool: Executor, count: int) -> None:
        self.pool, self.count = pool, count

    def submit(self, fn: Callable[..., Any], *args: Any) -> Future[Any]:
        """Submit ``fn(*args)``; a worker started now inherits :data:`_WORKER_ENV`."""
        with _environment(_WORKER_ENV):
            return self.pool.submit(fn, *args)

    def compile(self, jobs: Sequence[_Job], progress: bool) -> None:
        """Compile the parts ``jobs`` need that Numba's disk cache lacks, on all workers at
        once, saying so first (a fresh machine spends minutes here, once)."""
        parts = [part for part in _parts(jobs) if not _compiled(part)]
        if not parts:
            return
        plugins = plugins_in_code()
        guess = compile_estimate(parts, self.count)
        with progress_bars(progress, "parts", rate=False) as bars:
            shown = bars.add_task(
                f"compiling the engine ({describe_parts(parts)}), once per machine: about "
                f"{guess:.0f} s", total=len(parts))
            futures = {self.submit(_compile, part, plugins): part for part in parts}
            for future in as_completed(futures):
                record_compile(futures[future], future.result())
                bars.advance(shown, 1)

    def results(self, jobs: Sequence[_Job]) -> _Results:
        futures = {self.submit(_run_chunk, *call): job
                   for call, job in zip(_calls(jobs), jobs, strict=True)}
        try:
            for future in as_completed(futures):
                yield futures[future], future.result()
        finally:
            for future in futures:
                future.cancel()


class _Dask:
    """The workers of a Dask cluster."""

    def __init__(self, client: Any) -> None:
        self.client = client

    def results(self, jobs: Sequence[_Job]) -> _Results:
        from distributed import as_completed as dask_completed

        futures = {self.client.submit(_run_chunk, *call, pure=False): job
                   for call, job in zip(_calls(jobs), jobs, strict=True)}
        try:
            for future in dask_completed(futures):
                yield futures[future], future.result()
        finally:
            self.client.cancel(list(futures))


def _check(workers: int | None, scheduler: str | None, dask_local: bool) -> None:
    if scheduler is not None and dask_local:
        raise ConfigError("scheduler and dask_local exclude each other")
    if scheduler is not None and workers is not None:
        raise ConfigError("workers does not apply to a Dask scheduler's cluster; "
                          "start its workers with `dask worker`")
    if workers is not None and not 1 <= workers <= MAX_WORKERS:
        raise ConfigError(f"workers must be between 1 and {MAX_WORKERS}, got {workers}")


@contextmanager
def start_workers(workers: int | None = None, *, scheduler: str | None = None,
                  dask_local: bool = False) -> Iterator[Workers]:
    """Workers for :func:`sweep_all`: a local process pool of ``workers`` processes (default:
    one per core), a Dask ``LocalCluster`` (``dask_local``), or the Dask cluster at
    ``scheduler``. They stop when the context ends."""
    _check(workers, scheduler, dask_local)
    count = workers or os.cpu_count() or 1
    if scheduler is None and not dask_local:
        pool = _local_pool(count)
        try:
            yield _Local(pool, count)
        except BaseException:  # Ctrl-C or a failed task: the queue was cancelled, wait for
            pool.shutdown(wait=True)  # the running tasks; the next sweep starts new workers
            raise
        return
    from distributed import Client, LocalCluster

    with ExitStack() as stack:
        if scheduler is None:
            cluster = stack.enter_context(LocalCluster(
                n_workers=count, threads_per_worker=1, processes=True,
                dashboard_address=None, env=_WORKER_ENV))
            client = stack.enter_context(Client(cluster))
        else:
            try:
                client = stack.enter_context(Client(scheduler))
            except (OSError, ValueError, TypeError) as exc:  # unreachable, or not an address
                raise ConfigError(f"cannot reach the Dask scheduler {scheduler}: {exc}") from None
        yield _Dask(client)


def _check_names(experiment: Experiment) -> None:
    """Raise a :class:`ConfigError` naming the experiment's key (``mission.team.planner`` or
    a grid point) unless every planner, radio model and relay strategy it names is known."""
    try:
        check_mission(experiment.mission)
    except ConfigError as exc:
        if not {"planner", "radio", "relay_strategy"} & set(experiment.grid):
            raise ConfigError(f"mission.{exc}") from None
    for params, mission in experiment.points():
        try:
            check_mission(mission)
        except ConfigError as exc:
            point = ", ".join(f"{k}={v!r}" for k, v in params.items())
            raise ConfigError(f"grid point {point}: {exc}") from None


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
    (runs,) = sweep_all([(experiment, out_dir)], workers=workers, scheduler=scheduler,
                        dask_local=dask_local, progress=progress)
    return runs


def sweep_all(jobs: Sequence[tuple[Experiment, str | Path]], *, workers: int | None = None,
              scheduler: str | None = None, dask_local: bool = False, progress: bool = True,
              on_runs: Callable[[int], None] | None = None,
              pool: Workers | None = None) -> list[pd.DataFrame]:
    """Sweep several experiments, each into its own folder, with one set of workers.

    The same as :func:`sweep` for each ``(experiment, out_dir)`` of ``jobs``, but their tasks
    share the workers: ``pool`` (from :func:`start_workers`, kept by the caller across
    calls), or workers started for this call as ``workers``, ``scheduler`` and ``dask_local``
    say. ``on_runs(k)`` is called whenever ``k`` more runs are stored. Returns the runs of
    each experiment, in the order of ``jobs``.
    """
    _check(workers, scheduler, dask_local)
    with ExitStack() as stack:
        for experiment, _ in jobs:  # planners and radio models by name, before any work
            _check_names(experiment)
        stores = [stack.enter_context(storage.open_store(out_dir, experiment))
                  for experiment, out_dir in jobs]
        tasks = [task for store, (experiment, _) in zip(stores, jobs, strict=True)
                 for task in _plan(store, experiment.runs, experiment.chunk,
                                   experiment.staircase)]
        if tasks:
            batches = _jobs(tasks)
            if pool is None:
                pool = stack.enter_context(start_workers(
                    workers, scheduler=scheduler, dask_local=dask_local))
            total = sum(experiment.runs * len(store.points)
                        for store, (experiment, _) in zip(stores, jobs, strict=True))
            name = jobs[0][0].name if len(jobs) == 1 else f"{len(jobs)} experiments"
            if isinstance(pool, _Local):
                pool.compile(batches, progress)
            with progress_bars(progress, "runs") as bar, \
                    closing(pool.results(batches)) as results:
                shown = bar.add_task(name, total=total,
                                     completed=total - sum(len(t.runs) for t in tasks))
                for job, tables in results:
                    for task, table in zip(job, tables, strict=True):
                        task.store.write(task.point, task.runs, table)
                        bar.advance(shown, len(task.runs))
                        if on_runs is not None:
                            on_runs(len(task.runs))
        return [store.frame(experiment.runs)
                for store, (experiment, _) in zip(stores, jobs, strict=True)]
