"""Mission design (team sizing): the smallest team, planner and setting meeting a requirement.

``design(request, out)`` answers "which team reports the target within ``t_d`` with
probability at least ``P_s``?" by simulation, spending runs where the decision is uncertain
(:mod:`sarlink.design.search`) and keeping them in the sweep layer's folders
(:mod:`sarlink.design.runs`), so that a design started again reuses every finished run.
"""

from __future__ import annotations

import sys
from pathlib import Path

from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn

from sarlink.design.answer import CandidateEstimate, DesignAnswer, PlannerAnswer, TeamSize, Tuning
from sarlink.design.candidates import Candidate, PlannerVariant, Setting
from sarlink.design.request import DesignRequest
from sarlink.design.runs import Runs, Tally
from sarlink.design.search import search
from sarlink.design.sequential import Decision
from sarlink.execution import start_workers

__all__ = [
    "Candidate",
    "CandidateEstimate",
    "Decision",
    "DesignAnswer",
    "DesignRequest",
    "PlannerAnswer",
    "PlannerVariant",
    "Runs",
    "Setting",
    "Tally",
    "TeamSize",
    "Tuning",
    "design",
]

DEFAULT_OUT = Path("design-results")
"""Where ``sarlink design`` keeps its runs unless told otherwise."""


def design(request: DesignRequest, out: str | Path = DEFAULT_OUT, *, workers: int | None = None,
           scheduler: str | None = None, dask_local: bool = False,
           progress: bool = True) -> DesignAnswer:
    """Answer ``request``; runs are stored under ``out`` and reused by any later design.

    ``workers``, ``scheduler`` and ``dask_local`` choose where runs execute, as for
    :func:`sarlink.sweep`. ``progress`` shows the candidates decided and the runs spent (only
    when standard output is a terminal).
    """
    bar = Progress(TextColumn("design"), BarColumn(), MofNCompleteColumn(),
                   TextColumn("candidates decided, {task.fields[used]:,} runs used, "
                              "{task.fields[simulated]:,} simulated"),
                   disable=not (progress and sys.stdout.isatty()))
    with start_workers(workers, scheduler=scheduler, dask_local=dask_local) as pool, bar:
        task = bar.add_task("design", total=None, used=0, simulated=0)
        runs = Runs(out, request.seed, request.td, pool=pool,
                    on_runs=lambda k: bar.update(task, simulated=runs.simulated))

        def rounds(decided: int, opened: int, used: int) -> None:
            bar.update(task, completed=decided, total=opened, used=used)

        return search(request, runs, rounds)
