"""Beyond the paper: what drones that fly to tell the BS (``on_detect = report``) change.

Read from the main summary table (the paper's behaviour) and the ``report`` table (the same grid
and runs with reporting drones): common random numbers, so the two differ only by the rule. The
differences carry Newcombe's interval (:meth:`sarlink.paper.evidence.Estimate.minus`), which
treats the two as independent and is therefore conservative for runs that share their targets.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import pandas as pd

from sarlink.paper.evidence import Estimate, Grid
from sarlink.paper.experiments import DRONES, RANGES, TD_FIG3, TD_SHORT
from sarlink.planners import get_planner

__all__ = ["Gain", "beyond_text", "gains"]

TDS = (TD_SHORT, TD_FIG3)
"""The target durations compared: where success is not yet certain for most planners."""
_KEYS = ["planner", "drones", "rc", "td"]


@dataclass(frozen=True)
class Gain:
    """P_s with reporting minus P_s without, at one grid point."""

    planner: str
    drones: int
    rc: float
    td: float
    gain: Estimate

    def where(self) -> str:
        return f"N_m = {self.drones}, r_c = {self.rc:g} m, t_d = {self.td:g} s"


def _points(planners: Sequence[str]) -> list[tuple[str, int, float, float]]:
    return [(p, n, rc, td) for p in planners for n in DRONES for rc in RANGES for td in TDS]


def gains(main: pd.DataFrame, report: pd.DataFrame) -> list[Gain]:
    """The gain in P_s from reporting at every grid point of both tables."""
    paper, reporting = Grid("main", main, _KEYS), Grid("report", report, _KEYS)
    planners = [p for p in report["planner"].unique() if p in set(main["planner"])]
    return [Gain(p, n, rc, td, reporting.at("P_s", p, n, rc, td).minus(
                 paper.at("P_s", p, n, rc, td)))
            for p, n, rc, td in _points(planners)]


def beyond_text(main: pd.DataFrame, report: pd.DataFrame) -> list[str]:
    """Sentences, from the numbers, on where reporting helps most and whether a planner with
    reporting beats every planner of the paper at every grid point."""
    found = gains(main, report)
    if not found:
        return []
    planners = list(dict.fromkeys(g.planner for g in found))
    lines = []
    for p in planners:
        mine = [g for g in found if g.planner == p]
        best = max(mine, key=lambda g: g.gain.value)
        up = sum(g.gain.lo > 0 for g in mine)
        down = sum(g.gain.hi < 0 for g in mine)
        lines.append(f"{get_planner(p).label}: reporting raises P_s significantly at {up} of "
                     f"{len(mine)} grid points and lowers it at {down}; the largest gain is "
                     f"{best.gain} at {best.where()}.")
    top = max(found, key=lambda g: g.gain.value)
    lines.append(f"Reporting helps most {get_planner(top.planner).label}: {top.gain} at "
                 f"{top.where()}.")
    points = [(n, rc, td) for n in DRONES for rc in RANGES for td in TDS]
    always = []
    for p in planners:
        wins, losses = _against_the_paper(main, report, p, planners, points)
        lines.append(f"{get_planner(p).label} with reporting beats every planner of the paper "
                     f"at {wins} of {len(points)} grid points and is beaten by one at {losses}.")
        if wins == len(points):
            always.append(get_planner(p).label)
    lines.append("So " + (", ".join(always) + " with reporting beats every planner of the paper "
                          "at every grid point." if always else
                          "no planner with reporting beats every planner of the paper at every "
                          "grid point (95% intervals; where all are near 1, none can)."))
    return lines


def _against_the_paper(main: pd.DataFrame, report: pd.DataFrame, planner: str,
                       rivals: Sequence[str], points: Sequence[tuple[int, float, float]]
                       ) -> tuple[int, int]:
    """At how many points ``planner`` with reporting is above every rival without (the lower
    bound of each difference above 0), and at how many one rival is above it."""
    paper, reporting = Grid("main", main, _KEYS), Grid("report", report, _KEYS)
    wins = losses = 0
    for n, rc, td in points:
        mine = reporting.at("P_s", planner, n, rc, td)
        diffs = [mine.minus(paper.at("P_s", q, n, rc, td)) for q in rivals]
        wins += all(d.lo > 0 for d in diffs)
        losses += any(d.hi < 0 for d in diffs)
    return wins, losses
