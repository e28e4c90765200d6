"""The records phase (sarlink.engine.records) called directly: checkpoints against sums taken
step by step in Python, the jump to the horizon against the loop it replaces, when a team
has settled, and the BS's network against a hand-counted case and the slow reference's
breadth-first search (docs/model.md, Records and metrics)."""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from naive import network as naive_network
from phase_inputs import pack, words
from sarlink.engine.codes import Parked
from sarlink.engine.params import LANDED, PER_PERIOD, REPORTING, RETURNING, SEARCHING
from sarlink.engine.records import (
    carry_records,
    network,
    new_track,
    record_step,
    settled,
    take_checkpoints,
)

QUARTERS = st.integers(0, 8).map(lambda q: q / 4)  # sums of these are exact


@given(increments=st.lists(st.tuples(QUARTERS, QUARTERS), min_size=8, max_size=20),
       checkpoints=st.lists(st.integers(0, 24), min_size=1, max_size=12).map(
           lambda cp: [*cp, cp[0]]))  # one step holds two checkpoints at least
def test_checkpoints_hold_the_sums_of_the_steps_before_them(
        increments: list[tuple[float, float]], checkpoints: list[int]) -> None:
    """Taken at the start of step k, checkpoint c holds the sums over the steps before
    ``cp[c]`` (several checkpoints may share a step); those past the last step stay unset."""
    cp = np.array(sorted(checkpoints), dtype=np.int64)
    reach, conn = np.full(len(cp), np.nan), np.full(len(cp), np.nan)
    ci, acc_reach, acc_conn = 0, 0.0, 0.0
    for k, (d_reach, d_conn) in enumerate(increments):
        ci = take_checkpoints(k, cp, ci, reach, conn, acc_reach, acc_conn)
        assert ci == int((cp <= k).sum())
        acc_reach += d_reach
        acc_conn += d_conn
    for c, step in enumerate(cp.tolist()):
        if step < len(increments):
            assert reach[c] == sum(d for d, _ in increments[:step])
            assert conn[c] == sum(d for _, d in increments[:step])
        else:
            assert math.isnan(reach[c]) and math.isnan(conn[c])


@given(start=st.integers(0, 50), extra=st.integers(0, 50),
       checkpoints=st.lists(st.integers(0, 100), min_size=1, max_size=12),
       acc=st.tuples(st.floats(0, 1000), st.floats(0, 1000)),
       d=st.tuples(st.floats(0, 1), st.floats(0, 1)))
def test_the_jump_to_the_horizon_is_the_step_loop_bit_for_bit(
        start: int, extra: int, checkpoints: list[int], acc: tuple[float, float],
        d: tuple[float, float]) -> None:
    """A settled team adds the same ``d`` at every step: ``carry_records`` fills the
    checkpoints from ``start`` to the horizon exactly as the loop of steps would (the same
    additions in the same order), and leaves the earlier ones alone."""
    n_steps = start + extra
    cp = np.array(sorted(checkpoints), dtype=np.int64)
    ci = int((cp < start).sum())
    reach, conn = np.full(len(cp), -1.0), np.full(len(cp), -1.0)
    carry_records(start, n_steps, cp, ci, reach, conn, acc[0], acc[1], d[0], d[1])
    want_reach, want_conn = np.full(len(cp), -1.0), np.full(len(cp), -1.0)
    a_reach, a_conn = acc
    for k in range(start, n_steps + 1):
        for c in np.flatnonzero(cp == k):
            want_reach[c], want_conn[c] = a_reach, a_conn
        a_reach += d[0]
        a_conn += d[1]
    np.testing.assert_array_equal(reach, want_reach)
    np.testing.assert_array_equal(conn, want_conn)


@given(drones=st.lists(st.tuples(st.sampled_from([SEARCHING, RETURNING, LANDED, REPORTING]),
                                 st.booleans(), st.booleans()), min_size=1, max_size=8),
       all_landed=st.booleans(), look=st.integers(0, 1))
def test_a_team_has_settled_once_all_have_landed_and_none_still_looks(
        drones: list[tuple[int, bool, bool]], all_landed: bool, look: int) -> None:
    """Landed everywhere, and (with per-period looks) no drone in range that does not know
    yet: a later look could still detect the target."""
    if all_landed:
        drones = [(LANDED, r, k) for _, r, k in drones]
    mode = np.array([m for m, _, _ in drones], dtype=np.int8)
    in_range = np.array([r for _, r, _ in drones])
    knows = np.array([k for _, _, k in drones])
    looking = look == PER_PERIOD and any(r and not k for _, r, k in drones)
    assert settled(mode, in_range, knows, look) == (all(m == LANDED for m, _, _ in drones)
                                                    and not looking)


def test_a_recorded_step_holds_the_observed_state() -> None:
    """Positions, headings as angles, who is routed (from the bitset), who knows, modes and
    the link bitsets of step k; the other steps are left alone."""
    n, steps = 3, 4
    track = new_track(steps, n, 1)
    assert [a.shape for a in track] == [(4, 3, 2), (4, 3), (4, 3), (4, 3), (4, 3), (4, 5, 1)]
    px, py = np.array([1.0, 2.0, 3.0, 2000.0, 7.0]), np.array([4.0, 5.0, 6.0, 2000.0, 8.0])
    hx, hy = np.array([1.0, 0.0, -1.0]), np.array([0.0, 1.0, 0.0])
    routed = pack([{1, 3}], 1)[0]
    knows = np.array([True, False, True])
    mode = np.array([SEARCHING, RETURNING, LANDED], dtype=np.int8)
    adj = pack([{1}, {0, 3}, set(), {1}, set()], 1)
    for a in track:
        a[...] = 0
    record_step(2, px, py, hx, hy, routed, knows, mode, adj, *track)
    positions, headings, track_knows, bs_route, track_mode, links = track
    assert positions[2].tolist() == [[1.0, 4.0], [2.0, 5.0], [3.0, 6.0]]
    assert headings[2].tolist() == [0.0, math.pi / 2, math.pi]
    assert bs_route[2].tolist() == [False, True, False]
    assert track_knows[2].tolist() == knows.tolist()
    assert track_mode[2].tolist() == mode.tolist()
    np.testing.assert_array_equal(links[2], adj)
    assert all((a[[0, 1, 3]] == 0).all() for a in track)


def _symmetric(n: int, pairs: Iterable[tuple[int, int]]) -> np.ndarray:
    """The adjacency bitsets of ``n`` drones, the BS and the target with the links ``pairs``."""
    around: list[set[int]] = [set() for _ in range(n + 2)]
    for a, b in pairs:
        if a != b:
            around[int(a)].add(int(b))
            around[int(b)].add(int(a))
    return pack(around, words(n + 2))


def test_the_network_counts_hops_from_the_bs_and_its_parked_drones() -> None:
    """Six drones, the BS (6) and the target (7), counted by hand: 0 is one hop out, 1 two, 2
    three; drone 3 is parked, part of the BS under ``parked = base`` (linked to it or not), so
    4, linked to it, is one hop out; 5 is linked only to the target, which relays nothing, so
    it has no route. Depth 3; the farthest of 0, 1, 2 and 4 is 4, at 400 m: the farthest need
    not be the deepest. Under ``relay`` the parked drone is a drone like any other: with no
    link to the BS, 3 and 4 have no route; linked to it, 3 is one hop out and 4 two."""
    n, bs = 6, (0.0, 0.0)
    mode = np.array([SEARCHING, SEARCHING, RETURNING, LANDED, REPORTING, SEARCHING],
                    dtype=np.int8)
    px = np.array([100.0, 200.0, 300.0, 0.0, 400.0, 900.0, 0.0, 500.0])
    py = np.zeros(n + 2)
    chain = [(6, 0), (0, 1), (1, 2), (3, 4), (2, 7), (5, 7)]
    base, relay = Parked.BASE, Parked.RELAY
    assert network(_symmetric(n, chain), mode, base, px, py, *bs) == (3, 400.0)
    assert network(_symmetric(n, [*chain, (6, 3)]), mode, base, px, py, *bs) == (3, 400.0)
    assert network(_symmetric(n, chain), mode, relay, px, py, *bs) == (3, 300.0)
    assert network(_symmetric(n, [*chain, (6, 3)]), mode, relay, px, py, *bs) == (3, 400.0)
    parked = np.full(n, LANDED, dtype=np.int8)  # every drone parked: none airborne
    assert network(_symmetric(n, chain), parked, base, px, py, *bs) == (0, 0.0)
    alone = _symmetric(n, [(2, 7)])  # the BS linked to nothing, no drone parked
    searching = np.full(n, SEARCHING, dtype=np.int8)
    assert network(alone, searching, base, px, py, *bs) == (0, 0.0)


@given(n=st.integers(1, 70), p_link=st.floats(0.0, 0.3), seed=st.integers(0, 2**32 - 1),
       parked=st.sampled_from(Parked))
def test_the_network_is_the_reference_breadth_first_search(n: int, p_link: float, seed: int,
                                                           parked: Parked) -> None:
    """On random graphs of up to 72 nodes (two bitset words), random modes and positions, the
    bitset search level by level gives the depth and farthest distance of the slow
    reference's plain breadth-first search on the adjacency matrix."""
    rng = np.random.default_rng(seed)
    m = n + 2
    linked = np.triu(rng.random((m, m)) < p_link, 1)
    linked |= linked.T
    adj = _symmetric(n, zip(*np.nonzero(linked), strict=True))
    mode = rng.choice([SEARCHING, RETURNING, LANDED, REPORTING], n,
                      p=[0.6, 0.1, 0.2, 0.1]).astype(np.int8)
    px, py = rng.uniform(0.0, 4000.0, m), rng.uniform(0.0, 4000.0, m)
    bs = (float(px[n]), float(py[n]))
    base = (mode == LANDED) & (parked == Parked.BASE)
    want = naive_network(linked.tolist(), base.tolist(),
                         list(zip(px.tolist(), py.tolist(), strict=True)), bs)
    assert network(adj, mode, int(parked), px, py, *bs) == want
