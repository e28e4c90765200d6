"""Missions an autopilot flies: QGroundControl ``.plan`` and ``QGC WPL 110`` ``.waypoints``.

Written to the rules QGroundControl's loaders enforce (``PlanMasterController::loadFromFile``,
``MissionController::_loadJsonMissionFileV2``, ``MissionItem::load``, the geofence and rally
point loaders): a ``Plan`` file of version 1 from a ground station, a mission of version 2
with the firmware and vehicle type, the planned home position as ``[lat, lon, alt]``, and
simple items of seven parameters each, numbered by ``doJumpId`` from 1 (home is 0); a
geofence of version 2 whose polygons (version 1, ``inclusion``, ``polygon`` of ``[lat, lon]``
vertices, each once) are the search area to stay in and its no-fly zones to stay out of; no
rally points. A drone takes off at the BS, sets its speed, flies its waypoints at a constant
height above the BS (``MAV_FRAME_GLOBAL_RELATIVE_ALT``) and lands at the BS. The
``.waypoints`` text file holds the same items after ArduPilot's home line; the fence's
``QGC WPL 110`` file holds the same polygons as MAVLink fence items, each vertex an item of
``MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION`` (or ``_EXCLUSION``) whose first parameter is
its polygon's vertex count (what MAVProxy's ``fence load`` reads and ArduPilot stores).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

__all__ = ["ARDUPILOT_MAX_VERTICES", "FIRMWARE", "Fence", "Leg", "Route", "fence_text",
           "plan_json", "plan_text", "waypoints_text"]

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
MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION = 5001
MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION = 5002
PLAN_FILE_VERSION = 1
MISSION_VERSION = 2
FENCE_VERSION = 2
FENCE_POLYGON_VERSION = 1
RALLY_VERSION = 2
ARDUPILOT_MAX_VERTICES = 255
"""Most vertices of one fence polygon ArduPilot accepts (its ``MissionItemProtocol_Fence``
refuses a vertex count above 255)."""


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


@dataclass(frozen=True)
class Fence:
    """The search area on the map: a drone stays inside ``outline`` and out of every hole.

    Rings of (longitude, latitude), shape ``(k, 2)``, each vertex once: fence polygons close
    themselves (QGroundControl's and ArduPilot's), so a repeated first vertex would be a
    vertex too many.
    """

    outline: np.ndarray
    holes: tuple[np.ndarray, ...] = ()

    def polygons(self) -> list[tuple[bool, np.ndarray]]:
        """(inclusion, ring) of every fence polygon: the outline, then each no-fly zone."""
        return [(True, self.outline), *((False, hole) for hole in self.holes)]


def plan_json(route: Route, firmware: Firmware, fence: Fence) -> dict[str, Any]:
    """The QGroundControl ``.plan`` document of one drone's route inside ``fence``."""
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
        "geoFence": {"version": FENCE_VERSION, "circles": [], "polygons": [
            {"version": FENCE_POLYGON_VERSION, "inclusion": inclusion,
             "polygon": [[float(lat), float(lon)] for lon, lat in ring]}
            for inclusion, ring in fence.polygons()]},
        "rallyPoints": {"version": RALLY_VERSION, "points": []},
    }


def plan_text(route: Route, firmware: Firmware, fence: Fence) -> str:
    """The ``.plan`` file's text (JSON; a null stands for a parameter left to the vehicle)."""
    return json.dumps(plan_json(route, firmware, fence), indent=4) + "\n"


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


def fence_text(fence: Fence) -> str:
    """The fence as a ``QGC WPL 110`` file of MAVLink fence items (no home line: a fence has
    none), numbered from 0: every vertex of a polygon in turn, with the polygon's vertex count
    as its first parameter, in the global frame at altitude 0 (a fence has no height)."""
    lines = ["QGC WPL 110"]
    for inclusion, ring in fence.polygons():
        command = (MAV_CMD_NAV_FENCE_POLYGON_VERTEX_INCLUSION if inclusion
                   else MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION)
        for lon, lat in ring:
            lines.append(_line(len(lines) - 1, 0, MAV_FRAME_GLOBAL, command,
                               (float(len(ring)), 0.0, 0.0, 0.0, float(lat), float(lon), 0.0)))
    return "\n".join(lines) + "\n"


def _line(index: int, current: int, frame: int, command: int,
          params: tuple[float | None, ...]) -> str:
    p = [0.0 if v is None else float(v) for v in params]
    fields = [str(index), str(current), str(frame), str(command),
              *(f"{v:.8f}" for v in p[:4]), f"{p[4]:.8f}", f"{p[5]:.8f}", f"{p[6]:.6f}", "1"]
    return "\t".join(fields)
