"""The ``sarlink`` command line. Each command lives in a module of its own."""

import typer

from sarlink.cli.design import design
from sarlink.cli.plan import plan
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
)
app.command()(simulate)
app.command()(plan)
app.command()(sweep)
app.command()(summarize)
app.command()(reproduce)
app.command()(design)


@app.callback()
def main() -> None:
    """Plan and simulate search-and-rescue drone teams that must notify their base station."""
