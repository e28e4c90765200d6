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

With a battery (``battery.battery_wh``) each route is flown in sorties that each fit it
(:mod:`.sorties`): one ``.plan`` and one ``.waypoints`` per sortie,
``drone-00-sortie-1.plan``, ..., each sortie resuming where the last one turned home.
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
from sarlink.export.sorties import Sortie, battery_budget, split_route
from sarlink.planners import get_planner
from sarlink.simulation import simulate

__all__ = ["DISTRIBUTED_NOTE", "LEGAL_ALTITUDE", "MAX_ALTITUDE", "RELAY_NOTE", "DroneExport",
           "SortieExport", "TeamExport", "check_altitude", "export_mission", "mission_fence",
           "mission_frame"]

DISTRIBUTED_NOTE = ("run a distributed rule: they decide where to fly in the air, from what "
                    "they sense and hear, so no file can hold their flight in advance; their "
                    "simulated tracks of one run are in the GeoJSON, for the briefing")
RELAY_NOTE = ("hold the searchers' link to the BS: the BS chooses their points in the air, "
              "from what it hears of the searchers, so no file can hold their flight in "
              "advance; their simulated tracks of one run are in the GeoJSON, for the briefing")

TRACK_POINTS = 1000
"""About how many points of a simulated track the GeoJSON keeps (every k-th step)."""
MAX_ALTITUDE = 1000.0
"""Highest flight height above the BS, m, that an export takes: beyond what survey
multirotors fly (ArduPilot's altitude fence, ``FENCE_ALT_MAX``, stops at 1000 m) and
hundreds of metres above where a sensor finds a person."""
LEGAL_ALTITUDE = 120.0
"""The usual height limit for drones without a special permission, m (the EU's open
category; 400 ft under the US Part 107): a higher export gets a note saying so."""


def check_altitude(altitude: float) -> str | None:
    """Refuse a height no multirotor survey flies (a :class:`ConfigError` naming
    ``--altitude``); a note where it exceeds :data:`LEGAL_ALTITUDE`, else None."""
    if not (math.isfinite(altitude) and 0 < altitude <= MAX_ALTITUDE):
        raise ConfigError(f"--altitude must be a height above the BS > 0 m and at most "
                          f"{MAX_ALTITUDE:g} m (no survey multirotor flies higher), got "
                          f"{altitude:g}")
    if altitude > LEGAL_ALTITUDE:
        return (f"--altitude {altitude:g} m is above the {LEGAL_ALTITUDE:g} m that drones "
                "may usually fly without a special permission (the EU's open category, 400 "
                "ft under the US Part 107): check the rules where you fly")
    return None


@dataclass(frozen=True)
class SortieExport:
    """What was written for one sortie of a route drone."""

    number: int
    """1, 2, ... in the order they are flown."""
    length: float
    """Metres of level flight, the way out and home included."""
    duration: float
    """Seconds from take-off to landing (the climb and the descent included)."""
    energy: float
    """Joules under the mission's energy model (0 under ``none``)."""
    files: tuple[Path, ...]


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
    sorties: tuple[SortieExport, ...] = ()
    """A route drone's flights (one without a battery)."""


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
    """Write the mission's upload files and its team GeoJSON into ``folder`` (created if
    missing), every file computed before the first is written: on bad input nothing is.

    ``altitude`` is the flight height above the BS, m; ``seed`` and ``run`` choose the run
    whose simulated tracks stand for the distributed drones and the relays. With a battery,
    each route drone's route is cut into sorties (:mod:`.sorties`).
    """
    notes = [note for note in (check_altitude(altitude),) if note]
    frame = mission_frame(mission)
    fence = mission_fence(mission, frame)
    steering = get_planner(mission.team.planner).steering(mission.searching())
    n, speed = mission.team.drones, mission.team.speed
    bs = np.asarray(mission.area.bs_xy, dtype=float)
    home = (float(frame.anchor[0]), float(frame.anchor[1]))
    routes = list(steering.routes) + [np.empty((0, 2))] * (n - len(steering.routes))
    battery = battery_budget(mission) is not None
    texts: dict[Path, str] = {}
    drones: list[DroneExport] = []
    paths: dict[int, tuple[str, np.ndarray]] = {}
    legs: list[tuple[int, int, np.ndarray, Sortie]] = []
    searchers = n - mission.team.relays
    for i, route in enumerate(routes):
        if len(route) == 0:
            continue
        local = np.asarray(route, dtype=float)
        sorties = []
        for k, sortie in enumerate(split_route(mission, i, local, altitude), start=1):
            lon, lat = frame.to_lonlat(sortie.waypoints[:, 0], sortie.waypoints[:, 1])
            flight = Route(home, np.column_stack([lon, lat]), altitude, speed)
            stem = folder / (f"drone-{i:02d}-sortie-{k}" if battery else f"drone-{i:02d}")
            plan, wpl = stem.with_suffix(".plan"), stem.with_suffix(".waypoints")
            texts[plan] = plan_text(flight, firmware, fence)
            texts[wpl] = waypoints_text(flight)
            sorties.append(SortieExport(k, sortie.flight.length, sortie.flight.duration,
                                        sortie.energy, (plan, wpl)))
            if battery:
                legs.append((i, k, np.vstack([bs, sortie.waypoints]), sortie))
        length = _length(np.vstack([bs, local]))
        files = tuple(p for s in sorties for p in s.files)
        drones.append(DroneExport(i, "route", length, length / speed, files, tuple(sorties)))
        paths[i] = ("route", np.vstack([bs, local]))
    fence_file: Path | None = None
    most = max(len(ring) for _, ring in fence.polygons())
    if most <= ARDUPILOT_MAX_VERTICES:
        fence_file = folder / "fence.waypoints"
        texts[fence_file] = fence_text(fence)
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
    texts[geojson] = json.dumps(team_geojson(mission, frame, paths, speed, [
        (i, k, points, {"length_m": round(s.flight.length, 1),
                        "duration_s": round(s.flight.duration, 1),
                        "energy_wh": round(s.energy / 3600.0, 2)})
        for i, k, points, s in legs]), indent=1)
    _write(folder, texts)
    drones.sort(key=lambda d: d.drone)
    return TeamExport(folder, geojson, tuple(drones), fence_file, tuple(notes))


def _write(folder: Path, texts: dict[Path, str]) -> None:
    """Create ``folder`` if missing and write every file into it."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ConfigError(f"--out {folder}: cannot create the folder ({exc.strerror})") from None
    for path, text in texts.items():
        path.write_text(text, encoding="utf-8")
