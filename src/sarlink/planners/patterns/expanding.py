"""Expanding square search (IAMSAR SS), the squares shared among the drones.

IAMSAR's expanding square starts at the datum and expands outward in concentric squares one
track space S apart (legs S, S, 2S, 2S, 3S, ...; all turns the same way), for a single unit:
"must not be used simultaneously by multiple aircraft at similar altitudes". Here the datum is
the BS, and the squares are closed: square k has half-side (k + ½) S, so that with S = 2 r the
squares' sides cover every band around the BS (the pattern's corners leave small gaps on the
diagonals, as IAMSAR's do with a definite-range sensor). A side beyond the area is moved to
half a track space inside its edge. N drones share every square: drone i flies the i-th of N
equal arcs of each (counter-clockwise from its lower-left corner; every other square
backwards, so that its next arc starts where the last ended), so the team expands from the BS
together, each drone in its own wedge; one drone flies every square whole, turning one way
(docs/model.md, Search patterns).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from sarlink.planners.patterns.base import Search
from sarlink.planners.patterns.geometry import close_at, polyline_arc

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["plan", "routes", "squares"]


def squares(search: Search) -> list[np.ndarray]:
    """The concentric squares around the BS, innermost first, each a closed loop
    counter-clockwise from its lower-left corner, enough of them to reach every corner of the
    area, moved inside the area inset by half a track space."""
    spacing, (bx, by) = search.spacing, search.bs
    inner = search.area.inset(spacing / 2)
    reach = float(np.abs(search.area.corners - search.bs).max())  # Chebyshev, to a corner
    loops = []
    for k in range(max(1, math.ceil(reach / spacing - 1e-9))):
        h = (k + 0.5) * spacing
        (x0, y0), (x1, y1) = inner.clamp(np.array([[bx - h, by - h], [bx + h, by + h]]))
        loops.append(np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]]))
    return loops


def plan(search: Search) -> tuple[np.ndarray, ...]:
    """Every drone's share of the expanding squares, from and back to the BS (not yet fitted
    to the flight budget)."""
    n = search.drones
    loops = squares(search)
    out = []
    for i in range(n):
        arcs = []
        for k, loop in enumerate(loops):
            start, end = i / n, (i + 1) / n
            if n > 1 and k % 2:
                start, end = end, start
            arcs.append(polyline_arc(loop, start, end))
        out.append(close_at(search.bs, arcs))
    return tuple(out)


def routes(mission: Mission) -> tuple[np.ndarray, ...]:
    """The expanding square search of ``mission``: one route per drone, within its budget."""
    search = Search.of(mission)
    return search.fit(plan(search))
