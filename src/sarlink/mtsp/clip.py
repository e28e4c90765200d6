"""mTSP on a polygon area: the cells clipped to it, and tours bent around its holes.

The paper's square keeps :func:`sarlink.mtsp.grid.grid_cells`. On a polygon area the grid of
cells of side ``r`` covers the area's bounding box; a cell whose part inside the area is at
least :data:`MIN_SHARE` of a cell is a city, at the cell's centre if that lies in the area and
else at a point of its part inside (so no city lies in a hole or outside). The solvers plan
on straight distances; a leg that would cross a hole or leave the area is then flown along
the shortest way round (:class:`sarlink.engine.paths.Navigation`).
"""

from __future__ import annotations

import hashlib
import math

import numpy as np
import shapely
from shapely.geometry import Polygon, box

from sarlink.config import Mission
from sarlink.config.region import area_polygon
from sarlink.config.region import is_polygon as polygonal
from sarlink.engine.paths import Navigation

__all__ = ["MIN_SHARE", "area_cells", "area_key", "flyable", "is_polygon"]

MIN_SHARE = 0.05
"""The least part of a cell (of its area r²) inside the search area that makes it a city."""


def is_polygon(mission: Mission) -> bool:
    """Whether the mission's area is a polygon or has holes (else it is the paper's square)."""
    return polygonal(mission.region)


def area_key(mission: Mission) -> str:
    """A digest of the area's geometry, for the plan cache's key."""
    wkt = area_polygon(mission.region, mission.area.size).wkt
    return hashlib.sha256(wkt.encode()).hexdigest()[:16]


def area_cells(mission: Mission) -> np.ndarray:
    """The cities of a polygon area, shape ``(K, 2)``, in row-major order from the south-west."""
    area = area_polygon(mission.region, mission.area.size)
    r = mission.sensing.r
    min_x, min_y, max_x, max_y = area.bounds
    nx = max(1, math.ceil((max_x - min_x) / r - 1e-9))
    ny = max(1, math.ceil((max_y - min_y) / r - 1e-9))
    cities = []
    shapely.prepare(area)
    for row in range(ny):
        for col in range(nx):
            x0, y0 = min_x + col * r, min_y + row * r
            cell = box(x0, y0, x0 + r, y0 + r)
            part = cell.intersection(area)
            if part.area < MIN_SHARE * r * r:
                continue
            centre = (x0 + r / 2, y0 + r / 2)
            if area.contains(shapely.Point(centre)):
                cities.append(centre)
            else:
                pieces = [g for g in shapely.get_parts(part) if isinstance(g, Polygon)]
                inner = max(pieces, key=lambda g: g.area).representative_point()
                cities.append((inner.x, inner.y))
    return np.array(cities, dtype=float).reshape(-1, 2)


def flyable(mission: Mission, routes: tuple[np.ndarray, ...]) -> tuple[np.ndarray, ...]:
    """Routes from the BS with every leg that leaves the area or crosses a hole bent along
    the shortest way round; the square's routes unchanged."""
    if not is_polygon(mission):
        return routes
    nav = Navigation(area_polygon(mission.region, mission.area.size))
    bs = mission.area.bs_xy
    return tuple(nav.route(bs, r) if len(r) else r for r in routes)
