"""Plans for missions, made once: memoised per process and stored on disk (docs/mtsp.md).

Plans depend only on the area, ``r``, the BS, the number of drones and the solver settings, so
the cache key is a hash of exactly those; the files are written atomically and locked while a
plan is solved, so parallel workers solve each plan once.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import tempfile
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from filelock import FileLock

from sarlink.cachedir import cache_root
from sarlink.config import ConfigError
from sarlink.mtsp.clip import area_cells, area_key, is_polygon
from sarlink.mtsp.grid import grid_cells
from sarlink.mtsp.plan import MtspPlan
from sarlink.mtsp.solvers import budget_of, solve

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["CACHE_VERSION", "cache_dir", "clear_cache", "plan_for", "solve_for"]

MAX_CELLS = 10_000
"""Most cells of a plan: the solvers hold a dense distance matrix (800 MB at this size)."""

CACHE_VERSION = 4
"""Bumped whenever a solver or the file format changes, so that old plans are not reused
(4: the strong solver stops at a budget, never at a time)."""

STRONG_BUDGET: int | None = None
"""The strong solver's budget for missions' plans; None: :func:`sarlink.mtsp.budget_of`'s
default. Part of the cache key (resolved), like every setting that shapes a plan."""


_MEMO: dict[str, MtspPlan] = {}


def cache_dir() -> Path:
    """Where plans are stored: ``$SARLINK_CACHE_DIR/plans`` if the variable is set, else
    ``$XDG_CACHE_HOME/sarlink/plans`` (``~/.cache/sarlink/plans`` by default)."""
    return cache_root() / "plans"


def clear_cache(*, disk: bool = True) -> int:
    """Forget the plans memoised in this process and, if ``disk``, delete the stored ones.

    Returns the number of files deleted.
    """
    _MEMO.clear()
    if not disk:
        return 0
    removed = 0
    for path in cache_dir().glob("*.json"):
        path.unlink(missing_ok=True)
        removed += 1
    return removed


def _plan_params(mission: Mission, salesmen: int, cells: int) -> dict[str, Any]:
    """Everything a mission's plan depends on; ``min_cells`` resolved so None shares a key."""
    m = mission.mtsp
    min_cells = m.min_cells if m.min_cells is not None else cells // salesmen
    area = {"area": area_key(mission)} if is_polygon(mission) else {}
    return {
        **area,
        "version": CACHE_VERSION,
        "size": mission.area.size,
        "r": mission.sensing.r,
        "bs": list(mission.area.bs_xy),
        "salesmen": salesmen,
        "solver": m.solver,
        "objective": m.objective,
        "min_cells": min_cells,
        "population": m.population,
        "iterations": m.iterations,
        "plan_seed": m.plan_seed,
        "budget": budget_of(m.solver, m.objective, cells, salesmen, m.iterations, STRONG_BUDGET),
    }


def solve_for(mission: Mission, salesmen: int) -> MtspPlan:
    """Solve the mTSP plan for ``salesmen`` drones in ``mission`` now, bypassing every cache.

    The cities are the cells of :func:`grid_cells` for ``mission.area.size`` and
    ``mission.sensing.r`` (on a polygon area, :func:`sarlink.mtsp.clip.area_cells`); the
    depot is the BS; solver settings come from ``mission.mtsp``.
    A :class:`ConfigError` names the setting when the mission admits no plan.
    """
    points, params = _checked_params(mission, salesmen)
    m = mission.mtsp
    return solve(points, mission.area.bs_xy, salesmen, solver=m.solver, objective=m.objective,
                 min_cells=params["min_cells"], population=m.population,
                 iterations=m.iterations, seed=m.plan_seed, budget=STRONG_BUDGET)


def plan_for(mission: Mission, salesmen: int, *, compact: bool = False) -> MtspPlan:
    """The plan of :func:`solve_for`, computed once and cached.

    Plans are memoised in the process and stored as JSON in :func:`cache_dir`, under a hash
    of everything they depend on (:data:`CACHE_VERSION` included). Files are written
    atomically; an unreadable file counts as missing and is rewritten. A process about to
    solve a plan holds a lock on it, so workers that need the same plan at once solve it
    once and all use that one. ``compact`` plans (one per run: thousands of them) are stored
    without the GA's history, some 2 kB instead of 100 kB, under keys of their own, and are
    not memoised.
    """
    points, params = _checked_params(mission, salesmen)
    if compact:
        params["history"] = False
    key = hashlib.sha256(json.dumps(params, sort_keys=True).encode()).hexdigest()[:32]
    if key in _MEMO:
        return _MEMO[key]
    path = cache_dir() / f"{key}.json"
    plan = _read_plan(path, params, points)
    if plan is None:
        with _solve_lock(path):
            plan = _read_plan(path, params, points)  # solved while this process waited?
            if plan is None:
                plan = solve_for(mission, salesmen)
                if compact:
                    plan = replace(plan, history=np.empty(0))
                _write_plan(path, params, plan, sync=not compact)
    if not compact:
        _MEMO[key] = plan
    return plan


@contextmanager
def _solve_lock(path: Path) -> Iterator[None]:
    """Hold a lock on ``path``'s plan while it is solved, if the cache folder allows one;
    with an unwritable cache every process solves on its own, as :func:`_write_plan` warns."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        lock = FileLock(path.with_suffix(".lock"))
        lock.acquire()
    except OSError:
        yield
        return
    try:
        yield
    finally:
        lock.release()


def _checked_params(mission: Mission, salesmen: int) -> tuple[np.ndarray, dict[str, Any]]:
    """The cells and the plan parameters, or a :class:`ConfigError` if no plan exists."""
    if is_polygon(mission):
        points = area_cells(mission)
        if len(points) > MAX_CELLS:
            raise ConfigError(f"an mTSP plan has at most {MAX_CELLS:,} cells; the area holds "
                              f"{len(points):,} cells of side sensing.r = {mission.sensing.r:g} m")
    else:
        side = math.ceil(mission.area.size / mission.sensing.r - 1e-9)
        if side * side > MAX_CELLS:
            raise ConfigError(f"an mTSP plan has at most {MAX_CELLS:,} cells: area.size / "
                              f"sensing.r must be at most {math.isqrt(MAX_CELLS)}, got "
                              f"{mission.area.size:g} / {mission.sensing.r:g}")
        points = grid_cells(mission.area.size, mission.sensing.r)
    cells, min_cells = len(points), mission.mtsp.min_cells
    if not 1 <= salesmen <= cells:
        raise ConfigError(f"an mTSP plan needs 1 to {cells} drones, one per cell at most "
                          f"({cells} cells of side r in the area), got {salesmen}")
    if min_cells is not None and min_cells * salesmen > cells:
        raise ConfigError(f"mtsp.min_cells must be at most {cells // salesmen} = floor({cells} "
                          f"cells / {salesmen} drones), got {min_cells}")
    return points, _plan_params(mission, salesmen, cells)


def _read_plan(path: Path, params: dict[str, Any], points: np.ndarray) -> MtspPlan | None:
    """The stored plan, or None if it is missing, unreadable or made for other parameters."""
    try:
        data = json.loads(path.read_text())
        if data["params"] != params:
            return None
        return MtspPlan(points=points, depot=tuple(params["bs"]), tours=data["tours"],
                        min_cells=params["min_cells"], solver=params["solver"],
                        objective=params["objective"],
                        history=data["history"], seconds=data["seconds"])
    except (OSError, ValueError, KeyError, TypeError):
        return None


def _write_plan(path: Path, params: dict[str, Any], plan: MtspPlan, *, sync: bool) -> None:
    """Write via a temporary file in the same directory and ``os.replace``: a crash mid-write
    leaves either the old file or none, never a partial one.

    With ``sync`` the file is on disk before it is moved into place, so a plan survives a
    power cut. Plans made per run skip it: it made writing one 7 ms instead of 0.5 ms on a
    busy disk (benchmarks/results/per-run-plans.md), and a file the cut left empty or partial
    does not read (:func:`_read_plan`), so that plan is only made again."""
    data = {"params": params, "tours": [list(t) for t in plan.tours],
            "lengths": plan.lengths.tolist(), "history": plan.history.tolist(),
            "seconds": plan.seconds}
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile("w", dir=path.parent, prefix=path.stem,
                                         suffix=".tmp", delete=False) as fh:
            tmp = fh.name
            json.dump(data, fh)
            fh.flush()
            if sync:
                os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        if tmp is not None:
            Path(tmp).unlink(missing_ok=True)
        warnings.warn(f"could not cache the mTSP plan in {path.parent}: {exc}", stacklevel=3)
