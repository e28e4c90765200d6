"""``sarlink export``: the files to upload to each drone, and the team's map for the briefing."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, get_args

import typer
from rich.table import Table

from sarlink.cli import options
from sarlink.cli.common import console, output_folder, team_text, user_errors
from sarlink.cli.flags import MissionFlags, mission_flags
from sarlink.config import ConfigError
from sarlink.export import export_mission
from sarlink.export.qgc import Firmware
from sarlink.planners import get_planner


@mission_flags("export")
def export(
    flags: MissionFlags,
    out: Annotated[Path, typer.Option("--out", "-o", help="folder of the files to write")
                   ] = Path("plans"),
    altitude: Annotated[float, typer.Option(help="flight height above the BS, m")] = 50.0,
    firmware: Annotated[str, typer.Option(help="px4 or ardupilot")] = "px4",
    seed: options.Seed = 0,
    run: options.Run = 0,
) -> None:
    """Write one QGroundControl .plan and one .waypoints file per route drone (take-off at
    the BS, the route, landing at the BS; the .plan's geofence fences the drone into the area
    and out of its no-fly zones), fence.waypoints (the same fence for ArduPilot: MAVProxy's
    fence load) and the team's GeoJSON (area, no-fly zones, BS, routes; the distributed
    drones' simulated tracks of run RUN of SEED)."""
    with user_errors():
        if firmware not in get_args(Firmware):
            raise ConfigError(f"--firmware {firmware!r}: expected px4 or ardupilot")
        mission = flags.mission()
        folder = output_folder(out, "--out")
        team = export_mission(mission, folder, altitude=altitude,
                              firmware=firmware,  # type: ignore[arg-type]
                              seed=seed, run=run)
    label = get_planner(mission.team.planner).label
    table = Table(title=f"{label}, {team_text(mission)}, {altitude:g} m above the BS, "
                        f"{firmware}: files in {folder}", title_justify="left")
    for name in ("drone", "flies", "length", "flight time", "files"):
        table.add_column(name, justify="right" if name in ("drone", "length") else "left")
    for d in team.drones:
        files = ", ".join(p.name for p in d.files) or "[dim]none: decides in flight[/]"
        flies = {"route": "its route", "relay": "simulated track (relay)"}.get(
            d.kind, "simulated track")
        table.add_row(str(d.drone), flies,
                      f"{d.length / 1000:.2f} km", f"{d.flight_time / 60:.1f} min", files)
    console.print(table)
    console.print(f"team map: {team.geojson}", highlight=False)
    if team.fence is not None:
        console.print(f"fence for ArduPilot (MAVProxy: fence load): {team.fence}",
                      highlight=False)
    for note in team.notes:
        console.print(note, highlight=False, soft_wrap=True)
