"""Mission design (team sizing): the smallest team, planner and setting meeting a requirement.

``design(request, out)`` answers "which team reports the target within ``t_d`` with
probability at least ``P_s``?" by simulation, spending runs where the decision is uncertain
(:mod:`sarlink.design.search`) and keeping them in the sweep layer's folders
(:mod:`sarlink.design.runs`), so that a design started again reuses every finished run.
"""

from __future__ import annotations

from pathlib import Path

from sarlink.design.answer import CandidateEstimate, DesignAnswer, PlannerAnswer, TeamSize, Tuning
from sarlink.design.candidates import Candidate, PlannerVariant, Setting
from sarlink.design.live import LiveView
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
           progress: bool = True, max_seconds: float | None = None) -> DesignAnswer:
    """Answer ``request``; runs are stored under ``out`` and reused by any later design.

    ``workers``, ``scheduler`` and ``dask_local`` choose where runs execute, as for
    :func:`sarlink.sweep`. ``progress`` shows the best candidate so far and its interval
    after every round (:class:`~sarlink.design.live.LiveView`, on standard error).
    ``max_seconds``: no round starts after that many seconds; it changes when the search
    stops, never which runs it flies.
    """
    with start_workers(workers, scheduler=scheduler, dask_local=dask_local) as pool, \
            LiveView(progress) as view:
        runs = Runs(out, request.seed, request.td, pool=pool,
                    on_runs=lambda k: view.runs(runs.simulated))
        return search(request, runs, view.round, max_seconds=max_seconds)
