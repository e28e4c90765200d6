"""Exact bounds on the fewest relays that hold terminals together at range r_c.

The problem (the fewest Steiner points such that a tree over them and the terminals has every
edge at most r_c) is bounded on a partition of the terminals' convex hull into cells, refined
until the lower and upper bounds meet or settle the question asked.

Only the branch points need cells. In a tree with the fewest points, a point of degree one
can go; those of degree two lie on chains between two nodes u, w that are terminals or points
of degree three or more (branch points, at most n - 2 of them), and a chain of j points spans
at most (j + 1) r_c, so j >= ceil(|uw| / r_c) - 1, which j points evenly spaced on the segment
uw achieve. So the optimum is the cheapest tree over the terminals and branch points of
degree three or more, an edge uw costing ceil(|uw| / r_c) - 1 and a branch point 1; and the
branch points may be taken inside the terminals' convex hull (projecting every point onto
it lengthens no edge and moves no terminal).

Lower bound: a branch point in a cell charges each of its edges the chain count at the least
distance from the cell (to a terminal, to another cell), which no point of the cell beats;
two branch points may share a cell. So the cheapest such tree over terminals and cells
(:func:`cheapest_tree`) is at most the optimum, for any partition. Upper bound: the same
kind of tree with branch points at cells' centres is a placement (:func:`placement`, chains
evenly spaced), so it is feasible; the tests check each with a breadth-first search. A cell
whose cheapest tree through it costs the goal or more is dropped, with its parts; the cells
that hold the lower bound down are split in four. A deterministic cap on the cells (never a
clock) ends a search whose bounds have not met, and the caller sees the gap.

The cheapest tree is found exactly by the Dreyfus-Wagner dynamic programme over subsets of
the terminals (milliseconds), checked in the tests against an OR-Tools CP-SAT model of the
same graph problem (:func:`tree_cp_sat`, seconds even on a handful of cells, which is why it
is not the solver).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from ortools.sat.python import cp_model
from shapely.geometry import MultiPoint, box

from sarlink.engine.relays.placement import TOL


def chain(length: float, rc: float) -> int:
    """Relays on a straight link of ``length`` m so that each hop is at most ``rc`` (within
    :data:`sarlink.engine.relays.placement.TOL`)."""
    return max(0, math.ceil((length - TOL) / rc) - 1)


def near(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The least distances between rectangles ``(x0, y0, x1, y1)`` (rows; a point has
    x0 = x1, y0 = y1), broadcast."""
    gx = np.maximum(0.0, np.maximum(b[..., 0] - a[..., 2], a[..., 0] - b[..., 2]))
    gy = np.maximum(0.0, np.maximum(b[..., 1] - a[..., 3], a[..., 1] - b[..., 3]))
    return np.hypot(gx, gy)


def centres(shapes: np.ndarray) -> np.ndarray:
    """Each rectangle's centre, as a rectangle."""
    x = (shapes[:, 0] + shapes[:, 2]) / 2
    y = (shapes[:, 1] + shapes[:, 3]) / 2
    return np.column_stack([x, y, x, y])


def costs(shapes: np.ndarray, rc: float) -> np.ndarray:
    """Each pair's chain count at the least distance between the two shapes."""
    d = near(shapes[:, None, :], shapes[None, :, :])
    return np.maximum(0, np.ceil((d - TOL) / rc) - 1).astype(np.int64)


@njit(cache=False)
def _dreyfus_wagner(w: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The cheapest trees in which every node that is not a terminal has degree three or
    more, an edge uv costing ``w[u, v]`` and each node ``>= n`` (a cell) 1: ``best[S, v]`` for
    the terminals in S (bit t: terminal t) and a node v, the root; and how each was made:
    ``split[S, v]`` the submask whose trees meet at v (0: none), ``via[S, v]`` the node u
    whose tree of two or more branches has an edge to v (-1: none). A cell may recur (two
    branch points in one cell), a terminal may not: trees meet at a terminal v only if v is
    in one of them (it is itself there), an edge leaves a terminal u only from a tree that
    holds u, and enters a terminal v only from a tree that does not."""
    m = w.shape[0]
    full = (1 << n) - 1
    d = w.copy()  # an edge into v costs v's weight too
    for v in range(n, m):
        for u in range(m):
            if u != v:
                d[u, v] += 1
    best = np.full((full + 1, m), 1 << 40, dtype=np.int64)
    split = np.zeros((full + 1, m), dtype=np.int64)
    via = np.full((full + 1, m), -1, dtype=np.int64)
    for t in range(n):
        best[1 << t] = d[t]
    for s in range(1, full + 1):
        if s & (s - 1) == 0:
            continue
        for v in range(m):
            own = 1 if v >= n else 0
            sub = (s - 1) & s
            while sub > 0:
                if sub < (s ^ sub) and (v >= n or (sub >> v) & 1 != ((s ^ sub) >> v) & 1):
                    c = best[sub, v] + best[s ^ sub, v] - own
                    if c < best[s, v]:
                        best[s, v] = c
                        split[s, v] = sub
                sub = (sub - 1) & s
        merged = best[s].copy()
        for u in range(n):
            if not (s >> u) & 1:
                merged[u] = 1 << 40
        for v in range(m):
            if v < n and (s >> v) & 1:
                continue
            for u in range(m):
                c = merged[u] + d[u, v]
                if c < best[s, v]:
                    best[s, v] = c
                    via[s, v] = u
    return best, split, via


def _tree(split: np.ndarray, via: np.ndarray, n: int) -> tuple[list[int], list[tuple[int, int]]]:
    """The programme's tree for all terminals at the root (node 0): the label of each of its
    nodes (a terminal or a cell, which may recur) and its edges between node numbers."""
    labels = [0]
    edges: list[tuple[int, int]] = []

    def child(of: int, label: int) -> int:
        labels.append(label)
        edges.append((of, len(labels) - 1))
        return len(labels) - 1

    stack = [((1 << n) - 1, 0)]  # (subset, node): the subset's tree hangs at the node
    while stack:
        s, node = stack.pop()
        v = labels[node]
        if s & (s - 1) == 0:  # one terminal: the node itself, or an edge to it
            if s.bit_length() - 1 != v:
                child(node, s.bit_length() - 1)
            continue
        if via[s, v] >= 0:
            node = child(node, int(via[s, v]))
            v = labels[node]
        sub = int(split[s, v])
        stack += [(sub, node), (s ^ sub, node)]
    return labels, edges


def cheapest_tree(shapes: np.ndarray, n: int, rc: float
                  ) -> tuple[int, list[int], list[tuple[int, int]], np.ndarray]:
    """The cheapest tree over the terminals ``shapes[:n]`` (points) and branch points in the
    cells (the rest), an edge costing its chain count at the least distance and a branch point
    1, every branch point of degree three or more (Dreyfus-Wagner, exact): its cost, its
    nodes' labels and its edges, and for each shape the cost of the cheapest such tree that
    has a node there (the tree re-rooted there)."""
    best, split, via = _dreyfus_wagner(costs(shapes, rc), n)
    full = (1 << n) - 1
    return int(best[full, 0]), *_tree(split, via, n), best[full]


def tree_cp_sat(shapes: np.ndarray, n: int, rc: float) -> int:
    """The cost of :func:`cheapest_tree` by an OR-Tools CP-SAT model, to check the programme:
    up to n - 2 copies of each cell (branch points that share a cell), an arborescence from
    node 0 in which each terminal is entered once, each used copy once and has three or more
    arcs, and whose arcs carry a single-commodity flow of one unit to each terminal. One
    worker and a fixed seed, no time limit: the answer is proven optimal."""
    w = costs(shapes, rc)
    label = list(range(n)) + [c for c in range(n, len(shapes)) for _ in range(n - 2)]
    m = len(label)
    model = cp_model.CpModel()
    arcs = {(a, b): model.NewBoolVar("") for a in range(m) for b in range(1, m) if a != b}
    flow = {ab: model.NewIntVar(0, n - 1, "") for ab in arcs}
    used = [model.NewBoolVar("") for _ in range(m)]
    for v in range(1, m):
        into = [arcs[a, v] for a in range(m) if a != v]
        out = [arcs[v, b] for b in range(1, m) if b != v]
        model.Add(sum(into) == (1 if v < n else used[v]))
        model.Add(sum(flow[a, v] for a in range(m) if a != v)
                  - sum(flow[v, b] for b in range(1, m) if b != v) == (1 if v < n else 0))
        if v >= n:
            model.Add(sum(out) >= 2).OnlyEnforceIf(used[v])
            model.Add(sum(out) == 0).OnlyEnforceIf(used[v].Not())
    for ab, y in arcs.items():
        model.Add(flow[ab] <= (n - 1) * y)
    model.Minimize(sum(int(w[label[a], label[b]]) * y for (a, b), y in arcs.items())
                   + sum(used[n:]))
    solver = cp_model.CpSolver()
    solver.parameters.num_search_workers = 1
    solver.parameters.random_seed = 0
    status = solver.Solve(model)
    assert status == cp_model.OPTIMAL, solver.StatusName(status)
    return round(solver.ObjectiveValue())


def placement(at: np.ndarray, n: int, rc: float, labels: list[int],
              edges: list[tuple[int, int]]) -> np.ndarray:
    """The relays of a tree over terminals and branch points at the points ``at[:, :2]``
    (``labels`` its nodes', ``edges`` between node numbers): one at each branch point and each
    edge's chain evenly spaced between its ends, ``(k, 2)``."""
    out = [at[v, :2] for v in labels if v >= n]
    for a, b in edges:
        p, q = at[labels[a], :2], at[labels[b], :2]
        j = chain(float(np.hypot(*(q - p))), rc)
        out += [p + (q - p) * i / (j + 1) for i in range(1, j + 1)]
    return np.array(out, dtype=float).reshape(-1, 2)


@dataclass
class Bounds:
    lower: int
    upper: int
    relays: np.ndarray
    """A placement of ``upper`` relays (``(upper, 2)``) that holds the terminals together."""
    rounds: int
    """Refinement rounds taken."""
    cells: int
    """Cells in the last partition."""


def fewest_relays(terminals: np.ndarray, rc: float, heuristic: np.ndarray,
                  enough: int | None = None, first: float = 0.5, most: int = 1500) -> Bounds:
    """Lower and upper bounds on the fewest relays holding ``terminals`` (``(n, 2)``, the
    root first) together at range ``rc``, given a placement ``heuristic`` (``(h, 2)``, the MST
    heuristic's). Refines until the bounds meet, or (with ``enough``) until they settle whether
    the optimum is at least ``enough``, or the next partition would have more than ``most``
    cells; the first cells are ``first * rc`` wide."""
    n = len(terminals)
    points = np.column_stack([terminals, terminals]).astype(float)
    hull = MultiPoint([tuple(p) for p in terminals]).convex_hull
    lo_x, lo_y, hi_x, hi_y = hull.bounds
    side = first * rc
    cells = []
    if hull.area > 0:  # else branch points can all be taken onto the terminals' line
        for i in range(max(1, math.ceil((hi_x - lo_x) / side))):
            for j in range(max(1, math.ceil((hi_y - lo_y) / side))):
                c = (lo_x + i * side, lo_y + j * side, min(hi_x, lo_x + (i + 1) * side),
                     min(hi_y, lo_y + (j + 1) * side))
                if box(*c).intersects(hull):
                    cells.append(c)
    best, relays = len(heuristic), heuristic
    k = 0
    while True:
        shapes = np.vstack([points, np.array(cells).reshape(-1, 4)])
        at = centres(shapes)
        lower, labels, edges, through = cheapest_tree(shapes, n, rc)
        for tree in ((labels, edges), cheapest_tree(at, n, rc)[1:3]):
            got = placement(at, n, rc, *tree)
            if len(got) < best:
                best, relays = len(got), got
        goal = best if enough is None else min(best, enough)
        grow = 3 * int((through[n:] <= lower).sum())
        if lower >= goal or best < goal or len(cells) + grow > most:
            return Bounds(min(lower, best), best, relays, k, len(cells))
        split, refined = [], False
        for i, c in enumerate(cells):
            if through[n + i] >= goal:  # in no tree cheaper than the goal: nor its parts
                continue
            if through[n + i] > lower:  # not what holds the lower bound down: not yet
                split.append(c)
                continue
            refined = True
            mx, my = (c[0] + c[2]) / 2, (c[1] + c[3]) / 2
            split += [(c[0], c[1], mx, my), (mx, c[1], c[2], my), (c[0], my, mx, c[3]),
                      (mx, my, c[2], c[3])]
        assert refined, "a lower bound below the goal has a cell at it"
        cells = [c for c in split if box(*c).intersects(hull)]
        k += 1
