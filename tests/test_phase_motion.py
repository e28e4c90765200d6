"""The motion phase (sarlink.engine.motion) called directly: the boundary rule, route following,
the return-home schedule, reporting and the move, against the geometry and the model's text
(docs/model.md, Drones; Beyond the paper)."""

from __future__ import annotations

import math
from itertools import pairwise

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from scipy import stats

from phase_inputs import BS, params
from sarlink.engine.motion import (
    boundary,
    boundary_turn,
    farthest_home,
    fly_route,
    home_due,
    move,
    report,
    schedule,
)
from sarlink.engine.params import LANDED, RELAYING, REPORTING, RETURNING, SEARCHING

SIZE = 4000.0
STEP = 5.0  # V dt of the default mission
P = params()
COORD = st.floats(0.0, SIZE)
ANGLE = st.floats(-math.pi, math.pi)
NEAR_BS = st.floats(BS[0] - 8.0, BS[0] + 8.0)
MODE = st.sampled_from([SEARCHING, RETURNING, LANDED, REPORTING])


def _modes(values: list[int]) -> np.ndarray:
    return np.array(values, dtype=np.int8)


# -- the boundary rule ------------------------------------------------------------------------


@given(x=COORD, y=COORD, angle=ANGLE, seed=st.integers(0, 2**32 - 1))
def test_a_boundary_turn_never_leaves_the_square_and_points_away_from_the_wall(
        x: float, y: float, angle: float, seed: int) -> None:
    """A heading whose increment stays inside is kept; else the new one is a unit vector whose
    increment stays inside and that points away from (or along) every wall the old one
    crossed."""
    hx, hy = math.cos(angle), math.sin(angle)
    nx, ny = x + STEP * hx, y + STEP * hy
    gx, gy, turned = boundary_turn(x, y, hx, hy, STEP, SIZE, np.random.default_rng(seed))
    crossed = nx < 0.0 or nx > SIZE or ny < 0.0 or ny > SIZE
    assert turned == crossed
    if not crossed:
        assert (gx, gy) == (hx, hy)
        return
    assert math.hypot(gx, gy) == pytest.approx(1.0)
    assert 0.0 <= x + STEP * gx <= SIZE and 0.0 <= y + STEP * gy <= SIZE
    tiny = 1e-12
    assert not (nx < 0.0 and gx < -tiny) and not (nx > SIZE and gx > tiny)
    assert not (ny < 0.0 and gy < -tiny) and not (ny > SIZE and gy > tiny)


@pytest.mark.parametrize(("x", "y", "heading", "lo", "hi"), [
    (2.0, 2000.0, math.pi, -math.pi / 2, math.pi / 2),  # the west wall: a half circle
    (2000.0, 3998.0, math.pi / 2, -math.pi, 0.0),  # the north wall (angles as atan2 gives)
    (1.0, 1.0, -3 * math.pi / 4, 0.0, math.pi / 2),  # the south-west corner: a quarter
])
def test_a_boundary_turn_draws_uniformly_from_the_inward_arc(
        x: float, y: float, heading: float, lo: float, hi: float) -> None:
    """From a point next to a wall (or in a corner) every inward heading stays inside, so one
    draw decides: the new angles are uniform on the arc (Kolmogorov-Smirnov at 0.1 %, fixed
    seed), one random number per turn."""
    rng, twin = np.random.default_rng(11), np.random.default_rng(11)
    draws = 2000
    angles = []
    for _ in range(draws):
        gx, gy, turned = boundary_turn(x, y, math.cos(heading), math.sin(heading), STEP, SIZE,
                                       rng)
        assert turned
        angles.append(math.atan2(gy, gx))
    twin.random(draws)
    assert rng.bit_generator.state == twin.bit_generator.state
    assert lo <= min(angles) and max(angles) <= hi
    assert stats.kstest(angles, stats.uniform(lo, hi - lo).cdf).pvalue > 1e-3


def test_the_boundary_rule_turns_only_searching_distributed_drones_in_drone_order() -> None:
    """Four drones 2 m from the west wall: drone 0 (searching, flying west) turns, with the
    first random number (θ = -π/2 + u π) and a new clock; a route drone, a returning one and
    a searching one flying east keep their headings."""
    n = 4
    px, py = np.full(n, 2.0), np.full(n, 2000.0)
    nhx, nhy = np.array([-1.0, -1.0, -1.0, 1.0]), np.zeros(n)
    last_change = np.zeros(n, dtype=np.int64)
    rng = np.random.default_rng(4)
    boundary(17, P, px, py, _modes([SEARCHING, SEARCHING, RETURNING, SEARCHING]),
             np.array([False, True, False, False]), last_change, nhx, nhy, rng)
    theta = -math.pi / 2 + np.random.default_rng(4).random() * math.pi
    assert (nhx[0], nhy[0]) == pytest.approx((math.cos(theta), math.sin(theta)))
    assert nhx[1:].tolist() == [-1.0, -1.0, 1.0] and nhy[1:].tolist() == [0.0] * 3
    assert last_change.tolist() == [17, 0, 0, 0]


# -- routes -----------------------------------------------------------------------------------


@given(start=st.tuples(COORD, COORD), route=st.lists(st.tuples(COORD, COORD), min_size=1,
                                                      max_size=5),
       step=st.floats(0.5, 9000.0))
def test_a_route_drone_advances_exactly_the_step_along_its_polyline(
        start: tuple[float, float], route: list[tuple[float, float]], step: float) -> None:
    """Drone 1 (its waypoints after drone 0's) travels ``step`` metres of arc length along
    the polyline from where it is through its waypoints, ends on the segment it is flying,
    heading along it; if the route is shorter, it lands on the last waypoint."""
    other = [(0.0, 0.0), (1.0, 1.0)]  # drone 0's route, not touched
    wp = np.array(other + route)
    wp_next, wp_end = np.array([0, len(other)]), np.array([len(other), len(wp)])
    px, py = np.array([9.0, start[0]]), np.array([9.0, start[1]])
    hx, hy = np.array([1.0, 1.0]), np.array([0.0, 0.0])
    mode = _modes([SEARCHING, SEARCHING])
    path = [start, *route]
    cum = np.concatenate([[0.0], np.cumsum([math.dist(a, b) for a, b in pairwise(path)])])
    assume(abs(step - cum[-1]) > 1e-6 * max(1.0, cum[-1]))  # not landing on a knife edge
    fly_route(1, px, py, hx, hy, mode, wp, wp_next, wp_end, step)
    assert (px[0], py[0], hx[0], mode[0], wp_next[0]) == (9.0, 9.0, 1.0, SEARCHING, 0)
    if step > cum[-1]:
        assert (px[1], py[1]) == route[-1]
        assert mode[1] == LANDED and wp_next[1] == wp_end[1]
        return
    assert mode[1] == SEARCHING
    j = wp_next[1] - len(other)  # flying towards route[j], from path[j]
    assert 0 <= j < len(route)
    a, b = np.array(path[j]), np.array(route[j])
    here = np.array([px[1], py[1]])
    assert cum[j] + float(np.linalg.norm(here - a)) == pytest.approx(step, rel=1e-9, abs=1e-7)
    seg = (b - a) / np.linalg.norm(b - a)
    assert (hx[1], hy[1]) == pytest.approx(tuple(seg), abs=1e-9)
    off = here - a
    assert abs(seg[0] * off[1] - seg[1] * off[0]) <= 1e-7  # on the segment's line ...
    assert -1e-7 <= float(seg @ off) <= float(np.linalg.norm(b - a)) + 1e-7  # ... on it


# -- returning home ---------------------------------------------------------------------------


def test_a_drone_turns_home_when_its_budget_minus_the_flight_home_is_under_two_steps() -> None:
    """1000 m east of the BS at 5 m/s the flight home takes 200 s: 4000 - t - 200 < 2 first
    at t = 3799 s; until then it keeps its schedule, then heads due west."""
    px, py = np.array([3000.0]), np.array([2000.0])
    hx, hy = np.array([0.0]), np.array([1.0])
    home_max = farthest_home(P)
    for k in range(3790, 3801):
        mode, last_change = _modes([SEARCHING]), np.array([k - 1])
        deciding, nhx, nhy = np.zeros(1, dtype=np.bool_), np.zeros(1), np.zeros(1)
        homing = (P.flight_time - k * P.dt) - home_max / P.speed < 2.0 * P.dt
        assert homing  # the team-wide test fires no later than any drone's
        schedule(k, homing, P, px, py, hx, hy, mode, np.zeros(1, dtype=np.bool_), last_change,
                 deciding, nhx, nhy)
        assert mode[0] == (RETURNING if k >= 3799 else SEARCHING), k
        assert (nhx[0], nhy[0]) == ((-1.0, 0.0) if k >= 3799 else (0.0, 1.0))
        assert not deciding[0]  # its clock (k - 1) is not due


@given(bs=st.tuples(COORD, COORD), x=COORD, y=COORD, t=st.floats(0.0, 4000.0))
def test_the_team_s_homing_test_fires_no_later_than_any_drone_s(
        bs: tuple[float, float], x: float, y: float, t: float) -> None:
    p = params(bs_x=bs[0], bs_y=bs[1])
    home_max = farthest_home(p)
    assert home_max >= math.dist(bs, (x, y)) + 1.0 - 1e-9
    due, hdx, hdy = home_due(p, t, x, y)
    assert (hdx, hdy) == (bs[0] - x, bs[1] - y)
    if due:
        assert (p.flight_time - t) - home_max / p.speed < 2.0 * p.dt


@given(k=st.integers(0, 4000), homing=st.booleans(), flight_time=st.floats(100.0, 5000.0),
       drones=st.lists(st.tuples(COORD, COORD, ANGLE, MODE, st.booleans(), st.integers(0, 4)),
                       min_size=1, max_size=6))
def test_schedule_turns_home_or_decides_as_the_model_says(
        k: int, homing: bool, flight_time: float,
        drones: list[tuple[float, float, float, int, bool, int]]) -> None:
    """At step k a searching distributed drone goes home if the team's homing test has fired
    and its own budget minus its flight home is under two steps, else decides once t_s has
    passed since its last change; a reporting drone heads for the BS (and, distributed and
    due, goes home); route, returning and landed drones are left alone."""
    p = params(flight_time=flight_time)
    n = len(drones)
    px, py = np.array([d[0] for d in drones]), np.array([d[1] for d in drones])
    hx, hy = np.cos([d[2] for d in drones]), np.sin([d[2] for d in drones])
    mode, on_route = _modes([d[3] for d in drones]), np.array([d[4] for d in drones])
    last_change = np.array([k - d[5] for d in drones])
    deciding, nhx, nhy = np.ones(n, dtype=np.bool_), np.zeros(n), np.zeros(n)
    margin = [(flight_time - k * p.dt) - math.dist(BS, d[:2]) / p.speed - 2.0 * p.dt
              for d in drones]
    assume(all(abs(v) > 1e-9 for v in margin))
    any_deciding = schedule(k, homing, p, px, py, hx, hy, mode, on_route, last_change,
                            deciding, nhx, nhy)
    for i, (x, y, _, was, routed, age) in enumerate(drones):
        due = margin[i] < 0.0
        d = math.dist(BS, (x, y))
        to_bs = ((BS[0] - x) / d, (BS[1] - y) / d) if d > 0 else (hx[i], hy[i])
        want_mode, want_heading, want_deciding = was, (hx[i], hy[i]), False
        if was == REPORTING:
            want_heading = to_bs
            if due and homing and not routed:
                want_mode = RETURNING
        elif was == SEARCHING and not routed:
            if homing and due:
                want_mode, want_heading = RETURNING, to_bs
            elif age >= p.ts_steps:
                want_deciding = True
        assert mode[i] == want_mode
        assert (nhx[i], nhy[i]) == pytest.approx(want_heading, abs=1e-12)
        assert deciding[i] == want_deciding
        assert last_change[i] == (k if want_deciding else k - age)
    assert any_deciding == bool(deciding.any())


# -- reporting --------------------------------------------------------------------------------


def test_knowers_start_reporting_and_resume_once_the_bs_is_notified() -> None:
    """Drone 0 (distributed) and 1 (route) know, 2 does not, 3 knows but is going home. They
    report until the notification (only the detector, 1, with ``reporters = detector``); the
    route drone remembers where it left its tour; then they resume: the distributed drone is
    due for a direction update at once."""
    def state() -> tuple[np.ndarray, ...]:
        return (_modes([SEARCHING, SEARCHING, SEARCHING, RETURNING]),
                np.array([False, True, False, False]), np.zeros(4), np.zeros(4),
                np.zeros(4, dtype=np.bool_), np.full(4, 40, dtype=np.int64))

    px, py = np.array([10.0, 20.0, 30.0, 40.0]), np.array([1.0, 2.0, 3.0, 4.0])
    knows = np.array([True, True, False, True])
    mode, on_route, leave_x, leave_y, rejoin, last = state()
    report(50, P, False, 1, knows, mode, on_route, px, py, leave_x, leave_y, rejoin, last)
    assert mode.tolist() == [REPORTING, REPORTING, SEARCHING, RETURNING]
    assert (leave_x.tolist(), leave_y.tolist()) == ([0.0, 20.0, 0.0, 0.0], [0.0, 2.0, 0.0, 0.0])
    assert rejoin.tolist() == [False, True, False, False]
    report(60, P, True, 1, knows, mode, on_route, px, py, leave_x, leave_y, rejoin, last)
    assert mode.tolist() == [SEARCHING, SEARCHING, SEARCHING, RETURNING]
    assert last.tolist() == [60 - P.ts_steps, 40, 40, 40]
    assert rejoin.tolist() == [False, True, False, False]  # it still flies back first

    mode, on_route, leave_x, leave_y, rejoin, last = state()
    report(50, params(reporters=1), False, 1, knows, mode, on_route, px, py, leave_x, leave_y,
           rejoin, last)
    assert mode.tolist() == [SEARCHING, REPORTING, SEARCHING, RETURNING]


# -- the move ---------------------------------------------------------------------------------


def test_every_kind_of_drone_moves_as_the_model_says() -> None:
    """One step of V dt = 5 m: 0 searching moves along its heading; 1 landed stays; 2
    returning exactly 5 m from the BS lands on it; 3 returning farther moves on; 4 reporting
    4.5 m from the BS waits on it; 5 on its route rejoins its tour 3 m away and flies the 2 m left
    towards its next waypoint; 6 on its route, 8 m from where it left, flies 5 m back; 7 a
    relay 3 m from its aim holds it; 8 a relay 20 m from its aim flies 5 m towards it."""
    px = np.array([100.0, 2000.0, 2005.0, 2100.0, 1995.5, 500.0, 600.0, 800.0, 900.0])
    py = np.array([100.0, 2000.0, 2000.0, 2000.0, 2000.0, 500.0, 600.0, 800.0, 900.0])
    hx = np.array([0.6, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0, 1.0, 0.0])
    hy = np.array([0.8, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0])
    mode = _modes([SEARCHING, LANDED, RETURNING, RETURNING, REPORTING, SEARCHING, SEARCHING,
                   RELAYING, RELAYING])
    on_route = np.array([False] * 5 + [True, True] + [False] * 2)
    wp = np.array([[503.0, 600.0], [700.0, 700.0]])
    wp_next = np.array([0, 0, 0, 0, 0, 0, 1, 0, 0])
    wp_end = np.array([0, 0, 0, 0, 0, 1, 2, 0, 0])
    leave_x = np.array([0.0] * 5 + [503.0, 600.0] + [0.0] * 2)
    leave_y = np.array([0.0] * 5 + [500.0, 608.0] + [0.0] * 2)
    rejoin = np.array([False] * 5 + [True, True] + [False] * 2)
    aim_x, aim_y = np.array([0.0] * 7 + [803.0, 900.0]), np.array([0.0] * 7 + [800.0, 880.0])
    move(P, px, py, hx, hy, mode, on_route, wp, wp_next, wp_end, leave_x, leave_y, rejoin,
         aim_x, aim_y)
    assert px[:5] == pytest.approx([103.0, 2000.0, 2000.0, 2095.0, 2000.0])
    assert py[:5] == pytest.approx([104.0, 2000.0, 2000.0, 2000.0, 2000.0])
    assert (px[2], py[2]) == (px[4], py[4]) == BS  # exactly on the BS
    assert mode.tolist() == [SEARCHING, LANDED, LANDED, RETURNING, REPORTING, SEARCHING,
                             SEARCHING, RELAYING, RELAYING]
    assert (px[7], py[7]) == (803.0, 800.0) and (px[8], py[8]) == (900.0, 895.0)
    assert (px[5], py[5]) == pytest.approx((503.0, 502.0))
    assert (hx[5], hy[5]) == (0.0, 1.0) and not rejoin[5]
    assert (px[6], py[6]) == (600.0, 605.0) and (hx[6], hy[6]) == (0.0, 1.0) and rejoin[6]


@given(drones=st.lists(st.tuples(NEAR_BS | COORD, NEAR_BS | COORD, ANGLE, MODE, st.booleans()),
                       min_size=1, max_size=6))
def test_no_drone_moves_farther_than_v_dt_and_free_flyers_move_exactly_that(
        drones: list[tuple[float, float, float, int, bool]]) -> None:
    """Route drones follow a route of two waypoints; the others fly their headings (home or
    to the BS when returning or reporting, as the schedule set them). A route drone never
    returns (the schedule sends only distributed drones home)."""
    drones = [(x, y, a, SEARCHING if routed and was == RETURNING else was, routed)
              for x, y, a, was, routed in drones]
    n = len(drones)
    px, py = np.array([d[0] for d in drones]), np.array([d[1] for d in drones])
    hx, hy = np.cos([d[2] for d in drones]), np.sin([d[2] for d in drones])
    for i, (x, y, _, was, _) in enumerate(drones):
        if was in (RETURNING, REPORTING) and (x, y) != BS:
            d = math.dist(BS, (x, y))
            hx[i], hy[i] = (BS[0] - x) / d, (BS[1] - y) / d
    mode, on_route = _modes([d[3] for d in drones]), np.array([d[4] for d in drones])
    wp = np.array([[1000.0, 1000.0], [3000.0, 1000.0]] * n)
    wp_next, wp_end = np.arange(0, 2 * n, 2), np.arange(2, 2 * n + 1, 2)
    x0, y0 = px.copy(), py.copy()
    move(P, px, py, hx, hy, mode, on_route, wp, wp_next, wp_end, np.zeros(n), np.zeros(n),
         np.zeros(n, dtype=np.bool_), np.zeros(n), np.zeros(n))
    moved = np.hypot(px - x0, py - y0)
    assert (moved <= STEP + 1e-9).all()
    for i, (x, y, _, was, routed) in enumerate(drones):
        if was == LANDED:
            assert moved[i] == 0.0
        elif was in (RETURNING, REPORTING) and math.dist(BS, (x, y)) <= STEP:
            assert (px[i], py[i]) == BS
        elif not routed or was != SEARCHING:
            assert moved[i] == pytest.approx(STEP)
