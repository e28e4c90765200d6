"""``sarlink summarize``: the paper's measures per grid point of a results folder."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.table import Table

from sarlink.cli.common import console, user_errors
from sarlink.config import ConfigError

if TYPE_CHECKING:
    import pandas as pd


_MEASURES: list[tuple[str, str]] = [
    ("mission success P_s", "P_s"),
    ("detection P_d", "P_d"),
    ("immediate notification", "immediate"),
    ("mission time (s)", "mission_time"),
    ("search share", "search_share"),
    ("target reachability", "reachability"),
    ("drones connected", "connected"),
    ("BS's network depth (hops)", "depth"),
    ("farthest connected drone (m)", "farthest"),
]
"""Row label and column of each measure printed, formatted as :data:`sarlink.metrics.MEASURES`
says."""
_EACH = [("targets found", "found"), ("targets the BS was told of", "told")]
"""The rows added when some runs have several targets (``target.count > 1``)."""
_BATTERIES = [("sorties per drone (whole run)", "sorties"),
              ("energy per drone (Wh, whole run)", "energy")]
"""The rows added when some runs' teams fly on batteries (``battery.battery_wh``)."""


def _print_tables(table: pd.DataFrame, by: list[str], per_group: int) -> None:
    """One table per grid point: a row per measure, a column per t_d."""
    from sarlink.metrics import MEASURES

    for start in range(0, len(table), per_group):
        rows = table.iloc[start:start + per_group]
        # a column's own first value: a row of an all-numeric frame would turn counts to floats
        point = ", ".join(f"{name}={rows[name].iloc[0]}" for name in by) or "all runs"
        out = Table(title=f"{point} ({rows['runs'].iloc[0]} runs)", title_justify="left")
        out.add_column("measure")
        for td in rows["td"]:
            out.add_column(f"t_d = {td:g} s", justify="right")
        for label, column in (_MEASURES + (_EACH if "found" in rows else [])
                              + (_BATTERIES if "sorties" in rows else [])):
            measure = MEASURES[column]
            out.add_row(label, *(measure.text(row) for _, row in rows.iterrows()))
        console.print(out)


def summarize(
    results: Annotated[Path, typer.Argument(help="results folder written by sarlink sweep")],
    td: Annotated[list[float] | None, typer.Option(
        help="target duration t_d, s; repeat for several; default: the horizon")] = None,
    csv: Annotated[bool, typer.Option("--csv", help="print CSV: a row per point and t_d")] = False,
    json: Annotated[bool, typer.Option("--json", help="print JSON records")] = False,
    rc: Annotated[float | None, typer.Option(
        help="evaluate every run at this communication range, m, flown or not (runs stored with "
             "their notification staircase; reachability and connectivity only where flown)")
    ] = None,
) -> None:
    """P_s, P_d, immediate notification, mission time and reachability per grid point."""
    from sarlink.metrics import summarize as summarize_runs  # pandas: only for this command
    from sarlink.storage import load, read_manifest

    with user_errors():
        if csv and json:
            raise ConfigError("choose one of --csv and --json")
        for t in td or []:
            if not (math.isfinite(t) and t > 0):
                raise ConfigError(f"--td must be a finite number of seconds > 0, got {t:g}")
        by = list(read_manifest(results)["experiment"]["grid"])
        runs = load(results)
        if rc is not None:
            from sarlink.at_range import at_range

            runs = at_range(runs, rc)
        try:
            table = summarize_runs(runs, td=td, by=by)
        except ValueError as exc:  # no runs yet, or t_d beyond the horizon
            raise ConfigError(str(exc)) from None
    if csv:
        typer.echo(table.to_csv(index=False), nl=False)
    elif json:
        typer.echo(table.to_json(orient="records", indent=2, double_precision=15))
    else:
        _print_tables(table, by, len(td) if td else 1)
