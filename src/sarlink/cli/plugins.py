"""``sarlink plugins``: every plug-in of every kind known here (planners, radio models, ...),
where each comes from, and the installed plug-ins that failed to load (``sarlink planners`` is
the same listing)."""

from __future__ import annotations

from typing import Annotated, Any

import typer
from rich.table import Table

from sarlink.cli.common import console, print_json, user_errors
from sarlink.registry import KINDS


def listing() -> dict[str, Any]:
    """Per kind (``planners``, ``radios``, ...): name, the kind's own columns, origin; and the
    broken entry points of every kind."""
    data: dict[str, Any] = {}
    broken = []
    for kind, registry in KINDS.items():
        data[f"{kind}s"] = [{"name": name, **registry.describe(e.obj), "origin": e.origin}
                            for name, e in registry.entries().items()]
        broken += [{"kind": kind, "entry_point": name, "error": why}
                   for name, why in registry.broken().items()]
    return {**data, "broken": broken}


def plugins(
    json: Annotated[bool, typer.Option("--json", help="print one JSON object")] = False,
) -> None:
    """List every plug-in of every kind (built-in, registered in code or installed)."""
    with user_errors():
        data = listing()
    if json:
        print_json(data)
        return
    for kind, registry in KINDS.items():
        rows = data[f"{kind}s"]
        columns = list(rows[0]) if rows else ["name", "origin"]
        title = f"{registry.plural} ({registry.group})"
        table = Table(*(registry.label if c == "name" else "from" if c == "origin" else c
                        for c in columns), title=title, min_width=len(title))
        for row in rows:
            table.add_row(*("-" if row[c] is None else str(row[c]) for c in columns))
        console.print(table)
    for b in data["broken"]:
        console.print(f"[red]{b['kind']} plug-in {b['entry_point']} failed to load[/]: "
                      f"{b['error']}")
