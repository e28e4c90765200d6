"""Min-max plans by ruin and recreate: the search behind ``solver="ortools", objective="minmax"``.

Why not OR-Tools: its routing search stalls on the min-max objective (the longest tour is flat
wherever several tours are about as long), so its plans on the paper's grid stayed up to 3 %
above the best known even with 60 s, and polishing this search's plans with OR-Tools never
shortened them (docs/mtsp.md, "Choosing the min-max search").

Ruin and recreate moves many cells at once, which is what a flat objective needs: take a cell
and its nearest neighbours out of their tours, put them back one by one where the longest tour
grows least, re-optimise the changed tours with 2-opt, and accept the result by simulated
annealing on the longest tour (ties broken toward balanced tours). Restarts from the same
start with other random streams keep the best plan.

The kernel takes a ``numpy.random.Generator`` and the search ends after a number of steps,
never at a time, so a plan depends on the inputs and the seed only, not on the machine or how
busy it is.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from sarlink.mtsp.plan import distance_matrix

__all__ = ["RESTARTS", "RUIN_ITERATIONS", "RUIN_WORK", "ruin_steps", "solve_minmax"]

RESTARTS = 3
"""Independent searches per plan; the shortest longest tour wins."""

RUIN_ITERATIONS = 30_000
"""Ruin-and-recreate steps per search on the paper's grid and smaller instances: with three
searches every N from 2 to 22 is within 1 % of the best known, in about 1.3 s (docs/mtsp.md)."""

RUIN_WORK = 64 * 32 * RUIN_ITERATIONS
"""Rough work of one search on large instances: a step costs about K x K / salesmen (putting
points back anywhere, 2-opt on the changed tours), so the default steps shrink to keep a plan
of many cells within seconds (see :func:`ruin_steps`)."""

_MAX_RUIN = 64
"""Most points taken out in one step (all of them when there are fewer)."""

_TEMPERATURE = 0.006
"""Initial annealing temperature as a fraction of the floor (the round trip to the farthest
point); it falls linearly to zero over a search."""

_BALANCE = 1e-3
"""Weight of the tie-breaker: the sum of squared tour lengths over the longest, which prefers
plans whose other tours leave room to take cells from the longest."""


def ruin_steps(points: int, salesmen: int) -> int:
    """The default steps per search for ``points`` points and ``salesmen`` tours:
    :data:`RUIN_ITERATIONS` up to the paper's grid (64 cells, 2 tours), fewer on larger
    instances so that a search does about :data:`RUIN_WORK` (a function of the instance's
    size, so a plan still depends on its inputs only)."""
    return max(1, min(RUIN_ITERATIONS, RUIN_WORK // (points * math.ceil(points / salesmen))))


def solve_minmax(
    points: np.ndarray, depot: tuple[float, float], salesmen: int, min_cells: int, seed: int,
    *, restarts: int = RESTARTS, iterations: int | None = None,
) -> tuple[tuple[int, ...], ...]:
    """Tours (point indices per salesman) minimising the longest, each of ``min_cells`` or more.

    ``restarts`` searches of ``iterations`` steps each (``None``: :func:`ruin_steps`). Every
    search starts from an angular sweep around the depot cut into equal parts, which satisfies
    ``min_cells``; the searches stop early once a plan reaches the floor, the round trip to the
    farthest point, which no plan can beat.
    """
    dist = distance_matrix(points, depot)
    k = len(points)
    angles = np.arctan2(points[:, 1] - depot[1], points[:, 0] - depot[0])
    start = np.empty(k, dtype=np.int64)
    for part, cells in enumerate(np.array_split(np.argsort(angles, kind="stable"), salesmen)):
        start[cells] = part
    near = np.argsort(dist[1:, 1:], axis=1, kind="stable").astype(np.int64) + 1
    floor = 2 * float(dist[0].max())
    steps = ruin_steps(k, salesmen) if iterations is None else iterations
    best: list[np.ndarray] = []
    best_length = np.inf
    for rng in (np.random.default_rng(s) for s in np.random.SeedSequence(seed).spawn(restarts)):
        state = _State.start(dist, start, salesmen)
        if state.best > floor * (1 + 1e-12):
            state.best = _search(dist, near, min_cells, state.routes, state.sizes,
                                 state.best_routes, state.best_sizes, steps,
                                 min(_MAX_RUIN, k), _TEMPERATURE * floor, floor, rng)
        if state.best < best_length:
            best_length = state.best
            best = [state.best_routes[v, : state.best_sizes[v]] for v in range(salesmen)]
        if best_length <= floor * (1 + 1e-12):
            break
    return tuple(tuple(int(c) - 1 for c in tour) for tour in best)


@dataclass
class _State:
    """One search's current and best routes (node ids, depot 0; row ``v`` is salesman ``v``,
    its first ``sizes[v]`` entries his tour)."""

    routes: np.ndarray
    sizes: np.ndarray
    best_routes: np.ndarray
    best_sizes: np.ndarray
    best: float

    @staticmethod
    def start(dist: np.ndarray, start: np.ndarray, salesmen: int) -> _State:
        """The start plan: point ``c`` in tour ``start[c]``, each tour improved by 2-opt."""
        routes = np.zeros((salesmen, len(start)), dtype=np.int64)
        sizes = np.zeros(salesmen, dtype=np.int64)
        for c, v in enumerate(start):
            routes[v, sizes[v]] = c + 1
            sizes[v] += 1
        longest = 0.0
        for v in range(salesmen):
            _two_opt(dist, routes[v], sizes[v])
            longest = max(longest, _tour_length(dist, routes[v], sizes[v]))
        return _State(routes, sizes, routes.copy(), sizes.copy(), longest)


@njit(cache=True)
def _tour_length(dist: np.ndarray, route: np.ndarray, size: int) -> float:
    """Length of the tour depot -> route[:size] -> depot (0 for an empty route)."""
    if size == 0:
        return 0.0
    total = dist[0, route[0]] + dist[route[size - 1], 0]
    for i in range(size - 1):
        total += dist[route[i], route[i + 1]]
    return total


@njit(cache=True)
def _two_opt(dist: np.ndarray, route: np.ndarray, size: int) -> None:
    """Reverse segments of one tour (depot at both ends) while that shortens it."""
    improved = True
    while improved:
        improved = False
        for i in range(-1, size - 2):
            a = 0 if i < 0 else route[i]
            b = route[i + 1]
            for j in range(i + 2, size):
                c = route[j]
                d = 0 if j == size - 1 else route[j + 1]
                if dist[a, c] + dist[b, d] < dist[a, b] + dist[c, d] - 1e-9:
                    route[i + 1: j + 1] = route[i + 1: j + 1][::-1].copy()
                    b = route[i + 1]
                    improved = True


@njit(cache=True)
def _score(lengths: np.ndarray) -> float:
    """The longest tour, ties broken by the balance term (see :data:`_BALANCE`)."""
    longest = lengths.max()
    return longest + _BALANCE * (lengths**2).sum() / max(longest, 1e-12)


@njit(cache=True)
def _search(dist: np.ndarray, near: np.ndarray, min_cells: int, routes: np.ndarray,
            sizes: np.ndarray, best_routes: np.ndarray, best_sizes: np.ndarray, iterations: int,
            max_ruin: int, temperature: float, floor: float, rng: np.random.Generator) -> float:
    """An annealed ruin-and-recreate search of ``iterations`` steps; updates the current and
    best routes in place, returns the best longest tour."""
    salesmen = routes.shape[0]
    k = dist.shape[0] - 1
    lengths = np.zeros(salesmen)
    best_lengths = np.zeros(salesmen)
    for v in range(salesmen):
        lengths[v] = _tour_length(dist, routes[v], sizes[v])
        best_lengths[v] = _tour_length(dist, best_routes[v], best_sizes[v])
    score = _score(lengths)
    best = best_lengths.max()
    cur_routes, cur_sizes = routes.copy(), sizes.copy()
    removed = np.empty(max_ruin, dtype=np.int64)
    keys = np.empty(max_ruin)
    changed = np.zeros(salesmen, dtype=np.bool_)
    for it in range(iterations):
        if best <= floor * (1 + 1e-12):
            break
        new_routes, new_sizes, new_lengths = cur_routes.copy(), cur_sizes.copy(), lengths.copy()
        changed[:] = False
        # ruin: a random point and its nearest neighbours leave their tours
        seed_cell = rng.integers(0, k)
        count = rng.integers(2, max_ruin + 1) if max_ruin > 2 else max_ruin
        for r in range(count):
            cell = near[seed_cell, r]
            removed[r] = cell
            keys[r] = -dist[0, cell] * (0.8 + 0.4 * rng.random())
            for v in range(salesmen):
                size = new_sizes[v]
                for p in range(size):
                    if new_routes[v, p] == cell:
                        new_routes[v, p: size - 1] = new_routes[v, p + 1: size].copy()
                        new_sizes[v] = size - 1
                        changed[v] = True
                        break
        for v in range(salesmen):
            if changed[v]:
                new_lengths[v] = _tour_length(dist, new_routes[v], new_sizes[v])
        # recreate: farthest from the depot first (with noise), each where the longest grows
        # least; tours short of min_cells take the last points
        order = np.argsort(keys[:count])
        for left in range(count, 0, -1):
            cell = removed[order[count - left]]
            deficit = 0
            for v in range(salesmen):
                deficit += max(0, min_cells - new_sizes[v])
            forced = deficit >= left
            longest = new_lengths.max()
            best_cost, best_v, best_p, best_len = np.inf, -1, -1, 0.0
            for v in range(salesmen):
                size = new_sizes[v]
                if forced and size >= min_cells:
                    continue
                for p in range(size + 1):
                    a = 0 if p == 0 else new_routes[v, p - 1]
                    b = 0 if p == size else new_routes[v, p]
                    grown = new_lengths[v] + dist[a, cell] + dist[cell, b] - dist[a, b]
                    cost = max(grown, longest) * 1000.0 + grown - new_lengths[v]
                    if cost < best_cost:
                        best_cost, best_v, best_p, best_len = cost, v, p, grown
            size = new_sizes[best_v]
            new_routes[best_v, best_p + 1: size + 1] = new_routes[best_v, best_p: size].copy()
            new_routes[best_v, best_p] = cell
            new_sizes[best_v] = size + 1
            new_lengths[best_v] = best_len
            changed[best_v] = True
        for v in range(salesmen):
            if changed[v]:
                _two_opt(dist, new_routes[v], new_sizes[v])
                new_lengths[v] = _tour_length(dist, new_routes[v], new_sizes[v])
        new_score = _score(new_lengths)
        heat = temperature * (1.0 - it / iterations) + 1e-12
        if new_score < score or rng.random() < np.exp((score - new_score) / heat):
            cur_routes, cur_sizes, lengths, score = new_routes, new_sizes, new_lengths, new_score
            if lengths.max() < best - 1e-9:
                best = lengths.max()
                best_routes[:] = cur_routes
                best_sizes[:] = cur_sizes
    routes[:] = cur_routes
    sizes[:] = cur_sizes
    return best
