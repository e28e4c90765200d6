"""``sarlink summarize``: the paper's measures per grid point of a results folder."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.table import Table

from sarlink.cli.common import console, user_errors
from sarlink.config import ConfigError

if TYPE_CHECKING:
    import pandas as pd


def _probability(row: Any, name: str) -> str:
    p = row[name]
    return "–" if math.isnan(p) else f"{p:.3f} [{row[name + '_lo']:.3f}, {row[name + '_hi']:.3f}]"


def _mean(row: Any, name: str, digits: int) -> str:
    m, se = row[name], row[name + "_se"]
    if math.isnan(m):
        return "–"
    return f"{m:.{digits}f}" + ("" if math.isnan(se) else f" ± {se:.{digits}f}")


_MEASURES: list[tuple[str, Callable[[Any], str]]] = [
    ("mission success P_s", lambda r: _probability(r, "P_s")),
    ("detection P_d", lambda r: _probability(r, "P_d")),
    ("immediate notification", lambda r: _probability(r, "immediate")),
    ("mission time (s)", lambda r: _mean(r, "mission_time", 0)),
    ("search share", lambda r: _mean(r, "search_share", 3)),
    ("target reachability", lambda r: _mean(r, "reachability", 3)),
    ("drones connected", lambda r: _mean(r, "connected", 3)),
]


def _print_tables(table: pd.DataFrame, by: list[str], per_group: int) -> None:
    """One table per grid point: a row per measure, a column per t_d."""
    for start in range(0, len(table), per_group):
        rows = table.iloc[start:start + per_group]
        first = rows.iloc[0]
        point = ", ".join(f"{name}={first[name]}" for name in by) or "all runs"
        out = Table(title=f"{point} ({first['runs']} runs)", title_justify="left")
        out.add_column("measure")
        for td in rows["td"]:
            out.add_column(f"t_d = {td:g} s", justify="right")
        for label, cell in _MEASURES:
            out.add_row(label, *(cell(row) for _, row in rows.iterrows()))
        console.print(out)


def summarize(
    results: Annotated[Path, typer.Argument(help="results folder written by sarlink sweep")],
    td: Annotated[list[float] | None, typer.Option(
        help="target duration t_d, s; repeat for several; default: the horizon")] = None,
    csv: Annotated[bool, typer.Option("--csv", help="print CSV: a row per point and t_d")] = False,
    json: Annotated[bool, typer.Option("--json", help="print JSON records")] = False,
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
        try:
            table = summarize_runs(load(results), td=td, by=by)
        except ValueError as exc:  # no runs yet, or t_d beyond the horizon
            raise ConfigError(str(exc)) from None
    if csv:
        typer.echo(table.to_csv(index=False), nl=False)
    elif json:
        typer.echo(table.to_json(orient="records", indent=2, double_precision=15))
    else:
        _print_tables(table, by, len(td) if td else 1)
