"""Several targets (``target.count = K > 1``; docs/model.md, Several targets): each target
sensed, flooded and notified on its own, and the mission's events chosen by
``target.success``.

The kernel compiles this in only with ``MANY_TARGETS`` (:mod:`sarlink.engine.build`), so
that one target's kernel stays today's, bit for bit. Target ``j``'s state is row ``j`` of
``(K, N)`` arrays: whether each drone has it in range, when its pass started and whether it
knows where that target is. Target 0, the first, is node ``N + 1`` of the position arrays:
the node of the links and of the reachability record; the others are sensed, not nodes.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine import graph, records, sensing
from sarlink.engine.codes import Success
from sarlink.engine.params import Params

_FIRST = int(Success.FIRST)


@njit(cache=True, inline="always", error_model="numpy")
def sense(tx: np.ndarray, ty: np.ndarray, px: np.ndarray, py: np.ndarray, k: int, t: float,
          p: Params, in_range: np.ndarray, pass_start: np.ndarray, known: np.ndarray,
          t_det: np.ndarray, detector: np.ndarray, rng: np.random.Generator) -> None:
    """Every drone looks for every target in its range, target by target in order (each
    look one draw of the look stream, as for one target); ``t_det[j]`` and ``detector[j]``
    record target ``j``'s first detection."""
    for j in range(tx.shape[0]):
        first = sensing.sense_at(tx[j], ty[j], px, py, k, p, in_range[j], pass_start[j],
                                 known[j], rng)
        if t_det[j] < 0.0 and first >= 0:
            t_det[j], detector[j] = t, first


@njit(cache=True, inline="always", error_model="numpy")
def flood(adj: np.ndarray, routed: np.ndarray, known: np.ndarray, t_det: np.ndarray,
          t_not: np.ndarray, t: float, knows: np.ndarray, spread: np.ndarray,
          scratch: np.ndarray, stack: np.ndarray) -> None:
    """Flood each detected target's location from its knowers (:func:`graph.flood`); a
    target is notified (``t_not[j]``) at the first step its location reaches the BS.
    ``knows`` and ``spread``: who knows any target's location, what the rules see."""
    knows[:] = False
    spread[:] = 0
    for j in range(known.shape[0]):
        if t_det[j] < 0.0:
            continue
        if graph.flood(adj, routed, known[j], scratch, stack) and t_not[j] < 0.0:
            t_not[j] = t
        for w in range(spread.shape[0]):
            spread[w] |= scratch[w]
        for i in range(knows.shape[0]):
            knows[i] |= known[j, i]


@njit(cache=True, inline="always", error_model="numpy")
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


@njit(cache=True, inline="always", error_model="numpy")
def settled(mode: np.ndarray, in_range: np.ndarray, known: np.ndarray, look: int) -> bool:
    """:func:`records.settled` for every target: every drone has landed, and none still looks
    for a target in its range that it does not know."""
    for j in range(known.shape[0]):  # noqa: SIM110 (a loop Numba compiles; all() of a generator it does not)
        if not records.settled(mode, in_range[j], known[j], look):
            return False
    return True
