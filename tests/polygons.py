"""Random search areas for property tests: star-shaped polygons with star-shaped holes."""

from __future__ import annotations

import math

from hypothesis import assume
from hypothesis import strategies as st
from shapely.geometry import Point, Polygon

from sarlink import Mission


def star(cx: float, cy: float, radii: list[float], turn: float) -> list[tuple[float, float]]:
    """A ring around ``(cx, cy)`` with one vertex per radius at evenly spread angles."""
    angles = [turn + 2 * math.pi * i / len(radii) for i in range(len(radii))]
    return [(cx + r * math.cos(a), cy + r * math.sin(a))
            for r, a in zip(radii, angles, strict=True)]


@st.composite
def areas(draw: st.DrawFn, holes: int = 2) -> Mission:
    """A mission whose area is a random star-shaped polygon a few km across with up to
    ``holes`` random holes, and the BS at a random point inside it (out of the holes)."""
    outline = star(0.0, 0.0, draw(st.lists(st.floats(600, 2500), min_size=3, max_size=12)),
                   draw(st.floats(0, 2 * math.pi)))
    shell = Polygon(outline)
    rings: list[list[tuple[float, float]]] = []
    for _ in range(draw(st.integers(0, holes))):
        cx, cy = draw(st.floats(-1500, 1500)), draw(st.floats(-1500, 1500))
        ring = star(cx, cy, draw(st.lists(st.floats(60, 400), min_size=3, max_size=7)),
                    draw(st.floats(0, 2 * math.pi)))
        hole = Polygon(ring)
        if shell.buffer(-20).contains(hole) and all(hole.distance(Polygon(h)) > 20
                                                      for h in rings):
            rings.append(ring)
    area = Polygon(outline, rings)
    assume(area.is_valid)
    bs = area.representative_point() if draw(st.booleans()) else Point(0.0, 0.0)
    assume(area.buffer(-1.0).contains(bs))
    return Mission.from_dict({"area": {"bs": (bs.x, bs.y)},
                              "region": {"outline": outline, "holes": rings}})
