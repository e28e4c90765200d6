"""Several targets (``target.count = K > 1``; docs/model.md, Several targets): each target
sensed, flooded and notified on its own, and the mission's events chosen by
``target.success``.

The kernel compiles this in only with ``MANY_TARGETS`` (:mod:`sarlink.engine.build`), so
that one target's kernel stays today's, bit for bit. Target ``j``'s state is row ``j`` of
``(K, N)`` arrays, indexed in place (a row view per target and step would cost a reference
count): whether each drone has it in range, when its pass started and whether it
knows where that target is. Target 0, the first, is node ``N + 1`` of the position arrays:
the node of the links and of the reachability record; the others are sensed, not nodes.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine import graph
from sarlink.engine.codes import Success
from sarlink.engine.params import LANDED, PER_PERIOD, Params

_FIRST = int(Success.FIRST)


@njit(cache=True, error_model="numpy")
def sense(tx: np.ndarray, ty: np.ndarray, px: np.ndarray, py: np.ndarray, k: int, t: float,
          p: Params, in_range: np.ndarray, pass_start: np.ndarray, known: np.ndarray,
          t_det: np.ndarray, detector: np.ndarray, rng: np.random.Generator) -> None:
    """Every drone looks for every target in its range, target by target in order, as
    :func:`sensing.sense` looks for one (each look one draw of the look stream);
    ``t_det[j]`` and ``detector[j]`` record target ``j``'s first detection. Indexed in
    place, not by rows: a row view per target and step costs a reference count."""
    n = known.shape[1]
    r2 = p.r * p.r
    for j in range(tx.shape[0]):
        for i in range(n):
            dx, dy = px[i] - tx[j], py[i] - ty[j]
            now_in = dx * dx + dy * dy <= r2
            if now_in:
                look = not in_range[j, i]
                if look:
                    pass_start[j, i] = k
                elif p.look == PER_PERIOD and (k - pass_start[j, i]) % p.ts_steps == 0:
                    look = True
                if look and rng.random() >= p.p_miss:
                    known[j, i] = True
                    if t_det[j] < 0.0:
                        t_det[j], detector[j] = t, i
            in_range[j, i] = now_in


@njit(cache=True, inline="always", error_model="numpy")
def label(adj: np.ndarray, n: int, comp: np.ndarray, unseen: np.ndarray,
          stack: np.ndarray) -> None:
    """``comp[a]``: the lowest node of node ``a``'s component in the links among the drones
    and the BS (nodes ``0 .. n``; never through a target): what :func:`graph.flood` spreads
    a location over, found once a step for every target."""
    graph.first_nodes(unseen, n + 1)
    for s in range(n + 1):
        if not graph.has(unseen, s):
            continue
        graph.drop(unseen, s)
        stack[0] = s
        top = 1
        while top > 0:
            top -= 1
            a = stack[top]
            comp[a] = s
            for w in range(unseen.shape[0]):
                new = adj[a, w] & unseen[w]
                unseen[w] &= ~new
                top = graph.push_new(stack, top, w, new)


@njit(cache=True, error_model="numpy")
def flood(adj: np.ndarray, known: np.ndarray, t_det: np.ndarray,
          t_not: np.ndarray, t: float, knows: np.ndarray, spread: np.ndarray,
          comp: np.ndarray, reached: np.ndarray, unseen: np.ndarray,
          stack: np.ndarray) -> None:
    """Flood each detected target's location from its knowers to every drone of their
    components (the BS relays too), as :func:`graph.flood` does for one; a target is
    notified (``t_not[j]``) at the first step its location reaches the BS. ``knows`` and
    ``spread``: who knows any target's location, what the rules see. ``comp``, ``reached``
    (``n + 1`` nodes) and ``unseen`` (a bitset) are scratch."""
    n = knows.shape[0]
    label(adj, n, comp, unseen, stack)
    knows[:] = False
    for j in range(known.shape[0]):
        if t_det[j] < 0.0:
            continue
        reached[:] = False
        for i in range(n):
            if known[j, i]:
                reached[comp[i]] = True
        for i in range(n):
            known[j, i] = reached[comp[i]]
            knows[i] |= known[j, i]
        if reached[comp[n]] and t_not[j] < 0.0:
            t_not[j] = t
    spread[:] = 0
    for i in range(n):
        if knows[i]:
            graph.add(spread, i)
            if comp[i] == comp[n]:  # a knower in the BS's component: the BS knows too
                graph.add(spread, n)


@njit(cache=True, error_model="numpy")
def event(times: np.ndarray, success: int) -> int:
    """The target whose event time (``-1``: not yet) is the mission's: the earliest under
    ``first``, the latest once every target's has happened under ``all``; the lowest index
    among ties; -1 while there is none."""
    best = -1
    for j in range(times.shape[0]):
        if times[j] < 0.0:
            if success != _FIRST:
                return -1
            continue
        if best < 0 or (times[j] < times[best] if success == _FIRST else times[j] > times[best]):
            best = j
    return best


@njit(cache=True, error_model="numpy")
def settled(mode: np.ndarray, in_range: np.ndarray, known: np.ndarray, look: int) -> bool:
    """:func:`records.settled` for every target: every drone has landed, and none still looks
    for a target in its range that it does not know (only per-period looks repeat)."""
    for i in range(mode.shape[0]):
        if mode[i] != LANDED:
            return False
        if look == PER_PERIOD:
            for j in range(known.shape[0]):
                if in_range[j, i] and not known[j, i]:
                    return False
    return True
