"""``sarlink plan``: the mTSP plan of a mission, as a table, as JSON, or as a figure."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer
from rich.table import Table

from sarlink.cli.common import build_mission, console, plot_file, print_json, user_errors
from sarlink.config import Mission
from sarlink.mtsp import MtspPlan, plan_for


def _save_plot(result: MtspPlan, mission: Mission, path: Path) -> None:
    import matplotlib.pyplot as plt

    from sarlink.plots import plot_plan

    fig, ax = plt.subplots(figsize=(9, 7), layout="constrained")
    try:
        plot_plan(result, ax, size=mission.area.size, r=mission.sensing.r)
        fig.savefig(path, dpi=150)
    finally:
        plt.close(fig)


def plan(
    drones: Annotated[int | None, typer.Option(help="number of drones N_m (salesmen)")] = None,
    solver: Annotated[str | None, typer.Option(help="ga (the paper's) or ortools")] = None,
    objective: Annotated[str | None, typer.Option(
        help="minsum (total distance, the paper's) or minmax (longest tour)")] = None,
    min_cells: Annotated[int | None, typer.Option(
        help="minimum cells per drone (default floor(cells / drones))")] = None,
    seed: Annotated[int | None, typer.Option(
        help="seed of the plan search (the GA, or the min-max search)", min=0)] = None,
    size: Annotated[float | None, typer.Option(help="side a of the area, m")] = None,
    r: Annotated[float | None, typer.Option(help="sensing range r = cell side, m")] = None,
    speed: Annotated[float | None, typer.Option(help="flight speed V_m, m/s")] = None,
    population: Annotated[int | None, typer.Option(help="GA population")] = None,
    iterations: Annotated[int | None, typer.Option(help="GA iterations")] = None,
    config: Annotated[Path | None, typer.Option(help="mission TOML; flags override it")] = None,
    json: Annotated[bool, typer.Option("--json", help="print one JSON object")] = False,
    plot: Annotated[Path | None, typer.Option(help="write a figure of the plan here")] = None,
) -> None:
    """Plan the mTSP tours of a mission: each drone's cells, tour lengths and search time.

    Plans are cached on disk (see docs/mtsp.md), so asking twice costs nothing.
    """
    with user_errors():
        plot_file(plot)
        mission = build_mission(
            config, {"plan_seed": "--seed"}, drones=drones, solver=solver, objective=objective,
            min_cells=min_cells, plan_seed=seed, size=size, r=r, speed=speed, population=population,
            iterations=iterations,
        )
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
