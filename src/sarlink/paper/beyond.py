"""Beyond the paper: what drones that fly to tell the BS (``on_detect = report``) change, and how
the other planners (the IAMSAR search patterns) do against the paper's.

Read from the main summary table (the paper's behaviour), the ``report`` table (the same grid
and runs with reporting drones) and the ``others`` table (the other planners on the same grid,
both ways): common random numbers, so they differ only by the planner or the rule. The
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

__all__ = ["Gain", "beyond_text", "gains", "others_text", "where"]

TDS = (TD_SHORT, TD_FIG3)
"""The target durations compared: where success is not yet certain for most planners."""
_KEYS = ["planner", "drones", "rc", "td"]
_POINTS = [(n, rc, td) for n in DRONES for rc in RANGES for td in TDS]
"""The grid points compared: every team size and range, at each of :data:`TDS`."""


def where(drones: int, rc: float, td: float) -> str:
    """A grid point and target duration as the report's sentences name them."""
    return f"N_m = {drones}, r_c = {rc:g} m, t_d = {td:g} s"


@dataclass(frozen=True)
class Gain:
    """P_s with reporting minus P_s without, at one grid point."""

    planner: str
    drones: int
    rc: float
    td: float
    gain: Estimate

    def where(self) -> str:
        return where(self.drones, self.rc, self.td)


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
    points, always = _POINTS, []
    paper, reporting = Grid("main", main, _KEYS), Grid("report", report, _KEYS)
    for p in planners:
        wins, losses = _against(reporting, p, paper, planners, points)
        lines.append(f"{get_planner(p).label} with reporting beats every planner of the paper "
                     f"at {wins} of {len(points)} grid points and is beaten by one at {losses}.")
        if wins == len(points):
            always.append(get_planner(p).label)
    lines.append("So " + (", ".join(always) + " with reporting beats every planner of the paper "
                          "at every grid point." if always else
                          "no planner with reporting beats every planner of the paper at every "
                          "grid point (95% intervals; where all are near 1, none can)."))
    return lines


def _against(mine: Grid, planner: str, theirs: Grid, rivals: Sequence[str],
             points: Sequence[tuple[int, float, float]]) -> tuple[int, int]:
    """At how many points ``planner`` in ``mine`` is above every rival in ``theirs`` (the
    lower bound of each difference above 0), and at how many one rival is above it."""
    wins = losses = 0
    for n, rc, td in points:
        value = mine.at("P_s", planner, n, rc, td)
        diffs = [value.minus(theirs.at("P_s", q, n, rc, td)) for q in rivals]
        wins += all(d.lo > 0 for d in diffs)
        losses += any(d.hi < 0 for d in diffs)
    return wins, losses


_FLOWN = {"continue": "as in the paper", "report": "with reporting"}


def others_text(main: pd.DataFrame, report: pd.DataFrame, others: pd.DataFrame) -> list[str]:
    """Sentences, from the numbers, on how each planner beyond the paper's (the ``others``
    table, with its ``on_detect`` column) does against the paper's planners flown the same
    way (``main`` as in the paper, ``report`` with drones that report), and what reporting
    changes for it."""
    if others.empty:
        return []
    points = _POINTS
    modes = {m: Grid(m, others[others["on_detect"] == m].drop(columns="on_detect"), _KEYS)
             for m in _FLOWN}
    paper = {"continue": Grid("main", main, _KEYS), "report": Grid("report", report, _KEYS)}
    lines, always = [], []
    for p in dict.fromkeys(others["planner"]):
        label = get_planner(p).label
        for mode, flown in _FLOWN.items():
            rivals = list(dict.fromkeys(
                (main if mode == "continue" else report)["planner"]))
            wins, losses = _against(modes[mode], p, paper[mode], rivals, points)
            values = [modes[mode].at("P_s", p, n, rc, td) for n, rc, td in points]
            low = min(range(len(points)), key=lambda k: values[k].value)
            lines.append(f"{label} {flown}: beats every planner of the paper flown the same way "
                         f"at {wins} of {len(points)} grid points and is beaten by one at "
                         f"{losses}; its lowest P_s is {values[low]} at N_m = {points[low][0]}, "
                         f"r_c = {points[low][1]:g} m, t_d = {points[low][2]:g} s.")
            if wins == len(points):
                always.append(f"{label} {flown}")
        change = [modes["report"].at("P_s", p, *pt).minus(modes["continue"].at("P_s", p, *pt))
                  for pt in points]
        lines.append(f"{label}: reporting raises P_s significantly at "
                     f"{sum(g.lo > 0 for g in change)} of {len(points)} grid points and lowers "
                     f"it at {sum(g.hi < 0 for g in change)}.")
    lines.append("So " + (", ".join(always) + " beats every planner of the paper flown the "
                          "same way at every grid point." if always else
                          "no planner beyond the paper's beats every planner of the paper at "
                          "every grid point (95% intervals; where all are near 1, none can)."))
    return lines
