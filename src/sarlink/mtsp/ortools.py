"""OR-Tools routing: the strong solver to measure the GA against.

Chosen over PyVRP because it supports both objectives and the minimum number of cells per drone
directly (PyVRP minimises total distance only and has no lower bound on route size).
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from sarlink.mtsp.plan import Objective, distance_matrix

__all__ = ["ORTOOLS_TIME_LIMIT", "solve_ortools"]

ORTOOLS_TIME_LIMIT = 5.0
"""Default OR-Tools search time, s. Guided local search never stops by itself (the min-max
search stops at the floor); a plan is made once and cached."""

_ORTOOLS_TICKS = 1_000_000
"""OR-Tools needs integer arc costs: the longest arc is scaled to this many ticks."""

_ORTOOLS_EXCESS_COST = 1000
"""Min-max: cost of one tick of a tour beyond the bound, against one per tick of distance."""

_PROBE_SECONDS = 0.5
"""Min-max: the longest search for a plan under one route-length limit, s."""


def solve_ortools(
    points: np.ndarray, depot: tuple[float, float], salesmen: int, objective: Objective,
    min_cells: int, time_limit: float,
) -> tuple[tuple[int, ...], ...]:
    """OR-Tools routing from an angular sweep around the depot cut into equal parts.

    ``minsum`` is one guided local search on the arc costs. ``minmax`` is harder: a global span
    cost (the longest tour) is flat wherever several tours are about as long, so local search
    stalls, and no single recipe does well for every team size (docs/mtsp.md). It runs three
    stages of a third of the time each, every one starting from the best plan so far:

    1. guided local search with a span cost of weight 100 (OR-Tools' customary recipe);
    2. a bisection between the lower bound (the round trip to the farthest point) and the best
       longest tour, with a *soft* bound on every tour: each tick of excess costs
       :data:`_ORTOOLS_EXCESS_COST`, so shortening any long tour pays;
    3. a descent on a *hard* route-length limit below the best longest tour: points may be left
       out at a high price, so the search starts from the best plan with its tours cut to the
       limit and succeeds when it puts every point back.
    """
    dist = distance_matrix(points, depot)
    scale = _ORTOOLS_TICKS / dist.max() if dist.max() > 0 else 1.0
    ticks = np.rint(dist * scale).astype(np.int64)
    angles = np.arctan2(points[:, 1] - depot[1], points[:, 0] - depot[0])
    sweep = np.argsort(angles, kind="stable") + 1
    routes = [part.tolist() for part in np.array_split(sweep, salesmen)]
    if objective == "minsum":
        routes = _ortools_search(ticks, salesmen, min_cells, routes, time_limit)
    else:
        stage = time_limit / 3
        routes = _ortools_search(ticks, salesmen, min_cells, routes, stage, span_weight=100)
        routes = _bisect_soft_bound(ticks, salesmen, min_cells, routes, stage)
        routes = _descend_hard_limit(ticks, salesmen, min_cells, routes, stage)
    return tuple(tuple(node - 1 for node in route) for route in routes)


def _bisect_soft_bound(ticks: np.ndarray, salesmen: int, min_cells: int,
                       routes: list[list[int]], seconds: float) -> list[list[int]]:
    """Search under a soft bound halfway between the floor and the best longest tour; a plan
    within the bound lowers the best, a failure raises the floor (heuristically)."""
    deadline = time.perf_counter() + seconds
    floor = 2 * int(ticks[0].max())
    best = _longest_ticks(ticks, routes)
    while best > floor and (left := deadline - time.perf_counter()) > 0.01:
        bound = (floor + best) // 2
        found = _ortools_search(ticks, salesmen, min_cells, routes, min(_PROBE_SECONDS, left),
                                bound=bound)
        longest = _longest_ticks(ticks, found)
        if longest < best:
            routes, best = found, longest
        if longest > bound:
            floor = bound + 1
    return routes


def _descend_hard_limit(ticks: np.ndarray, salesmen: int, min_cells: int,
                        routes: list[list[int]], seconds: float) -> list[list[int]]:
    """Plans under a hard limit a step below the best longest tour; the step halves on each
    failure, and stays while the searches succeed."""
    deadline = time.perf_counter() + seconds
    floor = 2 * int(ticks[0].max())
    best, step = _longest_ticks(ticks, routes), 0.05
    while best > floor and step > 1e-4 and (left := deadline - time.perf_counter()) > 0.01:
        limit = max(floor, round(best * (1 - step)))
        found = _ortools_limited(ticks, salesmen, min_cells, routes, min(_PROBE_SECONDS, left),
                                 limit)
        if found is not None:
            routes, best = found, _longest_ticks(ticks, found)
        else:
            step /= 2
    return routes


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
    return _routes_of(routing, manager, solution, salesmen)


def _routes_of(routing: Any, manager: Any, solution: Any, salesmen: int) -> list[list[int]]:
    """The node lists (depot excluded) of a solution, one per vehicle."""
    found = []
    for v in range(salesmen):
        route = []
        index = solution.Value(routing.NextVar(routing.Start(v)))
        while not routing.IsEnd(index):
            route.append(manager.IndexToNode(index))
            index = solution.Value(routing.NextVar(index))
        found.append(route)
    return found


def _ortools_limited(ticks: np.ndarray, salesmen: int, min_cells: int, routes: list[list[int]],
                     seconds: float, limit: int) -> list[list[int]] | None:
    """A plan whose every tour is at most ``limit`` ticks, or None if none was found.

    Every point may be left out at a price above any route's length, and a tour short of
    ``min_cells`` points pays the same per missing point; the search starts from ``routes``
    with each tour cut where it would exceed the limit and stops at the first plan that
    visits every point with ``min_cells`` per tour.
    """
    from ortools.constraint_solver import pywrapcp, routing_enums_pb2

    nodes = len(ticks)
    manager = pywrapcp.RoutingIndexManager(nodes, salesmen, 0)
    routing = pywrapcp.RoutingModel(manager)
    arc = routing.RegisterTransitMatrix(ticks.tolist())
    routing.SetArcCostEvaluatorOfAllVehicles(arc)
    routing.AddDimension(arc, 0, limit, True, "distance")
    price = int(ticks.sum()) + 1
    for node in range(1, nodes):
        routing.AddDisjunction([manager.NodeToIndex(node)], price)
    count = routing.RegisterUnaryTransitVector([0] + [1] * (nodes - 1))
    routing.AddDimension(count, 0, nodes, True, "count")
    cells = routing.GetDimensionOrDie("count")
    for v in range(salesmen):
        cells.SetCumulVarSoftLowerBound(routing.End(v), min_cells, price)

    params = pywrapcp.DefaultRoutingSearchParameters()
    params.local_search_metaheuristic = (
        routing_enums_pb2.LocalSearchMetaheuristic.GUIDED_LOCAL_SEARCH)
    params.time_limit.FromMilliseconds(max(1, round(seconds * 1000)))
    routing.CloseModelWithParameters(params)

    def stop_when_complete() -> None:
        if routing.CostVar().Max() < price:  # nothing left out, no tour short of points
            routing.solver().FinishCurrentSearch()

    routing.AddAtSolutionCallback(stop_when_complete)
    start = routing.ReadAssignmentFromRoutes([_cut(ticks, r, limit) for r in routes], True)
    solution = routing.SolveFromAssignmentWithParameters(start, params)
    if solution is None:
        return None
    found = _routes_of(routing, manager, solution, salesmen)
    complete = sum(map(len, found)) == nodes - 1 and min(map(len, found)) >= min_cells
    return found if complete else None


def _cut(ticks: np.ndarray, route: list[int], limit: int) -> list[int]:
    """The longest prefix of ``route`` whose tour (back to the depot) is within ``limit``."""
    for end in range(len(route), 0, -1):
        if _longest_ticks(ticks, [route[:end]]) <= limit:
            return route[:end]
    return []
