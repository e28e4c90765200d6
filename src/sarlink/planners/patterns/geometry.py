"""Plane geometry the search patterns share: the area, polylines and the flight budget.

Every pattern asks the area only what this module's :class:`Rect` answers (inset, clamp, where
a ray leaves it, whether points lie in it); an area on the map is the ``Rect`` of its bounding
box, and :mod:`.polygon` clips the routes to it. A route here is what the engine flies: waypoints
of shape ``(k, 2)`` after take-off from the BS, the last one the BS.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

__all__ = ["Point", "Rect", "close_at", "fit_budget", "flight_length", "polyline_arc"]

Point = Sequence[float] | np.ndarray
"""A point ``(x, y)``, m."""


@dataclass(frozen=True)
class Rect:
    """An axis-aligned rectangle ``[x0, x1] × [y0, y1]``: the search area, or a part of it."""

    x0: float
    y0: float
    x1: float
    y1: float

    @classmethod
    def square(cls, size: float) -> Rect:
        """The paper's area ``[0, size]²``."""
        return cls(0.0, 0.0, size, size)

    @property
    def corners(self) -> np.ndarray:
        """The four corners, counter-clockwise from ``(x0, y0)``."""
        return np.array([[self.x0, self.y0], [self.x1, self.y0], [self.x1, self.y1],
                         [self.x0, self.y1]])

    def inset(self, d: float) -> Rect:
        """The rectangle shrunk by ``d`` on every side; a side shorter than ``2 d`` collapses
        to its midpoint (a track half a track space inside the edge covers up to it)."""
        def shrink(lo: float, hi: float) -> tuple[float, float]:
            return (lo + d, hi - d) if hi - lo >= 2 * d else ((lo + hi) / 2,) * 2
        (x0, x1), (y0, y1) = shrink(self.x0, self.x1), shrink(self.y0, self.y1)
        return Rect(x0, y0, x1, y1)

    def clamp(self, points: np.ndarray) -> np.ndarray:
        """Each point moved to the nearest point of the rectangle."""
        points = np.asarray(points, dtype=float)
        return np.column_stack([np.clip(points[..., 0], self.x0, self.x1),
                                np.clip(points[..., 1], self.y0, self.y1)])

    def contains(self, points: np.ndarray, tol: float = 1e-9) -> np.ndarray:
        """Whether each point lies in the rectangle (within ``tol``)."""
        p = np.asarray(points, dtype=float).reshape(-1, 2)
        return ((p[:, 0] >= self.x0 - tol) & (p[:, 0] <= self.x1 + tol)
                & (p[:, 1] >= self.y0 - tol) & (p[:, 1] <= self.y1 + tol))

    def view(self, origin: Point) -> tuple[float, float]:
        """The directions from ``origin`` into the rectangle, as the first angle and the
        counter-clockwise sweep from it (radians): the whole circle from inside, half of it
        from an edge, a quarter from a corner."""
        ox, oy = float(origin[0]), float(origin[1])
        if self.x0 < ox < self.x1 and self.y0 < oy < self.y1:
            return 0.0, 2 * math.pi
        rays = self.corners - (ox, oy)
        rays = rays[np.hypot(*rays.T) > 1e-9]
        angles = np.sort(np.arctan2(rays[:, 1], rays[:, 0]))
        gaps = np.diff(np.append(angles, angles[0] + 2 * math.pi))
        k = int(np.argmax(gaps))
        return float(angles[(k + 1) % len(angles)]), float(2 * math.pi - gaps[k])

    def exit(self, origin: Point, angle: float) -> np.ndarray:
        """Where the ray from ``origin`` (inside) at ``angle`` (radians) leaves the rectangle."""
        ox, oy = float(origin[0]), float(origin[1])
        dx, dy = math.cos(angle), math.sin(angle)
        reach = math.inf
        for o, d, lo, hi in ((ox, dx, self.x0, self.x1), (oy, dy, self.y0, self.y1)):
            if d > 1e-12:
                reach = min(reach, (hi - o) / d)
            elif d < -1e-12:
                reach = min(reach, (lo - o) / d)
        reach = max(reach, 0.0)
        return self.clamp(np.array([[ox + reach * dx, oy + reach * dy]]))[0]


def _legs(path: np.ndarray) -> np.ndarray:
    return np.hypot(*np.diff(path, axis=0).T) if len(path) > 1 else np.zeros(0)


def flight_length(bs: Point, route: np.ndarray) -> float:
    """Metres flown from take-off at ``bs`` along ``route``."""
    return float(_legs(np.vstack([bs, np.asarray(route).reshape(-1, 2)])).sum())


def close_at(bs: Point, pieces: Sequence[np.ndarray]) -> np.ndarray:
    """A route from take-off at ``bs`` through ``pieces`` in order and back to ``bs``: their
    waypoints joined, a waypoint within a nanometre of the one before it dropped."""
    path = np.vstack([np.reshape(bs, (1, 2)), *(np.reshape(p, (-1, 2)) for p in pieces),
                      np.reshape(bs, (1, 2))]).astype(float)
    keep = np.ones(len(path), dtype=bool)
    keep[1:] = (np.abs(np.diff(path, axis=0)) > 1e-9).any(axis=1)
    route = path[keep][1:] if keep[1:].any() else path[-1:]
    route[-1] = path[-1]  # the BS itself, not a point a rounding error away
    return route


def fit_budget(bs: Point, route: np.ndarray, budget: float) -> np.ndarray:
    """``route`` cut where the drone must turn home to land at ``bs`` within ``budget`` metres.

    Flown ``s`` metres along the path, a drone needs ``s + |p(s) - bs|`` metres to land; that
    never falls along the path (a leg is no shorter than the change of distance it makes), so
    the cut is the last point where it equals ``budget``, found in closed form on its leg. A
    route within budget is returned unchanged.
    """
    bs_xy = np.asarray(bs, dtype=float)
    path = np.vstack([bs_xy, np.asarray(route, dtype=float).reshape(-1, 2)])
    if flight_length(bs_xy, route) <= budget:
        return np.asarray(route, dtype=float).reshape(-1, 2)
    flown = 0.0
    for k in range(1, len(path)):
        a, b = path[k - 1], path[k]
        leg = float(np.hypot(*(b - a)))
        if leg == 0.0:
            continue
        if flown + leg + float(np.hypot(*(b - bs_xy))) > budget:
            u, w, left = (b - a) / leg, a - bs_xy, budget - flown
            # s0 + t + |w + t u| = budget, solved for t on this leg
            denominator = 2.0 * (float(w @ u) + left)
            t = (left * left - float(w @ w)) / denominator if denominator > 0 else 0.0
            cut = a + min(max(t, 0.0), leg) * u
            return close_at(bs_xy, [path[1:k], cut])
        flown += leg
    return path[1:]  # not reached: the whole route fits


def polyline_arc(line: np.ndarray, start: float, end: float) -> np.ndarray:
    """The part of polyline ``line`` between the fractions ``start`` and ``end`` of its length
    (``start > end``: flown backwards), its vertices in between included."""
    line = np.asarray(line, dtype=float).reshape(-1, 2)
    cum = np.concatenate([[0.0], np.cumsum(_legs(line))])
    total = cum[-1]
    if total == 0.0:
        return line[:1].copy()
    lo, hi = sorted((start, end))
    at = np.array([lo, hi]) * total
    inner = (cum > at[0]) & (cum < at[1])
    s = np.concatenate([[at[0]], cum[inner], [at[1]]])
    points = np.column_stack([np.interp(s, cum, line[:, 0]), np.interp(s, cum, line[:, 1])])
    return points if start <= end else points[::-1]
