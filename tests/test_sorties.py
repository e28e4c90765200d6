"""Routes cut into battery-sized sorties (sarlink.export.sorties): every sortie, read back
from the .waypoints file the autopilot gets, fits the battery; each is cut as late as it can
be (against a brute-force scan along the route); each resumes a fixed overlap before where
the last one turned home, so together they search the whole route; none trips the fence; a
route no sortie can fly is refused in one line."""

from __future__ import annotations

import itertools
import json
import re
from pathlib import Path

import numpy as np
import pytest
from pymavlink import mavwp
from shapely.geometry import LineString, Polygon

from sarlink import ConfigError, Mission
from sarlink.config.region import area_polygon
from sarlink.engine.energy import Flight, get_energy_model
from sarlink.engine.paths import Navigation
from sarlink.export import export_mission, mission_frame
from sarlink.export.sorties import RESUME_OVERLAP, battery_budget, split_route
from sarlink.planners import get_planner

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
MAV_FRAME_GLOBAL_RELATIVE_ALT = 3


@pytest.fixture(scope="module", params=["zeng2019", "rodrigues2021"])
def valley(request: pytest.FixtureRequest) -> Mission:
    """The docs' example: the valley, two mTSP drones at 8 m/s, a 25-minute battery (hover
    power times 25 minutes) of the model."""
    hover = get_energy_model(request.param).power(0.0)
    return Mission.from_dict({
        "team": {"planner": "mtsp", "drones": 2, "speed": 8.0},
        "battery": {"battery_wh": round(hover * 25 / 60, 1), "energy_model": request.param},
        "region": {"area": str(EXAMPLES / "valley.geojson")}})


def _routes(mission: Mission) -> tuple[np.ndarray, ...]:
    return get_planner(mission.team.planner).steering(mission.searching()).routes


def _flown(path: Path, mission: Mission) -> np.ndarray:
    """The level flight of a .waypoints file, as pymavlink reads it, in the mission's frame:
    from the take-off point through every waypoint to the landing point."""
    loader = mavwp.MAVWPLoader()
    loader.load(str(path))
    points = [w for w in map(loader.wp, range(1, loader.count()))  # after the home line
              if w.frame == MAV_FRAME_GLOBAL_RELATIVE_ALT]  # take-off, waypoints, landing
    x, y = mission_frame(mission).to_local([w.y for w in points], [w.x for w in points])
    return np.column_stack([x, y])


def _energy(mission: Mission, level: float, altitude: float) -> float:
    return Flight(level, mission.team.speed, altitude).energy(
        get_energy_model(mission.energy_model))


def test_every_sortie_fits_the_battery_as_the_autopilot_flies_it(tmp_path: Path,
                                                                   valley: Mission) -> None:
    """Each sortie's .waypoints, read by pymavlink, flown at the mission's speed with the
    climb and the landing, takes at most what a sortie may use; every sortie but the last
    of a drone takes it all (to a metre's worth)."""
    out = export_mission(valley, tmp_path, altitude=60.0)
    budget = battery_budget(valley)
    assert budget == pytest.approx(valley.battery.battery_wh * 3600 * 0.8)
    metre = get_energy_model(valley.energy_model).per_metre(valley.team.speed)
    for drone in out.drones:
        assert len(drone.sorties) >= 2
        for sortie in drone.sorties:
            plan, wpl = sortie.files
            assert (plan.name, wpl.name) == (f"drone-{drone.drone:02d}-sortie-{sortie.number}"
                                             ".plan", wpl.stem + ".waypoints")
            track = _flown(wpl, valley)
            length = float(np.hypot(*np.diff(track, axis=0).T).sum())
            assert length == pytest.approx(sortie.length, abs=0.05)
            energy = _energy(valley, length, 60.0)
            assert energy == pytest.approx(sortie.energy, abs=0.05 * metre)
            assert energy <= budget + 0.05 * metre
            if sortie.number < len(drone.sorties):
                assert energy >= budget - metre


def test_sorties_resume_where_the_last_turned_home_and_search_the_whole_route(
        valley: Mission) -> None:
    """Each sortie's search starts RESUME_OVERLAP metres before where the last one turned
    home, and passes through that point of the route; the first starts at the BS, the last
    ends there: together they fly the whole route."""
    for i, route in enumerate(_routes(valley)):
        sorties = split_route(valley, i, route, 50.0)
        path = np.vstack([valley.area.bs_xy, route])
        cum = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(path, axis=0).T))])
        assert sorties[0].start == 0.0 and sorties[-1].end == pytest.approx(cum[-1])
        for before, after in itertools.pairwise(sorties):
            assert after.start == pytest.approx(before.end - RESUME_OVERLAP)
            resume = np.array([np.interp(after.start, cum, path[:, k]) for k in (0, 1)])
            assert np.hypot(*(after.waypoints - resume).T).min() < 1e-6
        for sortie in sorties:  # the route's vertices in its stretch are all flown
            inner = path[(cum > sortie.start) & (cum < sortie.end)]
            for point in inner:
                assert np.hypot(*(sortie.waypoints - point).T).min() < 1e-9


def test_each_cut_is_the_last_point_that_fits(valley: Mission) -> None:
    """Against a brute-force scan of the route in half-metre steps: the last point where a
    sortie from the same start, out the shortest way and home the shortest way (computed
    here with the area's visibility graph), still fits."""
    nav = Navigation(area_polygon(valley.region, valley.area.size))
    bs = np.asarray(valley.area.bs_xy)
    budget = battery_budget(valley)
    assert budget is not None

    def home(p: np.ndarray) -> float:
        return float(np.hypot(*np.diff(np.vstack([p, nav.path(tuple(p), tuple(bs))]),
                                       axis=0).T).sum())

    route = _routes(valley)[0]
    path = np.vstack([bs, route])
    cum = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(path, axis=0).T))])
    sorties = split_route(valley, 0, route, 50.0)
    for sortie in sorties[:-1]:
        start = np.array([np.interp(sortie.start, cum, path[:, k]) for k in (0, 1)])
        out = home(start) if sortie.start > 0 else 0.0
        steps = np.arange(sortie.start, cum[-1], 0.5)
        points = np.column_stack([np.interp(steps, cum, path[:, k]) for k in (0, 1)])
        fits = [_energy(valley, out + s - sortie.start + home(p), 50.0) <= budget
                for s, p in zip(steps, points, strict=True)]
        last = steps[len(fits) - 1 - fits[::-1].index(True)]
        assert sortie.end == pytest.approx(last, abs=0.5)


def test_no_sortie_trips_the_fence(tmp_path: Path, valley: Mission) -> None:
    """Out, along the route and home, every sortie's legs stay in the valley and out of its
    no-fly zone, as the .plan's own fence draws them."""
    out = export_mission(valley, tmp_path)
    plans = [s.files[0] for d in out.drones for s in d.sorties]
    assert len(plans) >= 4
    for path in plans:
        plan = json.loads(path.read_text())
        legs = [i["params"][4:6] for i in plan["mission"]["items"]
                if i["frame"] == MAV_FRAME_GLOBAL_RELATIVE_ALT and i["params"][4] is not None]
        flight = LineString([(lon, lat) for lat, lon in legs])
        for fence in plan["geoFence"]["polygons"]:
            zone = Polygon(np.asarray(fence["polygon"])[:, ::-1])
            if fence["inclusion"]:
                assert zone.covers(flight)
            else:
                assert not flight.intersects(zone.buffer(-1e-7))


def test_without_a_battery_the_route_is_one_flight(tmp_path: Path) -> None:
    """No battery: one sortie, the route itself, under the files' old names; an energy
    model alone predicts its energy without cutting it."""
    mission = Mission.from_dict({"team": {"planner": "mtsp", "drones": 2},
                                 "battery": {"energy_model": "zeng2019"},
                                 "region": {"area": str(EXAMPLES / "valley.geojson")}})
    out = export_mission(mission, tmp_path)
    for drone, route in zip(out.drones, _routes(mission), strict=True):
        [sortie] = drone.sorties
        assert sortie.length == pytest.approx(drone.length)
        assert sortie.energy == pytest.approx(_energy(mission, drone.length, 50.0))
        assert [p.name for p in sortie.files] == [f"drone-{drone.drone:02d}.plan",
                                                  f"drone-{drone.drone:02d}.waypoints"]
        assert len(route) + 4 == mavwp.MAVWPLoader().load(str(sortie.files[1]))


def test_a_battery_too_small_for_a_round_trip_is_refused_and_nothing_is_written(
        tmp_path: Path, valley: Mission) -> None:
    small = valley.replace(battery_wh=valley.battery.battery_wh / 2)
    with pytest.raises(ConfigError, match=r"--battery-wh .*: drone 0's route cannot be flown "
                       r"in sorties of this battery: its farthest waypoint, ([\d.]+) km from "
                       r"the BS, takes ([\d.]+) Wh out and back .* may use ([\d.]+) Wh") as err:
        export_mission(small, tmp_path / "plans")
    assert "\n" not in str(err.value) and "--speed nearer" in str(err.value)
    found = re.search(r"farthest waypoint, ([\d.]+) km .* takes ([\d.]+) Wh .* may use "
                      r"([\d.]+) Wh", str(err.value))
    assert found is not None
    far, need, allowed = map(float, found.groups())
    assert need > allowed == pytest.approx(small.battery.battery_wh * 0.8, abs=0.05)
    assert need == pytest.approx(_energy(small, 2000 * far, 50.0) / 3600, abs=0.1)
    assert not (tmp_path / "plans").exists()
