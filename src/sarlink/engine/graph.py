"""Who is linked to whom, who has a route to the BS, and how the target's location floods.

Adjacency is kept as bitsets: row ``a`` of ``adj`` is ``W = ceil((N + 2) / 64)`` words whose
bit ``b`` says whether nodes ``a`` and ``b`` are linked; a breadth-first search then costs a
few word operations per node instead of a pass over a boolean matrix. Node indices: drones
``0 .. N-1``, the BS ``N``, the target ``N + 1`` (a node only for reachability: it never relays).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.codes import Mode, Parked, Reachability
from sarlink.engine.geometry import d2

_DIRECT = int(Reachability.DIRECT)
_RELAY = int(Parked.RELAY)
_BASE = int(Parked.BASE)
_LANDED = int(Mode.LANDED)
_ZERO = np.uint64(0)
_ONE = np.uint64(1)
_DEBRUIJN = np.uint64(0x03F79D71B4CB0A89)
_DEBRUIJN_INDEX = np.array(
    [0, 1, 48, 2, 57, 49, 28, 3, 61, 58, 50, 42, 38, 29, 17, 4, 62, 55, 59, 36, 53, 51, 43, 22,
     45, 39, 33, 30, 24, 18, 12, 5, 63, 47, 56, 27, 60, 41, 37, 16, 54, 35, 52, 21, 44, 32, 23,
     11, 46, 26, 40, 15, 34, 20, 31, 10, 25, 14, 19, 9, 13, 8, 7, 6], dtype=np.int64)


@njit(cache=True, error_model="numpy")
def bit(word: np.uint64, a: int) -> bool:
    """Whether node ``a``'s bit is set in ``word``, the bitset word that holds it (for loops
    that must not hand arrays to helpers, see :func:`sarlink.planners.rules.conb.conb_headings`)."""
    return (word >> np.uint64(a & 63)) & _ONE != 0


@njit(cache=True, inline="always", error_model="numpy")
def has(bits: np.ndarray, a: int) -> bool:
    """Whether node ``a`` is in the bitset ``bits``."""
    return (bits[a >> 6] >> np.uint64(a & 63)) & _ONE != 0


@njit(cache=True, inline="always", error_model="numpy")
def add(bits: np.ndarray, a: int) -> None:
    """Put node ``a`` into the bitset ``bits``."""
    bits[a >> 6] |= _ONE << np.uint64(a & 63)


@njit(cache=True, inline="always", error_model="numpy")
def drop(bits: np.ndarray, a: int) -> None:
    """Take node ``a`` out of the bitset ``bits``."""
    bits[a >> 6] &= ~(_ONE << np.uint64(a & 63))


@njit(cache=True, inline="always", error_model="numpy")
def covers(bits: np.ndarray, goal: np.ndarray) -> bool:
    """Whether every node of the bitset ``goal`` is in the bitset ``bits``."""
    missing = _ZERO
    for w in range(bits.shape[0]):
        missing |= goal[w] & ~bits[w]
    return missing == _ZERO


@njit(cache=True, inline="always", error_model="numpy")
def first_nodes(bits: np.ndarray, m: int) -> None:
    """``bits``: the nodes ``0 .. m-1``."""
    for w in range(bits.shape[0]):
        k = m - w * 64
        bits[w] = ~_ZERO if k >= 64 else (_ONE << np.uint64(max(k, 0))) - _ONE


@njit(cache=True, inline="always", error_model="numpy")
def linked(adj: np.ndarray, a: int, b: int) -> bool:
    """Whether nodes ``a`` and ``b`` are linked."""
    return (adj[a, b >> 6] >> np.uint64(b & 63)) & _ONE != 0


@njit(cache=True, error_model="numpy")
def links(
    px: np.ndarray, py: np.ndarray, pz: np.ndarray, thr2: np.ndarray, adj: np.ndarray,
    r2: float, near: np.ndarray, with_near: bool,
) -> None:
    """Bitsets of the pairs within squared link range ``thr2[a, b]`` (``adj``) and, if
    ``with_near``, within squared sensing range ``r2`` (``near``).

    A flag rather than an empty ``near``: choosing the array in the caller (``near if push
    else near[:0]``) left this inlined call's array references counted at every step.
    Every row is computed whole, without branches, so that the loop vectorizes: this is
    several times faster than testing each pair once and mirroring the bit. The positions
    are padded (see :data:`sarlink.engine.geometry.FAR`): a row's length is the padded one.
    The inner loop indexes with an unsigned integer: with a signed one Numba adds a check for
    a negative index (counted from the end) to every load, which by the timings kept LLVM
    from vectorizing the loop (docs/architecture.md); the same loads and arithmetic, so the
    same bits.
    """
    m = adj.shape[0]
    mp = px.shape[0]
    for a in range(m):
        xa, ya, za = px[a], py[a], pz[a]
        thr2_a = thr2[a]
        for w in range(adj.shape[1]):
            lo = w * 64
            row = np.uint64(0)
            close = np.uint64(0)
            for b in range(lo, min(mp, lo + 64)):
                u = np.uint64(b)  # an unsigned index has no wraparound check: see the docstring
                dd = d2(xa, ya, za, px[u], py[u], pz[u])
                shift = np.uint64(b - lo)
                row |= (_ONE if dd <= thr2_a[u] else _ZERO) << shift
                if with_near:
                    close |= (_ONE if dd <= r2 else _ZERO) << shift
            if w == a >> 6:  # a node is not its own neighbour
                row &= ~(_ONE << np.uint64(a & 63))
                close &= ~(_ONE << np.uint64(a & 63))
            adj[a, w] = row
            if with_near:
                near[a, w] = close


@njit(cache=True, error_model="numpy")
def lowest(bits: np.uint64) -> int:
    """Index of the lowest set bit of a non-zero word."""
    return _DEBRUIJN_INDEX[((bits & (~bits + _ONE)) * _DEBRUIJN) >> np.uint64(58)]


@njit(cache=True, inline="always", error_model="numpy")
def push_new(stack: np.ndarray, top: int, w: int, bits: np.uint64) -> int:
    """Push the node index of every set bit of word ``w``; return the new stack top."""
    while bits:
        stack[top] = w * 64 + lowest(bits)
        top += 1
        bits &= bits - _ONE
    return top


@njit(cache=True, inline="always", error_model="numpy")
def component(adj: np.ndarray, tg: int, out: np.ndarray, stack: np.ndarray) -> None:
    """Grow the node set ``out`` to everything linked to it, never routing through the target.

    The target (node ``tg``) is a leaf: it is marked as reached after the seeds are taken, so
    the search never expands it, and removed at the end.
    """
    top = 0
    for w in range(out.shape[0]):
        top = push_new(stack, top, w, out[w])
    add(out, tg)
    while top > 0:
        top -= 1
        a = stack[top]
        for w in range(out.shape[0]):
            new = adj[a, w] & ~out[w]
            out[w] |= new
            top = push_new(stack, top, w, new)
    drop(out, tg)


@njit(cache=True, error_model="numpy")
def bs_component(adj: np.ndarray, n: int, out: np.ndarray, stack: np.ndarray) -> None:
    """``out``: the nodes (drones and the BS, node n) with a multihop route to the BS."""
    out[:] = 0
    add(out, n)
    component(adj, n + 1, out, stack)


@njit(cache=True, error_model="numpy")
def flood(adj: np.ndarray, routed: np.ndarray, knows: np.ndarray, spread: np.ndarray,
          stack: np.ndarray) -> bool:
    """Pass the target's location from every drone that knows it to everyone it reaches, over
    any number of hops within the step (the BS relays too); ``knows`` grows accordingly.

    ``spread`` receives every node that knows afterwards; returns whether the BS is among them.
    The BS's component (``routed``) is closed: a knower in it informs exactly that component,
    so only the knowers outside it need a search of their own.
    """
    n = knows.shape[0]
    spread[:] = 0
    joined = False
    for i in range(n):
        if knows[i]:
            if has(routed, i):
                joined = True
            else:
                add(spread, i)
    component(adj, n + 1, spread, stack)
    if joined:  # word by word: ``spread |= routed`` kept the arguments' references counted
        for w in range(spread.shape[0]):
            spread[w] |= routed[w]
    for i in range(n):
        knows[i] = has(spread, i)
    return has(spread, n)


@njit(cache=True, error_model="numpy")
def part_of_bs(parked: int, mode: int) -> bool:
    """Whether a drone in ``mode`` counts as part of the BS: landed there, with
    ``readings.parked = base`` (``parked``, :class:`~sarlink.engine.codes.Parked`)."""
    return parked == _BASE and mode == _LANDED


@njit(cache=True, error_model="numpy")
def reachability(adj: np.ndarray, routed: np.ndarray, mode: np.ndarray, how: int = _DIRECT,
                 parked: int = _RELAY) -> tuple[bool, int]:
    """Whether the target has a route to the BS, and how many drones have one.

    ``how`` is ``readings.reachability``'s code (:class:`~sarlink.engine.codes.Reachability`):
    whether a direct target-BS link counts, or only a route over the drones. ``parked`` is
    ``readings.parked``'s (:class:`~sarlink.engine.codes.Parked`): with ``base`` a drone
    landed at the BS is part of it, so its link to the target is the BS's own (a direct
    link) and it is not a connected drone.
    """
    n = mode.shape[0]
    tg = n + 1
    reachable = how == _DIRECT and linked(adj, tg, n)
    connected = 0
    for i in range(n):
        if has(routed, i):
            if part_of_bs(parked, mode[i]):
                reachable |= how == _DIRECT and linked(adj, tg, i)
                continue
            connected += 1
            if linked(adj, tg, i):
                reachable = True
    return reachable, connected
