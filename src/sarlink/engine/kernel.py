"""The mission model as Numba kernels: one run from arrays and scalars (``MODEL.md``).

This module is the only copy of the model. It never validates: :mod:`sarlink.engine.run`
builds its inputs from a checked :class:`~sarlink.config.Mission`.

Node indices: drones ``0 .. N-1``, the BS is node ``N``, the target (a node only for
reachability) is node ``N + 1``. Headings are unit vectors ``(hx, hy)``.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from sarlink.engine.codes import Look, Mode, Rule, Stop

SEARCHING = int(Mode.SEARCHING)
RETURNING = int(Mode.RETURNING)
LANDED = int(Mode.LANDED)
COVB = int(Rule.COVB)
CONB = int(Rule.CONB)
CONCOV = int(Rule.CONCOV)
PER_PERIOD = int(Look.PER_PERIOD)
STOP_DETECTED = int(Stop.DETECTED)
STOP_NOTIFIED = int(Stop.NOTIFIED)

_TINY = 1e-12
_PAD = 8
"""Position arrays are padded to a multiple of this many nodes, which the link loops then
cover in whole vectors: at N = 10 the scalar remainder of 12 nodes cost more than the rest."""
_FAR = 1e18
"""Where the padding nodes sit: farther than any range, so no link or sensing bit is set."""
_LN10 = math.log(10.0)


class Params(NamedTuple):
    """Scalars of one mission, in kernel units (metres, seconds, steps)."""

    size: float
    bs_x: float
    bs_y: float
    speed: float
    rule: int
    alpha: float
    flight_time: float
    r: float
    p_miss: float
    look: int
    rc: float
    sigma: float
    pathloss_exponent: float
    altitude: float
    dt: float
    ts_steps: int
    coherence_steps: int
    n_steps: int
    stop: int
    record: bool


@njit(cache=True, inline="always", error_model="numpy")
def _unit(x: float, y: float, fx: float, fy: float) -> tuple[float, float]:
    """``(x, y)`` scaled to length 1, or the fallback ``(fx, fy)`` if it vanishes."""
    n = math.sqrt(x * x + y * y)
    if n < _TINY:
        return fx, fy
    return x / n, y / n


@njit(cache=True, inline="always", error_model="numpy")
def _inside(x: float, y: float, size: float) -> bool:
    return 0.0 <= x <= size and 0.0 <= y <= size


@njit(cache=True, inline="always", error_model="numpy")
def _boundary_turn(
    x: float, y: float, hx: float, hy: float, step: float, size: float, rng: np.random.Generator
) -> tuple[float, float, bool]:
    """Keep the heading if the next increment stays inside; else a random inward heading.

    The inward headings are the half circle facing away from each wall the increment would
    cross (a quarter circle at a corner). A redraw that crosses another wall adds that wall.
    """
    nx, ny = x + step * hx, y + step * hy
    if _inside(nx, ny, size):
        return hx, hy, False
    left = right = bottom = top = False
    while True:
        left |= nx < 0.0
        right |= nx > size
        bottom |= ny < 0.0
        top |= ny > size
        lo, hi = 0.0, 2.0 * math.pi
        if left:
            lo, hi = -0.5 * math.pi, 0.5 * math.pi
        elif right:
            lo, hi = 0.5 * math.pi, 1.5 * math.pi
        if bottom:
            lo, hi = (0.0, 0.5 * math.pi) if left else ((0.5 * math.pi, math.pi) if right
                                                        else (0.0, math.pi))
        elif top:
            lo, hi = ((-0.5 * math.pi, 0.0) if left else ((math.pi, 1.5 * math.pi) if right
                                                          else (math.pi, 2.0 * math.pi)))
        theta = lo + rng.random() * (hi - lo)
        hx, hy = math.cos(theta), math.sin(theta)
        nx, ny = x + step * hx, y + step * hy
        if _inside(nx, ny, size):
            return hx, hy, True


@njit(cache=True, inline="always", error_model="numpy")
def _draw_shadowing(thr2: np.ndarray, p: Params, rng: np.random.Generator) -> None:
    """Redraw the per-link squared range: ``10 n log10(d/rc) + S <= 0  <=>  d² <= rc² 10^(-S/5n)``.

    With ``S = 0`` the factor is exactly 1, so ``sigma = 0`` is the disc model bit for bit.
    """
    m = thr2.shape[0]
    rc2 = p.rc * p.rc
    scale = -_LN10 / (5.0 * p.pathloss_exponent)
    for a in range(m):
        for b in range(a + 1, m):
            s = p.sigma * rng.standard_normal()
            v = rc2 * math.exp(scale * s)
            thr2[a, b] = v
            thr2[b, a] = v


# Adjacency is kept as bitsets: row ``a`` of ``adj`` is ``W = ceil((N + 2) / 64)`` words whose
# bit ``b`` says whether nodes ``a`` and ``b`` are linked; a breadth-first search then costs a
# few word operations per node instead of a scan of a boolean matrix.
_ZERO = np.uint64(0)
_ONE = np.uint64(1)
_DEBRUIJN = np.uint64(0x03F79D71B4CB0A89)
_DEBRUIJN_INDEX = np.array(
    [0, 1, 48, 2, 57, 49, 28, 3, 61, 58, 50, 42, 38, 29, 17, 4, 62, 55, 59, 36, 53, 51, 43, 22,
     45, 39, 33, 30, 24, 18, 12, 5, 63, 47, 56, 27, 60, 41, 37, 16, 54, 35, 52, 21, 44, 32, 23,
     11, 46, 26, 40, 15, 34, 20, 31, 10, 25, 14, 19, 9, 13, 8, 7, 6], dtype=np.int64)


@njit(cache=True, inline="always", error_model="numpy")
def _bit(word: np.uint64, a: int) -> bool:
    """Whether node ``a``'s bit is set in ``word``, the bitset word that holds it (for loops
    that must not hand arrays to helpers, see :func:`_conb_headings`)."""
    return (word >> np.uint64(a & 63)) & _ONE != 0


@njit(cache=True, inline="always", error_model="numpy")
def _has(bits: np.ndarray, a: int) -> bool:
    return (bits[a >> 6] >> np.uint64(a & 63)) & _ONE != 0


@njit(cache=True, inline="always", error_model="numpy")
def _add(bits: np.ndarray, a: int) -> None:
    bits[a >> 6] |= _ONE << np.uint64(a & 63)


@njit(cache=True, inline="always", error_model="numpy")
def _linked(adj: np.ndarray, a: int, b: int) -> bool:
    return (adj[a, b >> 6] >> np.uint64(b & 63)) & _ONE != 0


@njit(cache=True, inline="always", error_model="numpy")
def _links(
    px: np.ndarray, py: np.ndarray, pz: np.ndarray, thr2: np.ndarray, adj: np.ndarray,
    r2: float, near: np.ndarray,
) -> None:
    """Bitsets of the pairs within squared link range ``thr2[a, b]`` (``adj``) and, unless
    ``near`` is empty, within squared sensing range ``r2`` (``near``).

    Distances are 3-D: drones fly at ``pz = h``, the BS and the target sit on the ground.
    Every row is computed whole, without branches, so that the loop vectorizes: this is
    several times faster than testing each pair once and mirroring the bit. The positions
    are padded (see :data:`_FAR`): a row's length is the padded one.
    """
    m = adj.shape[0]
    mp = px.shape[0]
    with_near = near.shape[0] > 0
    for a in range(m):
        xa, ya, za = px[a], py[a], pz[a]
        for w in range(adj.shape[1]):
            lo = w * 64
            row = np.uint64(0)
            close = np.uint64(0)
            for b in range(lo, min(mp, lo + 64)):
                dx = xa - px[b]
                dy = ya - py[b]
                dz = za - pz[b]
                dd = dx * dx + dy * dy + dz * dz
                bit = np.uint64(b - lo)
                row |= (_ONE if dd <= thr2[a, b] else _ZERO) << bit
                if with_near:
                    close |= (_ONE if dd <= r2 else _ZERO) << bit
            if w == a >> 6:  # a node is not its own neighbour
                row &= ~(_ONE << np.uint64(a & 63))
                close &= ~(_ONE << np.uint64(a & 63))
            adj[a, w] = row
            if with_near:
                near[a, w] = close


@njit(cache=True, inline="always", error_model="numpy")
def _lowest(bits: np.uint64) -> int:
    """Index of the lowest set bit of a non-zero word."""
    return _DEBRUIJN_INDEX[((bits & (~bits + _ONE)) * _DEBRUIJN) >> np.uint64(58)]


@njit(cache=True, inline="always", error_model="numpy")
def _push_new(stack: np.ndarray, top: int, w: int, bits: np.uint64) -> int:
    """Push the node index of every set bit of word ``w``; return the new stack top."""
    while bits:
        stack[top] = w * 64 + _lowest(bits)
        top += 1
        bits &= bits - _ONE
    return top


@njit(cache=True, inline="always", error_model="numpy")
def _component(adj: np.ndarray, tg: int, out: np.ndarray, stack: np.ndarray) -> None:
    """Grow the node set ``out`` to everything linked to it, never routing through the target.

    The target (node ``tg``) is a leaf: it is marked as reached after the seeds are taken, so
    the search never expands it, and removed at the end.
    """
    top = 0
    for w in range(out.shape[0]):
        top = _push_new(stack, top, w, out[w])
    _add(out, tg)
    while top > 0:
        top -= 1
        a = stack[top]
        for w in range(out.shape[0]):
            new = adj[a, w] & ~out[w]
            out[w] |= new
            top = _push_new(stack, top, w, new)
    out[tg >> 6] &= ~(_ONE << np.uint64(tg & 63))


@njit(cache=True, inline="always", error_model="numpy")
def _bs_component(adj: np.ndarray, n: int, out: np.ndarray, stack: np.ndarray) -> None:
    """``out``: the nodes (drones and the BS, node n) with a multihop route to the BS."""
    out[:] = 0
    _add(out, n)
    _component(adj, n + 1, out, stack)


@njit(cache=True, inline="always", error_model="numpy")
def _covb_force(
    i: int, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray, near: np.ndarray,
    flying: np.ndarray, r: float,
) -> tuple[float, float]:
    """Unit direction of Eq. 6: own heading / r plus a 1/d push from each flying drone within
    r (``near & flying``), added in increasing drone order."""
    fx, fy = hx[i] / r, hy[i] / r
    neighbours = False
    for w in range(flying.shape[0]):
        bits = near[i, w] & flying[w]
        while bits:
            j = w * 64 + _lowest(bits)
            bits &= bits - _ONE
            neighbours = True
            dx = px[i] - px[j]
            dy = py[i] - py[j]
            dd = dx * dx + dy * dy
            if dd >= 1.0:  # (1/d) * (p_i - p_j)/d; pairs closer than 1 m exert no force
                fx += dx / dd
                fy += dy / dd
    ux, uy = hx[i], hy[i]
    if neighbours:
        ux, uy = _unit(fx, fy, ux, uy)
    return ux, uy


@njit(cache=True, inline="always", error_model="numpy")
def _conb_headings(
    deciding: np.ndarray, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
    mode: np.ndarray, adj: np.ndarray, routed_next: np.ndarray, p: Params, vx: np.ndarray,
    vy: np.ndarray,
) -> None:
    """Unit direction of Eq. 9 (Algorithm 1, part 2) of every deciding drone, into ``vx, vy``.

    A drone keeps its heading if it is predicted to reach the BS at ``t + t_s``; else it
    steers towards where the neighbour with the longest contact (among those predicted to
    keep a route to the BS, if any) would be when the contact ends. A neighbour's route
    "without i" is its route in the predicted graph: ``i`` is not in the BS's predicted
    component here, so removing it changes nothing.

    The loop over drones is here, with no array-taking helper inside it, rather than a
    helper called per drone: Numba counts the references of every array it hands to an
    inlined helper, two atomic operations each, which cost a quarter of a ConB run.
    """
    n = hx.shape[0]
    rc2 = p.rc * p.rc
    for i in range(n):
        if not deciding[i]:
            continue
        vx[i], vy[i] = hx[i], hy[i]
        if _bit(routed_next[i >> 6], i):
            continue
        neighbours = False
        candidates = False
        for j in range(n + 1):
            if _bit(adj[i, j >> 6], j):
                neighbours = True
                candidates |= _bit(routed_next[j >> 6], j)
        if not neighbours:
            continue
        vix, viy = p.speed * hx[i], p.speed * hy[i]
        best = -1
        best_rank = -1.0
        best_d2 = np.inf
        best_tau = best_vx = best_vy = 0.0
        for j in range(n + 1):
            if not _bit(adj[i, j >> 6], j) or (candidates and not _bit(routed_next[j >> 6], j)):
                continue
            vjx = vjy = 0.0  # the BS and landed drones stand still
            if j < n and mode[j] != LANDED:
                vjx, vjy = p.speed * hx[j], p.speed * hy[j]
            relx, rely = px[j] - px[i], py[j] - py[i]
            rvx, rvy = vjx - vix, vjy - viy
            a = rvx * rvx + rvy * rvy
            rel2 = relx * relx + rely * rely
            if a < _TINY:  # equal velocities: the contact never ends
                rank, tau = np.inf, p.flight_time
            else:
                b = 2.0 * (relx * rvx + rely * rvy)
                disc = b * b - 4.0 * a * (rel2 - rc2)
                tau = 0.0 if disc < 0.0 else max(0.0, (-b + math.sqrt(disc)) / (2.0 * a))
                rank = tau
            if rank > best_rank or (rank == best_rank and rel2 < best_d2):
                best, best_rank, best_d2 = j, rank, rel2
                best_tau, best_vx, best_vy = tau, vjx, vjy
        cx, cy = px[best] + best_vx * best_tau, py[best] + best_vy * best_tau
        nx, ny = px[i] + p.speed * p.dt * hx[i], py[i] + p.speed * p.dt * hy[i]
        ux, uy = _unit(cx - nx, cy - ny, hx[i], hy[i])
        rx, ry = hx[i] + ux, hy[i] + uy
        if math.sqrt(rx * rx + ry * ry) >= 1e-9:  # else flying straight away from the contact
            ux, uy = _unit(rx, ry, ux, uy)
        vx[i], vy[i] = ux, uy


@njit(cache=True, inline="always", error_model="numpy")
def _predict_routes(
    px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray, mode: np.ndarray,
    pz: np.ndarray, p: Params, qx: np.ndarray, qy: np.ndarray, disc2: np.ndarray,
    out: np.ndarray, stack: np.ndarray,
) -> None:
    """Who reaches the BS at ``t + t_s`` if every node keeps its heading (shadow-free range).

    A breadth-first search from the BS that computes a node's links only when it reaches
    the node: the links of nodes cut off from the BS are never needed.
    """
    n = hx.shape[0]
    m = n + 2
    mp = qx.shape[0]
    ahead = p.speed * p.ts_steps * p.dt
    for j in range(m):
        qx[j], qy[j] = px[j], py[j]
        if j < n and mode[j] != LANDED:
            qx[j] += ahead * hx[j]
            qy[j] += ahead * hy[j]
    out[:] = 0
    _add(out, n)
    _add(out, n + 1)  # the target relays nothing
    stack[0] = n
    top = 1
    while top > 0:
        top -= 1
        a = stack[top]
        xa, ya, za = qx[a], qy[a], pz[a]
        for w in range(out.shape[0]):
            lo = w * 64
            row = np.uint64(0)
            for b in range(lo, min(mp, lo + 64)):
                dx = xa - qx[b]
                dy = ya - qy[b]
                dz = za - pz[b]
                row |= (_ONE if dx * dx + dy * dy + dz * dz <= disc2[a, b] else _ZERO) << (
                    np.uint64(b - lo))
            new = row & ~out[w]
            out[w] |= new
            top = _push_new(stack, top, w, new)
    out[(n + 1) >> 6] &= ~(_ONE << np.uint64((n + 1) & 63))


@njit(cache=True, error_model="numpy")
def _carry_records(start: int, n_steps: int, cp_steps: np.ndarray, ci: int, reach_cum: np.ndarray,
                   conn_cum: np.ndarray, acc_reach: float, acc_conn: float, d_reach: float,
                   d_conn: float) -> None:
    """Fill the checkpoints from step ``start`` on, as if every step added ``d_reach`` and
    ``d_conn``: summed step by step, like the full loop, so that the sums are the same."""
    for k in range(start, n_steps + 1):
        while ci < cp_steps.shape[0] and cp_steps[ci] == k:
            reach_cum[ci] = acc_reach
            conn_cum[ci] = acc_conn
            ci += 1
        acc_reach += d_reach
        acc_conn += d_conn


@njit(cache=True, inline="always", error_model="numpy")
def _settled(mode: np.ndarray, in_range: np.ndarray, knows: np.ndarray, look: int) -> bool:
    """Whether no later step can differ from this one: every drone has landed, and none in
    sensing range still looks for the target (only per-period looks repeat in place)."""
    for i in range(mode.shape[0]):
        if mode[i] != LANDED or (look == PER_PERIOD and in_range[i] and not knows[i]):
            return False
    return True


@njit(cache=True, inline="always", error_model="numpy")
def _fly_route(
    i: int, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
    mode: np.ndarray, wp: np.ndarray, wp_next: np.ndarray, wp_end: np.ndarray, step: float,
) -> None:
    """Advance drone ``i`` by ``step`` metres along its waypoints; land after the last one."""
    travel = step
    while True:
        k = wp_next[i]
        tx, ty = wp[k, 0], wp[k, 1]
        dx, dy = tx - px[i], ty - py[i]
        d = math.sqrt(dx * dx + dy * dy)
        if d > travel:
            px[i] += travel * dx / d
            py[i] += travel * dy / d
            hx[i], hy[i] = dx / d, dy / d
            return
        px[i], py[i] = tx, ty
        travel -= d
        wp_next[i] = k + 1
        if k + 1 >= wp_end[i]:
            mode[i] = LANDED
            return
        nx, ny = wp[k + 1, 0] - tx, wp[k + 1, 1] - ty
        hx[i], hy[i] = _unit(nx, ny, hx[i], hy[i])
        if travel <= 0.0:
            return


@njit(cache=True, error_model="numpy", nogil=True)
def simulate_kernel(
    p: Params,
    target_x: float,
    target_y: float,
    pos0: np.ndarray,
    heading0: np.ndarray,
    wp: np.ndarray,
    wp_start: np.ndarray,
    cp_steps: np.ndarray,
    rng_turn: np.random.Generator,
    rng_shadow: np.random.Generator,
    rng_look: np.random.Generator,
) -> tuple:
    """Simulate one run; return its event times, cumulative records and optional trajectory.

    ``wp[wp_start[i]:wp_start[i+1]]`` is drone ``i``'s route (empty: distributed drone).
    ``cp_steps`` are the steps at which the cumulative records are taken.
    Returns ``(events, reach_cum, conn_cum, traj_pos, traj_head, traj_knows, traj_route,
    traj_mode, traj_links)`` with ``events = [t_detect, t_notify, detector, immediate]`` (-1: never).
    A run stopped early (``p.stop``) has NaN records after its last step and a trajectory
    that ends there. The kernel releases the GIL, so that several threads (a threaded Dask
    worker) can simulate at once.
    """
    n = pos0.shape[0]
    m = n + 2
    bs, tg = n, n + 1  # node indices of the BS and the target
    # positions padded to whole vectors of far-away nodes, linked to nothing (see _FAR)
    mp = (m + _PAD - 1) // _PAD * _PAD
    px = np.full(mp, _FAR)
    py = np.full(mp, _FAR)
    hx = np.empty(n)
    hy = np.empty(n)
    px[:n], py[:n] = pos0[:, 0], pos0[:, 1]
    px[bs], py[bs] = p.bs_x, p.bs_y
    px[tg], py[tg] = target_x, target_y
    for i in range(n):
        hx[i], hy[i] = math.cos(heading0[i]), math.sin(heading0[i])
    mode = np.full(n, SEARCHING, dtype=np.int8)
    on_route = np.empty(n, dtype=np.bool_)
    wp_next = wp_start[:n].copy()
    wp_end = wp_start[1:].copy()
    for i in range(n):
        on_route[i] = wp_end[i] > wp_start[i]
        if on_route[i]:
            k = wp_start[i]
            hx[i], hy[i] = _unit(wp[k, 0] - px[i], wp[k, 1] - py[i], hx[i], hy[i])
    last_change = np.zeros(n, dtype=np.int64)
    knows = np.zeros(n, dtype=np.bool_)
    in_range = np.zeros(n, dtype=np.bool_)
    pass_start = np.zeros(n, dtype=np.int64)

    nw = (m + 63) // 64
    shadowed = p.sigma > 0.0
    pz = np.zeros(mp)
    pz[:n] = p.altitude
    disc2 = np.zeros((m, mp))  # squared link ranges without fading; none to the padding
    disc2[:, :m] = p.rc * p.rc
    thr2 = disc2.copy() if shadowed else disc2
    near = np.zeros((m, nw), dtype=np.uint64)  # pairs within sensing range, for CovB
    flying = np.zeros(nw, dtype=np.uint64)  # drones not landed: they exert CovB's push
    adj = np.zeros((m, nw), dtype=np.uint64)
    routed = np.zeros(nw, dtype=np.uint64)
    flood = np.zeros(nw, dtype=np.uint64)
    stack = np.empty(m, dtype=np.int64)
    # prediction buffers (shadow-free ranges: a drone cannot foresee fading)
    qx = np.full(mp, _FAR)
    qy = np.full(mp, _FAR)
    routed_next = np.zeros(nw, dtype=np.uint64)
    nhx = np.empty(n)
    nhy = np.empty(n)
    conb = p.rule == CONB or (p.rule == CONCOV and p.alpha < 1.0)
    deciding = np.zeros(n, dtype=np.bool_)  # drones whose t_s is up this step
    conb_x = np.zeros(n)  # ConB's direction of each deciding drone
    conb_y = np.zeros(n)

    kk = p.n_steps + 1 if p.record else 0
    traj_pos = np.empty((kk, n, 2))
    traj_head = np.empty((kk, n))
    traj_knows = np.empty((kk, n), dtype=np.bool_)
    traj_route = np.empty((kk, n), dtype=np.bool_)
    traj_mode = np.empty((kk, n), dtype=np.int8)
    traj_links = np.empty((kk, m, nw), dtype=np.uint64)

    reach_cum = np.empty(cp_steps.shape[0])
    conn_cum = np.empty(cp_steps.shape[0])
    acc_reach = 0.0
    acc_conn = 0.0
    ci = 0
    t_det = -1.0
    t_not = -1.0
    detector = -1
    immediate = False
    r2 = p.r * p.r
    covb = p.rule == COVB or (p.rule == CONCOV and p.alpha > 0.0)
    step = p.speed * p.dt
    routes = wp.shape[0] > 0
    may_settle = not (p.record or shadowed)  # a recorded run keeps every step
    # no drone inside the area is farther from the BS than the farthest corner, so the
    # return-home test cannot fire before that corner's flight home is due
    home_max = 1.0
    for cx in (0.0, p.size):
        for cy in (0.0, p.size):
            home_max = max(home_max, 1.0 + math.sqrt((p.bs_x - cx) ** 2 + (p.bs_y - cy) ** 2))

    for k in range(p.n_steps + 1):
        t = k * p.dt
        while ci < cp_steps.shape[0] and cp_steps[ci] == k:
            reach_cum[ci] = acc_reach
            conn_cum[ci] = acc_conn
            ci += 1
        # ---- observe: sense, link, flood, notify, account ----
        if shadowed and k % p.coherence_steps == 0:
            _draw_shadowing(thr2, p, rng_shadow)
        for i in range(n):
            dx, dy = px[i] - target_x, py[i] - target_y
            now_in = dx * dx + dy * dy <= r2
            if now_in:
                look = not in_range[i]
                if look:
                    pass_start[i] = k
                elif p.look == PER_PERIOD and (k - pass_start[i]) % p.ts_steps == 0:
                    look = True
                if look and rng_look.random() >= p.p_miss:
                    knows[i] = True
                    if t_det < 0.0:
                        t_det = t
                        detector = i
            in_range[i] = now_in
        push = False
        if covb:
            flying[:] = 0
            for i in range(n):
                push |= (not on_route[i] and mode[i] == SEARCHING
                         and k - last_change[i] >= p.ts_steps)
                if mode[i] != LANDED:
                    _add(flying, i)
        _links(px, py, pz, thr2, adj, r2, near if push else near[:0])
        _bs_component(adj, n, routed, stack)
        if t_det >= 0.0:
            # the BS's component is closed: a knower in it informs exactly that component,
            # so only the knowers outside it need a search of their own
            flood[:] = 0
            joined = False
            for i in range(n):
                if knows[i]:
                    if _has(routed, i):
                        joined = True
                    else:
                        _add(flood, i)
            _component(adj, tg, flood, stack)
            if joined:
                flood |= routed
            for i in range(n):
                knows[i] = _has(flood, i)
            if t_not < 0.0 and _has(flood, bs):
                t_not = t
                immediate = t_not == t_det
        reachable = _linked(adj, tg, bs)
        connected = 0
        for i in range(n):
            if _has(routed, i):
                connected += 1
                if _linked(adj, tg, i):
                    reachable = True
        if p.record:
            for i in range(n):
                traj_pos[k, i, 0] = px[i]
                traj_pos[k, i, 1] = py[i]
                traj_head[k, i] = math.atan2(hy[i], hx[i])
                traj_route[k, i] = _has(routed, i)
            traj_knows[k] = knows
            traj_mode[k] = mode
            traj_links[k] = adj
        if k == p.n_steps or (p.stop == STOP_DETECTED and t_det >= 0.0) or (
                p.stop == STOP_NOTIFIED and t_not >= 0.0):
            break
        acc_reach += p.dt if reachable else 0.0
        acc_conn += p.dt * connected / n
        homing = (p.flight_time - t) - home_max / p.speed < 2.0 * p.dt
        # a drone lands at the end of its route or, homing, at the BS
        if may_settle and (routes or homing) and _settled(mode, in_range, knows, p.look):
            # a settled team observes this step again and again (the graph, the knowers and
            # the links to the target are fixed): carry the sums to the horizon
            _carry_records(k + 1, p.n_steps, cp_steps, ci, reach_cum, conn_cum, acc_reach,
                           acc_conn, p.dt if reachable else 0.0, p.dt * connected / n)
            ci = cp_steps.shape[0]
            break

        # ---- decide: every drone from the state before anyone turns ----
        any_deciding = False
        for i in range(n):
            nhx[i], nhy[i] = hx[i], hy[i]
            deciding[i] = False
            if on_route[i] or mode[i] != SEARCHING:
                continue
            if homing:
                hdx, hdy = p.bs_x - px[i], p.bs_y - py[i]
                home = math.sqrt(hdx * hdx + hdy * hdy)
                if (p.flight_time - t) - home / p.speed < 2.0 * p.dt:
                    mode[i] = RETURNING
                    nhx[i], nhy[i] = _unit(hdx, hdy, hx[i], hy[i])
                    continue
            if k - last_change[i] >= p.ts_steps:
                last_change[i] = k
                deciding[i] = any_deciding = True
        if conb and any_deciding:
            _predict_routes(px, py, hx, hy, mode, pz, p, qx, qy, disc2, routed_next, stack)
            _conb_headings(deciding, px, py, hx, hy, mode, adj, routed_next, p, conb_x, conb_y)
        for i in range(n):
            if on_route[i] or mode[i] != SEARCHING:  # flying a route, home or landed
                continue
            if deciding[i]:
                cx, cy = hx[i], hy[i]
                vx, vy = conb_x[i], conb_y[i]
                if covb:
                    cx, cy = _covb_force(i, px, py, hx, hy, near, flying, p.r)
                if p.rule == COVB:
                    nhx[i], nhy[i] = cx, cy
                elif p.rule == CONB:
                    nhx[i], nhy[i] = vx, vy
                elif p.alpha == 1.0:  # Eq. 12 reduces to one unit force: skip the re-scaling
                    nhx[i], nhy[i] = cx, cy
                elif p.alpha == 0.0:
                    nhx[i], nhy[i] = vx, vy
                else:
                    nhx[i], nhy[i] = _unit(p.alpha * cx + (1.0 - p.alpha) * vx,
                                           p.alpha * cy + (1.0 - p.alpha) * vy, hx[i], hy[i])
            nhx[i], nhy[i], turned = _boundary_turn(px[i], py[i], nhx[i], nhy[i], step, p.size,
                                                    rng_turn)
            if turned:
                last_change[i] = k
        hx[:] = nhx
        hy[:] = nhy

        # ---- move ----
        for i in range(n):
            if mode[i] == LANDED:
                continue
            if on_route[i]:
                _fly_route(i, px, py, hx, hy, mode, wp, wp_next, wp_end, step)
            elif mode[i] == RETURNING:
                dx, dy = p.bs_x - px[i], p.bs_y - py[i]
                if dx * dx + dy * dy <= step * step:
                    px[i], py[i] = p.bs_x, p.bs_y
                    mode[i] = LANDED
                else:
                    px[i] += step * hx[i]
                    py[i] += step * hy[i]
            else:
                px[i] += step * hx[i]
                py[i] += step * hy[i]

    reach_cum[ci:] = np.nan  # checkpoints after an early stop
    conn_cum[ci:] = np.nan
    kk = min(kk, k + 1)
    events = np.array([t_det, t_not, float(detector), 1.0 if immediate else 0.0])
    return (events, reach_cum, conn_cum, traj_pos[:kk], traj_head[:kk], traj_knows[:kk],
            traj_route[:kk], traj_mode[:kk], traj_links[:kk])
