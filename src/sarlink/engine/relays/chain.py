"""Search, then relay (``on_detect = relay``; docs/model.md, Search, then relay): once a drone
has found the target it holds where it found it, and the drones that know of the find form a
chain of links from the BS to it (the scheme of "Search and rescue with sparsely connected
swarms", Autonomous Robots 2022).

The chain is the relay placement's tree over two terminals, the BS and the detection point
(:func:`sarlink.engine.relays.placement.tree`): ``ceil(L / r_c) - 1`` points evenly spaced on
the segment of length ``L``, each moved into the area. The news of the find carries the
detection point, so every drone that knows has the same points. Each step, the drones one
knower can hear (its component of the links) share out the points no drone among them holds,
by the placement's bottleneck assignment (:func:`sarlink.engine.relays.placement.assign`);
a drone that holds a point keeps it, so that no searcher passing closer takes it over. With
fewer drones than open points they take those nearest the BS: the chain grows from the BS
out, its first drone tells the BS much as a reporting drone would (it flies towards the BS
until linked), and every drone that comes within range of the part held learns and extends
it. A drone given a point stays in the chain until its budget turns it home (if two hold one
point when their components meet, the farther holds where it is until a point opens); a
knower given none keeps searching, as it would without the chain. Nothing is random.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.graph import add, component, has
from sarlink.engine.params import CHAINING, RELAYING, SEARCHING, Params
from sarlink.engine.relays.flight import fly
from sarlink.engine.relays.placement import assign, dist, points, tree


@njit(cache=True, error_model="numpy")
def start(p: Params, rc: float, detector: int, mode: np.ndarray, on_route: np.ndarray,
          px: np.ndarray, py: np.ndarray, aim_x: np.ndarray, aim_y: np.ndarray,
          edges: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """At the first detection: the detector, if it searches or relays (not on its way home
    or parked), holds where it is (leaving its route for good); returns the chain's points
    at range ``rc`` from the BS end to the detector's."""
    dx, dy = px[detector], py[detector]
    if mode[detector] == SEARCHING or mode[detector] == RELAYING:
        mode[detector] = CHAINING
        on_route[detector] = False
        aim_x[detector], aim_y[detector] = dx, dy
    x, y, parent, order, _, need = tree(np.array([p.bs_x, dx]), np.array([p.bs_y, dy]), 0, rc,
                                        False)
    cx, cy, _ = points(x, y, parent, order, need, p.size, edges, 2)
    return cx, cy


@njit(cache=True, inline="always", error_model="numpy")
def free(i: int, detector: int, knows: np.ndarray, mode: np.ndarray) -> bool:
    """Whether drone ``i`` may take a point of the chain: it knows of the find and searches,
    relays or already holds a point (not the detector, which holds the target; not a drone
    flying home or parked)."""
    return knows[i] and i != detector and (
        mode[i] == SEARCHING or mode[i] == RELAYING or mode[i] == CHAINING)


@njit(cache=True, error_model="numpy")
def join(detector: int, knows: np.ndarray, mode: np.ndarray, on_route: np.ndarray,
         px: np.ndarray, py: np.ndarray, adj: np.ndarray, cx: np.ndarray, cy: np.ndarray,
         slot: np.ndarray, aim_x: np.ndarray, aim_y: np.ndarray, heard: np.ndarray,
         stack: np.ndarray) -> None:
    """One step's share-out of the chain's points ``(cx, cy)`` (module docstring), in each
    component of the links ``adj`` (never through the target) that has a free drone
    (:func:`free`). A chain drone keeps its point (``slot``, -1: none) unless another chain
    drone of the component holds the same one nearer (ties: the lower index). The free drones
    without a point (searchers, and chain drones without one) take the points nobody in the
    component holds, those nearest the BS, as many as there are of them, by the bottleneck
    assignment from where they are: a drone given one flies to it as a chain drone; a chain
    drone given none holds where it is, a searcher given none flies on. ``heard`` is a bitset
    workspace, ``stack`` the search's."""
    n = knows.shape[0]
    total = cx.shape[0]
    seen = np.zeros(n, dtype=np.bool_)
    holder = np.empty(total, dtype=np.int64)
    waiting = np.empty(n, dtype=np.int64)
    for i in range(n):
        if seen[i] or not free(i, detector, knows, mode):
            continue
        heard[:] = 0
        add(heard, i)
        component(adj, n + 1, heard, stack)
        holder[:] = -1
        w = 0
        for j in range(i, n):
            if not (has(heard, j) and free(j, detector, knows, mode)):
                continue
            seen[j] = True
            b = slot[j]
            if mode[j] != CHAINING or b < 0:
                waiting[w] = j
                w += 1
            elif holder[b] < 0:
                holder[b] = j
            else:  # two hold one point: the nearer keeps it
                h = holder[b]
                if dist(px[j], py[j], cx[b], cy[b]) < dist(px[h], py[h], cx[b], cy[b]):
                    holder[b], h = j, h
                else:
                    h = j
                slot[h] = -1
                waiting[w] = h
                w += 1
        open_ = np.flatnonzero(holder < 0)[:w]
        goal, _ = assign(px[waiting[:w]], py[waiting[:w]], cx[open_], cy[open_])
        for a in range(w):
            j = waiting[a]
            if goal[a] >= 0:
                b = open_[goal[a]]
                mode[j] = CHAINING
                on_route[j] = False
                slot[j] = b
                aim_x[j], aim_y[j] = cx[b], cy[b]
            elif mode[j] == CHAINING:
                aim_x[j], aim_y[j] = px[j], py[j]


@njit(cache=True, error_model="numpy")
def steer(k: int, homing: bool, p: Params, px: np.ndarray, py: np.ndarray, hx: np.ndarray,
          hy: np.ndarray, mode: np.ndarray, aim_x: np.ndarray, aim_y: np.ndarray,
          nhx: np.ndarray, nhy: np.ndarray, edges: np.ndarray, nav: np.ndarray) -> None:
    """Every chain drone (the detector too) flies to its point and holds it, as a relay does
    (:func:`sarlink.engine.relays.flight.fly`: its budget still turns it home)."""
    for i in range(mode.shape[0]):
        if mode[i] == CHAINING:
            fly(i, k, homing, p, px, py, hx, hy, mode, aim_x, aim_y, nhx, nhy, edges, nav)
