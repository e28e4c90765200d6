"""The relays in the kernel: who they are, which points reach them, and how they fly there
(docs/model.md, Relays). The strategy proposes points
(:class:`~sarlink.engine.hooks.RelayStrategy`); this module is what a drone can do with them,
whatever the strategy."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.area import home_heading, way_to
from sarlink.engine.geometry import unit
from sarlink.engine.graph import has
from sarlink.engine.motion import home_due
from sarlink.engine.params import RELAYING, RETURNING, Params
from sarlink.engine.relays.placement import into_area


@njit(cache=True, error_model="numpy")
def start(p: Params, mode: np.ndarray) -> None:
    """The team's last ``p.relays`` drones take off as relays."""
    n = mode.shape[0]
    for i in range(n - p.relays, n):
        mode[i] = RELAYING


@njit(cache=True, error_model="numpy")
def steer(k: int, homing: bool, p: Params, px: np.ndarray, py: np.ndarray, hx: np.ndarray,
          hy: np.ndarray, mode: np.ndarray, routed: np.ndarray, gx: np.ndarray,
          gy: np.ndarray, aim_x: np.ndarray, aim_y: np.ndarray, nhx: np.ndarray,
          nhy: np.ndarray, edges: np.ndarray, nav: np.ndarray) -> None:
    """Every relay at step ``k``: a relay the BS reaches takes the strategy's point ``(gx,
    gy)`` (moved into the area; a point that is not finite is ignored) as its aim; one it
    does not reach aims at the BS until it does again (a relay that kept its aim out of
    contact would be stranded there: the BS could give it no other point); then it flies
    there (:func:`fly`)."""
    for i in range(mode.shape[0]):
        if mode[i] != RELAYING:
            continue
        if not has(routed, i):
            aim_x[i], aim_y[i] = p.bs_x, p.bs_y
        elif math.isfinite(gx[i]) and math.isfinite(gy[i]):
            aim_x[i], aim_y[i] = into_area(gx[i], gy[i], p.size, edges)
        fly(i, k, homing, p, px, py, hx, hy, mode, aim_x, aim_y, nhx, nhy, edges, nav)


@njit(cache=True, inline="always", error_model="numpy")
def fly(i: int, k: int, homing: bool, p: Params, px: np.ndarray, py: np.ndarray,
        hx: np.ndarray, hy: np.ndarray, mode: np.ndarray, aim_x: np.ndarray,
        aim_y: np.ndarray, nhx: np.ndarray, nhy: np.ndarray, edges: np.ndarray,
        nav: np.ndarray) -> None:
    """Drone ``i``, which holds a point (a relay, or a drone of the chain to a found target,
    :mod:`sarlink.engine.relays.chain`), at step ``k``: if its budget is due it turns home (the
    flight home round the holes on a polygon area); else it heads for its aim ``(aim_x[i],
    aim_y[i])``, the shortest way round the holes, and holds it once there
    (:func:`sarlink.engine.motion.move`)."""
    step = p.speed * p.dt
    t = k * p.dt
    polygon = edges.shape[0] > 0
    if homing:
        if polygon:
            ux, uy, home = home_heading(px[i], py[i], p.bs_x, p.bs_y, step, edges, nav,
                                        hx[i], hy[i])
            due = (p.flight_time - t) - home / p.speed < 2.0 * p.dt
        else:
            due, hdx, hdy = home_due(p, t, px[i], py[i])
            ux, uy = unit(hdx, hdy, hx[i], hy[i])
        if due:
            mode[i] = RETURNING
            nhx[i], nhy[i] = ux, uy
            return
    if polygon:
        nhx[i], nhy[i], _ = way_to(px[i], py[i], aim_x[i], aim_y[i], step, edges, nav,
                                   hx[i], hy[i])
    else:
        nhx[i], nhy[i] = unit(aim_x[i] - px[i], aim_y[i] - py[i], hx[i], hy[i])
