"""A polygon search area with holes in the kernel: inside tests and the boundary rule.

The area is given to the kernel as its edges, an ``(E, 4)`` array of segments
``(x1, y1, x2, y2)`` over every ring (the outline and each hole); an empty array is the
paper's square, whose walls :func:`sarlink.engine.motion.boundary_turn` handles. A point is
inside when a ray from it crosses the edges an odd number of times (so the holes are out).

The boundary rule generalised (docs/model.md, Drones): a searching drone whose next increment
would leave the area or enter a hole takes a uniform random heading among those whose
increment stays inside, drawn by rejection (uniform angles until one fits), which at a
straight wall is the paper's half circle of inward headings. A drone boxed in so tightly that
no heading fits within :data:`TRIES` draws hovers for that step.

A drone flying home (its budget due, or reporting) takes the shortest way round the holes:
straight to the BS when nothing is in the way, else towards the corner (``nav``, from
:meth:`sarlink.engine.paths.Navigation.home`) that minimises the flight there plus the
corner's own distance home; the same distance decides when its budget is due.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.geometry import unit
from sarlink.engine.params import REPORTING, RETURNING, SEARCHING, Params

TRIES = 256
"""Random headings tried before a drone hovers for a step: at a straight wall half of them
fit and at a right-angled corner a quarter, so only a drone boxed into a sliver narrower than
a step is left hovering."""


@njit(cache=True, error_model="numpy")
def contains(x: float, y: float, edges: np.ndarray) -> bool:
    """Whether ``(x, y)`` lies inside the area (even-odd rule over every ring's edges)."""
    odd = False
    for e in range(edges.shape[0]):
        x1, y1, x2, y2 = edges[e, 0], edges[e, 1], edges[e, 2], edges[e, 3]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            odd = not odd
    return odd


@njit(cache=True, inline="always", error_model="numpy")
def _side(ax: float, ay: float, bx: float, by: float, cx: float, cy: float) -> float:
    """Twice the signed area of the triangle ``abc``: > 0 when ``c`` is left of ``a -> b``."""
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


@njit(cache=True, error_model="numpy")
def clear(x0: float, y0: float, x1: float, y1: float, edges: np.ndarray) -> bool:
    """Whether the segment ``(x0, y0) -> (x1, y1)`` touches no edge of the area."""
    lo_x, hi_x = min(x0, x1), max(x0, x1)
    lo_y, hi_y = min(y0, y1), max(y0, y1)
    for e in range(edges.shape[0]):
        ax, ay, bx, by = edges[e, 0], edges[e, 1], edges[e, 2], edges[e, 3]
        if max(ax, bx) < lo_x or min(ax, bx) > hi_x or max(ay, by) < lo_y or \
                min(ay, by) > hi_y:
            continue
        d1 = _side(x0, y0, x1, y1, ax, ay)
        d2 = _side(x0, y0, x1, y1, bx, by)
        d3 = _side(ax, ay, bx, by, x0, y0)
        d4 = _side(ax, ay, bx, by, x1, y1)
        if d1 * d2 <= 0.0 and d3 * d4 <= 0.0:  # crossing or touching (also collinear)
            return False
    return True


@njit(cache=True, inline="always", error_model="numpy")
def stays_inside(x: float, y: float, hx: float, hy: float, step: float,
                 edges: np.ndarray) -> bool:
    """Whether the increment ``step (hx, hy)`` from ``(x, y)`` ends inside the area without
    touching its outline or a hole on the way."""
    nx, ny = x + step * hx, y + step * hy
    return contains(nx, ny, edges) and clear(x, y, nx, ny, edges)


@njit(cache=True, inline="always", error_model="numpy")
def inward_turn(x: float, y: float, hx: float, hy: float, step: float, edges: np.ndarray,
                rng: np.random.Generator) -> tuple[float, float, bool]:
    """Keep the heading if the next increment stays inside; else a uniform random heading
    among those that do (rejection), or none (hover) if :data:`TRIES` draws find none. A
    hovering drone (heading ``(0, 0)``, which would "stay inside") draws again next step, so
    it hovers for that step only."""
    if (hx != 0.0 or hy != 0.0) and stays_inside(x, y, hx, hy, step, edges):
        return hx, hy, False
    for _ in range(TRIES):
        theta = rng.random() * 2.0 * math.pi
        hx, hy = math.cos(theta), math.sin(theta)
        if stays_inside(x, y, hx, hy, step, edges):
            return hx, hy, True
    return 0.0, 0.0, True


@njit(cache=True, inline="always", error_model="numpy")
def _via(x: float, y: float, step: float, edges: np.ndarray, nav: np.ndarray,
         dist: np.ndarray, hx: float, hy: float) -> tuple[float, float, float]:
    """Towards the visible corner ``v`` with the least flight there plus ``dist[v]`` (its
    flight on to the goal), among those whose next increment stays inside; with none, the
    heading ``(hx, hy)`` if its increment stays inside, else none (hover), and an infinite
    length."""
    best, bx, by = np.inf, hx, hy
    for v in range(nav.shape[0]):
        ex, ey = nav[v, 0] - x, nav[v, 1] - y
        e = math.sqrt(ex * ex + ey * ey)
        total = e + dist[v]
        if total >= best or not clear(x, y, nav[v, 0], nav[v, 1], edges):
            continue
        ux, uy = unit(ex, ey, hx, hy)
        if e >= step or stays_inside(x, y, ux, uy, step, edges):
            best, bx, by = total, ux, uy
    if best == np.inf and not stays_inside(x, y, bx, by, step, edges):
        bx = by = 0.0
    return bx, by, best


@njit(cache=True, inline="always", error_model="numpy")
def home_heading(x: float, y: float, bs_x: float, bs_y: float, step: float, edges: np.ndarray,
                 nav: np.ndarray, hx: float, hy: float) -> tuple[float, float, float]:
    """The heading of the shortest flight home from ``(x, y)`` and its length, m: straight to
    the BS if the way is clear, else by the corners (``nav[:, 2]``, their distances home)."""
    dx, dy = bs_x - x, bs_y - y
    if clear(x, y, bs_x, bs_y, edges):
        ux, uy = unit(dx, dy, hx, hy)
        return ux, uy, math.sqrt(dx * dx + dy * dy)
    return _via(x, y, step, edges, nav, nav[:, 2], hx, hy)


@njit(cache=True, inline="always", error_model="numpy")
def way_to(x: float, y: float, gx: float, gy: float, step: float, edges: np.ndarray,
           nav: np.ndarray, hx: float, hy: float) -> tuple[float, float, float]:
    """The heading of the shortest flight from ``(x, y)`` to ``(gx, gy)`` and its length, m:
    the corners' distances to the goal by Dijkstra's algorithm over their visibility graph
    (``nav[:, 3:]``, the straight distance between two corners that see each other)."""
    dx, dy = gx - x, gy - y
    if clear(x, y, gx, gy, edges):
        ux, uy = unit(dx, dy, hx, hy)
        return ux, uy, math.sqrt(dx * dx + dy * dy)
    v = nav.shape[0]
    dist = np.full(v, np.inf)
    for a in range(v):
        if clear(nav[a, 0], nav[a, 1], gx, gy, edges):
            dist[a] = math.sqrt((nav[a, 0] - gx) ** 2 + (nav[a, 1] - gy) ** 2)
    done = np.zeros(v, dtype=np.bool_)
    for _ in range(v):
        u, near = -1, np.inf
        for a in range(v):
            if not done[a] and dist[a] < near:
                u, near = a, dist[a]
        if u < 0:
            break
        done[u] = True
        for w in range(v):
            if not done[w] and near + nav[u, 3 + w] < dist[w]:
                dist[w] = near + nav[u, 3 + w]
    return _via(x, y, step, edges, nav, dist, hx, hy)


@njit(cache=True, error_model="numpy")
def polygon_rules(k: int, homing: bool, p: Params, px: np.ndarray, py: np.ndarray,
                  nhx: np.ndarray, nhy: np.ndarray, mode: np.ndarray, on_route: np.ndarray,
                  last_change: np.ndarray, edges: np.ndarray, nav: np.ndarray,
                  rejoin: np.ndarray, leave_x: np.ndarray, leave_y: np.ndarray,
                  goal_x: np.ndarray, goal_y: np.ndarray, rng: np.random.Generator) -> None:
    """A polygon area's rules on the new headings ``(nhx, nhy)`` of step ``k``: drones flying
    home or to report take the shortest way round the holes; a searching distributed drone
    whose budget is due by that way turns home (``homing``: that may be so for some drone);
    the others follow the boundary rule, whose turn counts as a direction change.

    A route drone flying back to where it left its tour to report (``goal``, NaN when none)
    goes the shortest way round too: each step its rejoin point (``leave``, which the move
    flies to) is set one increment along that way, and to the goal itself once that is
    straight ahead within an increment (the move then flies on along the tour).
    """
    step = p.speed * p.dt
    t = k * p.dt
    for i in range(nhx.shape[0]):
        if on_route[i] and mode[i] == REPORTING:
            goal_x[i], goal_y[i] = leave_x[i], leave_y[i]
        elif on_route[i] and mode[i] == SEARCHING and not math.isnan(goal_x[i]):
            gx, gy = goal_x[i], goal_y[i]
            ux, uy, dist = way_to(px[i], py[i], gx, gy, step, edges, nav, nhx[i], nhy[i])
            rejoin[i] = True
            if dist <= step and clear(px[i], py[i], gx, gy, edges):  # back on the tour now
                leave_x[i], leave_y[i] = gx, gy
                goal_x[i] = goal_y[i] = np.nan
            else:
                leave_x[i], leave_y[i] = px[i] + step * ux, py[i] + step * uy
            continue
        if mode[i] == RETURNING or mode[i] == REPORTING:
            ux, uy, dist = home_heading(px[i], py[i], p.bs_x, p.bs_y, step, edges, nav,
                                        nhx[i], nhy[i])
            nhx[i], nhy[i] = ux, uy
            if (mode[i] == REPORTING and homing and not on_route[i]
                    and (p.flight_time - t) - dist / p.speed < 2.0 * p.dt):
                mode[i] = RETURNING
            continue
        if on_route[i] or mode[i] != SEARCHING:
            continue
        if homing:
            ux, uy, dist = home_heading(px[i], py[i], p.bs_x, p.bs_y, step, edges, nav,
                                        nhx[i], nhy[i])
            if (p.flight_time - t) - dist / p.speed < 2.0 * p.dt:
                mode[i] = RETURNING
                nhx[i], nhy[i] = ux, uy
                continue
        nhx[i], nhy[i], turned = inward_turn(px[i], py[i], nhx[i], nhy[i], step, edges, rng)
        if turned:
            last_change[i] = k


def edge_array(rings: list[np.ndarray]) -> np.ndarray:
    """The ``(E, 4)`` edges of closed rings given as ``(k, 2)`` vertex arrays (the closing
    vertex repeated or not)."""
    segments = []
    for ring in rings:
        ring = np.asarray(ring, dtype=float)
        if np.array_equal(ring[0], ring[-1]):
            ring = ring[:-1]
        segments.append(np.hstack([ring, np.roll(ring, -1, axis=0)]))
    return np.vstack(segments) if segments else np.empty((0, 4))
