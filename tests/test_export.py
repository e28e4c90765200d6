"""``sarlink export``: .plan files pass QGroundControl's loader rules, .waypoints load with
pymavlink, coordinates round-trip to the simulated routes, and the GeoJSON validates."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from geojson_pydantic import FeatureCollection
from pymavlink import mavwp
from shapely.geometry import Polygon, shape

from sarlink import ConfigError, Mission
from sarlink.config.region import area_polygon
from sarlink.export import export_mission, mission_frame
from sarlink.planners import get_planner

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
MAV_AUTOPILOT_PX4 = 12  # the MAVLink common message set's MAV_AUTOPILOT enum
MAV_AUTOPILOT_ARDUPILOTMEGA = 3
MAV_CMD_NAV_WAYPOINT = 16
MAV_FRAME_GLOBAL_RELATIVE_ALT = 3


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
    if not (rally.get("version") == 2 and isinstance(rally.get("points"), list)):
        bad.append("rallyPoints must have version 2 and points")
    return bad


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


def test_waypoint_files_load_with_pymavlink_and_round_trip(tmp_path: Path,
                                                           valley: Mission) -> None:
    """Every waypoint, read back by pymavlink's loader and projected into the mission's
    frame, lies within 0.1 m of the route the engine flies."""
    export_mission(valley, tmp_path, firmware="ardupilot")
    frame = mission_frame(valley)
    routes = get_planner("mtsp-conb").steering(valley).routes
    for i, route in enumerate(r for r in routes if len(r)):
        loader = mavwp.MAVWPLoader()
        count = loader.load(str(tmp_path / f"drone-{i:02d}.waypoints"))
        assert count == len(route) + 4  # home, take-off, speed, the route, land
        home = loader.wp(0)
        assert (home.y, home.x) == pytest.approx(frame.anchor, abs=1e-8)
        nav = [loader.wp(k) for k in range(loader.count()) if loader.wp(k).command == 16][1:]
        assert len(nav) == len(route)
        x, y = frame.to_local([w.y for w in nav], [w.x for w in nav])
        assert np.hypot(x - route[:, 0], y - route[:, 1]).max() < 0.1
        assert all(w.frame == MAV_FRAME_GLOBAL_RELATIVE_ALT for w in nav)


def test_the_team_geojson_validates(tmp_path: Path, valley: Mission) -> None:
    out = export_mission(valley, tmp_path)
    data = json.loads(out.geojson.read_text())
    FeatureCollection.model_validate(data)  # RFC 7946's structure (geojson-pydantic)
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
            assert props["flight_time_s"] == pytest.approx(props["length_m"] / 5.0, abs=0.2)


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
