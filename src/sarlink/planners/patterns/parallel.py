"""Parallel track search (IAMSAR PS), the area split among the drones.

IAMSAR divides a large area into sub-areas, one per search unit; each unit starts in a corner
of its sub-area, half a track space inside both sides, and flies legs parallel to the long
sides, one track space S apart. Here the tracks are laid over the whole area (along y on the
square; on the map, along the long sides of the area's bounding box), the first and last half
a track space inside its edges, the last moved inwards when the width is not a
multiple of S, and split among the drones: with no more drones than tracks each drone gets a
band of whole tracks (on the map, bands of about equal length inside the area); with more,
each track is cut into equal pieces, one per drone. Legs run
the sub-area's whole length, edge to edge, so that a definite-range sensor (S = 2 r) covers
every point, the corners included. Each drone enters at the corner of its sub-area that makes
its flight from and back to the BS shortest (docs/model.md, Search patterns).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from sarlink.planners.patterns.base import Search
from sarlink.planners.patterns.geometry import Rect, close_at, flight_length

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["plan", "routes", "tracks"]


def tracks(lo: float, hi: float, spacing: float) -> np.ndarray:
    """Track positions across ``[lo, hi]``: ``spacing`` apart, the outer ones half a spacing
    inside the edges (one track in the middle when the width is at most one spacing)."""
    if hi - lo <= spacing:
        return np.array([(lo + hi) / 2])
    count = math.ceil((hi - lo) / spacing - 1e-9)
    xs = lo + spacing / 2 + spacing * np.arange(count)
    xs[-1] = min(xs[-1], hi - spacing / 2)
    return xs


def _balanced(lengths: np.ndarray, drones: int) -> list[np.ndarray]:
    """Contiguous bands of the tracks, one per drone and at least one track each, cut where
    the summed ``lengths`` come nearest to equal shares."""
    count, total = len(lengths), float(lengths.sum())
    before = np.r_[0.0, np.cumsum(lengths)]  # length of the tracks before each cut
    cuts = [0]
    for j in range(1, drones):
        allowed = np.arange(cuts[-1] + 1, count - (drones - j) + 1)
        cuts.append(int(allowed[np.argmin(np.abs(before[allowed] - total * j / drones))]))
    cuts.append(count)
    return [np.arange(a, b) for a, b in itertools.pairwise(cuts)]


def _shares(drones: int, count: int, lengths: np.ndarray | None = None
            ) -> list[tuple[np.ndarray, float, float]]:
    """Each drone's tracks (indices) and the fractions of their length it flies; with the
    tracks' ``lengths`` inside an area on the map, bands of even length."""
    if drones <= count:
        bands = (np.array_split(np.arange(count), drones) if lengths is None
                 else _balanced(lengths, drones))
        return [(band, 0.0, 1.0) for band in bands]
    per_track = [len(part) for part in np.array_split(np.arange(drones), count)]
    return [(np.array([j]), m / n, (m + 1) / n) for j, n in enumerate(per_track)
            for m in range(n)]


def _mower(xs: np.ndarray, y0: float, y1: float) -> np.ndarray:
    """Legs along ``xs`` in turn, the first from ``y0`` to ``y1``, each the reverse of the last."""
    ends = [(y0, y1) if k % 2 == 0 else (y1, y0) for k in range(len(xs))]
    return np.array([(x, y) for x, pair in zip(xs, ends, strict=True) for y in pair])


def plan(search: Search) -> tuple[np.ndarray, ...]:
    """Every drone's parallel-track route over its sub-area, from and back to the BS (not yet
    fitted to the flight budget), the legs parallel to the area's long sides."""
    area = search.area
    if area.x1 - area.x0 > area.y1 - area.y0:  # planned with x and y swapped, then back
        swapped = replace(search, area=Rect(area.y0, area.x0, area.y1, area.x1),
                          bs=(search.bs[1], search.bs[0]),
                          on_map=None if search.on_map is None else search.on_map.swapped())
        return tuple(np.ascontiguousarray(route[:, ::-1]) for route in plan(swapped))
    xs = tracks(area.x0, area.x1, search.spacing)
    lengths = None if search.on_map is None else search.on_map.inside(
        np.array([[(x, area.y0), (x, area.y1)] for x in xs]))
    out = []
    for band, f0, f1 in _shares(search.drones, len(xs), lengths):
        y0, y1 = area.y0 + f0 * (area.y1 - area.y0), area.y0 + f1 * (area.y1 - area.y0)
        corners = [_mower(order, a, b) for order in (xs[band], xs[band][::-1])
                   for a, b in ((y0, y1), (y1, y0))]
        out.append(min((close_at(search.bs, [m]) for m in corners),
                       key=lambda route: flight_length(search.bs, route)))
    return tuple(out)


def routes(mission: Mission) -> tuple[np.ndarray, ...]:
    """The parallel track search of ``mission``: one route per drone, within its budget."""
    search = Search.of(mission)
    return search.fit(plan(search))
