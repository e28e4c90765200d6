"""ConB: the distributed rule that keeps drones attached to the BS (Section 3.2, Eqs. 9-11),
shaped like a plug-in: its hooks, its rule and its planner, registered by
:func:`sarlink.register_planner`.

A drone predicts the graph a sensing period ahead (every node keeping its heading, links at the
radio's nominal range: a drone cannot foresee fading) and, if it would lose its route to the
BS, steers towards where its longest-contact neighbour will be when the contact ends. With
``conb_check = continuous`` the prediction runs every step for every increment up to
``t + t_s`` (:func:`check_continuously`, the rule's ``due`` hook). Directions are computed for
all deciding drones in one pass: Numba counts the references of every array handed to a
helper called per drone (docs/architecture.md).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from sarlink.engine.geometry import FAR, TINY, d2, unit
from sarlink.engine.graph import add, bit, covers, drop, first_nodes, lowest
from sarlink.engine.hooks import DistributedRule
from sarlink.engine.observation import Observation
from sarlink.engine.params import (
    ALL_CONTACTS,
    CONB_KEEP_HEADING,
    CONB_LIMIT,
    CONTINUOUS,
    ISOLATED_HOME,
    LANDED,
    PREDICT_PATHS,
    SEARCHING,
    Params,
)
from sarlink.planners.base import RulePlanner
from sarlink.planners.registry import register_planner

_ONE = np.uint64(1)
_ZERO = np.uint64(0)


class Workspace(NamedTuple):
    """ConB's arrays, allocated once per run."""

    qx: np.ndarray  # predicted positions (padded like the kernel's)
    qy: np.ndarray
    disc2: np.ndarray  # squared nominal link ranges, none to the padding
    routed_next: np.ndarray  # predicted to keep a route to the BS
    routed_step: np.ndarray  # the same at one increment, or the goal of a search
    expanded: np.ndarray  # the nodes a search has expanded


@njit(cache=True, inline="always", error_model="numpy")
def workspace(obs: Observation) -> Workspace:
    """ConB's arrays for the run observed through ``obs``."""
    m, mp = obs.adj.shape[0], obs.px.shape[0]
    nw = obs.adj.shape[1]
    disc2 = np.zeros((m, mp))
    disc2[:, :m] = obs.rc * obs.rc
    return Workspace(np.full(mp, FAR), np.full(mp, FAR), disc2, np.zeros(nw, dtype=np.uint64),
                     np.zeros(nw, dtype=np.uint64), np.zeros(nw, dtype=np.uint64))


@njit(cache=True, inline="always", error_model="numpy")
def along_route(j: int, px: np.ndarray, py: np.ndarray, wp: np.ndarray, wp_next: np.ndarray,
                wp_end: np.ndarray, ahead: float) -> tuple[float, float]:
    """Where route drone ``j`` will be ``ahead`` metres on along its waypoints (at its last
    one, the BS, if the route ends before): what :func:`sarlink.engine.motion.fly_route`
    flies, step by step."""
    x, y = px[j], py[j]
    for k in range(wp_next[j], wp_end[j]):
        dx, dy = wp[k, 0] - x, wp[k, 1] - y
        d = math.sqrt(dx * dx + dy * dy)
        if d > ahead:
            return x + ahead * dx / d, y + ahead * dy / d
        x, y = wp[k, 0], wp[k, 1]
        ahead -= d
    return x, y


@njit(cache=True, inline="always", error_model="numpy")
def predict_routes(
    px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray, mode: np.ndarray,
    pz: np.ndarray, p: Params, steps: int, qx: np.ndarray, qy: np.ndarray, disc2: np.ndarray,
    out: np.ndarray, expanded: np.ndarray, on_route: np.ndarray, wp: np.ndarray,
    wp_next: np.ndarray, wp_end: np.ndarray, goal: np.ndarray,
) -> int:
    """Who reaches the BS ``steps`` increments ahead if every node keeps its heading
    (shadow-free range); with ``mtsp_prediction = paths`` a searching drone on a route
    (``on_route``, waypoints ``wp[wp_next[j]:wp_end[j]]``) flies on along it instead.

    A search from the BS that computes a node's links only when it expands the node (the
    links of nodes cut off from the BS are never needed) and stops once it has reached every
    node of the bitset ``goal``: ``out & goal`` is then exact, and ``out`` is exact when
    ``goal`` holds every node. A ConB team mostly flies within range of the BS, whose links
    alone then reach everyone: one node's links instead of every node's. The nodes still to
    expand are ``out & ~expanded``, a bitset rather than a stack, so that the nodes reached
    by the last expansion cost nothing when the search stops there. Returns the number of
    nodes expanded: the search's work, counted for Fig. 1.
    """
    n = hx.shape[0]
    m = n + 2
    mp = qx.shape[0]
    ahead = p.speed * steps * p.dt
    for j in range(n):  # every heading, in a loop without branches (it vectorizes)
        move = 0.0 if mode[j] == LANDED else ahead  # a landed drone's 0 * h adds a zero
        qx[j] = px[j] + move * hx[j]
        qy[j] = py[j] + move * hy[j]
    for j in range(n, m):  # the BS and the target
        qx[j], qy[j] = px[j], py[j]
    for j in range(n if p.mtsp_prediction == PREDICT_PATHS else 0):  # a loop, not a branch
        if on_route[j] and mode[j] == SEARCHING:
            qx[j], qy[j] = along_route(j, px, py, wp, wp_next, wp_end, ahead)
    nw = out.shape[0]
    for w in range(nw):
        out[w] = expanded[w] = _ZERO
    add(out, n)
    add(out, n + 1)
    add(expanded, n + 1)  # the target relays nothing
    w = 0
    expansions = 0
    while w < nw and not covers(out, goal):
        pending = out[w] & ~expanded[w]
        if not pending:
            w += 1
            continue
        a = w * 64 + lowest(pending)
        add(expanded, a)
        expansions += 1
        xa, ya, za = qx[a], qy[a], pz[a]
        disc2_a = disc2[a]
        for v in range(nw):
            lo = v * 64
            row = np.uint64(0)
            for b in range(lo, min(mp, lo + 64)):
                u = np.uint64(b)  # unsigned: the loop vectorizes (graph.links)
                row |= (_ONE if d2(xa, ya, za, qx[u], qy[u], pz[u]) <= disc2_a[u]
                        else _ZERO) << np.uint64(b - lo)
            out[v] |= row
        w = 0  # the new nodes may lie in any word
    drop(out, n + 1)
    return expansions


@njit(cache=True, inline="always", error_model="numpy")
def check_continuously(k: int, p: Params, obs: Observation, ws: Workspace, deciding: np.ndarray,
                       on: bool) -> bool:
    """ConB's connectivity check read as Section 3.2 words it (``conb_check = continuous``),
    when ``on``; returns whether any drone decides this step.

    "Within every sensing period the connectivity of a given UAV i to the BS ... is checked at
    incremental time intervals ... If at any time within the sensing period the UAV i would
    lose its connectivity to the BS, direction change would be initiated": every step, the
    graph is predicted at each increment up to ``t + t_s``; ``ws.routed_next`` holds the nodes
    routed at all of them, and a searching distributed drone outside it decides now (its
    clock restarts). Off, there are no increments: every node counts as routed and no drone
    is added.

    The increments are searched from the last to the first, and a search only has to reach
    the nodes routed at every increment searched before it (the goal of
    :func:`predict_routes`; at the last, every node): the others are out of ``routed_next``
    already. The result is the same intersection in any order; the last increment, the
    farthest ahead, loses the most nodes, so searched first it narrows the others' goal.

    Written for Numba's reference-count pruner (docs/architecture.md): no plain call, and
    the check's off state is a loop of no increments rather than a branch, as the pruner
    keeps the counts of an array whose last use lies in one arm of a branch.
    """
    n = obs.hx.shape[0]
    first_nodes(ws.routed_next, n + 2)  # before the first search: every node
    for s in range(p.ts_steps if on else 0, 0, -1):
        obs.work[0] += predict_routes(obs.px, obs.py, obs.hx, obs.hy, obs.mode, obs.pz, p, s,
                                      ws.qx, ws.qy, ws.disc2, ws.routed_step, ws.expanded,
                                      obs.on_route, obs.wp, obs.wp_next, obs.wp_end,
                                      ws.routed_next)
        for w in range(ws.routed_next.shape[0]):
            ws.routed_next[w] &= ws.routed_step[w]
    any_deciding = False
    for i in range(n):
        if not deciding[i] and not obs.on_route[i] and obs.mode[i] == SEARCHING and not bit(
                ws.routed_next[i >> 6], i):
            deciding[i] = True
            obs.last_change[i] = k
        any_deciding |= deciding[i]
    return any_deciding


@njit(cache=True, inline="always", error_model="numpy")
def conb_headings(
    deciding: np.ndarray, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
    mode: np.ndarray, adj: np.ndarray, routed_next: np.ndarray, p: Params, rc: float,
    no_term: bool, vx: np.ndarray, vy: np.ndarray, rng: np.random.Generator,
) -> None:
    """Unit direction of Eq. 9 (Algorithm 1, part 2) of every deciding drone, into ``vx, vy``.

    A drone keeps its heading if it is predicted to keep its route to the BS (``routed_next``;
    the term is zero instead with ``no_term``: ConCov's ``concov_connected = none``); else it
    steers towards where the neighbour with the longest contact (among those predicted to keep
    a route to the BS, if any, with ``contacts = routed``) would be when the contact ends (if
    the two unit terms cancel, it turns to that point, or with ``conb_fallback = heading``
    keeps its heading, or with ``limit`` turns a right angle to a side drawn from ``rng``);
    a drone without neighbours keeps its heading or, with ``isolated = home``, turns to the
    BS.

    The limit: for a heading ``α`` off the direction away from the contact, Eq. 9's resultant
    ``θ_i + θ_ij`` has length ``2|sin(α/2)|`` and points ``90° - α/2`` from the heading, to
    the side of ``α``; as ``α`` vanishes it is a right angle, to the side the drone's error
    would have chosen, which nothing in the equations fixes: a fair draw.
    A neighbour's route "without i" is its route in the predicted graph: ``i`` is not in the
    BS's predicted component here, so removing it changes nothing.
    """
    n = hx.shape[0]
    rc2 = rc * rc
    nw = adj.shape[1]
    tw = (n + 1) >> 6  # the word of the target's bit
    nodes = (_ONE << np.uint64((n + 1) & 63)) - _ONE  # its bits below the target's
    for i in range(n):
        if not deciding[i]:
            continue
        vx[i], vy[i] = hx[i], hy[i]
        if bit(routed_next[i >> 6], i):
            if no_term:
                vx[i] = vy[i] = 0.0
            continue
        neighbours = candidates = False
        for w in range(nw):  # the drones and the BS (not the target) linked to i
            linked = adj[i, w] & (~_ZERO if w < tw else nodes)
            neighbours |= linked != _ZERO
            candidates |= linked & routed_next[w] != _ZERO
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
        for w in range(nw):  # in increasing order of j
            linked = adj[i, w] & (~_ZERO if w < tw else nodes)
            if candidates:
                linked &= routed_next[w]
            while linked:
                j = w * 64 + lowest(linked)
                linked &= linked - _ONE
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
        if math.sqrt(rx * rx + ry * ry) >= 1e-9:
            ux, uy = unit(rx, ry, ux, uy)
        elif p.conb_fallback == CONB_KEEP_HEADING:  # flying straight away from the contact
            ux, uy = hx[i], hy[i]
        elif p.conb_fallback == CONB_LIMIT:
            side = 1.0 if rng.random() < 0.5 else -1.0
            ux, uy = -side * hy[i], side * hx[i]
        vx[i], vy[i] = ux, uy




@njit(cache=True, inline="always", error_model="numpy")
def prepare(p: Params, obs: Observation) -> Workspace:
    """The workspace of a ConB team."""
    return workspace(obs)


@njit(cache=True, inline="always", error_model="numpy")
def due(k: int, p: Params, obs: Observation, ws: Workspace, deciding: np.ndarray) -> bool:
    """With ``conb_check = continuous``, the drones that decide now because a loss of their
    route is predicted within the sensing period; returns whether any drone decides."""
    return check_continuously(k, p, obs, ws, deciding, p.conb_check == CONTINUOUS)


@njit(cache=True, inline="always", error_model="numpy")
def directions(p: Params, obs: Observation, ws: Workspace, deciding: np.ndarray, no_term: bool,
               vx: np.ndarray, vy: np.ndarray) -> None:
    """Eq. 9's direction of every deciding drone, predicting the routes a sensing period ahead
    unless the continuous check already did."""
    if p.conb_check != CONTINUOUS:
        first_nodes(ws.routed_step, obs.hx.shape[0] + 2)  # the goal: every node
        obs.work[0] += predict_routes(obs.px, obs.py, obs.hx, obs.hy, obs.mode, obs.pz, p,
                                      p.ts_steps, ws.qx, ws.qy, ws.disc2, ws.routed_next,
                                      ws.expanded, obs.on_route, obs.wp, obs.wp_next,
                                      obs.wp_end, ws.routed_step)
    conb_headings(deciding, obs.px, obs.py, obs.hx, obs.hy, obs.mode, obs.adj, ws.routed_next,
                  p, obs.rc, no_term, vx, vy, obs.rng)


@njit(cache=True, inline="always", error_model="numpy")
def decide(k: int, p: Params, obs: Observation, ws: Workspace, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    """ConB's direction for every deciding drone."""
    directions(p, obs, ws, deciding, False, vx, vy)


CONB = DistributedRule("conb", decide, prepare=prepare, due=due,
                       readings=("conb_check", "contacts", "isolated", "conb_fallback", "takeoff"),
                       ignores_reporting=True)
"""ConB's attachment to the BS (Eqs. 9-11); mTSP-ConB runs it too
(:mod:`sarlink.planners.paper`)."""

PLANNER = register_planner(RulePlanner("conb", "ConB", CONB, colour="#2ca02c", marker="^"))
