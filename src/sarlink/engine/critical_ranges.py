"""Critical ranges: one flight of a range-free team, scanned at every communication range.

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

Scanned at a few given ranges without the staircase (what a sweep over ``rc`` needs), a tree per
step is more than needed: the graph at each range changes only when a link's key crosses that
range, which moving drones do about once a step among all the links and ranges of a run. So
the links' *bands* (how many of the ranges lie below their key) are followed instead, and the
graph of a range, with its BS component, reachability and flood (the kernel's own functions),
is worked out again only when a link enters or leaves it, or a drone newly senses the target.
This range scan runs inside the flight (:func:`scan_step`, called by the kernel at every step
when given ranges): the flight's own looks and fades (its radio flies at ``r_c = 1``, so its
thresholds are the bare fades) and its positions as they are, with no graph at the flight's
own range.

The staircase is found after the flight from its positions (``Params.trace``: the flight
keeps no graph); the sensing looks and the fades are drawn again from copies of the run's
streams, which the flight draws independently of ``r_c`` (docs/model.md, "One flight, every
range"). Only the built-in log-normal radio (disc and shadowing) is scanned either way: its
fades are the same at every range.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from sarlink.engine import graph, records, sensing
from sarlink.engine.codes import Reachability
from sarlink.engine.geometry import FAR, PAD, d2
from sarlink.engine.params import PARKED_BASE, STOP_DETECTED, STOP_NOTIFIED, Params
from sarlink.engine.radios import lognormal

_DIRECT = int(Reachability.DIRECT)

_INF = math.inf
_ZERO = np.uint64(0)
_ONE = np.uint64(1)
_NO_KEY = np.empty((0, 0))  # a range scan's graphs are its own (_networks)


class Critical(NamedTuple):
    """A flight's critical ranges, and its records at the squared ranges it was scanned at."""

    det_step: int
    """The step of the first detection (``-1``: none)."""
    detector: int
    """The first detector (``-1``: none)."""
    notify_steps: np.ndarray
    """Steps at which the running minimum of the BS's knowledge key falls (empty unless the
    staircase was asked for)."""
    notify_keys: np.ndarray
    """That minimum from each of those steps on (squared ranges, m², in the link pass's
    arithmetic): notified by ``notify_steps[j]`` iff ``notify_keys[j] ≤ R2``."""
    notified: np.ndarray
    """Per squared range scanned at: the step of the notification (``-1``: never)."""
    reach_cum: np.ndarray
    """``(ranges, checkpoints)``: the kernel's ``reach_cum`` at each squared range."""
    conn_cum: np.ndarray
    """``(ranges, checkpoints)``: the kernel's ``conn_cum`` at each squared range."""
    depth: np.ndarray
    """``(ranges, checkpoints)``: the BS's network's depth at each squared range
    (:func:`sarlink.engine.records.network`)."""
    farthest: np.ndarray
    """``(ranges, checkpoints)``: its farthest drone at each squared range."""


@njit(cache=True, error_model="numpy")
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
            v = d2(xa, ya, za, px[b], py[b], pz[b])
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


@njit(cache=True, inline="always", error_model="numpy")
def _toggle(adj: np.ndarray, a: int, b: int) -> None:
    """Add or remove the link ``a``-``b`` in the adjacency bitsets ``adj``."""
    adj[a, b >> 6] ^= np.uint64(1) << np.uint64(b & 63)
    adj[b, a >> 6] ^= np.uint64(1) << np.uint64(a & 63)


@njit(cache=True, inline="always", error_model="numpy")
def _networks(k: int, cp_steps: np.ndarray, ci: int, going: np.ndarray, p: Params,
              graphs: np.ndarray, key: np.ndarray, r2s: np.ndarray, mode: np.ndarray,
              px: np.ndarray, py: np.ndarray, depth: np.ndarray, farthest: np.ndarray) -> None:
    """The BS's network (:func:`sarlink.engine.records.network`) at the checkpoints of step
    ``k`` (from ``ci``) at every range whose run goes on, as the kernel takes it at its own
    checkpoints. The graph at range ``r`` is the scan's ``graphs[r]`` or, given the links'
    ``key`` (a traced flight's), made in ``graphs[0]`` from the keys at most ``r2s[r]``."""
    if ci >= cp_steps.shape[0] or cp_steps[ci] != k:
        return  # no checkpoint at this step (mostly)
    for r in range(going.shape[0]):
        if not going[r]:
            continue
        adj = graphs[r] if key.shape[0] == 0 else _graph_at(key, r2s[r], graphs[0])
        d, f = records.network(adj, mode, p.parked, px, py, p.bs_x, p.bs_y)
        c = ci
        while c < cp_steps.shape[0] and cp_steps[c] == k:
            depth[r, c] = d
            farthest[r, c] = f
            c += 1


@njit(cache=True, inline="always", error_model="numpy")
def _graph_at(key: np.ndarray, r2: float, adj: np.ndarray) -> np.ndarray:
    """``adj``, made the graph of the links whose key is at most ``r2`` (the link pass's test,
    ``d² <= R²``, in the keys' arithmetic)."""
    adj[:] = 0
    m = key.shape[0]
    for a in range(m):
        for b in range(a + 1, m):
            if key[a, b] <= r2:
                _toggle(adj, a, b)
    return adj


@njit(cache=True, inline="always", error_model="numpy")
def _open_step(k: int, cp_steps: np.ndarray, ci: int, going: np.ndarray, reach_cum: np.ndarray,
               conn_cum: np.ndarray, acc_reach: np.ndarray, acc_conn: np.ndarray) -> int:
    """The checkpoints of step ``k`` at every range whose run has not stopped (the kernel's
    ``take_checkpoints``, whose next checkpoint is the same at all of them); return the next
    checkpoint."""
    while ci < cp_steps.shape[0] and cp_steps[ci] == k:
        for r in range(going.shape[0]):
            if going[r]:
                reach_cum[r, ci] = acc_reach[r]
                conn_cum[r, ci] = acc_conn[r]
        ci += 1
    return ci


@njit(cache=True, inline="always", error_model="numpy")
def _close_step(k: int, p: Params, det_step: int, notified: np.ndarray, going: np.ndarray,
                reachable: np.ndarray, connected: np.ndarray, acc_reach: np.ndarray,
                acc_conn: np.ndarray, n: int) -> None:
    """Stop the runs that stop at step ``k``, and add the step's records to the others, at
    every range as the kernel does (``reachable`` and ``connected``: per range)."""
    stop = k == p.n_steps or (p.stop == STOP_DETECTED and det_step >= 0)
    for r in range(going.shape[0]):
        if not going[r]:
            continue
        if stop or (p.stop == STOP_NOTIFIED and notified[r] >= 0):
            going[r] = False
            continue
        acc_reach[r] += p.dt if reachable[r] else 0.0
        acc_conn[r] += p.dt * connected[r] / n


@njit(cache=True, inline="always", error_model="numpy")
def _nodes(p: Params, unit: Params, n: int, target_x: float, target_y: float
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The nodes' coordinates (drones, the BS, the target, then far-away padding) and the
    radio's fade state."""
    m = n + 2
    mp = (m + PAD - 1) // PAD * PAD  # padded as the kernel pads them (the link loop's vectors)
    px, py, pz = np.full(mp, FAR), np.full(mp, FAR), np.zeros(mp)
    pz[:n] = p.altitude
    px[n], py[n], px[n + 1], py[n + 1] = p.bs_x, p.bs_y, target_x, target_y
    # the radio's own fade state (correlated fades keep theirs in rows past m)
    fade = lognormal.init(unit, np.empty(0), m, m) if p.sigma > 0.0 else np.ones((0, 0))
    return px, py, pz, fade


@njit(cache=True, inline="always", error_model="numpy")
def _records(nr: int, checkpoints: int) -> tuple[np.ndarray, ...]:
    """Every range's records and state at the start: its notification step, its cumulative
    reachability and connected fraction at the checkpoints and their running sums, whether
    its run goes on, the step's reachability and connected drones, and the BS's network's
    depth and farthest drone at the checkpoints."""
    return (np.full(nr, -1, dtype=np.int64), np.full((nr, checkpoints), np.nan),
            np.full((nr, checkpoints), np.nan), np.zeros(nr), np.zeros(nr),
            np.ones(nr, dtype=np.bool_), np.zeros(nr, dtype=np.bool_),
            np.zeros(nr, dtype=np.int64), np.full((nr, checkpoints), np.nan),
            np.full((nr, checkpoints), np.nan))


@njit(cache=True, inline="always", error_model="numpy")
def _observe(k: int, last: int, positions: np.ndarray, px: np.ndarray, py: np.ndarray,
             fade: np.ndarray, unit: Params, no_params: np.ndarray,
             rng_shadow: np.random.Generator, p: Params, in_range: np.ndarray,
             pass_start: np.ndarray, sensed: np.ndarray, rng_look: np.random.Generator) -> int:
    """Step ``k``'s positions (a settled team keeps its last traced ones), the radio's fades
    and the drones' looks; return the drone that first sensed the target now, or -1."""
    if k <= last:
        for i in range(positions.shape[1]):
            px[i] = positions[k, i, 0]
            py[i] = positions[k, i, 1]
    if p.sigma > 0.0:
        lognormal.update(fade, unit, no_params, k, rng_shadow)
    return sensing.sense(px, py, k, p, in_range, pass_start, sensed, rng_look)


@njit(cache=True, error_model="numpy")
def critical(p: Params, unit: Params, target_x: float, target_y: float, positions: np.ndarray,
             modes: np.ndarray, end: int, rng_shadow: np.random.Generator,
             rng_look: np.random.Generator, cp_steps: np.ndarray, r2s: np.ndarray) -> Critical:
    """The critical ranges of steps ``0 .. end`` of a range-free flight (its notification
    staircase, from every step's minimum spanning tree), and its records at every squared
    range of ``r2s``, summed step by step in the kernel's order.

    ``positions[k]`` and ``modes[k]`` are the drones' positions and modes at step ``k`` as
    the kernel traced them (``Params.trace``); a team that settled has fewer rows, and its
    last holds for the later steps. With ``readings.parked = base`` a parked drone is part of
    the BS (:func:`sarlink.engine.graph.reachability`). ``rng_shadow`` and ``rng_look`` are
    fresh copies of the run's streams; ``unit`` is ``p`` with ``r_c = 1``, with which the
    log-normal radio's ``update`` draws the bare fades.
    """
    n = positions.shape[1]
    last = positions.shape[0] - 1
    px, py, pz, fade = _nodes(p, unit, n, target_x, target_y)
    shadowed = p.sigma > 0.0
    no_params = np.empty(0)
    key = np.empty((n + 2, n + 2))
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
    (notified, reach_cum, conn_cum, acc_reach, acc_conn, going, reachable, connected, depth,
     farthest) = _records(nr, cp_steps.shape[0])
    scratch = np.zeros((1, n + 2, (n + 2 + 63) // 64), dtype=np.uint64)
    ci = 0
    for k in range(end + 1):
        due = ci
        ci = _open_step(k, cp_steps, ci, going, reach_cum, conn_cum, acc_reach, acc_conn)
        first = _observe(k, last, positions, px, py, fade, unit, no_params, rng_shadow, p,
                         in_range, pass_start, sensed, rng_look)
        if det_step < 0 and first >= 0:
            det_step, detector = k, first
        row = min(k, last)
        if k <= last or shadowed:  # a settled team's graph is that of its last traced step
            _keys(px, py, pz, fade, shadowed, key)
            _tree(key, n, order, parent, up_key, best, joined, routed)
            reach_key = key[n + 1, n] if p.reachability == _DIRECT else _INF
            for i in range(n):
                if p.reachability == _DIRECT or not graph.part_of_bs(p.parked, modes[row, i]):
                    reach_key = min(reach_key, max(routed[i], key[n + 1, i]))
        _networks(k, cp_steps, due, going, p, scratch, key, r2s, modes[row], px, py, depth,
                  farthest)
        if det_step >= 0:
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
            r2 = r2s[r]
            if notified[r] < 0 and lowest_bs <= r2:
                notified[r] = k
            reachable[r] = reach_key <= r2
            connected[r] = 0
            for i in range(n):
                if routed[i] <= r2 and not graph.part_of_bs(p.parked, modes[row, i]):
                    connected[r] += 1
        _close_step(k, p, det_step, notified, going, reachable, connected, acc_reach,
                    acc_conn, n)
    return Critical(det_step, detector, notify_steps[:count].copy(), notify_keys[:count].copy(),
                    notified, reach_cum, conn_cum, depth, farthest)


class Scan(NamedTuple):
    """A range-free flight scanned at several ranges as it flies (:func:`scan_step`): the graph
    at each range, and each range's records. Ranges are indexed in ascending order."""

    thr: np.ndarray
    """The squared ranges, ascending."""
    rank: np.ndarray
    """``thr[j] = r2s[rank[j]]``."""
    band: np.ndarray
    """``(m, m)``: per link ``a < b``, how many ranges lie below its key."""
    bounds: np.ndarray
    """``(2, m, mp)``: the keys between which a link stays in its band, ``(lo, hi]``; never
    crossed off the links (``a >= b``, the padding)."""
    adj: np.ndarray
    """``(ranges, m, words)``: the graph at each range."""
    routed: np.ndarray
    """``(ranges, words)``: the BS's component at each range."""
    knows: np.ndarray
    """``(ranges, N)``: who knows the target's location at each range."""
    counted: np.ndarray
    """``(N,)``: the drones whose sensing is already in ``knows``."""
    changed: np.ndarray
    """``(ranges,)``: whether the graph at a range changed this step."""
    moved: np.ndarray
    """``(ranges,)``: whether the BS's component or the target's links may have changed with
    it (:func:`_band_link`)."""
    notified: np.ndarray
    """Per range: the step of the notification (``-1``: never)."""
    reach_cum: np.ndarray
    """``(ranges, checkpoints)``: the kernel's ``reach_cum`` at each range."""
    conn_cum: np.ndarray
    """``(ranges, checkpoints)``: the kernel's ``conn_cum`` at each range."""
    acc_reach: np.ndarray
    """Per range: the running sums of those records."""
    acc_conn: np.ndarray
    going: np.ndarray
    """Per range: whether its run goes on."""
    d_reach: np.ndarray
    """Per range: what this step adds to ``acc_reach`` (``dt`` if the target is reachable)."""
    d_conn: np.ndarray
    """Per range: what it adds to ``acc_conn`` (``dt`` times the fraction of drones with a
    route to the BS), both as the kernel computes them."""
    parked: np.ndarray
    """``(1,)``: how many drones were landed at the last step (with ``readings.parked =
    base`` a landing changes the records at every range, as it may change no link)."""
    depth: np.ndarray
    """``(ranges, checkpoints)``: the BS's network's depth at each range."""
    farthest: np.ndarray
    """``(ranges, checkpoints)``: its farthest drone at each range."""


@njit(cache=True, error_model="numpy")
def new_scan(r2s: np.ndarray, n: int, mp: int, checkpoints: int) -> Scan:
    """The range scan of a flight of ``n`` drones (``mp`` padded nodes) at the squared ranges
    ``r2s``, before its first step: no link at any range yet, so that the BS's component is
    the BS alone, the target unreachable and no drone connected."""
    m = n + 2
    rank = np.argsort(r2s, kind="mergesort")
    thr = r2s[rank]
    nr = thr.shape[0]
    bounds = np.empty((2, m, mp))
    bounds[0] = -_INF
    bounds[1] = _INF
    for a in range(m):
        bounds[0, a, a + 1:m] = thr[nr - 1] if nr > 0 else -_INF
    nw = (m + 63) // 64
    (notified, reach_cum, conn_cum, acc_reach, acc_conn, going, _, _, depth,
     farthest) = _records(nr, checkpoints)
    routed = np.zeros((nr, nw), dtype=np.uint64)
    for j in range(nr):
        graph.add(routed[j], n)
    return Scan(thr, rank, np.full((m, m), nr, dtype=np.int64), bounds,
                   np.zeros((nr, m, nw), dtype=np.uint64), routed,
                   np.zeros((nr, n), dtype=np.bool_), np.zeros(n, dtype=np.bool_),
                   np.zeros(nr, dtype=np.bool_), np.zeros(nr, dtype=np.bool_), notified,
                   reach_cum, conn_cum, acc_reach, acc_conn, going, np.zeros(nr),
                   np.zeros(nr), np.zeros(1, dtype=np.int64), depth, farthest)


@njit(cache=True, inline="always", error_model="numpy")
def _relayed(adj: np.ndarray, a: int, b: int, tg: int) -> bool:
    """Whether nodes ``a`` and ``b`` have a common neighbour other than the target ``tg``
    (which never relays): then they stay linked through it when their own link goes."""
    common = _ZERO
    for w in range(adj.shape[1]):
        word = adj[a, w] & adj[b, w]
        if w == tg >> 6:
            word &= ~(_ONE << np.uint64(tg & 63))
        common |= word
    return common != _ZERO


@njit(cache=True, inline="always", error_model="numpy")
def _band_link(a: int, b: int, v: float, sc: Scan) -> None:
    """Link ``a < b``, of key ``v``, into its band: toggled in the graphs of the ranges
    between its old band and its new one, whose BS component (and reachability) is marked
    as moved where the toggle may change it. It cannot if the link is new between two nodes
    on the same side of the component, is lost between two nodes not both in it or between two
    that stay linked through a third (:func:`_relayed`), or links the target (a leaf, node
    ``m - 1``) to a node off the component."""
    m = sc.band.shape[0]
    thr = sc.thr
    nr = thr.shape[0]
    now = np.searchsorted(thr, v)  # the ranges below the key
    was = sc.band[a, b]
    for j in range(min(now, was), max(now, was)):
        _toggle(sc.adj[j], a, b)
        sc.changed[j] = True
        if not sc.moved[j]:  # the component as of the step before, still right
            joined = graph.has(sc.routed[j], a), graph.has(sc.routed[j], b)
            if b == m - 1:
                sc.moved[j] = joined[0]
            elif now < was:  # the link is new at range j
                sc.moved[j] = joined[0] != joined[1]
            else:
                sc.moved[j] = joined[0] and joined[1] and not _relayed(sc.adj[j], a, b, m - 1)
    sc.band[a, b] = now
    sc.bounds[0, a, b] = thr[now - 1] if now > 0 else -_INF
    sc.bounds[1, a, b] = thr[now] if now < nr else _INF


@njit(cache=True, inline="always", error_model="numpy")
def _band_links(px: np.ndarray, py: np.ndarray, pz: np.ndarray, fade: np.ndarray,
                shadowed: bool, sc: Scan, near: np.ndarray, r2: float,
                with_near: bool) -> bool:
    """Bring the graph at every range up to date with this step's positions and fades and,
    if ``with_near``, the pairs within squared sensing range ``r2`` (``near``, as
    :func:`sarlink.engine.graph.links` gives them: the flight has no link pass of its own).

    Every link sits in a *band*, the number of ranges below its key: it exists at the ranges
    from its band on. Every ``d²`` is computed as the link pass computes it (whole padded
    rows, word by word, in vectors) and compared with its band's bounds (those of ``a >= b``
    and of the padding are never crossed), which gives the bitset of the links that left
    their band; only they change a graph, at the ranges between the old and the new band.
    Under shadowing every link's key moves with its fade, so every link is looked at.
    Returns whether any graph changed.
    """
    m = sc.band.shape[0]
    mp = px.shape[0]
    lo, hi = sc.bounds[0], sc.bounds[1]
    toggled = False
    for a in range(m):
        xa, ya, za = px[a], py[a], pz[a]
        lo_a, hi_a = lo[a], hi[a]
        for w in range(sc.adj.shape[2]):
            first = w * 64
            close = np.uint64(0)
            left = np.uint64(0)  # the links that left their band
            for b in range(first, min(mp, first + 64)):
                u = np.uint64(b)  # unsigned: the loop vectorizes (graph.links)
                dd = d2(xa, ya, za, px[u], py[u], pz[u])
                shift = np.uint64(b - first)
                left |= (_ONE if (dd <= lo_a[u]) | (dd > hi_a[u]) else _ZERO) << shift
                if with_near:
                    close |= (_ONE if dd <= r2 else _ZERO) << shift
            if with_near:
                if w == a >> 6:  # a node is not its own neighbour
                    close &= ~(_ONE << np.uint64(a & 63))
                near[a, w] = close
            if shadowed:
                continue
            toggled |= left != _ZERO
            while left:
                b = first + graph.lowest(left)
                left &= left - _ONE
                _band_link(a, b, d2(xa, ya, za, px[b], py[b], pz[b]), sc)
        if shadowed:  # every link's key moves with its fade
            for b in range(a + 1, m):
                v = _effective(d2(xa, ya, za, px[b], py[b], pz[b]), fade[a, b])
                if not lo[a, b] < v <= hi[a, b]:
                    _band_link(a, b, v, sc)
                    toggled = True
    return toggled


@njit(cache=True, error_model="numpy")
def scan_step(k: int, ci: int, p: Params, cp_steps: np.ndarray, px: np.ndarray,
              py: np.ndarray, pz: np.ndarray, fade: np.ndarray, detected: bool,
              sensed: np.ndarray, mode: np.ndarray, spread: np.ndarray, stack: np.ndarray,
              sc: Scan, near: np.ndarray, with_near: bool) -> None:
    """Step ``k`` of a range-free flight at every range: the checkpoints due (``ci``: the
    first of them), the graph (the kernel's link pass at every range, which also gives the
    pairs within ``r`` in ``near`` when a rule reads them, ``with_near``), the BS's component,
    reachability and the knowledge's flood (the kernel's own functions,
    :mod:`sarlink.engine.graph`), the notification and the step's records.

    A range's component and reachability are found again only where a change of its graph
    may have moved them (:func:`_band_link`), and its knowledge flooded again only when its
    graph or the knowers changed and its BS is not notified yet. ``fade`` are the radio's bare
    fades (the kernel's thresholds at ``r_c = 1``) and ``sensed`` the drones that sensed the
    target (a range-free flight floods nothing).
    """
    n = sensed.shape[0]
    _open_step(k, cp_steps, ci, sc.going, sc.reach_cum, sc.conn_cum, sc.acc_reach,
               sc.acc_conn)
    new_knower = False
    for i in range(n):
        new_knower |= sensed[i] and not sc.counted[i]
        sc.counted[i] = sensed[i]
    toggled = _band_links(px, py, pz, fade, p.sigma > 0.0, sc, near, p.r * p.r, with_near)
    parked = 0
    for i in range(n if p.parked == PARKED_BASE else 0):
        parked += graph.part_of_bs(p.parked, mode[i])
    if parked != sc.parked[0]:  # a drone became part of the BS: every range's records move
        sc.parked[0] = parked
        sc.moved[:] = True
        toggled = True
    notified_now = False
    # a step that changed no graph and no knower moves no component and floods nothing
    for j in range(sc.thr.shape[0] if toggled or new_knower else 0):
        if sc.moved[j]:
            graph.bs_component(sc.adj[j], n, sc.routed[j], stack)
            reachable, connected = graph.reachability(sc.adj[j], sc.routed[j], mode,
                                                      p.reachability, p.parked)
            sc.d_reach[j] = p.dt if reachable else 0.0
            sc.d_conn[j] = p.dt * connected / n
        if detected and sc.notified[j] < 0 and (sc.changed[j] or new_knower):
            for i in range(n):
                sc.knows[j, i] |= sensed[i]
            if graph.flood(sc.adj[j], sc.routed[j], sc.knows[j], spread, stack):
                sc.notified[j] = k
                notified_now = True
        sc.changed[j] = sc.moved[j] = False
    _networks(k, cp_steps, ci, sc.going, p, sc.adj, _NO_KEY, sc.thr, mode, px, py, sc.depth,
              sc.farthest)
    # the step's records, added at every range at once: a range whose run stopped takes no
    # more checkpoints (_open_step), so what is added to it after does not matter
    if k == p.n_steps or (p.stop == STOP_DETECTED and detected):
        sc.going[:] = False
    elif p.stop == STOP_NOTIFIED and notified_now:
        for j in range(sc.thr.shape[0]):
            sc.going[j] &= sc.notified[j] < 0
    for j in range(sc.thr.shape[0]):
        sc.acc_reach[j] += sc.d_reach[j]
        sc.acc_conn[j] += sc.d_conn[j]


@njit(cache=True, error_model="numpy")
def carry_scan(start: int, p: Params, cp_steps: np.ndarray, ci: int, sc: Scan,
               mode: np.ndarray, px: np.ndarray, py: np.ndarray) -> None:
    """A settled team: every range whose run goes on observes its last step again to the
    horizon (:func:`sarlink.engine.records.carry_records`), its BS's network too."""
    for j in range(sc.thr.shape[0]):
        if sc.going[j]:
            records.carry_records(start, p.n_steps, cp_steps, ci, sc.reach_cum[j],
                                  sc.conn_cum[j], sc.acc_reach[j], sc.acc_conn[j],
                                  sc.d_reach[j], sc.d_conn[j])
            d, f = records.network(sc.adj[j], mode, p.parked, px, py, p.bs_x, p.bs_y)
            sc.depth[j, ci:] = d  # the graph is fixed too: the BS's network repeats
            sc.farthest[j, ci:] = f


@njit(cache=True, error_model="numpy")
def scan_records(sc: Scan) -> records.AtRanges:
    """Each range's records, in the order of the ranges as given."""
    back = np.empty_like(sc.rank)
    back[sc.rank] = np.arange(sc.rank.shape[0])
    return records.AtRanges(sc.notified[back], sc.reach_cum[back], sc.conn_cum[back],
                            sc.depth[back], sc.farthest[back])
