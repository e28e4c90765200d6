"""``sarlink replay``: one run flown by several planners, replayed side by side in a browser."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from sarlink.cli import options
from sarlink.cli.common import console, user_errors
from sarlink.cli.flags import MissionFlags, mission_flags
from sarlink.planners import planner_names
from sarlink.playback import compare


@mission_flags("replay")
def replay(
    flags: MissionFlags,
    planners: Annotated[str | None, typer.Option(
        help="planners to compare, separated by commas; default all")] = None,
    seed: options.Seed = 0,
    run: options.Run = 0,
    out: Annotated[Path, typer.Option("--out", "-o", help="the HTML file to write")
                   ] = Path("replay.html"),
) -> None:
    """Write one self-contained HTML page replaying run RUN of SEED (same target, same
    take-off) with each planner, in synchronised panels under one time control; open it in
    any browser, without network."""
    names = planner_names() if planners is None else [
        name.strip() for name in planners.split(",") if name.strip()]
    with user_errors():
        mission = flags.mission()
        page = compare(mission, names, seed, run)
        page.write(out)
    for panel in page.panels:
        res = panel.result
        detected = "not detected" if res.t_detect is None else f"detected at {res.t_detect:g} s"
        notified = ("BS not notified" if res.t_notify is None
                    else f"BS notified at {res.t_notify:g} s")
        console.print(f"{panel.title}: {detected}, {notified}", highlight=False)
    console.print(f"replay written to {out} ({out.stat().st_size / 1e6:.1f} MB): open it in a "
                  "browser, no network needed", highlight=False, soft_wrap=True)
