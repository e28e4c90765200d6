"""Command options shared by several commands that are not mission flags (those are the
table of :mod:`sarlink.cli.flags`)."""

from __future__ import annotations

from typing import Annotated

import typer

Seed = Annotated[int, typer.Option(help="experiment seed", min=0)]
Run = Annotated[int, typer.Option(help="run index within the experiment", min=0)]
