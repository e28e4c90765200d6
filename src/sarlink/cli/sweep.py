"""``sarlink sweep``: run an experiment file into a results folder, resuming what it holds."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from sarlink.cli.common import console, output_folder, user_errors
from sarlink.config.experiment import MAX_WORKERS


def sweep(
    experiment: Annotated[Path, typer.Argument(help="experiment TOML file")],
    out: Annotated[Path, typer.Option("--out", "-o", help="results folder, created or resumed")],
    workers: Annotated[int | None, typer.Option(
        help="worker processes (local pool or --dask-local); default: one per core",
        min=1, max=MAX_WORKERS)] = None,
    scheduler: Annotated[str | None, typer.Option(
        help="address of a running Dask scheduler, tcp://host:port")] = None,
    dask_local: Annotated[bool, typer.Option(
        "--dask-local", help="run on a Dask LocalCluster instead of the process pool")] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="no progress, no summary")] = False,
) -> None:
    """Run every grid point of an experiment; an interrupted sweep resumes where it stopped."""
    from sarlink.config import Experiment
    from sarlink.execution import sweep as run_sweep  # pandas and pyarrow: only for this command

    with user_errors():
        exp = Experiment.from_toml(experiment)
        runs = run_sweep(exp, output_folder(out, "--out"), workers=workers, scheduler=scheduler,
                         dask_local=dask_local, progress=not quiet)
    if not quiet:
        console.print(f"{len(runs)} runs of {runs['point'].nunique()} grid points in {out}; "
                      f"see them with `sarlink summarize {out}`", highlight=False)
