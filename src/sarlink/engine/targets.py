"""Where the target is: drawn from the mission's prior over its area (docs/model.md, World).

The paper's target is uniform in the square (:func:`sarlink.engine.scenario.draw_scenario`
keeps that draw as it was). A polygon area or a prior of weighted zones is cut into triangles
(constrained Delaunay, so holes stay out), each with its probability mass: a zone of weight
``w`` spreads it uniformly over the zone, so a triangle of the zone's part inside the area holds
``w · (triangle area) / (zone area)``. A draw takes three uniform numbers: one picks the
triangle by its mass, two place the point uniformly in it. The draw depends only on the
mission's region and the scenario stream of ``(seed, run)``, so every planner flown on the same
region and run searches for the same target.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from sarlink.config import Mission
from sarlink.config.region import Region, area_polygon, zone_polygon

__all__ = ["TargetPrior", "target_prior"]


@dataclass(frozen=True, eq=False)
class TargetPrior:
    """Triangles ``(K, 3, 2)`` and their cumulative probabilities (the last is 1)."""

    triangles: np.ndarray
    cumulative: np.ndarray

    def draw(self, rng: np.random.Generator) -> tuple[float, float]:
        """One target position: three uniform draws from ``rng``."""
        k = min(int(np.searchsorted(self.cumulative, rng.random(), side="right")),
                len(self.cumulative) - 1)
        r1, r2 = rng.random(), rng.random()
        if r1 + r2 > 1.0:
            r1, r2 = 1.0 - r1, 1.0 - r2
        a, b, c = self.triangles[k]
        x, y = a + r1 * (b - a) + r2 * (c - a)
        return float(x), float(y)


def _polygons(geometry: BaseGeometry) -> list[Polygon]:
    """The polygons of an intersection's result (points and lines carry no area)."""
    return [g for g in shapely.get_parts(geometry) if isinstance(g, Polygon) and g.area > 0]


def _triangles(polygon: Polygon) -> np.ndarray:
    parts = shapely.get_parts(shapely.constrained_delaunay_triangles(polygon))
    return np.array([np.asarray(t.exterior.coords)[:3] for t in parts], dtype=float)


@lru_cache(maxsize=16)
def _prior(region: Region, size: float) -> TargetPrior:
    area = area_polygon(region, size)
    zones = [(area, 1.0, area.area)] if not region.zones else \
        [(zone_polygon(z), z.weight, zone_polygon(z).area) for z in region.zones]
    tris, masses = [], []
    for zone, weight, zone_area in zones:
        for piece in _polygons(zone.intersection(area) if region.zones else zone):
            t = _triangles(piece)
            if len(t) == 0:
                continue
            u, v = t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]
            tri_area = 0.5 * np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
            tris.append(t)
            masses.append(weight * tri_area / zone_area)
    triangles, mass = np.concatenate(tris), np.concatenate(masses)
    cumulative = np.cumsum(mass) / mass.sum()
    cumulative[-1] = 1.0
    return TargetPrior(triangles, cumulative)


def target_prior(mission: Mission) -> TargetPrior | None:
    """The mission's target prior, or None for the paper's uniform target in the square."""
    region = mission.region
    if region is None or (region.outline is None and not region.holes and not region.zones):
        return None
    return _prior(region, mission.area.size)
