"""The kernel's polygon geometry (engine/area.py) against shapely, and the boundary rule."""

from __future__ import annotations

import math

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats
from shapely.geometry import LineString, Point

from polygons import areas
from sarlink import Mission, Scenario, prepare, simulate
from sarlink.config.region import area_polygon
from sarlink.engine.area import clear, contains, edge_array, inward_turn, stays_inside
from sarlink.engine.codes import Mode
from sarlink.engine.paths import Navigation


def _geometry(mission: Mission) -> tuple[shapely.Polygon, np.ndarray]:
    area = area_polygon(mission.region, mission.area.size)
    rings = [np.asarray(area.exterior.coords)] + [np.asarray(h.coords) for h in area.interiors]
    return area, edge_array(rings)


@given(areas(), st.integers(0, 2**32 - 1))
def test_inside_and_crossing_tests_agree_with_shapely(mission: Mission, seed: int) -> None:
    area, edges = _geometry(mission)
    rng = np.random.default_rng(seed)
    lo_x, lo_y, hi_x, hi_y = area.bounds
    pts = rng.uniform((lo_x - 100, lo_y - 100), (hi_x + 100, hi_y + 100), size=(300, 2))
    for x, y in pts:
        if area.boundary.distance(Point(x, y)) > 1e-6:  # on the edge either answer is right
            assert contains(x, y, edges) == area.contains(Point(x, y))
    for (x0, y0), (x1, y1) in zip(pts[::2], pts[1::2], strict=True):
        seg = LineString([(x0, y0), (x1, y1)])
        if abs(seg.distance(area.boundary)) > 1e-6 or seg.crosses(area.boundary):
            assert clear(x0, y0, x1, y1, edges) == (not seg.intersects(area.boundary))


@given(areas(), st.integers(0, 2**32 - 1))
def test_a_drone_under_the_boundary_rule_never_leaves_nor_enters_a_hole(
        mission: Mission, seed: int) -> None:
    """A drone at 5 m per step that keeps its heading until the rule turns it, for 3000
    steps from the BS: every increment lies inside the area (shapely's answer)."""
    area, edges = _geometry(mission)
    rng = np.random.default_rng(seed)
    x, y = mission.area.bs_xy
    theta = rng.random() * 2 * math.pi
    hx, hy = math.cos(theta), math.sin(theta)
    step = 5.0
    turns = 0
    for _ in range(3000):
        hx, hy, turned = inward_turn(x, y, hx, hy, step, edges, rng)
        turns += turned
        nx, ny = x + step * hx, y + step * hy
        assert area.covers(LineString([(x, y), (nx, ny)])) or (hx, hy) == (0.0, 0.0)
        x, y = nx, ny
    assert area.contains(Point(x, y))
    assert turns > 0  # 15 km of straight flight in an area a few km across meets a wall


def test_headings_after_a_wall_are_uniform_over_those_that_stay_inside() -> None:
    """At a straight wall (y = 0, the drone 1 m above it, heading straight into it) the
    increment stays inside for the headings in (-asin(1/5), pi + asin(1/5)): the rule draws
    uniformly from exactly those (Kolmogorov-Smirnov against that uniform law)."""
    edges = edge_array([np.array([(-1e4, 0), (1e4, 0), (1e4, 1e4), (-1e4, 1e4)], float)])
    rng = np.random.default_rng(5)
    angles = []
    for _ in range(4000):
        hx, hy, turned = inward_turn(0.0, 1.0, 0.0, -1.0, 5.0, edges, rng)
        assert turned
        angles.append(math.atan2(hy, hx))
    a = np.asarray(angles)
    a = np.where(a < -math.pi / 2, a + 2 * math.pi, a)
    lo = -math.asin(1 / 5)
    assert a.min() > lo and a.max() < math.pi - lo
    assert stats.kstest(a, stats.uniform(lo, math.pi - 2 * lo).cdf).pvalue > 1e-3


def test_a_drone_boxed_in_hovers() -> None:
    """In a sliver narrower than a step no heading fits: the drone stays put."""
    edges = edge_array([np.array([(0, 0), (3, 0), (3, 3), (0, 3)], float)])
    assert not stays_inside(1.5, 1.5, 1.0, 0.0, 5.0, edges)
    assert inward_turn(1.5, 1.5, 1.0, 0.0, 5.0, edges, np.random.default_rng(0)) == \
        (0.0, 0.0, True)


def test_a_hovering_drone_draws_again() -> None:
    """A hover lasts one step: where headings fit again, a drone at rest turns to one of them
    (a zero heading, though its increment "stays inside", is not kept)."""
    edges = edge_array([np.array([(0, 0), (100, 0), (100, 100), (0, 100)], float)])
    hx, hy, turned = inward_turn(50.0, 50.0, 0.0, 0.0, 5.0, edges, np.random.default_rng(0))
    assert turned and math.isclose(math.hypot(hx, hy), 1.0)
    assert stays_inside(50.0, 50.0, hx, hy, 5.0, edges)


@given(areas(holes=3), st.integers(0, 2**32 - 1))
def test_shortest_paths_stay_inside_and_bound_every_flight_home(mission: Mission,
                                                                seed: int) -> None:
    """Between random points the path bends only inside the area, is no shorter than the
    straight line, and no flight home from anywhere is longer than the bound the kernel
    uses to know when drones may be due home."""
    area, _ = _geometry(mission)
    nav = Navigation(area)
    _, far = nav.home(mission.area.bs_xy)
    rng = np.random.default_rng(seed)
    lo_x, lo_y, hi_x, hi_y = area.bounds
    points = [p for p in rng.uniform((lo_x, lo_y), (hi_x, hi_y), size=(40, 2))
              if area.contains(Point(p))][:8]
    for a, b in zip(points, [*points[1:], np.asarray(mission.area.bs_xy)], strict=False):
        path = np.vstack([a, nav.path(tuple(a), tuple(b))])
        assert area.covers(LineString(path)) if len(path) > 1 else True
        length = float(np.hypot(*np.diff(path, axis=0).T).sum())
        assert length >= math.dist(a, b) - 1e-9
        if tuple(b) == mission.area.bs_xy:
            assert length <= far


def test_a_flight_home_goes_round_a_hole() -> None:
    """The BS behind a wall-like hole: the shortest way passes the hole's end corner."""
    outline = [(0, 0), (1000, 0), (1000, 1000), (0, 1000)]
    hole = [(200, 480), (1000 - 100, 480), (1000 - 100, 520), (200, 520)]
    m = Mission.from_dict({"area": {"bs": (500.0, 100.0)},
                           "region": {"outline": outline, "holes": [hole]}})
    area, _ = _geometry(m)
    path = Navigation(area).path((500.0, 900.0), (500.0, 100.0))
    assert len(path) == 3  # round the nearer, west end: two bends there, then the BS
    assert all(195 < p[0] < 200 for p in path[:-1])


@settings(max_examples=12)
@given(areas(), st.sampled_from(["covb", "conb", "mtsp-conb"]), st.integers(0, 1000))
def test_whole_runs_stay_inside_and_every_drone_comes_home(mission: Mission, planner: str,
                                                            run: int) -> None:
    """The engine on random polygons with holes: at every step every drone's increment lies
    inside the area and out of the holes (searching, flying its route, home or to report),
    and with a flight budget shorter than the run every distributed drone has landed at the
    BS (route drones land at their route's end, whatever its length). Every drone that
    learns where the target is flies to tell the BS and back to its tour."""
    flown = mission.replace(planner=planner, drones=4, nr=2, flight_time=1200.0,
                            horizon=2000.0, on_detect="report", iterations=200)
    result = simulate(flown, seed=3, run=run, trajectory=True)
    traj = result.trajectory
    assert traj is not None
    area = area_polygon(flown.region, flown.area.size).buffer(1e-6)
    pos = traj.positions
    legs = shapely.linestrings(np.stack([pos[:-1], pos[1:]], axis=2).reshape(-1, 2, 2))
    assert shapely.covers(area, legs).all()
    distributed = prepare(flown).distributed
    assert (traj.mode[-1, distributed] == Mode.LANDED).all()
    assert np.allclose(pos[-1, distributed], flown.area.bs_xy)


def test_a_route_drone_reports_and_rejoins_its_tour_round_a_wall() -> None:
    """One mTSP drone finds the target north of an east-west wall, flies round it to tell
    the BS in the south (r_c = 50 m: no link across), and flies back round it to where it
    left its tour; no increment enters the wall, and it does reach that point."""
    outline = [(0, 0), (2000, 0), (2000, 2000), (0, 2000)]
    wall = [(0 + 300, 980), (2000 - 50, 980), (2000 - 50, 1020), (300, 1020)]
    m = Mission.from_dict({"area": {"bs": (1000.0, 200.0)},
                           "team": {"planner": "mtsp", "drones": 1, "on_detect": "report"},
                           "channel": {"rc": 50.0}, "timing": {"horizon": 4000.0},
                           "region": {"outline": outline, "holes": [wall]}})
    result = simulate(m, seed=0, run=0, scenario=Scenario(target=(1000.0, 1800.0)),
                      trajectory=True)
    traj = result.trajectory
    assert traj is not None and result.t_detect is not None and result.t_notify is not None
    area = area_polygon(m.region, m.area.size).buffer(1e-6)
    pos = traj.positions[:, 0]
    assert shapely.covers(area, shapely.linestrings(np.stack([pos[:-1], pos[1:]], axis=1))).all()
    left = pos[int(result.t_detect)]  # where it left its tour: where it learned
    after = pos[int(result.t_notify):]
    via = np.hypot(*(after[:-1] - left).T) + np.hypot(*(after[1:] - left).T)
    assert via.min() <= 5.0 + 1e-9  # one step of 5 m passes through that very point
    assert pos[int(result.t_notify)][1] < 980  # it told the BS from south of the wall
