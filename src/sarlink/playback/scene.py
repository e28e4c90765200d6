"""One panel of a replay: the run's fixed scenery, its events and its encoded frames."""

from __future__ import annotations

import math
from typing import Any

from sarlink.config import Mission
from sarlink.config.region import area_polygon, zone_polygon
from sarlink.engine.codes import Mode
from sarlink.planners import get_planner
from sarlink.playback.encoding import encode
from sarlink.playback.events import events
from sarlink.result import RunResult

__all__ = ["describe", "modes", "scene", "setting"]


def setting(mission: Mission) -> str:
    """Team size (and its relays), range, what a drone does on detecting the target if not the
    paper's (continue), and the imperfections switched on, for titles."""
    team = mission.team
    relays = f" ({team.relays} relay{'s' * (team.relays > 1)})" if team.relays else ""
    parts = [f"N = {team.drones}{relays}", f"r_c = {mission.channel.rc:g} m"]
    if team.on_detect != "continue":
        parts.append(f"on detect: {team.on_detect}")
    if mission.channel.sigma > 0:
        parts.append(f"σ = {mission.channel.sigma:g} dB")
    if mission.sensing.p_miss > 0:
        parts.append(f"p_miss = {mission.sensing.p_miss:g}")
    return ", ".join(parts)


def describe(mission: Mission, result: RunResult) -> str:
    """A panel's title: planner, setting, seed and run."""
    return (f"{get_planner(mission.team.planner).label}, {setting(mission)} "
            f"(seed {result.seed}, run {result.run})")


def modes() -> list[dict[str, Any]]:
    """Every drone mode the engine knows, so that the page colours new ones without edits."""
    return [{"value": int(m), "name": m.name.lower()} for m in Mode]


def scene(result: RunResult, mission: Mission, title: str | None = None,
          budget: float = math.inf) -> dict[str, Any]:
    """The JSON the page draws one run from; frames beyond ``budget`` bytes are thinned."""
    traj = result.trajectory
    if traj is None:
        raise ValueError("a replay needs a result simulated with trajectory=True")
    bs = mission.area.bs_xy
    tours = [[list(bs), *route.tolist()]
             for route in get_planner(mission.team.planner).steering(mission.searching()).routes
             if len(route)]
    return {
        "title": title or describe(mission, result),
        "planner": mission.team.planner,
        "size": mission.area.size,
        "bs": list(bs),
        "rc": mission.channel.rc,
        "r": mission.sensing.r,
        "target": list(result.target),
        "horizon": mission.timing.horizon,
        "stop": mission.timing.stop,
        "end": float(traj.t[-1]),
        "tDetect": result.t_detect,
        "tNotify": result.t_notify,
        "detector": result.detector,
        "immediate": result.immediate,
        "events": [e.json() for e in events(result)],
        "tours": tours,
        "frames": encode(traj, budget).json(),
        # several targets: where the others were last seen, and when each was found
        "others": [] if result.targets is None else result.targets[1:].tolist(),
        "othersDetect": [] if result.t_detect_each is None else
        [None if math.isnan(v) else v for v in result.t_detect_each[1:].tolist()],
        **_area(mission),  # a polygon's frame replaces the square's size
    }


def _area(mission: Mission) -> dict[str, Any]:
    """A polygon area's drawing (the square needs none: ``size`` is enough): the frame's
    corner ``origin`` and side ``size``, the rings and the prior zones with their relative
    density (1 for the likeliest per square metre)."""
    region = mission.region
    if region is None or (region.outline is None and not region.holes and not region.zones):
        return {}
    area = area_polygon(region, mission.area.size)
    x0, y0, x1, y1 = area.bounds
    density = [z.weight / zone_polygon(z).area for z in region.zones]
    top = max(density, default=1.0)
    return {
        "origin": [x0, y0],
        "size": max(x1 - x0, y1 - y0),
        "area": {
            "outline": [list(p) for p in area.exterior.coords],
            "holes": [[list(p) for p in h.coords] for h in area.interiors],
            "zones": [{"ring": [list(p) for p in zone_polygon(z).exterior.coords],
                       "density": d / top} for z, d in zip(region.zones, density, strict=True)],
        },
    }
