"""The built-in relay strategy (``team.relay_strategy = "tree"``): the relays hold the tree of
:func:`sarlink.engine.relays.placement.plan` over the BS and the searchers where the BS
believes them to be, re-planned every ``t_s`` (docs/model.md, Relays).

The BS hears a drone at every step at which the drone has a route to it, and then knows its
position, heading and route. Where it believes a drone it has not heard since is
``team.relay_estimate``:

- ``reckoned``: dead reckoning from the last hearing, by what the drone was doing then: along
  its route at ``V_m`` for a drone that flew one, straight home for one that flew home, where
  it was heard for a drone of the chain to a found target (it holds its point,
  ``on_detect = relay``), else on along its last heading at ``V_m`` (into the area): what
  the BS can know without hearing it (a drone that has since found the target and turned
  home is still reckoned on its way);
- ``heard``: where it was last heard. Such a point had a route to the BS, so the tree rarely
  needs a relay to reach it, and the relays hardly leave the BS (docs/model.md, Relays).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.codes import Estimate
from sarlink.engine.graph import has
from sarlink.engine.observation import Observation
from sarlink.engine.params import CHAINING, LANDED, RELAYING, REPORTING, RETURNING, Params
from sarlink.engine.relays.placement import dist, into_area, plan

HEARD = int(Estimate.HEARD)


@njit(cache=True, error_model="numpy")
def prepare(p: Params, obs: Observation) -> np.ndarray:
    """What the BS last heard of each drone, ``(8, N)``: x, y, heading x and y, the step, the
    index of its next waypoint, its mode and whether it flew its route; at take-off to start
    with."""
    n = obs.hx.shape[0]
    heard = np.zeros((8, n))
    _hear(0, obs, heard, n)
    return heard


@njit(cache=True, inline="always", error_model="numpy")
def _hear(k: int, obs: Observation, heard: np.ndarray, n: int) -> None:
    for i in range(n):
        if k == 0 or has(obs.routed, i):
            heard[0, i], heard[1, i] = obs.px[i], obs.py[i]
            heard[2, i], heard[3, i] = obs.hx[i], obs.hy[i]
            heard[4, i], heard[5, i] = k, obs.wp_next[i]
            heard[6, i], heard[7, i] = obs.mode[i], obs.on_route[i]


@njit(cache=True, error_model="numpy")
def reckon(k: int, p: Params, obs: Observation, heard: np.ndarray, i: int, edges: np.ndarray
           ) -> tuple[float, float]:
    """Where the BS believes drone ``i`` at step ``k`` by dead reckoning from what it heard
    (module docstring); ``edges``: the area
    (:func:`~sarlink.engine.relays.placement.into_area`)."""
    x, y = heard[0, i], heard[1, i]
    travel = p.speed * p.dt * (k - heard[4, i])
    mode = int(heard[6, i])
    if travel <= 0.0 or mode == CHAINING:  # a drone of the chain to a found target holds
        return x, y
    if heard[7, i] != 0.0 and mode != REPORTING:
        w = int(heard[5, i])
        while w < obs.wp_end[i]:
            wx, wy = obs.wp[w, 0], obs.wp[w, 1]
            d = dist(x, y, wx, wy)
            if d > travel:
                return x + travel * (wx - x) / d, y + travel * (wy - y) / d
            x, y, travel = wx, wy, travel - d
            w += 1
        return x, y
    if mode in (RETURNING, REPORTING):
        d = dist(x, y, p.bs_x, p.bs_y)
        if d <= travel:
            return p.bs_x, p.bs_y
        return x + travel * (p.bs_x - x) / d, y + travel * (p.bs_y - y) / d
    return into_area(x + travel * heard[2, i], y + travel * heard[3, i], p.size, edges)


@njit(cache=True, error_model="numpy")
def place(k: int, p: Params, obs: Observation, ws: np.ndarray, edges: np.ndarray,
          gx: np.ndarray, gy: np.ndarray) -> None:
    """Hear the drones the BS reaches this step; every ``t_s``, re-plan the points of the
    relays still relaying for the searchers (the team's first ``N - K`` drones) not heard
    landed, at ``obs.rc``. The roles are the BS's own assignment; a relay turned home is
    neither (its budget is due, which the BS knows)."""
    n = gx.shape[0]
    _hear(k, obs, ws, n)
    if k % p.ts_steps != 0:
        return
    searchers = relays = 0
    for i in range(n):
        if obs.mode[i] == RELAYING:
            relays += 1
        elif i < n - p.relays and ws[6, i] != LANDED:
            searchers += 1
    tx, ty = np.empty(searchers + 1), np.empty(searchers + 1)
    tx[0], ty[0] = p.bs_x, p.bs_y
    rx, ry = np.empty(relays), np.empty(relays)
    who = np.empty(relays, dtype=np.int64)
    s = r = 0
    for i in range(n):
        if obs.mode[i] == RELAYING:
            rx[r], ry[r], who[r] = ws[0, i], ws[1, i], i
            r += 1
        elif i < n - p.relays and ws[6, i] != LANDED:
            s += 1
            if p.relay_estimate == HEARD:
                tx[s], ty[s] = ws[0, i], ws[1, i]
            else:
                tx[s], ty[s] = reckon(k, p, obs, ws, i, edges)
    px, py, _, _, _ = plan(tx, ty, 0, obs.rc, rx, ry, p.relay_priority, p.size, edges)
    for j in range(relays):
        gx[who[j]], gy[who[j]] = px[j], py[j]
