"""The search area on a figure: the square, or a polygon with its no-fly holes and the target
prior's zones shaded by their probability density."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import PathPatch, Rectangle
from matplotlib.path import Path as MplPath
from shapely.geometry import Polygon

from sarlink.config import Mission
from sarlink.config.region import area_polygon, zone_polygon

__all__ = ["area_bounds", "draw_area"]


def _patch(poly: Polygon, **style: object) -> PathPatch:
    rings = [np.asarray(poly.exterior.coords), *(np.asarray(h.coords) for h in poly.interiors)]
    codes = [np.r_[MplPath.MOVETO, np.full(len(r) - 2, MplPath.LINETO), MplPath.CLOSEPOLY]
             for r in rings]
    return PathPatch(MplPath(np.vstack(rings), np.concatenate(codes)), **style)


def area_bounds(mission: Mission) -> tuple[float, float, float, float]:
    """``(min_x, min_y, max_x, max_y)`` of the area, m."""
    return area_polygon(mission.region, mission.area.size).bounds


def draw_area(ax: plt.Axes, mission: Mission) -> None:
    """Draw the area's outline, its holes (hatched: no-fly) and the prior's zones (the darker,
    the likelier per square metre), and set the axes' limits around it."""
    region, size = mission.region, mission.area.size
    if region is None or (region.outline is None and not region.holes and not region.zones):
        ax.add_patch(Rectangle((0, 0), size, size, fill=False, lw=1.2, color="black"))
    else:
        area = area_polygon(region, size)
        if region.zones:
            polys = [zone_polygon(z).intersection(area) for z in region.zones]
            density = np.array([z.weight / zone_polygon(z).area for z in region.zones])
            for k, (poly, d) in enumerate(zip(polys, density / density.max(), strict=True)):
                for part in getattr(poly, "geoms", [poly]):
                    if isinstance(part, Polygon) and part.area > 0:
                        ax.add_patch(_patch(part, color="tab:red", alpha=0.05 + 0.25 * d,
                                            lw=0, label="target prior" if k == 0 else None))
        ax.add_patch(_patch(Polygon(area.exterior), fill=False, lw=1.2, color="black"))
        for k, hole in enumerate(area.interiors):
            ax.add_patch(_patch(Polygon(hole), facecolor="0.85", edgecolor="0.3", hatch="//",
                                lw=0.8, label="no-fly zone" if k == 0 else None))
    x0, y0, x1, y1 = area_bounds(mission)
    pad = 0.03 * max(x1 - x0, y1 - y0)
    ax.set(xlim=(x0 - pad, x1 + pad), ylim=(y0 - pad, y1 + pad), aspect="equal")
