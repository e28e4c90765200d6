"""The search patterns on an area on the map: planned over its bounding box, clipped to it.

IAMSAR lays its patterns over rectangles and circles; a SAR area on the map is a polygon with
no-fly holes. Survey planners lay their tracks over the polygon's bounding box and keep what
falls inside (QGroundControl's Survey clips its transects to the polygon); sarlink does the
same with every pattern. A pattern is planned over the bounding box (:attr:`Search.area
<sarlink.planners.patterns.base.Search.area>`), then each route keeps the parts of its legs
that lie in the area :data:`INSET` inside its edges, flies from one part to the next along the
shortest way inside the area (around the holes, :class:`~sarlink.engine.paths.Navigation`),
and is cut where the drone must turn home to land within the budget, home along the shortest
way inside too. Every leg of a route then lies in the area, so the drone never crosses a
no-fly zone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from sarlink.engine.paths import Navigation
from sarlink.planners.patterns.geometry import Point, close_at

__all__ = ["INSET", "MIN_PIECE", "Clipped"]

INSET = 1.0
"""How far (m) inside the area's edges a clipped leg stays: its ends are waypoints, and a
waypoint on an edge is a rounding error away from outside."""
MIN_PIECE = 1.0
"""Parts of a leg inside the area shorter than this (m) are dropped: a leg that grazes a
corner is not worth the detour to it."""
_CUT_TOLERANCE = 1e-6
"""How close (m) the bisection puts a cut to the last point from which the drone lands within
its budget (always on the near side)."""


@dataclass(frozen=True, eq=False)
class Clipped:
    """Routes planned over the bounding box of ``area``, made flyable in it."""

    area: Polygon
    bs: tuple[float, float]

    @cached_property
    def nav(self) -> Navigation:
        return Navigation(self.area)

    @cached_property
    def _inner(self) -> Polygon:
        inner = self.area.buffer(-INSET, join_style="mitre")
        shapely.prepare(inner)
        return inner

    @cached_property
    def _home(self) -> tuple[np.ndarray, np.ndarray]:
        """The points a flight home first heads for (the BS and the bends of shortest paths),
        and each one's distance home."""
        nodes, _ = self.nav.home(self.bs)
        points = np.vstack([np.reshape(self.bs, (1, 2)), nodes[:, :2]])
        return points, np.r_[0.0, nodes[:, 2]]

    def home(self, point: Point) -> float:
        """The shortest flight home from ``point`` inside the area, m."""
        points, dist = self._home
        p = np.asarray(point, dtype=float)
        seen = self.nav.visible(np.broadcast_to(p, points.shape), points)
        return float((np.hypot(*(points - p).T) + dist)[seen].min(initial=math.inf))

    def swapped(self) -> Clipped:
        """The same area with x and y swapped (mirrored about the diagonal)."""
        return Clipped(shapely.transform(self.area, lambda xy: xy[:, ::-1]),
                       (self.bs[1], self.bs[0]))

    def inside(self, segments: np.ndarray) -> np.ndarray:
        """How long each segment ``(a, b)`` of ``segments`` (shape ``(k, 2, 2)``) is inside the
        area, :data:`INSET` inside its edges, m."""
        return np.asarray(shapely.length(shapely.intersection(shapely.linestrings(segments),
                                                              self._inner)))

    def exit(self, angle: float) -> np.ndarray:
        """Where the ray from the BS at ``angle`` (radians) first leaves the area, :data:`INSET`
        inside its edge (the BS itself if that is nearer)."""
        bx, by = self.bs
        far = 2.0 * math.hypot(*np.subtract(self.area.bounds[2:], self.area.bounds[:2]))
        ray = LineString([(bx, by), (bx + far * math.cos(angle), by + far * math.sin(angle))])
        first = min((np.asarray(g.coords) for g in shapely.get_parts(ray.intersection(
            self._inner)) if isinstance(g, LineString)),
            key=lambda c: math.hypot(c[0, 0] - bx, c[0, 1] - by), default=None)
        if first is None or math.hypot(first[0, 0] - bx, first[0, 1] - by) > 1e-9:
            return np.array([bx, by])
        return first[-1]

    def clip(self, route: np.ndarray) -> np.ndarray:
        """``route`` (from take-off at the BS) with only its legs' parts inside the area, joined
        by the shortest flights inside it, ending at the BS."""
        path = np.vstack([np.reshape(self.bs, (1, 2)), np.asarray(route, dtype=float)])
        starts, ends = path[:-1], path[1:]
        parts = shapely.intersection(shapely.linestrings(np.stack([starts, ends], axis=1)),
                                     self._inner)
        pieces = []
        for a, b, part in zip(starts, ends, parts, strict=True):
            along = b - a
            inside = [np.asarray(g.coords) for g in shapely.get_parts(part)
                      if isinstance(g, LineString) and g.length >= MIN_PIECE]
            for coords in sorted(inside, key=lambda c: float(min(c @ along, default=0.0))):
                pieces.append(coords if (coords[-1] - coords[0]) @ along >= 0 else coords[::-1])
        waypoints = close_at(self.bs, pieces)
        return self.nav.route(self.bs, waypoints)

    def fit(self, route: np.ndarray, budget: float) -> np.ndarray:
        """``route`` (every leg inside the area) cut where the drone must turn home, along the
        shortest way inside, to land within ``budget`` metres; a route within budget whole.

        Flown ``s`` metres along the route, a drone needs ``s + home(p(s))`` metres to land,
        which never falls along the route; the cut is found on its leg by bisection."""
        path = np.vstack([np.reshape(self.bs, (1, 2)), np.asarray(route, dtype=float)])
        legs = np.hypot(*np.diff(path, axis=0).T)
        if legs.sum() <= budget:
            return np.asarray(route, dtype=float)
        flown = np.r_[0.0, np.cumsum(legs)]
        k = next(k for k in range(1, len(path)) if flown[k] + self.home(path[k]) > budget)
        a, u = path[k - 1], (path[k] - path[k - 1]) / legs[k - 1]
        lo, hi = 0.0, float(legs[k - 1])
        while hi - lo > _CUT_TOLERANCE:
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if flown[k - 1] + mid + self.home(a + mid * u) <= budget \
                else (lo, mid)
        cut = a + lo * u
        return close_at(self.bs, [path[1:k], cut[None, :], self.nav.path(tuple(cut), self.bs)])
