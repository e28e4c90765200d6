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
from sarlink.engine.energy import get_energy_model
from sarlink.export import SortieExport, export_mission
from sarlink.export.qgc import Firmware
from sarlink.export.sorties import RESUME_OVERLAP
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
    drones' simulated tracks of run RUN of SEED). With --battery-wh, each route is flown in
    sorties that each fit the battery less its reserve, each resuming where the last one
    turned home: one .plan and one .waypoints per sortie (drone-00-sortie-1.plan, ...)."""
    with user_errors():
        if firmware not in get_args(Firmware):
            raise ConfigError(f"--firmware {firmware!r}: expected px4 or ardupilot")
        mission = flags.mission()
        output_folder(out, "--out", create=False)
        team = export_mission(mission, out, altitude=altitude,
                              firmware=firmware,  # type: ignore[arg-type]
                              seed=seed, run=run)
    label = get_planner(mission.team.planner).label
    table = Table(title=f"{label}, {team_text(mission)}, {altitude:g} m above the BS, "
                        f"{firmware}: files in {out}", title_justify="left")
    model = mission.energy_model
    energy = get_energy_model(model).draws_power
    capacity = mission.battery.battery_wh
    battery = capacity is not None
    columns = ["drone", "flies", *(["sortie"] * battery), "length",
               "duration" if energy else "flight time", *(["energy"] * energy), "files"]
    for name in columns:
        table.add_column(name, justify="right" if name in ("drone", "sortie", "length", "energy")
                         else "left")
    for d in team.drones:
        flies = {"route": "its route", "relay": "simulated track (relay)"}.get(
            d.kind, "simulated track")
        if not d.sorties:
            table.add_row(str(d.drone), flies, *([""] * battery), f"{d.length / 1000:.2f} km",
                          f"{d.flight_time / 60:.1f} min", *([""] * energy),
                          "[dim]none: decides in flight[/]")
            continue
        for s in d.sorties:
            length, time = (s.length, s.duration) if energy else (d.length, d.flight_time)
            table.add_row(str(d.drone) if s.number == 1 else "", flies if s.number == 1 else "",
                          *([str(s.number)] * battery), f"{length / 1000:.2f} km",
                          f"{time / 60:.1f} min", *([f"{s.energy / 3600:.1f} Wh"] * energy),
                          _names(s.files))
    console.print(table)
    if capacity is not None:
        b = mission.battery
        console.print(f"battery {capacity:g} Wh, {model}: a sortie uses at most "
                      f"{capacity * (1 - b.reserve):.1f} Wh ({1 - b.reserve:.0%}), each "
                      f"resuming {RESUME_OVERLAP:g} m before where the last one turned home; "
                      f"with {b.swap_time:g} s per battery swap, "
                      + ", ".join(f"drone {d.drone} is done after "
                                  f"{_total(d.sorties, b.swap_time) / 60:.1f} min"
                                  for d in team.drones if d.sorties), highlight=False)
    console.print(f"team map: {team.geojson}", highlight=False)
    if team.fence is not None:
        console.print(f"fence for ArduPilot (MAVProxy: fence load): {team.fence}",
                      highlight=False)
    for note in team.notes:
        console.print(note, highlight=False, soft_wrap=True)


def _names(files: tuple[Path, ...]) -> str:
    """``drone-00.plan, .waypoints``: the files of one flight, their shared stem once."""
    return ", ".join([files[0].name, *(p.suffix for p in files[1:])])


def _total(sorties: tuple[SortieExport, ...], swap: float) -> float:
    """Seconds from the first take-off to the last landing, a swap between sorties."""
    return sum(s.duration for s in sorties) + swap * (len(sorties) - 1)
