"""Relays in the engine (docs/model.md, Relays): whole runs keep every relay in the area and
out of its holes, the BS's dead reckoning stays in the area wherever the area lies, and a
relay count the team cannot take is one line. The relays' flight against the slow reference:
tests/test_reference.py; where they stand: tests/test_relay_placement.py."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from polygons import areas
from sarlink import Mission, simulate
from sarlink.config import ConfigError
from sarlink.config.region import area_polygon
from sarlink.engine.area import contains
from sarlink.engine.codes import PRIORITY_CODES, Mode
from sarlink.engine.observation import Observation
from sarlink.engine.relays.tree import reckon
from sarlink.simulation import prepare

WALL = Mission.from_dict({
    "area": {"bs": (1500.0, 300.0)},
    "region": {"outline": [(0, 0), (3000, 0), (3000, 3000), (0, 3000)],
               "holes": [[(300, 1200), (2700, 1200), (2700, 1300), (300, 1300)]]}})
"""A wall across the area between the BS and half of it: the tree's edges to searchers
beyond it cross it, so relays hold points moved out of it and fly round its ends."""


@settings(max_examples=12)
@given(st.one_of(st.sampled_from([None, WALL]), areas()), st.sampled_from(["covb", "mtsp"]),
       st.integers(1, 3), st.sampled_from(sorted(PRIORITY_CODES)),
       st.sampled_from(["reckoned", "heard"]), st.sampled_from(["continue", "report"]),
       st.integers(0, 1000))
def test_no_relay_leaves_the_area_or_enters_a_hole(area: Mission | None, planner: str,
                                                   relays: int, priority: str, estimate: str,
                                                   on_detect: str, run: int) -> None:
    """The square (None), a wall (:data:`WALL`) or a random polygon with holes, searchers
    under a rule or on mTSP routes, r_c = 300 m (the tree needs more relays than there are:
    k-bottleneck spreads them along its longest edges, across the holes): every step a relay
    flies, out to its points, holding them and home round the holes, lies inside the area
    and out of the holes; and with a budget shorter than the run every relay has landed at
    the BS."""
    flown = (area or Mission()).replace(
        planner=planner, drones=relays + 3, relays=relays, rc=300.0, flight_time=1200.0,
        horizon=1600.0, relay_priority=priority, relay_estimate=estimate,
        on_detect=on_detect, mtsp_plan="shared", iterations=200)
    traj = simulate(flown, seed=5, run=run, trajectory=True).trajectory
    assert traj is not None
    pos = traj.positions[:, -relays:]
    legs = shapely.linestrings(np.stack([pos[:-1], pos[1:]], axis=2).reshape(-1, 2, 2))
    inside = area_polygon(flown.region, flown.area.size).buffer(1e-6)
    assert shapely.covers(inside, legs).all()
    assert (traj.mode[-1, -relays:] == Mode.LANDED).all()
    assert np.allclose(pos[-1], flown.area.bs_xy)


@pytest.mark.parametrize("planner", ["covb", "mtsp"])
def test_a_relay_out_of_the_bs_reach_flies_back_to_it(planner: str) -> None:
    """k-bottleneck spreads three relays along the tree's longest edges, which they cannot
    hold at r_c = 500 m, so they fly out of the BS's reach: at every such step a relay (in
    the square: straight) closes on the BS by V dt, and never holds still out of contact,
    where the BS could give it no other point."""
    mission = Mission.build(planner=planner, drones=8, relays=3, rc=500.0, horizon=1000.0,
                            relay_priority="k-bottleneck", mtsp_plan="shared",
                            iterations=200)
    step = mission.team.speed * mission.timing.dt
    out = 0
    for run in range(4):
        traj = simulate(mission, seed=7, run=run, trajectory=True).trajectory
        assert traj is not None
        home = np.hypot(*(traj.positions[:, 5:] - mission.area.bs_xy).transpose(2, 0, 1))
        cut = (traj.mode[:-1, 5:] == Mode.RELAYING) & ~traj.bs_route[:-1, 5:]
        out += int(cut.sum())
        closer = np.maximum(home[:-1] - step, 0.0)
        np.testing.assert_allclose(home[1:][cut], closer[cut], rtol=0.0, atol=1e-6)
    assert out > 0


def _heard(n: int) -> Observation:
    """What :func:`reckon` reads of ``n`` searching distributed drones (no routes)."""
    m = n + 2
    bits = np.zeros((m, 1), dtype=np.uint64)
    return Observation(np.zeros(m), np.zeros(m), np.zeros(m), np.zeros(n), np.zeros(n),
                       np.zeros(n, dtype=np.int8), np.zeros(n, dtype=np.bool_),
                       np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.bool_), bits, bits,
                       bits[0], bits[0], 500.0, np.empty((0, 2)), np.zeros(n, dtype=np.int64),
                       np.zeros(n, dtype=np.int64), np.random.default_rng(0),
                       np.zeros(1, dtype=np.int64))


def test_dead_reckoning_keeps_to_a_polygon_area_wherever_it_lies() -> None:
    """A polygon area round the BS at the origin (as the valley example's): a searcher heard
    at (-2000, -1000) flying west is reckoned 50 m on 10 s later, not put on the square
    ``[0, size]²`` the polygon does not use; one reckoned into a hole is put on its nearest
    side, inside the area."""
    mission = Mission.from_dict({
        "area": {"bs": (0.0, 0.0)}, "team": {"drones": 3, "relays": 1},
        "region": {"outline": [(-3000, -3000), (3000, -3000), (3000, 3000), (-3000, 3000)],
                   "holes": [[(500, 500), (1500, 500), (1500, 1500), (500, 1500)]]}})
    prepared = prepare(mission)
    p, edges = prepared.params, prepared.edges
    # x, y, heading x and y, the step, next waypoint, mode and route flag of each hearing
    heard = np.array([[-2000.0, 400.0], [-1000.0, 1000.0], [-1.0, 1.0], [0.0, 0.0],
                      [0.0, 0.0], [0.0, 0.0], [Mode.SEARCHING] * 2, [0.0, 0.0]])
    obs = _heard(2)
    assert reckon(10, p, obs, heard, 0, edges) == (-2050.0, -1000.0)
    x, y = reckon(40, p, obs, heard, 1, edges)  # 600 m east: 100 m into the hole
    assert 500.0 - 1e-2 < x < 500.0 and y == 1000.0 and contains(x, y, edges)


@pytest.mark.parametrize("now", [Mode.REPORTING, Mode.RETURNING, Mode.LANDED],
                         ids=lambda m: m.name.lower())
def test_dead_reckoning_reads_what_the_bs_heard_not_what_the_drone_does_now(now: Mode) -> None:
    """A searcher heard searching, flying east, is reckoned on east whatever it has done since
    out of the BS's hearing (found the target and turned home, or landed); one heard flying
    home is reckoned on its way home."""
    prepared = prepare(Mission.build(drones=3, relays=1))
    p, edges = prepared.params, prepared.edges
    heard = np.array([[1000.0, 1000.0], [1000.0, 1000.0], [1.0, 1.0], [0.0, 0.0],
                      [0.0, 0.0], [0.0, 0.0], [Mode.SEARCHING, Mode.RETURNING], [0.0, 0.0]])
    obs = _heard(2)
    obs.mode[:] = now
    step = p.speed * p.dt
    assert reckon(10, p, obs, heard, 0, edges) == (1000.0 + 10 * step, 1000.0)
    x, y = reckon(10, p, obs, heard, 1, edges)
    home = math.dist((1000.0, 1000.0), (p.bs_x, p.bs_y))
    assert math.dist((x, y), (p.bs_x, p.bs_y)) == pytest.approx(home - 10 * step)


def test_a_drone_of_the_chain_to_a_found_target_is_reckoned_where_it_was_heard() -> None:
    """``on_detect = relay``: a drone of the chain holds its point, so the BS puts it where it
    last heard it, not on along its heading as a searcher."""
    prepared = prepare(Mission.build(drones=3, relays=1))
    heard = np.array([[1000.0, 1000.0], [1000.0, 1000.0], [1.0, 1.0], [0.0, 0.0],
                      [0.0, 0.0], [0.0, 0.0], [Mode.SEARCHING, Mode.CHAINING], [0.0, 0.0]])
    obs = _heard(2)
    p, edges = prepared.params, prepared.edges
    assert reckon(10, p, obs, heard, 0, edges) == (1050.0, 1000.0)
    assert reckon(10, p, obs, heard, 1, edges) == (1000.0, 1000.0)


@pytest.mark.parametrize(("relays", "message"), [
    (8, "team.relays = 8 leaves no searcher among team.drones = 8; allowed: 0 to 7"),
    (9, "team.relays = 9 leaves no searcher among team.drones = 8; allowed: 0 to 7"),
    (-1, "team.relays: Input should be greater than or equal to 0 (got -1)"),
])
def test_a_relay_count_the_team_cannot_take_is_one_line(relays: int, message: str) -> None:
    """As many relays as drones (or more) leave no one to search, a negative count is no
    count: one line naming ``team.relays`` and what is allowed."""
    with pytest.raises(ConfigError) as caught:
        Mission.build(drones=8, relays=relays)
    assert str(caught.value) == message
