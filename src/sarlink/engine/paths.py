"""Shortest flights inside a polygon area: around its holes and its inward corners.

A shortest path between two points of a polygon with holes is a chain of straight legs that
bends only at the area's reflex corners (the outline's inward corners and the holes' outer
ones), so the corners' visibility graph holds every such path. The corners are moved
:data:`MARGIN` into the free space, so that a leg passing one keeps clear of the edges. The
kernel gets each corner with its distance home (:meth:`Navigation.kernel_nodes`), and the
route planners' legs are bent around the holes (:meth:`Navigation.path`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import shapely
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import dijkstra
from shapely.geometry import Polygon

__all__ = ["MARGIN", "Navigation"]

MARGIN = 2.0
"""How far (m) a path's bend keeps from the corner it goes round."""


def _corners(area: Polygon, margin: float) -> np.ndarray:
    """The reflex corners of the free space, each moved ``margin`` into it along its
    bisector (and dropped if that leaves the area, as in a sliver)."""
    area = shapely.geometry.polygon.orient(area, sign=1.0)  # free space on each ring's left
    nodes = []
    for ring in [area.exterior, *area.interiors]:
        pts = np.asarray(ring.coords)[:-1]
        prev, nxt = np.roll(pts, 1, axis=0), np.roll(pts, -1, axis=0)
        d1, d2 = pts - prev, nxt - pts
        turn = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
        for k in np.flatnonzero(turn < 0):  # a right turn with free space on the left
            n1 = np.array([-d1[k, 1], d1[k, 0]]) / np.hypot(*d1[k])
            n2 = np.array([-d2[k, 1], d2[k, 0]]) / np.hypot(*d2[k])
            u = n1 + n2
            u /= np.hypot(*u)
            nodes.append(pts[k] + u * margin / max(float(u @ n1), 0.2))
    if not nodes:
        return np.empty((0, 2))
    nodes_arr = np.array(nodes)
    keep = shapely.contains_xy(area, nodes_arr[:, 0], nodes_arr[:, 1])
    return nodes_arr[keep]


@dataclass(frozen=True, eq=False)
class Navigation:
    """Shortest paths inside ``area`` (a polygon, maybe with holes)."""

    area: Polygon
    margin: float = MARGIN

    @cached_property
    def nodes(self) -> np.ndarray:
        """The bends of shortest paths, shape ``(V, 2)``."""
        return _corners(self.area, self.margin)

    @cached_property
    def _prepared(self) -> Polygon:
        shapely.prepare(self.area)
        return self.area

    def visible(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Whether each straight leg ``a[i] -> b[i]`` stays in the area (edges included)."""
        a, b = np.atleast_2d(a), np.atleast_2d(b)
        legs = shapely.linestrings(np.stack([a, b], axis=1))
        return np.asarray(shapely.covers(self._prepared, legs))

    def _graph(self, extra: np.ndarray) -> tuple[np.ndarray, csr_matrix]:
        """The visibility graph of the nodes and ``extra`` points (listed last)."""
        pts = np.vstack([self.nodes, extra])
        i, j = np.triu_indices(len(pts), k=1)
        seen = self.visible(pts[i], pts[j])
        i, j = i[seen], j[seen]
        w = np.hypot(*(pts[i] - pts[j]).T)
        n = len(pts)
        return pts, csr_matrix((np.r_[w, w], (np.r_[i, j], np.r_[j, i])), shape=(n, n))

    def path(self, a: tuple[float, float], b: tuple[float, float]) -> np.ndarray:
        """The shortest flight from ``a`` to ``b`` inside the area: its points after ``a``,
        ending with ``b``, shape ``(k, 2)``."""
        a_, b_ = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        if self.visible(a_, b_)[0]:
            return b_[None, :]
        pts, graph = self._graph(np.vstack([a_, b_]))
        start, end = len(pts) - 2, len(pts) - 1
        _, pred = dijkstra(graph, indices=start, return_predecessors=True)
        if pred[end] < 0:
            raise ValueError(f"no flight inside the area from {tuple(a)} to {tuple(b)}")
        chain = [end]
        while chain[-1] != start:
            chain.append(int(pred[chain[-1]]))
        return pts[chain[-2::-1]]

    def route(self, start: tuple[float, float], waypoints: np.ndarray) -> np.ndarray:
        """``waypoints`` flown from ``start`` with every leg bent around the holes."""
        legs, here = [], np.asarray(start, dtype=float)
        for point in np.asarray(waypoints, dtype=float):
            legs.append(self.path(tuple(here), tuple(point)))
            here = point
        return np.vstack(legs) if legs else np.empty((0, 2))

    def home(self, bs: tuple[float, float]) -> tuple[np.ndarray, float]:
        """For the kernel: each node with its distance home and its straight distance to every
        node it sees (infinite if it sees it not), ``(V, 3 + V)`` rows ``x, y, d, d_0 ..
        d_V-1``, and an upper bound on the flight home from anywhere in the area, m.

        The bound: the distance home of a point on an edge ``ab`` is at most the shorter of
        the flights through ``a`` and through ``b``, so at most ``(d_a + d_b + |ab|) / 2``;
        and no point inside the area is farther home than every boundary point (from there
        one can fly on, away from the BS, along the last leg). The drones fly by the nodes,
        a little off the corners, so the bound gets 1 % and 20 m of slack.
        """
        bs_ = np.asarray(bs, dtype=float)
        v = len(self.nodes)
        pts, graph = self._graph(bs_[None, :])  # the nodes and the BS (index v) only: the
        dist = dijkstra(graph, indices=v)       # kernel flies by the nodes, never a vertex
        seen = graph[:v, :v].toarray()
        seen[seen == 0] = np.inf  # no edge: out of sight (a node's distance to itself is 0)
        np.fill_diagonal(seen, 0.0)
        nodes = np.column_stack([self.nodes, dist[:v], seen])
        rings = [np.asarray(r.coords)[:-1] for r in [self.area.exterior, *self.area.interiors]]
        vertices = np.vstack(rings)
        a = np.repeat(vertices, len(pts), axis=0)  # each vertex to each node and the BS
        b = np.tile(pts, (len(vertices), 1))
        legs = np.where(self.visible(a, b), np.hypot(*(a - b).T), np.inf)
        at_vertex = (legs.reshape(len(vertices), len(pts)) + dist[None, :]).min(axis=1)
        bound, start = 0.0, 0
        for ring in rings:
            d = at_vertex[start:start + len(ring)]
            side = np.hypot(*(np.roll(ring, -1, axis=0) - ring).T)
            bound = max(bound, float(((d + np.roll(d, -1) + side) / 2).max()))
            start += len(ring)
        return nodes, 1.01 * bound + 20.0  # inf if a vertex saw nothing
