"""Sector search (IAMSAR VS), the sectors shared among the drones.

IAMSAR's sector search covers a circle around the datum with legs through it: out along a
radius, a cross leg, back through the datum, all turns to starboard (120° for vessels, six
legs 60° apart); "the angle between successive search legs will depend on the radius used and
the maximum track spacing at the ends of the search legs", and a pattern completed without
finding the object is "rotated and repeated with the second set of search legs falling
half-way between". Here the datum is the BS. The spokes are as many as make the gap between
their ends at most one track space S at the radius, rounded up to a multiple of N; each drone
takes a sector of consecutive spokes, clockwise: out along one, across to the next spoke's
end, home along it, and so on (a single spoke out and back). The radius reaches the farthest
corner of the area (a spoke stops at the edge) unless a drone could not fly its sector within
the flight budget: then it is the largest found by bisection that fits, a smaller circle
searched whole rather than part of a larger one. Then each drone flies its sector again with
the spokes rotated by half the angle between them, as far as the budget lets it
(docs/model.md, Search patterns).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from sarlink.planners.patterns.base import Search
from sarlink.planners.patterns.geometry import close_at, flight_length

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["PASSES", "plan", "radius", "routes", "spokes"]

PASSES = (0.25, 0.75)
"""Where each pass puts its spokes, as a fraction of the angle between them: the second pass
falls half-way between the first's legs, and both keep a quarter of it from an edge of the
area seen from a BS on that edge."""
_BISECTIONS = 30
"""Halvings of the radius interval: a thousand-millionth of the area's reach."""


def spokes(search: Search, phase: float, reach: float) -> np.ndarray:
    """The ends of every spoke of one pass of radius ``reach``, clockwise: ``reach`` from the
    BS, or where the spoke leaves the area if that is nearer."""
    first, sweep = search.area.view(search.bs)
    bs = np.asarray(search.bs, dtype=float)
    gap = 2 * math.asin(min(1.0, search.spacing / (2 * reach))) if reach > 0 else math.pi
    n = search.drones
    count = n * math.ceil(math.ceil(sweep / gap - 1e-9) / n)
    ends = []
    for angle in first + sweep - sweep * (np.arange(count) + phase) / count:
        edge = search.exit(angle)
        ends.append(bs + (edge - bs) * min(1.0, reach / max(float(np.hypot(*(edge - bs))),
                                                             1e-12)))
    return search.area.clamp(np.array(ends))  # bs + (edge - bs) may round past the edge


def _sectors(search: Search, ends: np.ndarray) -> list[list[np.ndarray]]:
    """Each drone's legs over its share of the spokes ``ends``: triangles through the BS."""
    bs = np.asarray(search.bs, dtype=float)
    out = []
    for mine in np.array_split(ends, search.drones):
        out.append([leg for k in range(0, len(mine), 2) for leg in (mine[k:k + 2], bs)])
    return out


def radius(search: Search) -> float:
    """The sector radius: to the area's farthest corner, or the largest found by bisection
    with which every drone flies its first pass within the budget."""
    def fits(reach: float) -> bool:
        return all(flight_length(search.bs, close_at(search.bs, legs)) <= search.budget
                   for legs in _sectors(search, spokes(search, PASSES[0], reach)))

    far = float(np.hypot(*(search.area.corners - search.bs).T).max())
    if fits(far):
        return far
    lo, hi = 0.0, far
    for _ in range(_BISECTIONS):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if fits(mid) else (lo, mid)
    return lo


def plan(search: Search) -> tuple[np.ndarray, ...]:
    """Every drone's sectors, both passes, from and back to the BS (the second pass not yet
    fitted to the flight budget)."""
    reach = radius(search)
    passes = [_sectors(search, spokes(search, phase, reach)) for phase in PASSES]
    return tuple(close_at(search.bs, [leg for legs in mine for leg in legs])
                 for mine in zip(*passes, strict=True))


def routes(mission: Mission) -> tuple[np.ndarray, ...]:
    """The sector search of ``mission``: one route per drone, within its budget."""
    search = Search.of(mission)
    return search.fit(plan(search))
