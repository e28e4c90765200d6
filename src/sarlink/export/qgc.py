"""Missions an autopilot flies: QGroundControl ``.plan`` and ``QGC WPL 110`` ``.waypoints``.

Written to the rules QGroundControl's loaders enforce (``PlanMasterController::loadFromFile``,
``MissionController::_loadJsonMissionFileV2``, ``MissionItem::load``, the geofence and rally
point loaders): a ``Plan`` file of version 1 from a ground station, a mission of version 2
with the firmware and vehicle type, the planned home position as ``[lat, lon, alt]``, and
simple items of seven parameters each, numbered by ``doJumpId`` from 1 (home is 0); an empty
geofence and rally points of version 2. A drone takes off at the BS, sets its speed, flies
its waypoints at a constant height above the BS (``MAV_FRAME_GLOBAL_RELATIVE_ALT``) and lands
at the BS. The ``.waypoints`` text file holds the same items after ArduPilot's home line.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

__all__ = ["FIRMWARE", "Leg", "Route", "plan_json", "waypoints_text"]

Firmware = Literal["px4", "ardupilot"]
FIRMWARE: dict[str, int] = {"px4": 12, "ardupilot": 3}
"""MAV_AUTOPILOT codes: MAV_AUTOPILOT_PX4 = 12, MAV_AUTOPILOT_ARDUPILOTMEGA = 3."""
MAV_TYPE_QUADROTOR = 2
MAV_FRAME_GLOBAL = 0
MAV_FRAME_MISSION = 2
MAV_FRAME_GLOBAL_RELATIVE_ALT = 3
MAV_CMD_NAV_WAYPOINT = 16
MAV_CMD_NAV_LAND = 21
MAV_CMD_NAV_TAKEOFF = 22
MAV_CMD_DO_CHANGE_SPEED = 178
PLAN_FILE_VERSION = 1
MISSION_VERSION = 2
FENCE_VERSION = 2
RALLY_VERSION = 2


@dataclass(frozen=True)
class Leg:
    """One mission item: a MAVLink command with its frame and seven parameters."""

    command: int
    frame: int
    params: tuple[float | None, ...]


@dataclass(frozen=True)
class Route:
    """One drone's flight on the map: from the BS through ``lonlat`` (which ends at the BS)."""

    home: tuple[float, float]
    """(longitude, latitude) of the BS."""
    lonlat: np.ndarray
    """Waypoints after take-off, shape ``(k, 2)``, (longitude, latitude)."""
    altitude: float
    """Height above the BS, m."""
    speed: float
    """Ground speed, m/s."""

    def legs(self) -> list[Leg]:
        """Take off at the BS, set the speed, fly every waypoint, land at the BS."""
        lon0, lat0 = self.home
        alt = float(self.altitude)
        items = [Leg(MAV_CMD_NAV_TAKEOFF, MAV_FRAME_GLOBAL_RELATIVE_ALT,
                     (0.0, 0.0, 0.0, None, lat0, lon0, alt)),
                 Leg(MAV_CMD_DO_CHANGE_SPEED, MAV_FRAME_MISSION,
                     (1.0, float(self.speed), -1.0, 0.0, 0.0, 0.0, 0.0))]
        items += [Leg(MAV_CMD_NAV_WAYPOINT, MAV_FRAME_GLOBAL_RELATIVE_ALT,
                      (0.0, 0.0, 0.0, None, float(lat), float(lon), alt))
                  for lon, lat in self.lonlat]
        items.append(Leg(MAV_CMD_NAV_LAND, MAV_FRAME_GLOBAL_RELATIVE_ALT,
                         (0.0, 0.0, 0.0, None, lat0, lon0, 0.0)))
        return items


def plan_json(route: Route, firmware: Firmware) -> dict[str, Any]:
    """The QGroundControl ``.plan`` document of one drone's route."""
    lon0, lat0 = route.home
    items = []
    for k, leg in enumerate(route.legs()):
        item: dict[str, Any] = {"type": "SimpleItem", "command": leg.command, "frame": leg.frame,
                                "params": list(leg.params), "autoContinue": True,
                                "doJumpId": k + 1}
        if leg.frame == MAV_FRAME_GLOBAL_RELATIVE_ALT:  # what QGC itself writes for a position
            item.update(AMSLAltAboveTerrain=None, Altitude=leg.params[6], AltitudeMode=1)
        items.append(item)
    return {
        "fileType": "Plan",
        "version": PLAN_FILE_VERSION,
        "groundStation": "QGroundControl",
        "mission": {
            "version": MISSION_VERSION,
            "firmwareType": FIRMWARE[firmware],
            "vehicleType": MAV_TYPE_QUADROTOR,
            "cruiseSpeed": route.speed,
            "hoverSpeed": route.speed,
            "globalPlanAltitudeMode": 1,
            "plannedHomePosition": [lat0, lon0, 0.0],
            "items": items,
        },
        "geoFence": {"version": FENCE_VERSION, "circles": [], "polygons": []},
        "rallyPoints": {"version": RALLY_VERSION, "points": []},
    }


def plan_text(route: Route, firmware: Firmware) -> str:
    """The ``.plan`` file's text (JSON; a null stands for a parameter left to the vehicle)."""
    return json.dumps(plan_json(route, firmware), indent=4) + "\n"


def waypoints_text(route: Route) -> str:
    """The ``QGC WPL 110`` file: ArduPilot's home line (index 0), then every item.

    Columns: index, current, frame, command, param 1-4, latitude, longitude, altitude,
    autocontinue, tab-separated; coordinates with 8 decimals (about a millimetre).
    """
    lon0, lat0 = route.home
    lines = ["QGC WPL 110",
             _line(0, 1, MAV_FRAME_GLOBAL, MAV_CMD_NAV_WAYPOINT,
                   (0.0, 0.0, 0.0, 0.0, lat0, lon0, 0.0))]
    for k, leg in enumerate(route.legs()):
        lines.append(_line(k + 1, 0, leg.frame, leg.command, leg.params))
    return "\n".join(lines) + "\n"


def _line(index: int, current: int, frame: int, command: int,
          params: tuple[float | None, ...]) -> str:
    p = [0.0 if v is None else float(v) for v in params]
    fields = [str(index), str(current), str(frame), str(command),
              *(f"{v:.8f}" for v in p[:4]), f"{p[4]:.8f}", f"{p[5]:.8f}", f"{p[6]:.6f}", "1"]
    return "\t".join(fields)
