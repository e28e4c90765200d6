"""Critical ranges: one flight of a range-free team, read at every communication range.

When no drone's path depends on the links (routes, CovB, drones that do not report:
:attr:`sarlink.engine.run.Prepared.range_free`), the flight is the same at every range
``r_c`` and only the graph changes. Every link is then described by one number, its *key*:
the smallest ``R2 = fl(r_c²)`` at which it exists. On the disc the key is the squared
distance ``d²`` exactly as the link pass computes it (:func:`sarlink.engine.graph.links`:
``d² ≤ R2``); under shadowing, where the link pass tests ``d² ≤ fl(R2 · f)`` with the fade
``f = 10^(-S/5n)``, it is the smallest float ``R2`` that passes, found with ``nextafter``, so
the effective squared distance ``d² / f`` is exact in the engine's own arithmetic. Everything
below is a comparison of keys with ``R2``, so the results equal a direct flight at any range
bit for bit, knife edges included.

Per step, a minimum spanning tree of the drones and the BS (Prim's, from the BS; the target
never relays) gives every bottleneck path: a drone is routed to the BS at ``R2`` iff the
largest key on its tree path is ``≤ R2`` (its *routed key*), and the target is reachable iff
``min(key(target, BS), min_i max(routed key_i, key(target, i))) ≤ R2``. Knowledge spreads
hop by hop within a step and is kept: a drone's *knowledge key* is the smallest ``R2`` at
which it knows, the minimum over the sources (drones that sensed the target: 0; drones that
knew the step before: their key) of the largest key on the way, two passes over the tree.
The BS is notified at ``R2`` from the first step its key is ``≤ R2``; the steps at which the
running minimum of its key falls are the run's notification staircase, all that P_s needs.

The flight is read from its positions (``Params.trace``); the sensing looks and the fades are
drawn again from fresh copies of the run's streams, which the flight draws independently of
``r_c`` (docs/model.md, "One flight, every range"). Only the built-in log-normal radio
(disc and shadowing) is read this way: its fades are redrawn here with its own hook.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from sarlink.engine import records, sensing
from sarlink.engine.codes import Reachability
from sarlink.engine.params import STOP_DETECTED, STOP_NOTIFIED, Params
from sarlink.engine.radios import lognormal

_DIRECT = int(Reachability.DIRECT)

_INF = math.inf


class Critical(NamedTuple):
    """A flight's critical ranges, and its records at the squared ranges it was read at."""

    det_step: int
    """The step of the first detection (``-1``: none)."""
    detector: int
    """The first detector (``-1``: none)."""
    notify_steps: np.ndarray
    """Steps at which the running minimum of the BS's knowledge key falls."""
    notify_keys: np.ndarray
    """That minimum from each of those steps on (squared ranges, m², in the link pass's
    arithmetic): notified by ``notify_steps[j]`` iff ``notify_keys[j] ≤ R2``."""
    notified: np.ndarray
    """Per squared range read at: the step of the notification (``-1``: never)."""
    reach_cum: np.ndarray
    """``(ranges, checkpoints)``: the kernel's ``reach_cum`` at each squared range."""
    conn_cum: np.ndarray
    """``(ranges, checkpoints)``: the kernel's ``conn_cum`` at each squared range."""


@njit(cache=True, inline="always", error_model="numpy")
def _effective(dd: float, fade: float) -> float:
    """The smallest ``R2 >= 0`` with ``fl(R2 * fade) >= dd``: the link's key under a fade."""
    x = dd / fade
    if x * fade >= dd:
        while x > 0.0:
            lower = np.nextafter(x, -_INF)
            if lower * fade < dd:
                break
            x = lower
    else:
        while x * fade < dd:
            x = np.nextafter(x, _INF)
    return max(x, 0.0)


@njit(cache=True, inline="always", error_model="numpy")
def _keys(px: np.ndarray, py: np.ndarray, pz: np.ndarray, fade: np.ndarray, shadowed: bool,
          key: np.ndarray) -> None:
    """Every link's key among the ``m`` nodes, computed as the link pass computes ``d²``
    (``dx² + dy² + dz²`` from node ``a`` to node ``b``, the same bits either way)."""
    m = key.shape[0]
    for a in range(m):
        xa, ya, za = px[a], py[a], pz[a]
        for b in range(a + 1, m):
            dx = xa - px[b]
            dy = ya - py[b]
            dz = za - pz[b]
            v = dx * dx + dy * dy + dz * dz
            if shadowed:
                v = _effective(v, fade[a, b])
            key[a, b] = v
            key[b, a] = v


@njit(cache=True, inline="always", error_model="numpy")
def _tree(key: np.ndarray, n: int, order: np.ndarray, parent: np.ndarray, up_key: np.ndarray,
          best: np.ndarray, joined: np.ndarray, routed: np.ndarray) -> None:
    """Prim's minimum spanning tree of the drones and the BS (node ``n``), grown from the BS.

    ``order``: the nodes in the order they joined (BS first), ``parent`` and ``up_key`` (the
    key of the edge to it) per node, ``routed``: the largest key on each node's path to the
    BS, which on a minimum spanning tree is the smallest over all paths. A joined node's
    ``best`` is infinite, so that the choice of the next node is a plain minimum.
    """
    for v in range(n):
        best[v] = key[n, v]
        parent[v] = n
        joined[v] = False
    routed[n] = 0.0
    order[0] = n
    for j in range(1, n + 1):
        u = 0
        low = _INF
        for v in range(n):
            b = best[v]
            if b < low:
                low = b
                u = v
        order[j] = u
        joined[u] = True
        best[u] = _INF
        up_key[u] = low
        routed[u] = max(routed[parent[u]], low)
        for v in range(n):
            k = key[u, v]
            better = k < best[v] and not joined[v]
            best[v] = k if better else best[v]
            parent[v] = u if better else parent[v]


@njit(cache=True, error_model="numpy")
def critical(p: Params, unit: Params, target_x: float, target_y: float, positions: np.ndarray,
             end: int, rng_shadow: np.random.Generator, rng_look: np.random.Generator,
             cp_steps: np.ndarray, r2s: np.ndarray, stairs: bool) -> Critical:
    """The critical ranges of steps ``0 .. end`` of a range-free flight, and its records at
    every squared range of ``r2s``, summed step by step in the kernel's order.

    Without ``stairs`` the knowledge keys are followed only until every range of ``r2s`` is
    notified, and the staircase is cut there.

    ``positions[k]`` are the drones' positions at step ``k`` as the kernel traced them; a
    team that settled has fewer rows, and its last holds for the later steps. ``rng_shadow``
    and ``rng_look`` are fresh copies of the run's streams; ``unit`` is ``p`` with ``r_c = 1``,
    with which the log-normal radio's ``update`` draws the bare fades.
    """
    n = positions.shape[1]
    m = n + 2
    last = positions.shape[0] - 1
    px, py, pz = np.zeros(m), np.zeros(m), np.zeros(m)
    pz[:n] = p.altitude
    px[n], py[n], px[n + 1], py[n + 1] = p.bs_x, p.bs_y, target_x, target_y
    shadowed = p.sigma > 0.0
    no_params = np.empty(0)
    # the radio's own fade state (correlated fades keep theirs in rows past m)
    fade = lognormal.init(unit, no_params, m, m) if shadowed else np.ones((0, 0))
    key = np.empty((m, m))
    order = np.empty(n + 1, dtype=np.int64)
    parent = np.empty(n + 1, dtype=np.int64)
    up_key, best, routed = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1)
    joined = np.zeros(n, dtype=np.bool_)
    up, knows_key = np.empty(n + 1), np.full(n + 1, _INF)
    in_range = np.zeros(n, dtype=np.bool_)
    pass_start = np.zeros(n, dtype=np.int64)
    sensed = np.zeros(n, dtype=np.bool_)
    notify_steps = np.empty(end + 1, dtype=np.int64)
    notify_keys = np.empty(end + 1)
    count = 0
    lowest_bs = _INF  # the running minimum of the BS's knowledge key
    det_step = detector = -1
    reach_key = _INF
    nr = r2s.shape[0]
    notified = np.full(nr, -1, dtype=np.int64)
    reach_cum = np.full((nr, cp_steps.shape[0]), np.nan)
    conn_cum = np.full((nr, cp_steps.shape[0]), np.nan)
    acc_reach, acc_conn = np.zeros(nr), np.zeros(nr)
    ci = np.zeros(nr, dtype=np.int64)
    going = np.ones(nr, dtype=np.bool_)  # ranges whose run has not stopped
    narrowest = r2s.min() if nr > 0 else -_INF
    for k in range(end + 1):
        for r in range(nr):
            if going[r]:
                ci[r] = records.take_checkpoints(k, cp_steps, ci[r], reach_cum[r], conn_cum[r],
                                                 acc_reach[r], acc_conn[r])
        if k <= last:
            for i in range(n):
                px[i] = positions[k, i, 0]
                py[i] = positions[k, i, 1]
        if shadowed:
            lognormal.update(fade, unit, no_params, k, rng_shadow)
        first = sensing.sense(px, py, k, p, in_range, pass_start, sensed, rng_look)
        if det_step < 0 and first >= 0:
            det_step, detector = k, first
        if k <= last or shadowed:  # a settled team's graph is that of its last traced step
            _keys(px, py, pz, fade, shadowed, key)
            _tree(key, n, order, parent, up_key, best, joined, routed)
            reach_key = key[n + 1, n] if p.reachability == _DIRECT else _INF
            for i in range(n):
                reach_key = min(reach_key, max(routed[i], key[n + 1, i]))
        if det_step >= 0 and (stairs or lowest_bs > narrowest):
            # knowledge: sources are the drones that sensed (key 0) or knew (their key); a
            # key at or above the BS's running minimum no longer matters (notified there)
            for i in range(n):
                up[i] = 0.0 if sensed[i] else knows_key[i]
                if up[i] >= lowest_bs:
                    up[i] = _INF
            up[n] = _INF  # the BS relays but does not keep knowledge (graph.flood)
            for j in range(n, 0, -1):
                v = order[j]
                u = parent[v]
                up[u] = min(up[u], max(up[v], up_key[v]))
            bs_key = float(up[n])
            knows_key[n] = bs_key
            for j in range(1, n + 1):
                v = order[j]
                knows_key[v] = min(up[v], max(knows_key[parent[v]], up_key[v]))
            if bs_key < lowest_bs:
                lowest_bs = bs_key
                notify_steps[count] = k
                notify_keys[count] = lowest_bs
                count += 1
        for r in range(nr):
            if not going[r]:
                continue
            r2 = r2s[r]
            if notified[r] < 0 and lowest_bs <= r2:
                notified[r] = k
            if k == p.n_steps or (p.stop == STOP_DETECTED and det_step >= 0) or (
                    p.stop == STOP_NOTIFIED and notified[r] >= 0):
                going[r] = False
                continue
            connected = 0
            for i in range(n):
                if routed[i] <= r2:
                    connected += 1
            acc_reach[r] += p.dt if reach_key <= r2 else 0.0
            acc_conn[r] += p.dt * connected / n
    return Critical(det_step, detector, notify_steps[:count].copy(), notify_keys[:count].copy(),
                    notified, reach_cum, conn_cum)
