"""``sarlink planners``: every planner and radio model known here, and where each comes from."""

from __future__ import annotations

from typing import Annotated, Any

import typer
from rich.table import Table

from sarlink.cli.common import console, print_json, user_errors
from sarlink.engine.radios import broken_radios, radio_names, radio_origin
from sarlink.planners import PAPER_PLANNERS, planner_entries
from sarlink.planners.registry import broken_plugins


def listing() -> dict[str, Any]:
    """The planners (name, kind, label, rule, origin, in the paper) and the radio models."""
    planners = [{"name": name, "kind": e.planner.kind, "label": e.planner.label,
                 "rule": e.planner.rule.name if e.planner.rule else None,
                 "origin": e.origin, "paper": name in PAPER_PLANNERS}
                for name, e in planner_entries().items()]
    radios = [{"name": name, "origin": radio_origin(name)} for name in radio_names()]
    broken = [{"entry_point": name, "error": why}
              for name, why in {**broken_plugins(), **broken_radios()}.items()]
    return {"planners": planners, "radios": radios, "broken": broken}


def planners(
    json: Annotated[bool, typer.Option("--json", help="print one JSON object")] = False,
) -> None:
    """List every planner (built-in, registered or installed as a plug-in) and radio model."""
    with user_errors():
        data = listing()
    if json:
        print_json(data)
        return
    table = Table("planner", "kind", "label", "rule", "from", title="Planners")
    for p in data["planners"]:
        table.add_row(p["name"], p["kind"], p["label"], p["rule"] or "-", p["origin"])
    console.print(table)
    radios = Table("radio model", "from", title="Radio models")
    for r in data["radios"]:
        radios.add_row(r["name"], r["origin"])
    console.print(radios)
    for b in data["broken"]:
        console.print(f"[red]plug-in {b['entry_point']} failed to load[/]: {b['error']}")
