"""Helpers shared by the CLI commands: output paths, JSON (mission flags: :mod:`.flags`)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import typer
from rich.console import Console

from sarlink.cli.errors import err_console, user_errors
from sarlink.config import ConfigError, Mission

__all__ = ["console", "err_console", "output_folder", "plot_file",
           "print_json", "team_text", "user_errors"]

console = Console()


def output_folder(path: Path, option: str, *, create: bool = True) -> Path:
    """``path`` as a folder to write into, created if missing (unless not ``create``: its
    writer creates it once it has something to write); a :class:`ConfigError` names
    ``option`` if it cannot be one."""
    if path.exists() and not path.is_dir():
        raise ConfigError(f"{option} {path} is a file; a folder is expected (a new one is "
                          "created)")
    if not create:
        return path
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ConfigError(f"{option} {path}: cannot create the folder ({exc.strerror})") from None
    return path


def plot_file(path: Path | None, option: str = "--plot") -> Path | None:
    """Check a figure's path before any work is done: its folder exists, it is not a folder,
    and matplotlib knows its format (the suffix)."""
    if path is None:
        return None
    from matplotlib.figure import Figure

    formats = Figure().canvas.get_supported_filetypes()
    suffix = path.suffix.removeprefix(".").lower()
    if suffix not in formats:
        raise ConfigError(f"{option} {path}: the file name must end in a figure format, one of "
                          f".{', .'.join(sorted(formats))}")
    return output_file(path, option)


def output_file(path: Path | None, option: str) -> Path | None:
    """Check a file to write before any work is done: not a folder, in a folder that exists."""
    if path is None:
        return None
    if path.is_dir():
        raise ConfigError(f"{option} {path} is a folder; a file name is expected")
    if not path.parent.is_dir():
        raise ConfigError(f"{option} {path}: the folder {path.parent} does not exist")
    return path


def print_json(data: dict[str, Any]) -> None:
    typer.echo(json.dumps(data, indent=2))


def team_text(mission: Mission) -> str:
    """The team for a title: ``8 drones``, ``8 drones, 3 of them relays``."""
    k = mission.team.relays
    relays = "" if k == 0 else ", one of them a relay" if k == 1 else f", {k} of them relays"
    return f"{mission.team.drones} drones{relays}"
