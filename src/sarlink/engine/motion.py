"""How drones move: when they turn home or update their direction, the boundary rule, route
following and the move itself (docs/model.md, Drones)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.geometry import inside, turned, unit
from sarlink.engine.params import (
    CHAINING,
    DETECTOR_ONLY,
    LANDED,
    RELAYING,
    REPORTING,
    RETURNING,
    SEARCHING,
    Params,
)


@njit(cache=True, error_model="numpy")
def farthest_home(p: Params) -> float:
    """The flight home from the area's farthest corner, m (plus 1 m of margin): no drone
    inside the area is farther, so the return-home test cannot fire before it is due."""
    home_max = 1.0
    for cx in (0.0, p.size):
        for cy in (0.0, p.size):
            home_max = max(home_max, 1.0 + math.sqrt((p.bs_x - cx) ** 2 + (p.bs_y - cy) ** 2))
    return home_max


@njit(cache=True, inline="always", error_model="numpy")
def home_due(p: Params, t: float, x: float, y: float) -> tuple[bool, float, float]:
    """Whether a drone at ``(x, y)`` must turn home at time ``t`` (its remaining budget minus
    the straight flight home is under two steps), and the vector to the BS."""
    hdx, hdy = p.bs_x - x, p.bs_y - y
    home = math.sqrt(hdx * hdx + hdy * hdy)
    return (p.flight_time - t) - home / p.speed < 2.0 * p.dt, hdx, hdy


@njit(cache=True, error_model="numpy")
def report(k: int, p: Params, notified: bool, detector: int, knows: np.ndarray,
           mode: np.ndarray, on_route: np.ndarray, px: np.ndarray, py: np.ndarray,
           leave_x: np.ndarray, leave_y: np.ndarray, rejoin: np.ndarray,
           last_change: np.ndarray) -> None:
    """``on_detect = report``: who starts and who stops flying to tell the BS at step ``k``.

    While the BS has not been notified, a searching drone that knows the target's location
    (every knower, or only the first detector) starts reporting; a route drone remembers
    where it left its tour. Once the BS is notified every reporting drone resumes: a
    distributed drone decides under its rule at once, a route drone flies back to where it
    left its tour (:func:`move`).
    """
    for i in range(knows.shape[0]):
        if notified:
            if mode[i] == REPORTING:
                mode[i] = SEARCHING
                if not on_route[i]:
                    last_change[i] = k - p.ts_steps  # due for a direction update now
        elif (mode[i] == SEARCHING and knows[i]
              and (p.reporters != DETECTOR_ONLY or i == detector)):
            mode[i] = REPORTING
            if on_route[i]:
                leave_x[i], leave_y[i] = px[i], py[i]
                rejoin[i] = True


@njit(cache=True, error_model="numpy")
def schedule(k: int, homing: bool, p: Params, px: np.ndarray, py: np.ndarray, hx: np.ndarray,
             hy: np.ndarray, mode: np.ndarray, on_route: np.ndarray, last_change: np.ndarray,
             deciding: np.ndarray, nhx: np.ndarray, nhy: np.ndarray) -> bool:
    """Which distributed drones turn home and which update their direction at step ``k``.

    A drone turns home at the first step at which its remaining budget minus the straight
    flight home is under two steps (``homing``: that step may have come for some drone). A
    drone updates its direction every ``t_s`` since its last change. A reporting drone heads
    for the BS, and a distributed one whose budget is due simply goes home. ``nhx, nhy``
    start as the current headings; returns whether any drone decides.
    """
    any_deciding = False
    t = k * p.dt
    for i in range(hx.shape[0]):
        nhx[i], nhy[i] = hx[i], hy[i]
        deciding[i] = False
        if mode[i] == REPORTING:
            due, hdx, hdy = home_due(p, t, px[i], py[i])
            if due and homing and not on_route[i]:
                mode[i] = RETURNING
            nhx[i], nhy[i] = unit(hdx, hdy, hx[i], hy[i])
            continue
        if on_route[i] or mode[i] != SEARCHING:
            continue
        if homing:
            due, hdx, hdy = home_due(p, t, px[i], py[i])
            if due:
                mode[i] = RETURNING
                nhx[i], nhy[i] = unit(hdx, hdy, hx[i], hy[i])
                continue
        if k - last_change[i] >= p.ts_steps:
            last_change[i] = k
            deciding[i] = any_deciding = True
    return any_deciding


@njit(cache=True, error_model="numpy")
def turn_errors(p: Params, deciding: np.ndarray, hx: np.ndarray, hy: np.ndarray,
                nhx: np.ndarray, nhy: np.ndarray, rng: np.random.Generator) -> None:
    """Fly every commanded change of heading off by a uniform error of at most
    ``p.turn_error`` (``readings.turns = jitter``): a drone's compass and heading control hold
    a heading to a few degrees, not to the last bit. Only a drone that decides and is told a
    new heading (by more than :data:`~sarlink.engine.geometry.TURNED`, so that rounding in a
    rule's sums is no turn) draws, in drone order; a kept heading is flown as it was."""
    for i in range(nhx.shape[0]):
        if deciding[i] and turned(hx[i], hy[i], nhx[i], nhy[i]):
            e = p.turn_error * (2.0 * rng.random() - 1.0)
            c, s = math.cos(e), math.sin(e)
            nhx[i], nhy[i] = c * nhx[i] - s * nhy[i], s * nhx[i] + c * nhy[i]


@njit(cache=True, inline="always", error_model="numpy")
def boundary_turn(
    x: float, y: float, hx: float, hy: float, step: float, size: float, rng: np.random.Generator
) -> tuple[float, float, bool]:
    """Keep the heading if the next increment stays inside; else a random inward heading.

    The inward headings are the half circle facing away from each wall the increment would
    cross (a quarter circle at a corner). A redraw that crosses another wall adds that wall.
    """
    nx, ny = x + step * hx, y + step * hy
    if inside(nx, ny, size):
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
        if inside(nx, ny, size):
            return hx, hy, True


@njit(cache=True, error_model="numpy")
def boundary(k: int, p: Params, px: np.ndarray, py: np.ndarray, mode: np.ndarray,
             on_route: np.ndarray, last_change: np.ndarray, nhx: np.ndarray, nhy: np.ndarray,
             rng: np.random.Generator) -> None:
    """The boundary rule for every searching distributed drone after the rule has decided
    (:func:`boundary_turn`); a turn counts as a direction change. One pass, in drone order,
    so the random draws do not depend on the rule."""
    step = p.speed * p.dt
    for i in range(nhx.shape[0]):
        if on_route[i] or mode[i] != SEARCHING:  # flying a route, home or landed
            continue
        nhx[i], nhy[i], turned = boundary_turn(px[i], py[i], nhx[i], nhy[i], step, p.size, rng)
        if turned:
            last_change[i] = k


@njit(cache=True, inline="always", error_model="numpy")
def fly_route(
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
        hx[i], hy[i] = unit(nx, ny, hx[i], hy[i])
        if travel <= 0.0:
            return


@njit(cache=True, error_model="numpy")
def move(p: Params, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
         mode: np.ndarray, on_route: np.ndarray, wp: np.ndarray, wp_next: np.ndarray,
         wp_end: np.ndarray, leave_x: np.ndarray, leave_y: np.ndarray,
         rejoin: np.ndarray, aim_x: np.ndarray, aim_y: np.ndarray) -> None:
    """Move every drone ``V dt``: along its route (back to where it left it first, after
    reporting), home (landing on arrival), to the BS to report (waiting there), a relay or a
    drone of the chain to a found target to its aim (holding it on arrival), or on.

    Inlined: it draws no random numbers, and as a call (a dozen arrays, some 100 arguments)
    it cost some 5 % of a CovB run at N = 10.
    """
    step = p.speed * p.dt
    for i in range(hx.shape[0]):
        if mode[i] == LANDED:
            continue
        if mode[i] == REPORTING:
            dx, dy = p.bs_x - px[i], p.bs_y - py[i]
            if dx * dx + dy * dy <= step * step:
                px[i], py[i] = p.bs_x, p.bs_y
            else:
                px[i] += step * hx[i]
                py[i] += step * hy[i]
        elif on_route[i]:
            travel = step
            if rejoin[i]:
                dx, dy = leave_x[i] - px[i], leave_y[i] - py[i]
                d = math.sqrt(dx * dx + dy * dy)
                if d > travel:
                    px[i] += travel * dx / d
                    py[i] += travel * dy / d
                    hx[i], hy[i] = dx / d, dy / d
                    continue
                px[i], py[i] = leave_x[i], leave_y[i]
                rejoin[i] = False
                travel -= d
            if travel > 0.0:
                fly_route(i, px, py, hx, hy, mode, wp, wp_next, wp_end, travel)
        elif mode[i] == RETURNING:
            dx, dy = p.bs_x - px[i], p.bs_y - py[i]
            if dx * dx + dy * dy <= step * step:
                px[i], py[i] = p.bs_x, p.bs_y
                mode[i] = LANDED
            else:
                px[i] += step * hx[i]
                py[i] += step * hy[i]
        elif mode[i] == RELAYING or mode[i] == CHAINING:
            dx, dy = aim_x[i] - px[i], aim_y[i] - py[i]
            if dx * dx + dy * dy <= step * step:
                px[i], py[i] = aim_x[i], aim_y[i]
            else:
                px[i] += step * hx[i]
                py[i] += step * hy[i]
        else:
            px[i] += step * hx[i]
            py[i] += step * hy[i]
