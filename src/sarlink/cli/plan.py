"""``sarlink plan``: the mTSP plan of a mission, as a table, as JSON, or as a figure."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.table import Table

from sarlink.cli.common import console, plot_file, print_json, user_errors
from sarlink.cli.flags import MissionFlags, mission_flags
from sarlink.config import Mission
from sarlink.config.region import is_polygon
from sarlink.mtsp import MtspPlan, flyable, plan_for


def _save_plot(result: MtspPlan, mission: Mission, path: Path) -> None:
    import matplotlib.pyplot as plt

    from sarlink.plots import plot_plan
    from sarlink.plots.area import draw_area

    fig, ax = plt.subplots(figsize=(9, 7), layout="constrained")
    try:
        if is_polygon(mission.region):  # the area, and the tours as flown round its holes
            draw_area(ax, mission)
            plot_plan(result, ax, r=mission.sensing.r, routes=flyable(mission, result.routes()))
        else:
            plot_plan(result, ax, size=mission.area.size, r=mission.sensing.r)
        fig.savefig(path, dpi=150)
    finally:
        plt.close(fig)


@mission_flags("plan")
def plan(
    flags: MissionFlags,
    json: Annotated[bool, typer.Option("--json", help="print one JSON object")] = False,
    plot: Annotated[Path | None, typer.Option(help="write a figure of the plan here")] = None,
) -> None:
    """Plan the mTSP tours of a mission: each drone's cells, tour lengths and search time.

    Plans are cached on disk (see docs/mtsp.md), so asking twice costs nothing.
    """
    with user_errors():
        plot_file(plot)
        mission = flags.mission()
        result = plan_for(mission, mission.team.drones)
        if plot is not None:
            _save_plot(result, mission, plot)
    v = mission.team.speed
    out: dict[str, Any] = {
        "drones": len(result.tours),
        "cells": len(result.points),
        "size": mission.area.size,
        "r": mission.sensing.r,
        "bs": list(result.depot),
        "solver": result.solver,
        "objective": result.objective,
        "min_cells": result.min_cells,
        "speed": v,
        "tours": [list(tour) for tour in result.tours],
        "lengths": result.lengths.tolist(),
        "total": result.total,
        "longest": result.longest,
        "longest_time": result.longest / v,
        "solve_seconds": result.seconds,
    }
    if json:
        print_json(out)
        return
    table = Table(title=f"mTSP plan ({result.solver}, {result.objective}): "
                        f"{out['drones']} drones, {out['cells']} cells, BS at "
                        f"({result.depot[0]:g}, {result.depot[1]:g}) m")
    for name in ("drone", "cells", "length (m)", "time (s)"):
        table.add_column(name, justify="right")
    table.add_column("cells in flying order")
    for i, (tour, length) in enumerate(zip(result.tours, result.lengths, strict=True)):
        table.add_row(str(i), str(len(tour)), f"{length:.0f}", f"{length / v:.0f}",
                      " ".join(map(str, tour)))
    console.print(table)
    console.print(f"total {result.total:.0f} m, longest {result.longest:.0f} m = "
                  f"{result.longest / v:.0f} s of flight at {v:g} m/s")
    if plot is not None:
        console.print(f"figure written to {plot}")
