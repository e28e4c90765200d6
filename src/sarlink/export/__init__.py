"""``sarlink export``: a mission's plans as files for the autopilots and the briefing.

Route drones (any planner whose steering gives a drone waypoints: mTSP, mTSP-ConB's route
drones, search patterns) get one QGroundControl ``.plan`` and one ``QGC WPL 110``
``.waypoints`` file each (:mod:`.qgc`). Each ``.plan`` carries the search area as the
autopilot's geofence (stay inside the outline, out of the no-fly zones), so that a drone that
drifts or is flown by hand meets the autopilot's breach action at the area's edge and at
every no-fly zone; ``fence.waypoints`` holds the same fence for ArduPilot, which takes its
fence apart from the mission. Distributed drones decide where to fly in the air, from what
they sense and hear, so no file can hold their flight in advance: their simulated tracks of
one run go into the team's GeoJSON for the briefing instead (:mod:`.geojson`). So do the
relays' (``team.relays``): the BS chooses their points in the air, from what it hears of the
searchers.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from sarlink.config import ConfigError, Mission
from sarlink.config.geo import Frame
from sarlink.config.region import area_polygon
from sarlink.export.geojson import team_geojson
from sarlink.export.qgc import (
    ARDUPILOT_MAX_VERTICES,
    Fence,
    Firmware,
    Route,
    fence_text,
    plan_text,
    waypoints_text,
)
from sarlink.planners import get_planner
from sarlink.simulation import simulate

__all__ = ["DISTRIBUTED_NOTE", "RELAY_NOTE", "DroneExport", "TeamExport", "export_mission",
           "mission_fence", "mission_frame"]

DISTRIBUTED_NOTE = ("run a distributed rule: they decide where to fly in the air, from what "
                    "they sense and hear, so no file can hold their flight in advance; their "
                    "simulated tracks of one run are in the GeoJSON, for the briefing")
RELAY_NOTE = ("hold the searchers' link to the BS: the BS chooses their points in the air, "
              "from what it hears of the searchers, so no file can hold their flight in "
              "advance; their simulated tracks of one run are in the GeoJSON, for the briefing")

TRACK_POINTS = 1000
"""About how many points of a simulated track the GeoJSON keeps (every k-th step)."""


@dataclass(frozen=True)
class DroneExport:
    """What was written for one drone."""

    drone: int
    kind: str
    """``route`` (upload files written), ``distributed`` or ``relay`` (a simulated track
    only)."""
    length: float
    """Route length, or the simulated track's length, m."""
    flight_time: float
    """length / speed, s."""
    files: tuple[Path, ...] = ()


@dataclass(frozen=True)
class TeamExport:
    """Every file of an export and what it holds."""

    folder: Path
    geojson: Path
    drones: tuple[DroneExport, ...]
    fence: Path | None = None
    """The fence for ArduPilot (``fence.waypoints``), or None if ArduPilot cannot take it."""
    notes: tuple[str, ...] = field(default=())


def mission_frame(mission: Mission) -> Frame:
    """The mission's frame on the map, or a :class:`ConfigError` saying how to place it."""
    region = mission.region
    if region is None or region.anchor is None:
        raise ConfigError("the mission has no place on the map: give the area as GeoJSON "
                          "(--area FILE.geojson) or the BS's longitude,latitude (--bs)")
    return Frame(region.anchor, mission.area.bs_xy)


def mission_fence(mission: Mission, frame: Frame) -> Fence:
    """The mission's area on the map (its outline, or the paper's square, and its no-fly
    zones) as the autopilot's fence."""
    area = area_polygon(mission.region, mission.area.size)

    def ring(coords: np.ndarray) -> np.ndarray:
        lon, lat = frame.to_lonlat(coords[:-1, 0], coords[:-1, 1])  # each vertex once
        return np.column_stack([lon, lat])

    return Fence(ring(np.asarray(area.exterior.coords)),
                 tuple(ring(np.asarray(h.coords)) for h in area.interiors))


def _length(points: np.ndarray) -> float:
    return float(np.hypot(*np.diff(points, axis=0).T).sum()) if len(points) > 1 else 0.0


def export_mission(mission: Mission, folder: Path, *, altitude: float = 50.0,
                   firmware: Firmware = "px4", seed: int = 0, run: int = 0) -> TeamExport:
    """Write the mission's upload files and its team GeoJSON into ``folder``.

    ``altitude`` is the flight height above the BS, m; ``seed`` and ``run`` choose the run
    whose simulated tracks stand for the distributed drones and the relays.
    """
    if not (math.isfinite(altitude) and altitude > 0):
        raise ConfigError(f"--altitude must be a height above the BS > 0 m, got {altitude:g}")
    frame = mission_frame(mission)
    fence = mission_fence(mission, frame)
    steering = get_planner(mission.team.planner).steering(mission.searching())
    n, speed = mission.team.drones, mission.team.speed
    bs = np.asarray(mission.area.bs_xy, dtype=float)
    home = (float(frame.anchor[0]), float(frame.anchor[1]))
    routes = list(steering.routes) + [np.empty((0, 2))] * (n - len(steering.routes))
    drones: list[DroneExport] = []
    paths: dict[int, tuple[str, np.ndarray]] = {}
    searchers = n - mission.team.relays
    for i, route in enumerate(routes):
        if len(route) == 0:
            continue
        local = np.asarray(route, dtype=float)
        lon, lat = frame.to_lonlat(local[:, 0], local[:, 1])
        flight = Route(home, np.column_stack([lon, lat]), altitude, speed)
        stem = folder / f"drone-{i:02d}"
        plan, wpl = stem.with_suffix(".plan"), stem.with_suffix(".waypoints")
        plan.write_text(plan_text(flight, firmware, fence), encoding="utf-8")
        wpl.write_text(waypoints_text(flight), encoding="utf-8")
        length = _length(np.vstack([bs, local]))
        drones.append(DroneExport(i, "route", length, length / speed, (plan, wpl)))
        paths[i] = ("route", np.vstack([bs, local]))
    notes = []
    fence_file: Path | None = None
    most = max(len(ring) for _, ring in fence.polygons())
    if most <= ARDUPILOT_MAX_VERTICES:
        fence_file = folder / "fence.waypoints"
        fence_file.write_text(fence_text(fence), encoding="utf-8")
    else:
        notes.append(f"no fence.waypoints: a polygon of the area has {most} vertices and "
                     f"ArduPilot takes at most {ARDUPILOT_MAX_VERTICES}; simplify the area "
                     "to fence it on ArduPilot (the .plan files carry the whole fence)")
    distributed = [i for i, r in enumerate(routes[:searchers]) if len(r) == 0]
    relays = list(range(searchers, n))
    if distributed or relays:
        result = simulate(mission, seed=seed, run=run, trajectory=True)
        assert result.trajectory is not None
        tracks = result.trajectory.positions
        every = max(1, len(tracks) // TRACK_POINTS)
        for kind, group in (("distributed", distributed), ("relay", relays)):
            for i in group:
                track = tracks[:, i]
                length = _length(track)
                track = np.vstack([track[::every], track[-1:]])
                drones.append(DroneExport(i, kind, length, length / speed))
                paths[i] = ("simulated track", track)
        label = get_planner(mission.team.planner).label
        which = f"(seed {seed}, run {run})"
        if distributed:
            notes.append(f"{label}'s drones {', '.join(map(str, distributed))} "
                         f"{DISTRIBUTED_NOTE} {which}")
        if relays:
            notes.append(f"the relays, drones {', '.join(map(str, relays))}, {RELAY_NOTE} "
                         f"{which}")
    geojson = folder / "team.geojson"
    geojson.write_text(json.dumps(team_geojson(mission, frame, paths, speed), indent=1),
                       encoding="utf-8")
    drones.sort(key=lambda d: d.drone)
    return TeamExport(folder, geojson, tuple(drones), fence_file, tuple(notes))
