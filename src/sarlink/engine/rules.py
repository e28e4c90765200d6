"""The distributed planners' rules: CovB's push, ConB's prediction and contact choice, and
ConCov's blend of the two (docs/model.md, Planners).

Every drone that decides this step gets its new direction from the state before anyone turns.
ConB's directions are computed for all deciding drones in one pass (no array-taking helper
called per drone: Numba counts the references of every array it hands to an inlined helper,
two atomic operations each, which cost a quarter of a ConB run); :func:`steer` then applies
the team's rule and the boundary rule in one pass over the drones (docs/architecture.md).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.geometry import TINY, unit
from sarlink.engine.graph import add, bit, drop, lowest, push_new
from sarlink.engine.motion import boundary_turn
from sarlink.engine.params import (
    ALL_CONTACTS,
    CONB,
    CONCOV,
    CONNECTED_NONE,
    COVB,
    FALLBACK_CONNECTIVITY,
    ISOLATED_HOME,
    LANDED,
    SEARCHING,
    Params,
)

_ONE = np.uint64(1)
_ZERO = np.uint64(0)


@njit(cache=True, inline="always", error_model="numpy")
def uses_covb(p: Params) -> bool:
    """Whether the team needs CovB's force (CovB, or ConCov with α > 0)."""
    return p.rule == COVB or (p.rule == CONCOV and p.alpha > 0.0)


@njit(cache=True, inline="always", error_model="numpy")
def uses_conb(p: Params) -> bool:
    """Whether the team needs ConB's force (ConB, or ConCov with α < 1)."""
    return p.rule == CONB or (p.rule == CONCOV and p.alpha < 1.0)


@njit(cache=True, inline="always", error_model="numpy")
def covb_force(i: int, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
               near: np.ndarray, flying: np.ndarray, r: float) -> tuple[float, float]:
    """Unit direction of Eq. 6 for drone ``i``: own heading / r plus a 1/d push from each
    flying drone within r (``near & flying``), added in increasing drone order. No
    neighbour: keep the heading."""
    fx, fy = hx[i] / r, hy[i] / r
    neighbours = False
    for w in range(flying.shape[0]):
        bits = near[i, w] & flying[w]
        while bits:
            j = w * 64 + lowest(bits)
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
        ux, uy = unit(fx, fy, ux, uy)
    return ux, uy


@njit(cache=True, inline="always", error_model="numpy")
def predict_routes(
    px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray, mode: np.ndarray,
    pz: np.ndarray, p: Params, steps: int, qx: np.ndarray, qy: np.ndarray, disc2: np.ndarray,
    out: np.ndarray, stack: np.ndarray,
) -> None:
    """Who reaches the BS ``steps`` increments ahead if every node keeps its heading
    (shadow-free range).

    A breadth-first search from the BS that computes a node's links only when it reaches
    the node: the links of nodes cut off from the BS are never needed.
    """
    n = hx.shape[0]
    m = n + 2
    mp = qx.shape[0]
    ahead = p.speed * steps * p.dt
    for j in range(m):
        qx[j], qy[j] = px[j], py[j]
        if j < n and mode[j] != LANDED:
            qx[j] += ahead * hx[j]
            qy[j] += ahead * hy[j]
    out[:] = 0
    add(out, n)
    add(out, n + 1)  # the target relays nothing
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
            top = push_new(stack, top, w, new)
    drop(out, n + 1)


@njit(cache=True, error_model="numpy")
def check_continuously(
    k: int, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray, mode: np.ndarray,
    on_route: np.ndarray, pz: np.ndarray, p: Params, qx: np.ndarray, qy: np.ndarray,
    disc2: np.ndarray, routed_next: np.ndarray, routed_step: np.ndarray, stack: np.ndarray,
    deciding: np.ndarray, last_change: np.ndarray,
) -> bool:
    """ConB's connectivity check read as Section 3.2 words it (``conb_check = continuous``).

    "Within every sensing period the connectivity of a given UAV i to the BS ... is checked at
    incremental time intervals ... If at any time within the sensing period the UAV i would
    lose its connectivity to the BS, direction change would be initiated": every step, the
    graph is predicted at each increment up to ``t + t_s``; ``routed_next`` holds the nodes
    routed at all of them, and a searching distributed drone outside it decides now (its
    clock restarts). Returns whether any drone decides this step.
    """
    predict_routes(px, py, hx, hy, mode, pz, p, 1, qx, qy, disc2, routed_next, stack)
    for s in range(2, p.ts_steps + 1):
        predict_routes(px, py, hx, hy, mode, pz, p, s, qx, qy, disc2, routed_step, stack)
        for w in range(routed_next.shape[0]):
            routed_next[w] &= routed_step[w]
    any_deciding = False
    for i in range(hx.shape[0]):
        if not deciding[i] and not on_route[i] and mode[i] == SEARCHING and not bit(
                routed_next[i >> 6], i):
            deciding[i] = True
            last_change[i] = k
        any_deciding |= deciding[i]
    return any_deciding


@njit(cache=True, inline="always", error_model="numpy")
def conb_headings(
    deciding: np.ndarray, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
    mode: np.ndarray, adj: np.ndarray, routed_next: np.ndarray, p: Params, vx: np.ndarray,
    vy: np.ndarray,
) -> None:
    """Unit direction of Eq. 9 (Algorithm 1, part 2) of every deciding drone, into ``vx, vy``.

    A drone keeps its heading if it is predicted to keep its route to the BS (``routed_next``;
    ConCov's term is then zero with ``concov_connected = none``); else it steers towards where
    the neighbour with the longest contact (among those predicted to keep a route to the BS,
    if any, with ``contacts = routed``) would be when the contact ends; a drone without
    neighbours keeps its heading or, with ``isolated = home``, turns to the BS.
    A neighbour's route "without i" is its route in the predicted graph: ``i`` is not in the
    BS's predicted component here, so removing it changes nothing.
    """
    n = hx.shape[0]
    rc2 = p.rc * p.rc
    no_term = p.rule == CONCOV and p.concov_connected == CONNECTED_NONE and p.alpha > 0.0
    for i in range(n):
        if not deciding[i]:
            continue
        vx[i], vy[i] = hx[i], hy[i]
        if bit(routed_next[i >> 6], i):
            if no_term:
                vx[i] = vy[i] = 0.0
            continue
        neighbours = False
        candidates = False
        for j in range(n + 1):
            if bit(adj[i, j >> 6], j):
                neighbours = True
                candidates |= bit(routed_next[j >> 6], j)
        if not neighbours:
            if p.isolated == ISOLATED_HOME:
                vx[i], vy[i] = unit(p.bs_x - px[i], p.bs_y - py[i], hx[i], hy[i])
            continue
        candidates &= p.contacts != ALL_CONTACTS
        vix, viy = p.speed * hx[i], p.speed * hy[i]
        best = -1
        best_rank = -1.0
        best_d2 = np.inf
        best_tau = best_vx = best_vy = 0.0
        for j in range(n + 1):
            if not bit(adj[i, j >> 6], j) or (candidates and not bit(routed_next[j >> 6], j)):
                continue
            vjx = vjy = 0.0  # the BS and landed drones stand still
            if j < n and mode[j] != LANDED:
                vjx, vjy = p.speed * hx[j], p.speed * hy[j]
            relx, rely = px[j] - px[i], py[j] - py[i]
            rvx, rvy = vjx - vix, vjy - viy
            a = rvx * rvx + rvy * rvy
            rel2 = relx * relx + rely * rely
            if a < TINY:  # equal velocities: the contact never ends
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
        ux, uy = unit(cx - nx, cy - ny, hx[i], hy[i])
        rx, ry = hx[i] + ux, hy[i] + uy
        if math.sqrt(rx * rx + ry * ry) >= 1e-9:  # else flying straight away from the contact
            ux, uy = unit(rx, ry, ux, uy)
        vx[i], vy[i] = ux, uy


@njit(cache=True, inline="always", error_model="numpy")
def blend(p: Params, cx: float, cy: float, vx: float, vy: float, hx: float,
          hy: float) -> tuple[float, float]:
    """The team rule's new heading from CovB's unit force ``(cx, cy)`` and ConB's ``(vx, vy)``:
    one of them, or ConCov's ``α R_cov + (1 − α) R_con`` re-scaled to length 1 (Eq. 12).

    At ``α = 1`` (``0``) Eq. 12 is exactly the CovB (ConB) direction and is used as such, so
    those trajectories are identical to the pure rules'. Where the two terms cancel, the drone
    keeps its heading or, with ``concov_fallback = connectivity``, follows ConB's term.
    """
    if p.rule == COVB or (p.rule == CONCOV and p.alpha == 1.0):
        return cx, cy
    if p.rule == CONB or p.alpha == 0.0:
        return vx, vy
    if p.concov_fallback == FALLBACK_CONNECTIVITY:
        hx, hy = vx, vy
    return unit(p.alpha * cx + (1.0 - p.alpha) * vx, p.alpha * cy + (1.0 - p.alpha) * vy,
                hx, hy)


@njit(cache=True, error_model="numpy")
def steer(k: int, p: Params, deciding: np.ndarray, px: np.ndarray, py: np.ndarray,
          hx: np.ndarray, hy: np.ndarray, mode: np.ndarray, on_route: np.ndarray,
          last_change: np.ndarray, near: np.ndarray, flying: np.ndarray, con_x: np.ndarray,
          con_y: np.ndarray, nhx: np.ndarray, nhy: np.ndarray,
          rng: np.random.Generator) -> None:
    """The new heading of every searching distributed drone: the team's rule for those that
    decide this step (ConB's directions precomputed in ``con_x, con_y``), then the boundary
    rule (:func:`sarlink.engine.motion.boundary_turn`), which counts as a direction change.

    One pass over the drones: at N = 22 a step costs about a microsecond, and every extra
    pass shows.
    """
    step = p.speed * p.dt
    covb = uses_covb(p)
    for i in range(hx.shape[0]):
        if on_route[i] or mode[i] != SEARCHING:  # flying a route, home or landed
            continue
        if deciding[i]:
            cx, cy = hx[i], hy[i]
            if covb:
                cx, cy = covb_force(i, px, py, hx, hy, near, flying, p.r)
            nhx[i], nhy[i] = blend(p, cx, cy, con_x[i], con_y[i], hx[i], hy[i])
        nhx[i], nhy[i], turned = boundary_turn(px[i], py[i], nhx[i], nhy[i], step, p.size, rng)
        if turned:
            last_change[i] = k
