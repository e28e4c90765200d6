"""Beyond the paper: searchers and relays against the paper's five planners at equal team size
(Fig. :data:`~sarlink.paper.experiments.RELAY_FIG`), paired run by run.

Every sweep flies runs ``0 .. n-1`` of the one seed, and run ``k`` draws its target from
``(seed, k)`` alone, whatever the team: run ``k`` of CovB with 3 relays among 10 drones and
run ``k`` of each paper planner with 10 drones search for the same target. So P_s of the
searchers and relays is compared at each grid point (N_m, r_c, t_d) with that of the best of
the paper's five there, and with that of the searchers' planner when every drone searches (no
relays), run by run (:mod:`sarlink.paper.paired`: the interval of a difference of two success
indicators from its discordant runs, McNemar's exact test for its sign). The best is the one
with the highest P_s at that point on these runs (the first in the paper's legend order among
equals): picking the largest of five on the same runs favours the paper, so a point where the
relays come out above it is not a chance pick.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import pandas as pd

from sarlink.paper.beyond import where
from sarlink.paper.evidence import Estimate
from sarlink.paper.experiments import RELAY_PLANNER, RELAY_TDS, relay_label
from sarlink.paper.paired import RunGrid
from sarlink.planners import PAPER_PLANNERS, get_planner

__all__ = ["RelayPoint", "relay_points", "relays_summary", "relays_table", "relays_text"]


@dataclass(frozen=True)
class RelayPoint:
    """The searchers and relays at one grid point against the paper's planners."""

    relays: int
    drones: int
    rc: float
    td: float
    mine: Estimate
    """P_s of the searchers and relays."""
    best: str
    """The paper's planner with the highest P_s at this point."""
    theirs: Estimate
    """Its P_s."""
    gain: Estimate
    """``mine`` minus ``theirs``, paired."""
    alone: Estimate
    """``mine`` minus P_s of the searchers' planner with every drone searching, paired."""

    def where(self) -> str:
        return where(self.drones, self.rc, self.td)


def relay_points(main_runs: pd.DataFrame, relays_runs: pd.DataFrame,
                 tds: Sequence[float] = RELAY_TDS) -> list[RelayPoint]:
    """Every grid point of ``relays_runs`` (the ``relays`` sweep's per-run values) at each
    of ``tds`` against the paper's planners in ``main_runs`` (the ``main`` sweep's), over the
    runs the relays flew: a quick reproduction flies fewer of them, the first ones, which
    every sweep has."""
    if relays_runs.empty:
        return []
    flown = set(relays_runs["run"])
    missing = flown - set(main_runs["run"])
    if missing:
        raise ValueError(f"the relays' runs {sorted(missing)[:3]} are not among the main "
                         "sweep's: paired statistics need the same runs on both sides")
    paper = RunGrid("main", main_runs[main_runs["run"].isin(flown)],
                    ["planner", "drones", "rc"])
    mine = RunGrid("relays", relays_runs, ["planner", "drones", "rc", "relays"])
    planners = [p for p in PAPER_PLANNERS if p in set(main_runs["planner"])]
    points = relays_runs[["relays", "drones", "rc"]].drop_duplicates().sort_values(
        ["relays", "rc", "drones"])
    found = []
    for k, n, rc in points.itertuples(index=False):
        for td in tds:
            ours = mine.stat("P_s", RELAY_PLANNER, n, rc, k, td=float(td))
            theirs = {p: paper.stat("P_s", p, n, rc, td=float(td)) for p in planners}
            best = max(planners, key=lambda p: theirs[p].value)
            found.append(RelayPoint(
                int(k), int(n), float(rc), float(td), ours.estimate(), best,
                theirs[best].estimate(),
                (ours - theirs[best]).estimate(),
                (ours - paper.stat("P_s", RELAY_PLANNER, n, rc, td=float(td))).estimate()))
    return found


def _tally(estimates: Sequence[Estimate]) -> tuple[int, int]:
    """At how many the interval lies above 0, and at how many below."""
    return sum(e.lo > 0 for e in estimates), sum(e.hi < 0 for e in estimates)


def relays_text(points: Sequence[RelayPoint]) -> list[str]:
    """Sentences, from the numbers, on where searchers and relays beat the best of the
    paper's planners at equal team size, what the relays cost or buy their own planner, and
    whether some relay count beats the paper at every point."""
    if not points:
        return []
    searcher = get_planner(RELAY_PLANNER).label
    lines = []
    for k in sorted({p.relays for p in points}):
        mine = [p for p in points if p.relays == k]
        up, down = _tally([p.gain for p in mine])
        top = max(mine, key=lambda p: (p.gain.value, p.gain.lo))
        low = min(mine, key=lambda p: p.gain.value)
        raised, lowered = _tally([p.alone for p in mine])
        lines.append(
            f"{relay_label(k)} (N_m − {k} searchers): above the best of the paper's planners "
            f"at {up} of {len(mine)} points and below it at {down}; closest to it or above: "
            f"{top.gain} at {top.where()} (against {get_planner(top.best).label}); farthest "
            f"below: {low.gain} at {low.where()} (against {get_planner(low.best).label}). "
            f"Against {searcher} with every drone searching, P_s is higher with the relays at "
            f"{raised} of {len(mine)} points and lower at {lowered}.")
    where = sorted({(p.drones, p.rc, p.td) for p in points})
    some = [w for w in where if any(p.gain.lo > 0 for p in points
                                    if (p.drones, p.rc, p.td) == w)]
    none = [w for w in where if all(p.gain.hi < 0 for p in points
                                    if (p.drones, p.rc, p.td) == w)]
    lines.append(f"So at {len(some)} of {len(where)} points (N_m, r_c, t_d) some relay count "
                 "beats the best of the paper's planners at equal team size, and at "
                 f"{len(none)} every relay count is beaten by it (paired, 95% intervals; "
                 "where all are near 1, none can be told apart)."
                 + ("" if not some else " Those points: " + "; ".join(
                     f"N_m = {n}, r_c = {rc:g} m, t_d = {td:g} s" for n, rc, td in some)
                    + "."))
    return lines


def _count(part: int, whole: int) -> str:
    return f"{part} of {whole}"


def relays_summary(points: Sequence[RelayPoint]) -> pd.DataFrame:
    """Per relay count and range, at how many points (team sizes × t_d) the searchers and
    relays are above and below the best of the paper's planners and their own planner with
    every drone searching."""
    alone = get_planner(RELAY_PLANNER).label
    rows = []
    for (k, rc), group in pd.DataFrame({"k": [p.relays for p in points],
                                        "rc": [p.rc for p in points]}).groupby(["k", "rc"]):
        mine = [points[i] for i in group.index]
        up, down = _tally([p.gain for p in mine])
        raised, lowered = _tally([p.alone for p in mine])
        rows.append({"team": relay_label(int(k)), "r_c (m)": f"{rc:g}",
                     "above the best of the paper": _count(up, len(mine)),
                     "below the best of the paper": _count(down, len(mine)),
                     f"above {alone} alone": _count(raised, len(mine)),
                     f"below {alone} alone": _count(lowered, len(mine))})
    return pd.DataFrame(rows)


def relays_table(points: Sequence[RelayPoint]) -> pd.DataFrame:
    """Every point as text: the searchers and relays' P_s, the best of the paper's planners
    and its P_s, and the paired differences, each with its 95% interval."""
    return pd.DataFrame([{
        "r_c (m)": f"{p.rc:g}", "t_d (s)": f"{p.td:g}", "N_m": p.drones,
        "team": relay_label(p.relays), "P_s": str(p.mine),
        "best of the paper": get_planner(p.best).label, "its P_s": str(p.theirs),
        "difference (paired)": str(p.gain),
        f"minus {get_planner(RELAY_PLANNER).label} alone (paired)": str(p.alone),
    } for p in sorted(points, key=lambda p: (p.rc, p.td, p.drones, p.relays))])
