"""``sarlink simulate``: one run, summarised, as JSON, or as a figure."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer
from rich.table import Table

from sarlink.cli import options
from sarlink.cli.common import (
    console,
    output_file,
    plot_file,
    print_json,
    team_text,
    user_errors,
)
from sarlink.cli.flags import MissionFlags, mission_flags
from sarlink.config import Mission
from sarlink.planners import get_planner
from sarlink.playback import replay
from sarlink.result import RunResult
from sarlink.simulation import simulate as run_simulation


def _finite_or_none(value: float) -> float | None:
    return value if math.isfinite(value) else None


def _save_plot(result: RunResult, mission: Mission, path: Path) -> None:
    import matplotlib.pyplot as plt

    from sarlink.plots import plot_network, plot_run

    fig, (ax, hops) = plt.subplots(2, 1, figsize=(7, 9.5), height_ratios=(7, 2.5),
                                   layout="constrained")
    try:
        plot_run(result, mission, ax=ax)
        plot_network(result, mission, ax=hops)
        fig.savefig(path, dpi=150)
    finally:
        plt.close(fig)


def _when(times: np.ndarray, values: np.ndarray, text: str) -> str:
    """``text`` and the first checkpoint at which ``values`` was largest."""
    return f"{text}, first at {times[int(np.nanargmax(values))]:g} s"


def _each_target(result: RunResult, mission: Mission) -> dict[str, Any]:
    """The JSON fields of a run with several targets (``target.count > 1``)."""
    assert result.targets is not None and result.t_detect_each is not None
    assert result.t_notify_each is not None and result.detector_each is not None

    def times(values: np.ndarray) -> list[float | None]:
        return [None if math.isnan(v) else float(v) for v in values.tolist()]

    out: dict[str, Any] = {
        "success": mission.target.success,
        "targets": [[round(float(x), 1), round(float(y), 1)] for x, y in result.targets],
        "t_detect_each": times(result.t_detect_each),
        "t_notify_each": times(result.t_notify_each),
        "detector_each": [None if d < 0 else int(d) for d in result.detector_each.tolist()],
        "found": result.found(),
        "notified": result.told(),
    }
    traj = result.trajectory
    if traj is not None and traj.target is not None:  # where each one was at the end
        out["targets_at_end"] = [[round(float(x), 1), round(float(y), 1)]
                                 for x, y in traj.target[-1]]
    return out


@mission_flags("simulate")
def simulate(
    flags: MissionFlags,
    seed: options.Seed = 0,
    run: options.Run = 0,
    json: Annotated[bool, typer.Option("--json", help="print one JSON object")] = False,
    plot: Annotated[Path | None, typer.Option(help="write a figure of the run here")] = None,
    html: Annotated[Path | None, typer.Option(
        help="write an interactive replay of the run here (one HTML file, works offline)")
    ] = None,
) -> None:
    """Simulate one mission run and report detection, notification and reachability."""
    with user_errors():
        plot_file(plot)
        output_file(html, "--html")
        mission = flags.mission()
        moves = mission.target.motion != "still"  # its track says where it went
        result = run_simulation(mission, seed=seed, run=run,
                                trajectory=plot is not None or html is not None or moves)
        if plot is not None:
            _save_plot(result, mission, plot)
        if html is not None:
            replay(result, mission).write(html)
    out: dict[str, Any] = {
        "planner": mission.team.planner,
        "drones": mission.team.drones,
        "relays": mission.team.relays,
        "rc": mission.channel.rc,
        "td": mission.timing.horizon,
        "seed": seed,
        "run": run,
        "target": list(result.target),
        "t_detect": result.t_detect,
        "t_notify": result.t_notify,
        "immediate": result.immediate,
        "detector": result.detector,
        # null, not NaN, when the run stopped before the horizon: JSON has no NaN
        "t_reachable": _finite_or_none(result.t_reachable()),
        "connected_fraction": _finite_or_none(result.connected_fraction()),
        # the BS's network at the checkpoints: null where not recorded (docs/model.md)
        "depth_max": _finite_or_none(float(np.nanmax(result.depth, initial=-np.inf))),
        "farthest_max": _finite_or_none(float(np.nanmax(result.farthest, initial=-np.inf))),
    }
    if result.targets is not None:  # several targets: each one's position and events
        out.update(_each_target(result, mission))
    traj = result.trajectory
    # one moving target: where it was when found (several: each one's events above)
    walked = None if traj is None or traj.target is None or result.targets is not None \
        else traj.target[:, 0, :]
    if traj is not None and walked is not None:  # a moving target: where it was when found
        out["target_motion"] = mission.target.motion
        out["target_delay"] = mission.target.delay
        out["target_motion_step"] = mission.target.motion_step
        found = None if result.t_detect is None else \
            walked[int(np.searchsorted(traj.t, result.t_detect))]
        out["target_at_detection"] = None if found is None else [round(float(v), 1)
                                                                 for v in found]
        out["target_at_end"] = [round(float(v), 1) for v in walked[-1]]
    if result.sorties is not None and result.ground_time is not None and \
            result.energy is not None:  # a team on batteries
        out["sorties"] = result.sorties.tolist()
        out["ground_time"] = result.ground_time.tolist()
        out["energy_wh"] = [round(e / 3600.0, 3) for e in result.energy.tolist()]
    region = mission.region
    if region is not None and region.anchor is not None:  # on the map: where to look
        from sarlink.export import mission_frame

        lon, lat = mission_frame(mission).to_lonlat(*result.target)
        out["target_lonlat"] = [round(float(lon), 7), round(float(lat), 7)]
    if json:
        print_json(out)
        return
    label = get_planner(mission.team.planner).label
    table = Table(title=f"{label}: {team_text(mission)}, r_c = {mission.channel.rc:g} m, "
                        f"t_d = {mission.timing.horizon:g} s (seed {seed}, run {run})")
    table.add_column("outcome")
    table.add_column("value", justify="right")
    never = "[dim]not within t_d[/]"
    where = f"({result.target[0]:.0f}, {result.target[1]:.0f}) m"
    if "target_lonlat" in out:
        where += " = {:.5f}, {:.5f}".format(*out["target_lonlat"])
    if result.targets is None:  # several: each one's row below
        table.add_row("target last seen at" if walked is not None else "target at", where)
    if walked is not None:
        every = (f"every {mission.target.motion_step:g} s" if mission.target.motion_step
                 else "every time step")
        table.add_row("target moves", f"{mission.target.motion}, {every}, from "
                      f"{mission.target.delay:g} s before take-off")
        if out["target_at_detection"] is not None:
            table.add_row("target when detected", "({:.0f}, {:.0f}) m".format(
                *out["target_at_detection"]))
        table.add_row("target at the end", "({:.0f}, {:.0f}) m".format(*out["target_at_end"]))
    if "t_detect_each" in out:
        table.add_row("targets", f"{mission.target.count}, success when "
                      f"{'every one' if mission.target.success == 'all' else 'the first'} "
                      "is found and the BS told")
        for j, (xy, td, tn) in enumerate(zip(out["targets"], out["t_detect_each"],
                                             out["t_notify_each"], strict=True)):
            table.add_row(f"target {j + 1} last seen at ({xy[0]:.0f}, {xy[1]:.0f}) m",
                          ("not found" if td is None else f"found at {td:g} s")
                          + ("" if tn is None else f", BS told at {tn:g} s"))
    table.add_row("detected at", never if result.t_detect is None else
                  f"{result.t_detect:g} s by drone {result.detector}")
    table.add_row("BS notified at", never if result.t_notify is None else f"{result.t_notify:g} s")
    table.add_row("mission success", "yes" if result.notified() else "no")
    table.add_row("immediate notification", "yes" if result.immediate else "no")
    if out["t_reachable"] is None:
        unrecorded = f"[dim]not recorded (the run stopped when {mission.timing.stop})[/]"
        table.add_row("target reachable", unrecorded)
        table.add_row("drones connected to BS", unrecorded)
    else:
        table.add_row("target reachable" if result.targets is None else
                      "target 1 reachable", f"{out['t_reachable']:g} s "
                      f"({out['t_reachable'] / mission.timing.horizon:.1%} of t_d)")
        table.add_row("drones connected to BS", f"{out['connected_fraction']:.1%} on average")
    if out["depth_max"] is not None:
        hops = round(out["depth_max"])
        table.add_row("BS's network, deepest", _when(
            result.checkpoints, result.depth, f"{hops} hop{'' if hops == 1 else 's'}"))
        table.add_row("farthest connected drone", _when(
            result.checkpoints, result.farthest,
            f"{out['farthest_max']:.0f} m (r_c = {mission.channel.rc:g} m)"))
    if "sorties" in out:
        table.add_row("sorties per drone", ", ".join(map(str, out["sorties"])))
        table.add_row("on the ground for swaps", ", ".join(f"{g:g} s" for g in
                                                           out["ground_time"]))
        table.add_row("energy drawn", ", ".join(f"{e:.1f} Wh" for e in out["energy_wh"]))
    console.print(table)
    if plot is not None:
        console.print(f"figure written to {plot}")
    if html is not None:
        console.print(f"replay written to {html}: open it in a browser")
