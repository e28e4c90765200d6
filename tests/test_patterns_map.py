"""The search patterns on an area on the map: planned over its bounding box, clipped to the
polygon, flown around its holes and home within the budget (planners/patterns/polygon.py)."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString

from polygons import areas
from sarlink import Mission, get_planner, simulate
from sarlink.config.region import EDGE, area_polygon
from sarlink.engine.codes import Mode
from sarlink.planners.patterns import PATTERNS, expanding, parallel, sector
from sarlink.planners.patterns.base import Search
from sarlink.planners.patterns.geometry import flight_length
from sarlink.planners.patterns.polygon import INSET, MIN_PIECE

NAMES = [p.name for p in PATTERNS]
PLANS = {"parallel": parallel.plan, "expanding-square": expanding.plan, "sector": sector.plan}


def _teams(budget: st.SearchStrategy[float]) -> st.SearchStrategy[Mission]:
    return st.builds(
        lambda mission, drones, r, flight: mission.replace(
            drones=drones, r=r, flight_time=flight, horizon=min(flight, 4000.0)),
        areas(), st.integers(1, 12), st.floats(100.0, 1200.0), budget)


def _legs(search: Search, route: np.ndarray) -> np.ndarray:
    path = np.vstack([search.bs, route])
    return shapely.linestrings(np.stack([path[:-1], path[1:]], axis=1))


@pytest.mark.parametrize("name", NAMES)
@settings(max_examples=30, deadline=None)
@given(mission=_teams(st.sampled_from([300.0, 1500.0, 4000.0])))
def test_on_the_map_every_leg_stays_in_the_area_and_every_route_fits_the_budget(
        name: str, mission: Mission) -> None:
    """Each leg flown straight (as the engine flies a route) lies in the polygon, never across
    a hole; every route ends at the BS; its flight, landing included, fits the budget."""
    routes = get_planner(name).steering(mission.replace(planner=name)).routes
    search = Search.of(mission)
    area = area_polygon(mission.region, mission.area.size)
    assert len(routes) == mission.team.drones
    for route in routes:
        assert shapely.dwithin(area, shapely.points(route), EDGE).all()
        assert shapely.covers(area.buffer(EDGE), _legs(search, route)).all()
        np.testing.assert_array_equal(route[-1], mission.area.bs_xy)
        assert flight_length(search.bs, route) <= search.budget + 1e-6


@pytest.mark.parametrize("name", NAMES)
@settings(max_examples=30, deadline=None)
@given(mission=_teams(st.just(1e7)))
def test_on_the_map_every_part_of_the_plan_inside_the_area_is_flown(
        name: str, mission: Mission) -> None:
    """With budget to spare, the pattern's legs are flown wherever they lie in the area (an
    inset's width inside its edges), so the area is searched as the pattern searches the
    bounding box; only the flights between those parts are new."""
    search = Search.of(mission)
    flown = get_planner(name).steering(mission.replace(planner=name)).routes
    inner = area_polygon(mission.region, mission.area.size).buffer(-INSET, join_style="mitre")
    for plan, route in zip(PLANS[name](search), flown, strict=True):
        line = LineString(np.vstack([search.bs, route])).buffer(1e-6)
        for leg in _legs(search, plan):
            for piece in shapely.get_parts(shapely.intersection(leg, inner)):
                if isinstance(piece, LineString) and piece.length >= MIN_PIECE:
                    assert line.covers(piece)


squares_on_the_map = st.builds(
    lambda size, bx, by, drones, r: Mission.from_dict({
        "area": {"size": size, "bs": (bx * size, by * size)},
        "region": {"outline": [(0.0, 0.0), (size, 0.0), (size, size), (0.0, size)]},
        "team": {"drones": drones, "flight_time": 1e7},
        "sensing": {"r": r}, "timing": {"horizon": 1000.0}}),
    st.floats(500.0, 5000.0), st.floats(0.01, 0.99), st.floats(0.01, 0.99),
    st.integers(1, 12), st.floats(150.0, 1200.0))


def _farthest(mission: Mission, routes: tuple[np.ndarray, ...], points: int = 31) -> float:
    """The largest distance from a grid point of the square to the nearest drone's path."""
    size = mission.area.size
    grid = shapely.points(list(itertools.product(np.linspace(0, size, points), repeat=2)))
    paths = [LineString(np.vstack([mission.area.bs_xy, route])) if len(route) else
             shapely.Point(mission.area.bs_xy) for route in routes]
    return float(np.min([shapely.distance(grid, path) for path in paths], axis=0).max())


@settings(max_examples=40, deadline=None)
@given(mission=squares_on_the_map)
def test_the_square_drawn_on_the_map_is_searched_as_the_square_is(mission: Mission) -> None:
    """A square outline is the paper's area: parallel track covers every point within r, and
    expanding squares within √2 r, as on the square (tests/test_patterns.py), but for the
    inset the clipped legs keep from the edges."""
    r = mission.sensing.r
    tracks = get_planner("parallel").steering(mission.replace(planner="parallel")).routes
    assert _farthest(mission, tracks) <= r + INSET + 1e-6
    squares = get_planner("expanding-square").steering(
        mission.replace(planner="expanding-square")).routes
    assert _farthest(mission, squares) <= math.sqrt(2) * r + INSET + 1e-6


@pytest.mark.parametrize("name", NAMES)
def test_a_pattern_flies_the_valley_and_every_drone_lands(name: str) -> None:
    """End to end on the worked example of docs/missions.md: the engine flies the routes, no
    drone leaves the area or enters the no-fly zone, and every one lands at the BS."""
    mission = Mission.from_dict({"team": {"planner": name, "drones": 4},
                                 "region": {"area": "examples/valley.geojson"},
                                 "timing": {"horizon": 4000.0}})
    result = simulate(mission, seed=2, run=1, trajectory=True)
    traj = result.trajectory
    assert traj is not None
    area = area_polygon(mission.region, mission.area.size)
    assert shapely.dwithin(area, shapely.points(traj.positions.reshape(-1, 2)), 1e-6).all()
    assert (traj.mode[-1] == Mode.LANDED).all()
    np.testing.assert_allclose(traj.positions[-1], np.tile(mission.area.bs_xy, (4, 1)))


@given(tracks=st.lists(st.floats(0.0, 5000.0), min_size=1, max_size=30).flatmap(
    lambda lengths: st.tuples(st.just(lengths), st.integers(1, len(lengths)))))
def test_bands_of_tracks_are_contiguous_and_even_up_to_one_track(
        tracks: tuple[list[float], int]) -> None:
    """Every track in one band, bands in order, none empty, and no band longer than an equal
    share plus two of the longest track (each cut at the track boundary nearest its share,
    unless a band would be left empty). At most as many drones as tracks, drawn so (filtering
    the draws failed Hypothesis's health check now and then)."""
    lengths, drones = tracks
    weights = np.array(lengths)
    bands = parallel._balanced(weights, drones)
    assert len(bands) == drones and all(len(b) for b in bands)
    np.testing.assert_array_equal(np.concatenate(bands), np.arange(len(weights)))
    longest = max(float(weights[b].sum()) for b in bands)
    assert longest <= weights.sum() / drones + 2 * weights.max() + 1e-6


def test_on_the_map_parallel_track_bands_share_the_track_length_inside_the_area() -> None:
    """The valley is wider than tall: its tracks run east-west, S apart across its bounding
    box, and each drone flies the band of them that the track lengths inside the area
    (computed here with shapely) share out."""
    mission = Mission.from_dict({"team": {"planner": "parallel", "drones": 3},
                                 "sensing": {"r": 250.0},
                                 "region": {"area": "examples/valley.geojson"}})
    area = area_polygon(mission.region, mission.area.size)
    x0, y0, x1, y1 = area.bounds
    assert x1 - x0 > y1 - y0
    ys = parallel.tracks(y0, y1, 2 * mission.sensing.r)
    inner = area.buffer(-INSET, join_style="mitre")
    lengths = np.array([LineString([(x0, y), (x1, y)]).intersection(inner).length for y in ys])
    routes = get_planner("parallel").steering(mission).routes
    for band, route in zip(parallel._balanced(lengths, 3), routes, strict=True):
        flown = {y for y in ys if np.isclose(route[:, 1], y).sum() >= 2}
        assert flown == set(ys[band].tolist())
