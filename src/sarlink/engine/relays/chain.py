"""Search, then relay (``on_detect = relay``; docs/model.md, Search, then relay): once a drone
has found the target it holds where it found it, and the drones that know of the find form a
chain of links from the BS to it (the scheme of "Search and rescue with sparsely connected
swarms", Autonomous Robots 2022).

The chain is the relay placement's tree over two terminals, the BS and the detection point
(:func:`sarlink.engine.relays.placement.tree`): ``ceil(L / r_c) - 1`` points evenly spaced on
the segment of length ``L``, each moved into the area. The news of the find carries the
detection point, so every drone that knows has the same points. Each step, the drones one
knower can hear (its component of the links) share out the points by the placement's
bottleneck assignment (:func:`sarlink.engine.relays.placement.assign`). With fewer of them
than points they take those nearest the BS: the chain grows from the BS out, its first drone
tells the BS much as a reporting drone would (it flies towards the BS until linked), and every
drone that comes within range of the part held learns and extends it (the drones shift out
by a point each, the bottleneck assignment's choice). A drone given a point stays in the
chain until its budget turns it home (given none later, when another component's drones
have joined its own, it holds where it is); a knower given none keeps searching, as it
would without the chain. Nothing is random.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.graph import add, component, has
from sarlink.engine.params import CHAINING, RELAYING, SEARCHING, Params
from sarlink.engine.relays.flight import fly
from sarlink.engine.relays.placement import assign, points, tree


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
         aim_x: np.ndarray, aim_y: np.ndarray, heard: np.ndarray, stack: np.ndarray) -> None:
    """One step's share-out of the chain's points ``(cx, cy)`` (module docstring): in each
    component of the links ``adj`` (never through the target), the free drones (:func:`free`)
    take the points nearest the BS, as many as there are of them, by the bottleneck
    assignment from where they are; a drone given a point flies to it (``aim``) as a chain
    drone, a chain drone given none holds where it is, a knower given none flies on.
    ``heard`` is a bitset workspace, ``stack`` the search's."""
    n = knows.shape[0]
    total = cx.shape[0]
    seen = np.zeros(n, dtype=np.bool_)
    who = np.empty(n, dtype=np.int64)
    for i in range(n):
        if seen[i] or not free(i, detector, knows, mode):
            continue
        heard[:] = 0
        add(heard, i)
        component(adj, n + 1, heard, stack)
        m = 0
        for j in range(i, n):
            if has(heard, j) and free(j, detector, knows, mode):
                seen[j] = True
                who[m] = j
                m += 1
        q = min(m, total)
        goal, _ = assign(px[who[:m]], py[who[:m]], cx[:q], cy[:q])
        for s in range(m):
            j = who[s]
            if goal[s] >= 0:
                mode[j] = CHAINING
                on_route[j] = False
                aim_x[j], aim_y[j] = cx[goal[s]], cy[goal[s]]
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
