"""Where relays stand (engine/relays/placement.py): the tree against scipy, the priorities
against the slow reference, the assignment against brute force and OR-Tools, the counts
against exact bounds on the fewest relays (tests/steiner_bounds.py), and the points against
the area."""

from __future__ import annotations

import itertools
import math
from collections import deque

import numpy as np
import pytest
import shapely
from hypothesis import given
from hypothesis import strategies as st
from ortools.sat.python import cp_model
from scipy.sparse.csgraph import minimum_spanning_tree
from scipy.spatial.distance import cdist

import steiner_bounds
from naive import relay_plan
from polygons import areas
from sarlink import Mission
from sarlink.config.region import area_polygon
from sarlink.engine.area import contains, edge_array
from sarlink.engine.codes import PRIORITY_CODES
from sarlink.engine.relays.placement import (
    NUDGE,
    TOL,
    allocate,
    assign,
    chain,
    edge_needs,
    into_area,
    plan,
    points,
    spanning_tree,
    tree,
)

SQUARE = np.empty((0, 4))
"""No polygon: the square area, here so large that nothing is moved into it."""
SIDE = 1e7


def _random(seed: int, n: int, side: float = 3000.0) -> np.ndarray:
    return np.random.default_rng(seed).uniform(0.0, side, size=(n, 2))


def _tree(t: np.ndarray, rc: float) -> tuple[np.ndarray, ...]:
    x, y = t[:, 0].copy(), t[:, 1].copy()
    parent, order = spanning_tree(x, y, 0)
    length, need = edge_needs(x, y, parent, rc)
    return x, y, parent, order, length, need


def _held(fixed: np.ndarray, relays: np.ndarray, rc: float) -> set[int]:
    """The nodes of ``fixed`` linked to node 0 over links of at most ``rc`` (with the
    module's slack) through ``relays``: a plain breadth-first search on the disc graph."""
    nodes = np.vstack([fixed, relays.reshape(-1, 2)])
    d = cdist(nodes, nodes)
    seen, queue = {0}, deque([0])
    while queue:
        a = queue.popleft()
        for b in np.flatnonzero(d[a] <= rc + TOL):
            if int(b) not in seen:
                seen.add(int(b))
                queue.append(int(b))
    return {i for i in seen if i < len(fixed)}


@given(st.lists(st.tuples(st.floats(0, 5000), st.floats(0, 5000)), min_size=2, max_size=31))
def test_the_tree_is_a_minimum_spanning_tree(pts: list[tuple[float, float]]) -> None:
    """Prim's tree has scipy's total length (a different algorithm, Kruskal's)."""
    t = np.array(pts)
    parent, order = spanning_tree(t[:, 0].copy(), t[:, 1].copy(), 0)
    assert order[0] == 0 and sorted(order) == list(range(len(t)))
    assert all(parent[v] in order[:k] for k, v in enumerate(order) if k)  # parents first
    d = cdist(t, t)
    total = sum(d[v, parent[v]] for v in range(1, len(t)))
    shifted = d + 1.0 - np.eye(len(t))  # scipy reads (near) zeros as no edge; every tree
    expected = minimum_spanning_tree(shifted).sum() - (len(t) - 1)  # has n - 1 edges
    assert total == pytest.approx(expected, rel=1e-12, abs=1e-9)


@given(st.integers(1, 6), st.floats(50, 2000))
def test_an_edge_of_a_whole_number_of_ranges_needs_one_relay_fewer(k: int, rc: float) -> None:
    """An edge of exactly k r_c needs k - 1 relays; a millimetre more, k."""
    assert chain(k * rc, rc) == k - 1
    assert chain(k * rc + 1e-3, rc) == k
    assert chain(k * rc + TOL / 2, rc) == k - 1
    assert chain(0.0, rc) == 0


@given(st.integers(0, 2**32 - 1), st.integers(2, 31), st.floats(100, 1500),
       st.integers(0, 8))
def test_as_many_relays_as_the_tree_needs_hold_every_searcher(seed: int, n: int, rc: float,
                                                              spare: int) -> None:
    """The invariant: relays standing at the points (as many as the spanning tree needs, or
    more) link every searcher to the BS, branch points and all; the branched tree needs no
    more relays than the spanning tree; the spare relays hold where they are."""
    t = _random(seed, n)
    *_, need = _tree(t, rc)
    r = _random(seed + 1, int(need.sum()) + spare)
    gx, gy, serves, held, needed = plan(t[:, 0].copy(), t[:, 1].copy(), 0, rc, r[:, 0].copy(),
                                        r[:, 1].copy(), 0, SIDE, SQUARE)
    assert needed <= need.sum() and held.all() and len(held) == n
    assert _held(t, np.column_stack([gx, gy]), rc) == set(range(n))
    assert (serves < 0).sum() == len(r) - needed
    assert np.array_equal(gx[serves < 0], r[serves < 0, 0])  # spare relays hold


@pytest.mark.parametrize("priority", sorted(PRIORITY_CODES))
@given(st.integers(0, 2**32 - 1), st.integers(2, 12), st.data())
def test_the_root_may_be_any_terminal(priority: str, seed: int, n: int,
                                      data: st.DataObject) -> None:
    """The BS moved to index ``root`` (and the searchers shifted to make room) gives the same
    goals, the same terminals served and held (renumbered), and the same count."""
    t = _random(seed, n)
    k = data.draw(st.integers(0, 6))
    root = data.draw(st.integers(0, n - 1))
    moved = np.roll(t, root, axis=0)  # terminal i is now at (i + root) % n
    r = _random(seed + 1, k)
    code = int(PRIORITY_CODES[priority])
    a = plan(t[:, 0].copy(), t[:, 1].copy(), 0, 400.0, r[:, 0].copy(), r[:, 1].copy(), code,
             SIDE, SQUARE)
    b = plan(moved[:, 0].copy(), moved[:, 1].copy(), root, 400.0, r[:, 0].copy(),
             r[:, 1].copy(), code, SIDE, SQUARE)
    assert np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1]) and a[4] == b[4]
    renumbered = np.where((a[2] >= 0) & (a[2] < n), (a[2] + root) % n, a[2])  # branch
    assert np.array_equal(renumbered, b[2])  # points keep their numbers n, n + 1, ...
    assert np.array_equal(np.roll(a[3], root), b[3])


@pytest.mark.parametrize("priority", sorted(PRIORITY_CODES))
@given(st.integers(0, 2**32 - 1), st.integers(2, 9), st.floats(200, 1000), st.data())
def test_fewer_relays_connect_what_the_priority_says(priority: str, seed: int, n: int,
                                                     rc: float, data: st.DataObject) -> None:
    """Against the slow reference: nearest-first holds exactly its searchers for exactly its
    relays, most-connected as many terminals for as few relays as any choice of paths,
    k-bottleneck the shortest longest hop; and what a plan says it holds, its relays hold.
    With branch points, the plan holds everyone when the relays suffice for the branched tree,
    and is the spanning tree's plan when they do not."""
    t = _random(seed, n)
    x, y, parent, order, length, need = _tree(t, rc)
    k = data.draw(st.integers(0, int(need.sum())))
    code = int(PRIORITY_CODES[priority])
    alloc = allocate(x, y, 0, parent, order, length, need, k, code)
    ref = relay_plan([tuple(p) for p in t], rc, k, priority)
    assert dict(enumerate(need[1:], 1)) == ref.needs
    assert alloc.sum() <= k and (alloc <= need).all()
    r = _random(seed + 1, k)
    spanning = plan(x, y, 0, rc, r[:, 0].copy(), r[:, 1].copy(), code, SIDE, SQUARE, False)
    branched = plan(x, y, 0, rc, r[:, 0].copy(), r[:, 1].copy(), code, SIDE, SQUARE)
    for gx, gy, serves, held, _ in (spanning, branched):
        assert set(np.flatnonzero(held)) <= _held(t, np.column_stack([gx, gy])[serves >= 0], rc)
    if k >= branched[4]:
        assert branched[3].all()
    else:
        assert all(np.array_equal(a, b) for a, b in zip(spanning[:4], branched[:4], strict=True))
    claimed = set(np.flatnonzero(spanning[3]).tolist())
    if priority == "nearest-first":
        assert claimed == ref.connected and alloc.sum() == ref.spent
    elif priority == "most-connected":
        assert len(claimed) == len(ref.connected) and alloc.sum() == ref.spent
    else:
        hop = max(length[v] / (alloc[v] + 1) for v in range(1, n))
        assert alloc.sum() == k and hop == pytest.approx(ref.longest_hop, rel=1e-12)


def _flight(px: np.ndarray, rx: np.ndarray) -> np.ndarray:
    """Each point's distance to each relay, in the module's arithmetic."""
    return np.array([[math.sqrt((p[0] - r[0]) * (p[0] - r[0]) + (p[1] - r[1]) * (p[1] - r[1]))
                      for r in rx] for p in px])


def _lexicographic(rx: np.ndarray, px: np.ndarray) -> tuple[float, float]:
    """The least (longest flight, total flight) over every assignment, by brute force."""
    d = _flight(px, rx)
    return min((max(d[i, j] for i, j in enumerate(p)), sum(d[i, j] for i, j in enumerate(p)))
               for p in itertools.permutations(range(len(rx)), len(px)))


def _flights(rx: np.ndarray, px: np.ndarray, goal: np.ndarray) -> tuple[float, float]:
    d = _flight(px, rx)
    out = [d[goal[j], j] for j in range(len(rx)) if goal[j] >= 0]
    return max(out, default=0.0), sum(out)


@given(st.integers(0, 2**32 - 1), st.integers(0, 7), st.data())
def test_the_assignment_is_the_brute_force_best(seed: int, k: int, data: st.DataObject) -> None:
    """Each point its own relay, the longest flight shortest and then the total: the same
    values as trying every assignment (ties in distance included: a coarse grid)."""
    p = data.draw(st.integers(0, k))
    rng = np.random.default_rng(seed)
    grid = data.draw(st.booleans())
    rx = rng.integers(0, 4, (k, 2)) * 100.0 if grid else rng.uniform(0, 1000, (k, 2))
    px = rng.integers(0, 4, (p, 2)) * 100.0 if grid else rng.uniform(0, 1000, (p, 2))
    goal, longest = assign(rx[:, 0].copy(), rx[:, 1].copy(), px[:, 0].copy(), px[:, 1].copy())
    assert sorted(goal[goal >= 0]) == list(range(p))
    worst, total = _flights(rx, px, goal)
    assert worst == longest
    if p:
        best = _lexicographic(rx, px)
        assert worst == best[0] and total == pytest.approx(best[1], rel=1e-12)


@pytest.mark.parametrize("seed", range(6))
def test_the_assignment_matches_cp_sat_on_larger_teams(seed: int) -> None:
    """Against OR-Tools CP-SAT minimising the longest flight (as the rank of its distance, so
    exactly), then the total in millimetres with the longest held: equal longest flight, and
    a total no more than CP-SAT's (up to its rounding)."""
    rng = np.random.default_rng(seed)
    k = int(rng.integers(8, 21))
    p = int(rng.integers(1, k + 1))
    rx, px = rng.uniform(0, 3000, (k, 2)), rng.uniform(0, 3000, (p, 2))
    goal, longest = assign(rx[:, 0].copy(), rx[:, 1].copy(), px[:, 0].copy(), px[:, 1].copy())
    d = _flight(px, rx)
    levels = np.unique(d)
    model = cp_model.CpModel()
    x = {(i, j): model.NewBoolVar("") for i in range(p) for j in range(k)}
    for i in range(p):
        model.AddExactlyOne(x[i, j] for j in range(k))
    for j in range(k):
        model.AddAtMostOne(x[i, j] for i in range(p))
    worst = model.NewIntVar(0, len(levels) - 1, "")
    for (i, j), v in x.items():
        model.Add(worst >= int(np.searchsorted(levels, d[i, j]))).OnlyEnforceIf(v)
    model.Minimize(worst)
    solver = cp_model.CpSolver()
    solver.parameters.num_search_workers = 1
    solver.parameters.random_seed = 0
    assert solver.Solve(model) == cp_model.OPTIMAL
    assert longest == levels[solver.Value(worst)]
    model.Add(worst == solver.Value(worst))
    model.Minimize(sum(round(d[i, j] * 1000) * v for (i, j), v in x.items()))
    assert solver.Solve(model) == cp_model.OPTIMAL
    assert _flights(rx, px, goal)[1] <= solver.ObjectiveValue() / 1000 + p * 5e-4


@given(areas(), st.integers(0, 2**32 - 1), st.integers(2, 12), st.floats(150, 800),
       st.sampled_from(sorted(PRIORITY_CODES)))
def test_no_relay_point_is_outside_the_area_or_in_a_hole(mission: Mission, seed: int, n: int,
                                                         rc: float, priority: str) -> None:
    """Searchers anywhere in a polygon with holes: every goal is inside (the kernel's test
    and shapely's), and a point that had to move went to the nearest point inside (to within
    the nudge past the boundary). The relays start inside too: a spare one holds where it is."""
    area = area_polygon(mission.region, mission.area.size)
    edges = edge_array([np.asarray(area.exterior.coords)]
                       + [np.asarray(h.coords) for h in area.interiors])
    rng = np.random.default_rng(seed)
    lo_x, lo_y, hi_x, hi_y = area.bounds

    def inside(k: int) -> list[tuple[float, float]]:
        out: list[tuple[float, float]] = []
        while len(out) < k:
            p = rng.uniform((lo_x, lo_y), (hi_x, hi_y))
            if area.contains(shapely.Point(p)):
                out.append((float(p[0]), float(p[1])))
        return out

    tt = np.array([mission.area.bs_xy, *inside(n - 1)])
    x, y, parent, order, length, need = _tree(tt, rc)
    alloc = allocate(x, y, 0, parent, order, length, need, int(need.sum()),
                     int(PRIORITY_CODES[priority]))
    on_tree = [(x[parent[v]] + (x[v] - x[parent[v]]) * j / (alloc[v] + 1),
                y[parent[v]] + (y[v] - y[parent[v]]) * j / (alloc[v] + 1))
               for v in order[1:] for j in range(1, alloc[v] + 1)]
    px, py, _ = points(x, y, parent, order, alloc, mission.area.size, edges, n)
    for (a, b), qx, qy in zip(on_tree, px, py, strict=True):
        assert contains(qx, qy, edges) and area.covers(shapely.Point(qx, qy))
        assert math.hypot(qx - a, qy - b) <= area.distance(shapely.Point(a, b)) + NUDGE + 1e-6
    r = np.array(inside(int(need.sum()))).reshape(-1, 2)  # the branched tree may leave some
    gx, gy, *_ = plan(x, y, 0, rc, r[:, 0].copy(), r[:, 1].copy(),
                      int(PRIORITY_CODES[priority]), mission.area.size, edges)
    assert all(contains(a, b, edges) for a, b in zip(gx, gy, strict=True))


@given(st.floats(-500, 1500), st.floats(-500, 1500))
def test_the_square_clamps(x: float, y: float) -> None:
    assert into_area(x, y, 1000.0, SQUARE) == (min(max(x, 0), 1000), min(max(y, 0), 1000))


@pytest.mark.parametrize("seed", range(8))
def test_the_exact_programme_agrees_with_cp_sat(seed: int) -> None:
    """The cheapest tree over terminals and cells (tests/steiner_bounds.py), by the
    Dreyfus-Wagner programme and by an OR-Tools CP-SAT model of the same graph problem."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(3, 6))
    t = rng.uniform(0, 2000, (n, 2))
    lo = rng.uniform(0, 1800, (5 - n // 2, 2))
    cells = np.column_stack([lo, lo + rng.uniform(50, 400, lo.shape)])
    shapes = np.vstack([np.column_stack([t, t]), cells])
    rc = float(rng.uniform(250, 600))
    assert steiner_bounds.cheapest_tree(shapes, n, rc)[0] == steiner_bounds.tree_cp_sat(
        shapes, n, rc)


@given(st.floats(100, 1500), st.floats(1.0 + 1e-6, math.sqrt(3) - 1e-6), st.floats(0, 2 * math.pi),
       st.integers(0, 2))
def test_a_branch_point_holds_a_wide_triangle_with_one_relay(rc: float, side: float,
                                                             turn: float, root: int) -> None:
    """Three terminals at the corners of an equilateral triangle of side s, r_c < s <= sqrt(3)
    r_c: each spanning-tree edge needs a relay (two in all), one relay at the centre, s / sqrt(3)
    from each, holds all three; with one relay the branched plan holds them, with the
    spanning tree alone it could not."""
    a = turn + np.array([0.0, 2 * math.pi / 3, 4 * math.pi / 3])
    t = 5000.0 + side * rc / math.sqrt(3) * np.column_stack([np.cos(a), np.sin(a)])
    x, y = t[:, 0].copy(), t[:, 1].copy()
    assert int(tree(x, y, root, rc, False)[5].sum()) == 2
    assert int(tree(x, y, root, rc, True)[5].sum()) == 1
    gx, gy, serves, held, needed = plan(x, y, root, rc, np.zeros(1), np.zeros(1), 0, SIDE, SQUARE)
    assert needed == 1 and held.all() and serves[0] == 3
    assert _held(t, np.column_stack([gx, gy]), rc) == {0, 1, 2}
    assert not plan(x, y, root, rc, np.zeros(1), np.zeros(1), 0, SIDE, SQUARE, False)[3].all()


def test_the_count_against_the_fewest_relays() -> None:
    """On 200 random instances (the BS and 1 to 7 searchers in a 3 km square, r_c 300 to
    1000 m): the spanning tree's count (against scipy's) and the branched tree's count h, no
    more, against exact bounds on the fewest relays (refined until they settle whether the
    optimum is at least h - 1). Every upper bound is a placement that holds (checked by a
    breadth-first search), so a gap of two or more it shows is real; the ratio h <= 4 OPT
    (Mandoiu and Zelikovsky's, for the spanning tree's count) holds on every instance. Within
    one of the optimum is proven on 195 (97.5 %; the issue asks 95 %), more than one on 1
    (the gaps: benchmarks/results/relays.md). The spanning tree alone: 178 and 12."""
    rng = np.random.default_rng(2024)
    within = beyond = 0
    for _ in range(200):
        n = int(rng.integers(2, 9))
        t = rng.uniform(0, 3000, (n, 2))
        rc = float(rng.uniform(300, 1000))
        x, y = t[:, 0].copy(), t[:, 1].copy()
        mst = minimum_spanning_tree(cdist(t, t)).tocoo()
        assert int(tree(x, y, 0, rc, False)[5].sum()) == sum(chain(d, rc) for d in mst.data)
        bx, by, parent, order, _, need = tree(x, y, 0, rc, True)
        h = int(need.sum())
        assert h <= sum(chain(d, rc) for d in mst.data)
        px, py, _ = points(bx, by, parent, order, need, SIDE, SQUARE, n)
        found = steiner_bounds.fewest_relays(t, rc, np.column_stack([px, py]),
                                             enough=max(h - 1, 0))
        assert len(found.relays) == found.upper and found.lower <= found.upper <= h
        assert _held(t, found.relays, rc) == set(range(n))
        if h and 4 * max(found.lower, 1) < h:
            found = steiner_bounds.fewest_relays(t, rc, found.relays, enough=math.ceil(h / 4))
        assert h <= 4 * max(found.lower, 1)
        within += found.lower >= h - 1
        beyond += found.upper <= h - 2
    assert within >= 195 and beyond <= 1, (within, beyond)
