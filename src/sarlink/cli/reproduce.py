"""``sarlink reproduce``: rerun the paper's evaluation, draw its figures, check its findings."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from sarlink.cli.common import console, output_folder, user_errors
from sarlink.config import DEFAULT_READING, READINGS, ConfigError
from sarlink.config.experiment import MAX_WORKERS


def _numbers(text: str | None) -> list[int] | None:
    if text is None:
        return None
    try:
        return [int(part) for part in text.split(",") if part.strip()]
    except ValueError:
        raise ConfigError(f"--figures takes figure numbers separated by commas, like 1,3,7; "
                          f"got {text!r}") from None


def reproduce(
    runs: Annotated[int | None, typer.Option(
        help="runs per grid point; default 2000 (the paper's), 100 with --quick")] = None,
    quick: Annotated[bool, typer.Option(
        "--quick", help="few runs (100 per point): the trends in minutes")] = False,
    out: Annotated[Path, typer.Option(
        "--out", "-o", help="output folder, created or resumed")] = Path("reproduction"),
    figures: Annotated[str | None, typer.Option(
        help="figures to reproduce, e.g. 1,3,7 (the paper's 1-7; beyond the paper, 8: drones "
             "that fly to tell the BS, 9: the other planners, such as the IAMSAR search "
             "patterns, 10: P_s against a continuous range, 11: searchers and relays, "
             "12: targets that walk or drift); default all")] = None,
    workers: Annotated[int | None, typer.Option(
        help="local worker processes; default one per core", min=1, max=MAX_WORKERS)] = None,
    scheduler: Annotated[str | None, typer.Option(
        help="address of a running Dask scheduler, tcp://host:port")] = None,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="no progress bars")] = False,
    reading: Annotated[str, typer.Option(
        help=f"the reading of what the paper leaves open: {', '.join(READINGS)} "
             "(docs/model.md, Readings)")] = DEFAULT_READING,
    sensitivity: Annotated[bool, typer.Option(
        "--sensitivity", help="also decide every claim under each single change of the "
        "reading (reruns only what a change reaches) and report what each claim depends "
        "on")] = False,
    presets: Annotated[bool | None, typer.Option(
        "--presets/--no-presets", help="also tally the claims under every other preset "
        "reading (reruns the planners each reaches); default: yes, but not with --quick",
        show_default=False)] = None,
) -> None:
    """Rerun the experiments behind the paper's Figs. 1-7 (and Figs. 8-12, beyond it), draw
    them and report which of the paper's claims hold, are contradicted or stay undecided; an
    interrupted reproduction resumes where it stopped."""
    import matplotlib

    matplotlib.use("Agg")  # files only, never a window

    from sarlink.paper import reproduce as run_reproduction
    from sarlink.paper.findings import tally

    with user_errors():
        folder = output_folder(out, "--out")  # plan_times.json goes straight into it
        result = run_reproduction(folder, runs=runs, quick=quick, figures=_numbers(figures),
                                  workers=workers, scheduler=scheduler, progress=not quiet,
                                  reading=reading, sensitivity_analysis=sensitivity,
                                  presets=presets)
    findings = (f"{len(result.findings)} of the paper's claims checked: "
                f"{tally(result.findings)}" if result.findings else "no claims checked")
    others = "".join(f"; under {name}: {tally(found)}" for name, found in result.presets.items()
                     if name != result.reading and found)
    changes = (f"; {len(result.variants)} single changes of the reading decided too"
               if result.variants else "")
    console.print(f"report: {result.report_html} and {result.report_md} "
                  f"({result.runs} runs per point, reading {result.reading!r}, "
                  f"{result.seconds:.0f} s); {findings}{others}{changes}",
                  highlight=False, soft_wrap=True)
