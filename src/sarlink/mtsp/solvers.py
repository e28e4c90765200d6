"""One entry point for every mTSP solver: arguments checked once, the plan built once."""

from __future__ import annotations

import math
import time
from typing import Any

import numpy as np

from sarlink.mtsp.ga import solve_ga
from sarlink.mtsp.ortools import ORTOOLS_SOLUTIONS, solve_ortools
from sarlink.mtsp.plan import MtspPlan, Objective, Solver
from sarlink.mtsp.ruin import ruin_steps, solve_minmax

__all__ = ["budget_of", "solve"]


def budget_of(solver: Solver, objective: Objective, points: int, salesmen: int,
              iterations: int, budget: int | None = None) -> int:
    """The search budget a solve spends, the only thing besides its inputs and seed that
    shapes a plan: the GA's ``iterations``; the strong solver's ``budget``, or by default
    :data:`~sarlink.mtsp.ortools.ORTOOLS_SOLUTIONS` solutions of OR-Tools' search (minsum) or
    :func:`~sarlink.mtsp.ruin.ruin_steps` steps per ruin-and-recreate search (minmax)."""
    if solver == "ga":
        return iterations
    if budget is not None:
        return budget
    return ORTOOLS_SOLUTIONS if objective == "minsum" else ruin_steps(points, salesmen)


def solve(
    points: np.ndarray,
    depot: tuple[float, float],
    salesmen: int,
    *,
    solver: Solver = "ga",
    objective: Objective = "minsum",
    min_cells: int | None = None,
    population: int = 80,
    iterations: int = 5000,
    seed: int = 0,
    budget: int | None = None,
) -> MtspPlan:
    """Plan closed tours from ``depot`` that visit every point exactly once.

    Parameters
    ----------
    points
        The cities, shape ``(K, 2)``: the cell centres of :func:`grid_cells`, or any points.
    depot
        Start and end of every tour (the BS).
    salesmen
        Number of tours, ``1 <= salesmen <= K``; every salesman visits at least one point.
    solver
        ``"ga"``: Kirk's genetic algorithm (the paper's); ``"ortools"``: the strong solver,
        OR-Tools routing under ``minsum`` and a ruin-and-recreate search under ``minmax``
        (:mod:`sarlink.mtsp.ruin`, where OR-Tools stalls).
    objective
        ``"minsum"``: total distance (the paper's); ``"minmax"``: the longest tour, which is
        what bounds the search time of a team.
    min_cells
        Minimum points per salesman; ``None`` means ``floor(K / salesmen)``, which balances the
        tours enough that two drones finish the paper's search within their flight budget.
    population, iterations, seed
        GA settings. The population is rounded down to a multiple of 8 (groups of 8). The seed
        is the only source of randomness of the GA and of the min-max search; OR-Tools routing
        (``ortools``, ``minsum``) has no random seed and ignores it.
    budget
        The strong solver's budget (``solver="ortools"``): under ``minsum`` the solutions
        OR-Tools' guided local search may generate, under ``minmax`` the steps of each of the
        three ruin-and-recreate searches; ``None`` means the default of :func:`budget_of`.
        No solver stops at a time: a plan is a function of its arguments only, the same on
        every machine however busy (``seconds`` is the one field that varies).
    """
    pts = np.asarray(points, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) == 0:
        raise ValueError(f"points must have shape (K, 2) with K >= 1, got {pts.shape}")
    if not np.isfinite(pts).all():
        raise ValueError("points must be finite")
    if len(depot) != 2 or not all(math.isfinite(float(c)) for c in depot):
        raise ValueError(f"depot must be two finite coordinates (x, y), got {depot!r}")
    dep = (float(depot[0]), float(depot[1]))
    k = len(pts)
    _check_int("salesmen", salesmen, 1, k, f"{k}, the number of points")
    if solver not in ("ga", "ortools"):
        raise ValueError(f"solver must be 'ga' or 'ortools', got {solver!r}")
    if objective not in ("minsum", "minmax"):
        raise ValueError(f"objective must be 'minsum' or 'minmax', got {objective!r}")
    most = k // salesmen
    if min_cells is None:
        min_cells = most
    _check_int("min_cells", min_cells, 1, most, f"{most} = floor({k} points / {salesmen} salesmen)")
    _check_int("population", population, 8, None)
    _check_int("iterations", iterations, 1, None)
    _check_int("seed", seed, 0, None)
    if budget is not None:
        _check_int("budget", budget, 1, None)
    steps = budget_of(solver, objective, k, salesmen, iterations, budget)

    start = time.perf_counter()
    evaluations = None
    if solver == "ga":
        tours, history, evaluations = solve_ga(pts, dep, salesmen, objective, min_cells,
                                               population // 8 * 8, iterations, seed)
    elif objective == "minmax":
        tours = solve_minmax(pts, dep, salesmen, min_cells, seed, iterations=steps)
        history = np.empty(0)
    else:
        tours, history = solve_ortools(pts, dep, salesmen, min_cells, steps), np.empty(0)
    return MtspPlan(points=pts, depot=dep, tours=tours, min_cells=min_cells, solver=solver,
                    objective=objective, history=history, seconds=time.perf_counter() - start,
                    evaluations=evaluations)


def _check_int(name: str, value: Any, lo: int, hi: int | None, hi_text: str = "") -> None:
    """Raise a ValueError naming ``name`` and its allowed range unless ``lo <= value <= hi``."""
    ok = isinstance(value, int | np.integer) and not isinstance(value, bool)
    if ok and value >= lo and (hi is None or value <= hi):
        return
    allowed = f"an integer >= {lo}" if hi is None else f"an integer in [{lo}, {hi_text or hi}]"
    raise ValueError(f"{name} must be {allowed}, got {value!r}")
