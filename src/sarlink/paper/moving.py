"""Beyond the paper: the paper's planners and the IAMSAR search patterns against a target that
walks or drifts (Fig. :data:`~sarlink.paper.experiments.MOVING_FIG`), paired run by run.

Run ``k`` draws where the target was last seen from ``(seed, k)`` alone and its motion from a
stream of its own (docs/model.md, Target motion), so run ``k`` of a walking, a drifting and a
still target starts from the same point. The change a motion makes to a planner's P_s is
therefore judged run by run (:mod:`sarlink.paper.paired`: the interval of a difference of two
success indicators from its discordant runs), and so is the comparison of two planners on the
same targets. The best planner of a setting is the one with the highest P_s on these runs (the
first in the registry's order among equals).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import pandas as pd

from sarlink.paper.evidence import Estimate
from sarlink.paper.experiments import MOTIONS, MOVING_TDS, TD_SHORT
from sarlink.paper.paired import RunGrid
from sarlink.planners import PAPER_PLANNERS, get_planner, planner_names

__all__ = [
    "MovingPoint",
    "best_text",
    "motion_label",
    "moving_points",
    "moving_table",
    "moving_text",
]

_KEYS = ["planner", "drones", "rc", "motion", "delay"]


def motion_label(motion: str, delay: float) -> str:
    """A target motion and delay as the report's sentences name them."""
    what = {"still": "a still target", "walk": "a walking target",
            "drift": "a drifting target"}.get(motion, f"a target that moves by {motion!r}")
    return what if motion == "still" else f"{what}, {delay:g} s from the last sighting to take-off"


@dataclass(frozen=True)
class MovingPoint:
    """One planner against a moving target, at one delay and t_d, beside a still target."""

    planner: str
    motion: str
    delay: float
    td: float
    mine: Estimate
    """P_s against the moving target."""
    still: Estimate
    """P_s against a still target on the same runs."""
    change: Estimate
    """``mine`` minus ``still``, paired."""


def _grid(moving_runs: pd.DataFrame) -> tuple[RunGrid, int, float]:
    drones, rc = (moving_runs[c].iloc[0] for c in ("drones", "rc"))
    return RunGrid("moving", moving_runs, _KEYS), int(drones), float(rc)


def _planners(moving_runs: pd.DataFrame) -> list[str]:
    """The planners of the runs, in the registry's order."""
    found = set(moving_runs["planner"])
    return [p for p in planner_names() if p in found]


def _settings(moving_runs: pd.DataFrame) -> list[tuple[str, float]]:
    """The (motion, delay) of the runs other than a still target, in :data:`MOTIONS` order."""
    flown = set(moving_runs[["motion", "delay"]].itertuples(index=False, name=None))
    motions = [m for m in MOTIONS if m != "still"] + sorted(
        {m for m, _ in flown} - set(MOTIONS))
    return [(m, float(d)) for m in motions for d in sorted({d for n, d in flown if n == m})]


def moving_points(moving_runs: pd.DataFrame, tds: Sequence[float] = MOVING_TDS
                  ) -> list[MovingPoint]:
    """Every planner against every moving target of ``moving_runs`` (the ``moving`` sweep's
    per-run values) at each of ``tds``, beside a still target at the same delay."""
    if moving_runs.empty:
        return []
    grid, n, rc = _grid(moving_runs)
    found = []
    for motion, delay in _settings(moving_runs):
        for p in _planners(moving_runs):
            for td in tds:
                mine = grid.stat("P_s", p, n, rc, motion, delay, td=float(td))
                still = grid.stat("P_s", p, n, rc, "still", delay, td=float(td))
                found.append(MovingPoint(p, motion, delay, float(td), mine.estimate(),
                                         still.estimate(), (mine - still).estimate()))
    return found


def _tally(estimates: Sequence[Estimate]) -> tuple[int, int]:
    """At how many the interval lies above 0, and at how many below."""
    return sum(e.lo > 0 for e in estimates), sum(e.hi < 0 for e in estimates)


def moving_text(points: Sequence[MovingPoint]) -> list[str]:
    """Sentences, from the numbers, on what each moving target does to P_s against a still
    one, per motion and delay: at how many (planner, t_d) it lowers and raises P_s, and the
    largest fall."""
    lines = []
    for motion, delay in dict.fromkeys((p.motion, p.delay) for p in points):
        mine = [p for p in points if (p.motion, p.delay) == (motion, delay)]
        up, down = _tally([p.change for p in mine])
        worst = min(mine, key=lambda p: (p.change.value, p.change.hi))
        planners = len({p.planner for p in mine})
        fall = (f"the largest fall: {get_planner(worst.planner).label}, {worst.change} at "
                f"t_d = {worst.td:g} s ({worst.still} to {worst.mine})"
                if worst.change.value < 0 else "no planner's P_s is lower at any point")
        lines.append(
            f"Against {motion_label(motion, delay)}, P_s is lower than against a still one "
            f"at {down} and higher at {up} of {len(mine)} points ({planners} planners × "
            f"t_d = {', '.join(f'{td:g}' for td in dict.fromkeys(p.td for p in mine))} s; "
            f"paired, 95% intervals); {fall}.")
    return lines


def best_text(moving_runs: pd.DataFrame, td: float = TD_SHORT) -> list[str]:
    """Sentences, from the numbers, on which planner has the highest P_s at ``td`` for each
    target, whether the still target's best is beaten (paired) by the best for a moving one,
    and whether the best IAMSAR pattern beats the best of the paper's planners. The default
    ``td``, 1000 s, is where P_s is still rising at the figure's setting: by 2000 s most
    planners notify nearly every run."""
    if moving_runs.empty:
        return []
    grid, n, rc = _grid(moving_runs)
    planners = _planners(moving_runs)
    paper = [p for p in planners if p in PAPER_PLANNERS]
    patterns = [p for p in planners if p not in PAPER_PLANNERS]
    delays = sorted({float(d) for d in moving_runs["delay"]})
    settings = [("still", delays[0]), *_settings(moving_runs)]
    p_s = {(p, m, d): grid.stat("P_s", p, n, rc, m, d, td=td) for p in planners
           for m, d in settings}

    def best(among: Sequence[str], m: str, d: float) -> str:
        return max(among, key=lambda p: p_s[p, m, d].value)

    still_best = best(planners, *settings[0])
    lines = [f"At t_d = {td:g} s the highest P_s: " + "; ".join(
        f"{motion_label(m, d)}: {get_planner(b).label}, {p_s[b, m, d].estimate()}"
        for m, d in settings for b in [best(planners, m, d)]) + "."]
    beaten = []
    for m, d in settings[1:]:
        top = best(planners, m, d)
        if top != still_best:
            gap = (p_s[top, m, d] - p_s[still_best, m, d]).estimate()
            if gap.lo > 0:
                beaten.append(f"{motion_label(m, d)} ({get_planner(top).label} by {gap})")
    label = get_planner(still_best).label
    lines.append(f"So {label}, the best against a still target, is "
                 + ("beaten on the same runs against " + "; ".join(beaten) if beaten else
                    "beaten on the same runs against no moving target (paired, 95% intervals)")
                 + ".")
    if paper and patterns:
        rows = []
        for m, d in settings:
            ours, theirs = best(patterns, m, d), best(paper, m, d)
            gap = (p_s[ours, m, d] - p_s[theirs, m, d]).estimate()
            verdict = "above" if gap.lo > 0 else "below" if gap.hi < 0 else "not told apart from"
            rows.append(f"{motion_label(m, d)}: {get_planner(ours).label} {verdict} "
                        f"{get_planner(theirs).label}, {gap}")
        lines.append(f"The best IAMSAR pattern against the best of the paper's planners at "
                     f"t_d = {td:g} s (paired): " + "; ".join(rows) + ".")
    return lines


def moving_table(points: Sequence[MovingPoint]) -> pd.DataFrame:
    """Every point as text: P_s against the moving and the still target and their paired
    difference, each with its 95% interval."""
    return pd.DataFrame([{
        "target": p.motion, "delay (s)": f"{p.delay:g}", "t_d (s)": f"{p.td:g}",
        "planner": get_planner(p.planner).label, "P_s": str(p.mine),
        "P_s, still target": str(p.still), "difference (paired)": str(p.change),
    } for p in points])
