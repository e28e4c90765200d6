"""OR-Tools routing: the strong solver's min-sum plans (its min-max plans are :mod:`.ruin`'s).

Chosen over PyVRP because it supports the minimum number of cells per drone directly (PyVRP
has no lower bound on route size). Under ``minmax`` its routing search stalls on the flat
longest-tour objective, so ``solver="ortools", objective="minmax"`` runs the ruin-and-recreate
search of :mod:`.ruin` instead (docs/mtsp.md has the measurements).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from sarlink.mtsp.plan import distance_matrix

__all__ = ["ORTOOLS_SOLUTIONS", "solve_ortools"]

ORTOOLS_SOLUTIONS = 1000
"""Default budget of the min-sum search: the solutions OR-Tools' guided local search may
generate (its ``solution_limit``). The search never stops by itself; a count of solutions,
unlike a time limit, ends it at the same plan on every machine (about 3 s on the paper's grid,
within 0.1 % of the total of a 5 s search: docs/mtsp.md)."""

_ORTOOLS_TICKS = 1_000_000
"""OR-Tools needs integer arc costs: the longest arc is scaled to this many ticks."""


def solve_ortools(
    points: np.ndarray, depot: tuple[float, float], salesmen: int, min_cells: int,
    solutions: int = ORTOOLS_SOLUTIONS,
) -> tuple[tuple[int, ...], ...]:
    """Min-sum tours by guided local search from an angular sweep around the depot cut into
    equal parts: OR-Tools' first-solution heuristics cannot satisfy the ``min_cells`` bound,
    the sweep always does. The search ends after ``solutions`` solutions, so the plan depends
    on the inputs only (OR-Tools' routing search is single-threaded and has no random seed)."""
    dist = distance_matrix(points, depot)
    scale = _ORTOOLS_TICKS / dist.max() if dist.max() > 0 else 1.0
    ticks = np.rint(dist * scale).astype(np.int64)
    angles = np.arctan2(points[:, 1] - depot[1], points[:, 0] - depot[0])
    sweep = np.argsort(angles, kind="stable") + 1
    routes = [part.tolist() for part in np.array_split(sweep, salesmen)]
    routes = _ortools_search(ticks, salesmen, min_cells, routes, solutions)
    return tuple(tuple(node - 1 for node in route) for route in routes)


def _ortools_search(
    ticks: np.ndarray, salesmen: int, min_cells: int, routes: list[list[int]], solutions: int,
) -> list[list[int]]:
    """Guided local search from ``routes`` (node lists, depot 0 excluded) on the arc costs
    ``ticks`` until it has generated ``solutions`` solutions; a count dimension bounds every
    tour below by ``min_cells`` nodes."""
    from ortools.constraint_solver import pywrapcp, routing_enums_pb2
    from ortools.util import optional_boolean_pb2

    nodes = len(ticks)
    manager = pywrapcp.RoutingIndexManager(nodes, salesmen, 0)
    routing = pywrapcp.RoutingModel(manager)
    arc = routing.RegisterTransitMatrix(ticks.tolist())
    routing.SetArcCostEvaluatorOfAllVehicles(arc)
    count = routing.RegisterUnaryTransitVector([0] + [1] * (nodes - 1))
    routing.AddDimension(count, 0, nodes, True, "count")
    cells = routing.GetDimensionOrDie("count")
    for v in range(salesmen):
        cells.CumulVar(routing.End(v)).SetMin(min_cells)

    params = pywrapcp.DefaultRoutingSearchParameters()
    params.local_search_metaheuristic = (
        routing_enums_pb2.LocalSearchMetaheuristic.GUIDED_LOCAL_SEARCH)
    params.solution_limit = solutions
    # the neighbourhoods searched by a completion search stop at a time (lns_time_limit); they
    # are off by default, and kept off so that a plan never depends on the machine's speed
    operators = params.local_search_operators
    for name in ("use_path_lns", "use_full_path_lns", "use_tsp_lns", "use_inactive_lns"):
        setattr(operators, name, optional_boolean_pb2.BOOL_FALSE)
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
