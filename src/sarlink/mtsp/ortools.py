"""OR-Tools routing: the strong solver to measure the GA against.

Chosen over PyVRP because it supports both objectives and the minimum number of cells per drone
directly (PyVRP minimises total distance only and has no lower bound on route size).
"""

from __future__ import annotations

import numpy as np

from sarlink.mtsp.plan import Objective, distance_matrix

__all__ = ["ORTOOLS_TIME_LIMIT", "solve_ortools"]

ORTOOLS_TIME_LIMIT = 5.0
"""Default OR-Tools search time, s. Guided local search never stops by itself; on the 64-cell
grid, 2 s already gives nearly the same plans (docs/mtsp.md), and a plan is made once."""

_ORTOOLS_TICKS = 1_000_000
"""OR-Tools needs integer arc costs: the longest arc is scaled to this many ticks."""

_ORTOOLS_ROUNDS = 4
"""Min-max: rounds of search against a lowered bound on every tour."""

_ORTOOLS_EXCESS_COST = 1000
"""Min-max: cost of one tick of a tour beyond the bound, against one per tick of distance."""


def solve_ortools(
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
    dist = distance_matrix(points, depot)
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
