"""mTSP plans for the centralized planners (Section 3.1.1 of the paper).

The search area is cut into square cells whose centres are the cities; a multiple travelling
salesmen plan sends every drone from the base station (BS, the depot) through its own cells
and back. Two solvers give the same :class:`MtspPlan`:

``ga``
    The paper's genetic algorithm, after Joseph Kirk's MATLAB ``mtspf_ga`` (fixed start and end
    at the depot), compiled with Numba. Faithful, seeded, about a second for 80 × 5000 on 64
    cells.
``ortools``
    OR-Tools routing with guided local search: a strong solver to measure the GA against. It is
    chosen over PyVRP because it supports both objectives and the minimum number of cells per
    drone directly (PyVRP minimises total distance only and has no lower bound on route size).

Plans depend only on the area, ``r``, the BS, the number of drones and the solver settings, so
:func:`plan_for` computes each once and caches it on disk.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import tempfile
import time
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from filelock import FileLock
from numba import njit

from sarlink.config import ConfigError

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = [
    "CACHE_VERSION",
    "ORTOOLS_TIME_LIMIT",
    "MtspPlan",
    "cache_dir",
    "clear_cache",
    "grid_cells",
    "plan_for",
    "solve",
    "solve_for",
]

Solver = Literal["ga", "ortools"]
Objective = Literal["minsum", "minmax"]

CACHE_VERSION = 1
"""Bumped whenever a solver or the file format changes, so that old plans are not reused."""

ORTOOLS_TIME_LIMIT = 5.0
"""Default OR-Tools search time, s. Guided local search never stops by itself; on the 64-cell
grid, 2 s already gives nearly the same plans (docs/mtsp.md), and a plan is made once."""

_ORTOOLS_TICKS = 1_000_000
"""OR-Tools needs integer arc costs: the longest arc is scaled to this many ticks."""

_ORTOOLS_ROUNDS = 4
"""Min-max: rounds of search against a lowered bound on every tour."""

_ORTOOLS_EXCESS_COST = 1000
"""Min-max: cost of one tick of a tour beyond the bound, against one per tick of distance."""


# -- cells ------------------------------------------------------------------------------------


def grid_cells(size: float, r: float) -> np.ndarray:
    """Centres of the square cells of side ``r`` that cover the area ``[0, size]²``.

    There are ``n = ceil(size / r)`` cells per side (8 for the paper's 4000 m and 500 m, so 64
    cells). Cell ``k`` lies in column ``k % n`` (x) and row ``k // n`` (y), rows counted from
    ``y = 0``: row-major order. When ``size / r`` is not an integer, the last column and row
    are moved inwards so that their centres stay ``r / 2`` from the border (the last cells then
    overlap their neighbours instead of sticking out of the area); when ``r > size`` the single
    cell is centred in the area.

    Returns
    -------
    np.ndarray
        Shape ``(n², 2)``, the cell centres (x, y) in metres.
    """
    if not (math.isfinite(size) and size > 0):
        raise ValueError(f"size must be a finite number > 0, got {size}")
    if not (math.isfinite(r) and r > 0):
        raise ValueError(f"r must be a finite number > 0, got {r}")
    n = max(1, math.ceil(size / r - 1e-9))
    centres = np.minimum((np.arange(n) + 0.5) * r, max(size - r / 2, size / 2))
    xs, ys = np.meshgrid(centres, centres)
    return np.column_stack([xs.ravel(), ys.ravel()])


# -- the plan ---------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class MtspPlan:
    """An mTSP plan: which points each salesman (drone) visits, in order, from and to the depot.

    The plan checks itself on construction: the tours must visit every point exactly once, each
    at least ``min_cells`` of them.
    Arrays are read-only, so a plan can be shared (it is memoised by :func:`plan_for`).
    """

    points: np.ndarray
    """The cities, shape ``(K, 2)``, metres."""
    depot: tuple[float, float]
    """Where every tour starts and ends (the BS)."""
    tours: tuple[tuple[int, ...], ...]
    """Per salesman, the indices into ``points`` in visiting order; the depot is not listed."""
    min_cells: int = 1
    """The least number of points any tour was allowed."""
    solver: Solver = "ga"
    objective: Objective = "minsum"
    history: np.ndarray = field(default_factory=lambda: np.empty(0))
    """GA: the best cost in each iteration's population (Kirk's ``dist_history``; the best of
    each group survives, so it never rises); empty for OR-Tools."""
    seconds: float = 0.0
    """Wall time of the solve that produced the plan (kept when the plan is read from cache)."""
    lengths: np.ndarray = field(init=False)
    """Per salesman the tour length in metres, including the legs from and to the depot."""

    def __post_init__(self) -> None:
        points = np.array(self.points, dtype=float)
        depot = (float(self.depot[0]), float(self.depot[1]))
        tours = tuple(tuple(int(i) for i in tour) for tour in self.tours)
        visited = sorted(i for tour in tours for i in tour)
        if visited != list(range(len(points))):
            raise ValueError("tours must visit every point index exactly once")
        if min(map(len, tours), default=0) < self.min_cells:
            raise ValueError(f"every tour must visit at least min_cells = {self.min_cells} points")
        lengths = np.array([_tour_length(points, depot, tour) for tour in tours])
        history = np.array(self.history, dtype=float)
        for arr in (points, lengths, history):
            arr.setflags(write=False)
        for name, value in (("points", points), ("depot", depot), ("tours", tours),
                            ("history", history), ("lengths", lengths)):
            object.__setattr__(self, name, value)

    @property
    def total(self) -> float:
        """Total distance flown by all salesmen, m (the paper's objective)."""
        return float(self.lengths.sum())

    @property
    def longest(self) -> float:
        """Length of the longest tour, m: with the speed, the time the search takes."""
        return float(self.lengths.max())

    def routes(self) -> tuple[np.ndarray, ...]:
        """Per salesman the waypoints to fly, shape ``(k + 1, 2)``: its points, then the depot.

        The drone takes off at the depot, so the depot is not repeated at the start.
        """
        return tuple(np.vstack([self.points[list(tour)], self.depot]) for tour in self.tours)


def _tour_length(points: np.ndarray, depot: tuple[float, float], tour: tuple[int, ...]) -> float:
    path = np.vstack([depot, points[list(tour)], depot])
    return float(np.hypot(*np.diff(path, axis=0).T).sum())


# -- solving ----------------------------------------------------------------------------------


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
    time_limit: float = ORTOOLS_TIME_LIMIT,
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
        ``"ga"``: Kirk's genetic algorithm (the paper's); ``"ortools"``: OR-Tools routing.
    objective
        ``"minsum"``: total distance (the paper's); ``"minmax"``: the longest tour, which is
        what bounds the search time of a team.
    min_cells
        Minimum points per salesman; ``None`` means ``floor(K / salesmen)``, which balances the
        tours enough that two drones finish the paper's search within their flight budget.
    population, iterations, seed
        GA settings. The population is rounded down to a multiple of 8 (groups of 8). The seed
        is the only source of randomness; OR-Tools routing has no random seed and ignores it.
    time_limit
        OR-Tools search time, s. A time-limited search may end at a different plan on a
        faster or slower machine; the GA does not depend on time.
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
    if not (math.isfinite(time_limit) and time_limit > 0):
        raise ValueError(f"time_limit must be a finite number of seconds > 0, got {time_limit}")

    start = time.perf_counter()
    if solver == "ga":
        tours, history = _solve_ga(pts, dep, salesmen, objective, min_cells,
                                   population // 8 * 8, iterations, seed)
    else:
        tours = _solve_ortools(pts, dep, salesmen, objective, min_cells, time_limit)
        history = np.empty(0)
    return MtspPlan(points=pts, depot=dep, tours=tours, min_cells=min_cells, solver=solver,
                    objective=objective, history=history, seconds=time.perf_counter() - start)


def _check_int(name: str, value: Any, lo: int, hi: int | None, hi_text: str = "") -> None:
    """Raise a ValueError naming ``name`` and its allowed range unless ``lo <= value <= hi``."""
    ok = isinstance(value, int | np.integer) and not isinstance(value, bool)
    if ok and value >= lo and (hi is None or value <= hi):
        return
    allowed = f"an integer >= {lo}" if hi is None else f"an integer in [{lo}, {hi_text or hi}]"
    raise ValueError(f"{name} must be {allowed}, got {value!r}")


def _distances(points: np.ndarray, depot: tuple[float, float]) -> np.ndarray:
    """Euclidean distance matrix over the depot (index 0) and the points (1..K)."""
    coords = np.vstack([depot, points])
    diff = coords[:, None, :] - coords[None, :, :]
    return np.sqrt((diff**2).sum(axis=-1))


def _solve_ga(
    points: np.ndarray, depot: tuple[float, float], salesmen: int, objective: Objective,
    min_cells: int, population: int, iterations: int, seed: int,
) -> tuple[tuple[tuple[int, ...], ...], np.ndarray]:
    rng = np.random.default_rng(seed)
    route, breaks, history = _ga_kernel(_distances(points, depot), salesmen, min_cells,
                                        population, iterations, objective == "minmax", rng)
    bounds = [0, *breaks.tolist(), len(points)]
    tours = tuple(tuple(int(c) - 1 for c in route[bounds[s]:bounds[s + 1]])
                  for s in range(salesmen))
    return tours, history


@njit(cache=True)
def _cost(dmat: np.ndarray, route: np.ndarray, breaks: np.ndarray, minmax: bool) -> float:
    """Total or longest tour length of one (route, breaks) individual; city 0 is the depot."""
    n = route.size
    total = 0.0
    longest = 0.0
    start = 0
    for s in range(breaks.size + 1):
        end = breaks[s] if s < breaks.size else n
        d = dmat[0, route[start]] + dmat[route[end - 1], 0]
        for q in range(start, end - 1):
            d += dmat[route[q], route[q + 1]]
        total += d
        longest = max(longest, d)
        start = end
    return longest if minmax else total


@njit(cache=True)
def _break_probabilities(dof: int, n_breaks: int) -> np.ndarray:
    """Kirk's cumulative law of the number of spare points handed to the first salesmen.

    ``addto[j]`` is proportional to the number of ways to share ``j`` spare points among
    ``n_breaks`` salesmen; it is normalised at every step so that it cannot overflow.
    """
    addto = np.ones(dof + 1)
    for _ in range(1, n_breaks):
        addto = np.cumsum(addto)
        addto /= addto[-1]
    cum = np.cumsum(addto)
    return cum / cum[-1]


@njit(cache=True)
def _random_breaks(
    out: np.ndarray, n: int, min_tour: int, cum_prob: np.ndarray, scratch: np.ndarray,
    adjust: np.ndarray, rng: np.random.Generator,
) -> None:
    """Kirk's ``randbreaks``: sorted break points leaving every salesman ``min_tour`` points."""
    n_breaks = out.size
    if n_breaks == 0:
        return
    if min_tour == 1:
        # a uniform random subset of the positions 1..n-1 (partial Fisher-Yates)
        for q in range(n - 1):
            scratch[q] = q + 1
        for q in range(n_breaks):
            j = q + int((n - 1 - q) * rng.random())
            scratch[q], scratch[j] = scratch[j], scratch[q]
        out[:] = scratch[:n_breaks]
        out.sort()
        return
    u = rng.random()
    spare = cum_prob.size - 1
    for j in range(cum_prob.size):
        if u < cum_prob[j]:
            spare = j
            break
    adjust[:] = 0
    for _ in range(spare):
        adjust[int(n_breaks * rng.random())] += 1
    extra = 0
    for b in range(n_breaks):
        extra += adjust[b]
        out[b] = min_tour * (b + 1) + extra


@njit(cache=True)
def _ga_kernel(
    dmat: np.ndarray, salesmen: int, min_tour: int, pop_size: int, iterations: int,
    minmax: bool, rng: np.random.Generator,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Kirk's ``mtspf_ga``: the depot is city 0, the cities 1..n are permuted and split.

    An individual is a permutation ``route`` of 1..n and sorted ``breaks``: salesman ``s``
    visits ``route[breaks[s-1]:breaks[s]]`` (with 0 and n at the ends). Returns the best route,
    its breaks and the best cost in each iteration's population.
    """
    n = dmat.shape[0] - 1
    n_breaks = salesmen - 1
    cum_prob = _break_probabilities(n - min_tour * salesmen, n_breaks)
    scratch = np.empty(max(n - 1, 1), dtype=np.int64)
    adjust = np.empty(n_breaks, dtype=np.int64)

    pop_rte = np.empty((pop_size, n), dtype=np.int64)
    pop_brk = np.empty((pop_size, n_breaks), dtype=np.int64)
    for p in range(pop_size):
        pop_rte[p] = rng.permutation(n) + 1
        _random_breaks(pop_brk[p], n, min_tour, cum_prob, scratch, adjust, rng)
    new_rte = np.empty_like(pop_rte)
    new_brk = np.empty_like(pop_brk)

    costs = np.empty(pop_size)
    order = np.arange(pop_size)
    best_rte = pop_rte[0].copy()
    best_brk = pop_brk[0].copy()
    best_cost = np.inf
    history = np.empty(iterations)
    for it in range(iterations):
        for p in range(pop_size):
            costs[p] = _cost(dmat, pop_rte[p], pop_brk[p], minmax)
        p_min = np.argmin(costs)
        history[it] = costs[p_min]  # Kirk's dist_history: elitism keeps it from rising
        if costs[p_min] < best_cost:
            best_cost = costs[p_min]
            best_rte[:] = pop_rte[p_min]
            best_brk[:] = pop_brk[p_min]

        rng.shuffle(order)
        for g in range(0, pop_size, 8):
            b = order[g]
            for q in range(g + 1, g + 8):
                if costs[order[q]] < costs[b]:
                    b = order[q]
            i = int(n * rng.random())
            j = int(n * rng.random())
            if i > j:
                i, j = j, i
            for c in range(8):
                rte = new_rte[g + c]
                rte[:] = pop_rte[b]
                new_brk[g + c] = pop_brk[b]
                op = c % 4  # 0 keep, 1 flip, 2 swap, 3 slide; children 4..7 also re-break
                if op == 1:
                    rte[i:j + 1] = rte[i:j + 1][::-1].copy()
                elif op == 2:
                    rte[i], rte[j] = rte[j], rte[i]
                elif op == 3 and j > i:
                    first = rte[i]
                    rte[i:j] = rte[i + 1:j + 1].copy()
                    rte[j] = first
                if c >= 4:
                    _random_breaks(new_brk[g + c], n, min_tour, cum_prob, scratch, adjust, rng)
        pop_rte, new_rte = new_rte, pop_rte
        pop_brk, new_brk = new_brk, pop_brk
    return best_rte, best_brk, history


def _solve_ortools(
    points: np.ndarray, depot: tuple[float, float], salesmen: int, objective: Objective,
    min_cells: int, time_limit: float,
) -> tuple[tuple[int, ...], ...]:
    """OR-Tools routing from an angular sweep around the depot cut into equal parts.

    ``minsum`` is one guided local search on the arc costs. ``minmax`` is harder for OR-Tools:
    a global span cost (the longest tour) is flat wherever several tours are about as long,
    so local search stalls. It therefore runs in two halves: a guided local search with a span
    cost of weight 100 (OR-Tools' customary recipe, which does well for few drones), then
    rounds that penalise every tour's excess over a target below the best longest tour so far
    (a soft upper bound: shortening any long tour pays, which does well for many drones),
    lowering the target after each success. The plan with the shortest longest tour wins.
    """
    dist = _distances(points, depot)
    scale = _ORTOOLS_TICKS / dist.max() if dist.max() > 0 else 1.0
    ticks = np.rint(dist * scale).astype(np.int64)
    angles = np.arctan2(points[:, 1] - depot[1], points[:, 0] - depot[0])
    sweep = np.argsort(angles, kind="stable") + 1
    routes = [part.tolist() for part in np.array_split(sweep, salesmen)]
    if objective == "minsum":
        routes = _ortools_search(ticks, salesmen, min_cells, routes, time_limit)
    else:
        routes = _ortools_search(ticks, salesmen, min_cells, routes, time_limit / 2,
                                 span_weight=100)
        longest = _longest_ticks(ticks, routes)
        cut = 0.1
        for _ in range(_ORTOOLS_ROUNDS):
            found = _ortools_search(ticks, salesmen, min_cells, routes,
                                    time_limit / (2 * _ORTOOLS_ROUNDS),
                                    bound=round(longest * (1 - cut)))
            if _longest_ticks(ticks, found) < longest:
                routes, longest = found, _longest_ticks(ticks, found)
            else:
                cut /= 2
    return tuple(tuple(node - 1 for node in route) for route in routes)


def _longest_ticks(ticks: np.ndarray, routes: list[list[int]]) -> int:
    return max(int(ticks[[0, *r], [*r, 0]].sum()) for r in routes)


def _ortools_search(
    ticks: np.ndarray, salesmen: int, min_cells: int, routes: list[list[int]], seconds: float,
    *, span_weight: int = 0, bound: int | None = None,
) -> list[list[int]]:
    """Guided local search from ``routes`` (node lists, depot 0 excluded) for ``seconds``.

    Arc costs are the integer distances ``ticks``. A positive ``span_weight`` adds that global
    span cost on a distance dimension (its span is the longest tour, as every tour starts at
    0); a ``bound`` instead costs each tick of a tour beyond it :data:`_ORTOOLS_EXCESS_COST`.
    A count dimension bounds every tour below by ``min_cells`` nodes.
    """
    from ortools.constraint_solver import pywrapcp, routing_enums_pb2

    nodes = len(ticks)
    manager = pywrapcp.RoutingIndexManager(nodes, salesmen, 0)
    routing = pywrapcp.RoutingModel(manager)
    arc = routing.RegisterTransitMatrix(ticks.tolist())
    routing.SetArcCostEvaluatorOfAllVehicles(arc)
    if span_weight or bound is not None:
        routing.AddDimension(arc, 0, int(ticks.sum()), True, "distance")
        distance = routing.GetDimensionOrDie("distance")
        distance.SetGlobalSpanCostCoefficient(span_weight)
        if bound is not None:
            for v in range(salesmen):
                distance.SetCumulVarSoftUpperBound(routing.End(v), bound, _ORTOOLS_EXCESS_COST)
    count = routing.RegisterUnaryTransitVector([0] + [1] * (nodes - 1))
    routing.AddDimension(count, 0, nodes, True, "count")
    cells = routing.GetDimensionOrDie("count")
    for v in range(salesmen):
        cells.CumulVar(routing.End(v)).SetMin(min_cells)

    params = pywrapcp.DefaultRoutingSearchParameters()
    params.local_search_metaheuristic = (
        routing_enums_pb2.LocalSearchMetaheuristic.GUIDED_LOCAL_SEARCH)
    params.time_limit.FromMilliseconds(max(1, round(seconds * 1000)))
    routing.CloseModelWithParameters(params)
    start = routing.ReadAssignmentFromRoutes(routes, True)
    solution = routing.SolveFromAssignmentWithParameters(start, params)
    if solution is None:
        raise RuntimeError("OR-Tools found no solution from a feasible start; please report it")
    found = []
    for v in range(salesmen):
        route = []
        index = solution.Value(routing.NextVar(routing.Start(v)))
        while not routing.IsEnd(index):
            route.append(manager.IndexToNode(index))
            index = solution.Value(routing.NextVar(index))
        found.append(route)
    return found


# -- plans for missions, cached ---------------------------------------------------------------


_MEMO: dict[str, MtspPlan] = {}


def cache_dir() -> Path:
    """Where plans are stored: ``$SARLINK_CACHE_DIR/plans`` if the variable is set, else
    ``$XDG_CACHE_HOME/sarlink/plans`` (``~/.cache/sarlink/plans`` by default)."""
    root = os.environ.get("SARLINK_CACHE_DIR")
    if root:
        return Path(root) / "plans"
    xdg = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(xdg) / "sarlink" / "plans"


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
    return {
        "version": CACHE_VERSION,
        "size": mission.area.size,
        "r": mission.sensing.r,
        "bs": list(mission.area.bs_xy),
        "salesmen": salesmen,
        "solver": m.solver,
        "objective": m.objective,
        "min_cells": m.min_cells if m.min_cells is not None else cells // salesmen,
        "population": m.population,
        "iterations": m.iterations,
        "plan_seed": m.plan_seed,
        "time_limit": ORTOOLS_TIME_LIMIT,
    }


def solve_for(mission: Mission, salesmen: int) -> MtspPlan:
    """Solve the mTSP plan for ``salesmen`` drones in ``mission`` now, bypassing every cache.

    The cities are the cells of :func:`grid_cells` for ``mission.area.size`` and
    ``mission.sensing.r``; the depot is the BS; solver settings come from ``mission.mtsp``.
    A :class:`ConfigError` names the setting when the mission admits no plan.
    """
    points, params = _checked_params(mission, salesmen)
    m = mission.mtsp
    return solve(points, mission.area.bs_xy, salesmen, solver=m.solver, objective=m.objective,
                 min_cells=params["min_cells"], population=m.population,
                 iterations=m.iterations, seed=m.plan_seed, time_limit=ORTOOLS_TIME_LIMIT)


def plan_for(mission: Mission, salesmen: int) -> MtspPlan:
    """The plan of :func:`solve_for`, computed once and cached.

    Plans are memoised in the process and stored as JSON in :func:`cache_dir`, under a hash
    of everything they depend on (:data:`CACHE_VERSION` included). Files are written
    atomically; an unreadable file counts as missing and is rewritten. A process about to
    solve a plan holds a lock on it, so workers that need the same plan at once solve it
    once and all use that one (OR-Tools' plans may differ from one solve to the next).
    """
    points, params = _checked_params(mission, salesmen)
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
                _write_plan(path, params, plan)
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


def _write_plan(path: Path, params: dict[str, Any], plan: MtspPlan) -> None:
    """Write via a temporary file in the same directory and ``os.replace``: a crash mid-write
    leaves either the old file or none, never a partial one."""
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
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        if tmp is not None:
            Path(tmp).unlink(missing_ok=True)
        warnings.warn(f"could not cache the mTSP plan in {path.parent}: {exc}", stacklevel=3)
