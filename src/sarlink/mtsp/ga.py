"""The paper's solver: Joseph Kirk's MATLAB ``mtspf_ga`` (fixed start and end at the depot),
ported faithfully and compiled with Numba.

An individual is a permutation of the points and sorted break points that cut it into one route
per salesman; there is no crossover. The kernel takes a ``numpy.random.Generator`` made from the
seed, so a plan depends on the seed only (docs/mtsp.md says how the port differs from Kirk's).
"""

from __future__ import annotations

import numpy as np
from numba import njit
from numba.np.random.random_methods import random_interval

from sarlink.mtsp.plan import Objective, distance_matrix

__all__ = ["solve_ga"]


def solve_ga(
    points: np.ndarray, depot: tuple[float, float], salesmen: int, objective: Objective,
    min_cells: int, population: int, iterations: int, seed: int,
) -> tuple[tuple[tuple[int, ...], ...], np.ndarray, int]:
    """Tours (point indices per salesman), the best cost of each iteration's population and
    the number of individuals costed (the GA's evaluations, Fig. 1).

    ``population`` must be a multiple of 8 (Kirk's groups); the arguments are checked by
    :func:`sarlink.mtsp.solve`.
    """
    rng = np.random.default_rng(seed)
    route, breaks, history, evaluations = _ga_kernel(
        distance_matrix(points, depot), salesmen, min_cells, population, iterations,
        objective == "minmax", rng)
    bounds = [0, *breaks.tolist(), len(points)]
    tours = tuple(tuple(int(c) - 1 for c in route[bounds[s]:bounds[s + 1]])
                  for s in range(salesmen))
    return tours, history, int(evaluations)


@njit(cache=True, inline="always")
def _measure(
    dmat: np.ndarray, rte: np.ndarray, brk: np.ndarray, lens: np.ndarray, p: int,
    ref_len: np.ndarray, r: int, lo: int, hi: int, minmax: bool,
) -> float:
    """Total or longest tour length of individual ``p`` (``rte[p]``, ``brk[p]``); its tour
    lengths go to ``lens[p]``.

    The reference, individual ``r`` with tour lengths ``ref_len[r]``, has the same breaks
    and the same route outside positions ``lo..hi`` (``lo = n``: everywhere), so a tour
    that visits none of those positions is the reference's tour: its length is taken, bit
    for bit, not computed again. The total is summed tour by tour in order, exactly as over
    freshly computed lengths. Rows are passed by index, as a view per call would cost two
    atomic reference counts.
    """
    n = rte.shape[1]
    n_breaks = brk.shape[1]
    total = 0.0
    longest = 0.0
    start = 0
    for s in range(n_breaks + 1):
        end = brk[p, s] if s < n_breaks else n
        if end <= lo or start > hi:
            d = ref_len[r, s]
        else:
            d = dmat[0, rte[p, start]] + dmat[rte[p, end - 1], 0]
            for q in range(start, end - 1):
                d += dmat[rte[p, q], rte[p, q + 1]]
        lens[p, s] = d
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


@njit(cache=True, inline="always")
def _random_breaks(
    brk: np.ndarray, p: int, n: int, min_tour: int, cum_prob: np.ndarray, scratch: np.ndarray,
    adjust: np.ndarray, rng: np.random.Generator,
) -> None:
    """Kirk's ``randbreaks`` into ``brk[p]``: sorted break points leaving every salesman
    ``min_tour`` points."""
    n_breaks = brk.shape[1]
    if n_breaks == 0:
        return
    if min_tour == 1:
        # a uniform random subset of the positions 1..n-1 (partial Fisher-Yates)
        for q in range(n - 1):
            scratch[q] = q + 1
        for q in range(n_breaks):
            j = q + int((n - 1 - q) * rng.random())
            scratch[q], scratch[j] = scratch[j], scratch[q]
        scratch[:n_breaks].sort()
        for q in range(n_breaks):
            brk[p, q] = scratch[q]
        return
    u = rng.random()
    spare = cum_prob.size - 1
    for j in range(cum_prob.size):
        if u < cum_prob[j]:
            spare = j
            break
    for b in range(n_breaks):
        adjust[b] = 0
    for _ in range(spare):
        adjust[int(n_breaks * rng.random())] += 1
    extra = 0
    for b in range(n_breaks):
        extra += adjust[b]
        brk[p, b] = min_tour * (b + 1) + extra


@njit(cache=True, inline="always")
def _shuffle(x: np.ndarray, rng: np.random.Generator) -> None:
    """``rng.shuffle(x)`` of a 1-d array: the same draws (Numba's own ``random_interval``, the
    bounded integers its ``shuffle`` draws) and the same swaps, without the 0-d views through
    which Numba's ``shuffle`` swaps, with atomic reference counts at every swap. The kernel's
    test compares with ``rng.shuffle``, so a Numba that draws otherwise fails it."""
    bitgen = rng.bit_generator
    for i in range(x.size - 1, 0, -1):
        j = np.int64(random_interval(bitgen, i))
        if i != j:
            x[i], x[j] = x[j], x[i]


@njit(cache=True)
def _ga_kernel(
    dmat: np.ndarray, salesmen: int, min_tour: int, pop_size: int, iterations: int,
    minmax: bool, rng: np.random.Generator,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
    """Kirk's ``mtspf_ga``: the depot is city 0, the cities 1..n are permuted and split.

    An individual is a permutation ``route`` of 1..n and sorted ``breaks``: salesman ``s``
    visits ``route[breaks[s-1]:breaks[s]]`` (with 0 and n at the ends). Returns the best route,
    its breaks, the best cost in each iteration's population and the number of evaluations:
    individuals costed, one per individual of every iteration's population, as Kirk's GA
    costs them (each group's best, whose cost is carried over here, included).

    Children are costed as they are made, from what they share with a costed individual
    (:func:`_measure`): the group's best keeps its cost, a route move keeps the lengths of
    the parent's tours outside the moved segment, and new breaks that are the parent's (always
    when the breaks have no freedom, as for N = 2 or 16 on the paper's grid) make a copy of
    the sibling with the same move. Every cost is the one a fresh evaluation gives, bit for
    bit, so the plans are those of the plain kernel (``tests/test_mtsp_kernel.py``).
    """
    n = dmat.shape[0] - 1
    n_breaks = salesmen - 1
    cum_prob = _break_probabilities(n - min_tour * salesmen, n_breaks)
    scratch = np.empty(max(n - 1, 1), dtype=np.int64)
    adjust = np.empty(n_breaks, dtype=np.int64)

    pop_rte = np.empty((pop_size, n), dtype=np.uint32)  # unsigned: indexing skips wraparound
    pop_brk = np.empty((pop_size, n_breaks), dtype=np.int64)
    pop_len = np.empty((pop_size, salesmen))  # every individual's tour lengths
    costs = np.empty(pop_size)
    evaluations = 0
    for p in range(pop_size):
        pop_rte[p] = rng.permutation(n) + 1
        _random_breaks(pop_brk, p, n, min_tour, cum_prob, scratch, adjust, rng)
        costs[p] = _measure(dmat, pop_rte, pop_brk, pop_len, p, pop_len, p, 0, n - 1, minmax)
        evaluations += 1
    new_rte = np.empty_like(pop_rte)
    new_brk = np.empty_like(pop_brk)
    new_len = np.empty_like(pop_len)
    new_costs = np.empty_like(costs)

    order = np.arange(pop_size)
    best_rte = pop_rte[0].copy()
    best_brk = pop_brk[0].copy()
    best_cost = np.inf
    history = np.empty(iterations)
    for it in range(iterations):
        p_min = np.argmin(costs)
        history[it] = costs[p_min]  # Kirk's dist_history: elitism keeps it from rising
        if costs[p_min] < best_cost:
            best_cost = costs[p_min]
            best_rte[:] = pop_rte[p_min]
            best_brk[:] = pop_brk[p_min]
        if it == iterations - 1:
            break  # the last iteration's children would never be costed

        _shuffle(order, rng)
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
                k = g + c
                evaluations += 1  # child k's cost, measured or carried below
                for q in range(n):
                    new_rte[k, q] = pop_rte[b, q]
                for q in range(n_breaks):
                    new_brk[k, q] = pop_brk[b, q]
                if c == 0:  # the group's best, unchanged
                    for q in range(salesmen):
                        new_len[k, q] = pop_len[b, q]
                    new_costs[k] = costs[b]
                    continue
                op = c % 4  # 0 keep, 1 flip, 2 swap, 3 slide; children 4..7 also re-break
                if op == 1:
                    a, z = i, j
                    while a < z:
                        new_rte[k, a], new_rte[k, z] = new_rte[k, z], new_rte[k, a]
                        a += 1
                        z -= 1
                elif op == 2:
                    new_rte[k, i], new_rte[k, j] = new_rte[k, j], new_rte[k, i]
                elif op == 3 and j > i:
                    first = new_rte[k, i]
                    for q in range(i, j):
                        new_rte[k, q] = new_rte[k, q + 1]
                    new_rte[k, j] = first
                if c < 4:  # parent b's breaks, its route outside i..j
                    new_costs[k] = _measure(dmat, new_rte, new_brk, new_len, k, pop_len, b, i, j,
                                            minmax)
                    continue
                _random_breaks(new_brk, k, n, min_tour, cum_prob, scratch, adjust, rng)
                lo, hi = n, n - 1  # new breaks that are b's: the child is child k - 4 again
                for q in range(n_breaks):
                    if new_brk[k, q] != new_brk[k - 4, q]:
                        lo, hi = 0, n - 1  # other breaks: every tour is measured
                        break
                new_costs[k] = _measure(dmat, new_rte, new_brk, new_len, k, new_len, k - 4, lo,
                                        hi, minmax)
        pop_rte, new_rte = new_rte, pop_rte
        pop_brk, new_brk = new_brk, pop_brk
        pop_len, new_len = new_len, pop_len
        costs, new_costs = new_costs, costs
    return best_rte, best_brk, history, evaluations
