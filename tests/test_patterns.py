"""The IAMSAR search patterns: their geometry, the routes they plan, and their runs.

Coverage is checked on a grid of points against the distance to each drone's flown polyline
(take-off at the BS, then its waypoints), computed here independently of the planners.
"""

from __future__ import annotations

import itertools
import json
import math
import re

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from typer.testing import CliRunner

from sarlink import Mission, get_planner, simulate
from sarlink.cli import app
from sarlink.engine.codes import Mode
from sarlink.planners.patterns import PATTERNS, expanding, parallel, sector
from sarlink.planners.patterns.base import Search
from sarlink.planners.patterns.geometry import (
    Rect,
    close_at,
    fit_budget,
    flight_length,
    polyline_arc,
)

PLANS = {"parallel": parallel.plan, "expanding-square": expanding.plan, "sector": sector.plan}
NAMES = [p.name for p in PATTERNS]


def _distance(points: np.ndarray, path: np.ndarray) -> np.ndarray:
    """Each point's distance to the polyline ``path`` (a point, if it has one vertex)."""
    best = np.hypot(*(points - path[0]).T)
    for a, b in itertools.pairwise(path):
        ab = b - a
        length2 = float(ab @ ab)
        t = np.zeros(len(points)) if length2 == 0 else np.clip((points - a) @ ab / length2, 0, 1)
        best = np.minimum(best, np.hypot(*(a + t[:, None] * ab - points).T))
    return best


def _uncovered(search: Search, routes: tuple[np.ndarray, ...], points: int = 41) -> float:
    """The largest distance from a grid point of the area to the nearest drone's path."""
    area = search.area
    grid = np.array(list(itertools.product(np.linspace(area.x0, area.x1, points),
                                           np.linspace(area.y0, area.y1, points))))
    paths = [np.vstack([search.bs, route]) for route in routes]
    return float(np.min([_distance(grid, path) for path in paths], axis=0).max())


# -- geometry -------------------------------------------------------------------------------

coordinates = st.floats(0, 1000, allow_nan=False)
polylines = st.lists(st.tuples(coordinates, coordinates), min_size=1, max_size=8)


@given(bs=st.tuples(coordinates, coordinates), route=polylines, budget=st.floats(0, 6000))
def test_a_route_fitted_to_the_budget_is_its_start_then_home_within_the_budget(
        bs: tuple[float, float], route: list[tuple[float, float]], budget: float) -> None:
    route_xy = close_at(bs, [np.array(route)])
    fitted = fit_budget(bs, route_xy, budget)
    np.testing.assert_array_equal(fitted[-1], bs)
    length = flight_length(bs, route_xy)
    if length <= budget:
        np.testing.assert_array_equal(fitted, route_xy)
        return
    assert flight_length(bs, fitted) == pytest.approx(budget, abs=1e-6)  # cut no earlier
    path = np.vstack([bs, route_xy])
    assert (_distance(fitted[:-1], path) < 1e-6).all()  # every point before home on the path
    # the points before the cut are the route's own, in its order
    kept = fitted[:-2]
    np.testing.assert_array_equal(kept, route_xy[:len(kept)])


def test_a_fitted_route_turns_home_where_the_straight_flight_back_uses_up_the_budget() -> None:
    # out 3000 m along x, home 3000 m: with 4000 m the drone turns at 2000 m
    fitted = fit_budget((0.0, 0.0), np.array([[3000.0, 0.0], [0.0, 0.0]]), 4000.0)
    np.testing.assert_allclose(fitted, [[2000.0, 0.0], [0.0, 0.0]])
    # a right angle: after x along the first leg the way home is sqrt(1000² + x²) ...
    fitted = fit_budget((0.0, 0.0), np.array([[0.0, 1000.0], [1000.0, 1000.0], [0.0, 0.0]]),
                        2500.0)
    x = fitted[1, 0]
    assert 1000 + x + math.hypot(1000.0, x) == pytest.approx(2500.0)


def test_the_directions_into_the_area_from_inside_an_edge_and_a_corner() -> None:
    area = Rect.square(100.0)
    assert area.view((50.0, 50.0)) == (0.0, pytest.approx(2 * math.pi))
    first, sweep = area.view((50.0, 0.0))
    assert sweep == pytest.approx(math.pi) and first == pytest.approx(0.0)
    first, sweep = area.view((100.0, 100.0))
    assert sweep == pytest.approx(math.pi / 2) and first == pytest.approx(math.pi)


@given(x=st.floats(0, 100), y=st.floats(0, 100), angle=st.floats(-7, 7))
def test_a_ray_leaves_the_area_on_its_edge(x: float, y: float, angle: float) -> None:
    area = Rect.square(100.0)
    end = area.exit((x, y), angle)
    assert area.contains(end).all()
    on_edge = min(end[0], end[1], 100 - end[0], 100 - end[1])
    assert on_edge < 1e-9
    if not np.allclose(end, (x, y)):
        direction = (end - (x, y)) / np.hypot(*(end - (x, y)))
        np.testing.assert_allclose(direction, [math.cos(angle), math.sin(angle)], atol=1e-9)


@given(line=polylines, a=st.floats(0, 1), b=st.floats(0, 1))
def test_an_arc_is_its_share_of_the_polyline(line: list[tuple[float, float]], a: float,
                                             b: float) -> None:
    points = np.array(line)
    arc = polyline_arc(points, a, b)
    total = flight_length(points[0], points[1:])
    assert flight_length(arc[0], arc[1:]) == pytest.approx(abs(b - a) * total, abs=1e-6)
    assert (_distance(arc, points) < 1e-6).all()
    if a == 0 and b == 1 and total > 0:
        np.testing.assert_allclose(arc[[0, -1]], points[[0, -1]])


# -- the planned routes ----------------------------------------------------------------------

searches = st.builds(
    lambda drones, size, r, bs, flight: Mission.build(
        drones=drones, size=size, r=r, flight_time=flight, horizon=min(flight, 4000.0),
        bs=None if bs is None else (bs[0] * size, bs[1] * size)),
    drones=st.integers(1, 22),
    size=st.floats(500.0, 6000.0),
    r=st.floats(100.0, 1500.0),
    bs=st.none() | st.tuples(st.floats(0, 1), st.floats(0, 1)),
    flight=st.sampled_from([300.0, 1500.0, 4000.0]),
)


@pytest.mark.parametrize("name", NAMES)
@given(mission=searches)
def test_every_route_stays_in_the_area_ends_at_the_bs_and_fits_the_budget(
        name: str, mission: Mission) -> None:
    routes = get_planner(name).steering(mission.replace(planner=name)).routes
    search = Search.of(mission)
    assert len(routes) == mission.team.drones
    for route in routes:
        assert route.ndim == 2 and route.shape[1] == 2 and len(route) >= 1
        assert search.area.contains(route).all()
        np.testing.assert_array_equal(route[-1], mission.area.bs_xy)
        assert flight_length(search.bs, route) <= search.budget + 1e-6


ROUNDS_PAST_THE_EDGE = Mission.build(
    drones=1, size=2648.825857110521, r=322.0, flight_time=4000.0, horizon=4000.0,
    bs=(0.0, 0.2265625 * 2648.825857110521))
"""Found by hypothesis in CI: a sector spoke's end, bs + (edge - bs) * 1.0, rounded past the
area's edge."""


@pytest.mark.parametrize("name", NAMES)
@given(mission=searches)
@example(mission=ROUNDS_PAST_THE_EDGE)
def test_within_budget_a_plan_is_flown_whole(name: str, mission: Mission) -> None:
    search = Search.of(mission)
    plan = PLANS[name](search)
    flown = get_planner(name).steering(mission).routes
    for whole, route in zip(plan, flown, strict=True):
        assert search.area.contains(whole).all()
        if flight_length(search.bs, whole) <= search.budget:
            np.testing.assert_array_equal(whole, route)


unlimited = st.builds(
    lambda drones, size, r, bs: Search.of(Mission.build(
        drones=drones, size=size, r=r, flight_time=1e7, horizon=1000.0,
        bs=None if bs is None else (bs[0] * size, bs[1] * size))),
    drones=st.integers(1, 22),
    size=st.floats(500.0, 6000.0),
    r=st.floats(150.0, 1500.0),
    bs=st.none() | st.tuples(st.floats(0, 1), st.floats(0, 1)),
)


@given(search=unlimited)
def test_parallel_track_covers_every_point_of_the_area(search: Search) -> None:
    """Tracks 2 r apart, half of it inside the edges, legs edge to edge: within r."""
    assert _uncovered(search, parallel.plan(search)) <= search.spacing / 2 + 1e-6


@given(search=unlimited)
def test_expanding_squares_leave_only_their_corners_farther_than_r(search: Search) -> None:
    """Every point is within S/2 of a square's side in each axis (Chebyshev), so within
    √2 r: the corners of the squares, as IAMSAR's pattern with a definite-range sensor."""
    assert _uncovered(search, expanding.plan(search)) <= math.sqrt(2) * search.spacing / 2 + 1e-6


@given(search=unlimited)
def test_a_sector_search_to_the_farthest_corner_covers_every_point(search: Search) -> None:
    """Spokes whose ends are at most S apart at the radius, and a second pass half-way
    between: every point within r (when the budget lets the radius reach every corner)."""
    far = float(np.hypot(*(search.area.corners - search.bs).T).max())
    assert sector.radius(search) == far
    assert _uncovered(search, sector.plan(search)) <= search.spacing / 2 + 1e-6


def test_parallel_tracks_are_split_into_bands_then_into_pieces() -> None:
    search = Search.of(Mission.build(drones=2))  # 4 km, r = 500 m: tracks at 500 ... 3500
    np.testing.assert_allclose(parallel.tracks(0.0, 4000.0, 1000.0), [500, 1500, 2500, 3500])
    left, right = parallel.plan(search)
    assert set(left[:-1, 0]) == {500.0, 1500.0} and set(right[:-1, 0]) == {2500.0, 3500.0}
    eight = parallel.plan(Search.of(Mission.build(drones=8)))  # two drones per track
    assert [len(route) for route in eight] == [3] * 8
    assert sorted({float(route[0, 0]) for route in eight}) == [500, 1500, 2500, 3500]


def test_one_drone_flies_the_expanding_squares_whole_and_n_drones_share_them() -> None:
    one = expanding.plan(Search.of(Mission.build(drones=1)))[0]
    np.testing.assert_allclose(one, [[1500, 1500], [2500, 1500], [2500, 2500], [1500, 2500],
                                     [1500, 1500], [500, 500], [3500, 500], [3500, 3500],
                                     [500, 3500], [500, 500], [2000, 2000]])
    search = Search.of(Mission.build(drones=4))
    four = expanding.plan(search)
    inner, outer = 4000.0, 12000.0  # perimeters
    for route in four:  # a quarter of each square (a side), the step out across the corner
        # where that side ends and the next square's side starts, and the legs from and home
        assert flight_length(search.bs, route) == pytest.approx(
            math.hypot(500, 500) + inner / 4 + math.hypot(1000, 1000) + outer / 4
            + math.hypot(1500, 1500))


def test_sectors_turn_to_starboard_and_the_second_pass_falls_half_way() -> None:
    search = Search.of(Mission.build(drones=1, flight_time=1e6))
    first, second = (sector.spokes(search, phase, 2000.0) for phase in sector.PASSES)
    angles = [np.unwrap(np.arctan2(*(ends - search.bs).T[::-1])) for ends in (first, second)]
    step = np.diff(angles[0])
    assert (step < 0).all() and np.allclose(step, step[0])  # clockwise, evenly
    np.testing.assert_allclose(angles[1] - angles[0], step[0] / 2)
    np.testing.assert_allclose(np.hypot(*(first - search.bs).T), 2000.0)
    gap = float(np.hypot(*(first[1] - first[0])))  # the fewest spokes whose ends are at most
    assert gap <= search.spacing  # one track space apart
    assert 2 * 2000.0 * math.sin(math.pi / (len(first) - 1)) > search.spacing


def test_a_sector_shrinks_to_a_circle_one_drone_can_fly() -> None:
    search = Search.of(Mission.build(drones=1))
    reach = sector.radius(search)
    assert 0 < reach < float(np.hypot(2000, 2000))
    (route,) = sector.plan(search)
    assert (np.hypot(*(route - search.bs).T) <= reach + 1e-6).all()


def test_patterns_are_route_planners() -> None:
    for pattern in PATTERNS:
        steering = pattern.steering(Mission.build(drones=3))
        assert pattern.kind == "route" and pattern.rule is None and steering.rule is None
        assert not steering.distributed(3).any()


# -- their runs ------------------------------------------------------------------------------

missions = st.builds(
    lambda planner, drones, rc, p_miss, on_detect, flight: Mission.build(
        planner=planner, drones=drones, rc=rc, p_miss=p_miss, on_detect=on_detect,
        flight_time=flight, horizon=900.0),
    planner=st.sampled_from(NAMES),
    drones=st.integers(1, 22),
    rc=st.sampled_from([500.0, 1000.0, 2000.0]),
    p_miss=st.sampled_from([0.0, 0.3]),
    on_detect=st.sampled_from(["continue", "report"]),
    flight=st.sampled_from([700.0, 4000.0]),
)


@given(mission=missions, seed=st.integers(0, 2**32), run=st.integers(0, 10_000))
def test_runs_keep_the_engine_contract(mission: Mission, seed: int, run: int) -> None:
    result = simulate(mission, seed=seed, run=run, trajectory=True)
    traj = result.trajectory
    assert traj is not None
    size = mission.area.size
    assert (traj.positions >= -1e-9).all() and (traj.positions <= size + 1e-9).all()
    if result.t_notify is not None:
        assert result.t_detect is not None and result.t_notify >= result.t_detect
    again = simulate(mission, seed=seed, run=run, trajectory=True)
    assert again.row() == result.row()
    assert again.trajectory is not None
    np.testing.assert_array_equal(again.trajectory.positions, traj.positions)


@pytest.mark.parametrize("name", NAMES)
def test_a_complete_run_of_a_pattern_lands_every_drone_at_the_bs(name: str) -> None:
    mission = Mission.build(planner=name, drones=6, horizon=4000.0)
    result = simulate(mission, seed=3, run=0, trajectory=True)
    traj = result.trajectory
    assert traj is not None
    assert (traj.mode[-1] == Mode.LANDED).all()
    np.testing.assert_allclose(traj.positions[-1], np.tile(mission.area.bs_xy, (6, 1)))


def test_with_ideal_sensing_parallel_track_always_detects_within_its_flight() -> None:
    mission = Mission.build(planner="parallel", drones=6, horizon=4000.0, stop="detected")
    longest = max(flight_length(mission.area.bs_xy, route)
                  for route in get_planner("parallel").steering(mission).routes)
    for run in range(30):
        result = simulate(mission, seed=11, run=run)
        assert result.t_detect is not None and result.t_detect <= longest / mission.team.speed


# -- by name, end to end ---------------------------------------------------------------------

runner = CliRunner()


@pytest.mark.parametrize("name", NAMES)
def test_simulate_flies_a_pattern_by_name(name: str) -> None:
    out = runner.invoke(app, ["simulate", "--planner", name, "--drones", "6", "--rc", "500",
                              "--seed", "4", "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    expected = simulate(Mission.build(planner=name, drones=6, rc=500.0), seed=4)
    assert (data["planner"], data["t_detect"], data["t_notify"]) == (
        name, expected.t_detect, expected.t_notify)


def test_replay_draws_the_patterns_tours(tmp_path) -> None:
    page = tmp_path / "patterns.html"
    out = runner.invoke(app, ["replay", "--planners", "parallel,sector,expanding-square",
                              "--drones", "4", "--rc", "500", "--out", str(page)])
    assert out.exit_code == 0, out.output
    data = re.search(r'id="sarlink-data">(.*?)</script>', page.read_text(), re.S)
    assert data is not None
    panels = json.loads(data.group(1))["panels"]
    assert [p["planner"] for p in panels] == ["parallel", "sector", "expanding-square"]
    for panel in panels:
        mission = Mission.build(planner=panel["planner"], drones=4, rc=500.0)
        routes = get_planner(panel["planner"]).steering(mission).routes
        assert panel["tours"] == [[list(mission.area.bs_xy), *r.tolist()] for r in routes]


# -- in a design ----------------------------------------------------------------------------


def test_design_considers_the_patterns_and_meets_where_parallel_track_must_find(
        tmp_path) -> None:
    """With one hop to the BS from anywhere (r_c beyond the area's diagonal) success is
    detection, and a parallel track team whose every route ends within t_d detects every
    target: that team meets any P_s below 1, so the smallest team found is no larger."""
    from sarlink.design import DesignRequest, design

    base = Mission.build(size=2000.0, rc=2900.0, r=250.0)
    assert {p.name for p in PATTERNS} <= set(DesignRequest(td=500.0, ps=0.5).planners)
    td = 700.0

    def longest(n: int) -> float:
        routes = get_planner("parallel").steering(base.replace(drones=n)).routes
        return max(flight_length(base.area.bs_xy, r) for r in routes) / base.team.speed

    finishing = next(n for n in range(1, 9) if longest(n) <= td)
    request = DesignRequest(mission=base, td=td, ps=0.9, planners=("parallel",),
                            max_drones=8, options={"on_detect": ["continue"]})
    answer = design(request, tmp_path, progress=False)
    (planner,) = answer.planners
    assert planner.smallest is not None and planner.smallest <= finishing
    team = base.replace(planner="parallel", drones=finishing, horizon=td, stop="notified")
    for run in range(40):
        result = simulate(team, seed=2024, run=run)
        assert result.t_notify is not None and result.t_notify == result.t_detect
