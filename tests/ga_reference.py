"""The GA kernel as it was before it reused costs (main at ab53e80, src/sarlink/mtsp/ga.py),
kept verbatim (``_ga_kernel`` renamed ``ga_kernel``) as the reference of
tests/test_mtsp_kernel.py: every child is costed afresh by ``_cost``, the flip and slide
copy slices. Plans stored by that code must stay valid (``CACHE_VERSION`` was not bumped),
so the kernel of ``sarlink.mtsp.ga`` must give the same routes, breaks and history, bit for
bit.
"""

from __future__ import annotations

import numpy as np
from numba import njit


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
def ga_kernel(
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
