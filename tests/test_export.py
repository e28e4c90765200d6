"""``sarlink export``: .plan files pass QGroundControl's loader rules, and MAVSDK (an
autopilot client's own importer and mission uploader) imports each one and uploads it to a
vehicle stand-in of either autopilot, which receives the route; .waypoints load with pymavlink
field for field as the .plan's items; coordinates round-trip to the simulated routes, the
fence (in the .plan and in fence.waypoints, loaded by pymavlink's fence loader and checked
against ArduPilot's rules) is the mission's area, and the GeoJSON validates (geojson-pydantic
and geojson-validator: RFC 7946's structure, winding and valid geometries)."""

from __future__ import annotations

import json
import math
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import geojson_validator
import numpy as np
import pytest
from geojson_pydantic import FeatureCollection
from pymavlink import mavutil, mavwp
from shapely.geometry import LineString, MultiPoint, Polygon, shape

from mavlink_vehicle import upload
from sarlink import ConfigError, Mission, simulate
from sarlink.config.region import area_polygon
from sarlink.export import RELAY_NOTE, TRACK_POINTS, export_mission, mission_frame
from sarlink.export.sorties import split_route
from sarlink.planners import get_planner

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
MAV_AUTOPILOT_PX4 = 12  # the MAVLink common message set's MAV_AUTOPILOT enum
MAV_AUTOPILOT_ARDUPILOTMEGA = 3
MAV_CMD_NAV_WAYPOINT = 16
MAV_CMD_NAV_LAND = 21
MAV_CMD_NAV_TAKEOFF = 22
MAV_CMD_DO_CHANGE_SPEED = 178
MAV_FRAME_GLOBAL = 0
MAV_FRAME_MISSION = 2
MAV_FRAME_GLOBAL_RELATIVE_ALT = 3
MAV_FRAME_GLOBAL_INT = 5
MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION = 5001
MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION = 5002
GLOBAL_FRAMES = {0, 3, 5, 6, 10, 11}
"""MAV_FRAME_GLOBAL, _RELATIVE_ALT, _INT, _RELATIVE_ALT_INT, _TERRAIN_ALT, _TERRAIN_ALT_INT: the
frames ArduPilot takes a fence item in."""


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def qgc_plan_problems(plan: Any) -> list[str]:
    """Every rule QGroundControl's plan loader enforces (PlanMasterController::loadFromFile,
    JsonHelper::validateExternalQGCJsonFile, MissionController::_loadJsonMissionFileV2,
    MissionItem::load, GeoFenceController::load, RallyPointController::load) that ``plan``
    breaks."""
    bad = []
    if not isinstance(plan, dict):
        return ["not a JSON object"]
    if not isinstance(plan.get("groundStation"), str):
        bad.append("groundStation must be a string")
    if plan.get("fileType") != "Plan":
        bad.append("fileType must be Plan")
    if not (_number(plan.get("version")) and int(plan["version"]) == 1):
        bad.append("Plan file version must be 1")
    for key in ("mission", "geoFence", "rallyPoints"):
        if not isinstance(plan.get(key), dict):
            bad.append(f"{key} must be an object")
    if bad:
        return bad
    mission = plan["mission"]
    if mission.get("version") != 2:
        bad.append("mission version must be 2")
    home = mission.get("plannedHomePosition")
    if not (isinstance(home, list) and len(home) == 3 and all(map(_number, home))
            and -90 <= home[0] <= 90 and -180 <= home[1] <= 180):
        bad.append("plannedHomePosition must be [lat, lon, alt]")
    if not isinstance(mission.get("items"), list):
        bad.append("items must be an array")
    if not _number(mission.get("firmwareType")):
        bad.append("firmwareType must be a number")
    for key in ("vehicleType", "cruiseSpeed", "hoverSpeed", "globalPlanAltitudeMode"):
        if key in mission and not _number(mission[key]):
            bad.append(f"{key} must be a number")
    jump_ids = []
    for k, item in enumerate(mission.get("items") or []):
        if not isinstance(item, dict) or item.get("type") != "SimpleItem":
            bad.append(f"item {k} must be a SimpleItem object")
            continue
        for key in ("frame", "command"):
            if not _number(item.get(key)):
                bad.append(f"item {k}: {key} must be a number")
        if not isinstance(item.get("autoContinue"), bool):
            bad.append(f"item {k}: autoContinue must be a boolean")
        params = item.get("params")
        if not (isinstance(params, list) and len(params) == 7):
            bad.append(f"item {k}: params must hold 7 values")
        elif not all(_number(p) or p is None for p in params):
            bad.append(f"item {k}: params must be numbers or null")
        if "doJumpId" in item:
            if not _number(item["doJumpId"]):
                bad.append(f"item {k}: doJumpId must be a number")
            jump_ids.append(item["doJumpId"])
    if jump_ids != list(range(1, len(jump_ids) + 1)):
        bad.append("doJumpId must number the items from 1 (home is 0)")
    fence, rally = plan["geoFence"], plan["rallyPoints"]
    if not (fence.get("version") == 2 and isinstance(fence.get("circles"), list)
            and isinstance(fence.get("polygons"), list)):
        bad.append("geoFence must have version 2, circles and polygons")
    else:
        bad += fence_problems(fence)
    if not (rally.get("version") == 2 and isinstance(rally.get("points"), list)):
        bad.append("rallyPoints must have version 2 and points")
    return bad


def fence_problems(fence: dict[str, Any]) -> list[str]:
    """The rules QGroundControl's fence loader enforces (src/MissionManager/
    GeoFenceController.cc ``load``: an optional ``breachReturn`` [lat, lon, alt]; each polygon
    an object, read by QGCFencePolygon.cc ``loadFromJson``: ``version`` 1 and a boolean
    ``inclusion``, then QGCMapPolygon.cc ``loadFromJson``: a required ``polygon`` read by
    JsonHelper ``loadGeoCoordinateArray``/``loadGeoCoordinate``: an array of coordinates of
    exactly two numbers, [lat, lon]), the coordinates valid (QGeoCoordinate), and MAVLink's
    rules for a fence polygon (common.xml, MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION: at least
    3 vertices, not self-intersecting)."""
    bad = []
    if "breachReturn" in fence:
        point = fence["breachReturn"]
        if not (isinstance(point, list) and len(point) == 3 and all(map(_number, point))):
            bad.append("breachReturn must be [lat, lon, alt]")
    for k, polygon in enumerate(fence["polygons"]):
        if not isinstance(polygon, dict):
            bad.append(f"fence polygon {k} must be an object")
            continue
        if not (_number(polygon.get("version")) and int(polygon["version"]) == 1):
            bad.append(f"fence polygon {k}: version must be 1")
        if not isinstance(polygon.get("inclusion"), bool):
            bad.append(f"fence polygon {k}: inclusion must be true or false")
        ring = polygon.get("polygon")
        if not (isinstance(ring, list) and all(
                isinstance(v, list) and len(v) == 2 and all(map(_number, v)) for v in ring)):
            bad.append(f"fence polygon {k}: polygon must be an array of [lat, lon]")
            continue
        if not all(-90 <= lat <= 90 and -180 <= lon <= 180 for lat, lon in ring):
            bad.append(f"fence polygon {k}: a vertex is not a latitude, longitude")
        elif len(ring) < 3:
            bad.append(f"fence polygon {k}: at least 3 vertices")
        elif not LineString([*ring, ring[0]]).is_simple:
            bad.append(f"fence polygon {k}: its edges must not cross")
    return bad


def ardupilot_fence_problems(items: list[Any]) -> list[str]:
    """The rules ArduPilot checks on an uploaded fence (libraries/GCS_MAVLink/
    MissionItemProtocol_Fence.cpp ``convert_MISSION_ITEM_INT_to_AC_PolyFenceItem``: a global
    frame, a vertex count of at most 255; libraries/AC_Fence/AC_PolyFence_loader.cpp
    ``validate_fence``: at least 3 vertices, each polygon's vertices one after another with
    the same type and count, no polygon left unfinished, valid latitudes and longitudes).
    sarlink writes polygon vertices only, so any other item is reported too."""
    bad = []
    left, kind, count = 0, 0, 0
    for k, w in enumerate(items):
        if w.command not in (MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION,
                             MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION):
            bad.append(f"item {k}: command {w.command} is not a polygon vertex")
            continue
        if w.frame not in GLOBAL_FRAMES:
            bad.append(f"item {k}: frame {w.frame} is not a global frame")
        if not 3 <= w.param1 <= 255:
            bad.append(f"item {k}: vertex count {w.param1:g} not in 3..255")
        if left == 0:
            left, kind, count = int(w.param1), w.command, int(w.param1)
        elif (w.command, int(w.param1)) != (kind, count):
            bad.append(f"item {k}: a vertex of another polygon before the last one ended")
        left -= 1
        if not (-90 <= w.x <= 90 and -180 <= w.y <= 180):
            bad.append(f"item {k}: bad lat or lon")
    if left > 0:
        bad.append("the last polygon lacks vertices")
    return bad


def _rings(plan: dict[str, Any]) -> list[tuple[bool, np.ndarray]]:
    """(inclusion, [lat, lon] vertices) of a .plan's fence polygons."""
    return [(p["inclusion"], np.asarray(p["polygon"], dtype=float))
            for p in plan["geoFence"]["polygons"]]


@pytest.fixture(scope="module")
def valley() -> Mission:
    return Mission.from_dict({
        "team": {"planner": "mtsp-conb", "drones": 5, "nr": 3},
        "region": {"area": str(EXAMPLES / "valley.geojson"),
                   "prior": str(EXAMPLES / "valley-prior.geojson")}})


@pytest.mark.parametrize(("firmware", "code"), [("px4", MAV_AUTOPILOT_PX4),
                                                ("ardupilot", MAV_AUTOPILOT_ARDUPILOTMEGA)])
def test_plans_pass_qgroundcontrols_loader_rules(tmp_path: Path, valley: Mission,
                                                 firmware: str, code: int) -> None:
    out = export_mission(valley, tmp_path, firmware=firmware, altitude=60.0)  # type: ignore[arg-type]
    plans = sorted(tmp_path.glob("*.plan"))
    assert [p.name for p in plans] == ["drone-00.plan", "drone-01.plan", "drone-02.plan"]
    frame = mission_frame(valley)
    for path in plans:
        plan = json.loads(path.read_text())
        assert qgc_plan_problems(plan) == []
        mission = plan["mission"]
        assert mission["firmwareType"] == code
        lat, lon, _ = mission["plannedHomePosition"]
        assert (lon, lat) == pytest.approx(frame.anchor, abs=1e-9)
        waypoints = [i for i in mission["items"] if i["command"] == MAV_CMD_NAV_WAYPOINT]
        assert waypoints and all(i["frame"] == MAV_FRAME_GLOBAL_RELATIVE_ALT and
                                 i["params"][6] == 60.0 for i in waypoints)
    assert [d.kind for d in out.drones] == ["route"] * 3 + ["distributed"] * 2
    assert out.notes and "no file can hold their flight" in out.notes[0]


def test_a_broken_plan_breaks_the_rules() -> None:
    """The checker above can fail: each rule on a plan that breaks it."""
    plan = {"fileType": "Plan", "version": 1, "groundStation": "QGroundControl",
            "mission": {"version": 2, "firmwareType": 12, "plannedHomePosition": [46.0, 7.0],
                        "items": [{"type": "SimpleItem", "command": 16, "frame": 3,
                                   "params": [0, 0, 0, None, 46.0, 7.0], "autoContinue": True,
                                   "doJumpId": 2}]},
            "geoFence": {"version": 1, "polygons": []}, "rallyPoints": {"points": []}}
    problems = qgc_plan_problems(plan)
    assert problems == ["plannedHomePosition must be [lat, lon, alt]",
                        "item 0: params must hold 7 values",
                        "doJumpId must number the items from 1 (home is 0)",
                        "geoFence must have version 2, circles and polygons",
                        "rallyPoints must have version 2 and points"]


VALID_PLAN = {"fileType": "Plan", "version": 1, "groundStation": "QGroundControl",
              "mission": {"version": 2, "firmwareType": 12, "plannedHomePosition": [46, 7, 0],
                          "items": []},
              "rallyPoints": {"version": 2, "points": []}}
SQUARE = [[46.0, 7.0], [46.0, 7.01], [46.01, 7.01], [46.01, 7.0]]


@pytest.mark.parametrize(("fence", "problem"), [
    ({"breachReturn": [46.0, 7.0]}, "breachReturn must be [lat, lon, alt]"),
    ({"polygons": [SQUARE]}, "fence polygon 0 must be an object"),
    ({"polygons": [{"inclusion": True, "polygon": SQUARE}]}, "version must be 1"),
    ({"polygons": [{"version": 2, "inclusion": True, "polygon": SQUARE}]}, "version must be 1"),
    ({"polygons": [{"version": 1, "inclusion": 1, "polygon": SQUARE}]}, "true or false"),
    ({"polygons": [{"version": 1, "inclusion": True}]}, "array of [lat, lon]"),
    ({"polygons": [{"version": 1, "inclusion": True, "polygon": [[46.0, 7.0, 0.0]] * 3}]},
     "array of [lat, lon]"),
    ({"polygons": [{"version": 1, "inclusion": False, "polygon": [[146.0, 7.0]] * 3}]},
     "not a latitude, longitude"),
    ({"polygons": [{"version": 1, "inclusion": False, "polygon": SQUARE[:2]}]},
     "at least 3 vertices"),
    ({"polygons": [{"version": 1, "inclusion": True,  # a bow tie
                    "polygon": [SQUARE[0], SQUARE[2], SQUARE[1], SQUARE[3]]}]},
     "must not cross"),
])
def test_a_broken_fence_breaks_the_rules(fence: dict[str, Any], problem: str) -> None:
    """The fence checker can fail: each rule on a fence that breaks it (and only that one)."""
    good = {"version": 2, "circles": [], "polygons": [
        {"version": 1, "inclusion": True, "polygon": SQUARE}]}
    assert qgc_plan_problems({**VALID_PLAN, "geoFence": good}) == []
    problems = qgc_plan_problems({**VALID_PLAN, "geoFence": {**good, **fence}})
    assert len(problems) == 1 and problem in problems[0]


@pytest.fixture(params=["valley", "square"])
def fenced(request: pytest.FixtureRequest, valley: Mission) -> Mission:
    """The valley (an outline with a no-fly zone) and the paper's square placed on the map."""
    if request.param == "valley":
        return valley
    return Mission.from_dict({"team": {"planner": "mtsp", "drones": 3},
                              "region": {"bs": [-3.7038, 40.4168]}})


def test_the_fence_is_the_mission_area(tmp_path: Path, fenced: Mission) -> None:
    """Every .plan's fence, projected back into the mission's frame, is the area the engine
    flies: its outline (inclusion) and each no-fly zone (exclusion), vertex for vertex within
    a centimetre, each vertex once as QGroundControl writes a polygon (QGCMapPolygon.cc
    ``saveToJson`` writes the vertices it holds; its KML reader drops the closing one)."""
    out = export_mission(fenced, tmp_path)
    frame = mission_frame(fenced)
    area = area_polygon(fenced.region, fenced.area.size)
    expected = [(True, area.exterior), *((False, h) for h in area.interiors)]
    plans = [json.loads(d.files[0].read_text()) for d in out.drones if d.kind == "route"]
    assert plans
    for plan in plans:
        assert qgc_plan_problems(plan) == []
        rings = _rings(plan)
        assert [inclusion for inclusion, _ in rings] == [inclusion for inclusion, _ in expected]
        for (_, ring), (_, want) in zip(rings, expected, strict=True):
            assert not np.array_equal(ring[0], ring[-1])
            x, y = frame.to_local(ring[:, 1], ring[:, 0])
            assert np.hypot(x - want.xy[0][:-1], y - want.xy[1][:-1]).max() < 0.01  # m
    assert all(p["geoFence"] == plans[0]["geoFence"] for p in plans)


def test_the_valley_fence_is_the_area_file(tmp_path: Path, valley: Mission) -> None:
    """Straight from examples/valley.geojson: the polygon's outer ring is the inclusion fence
    and its hole the exclusion fence, to the millimetre the mission rounds its geometry to."""
    out = export_mission(valley, tmp_path)
    area = json.loads((EXAMPLES / "valley.geojson").read_text())
    rings = next(f["geometry"]["coordinates"] for f in area["features"]
                 if f["geometry"]["type"] == "Polygon")
    fence = _rings(json.loads(out.drones[0].files[0].read_text()))
    assert [inclusion for inclusion, _ in fence] == [True] + [False] * (len(rings) - 1)
    for (_, got), want in zip(fence, rings, strict=True):
        assert np.abs(got[:, ::-1] - np.asarray(want)[:-1]).max() < 1e-7  # degrees, ~1 cm


def test_the_square_fence_has_the_squares_corners(tmp_path: Path) -> None:
    """The paper's square placed with --bs: the fence's four corners lie half a diagonal from
    the BS at its centre, to the north-east, south-east, south-west and north-west
    (geodesics on WGS84 by pyproj's Geod, independent of the mission's projection)."""
    from pyproj import Geod

    m = Mission.from_dict({"team": {"planner": "mtsp", "drones": 2},
                           "region": {"bs": [-3.7038, 40.4168]}})
    out = export_mission(m, tmp_path)
    [(inclusion, ring)] = _rings(json.loads(out.drones[0].files[0].read_text()))
    assert inclusion and len(ring) == 4
    n = len(ring)
    azimuth, _, dist = Geod(ellps="WGS84").inv([-3.7038] * n, [40.4168] * n, ring[:, 1],
                                               ring[:, 0])
    assert dist == pytest.approx([m.area.size / math.sqrt(2)] * 4, abs=0.01)
    assert sorted(np.round(np.asarray(azimuth) % 360, 3)) == [45.0, 135.0, 225.0, 315.0]


def test_no_drone_trips_its_own_fence(tmp_path: Path, fenced: Mission) -> None:
    """On the map (longitude, latitude), every leg a drone flies, from take-off to landing,
    stays inside the inclusion polygon and never enters an exclusion polygon."""
    out = export_mission(fenced, tmp_path)
    for drone in (d for d in out.drones if d.kind == "route"):
        plan = json.loads(drone.files[0].read_text())
        legs = [i["params"][4:6] for i in plan["mission"]["items"] if i["params"][4] is not None
                and i["frame"] == MAV_FRAME_GLOBAL_RELATIVE_ALT]
        flight = LineString([(lon, lat) for lat, lon in legs])
        for inclusion, ring in _rings(plan):
            zone = Polygon(ring[:, ::-1])
            if inclusion:
                assert zone.covers(flight)
            else:
                assert not flight.intersects(zone.buffer(-1e-7))  # not inside (~1 cm)


@pytest.fixture
def mavlink2() -> Iterator[None]:
    """MAVLink 2 for pymavlink's fence loader (fence items exist only in MAVLink 2, which
    MAVProxy speaks); the dialect chosen before is restored afterwards."""
    mp = pytest.MonkeyPatch()
    dialect = mavutil.current_dialect
    mp.setenv("MAVLINK20", "1")
    mavutil.set_dialect(dialect)
    yield
    mp.undo()
    mavutil.set_dialect(dialect)


def _fence_items(path: Path) -> list[Any]:
    loader = mavwp.MissionItemProtocol_Fence()  # MAVProxy's fence module's loader_class
    loader.load(str(path))
    return [loader.item(k) for k in range(loader.count())]


@pytest.mark.usefixtures("mavlink2")
def test_the_ardupilot_fence_loads_with_pymavlink_and_is_the_plans(tmp_path: Path,
                                                                    fenced: Mission) -> None:
    out = export_mission(fenced, tmp_path, firmware="ardupilot")
    assert out.fence == tmp_path / "fence.waypoints"
    items = _fence_items(out.fence)
    assert ardupilot_fence_problems(items) == []
    plan = json.loads(out.drones[0].files[0].read_text())
    rings = _rings(plan)
    assert len(items) == sum(len(r) for _, r in rings)
    k = 0
    for inclusion, ring in rings:  # the .plan's polygons, in order, to 1e-8 degree (~1 mm)
        polygon = items[k:k + len(ring)]
        k += len(ring)
        assert {w.command for w in polygon} == {MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION
                                                if inclusion else
                                                MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION}
        assert np.abs(np.array([(w.x, w.y) for w in polygon]) - ring).max() < 1e-8


@pytest.mark.usefixtures("mavlink2")
@pytest.mark.parametrize(("field", "value", "problem"), [
    ("command", 16, "not a polygon vertex"),
    ("frame", 2, "not a global frame"),
    ("param1", 2.0, "not in 3..255"),
    ("param1", 256.0, "not in 3..255"),
    ("x", 91.0, "bad lat or lon"),
])
def test_a_broken_ardupilot_fence_breaks_the_rules(tmp_path: Path, valley: Mission, field: str,
                                                   value: float, problem: str) -> None:
    """The ArduPilot checker can fail: one item broken, or a polygon cut short."""
    out = export_mission(valley, tmp_path)
    assert out.fence is not None
    items = _fence_items(out.fence)
    assert [p for p in ardupilot_fence_problems(items[:-1]) if "lacks" in p]
    setattr(items[3], field, value)
    problems = ardupilot_fence_problems(items)
    assert any(problem in p for p in problems)


def test_an_area_too_fine_for_ardupilot_keeps_its_fence_in_the_plan(tmp_path: Path) -> None:
    """ArduPilot takes at most 255 vertices a polygon: a finer outline gets no fence.waypoints
    (and a note saying why), while the .plan still holds the whole fence."""
    angles = np.linspace(0, 2 * np.pi, 300, endpoint=False)
    ring = [[7.0 + 0.02 * math.cos(a), 46.0 + 0.014 * math.sin(a)] for a in angles]
    area = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {}, "geometry": {
            "type": "Polygon", "coordinates": [[*ring, ring[0]]]}},
        {"type": "Feature", "properties": {}, "geometry": {
            "type": "Point", "coordinates": [7.0, 46.0]}}]}
    (tmp_path / "round.geojson").write_text(json.dumps(area))
    m = Mission.from_dict({"team": {"planner": "mtsp", "drones": 1},
                           "region": {"area": str(tmp_path / "round.geojson")}})
    out = export_mission(m, tmp_path)
    assert out.fence is None and not (tmp_path / "fence.waypoints").exists()
    assert any("300 vertices" in note and "255" in note for note in out.notes)
    plan = json.loads(out.drones[0].files[0].read_text())
    assert qgc_plan_problems(plan) == []
    assert [len(r) for _, r in _rings(plan)] == [300]


def test_waypoint_files_load_with_pymavlink_and_round_trip(tmp_path: Path,
                                                           valley: Mission) -> None:
    """Every waypoint, read back by pymavlink's loader and projected into the mission's
    frame, lies within 0.1 m of the route the engine flies; and every item after the home
    line is the .plan's item, field for field (command, frame, the four parameters, latitude
    and longitude to 1e-8 degree, altitude, autocontinue), the home line the BS on the
    ground, the only current item."""
    export_mission(valley, tmp_path, firmware="ardupilot")
    frame = mission_frame(valley)
    routes = get_planner("mtsp-conb").steering(valley).routes
    for i, route in enumerate(r for r in routes if len(r)):
        loader = mavwp.MAVWPLoader()
        count = loader.load(str(tmp_path / f"drone-{i:02d}.waypoints"))
        assert count == len(route) + 4  # home, take-off, speed, the route, land
        home = loader.wp(0)
        assert (home.y, home.x) == pytest.approx(frame.anchor, abs=1e-8)
        assert (home.command, home.frame, home.z) == (MAV_CMD_NAV_WAYPOINT, MAV_FRAME_GLOBAL, 0)
        assert [loader.wp(k).current for k in range(count)] == [1] + [0] * (count - 1)
        nav = [loader.wp(k) for k in range(loader.count()) if loader.wp(k).command == 16][1:]
        assert len(nav) == len(route)
        x, y = frame.to_local([w.y for w in nav], [w.x for w in nav])
        assert np.hypot(x - route[:, 0], y - route[:, 1]).max() < 0.1
        assert all(w.frame == MAV_FRAME_GLOBAL_RELATIVE_ALT for w in nav)
        items = json.loads((tmp_path / f"drone-{i:02d}.plan").read_text())["mission"]["items"]
        for k, item in enumerate(items, start=1):
            w = loader.wp(k)
            assert (w.seq, w.command, w.frame, w.autocontinue) == (
                k, item["command"], item["frame"], 1)
            params = [0.0 if p is None else p for p in item["params"]]
            assert [w.param1, w.param2, w.param3, w.param4] == pytest.approx(params[:4],
                                                                             abs=1e-8)
            assert (w.x, w.y, w.z) == (pytest.approx(params[4], abs=1e-8),
                                       pytest.approx(params[5], abs=1e-8),
                                       pytest.approx(params[6], abs=1e-6))


@pytest.fixture(params=["valley", "sorties"])
def uploaded(request: pytest.FixtureRequest, valley: Mission) -> Mission:
    """The valley's route drones, and the docs' example cut into sorties by a battery."""
    if request.param == "valley":
        return valley
    return valley.replace(planner="mtsp", drones=2, speed=8.0, battery_wh=70.0,
                          energy_model="zeng2019")


@pytest.mark.parametrize(("firmware", "code"), [("px4", MAV_AUTOPILOT_PX4),
                                                ("ardupilot", MAV_AUTOPILOT_ARDUPILOTMEGA)])
def test_every_plan_uploads_through_mavsdk(tmp_path: Path, uploaded: Mission, firmware: str,
                                           code: int) -> None:
    """MAVSDK imports each .plan with its QGroundControl importer and uploads the mission
    to a vehicle of the plan's autopilot (tests/mavlink_vehicle.py): the vehicle receives
    take-off at the BS, the speed, every waypoint of the flight to 1e-7 degree at the height,
    landing at the BS, with their commands and frames and exactly one current item, the
    take-off; under ArduPilot after the home position MAVSDK puts first (ArduPilot's item
    0)."""
    out = export_mission(uploaded, tmp_path, firmware=firmware, altitude=60.0)  # type: ignore[arg-type]
    frame = mission_frame(uploaded)
    routes = [r for r in get_planner(uploaded.team.planner).steering(
        uploaded.searching()).routes if len(r)]
    home = frame.anchor
    flights = 0
    for drone, route in zip((d for d in out.drones if d.kind == "route"), routes, strict=True):
        flown = [split.waypoints for split in split_route(uploaded, drone.drone, route, 60.0)]
        assert len(flown) == len(drone.sorties)
        for sortie, waypoints in zip(drone.sorties, flown, strict=True):
            items = upload(sortie.files[0], code)
            flights += 1
            assert [i.seq for i in items] == list(range(len(items)))
            assert [i.current for i in items].count(1) == 1
            if firmware == "ardupilot":
                first = items.pop(0)
                assert (first.command, first.current) == (MAV_CMD_NAV_WAYPOINT, 0)
                assert (first.y / 1e7, first.x / 1e7) == pytest.approx(home, abs=1e-7)
            lon, lat = frame.to_lonlat(waypoints[:, 0], waypoints[:, 1])
            expected = [(MAV_CMD_NAV_TAKEOFF, MAV_FRAME_GLOBAL_RELATIVE_ALT, home, 60.0),
                        (MAV_CMD_DO_CHANGE_SPEED, MAV_FRAME_MISSION, None, 0.0)]
            expected += [(MAV_CMD_NAV_WAYPOINT, MAV_FRAME_GLOBAL_RELATIVE_ALT, point, 60.0)
                         for point in zip(lon, lat, strict=True)]
            expected.append((MAV_CMD_NAV_LAND, MAV_FRAME_GLOBAL_RELATIVE_ALT, home, 0.0))
            assert [(i.command, i.frame) for i in items] == [e[:2] for e in expected]
            assert items[0].current == 1 and items[1].param2 == uploaded.team.speed
            for item, (_, _, point, height) in zip(items, expected, strict=True):
                if point is not None:
                    assert abs(item.y / 1e7 - point[0]) <= 1e-7
                    assert abs(item.x / 1e7 - point[1]) <= 1e-7
                assert item.z == pytest.approx(height)
    assert flights == sum(len(d.sorties) for d in out.drones)


def test_mavsdks_mission_planner_importer_adds_a_second_home_under_ardupilot(
        tmp_path: Path, valley: Mission) -> None:
    """What docs/missions.md warns of: MAVSDK's Mission Planner importer reads a .waypoints
    file's home line as a waypoint and, under ArduPilot, puts a home position of its own
    before it, so the vehicle gets two home items and the take-off third; under PX4 it would
    fly to the home line, a waypoint at 0 m above sea level."""
    out = export_mission(valley, tmp_path, firmware="ardupilot")
    path = out.drones[0].files[1]
    ardupilot = upload(path, MAV_AUTOPILOT_ARDUPILOTMEGA, importer="mission_planner")
    assert [i.command for i in ardupilot[:3]] == [MAV_CMD_NAV_WAYPOINT, MAV_CMD_NAV_WAYPOINT,
                                                  MAV_CMD_NAV_TAKEOFF]
    assert ardupilot[1].frame == MAV_FRAME_GLOBAL and ardupilot[1].z == 0.0
    px4 = upload(path, MAV_AUTOPILOT_PX4, importer="mission_planner")
    assert (px4[0].command, px4[0].frame, px4[0].current) == (MAV_CMD_NAV_WAYPOINT,
                                                              MAV_FRAME_GLOBAL, 1)


ADVICE_NOT_KEPT = {"excessive_coordinate_precision"}
"""What geojson-validator calls problematic and the team's map does on purpose: coordinates
to 8 decimals (a millimetre: the routes and the area round-trip through the GeoJSON to it),
where RFC 7946 advises 6 (about 10 cm) for plain maps."""
TRACK_ADVICE_NOT_KEPT = {"duplicate_nodes", "excessive_vertices"}
"""And for a simulated track: it passes its own points again (a drone parked at the BS), and
keeps about TRACK_POINTS points of the run."""


def _validator_problems(data: dict[str, Any]) -> dict[str, Any]:
    """geojson-validator's findings: structure, invalid geometries, and problematic ones but
    for the advice the map does not keep on purpose."""
    geometries = geojson_validator.validate_geometries(data)
    tracks = {k for k, f in enumerate(data["features"])
              if f["properties"].get("role") == "simulated track"}
    problematic = {kind: bad for kind, found in geometries["problematic"].items()
                   if kind not in ADVICE_NOT_KEPT
                   and (bad := [k for k in found
                                if k not in tracks or kind not in TRACK_ADVICE_NOT_KEPT])}
    return {**geojson_validator.validate_structure(data), **geometries["invalid"],
            **problematic}


def test_geojson_validator_can_fail() -> None:
    """A clockwise outer ring breaks RFC 7946's winding; the checker above says so."""
    ring = [[7.0, 46.0], [7.0, 46.01], [7.01, 46.01], [7.01, 46.0], [7.0, 46.0]]
    data = {"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
            "geometry": {"type": "Polygon", "coordinates": [ring]}}]}
    assert _validator_problems(data) == {"exterior_not_ccw": [0]}


@pytest.mark.parametrize("battery_wh", [None, 70.0])
def test_the_team_geojson_validates(tmp_path: Path, valley: Mission,
                                    battery_wh: float | None) -> None:
    """The team's map, with and without sorties (each a feature of its own)."""
    mission = valley.replace(battery_wh=battery_wh, speed=8.0, energy_model="zeng2019")
    out = export_mission(mission, tmp_path)
    data = json.loads(out.geojson.read_text())
    FeatureCollection.model_validate(data)  # RFC 7946's structure (geojson-pydantic)
    assert _validator_problems(data) == {}
    sorties = [f for f in data["features"] if f["properties"]["role"] == "sortie"]
    assert len(sorties) == (0 if battery_wh is None else
                            sum(len(d.sorties) for d in out.drones))
    data["features"] = [f for f in data["features"] if f["properties"]["role"] != "sortie"]
    roles = [f["properties"]["role"] for f in data["features"]]
    assert roles.count("area") == 1 and roles.count("no-fly zone") == 1
    assert roles.count("prior zone") == 3 and roles.count("BS") == 1
    assert roles.count("route") == 3 and roles.count("simulated track") == 2
    frame = mission_frame(valley)
    area = area_polygon(valley.region, valley.area.size)
    for feature in data["features"]:
        geom = shape(feature["geometry"])
        assert geom.is_valid
        if feature["geometry"]["type"] == "Polygon":
            assert geom.exterior.is_ccw and all(not h.is_ccw for h in geom.interiors)
        if feature["properties"]["role"] == "area":  # back in metres, the same outline
            coords = np.asarray(geom.exterior.coords)
            x, y = frame.to_local(coords[:, 0], coords[:, 1])
            back = Polygon(np.column_stack([x, y]))
            assert back.exterior.hausdorff_distance(area.exterior) < 0.01  # m
        if feature["properties"]["role"] == "route":
            props = feature["properties"]
            assert props["flight_time_s"] == pytest.approx(props["length_m"] / 8.0, abs=0.2)


def test_relays_are_written_as_their_simulated_tracks(tmp_path: Path, valley: Mission) -> None:
    """Relays fly no route (the BS chooses their points in the air): no upload file, and in
    the GeoJSON their simulated tracks as the distributed drones' are, marked with their task,
    which stay in the valley and out of its no-fly zone. The searchers keep their routes."""
    mission = valley.replace(relays=2)  # three searchers, all on mTSP routes (N_r = 3)
    out = export_mission(mission, tmp_path, seed=3)
    assert [(d.drone, d.kind) for d in out.drones] == [
        (0, "route"), (1, "route"), (2, "route"), (3, "relay"), (4, "relay")]
    assert sorted(p.name for p in tmp_path.glob("*.plan")) == [
        "drone-00.plan", "drone-01.plan", "drone-02.plan"]
    assert out.notes == (f"the relays, drones 3, 4, {RELAY_NOTE} (seed 3, run 0)",)
    data = json.loads(out.geojson.read_text())
    FeatureCollection.model_validate(data)
    tracks = {f["properties"]["drone"]: f for f in data["features"]
              if f["geometry"]["type"] == "LineString"}
    assert {i: (f["properties"]["role"], f["properties"]["task"]) for i, f in tracks.items()} == {
        **{i: ("route", "searcher") for i in range(3)},
        **{i: ("simulated track", "relay") for i in (3, 4)}}
    flown = simulate(mission, seed=3, trajectory=True).trajectory
    assert flown is not None
    frame = mission_frame(mission)
    area = area_polygon(mission.region, mission.area.size)
    every = max(1, len(flown.t) // TRACK_POINTS)
    for i in (3, 4):
        lon, lat = np.asarray(tracks[i]["geometry"]["coordinates"]).T
        x, y = frame.to_local(lon, lat)
        expected = np.vstack([flown.positions[::every, i], flown.positions[-1:, i]])
        assert np.hypot(x - expected[:, 0], y - expected[:, 1]).max() < 0.01  # m
        assert np.hypot(x - x[0], y - y[0]).max() > mission.channel.rc / 2  # it left the BS
        assert area.buffer(0.01).covers(MultiPoint(np.column_stack([x, y])))


def test_missions_off_the_map_cannot_be_exported(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="no place on the map"):
        export_mission(Mission.build(planner="mtsp", drones=2), tmp_path)


def test_an_anchored_square_exports_the_papers_plan(tmp_path: Path) -> None:
    """The paper's square placed on the map with the BS's longitude/latitude: the mTSP plan's
    tours, each from the BS and back, one file pair per drone."""
    m = Mission.from_dict({"team": {"planner": "mtsp", "drones": 2},
                           "region": {"bs": [-3.7038, 40.4168]}})
    out = export_mission(m, tmp_path)
    assert [d.kind for d in out.drones] == ["route", "route"]
    total = sum(d.length for d in out.drones)
    from sarlink.mtsp import plan_for

    assert total == pytest.approx(plan_for(m, 2).total, rel=1e-9)
    assert not out.notes
    assert math.isclose(out.drones[0].flight_time, out.drones[0].length / 5.0)
