"""The graph phase (sarlink.engine.graph) called directly: links against a brute-force distance
matrix, the BS's component, flooding and reachability against plain breadth-first searches,
and the bitset helpers against Python sets and integers.

Node indices: drones ``0 .. n-1``, the BS ``n``, the target ``n + 1``. Graphs span one to two
bitset words (up to 70 drones), so that the word boundary is crossed.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from phase_inputs import component, members, node_arrays, pack, padded, words
from sarlink.engine.codes import Mode, Parked, Reachability
from sarlink.engine.graph import (
    add,
    bit,
    bs_component,
    covers,
    drop,
    first_nodes,
    flood,
    has,
    linked,
    links,
    lowest,
    push_new,
    reachability,
)

U64 = st.integers(0, 2**64 - 1)


@st.composite
def graphs(draw: st.DrawFn) -> tuple[int, list[set[int]]]:
    """``n`` drones and the neighbour sets of the ``n + 2`` nodes (symmetric, no self-link)."""
    n = draw(st.integers(1, 70))
    m = n + 2
    node = st.integers(0, m - 1)
    edges = draw(st.lists(st.tuples(node, node), max_size=3 * m))
    neighbours: list[set[int]] = [set() for _ in range(m)]
    for a, b in edges:
        if a != b:
            neighbours[a].add(b)
            neighbours[b].add(a)
    return n, neighbours


def _graph_arrays(n: int, neighbours: list[set[int]]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``adj``, an empty bitset and a stack for ``n`` drones."""
    m = n + 2
    return (pack(neighbours, words(m)), np.zeros(words(m), dtype=np.uint64),
            np.empty(m, dtype=np.int64))


# -- links ------------------------------------------------------------------------------------


@given(n=st.integers(1, 70), altitude=st.integers(0, 300), r=st.integers(0, 1500),
       seed=st.integers(0, 2**32 - 1), ties=st.floats(0, 1))
def test_links_are_the_brute_force_distance_matrix(n: int, altitude: int, r: int, seed: int,
                                                   ties: float) -> None:
    """``adj[a]`` holds exactly the other nodes within ``thr2[a, b]`` (squared 3-D distance,
    drones at the altitude, the BS and target on the ground), ``near[a]`` those within ``r``;
    no node links to itself, none to the padding. Whole-metre coordinates make every squared
    distance exact, and a share ``ties`` of the thresholds sits exactly at the distance (linked)
    or one below it (not linked): ``<=`` is tested at the edge."""
    rng = np.random.default_rng(seed)
    m = n + 2
    xy = [(float(x), float(y)) for x, y in rng.integers(0, 4001, size=(m, 2))]
    px, py, pz = node_arrays(xy, n, float(altitude))
    height = [altitude if j < n else 0 for j in range(m)]

    def d2(a: int, b: int) -> int:
        return (int(xy[a][0] - xy[b][0]) ** 2 + int(xy[a][1] - xy[b][1]) ** 2
                + (height[a] - height[b]) ** 2)

    thr2 = np.zeros((m, padded(m)))
    thr2[:, :m] = rng.integers(0, 3000, size=(m, m)).astype(float) ** 2  # the diagonal too
    for a, b in zip(*np.nonzero(rng.random((m, m)) < ties), strict=True):
        thr2[a, b] = d2(a, b) - rng.integers(0, 2)
    adj = np.full((m, words(m)), 12345, dtype=np.uint64)
    near = adj.copy()
    links(px, py, pz, thr2, adj, float(r * r), near, True)
    for a in range(m):
        assert members(adj[a]) == {b for b in range(m) if b != a and d2(a, b) <= thr2[a, b]}
        assert members(near[a]) == {b for b in range(m) if b != a and d2(a, b) <= r * r}
        assert all(linked(adj, a, b) == (b in members(adj[a])) for b in range(m))
    # without the sensing pairs, ``near`` is left alone
    untouched = np.full_like(near, 777)
    links(px, py, pz, thr2, adj, float(r * r), untouched, False)
    assert (untouched == 777).all()


def test_a_link_at_exactly_the_range_exists_and_one_beyond_does_not() -> None:
    """3-4-5 triangles: drone 0 flies 300 m up, the BS is 400 m east of it and the target 400 m
    south, on the ground; both are exactly 500 m away (slant), and 566 m from each other."""
    xy = [(1000.0, 1000.0), (1400.0, 1000.0), (1000.0, 600.0)]
    px, py, pz = node_arrays(xy, 1, altitude=300.0)
    adj, near = np.zeros((3, 1), dtype=np.uint64), np.zeros((3, 1), dtype=np.uint64)
    for range2, linked_pairs in ((500.0**2, {(0, 1), (0, 2)}),
                                 (np.nextafter(500.0**2, 0.0), set())):
        thr2 = np.zeros((3, padded(3)))
        thr2[:, :3] = range2
        links(px, py, pz, thr2, adj, range2, near, True)
        for a, b in ((0, 1), (0, 2), (1, 2)):
            assert linked(adj, a, b) == linked(adj, b, a) == ((a, b) in linked_pairs)
            assert linked(near, a, b) == ((a, b) in linked_pairs)


# -- the BS's component, flooding, reachability ------------------------------------------------


@given(graphs())
def test_the_bs_component_is_a_breadth_first_search_that_the_target_never_relays(
        graph: tuple[int, list[set[int]]]) -> None:
    n, neighbours = graph
    adj, routed, stack = _graph_arrays(n, neighbours)
    routed[:] = 99  # stale bits are cleared
    bs_component(adj, n, routed, stack)
    assert members(routed) == component({n}, neighbours, blocked=n + 1)


def test_a_drone_linked_to_the_bs_only_through_the_target_has_no_route() -> None:
    n = 2  # drone 0 - target - BS; drone 1 - BS
    neighbours = [{3}, {2}, {1, 3}, {0, 2}]
    adj, routed, stack = _graph_arrays(n, neighbours)
    bs_component(adj, n, routed, stack)
    assert members(routed) == {1, 2}
    assert reachability(adj, routed, np.zeros(n, dtype=np.int8)) == (True, 1)


@given(graph=graphs(), knowers=st.lists(st.booleans(), min_size=70, max_size=70))
def test_flooding_informs_exactly_the_components_of_the_knowers(
        graph: tuple[int, list[set[int]]], knowers: list[bool]) -> None:
    """Knowledge spreads over any number of hops (the BS relays, the target does not) to the
    components of the drones that know; the result says whether the BS learnt it."""
    n, neighbours = graph
    adj, routed, stack = _graph_arrays(n, neighbours)
    bs_component(adj, n, routed, stack)
    knows = np.array(knowers[:n])
    before = set(np.flatnonzero(knows).tolist())
    expected = component(before, neighbours, blocked=n + 1)
    spread = np.full_like(routed, 5)
    told = flood(adj, routed, knows, spread, stack)
    assert members(spread) == expected
    assert set(np.flatnonzero(knows).tolist()) == expected - {n}
    assert before <= expected  # knowing is permanent
    assert told == (n in expected)


@given(graphs(), st.lists(st.booleans(), min_size=70, max_size=70))
def test_reachability_counts_routed_drones_and_a_target_linked_to_one(
        graph: tuple[int, list[set[int]]], landed: list[bool]) -> None:
    """Every reading of reachability and of parked drones: a parked drone (landed) is a relay
    like any other, or part of the BS (not connected, its target link the BS's own, which only
    ``direct`` counts)."""
    n, neighbours = graph
    adj, routed, stack = _graph_arrays(n, neighbours)
    bs_component(adj, n, routed, stack)
    routed_nodes = component({n}, neighbours, blocked=n + 1)
    mode = np.array([Mode.LANDED if x else Mode.SEARCHING for x in landed[:n]], dtype=np.int8)
    for how in Reachability:
        for parked in Parked:
            flying = {i for i in range(n) if parked == Parked.RELAY or not landed[i]}
            via = set(range(n + 1)) if how == Reachability.DIRECT else flying
            reachable, connected = reachability(adj, routed, mode, int(how), int(parked))
            assert connected == len(routed_nodes & flying)
            assert reachable == bool(neighbours[n + 1] & routed_nodes & via)


# -- bitset helpers ---------------------------------------------------------------------------


@given(st.lists(st.tuples(st.booleans(), st.integers(0, 191)), max_size=60))
def test_add_drop_and_has_behave_as_a_set(ops: list[tuple[bool, int]]) -> None:
    bits = np.zeros(3, dtype=np.uint64)
    expected: set[int] = set()
    for put, a in ops:
        if put:
            add(bits, a)
            expected.add(a)
        else:
            drop(bits, a)
            expected.discard(a)
        assert members(bits) == expected
    assert [has(bits, a) for a in range(192)] == [a in expected for a in range(192)]
    assert all(bit(bits[a >> 6], a) == (a in expected) for a in range(192))


@given(st.integers(1, 2**64 - 1))
def test_lowest_is_the_index_of_the_lowest_set_bit(word: int) -> None:
    assert lowest(np.uint64(word)) == (word & -word).bit_length() - 1


@given(word=U64, w=st.integers(0, 2), top=st.integers(0, 10))
def test_push_new_pushes_every_set_bit_in_increasing_order(word: int, w: int, top: int) -> None:
    stack = np.full(80, -1, dtype=np.int64)
    new_top = push_new(stack, top, w, np.uint64(word))
    pushed = [w * 64 + b for b in range(64) if (word >> b) & 1]
    assert new_top == top + len(pushed)
    assert stack[top:new_top].tolist() == pushed
    assert (stack[:top] == -1).all() and (stack[new_top:] == -1).all()


@given(st.sets(st.integers(0, 191)), st.sets(st.integers(0, 191)))
def test_covers_is_the_subset_test(have: set[int], goal: set[int]) -> None:
    bits, want = pack([have, goal], 3)
    assert covers(bits, want) == (goal <= have)


@given(st.integers(0, 192))
def test_first_nodes_are_the_nodes_below_m(m: int) -> None:
    bits = np.full(3, 12345, dtype=np.uint64)
    first_nodes(bits, m)
    assert members(bits) == set(range(m))
