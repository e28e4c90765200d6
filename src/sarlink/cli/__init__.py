"""The ``sarlink`` command line. Each command lives in a module of its own."""

from typing import Annotated

import typer

from sarlink.cli.design import design
from sarlink.cli.errors import Guarded
from sarlink.cli.export import export
from sarlink.cli.plan import plan
from sarlink.cli.plugins import plugins
from sarlink.cli.replay import replay
from sarlink.cli.reproduce import reproduce
from sarlink.cli.simulate import simulate
from sarlink.cli.summarize import summarize
from sarlink.cli.sweep import sweep

app = typer.Typer(
    name="sarlink",
    help="Plan and simulate search-and-rescue drone teams that must notify their base station.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    cls=Guarded,
)
app.command()(simulate)
app.command()(plan)
app.command()(sweep)
app.command()(summarize)
app.command()(reproduce)
app.command()(replay)
app.command()(design)
app.command()(plugins)
app.command("planners", hidden=True, help="The same as plugins.")(plugins)
app.command()(export)


@app.callback()
def main(
    debug: Annotated[bool, typer.Option(
        "--debug", help="show the traceback of an unexpected error (also SARLINK_DEBUG=1)")
    ] = False,
) -> None:
    """Plan and simulate search-and-rescue drone teams that must notify their base station."""
