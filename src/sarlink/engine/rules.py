"""The distributed planners' rules: CovB's push, ConB's prediction and contact choice, and
ConCov's blend of the two (docs/model.md, Planners).

Each rule writes the direction of every drone that decides this step into arrays, from the
state before anyone turns. The loops over drones are inside these functions, with no
array-taking helper called per drone: Numba counts the references of every array it hands
to an inlined helper, two atomic operations each, which cost a quarter of a ConB run.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.geometry import TINY, unit
from sarlink.engine.graph import add, bit, drop, lowest, push_new
from sarlink.engine.params import CONB, CONCOV, COVB, LANDED, Params

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
def covb_headings(deciding: np.ndarray, px: np.ndarray, py: np.ndarray, hx: np.ndarray,
                  hy: np.ndarray, near: np.ndarray, flying: np.ndarray, r: float,
                  vx: np.ndarray, vy: np.ndarray) -> None:
    """Unit direction of Eq. 6 of every deciding drone, into ``vx, vy``: own heading / r plus
    a 1/d push from each flying drone within r (``near & flying``), added in increasing drone
    order. No neighbour: keep the heading."""
    for i in range(hx.shape[0]):
        if not deciding[i]:
            continue
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
        vx[i], vy[i] = ux, uy


@njit(cache=True, inline="always", error_model="numpy")
def predict_routes(
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


@njit(cache=True, inline="always", error_model="numpy")
def conb_headings(
    deciding: np.ndarray, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
    mode: np.ndarray, adj: np.ndarray, routed_next: np.ndarray, p: Params, vx: np.ndarray,
    vy: np.ndarray,
) -> None:
    """Unit direction of Eq. 9 (Algorithm 1, part 2) of every deciding drone, into ``vx, vy``.

    A drone keeps its heading if it is predicted to reach the BS at ``t + t_s``
    (``routed_next``); else it steers towards where the neighbour with the longest contact
    (among those predicted to keep a route to the BS, if any) would be when the contact ends.
    A neighbour's route "without i" is its route in the predicted graph: ``i`` is not in the
    BS's predicted component here, so removing it changes nothing.
    """
    n = hx.shape[0]
    rc2 = p.rc * p.rc
    for i in range(n):
        if not deciding[i]:
            continue
        vx[i], vy[i] = hx[i], hy[i]
        if bit(routed_next[i >> 6], i):
            continue
        neighbours = False
        candidates = False
        for j in range(n + 1):
            if bit(adj[i, j >> 6], j):
                neighbours = True
                candidates |= bit(routed_next[j >> 6], j)
        if not neighbours:
            continue
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
def blend(deciding: np.ndarray, p: Params, hx: np.ndarray, hy: np.ndarray, cov_x: np.ndarray,
          cov_y: np.ndarray, con_x: np.ndarray, con_y: np.ndarray, nhx: np.ndarray,
          nhy: np.ndarray) -> None:
    """The team rule's new heading of every deciding drone: CovB's, ConB's, or ConCov's blend
    ``α R_cov + (1 − α) R_con`` of the two unit forces (Eq. 12), re-scaled to length 1.

    At ``α = 1`` (``0``) Eq. 12 is exactly the CovB (ConB) direction and is used as such, so
    those trajectories are identical to the pure rules'.
    """
    for i in range(hx.shape[0]):
        if not deciding[i]:
            continue
        if p.rule == COVB or (p.rule == CONCOV and p.alpha == 1.0):
            nhx[i], nhy[i] = cov_x[i], cov_y[i]
        elif p.rule == CONB or p.alpha == 0.0:
            nhx[i], nhy[i] = con_x[i], con_y[i]
        else:
            nhx[i], nhy[i] = unit(p.alpha * cov_x[i] + (1.0 - p.alpha) * con_x[i],
                                  p.alpha * cov_y[i] + (1.0 - p.alpha) * con_y[i],
                                  hx[i], hy[i])
