"""Helpers shared by the CLI commands: mission assembly and error reporting."""

from __future__ import annotations

import json
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import typer
from rich.console import Console

from sarlink.config import ConfigError, Mission

console = Console()
err_console = Console(stderr=True, soft_wrap=True)
"""Errors stay one line each, also when stderr is a pipe or a log (rich would wrap at 80)."""


@contextmanager
def user_errors() -> Iterator[None]:
    """Report configuration mistakes as one line and exit with status 2, no traceback."""
    try:
        yield
    except (ConfigError, KeyError, FileNotFoundError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else exc
        err_console.print(f"[bold red]error:[/] {message}", highlight=False)
        raise typer.Exit(2) from None


def build_mission(config: Path | None, **overrides: Any) -> Mission:
    """The mission of a TOML file (or the paper's defaults) with the given flags applied."""
    base = Mission.from_toml(config) if config is not None else Mission()
    return base.replace(**{k: v for k, v in overrides.items() if v is not None})


def print_json(data: dict[str, Any]) -> None:
    typer.echo(json.dumps(data, indent=2))
