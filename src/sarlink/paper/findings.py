"""The paper's checkable claims (Section 4, Figs. 1–7), each decided from the summary tables.

Each claim is the paper's statement, grouped by the figure it is about, with a check whose
docstring is the exact criterion (the report quotes it). A check reads the summary tables of
:mod:`sarlink.paper.experiments` and tests one or more parts, each *holds*, *contradicted* or
*undecided at this sample size* by the rules of :mod:`sarlink.paper.evidence`; the claim's
outcome is that of its parts together. The criteria were written from the paper's words, not
from the results. Conventions where the paper is loose:

- Comparisons between planners ("X beats Y", "the lowest") average the difference over the
  team sizes N_m = 2, ..., 22; statements about levels of every scheme ("all low", "all near
  1") hold at every team size.
- mTSP-ConB flies exactly mTSP's mission up to N_r = 6 drones, so the two are compared only
  above N_r.
- "Near 1" is above :data:`NEAR_ONE`; "about x" is x ± :data:`ABOUT`; a "small" or "slight"
  change of a probability, and "no help", is less than :data:`SMALL`.
- Fig. 3's t_d, which the paper does not state, is :attr:`Settings.td_fig3`.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import pandas as pd

from sarlink.config import Mission
from sarlink.metrics import MEASURES
from sarlink.paper.evidence import (
    Estimate,
    Outcome,
    Part,
    SummaryTables,
    Verdict,
    average,
    change,
    peak,
    spread,
    worst,
)
from sarlink.paper.experiments import (
    DRONES,
    FIG2_DRONES,
    FIG5_RANGES,
    P_MISS,
    RANGES,
    TD_FIG3,
    TD_LONG,
    TD_SHORT,
)
from sarlink.planners import PAPER_PLANNERS, get_planner

__all__ = ["CLAIMS", "DEFAULT_SETTINGS", "Claim", "Finding", "Settings", "check_all", "tally"]

NEAR_ONE = 0.9
"""A probability whose interval lies above this is "near 1" (the paper's "higher than 90%")."""
ABOUT = 0.1
"""What "about x" admits for a probability or share: the interval must lie within x ± this."""
SMALL = 0.1
"""A change of a probability smaller than this (ten points) is "small", "slight", "no help"."""
LOW = 0.25
"""Target reachability below this share of t_d (a quarter) is "low"."""
FLAT = 2.0
"""A plan time that changes by less than this factor over Fig. 1's team sizes (2 to 22, an
11-fold team) "does not change significantly"; Fig. 1's log axis spans decades."""
SMALL_MISS = 0.2
"""The largest miss probability that is "small" (Fig. 7a)."""
SMALL_TEAMS = (2, 4)
"""The "small N_m" of the mission-time claim: the two smallest teams."""
NR = Mission().team.nr
"""mTSP-ConB's mTSP drones: up to this team size it flies exactly the mTSP plan."""


@dataclass(frozen=True)
class Settings:
    """Choices the paper leaves open that the claims' checks depend on (a model reading can
    set them; the defaults are sarlink's)."""

    td_fig3: float = TD_FIG3
    """Fig. 3's target duration, s, at which the claims of Figs. 2–3 read P_s: the paper does
    not state it (:data:`sarlink.paper.experiments.TD_FIG3`, 2000 s; 4000 s is the other
    candidate). The main table has P_s at 1000, 2000 and 4000 s."""


DEFAULT_SETTINGS = Settings()
"""sarlink's choices."""


@dataclass(frozen=True)
class Finding:
    """One of the paper's claims decided on sarlink's results."""

    figure: str
    """The figure the claim is about (``Fig. 1``, ``Figs. 2–3``, ..., ``Fig. 7b``)."""
    claim: str
    outcome: Outcome
    parts: tuple[Part, ...]
    """Every tested part: the numbers that decide it, with their 95% intervals."""
    notes: tuple[str, ...]
    """Numbers shown for context, which decide nothing."""
    criterion: str
    """The exact rule applied (the check's docstring)."""

    @property
    def holds(self) -> bool:
        """Whether the claim holds (neither contradicted nor undecided)."""
        return self.outcome is Outcome.HOLDS

    @property
    def against(self) -> tuple[Part, ...]:
        """The parts that do not hold, the contradicted ones first."""
        return tuple(sorted((p for p in self.parts if p.outcome is not Outcome.HOLDS),
                            key=lambda p: p.outcome is not Outcome.CONTRADICTED))


Check = Callable[[SummaryTables, Settings], Verdict]


@dataclass(frozen=True)
class Claim:
    """A claim of the paper, the summary tables its check reads, and the check."""

    figure: str
    text: str
    tables: tuple[str, ...]
    check: Check

    @property
    def name(self) -> str:
        return self.check.__name__

    @property
    def criterion(self) -> str:
        return " ".join((self.check.__doc__ or "").split())

    def checkable(self, tables: Mapping[str, pd.DataFrame]) -> bool:
        return all(t in tables for t in self.tables)

    def __call__(self, tables: Mapping[str, pd.DataFrame],
                 settings: Settings = DEFAULT_SETTINGS) -> Finding:
        verdict = self.check(SummaryTables(tables), settings)
        return Finding(self.figure, self.text, worst(p.outcome for p in verdict.parts),
                       tuple(verdict.parts), tuple(verdict.notes), self.criterion)


CLAIMS: list[Claim] = []
"""Every claim, grouped by figure in the paper's order."""


def _claim(figure: str, text: str, tables: tuple[str, ...] = ("main",)
           ) -> Callable[[Check], Claim]:
    def register(check: Check) -> Claim:
        claim = Claim(figure, text, tables, check)
        CLAIMS.append(claim)
        return claim
    return register


def check_all(tables: Mapping[str, pd.DataFrame],
              settings: Settings = DEFAULT_SETTINGS) -> list[Finding]:
    """Every claim whose summary tables are in ``tables``, decided on them."""
    return [claim(tables, settings) for claim in CLAIMS if claim.checkable(tables)]


def tally(findings: Sequence[Finding]) -> str:
    """``"N hold, M contradicted, K undecided"``."""
    count = {o: sum(f.outcome is o for f in findings) for o in Outcome}
    return (f"{count[Outcome.HOLDS]} hold, {count[Outcome.CONTRADICTED]} contradicted, "
            f"{count[Outcome.UNDECIDED]} undecided")


def _label(planner: str) -> str:
    return get_planner(planner).label


def _rc(rc: float) -> str:
    return f"r_c = {rc:g} m"


def _others(planner: str) -> list[str]:
    return [p for p in PAPER_PLANNERS if p != planner]


def _same_up_to(a: str, b: str) -> int:
    """Team sizes up to which ``a`` and ``b`` fly the same mission (mTSP and mTSP-ConB)."""
    return NR if {a, b} == {"mtsp", "mtsp-conb"} else 0


def _gap(t: SummaryTables, a: str, b: str, rc: float, td: float, column: str) -> Estimate:
    return t.main.gap(a, b, rc, td, column, _same_up_to(a, b))


def _order(v: Verdict, t: SummaryTables, planner: str, others: Sequence[str],
           ranges: Sequence[float], column: str, *, higher: bool) -> None:
    """Test at t_d = 4000 s and each range that ``planner``'s ``column`` minus each of
    ``others``', averaged over team sizes, lies above 0 (``higher``) or below 0."""
    for rc in ranges:
        for p in others:
            g = _gap(t, planner, p, rc, TD_LONG, column)
            v.test(g.above(0.0) if higher else g.below(0.0),
                   f"{_rc(rc)}: {_label(planner)} − {_label(p)} {MEASURES[column].label} "
                   f"averaged over N_m: {g}")


# -- Fig. 1 --------------------------------------------------------------------------------------


@_claim("Fig. 1", "CovB's plan computation time is the lowest.", ("plan_times",))
def covb_plans_fastest(t: SummaryTables, s: Settings) -> Verdict:
    """For mTSP and for ConB: the ratio of its plan computation time to CovB's lies above 1.
    The ratio is a geometric mean over the timed team sizes: per team size, the difference of
    mean log times has Welch's 95% interval from the repeated timings, and the average over
    team sizes averages the bounds."""
    v = Verdict()
    times = t.plan_times
    for p in ("mtsp", "conb"):
        ratio = average(times.log_ratio(p, "covb", n) for n in times.team_sizes())
        ratio = ratio.mapped(math.exp, 2)
        v.test(ratio.above(1.0), f"{_label(p)} / CovB plan time, geometric mean over N_m: "
                                 f"{ratio}")
    return v


@_claim("Fig. 1", "mTSP's plan computation time does not change significantly with N_m.",
        ("plan_times",))
def mtsp_plan_time_flat(t: SummaryTables, s: Settings) -> Verdict:
    """The factor by which mTSP's plan computation time changes from the smallest timed team
    to the largest (a least-squares line through the log times of every repeat against N_m,
    with the 95% t interval of its slope) lies within [1/2, 2]: holds if its interval does,
    contradicted if its interval lies outside."""
    v = Verdict()
    factor = t.plan_times.trend("mtsp")
    v.test(factor.within(1 / FLAT, FLAT), f"mTSP's plan time, largest over smallest team "
                                          f"(fitted): {factor}")
    return v


@_claim("Fig. 1", "ConB's plan computation time grows with N_m.", ("plan_times",))
def conb_plan_time_grows(t: SummaryTables, s: Settings) -> Verdict:
    """The factor by which ConB's plan computation time changes from the smallest timed team to
    the largest (a least-squares line through the log times of every repeat against N_m, with
    the 95% t interval of its slope) lies above 1."""
    v = Verdict()
    factor = t.plan_times.trend("conb")
    v.test(factor.above(1.0), f"ConB's plan time, largest over smallest team (fitted): {factor}")
    return v


# -- Figs. 2-3 -----------------------------------------------------------------------------------


@_claim("Figs. 2–3", "Larger r_c drives P_s toward 1 even for short t_d.")
def larger_range_short_td(t: SummaryTables, s: Settings) -> Verdict:
    """At the short t_d = 1000 s, for every planner and each team size of Fig. 2 (10 and 22):
    P_s never falls significantly as r_c grows (contradicted if its interval at a range lies
    entirely below the one at the next smaller range), and at the largest r_c (2000 m) it lies
    above 0.9."""
    v = Verdict()
    for n in FIG2_DRONES:
        for p in PAPER_PLANNERS:
            e = [t.main.at("P_s", p, n, rc, TD_SHORT) for rc in RANGES]
            falls = [f"{a:g} to {b:g} m" for (a, x), (b, y) in itertools.pairwise(
                zip(RANGES, e, strict=True)) if y.hi < x.lo]
            outcome = Outcome.CONTRADICTED if falls else e[-1].above(NEAR_ONE)
            v.test(outcome, f"N_m = {n}, {_label(p)}: P_s({TD_SHORT:g} s) at "
                   + ", ".join(f"{_rc(rc)}: {x}" for rc, x in zip(RANGES, e, strict=True))
                   + (f"; falls significantly from {', '.join(falls)}" if falls else ""))
    return v


@_claim("Figs. 2–3", "At t_d = 4000 s mTSP succeeds with probability 1 even with 2 drones.")
def mtsp_two_drones(t: SummaryTables, s: Settings) -> Verdict:
    """For every r_c, every run of mTSP with N_m = 2 notifies the BS within t_d = 4000 s, so
    that P_s = 1 and its Wilson interval reaches 1 (its lower bound says how close to 1 the
    sample size can vouch for). A single run not notified puts the interval below 1: the
    claim is then contradicted at any sample size."""
    v = Verdict()
    for rc in RANGES:
        r = t.main.row("mtsp", 2, rc, TD_LONG)
        v.test(Outcome.HOLDS if r["notified"] == r["runs"] else Outcome.CONTRADICTED,
               f"{_rc(rc)}: {int(r['notified'])} of {int(r['runs'])} runs notified, "
               f"P_s = {t.main.at('P_s', 'mtsp', 2, rc, TD_LONG)}")
    return v


@_claim("Figs. 2–3", "More drones do not help ConB, but help mTSP and CovB.")
def drones_help(t: SummaryTables, s: Settings) -> Verdict:
    """At Fig. 3's t_d and for every r_c, the gain in P_s from the smallest team (2) to the
    largest (22) lies above 0 for mTSP and for CovB, and below 0.1 for ConB (Newcombe
    intervals)."""
    v = Verdict()
    first, last = DRONES[0], DRONES[-1]
    for rc in RANGES:
        for p in ("mtsp", "covb", "conb"):
            small, large = (t.main.at("P_s", p, n, rc, s.td_fig3) for n in (first, last))
            gain = large.minus(small)
            v.test(gain.below(SMALL) if p == "conb" else gain.above(0.0),
                   f"{_rc(rc)}, {_label(p)}: P_s({s.td_fig3:g} s) {small} at N_m = {first}, "
                   f"{large} at N_m = {last}; gain {gain}")
    return v


@_claim("Figs. 2–3", "Both hybrids beat ConB, most clearly at small r_c.")
def hybrids_beat_conb(t: SummaryTables, s: Settings) -> Verdict:
    """At Fig. 3's t_d, for ConCov and for mTSP-ConB: the advantage over ConB in P_s, averaged
    over team sizes, lies above 0 at every r_c, and at the smallest r_c (500 m) its interval
    lies entirely above the one at each larger r_c (contradicted if entirely below)."""
    v = Verdict()
    for h in ("concov", "mtsp-conb"):
        gaps = {rc: _gap(t, h, "conb", rc, s.td_fig3, "P_s") for rc in RANGES}
        for rc, g in gaps.items():
            v.test(g.above(0.0), f"{_label(h)} − ConB, P_s({s.td_fig3:g} s) averaged over N_m, "
                                 f"{_rc(rc)}: {g}")
        small = gaps[RANGES[0]]
        for rc in RANGES[1:]:
            v.test(small.exceeds(gaps[rc]), f"{_label(h)}'s advantage at {_rc(RANGES[0])} "
                                            f"{small} against {_rc(rc)} {gaps[rc]}")
    return v


@_claim("Figs. 2–3", "ConCov beats mTSP-ConB as N_m grows.")
def concov_beats_mtsp_conb(t: SummaryTables, s: Settings) -> Verdict:
    """At Fig. 3's t_d, for every r_c: ConCov's P_s at the largest team (22) exceeds
    mTSP-ConB's (Newcombe interval of the difference above 0), and this advantage exceeds the
    one at the smallest team (2) (the change, with the interval of its extreme bounds
    [lo_22 − hi_2, hi_22 − lo_2], above 0)."""
    v = Verdict()
    for rc in RANGES:
        d = {n: t.main.at("P_s", "concov", n, rc, s.td_fig3).minus(
                t.main.at("P_s", "mtsp-conb", n, rc, s.td_fig3)) for n in DRONES}
        small, large = d[DRONES[0]], d[DRONES[-1]]
        growth = change(small, large)
        v.test(large.above(0.0), f"{_rc(rc)}: ConCov − mTSP-ConB in P_s({s.td_fig3:g} s) at "
                                 f"N_m = {DRONES[-1]}: {large}")
        v.test(growth.above(0.0), f"{_rc(rc)}: its change from N_m = {DRONES[0]} ({small}): "
                                  f"{growth}")
        behind = [str(n) for n, e in d.items() if e.hi < 0]
        if behind:
            v.note(f"{_rc(rc)}: mTSP-ConB is ahead at N_m = {', '.join(behind)}")
    return v


@_claim("Figs. 2–3", "The hybrids still trail mTSP and CovB where detection dominates.")
def hybrids_trail_coverage(t: SummaryTables, s: Settings) -> Verdict:
    """Where detection dominates the mission, at the largest r_c (2000 m, where notification
    is quickest), at Fig. 3's t_d: for each hybrid (ConCov, mTSP-ConB) against each of mTSP and
    CovB, the hybrid's P_s minus the other's, averaged over team sizes, lies below 0."""
    v = Verdict()
    rc = RANGES[-1]
    for h in ("concov", "mtsp-conb"):
        for x in ("mtsp", "covb"):
            g = _gap(t, h, x, rc, s.td_fig3, "P_s")
            v.test(g.below(0.0), f"{_rc(rc)}: {_label(h)} − {_label(x)}, P_s({s.td_fig3:g} s) "
                                 f"averaged over N_m: {g}")
    return v


# -- Fig. 4 --------------------------------------------------------------------------------------


@_claim("Fig. 4", "The mission times of all schemes converge as N_m grows.")
def mission_times_converge(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and every r_c: the spread of the planners' mean mission times (largest
    minus smallest, its interval from the extreme bounds) is smaller at the largest team (22)
    than at the smallest (2): holds if the two intervals are disjoint with the one at 22 below,
    contradicted if they are disjoint the other way."""
    v = Verdict()
    first, last = DRONES[0], DRONES[-1]
    for rc in RANGES:
        small, large = (spread(t.main.at("mission_time", p, n, rc, TD_LONG)
                               for p in PAPER_PLANNERS) for n in (first, last))
        v.test(small.exceeds(large), f"{_rc(rc)}: spread of mean mission times {small} s at "
                                     f"N_m = {first}, {large} s at N_m = {last}")
    return v


@_claim("Fig. 4", "ConB's mission time is under half of the others' for small N_m.")
def conb_mission_time(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s, for every r_c and N_m in {2, 4}, and against each other planner P:
    half of P's mean mission time minus ConB's lies above 0 (interval from the standard
    errors). Mission time is the mean notification time of the runs notified within t_d."""
    v = Verdict()
    for rc in RANGES:
        for n in SMALL_TEAMS:
            conb = t.main.at("mission_time", "conb", n, rc, TD_LONG)
            for p in _others("conb"):
                e = t.main.at("mission_time", p, n, rc, TD_LONG)
                v.test(e.scaled(0.5).minus(conb).above(0.0),
                       f"{_rc(rc)}, N_m = {n}: ConB {conb} s, half of {_label(p)}'s "
                       f"{e.scaled(0.5)} s")
    return v


@_claim("Fig. 4", "ConCov's and mTSP-ConB's mission times stay above ConB's.")
def hybrid_times_above_conb(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and every r_c, for ConCov and for mTSP-ConB: its mean mission time
    minus ConB's, averaged over team sizes, lies above 0."""
    v = Verdict()
    for rc in RANGES:
        for h in ("concov", "mtsp-conb"):
            g = _gap(t, h, "conb", rc, TD_LONG, "mission_time")
            v.test(g.above(0.0), f"{_rc(rc)}: {_label(h)} − ConB mission time averaged over "
                                 f"N_m: {g} s")
    return v


def _notification_share(t: SummaryTables, planner: str, rc: float) -> Estimate:
    """The largest notification share (1 − search share) over the team sizes."""
    shares = (t.main.at("search_share", planner, n, rc, TD_LONG) for n in DRONES)
    return peak(Estimate(1 - e.value, 1 - e.hi, 1 - e.lo) for e in shares)


@_claim("Fig. 4", "The notification phase takes about 30 % of the mission for ConCov against "
                  "about 45 % for the coverage schemes at r_c = 1000 m, and about 10 % for ConB "
                  "at the larger ranges.")
def notification_shares(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s, the notification share of the mission time (1 − the search share of
    Fig. 4b, the mean detection time over the mean notification time of the runs notified),
    at its largest over the team sizes (the sizes "in between" where the paper finds
    notification significant; the interval is that of the largest true share when every
    interval covers its own): about 0.3 for ConCov and about 0.45 for mTSP and for CovB at
    r_c = 1000 m, and about 0.1 for ConB at r_c = 1000 and 2000 m, "about x" meaning
    x ± 0.1: holds if the interval lies within it, contradicted if it lies outside."""
    v = Verdict()
    for p, rc, level in (("concov", 1000.0, 0.3), ("mtsp", 1000.0, 0.45),
                         ("covb", 1000.0, 0.45), ("conb", 1000.0, 0.1), ("conb", 2000.0, 0.1)):
        share = _notification_share(t, p, rc)
        v.test(share.within(level - ABOUT, level + ABOUT),
               f"{_rc(rc)}, {_label(p)}: largest notification share over N_m {share} "
               f"(about {level:g})")
    return v


@_claim("Fig. 4", "The total mission time falls monotonically with N_m.")
def mission_time_falls(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s, for every planner and r_c, the mean mission time against N_m:
    contradicted if it rises significantly from one team size to the next or from the
    smallest team to the largest (Newcombe interval of the difference above 0); holds if it
    falls significantly from the smallest team to the largest (interval below 0) and rises
    significantly nowhere; undecided otherwise."""
    v = Verdict()
    for rc in RANGES:
        for p in PAPER_PLANNERS:
            e = {n: t.main.at("mission_time", p, n, rc, TD_LONG) for n in DRONES}
            rises = [f"{a} to {b}" for a, b in itertools.pairwise(DRONES)
                     if e[b].minus(e[a]).lo > 0]
            overall = e[DRONES[-1]].minus(e[DRONES[0]])
            v.test(Outcome.CONTRADICTED if rises else overall.below(0.0),
                   f"{_rc(rc)}, {_label(p)}: {e[DRONES[0]]} s at N_m = {DRONES[0]}, "
                   f"{e[DRONES[-1]]} s at N_m = {DRONES[-1]}, change {overall} s"
                   + (f"; rises significantly from N_m = {', '.join(rises)}" if rises else ""))
    return v


# -- Fig. 5 --------------------------------------------------------------------------------------


@_claim("Fig. 5", "ConB is far more likely than the others to notify at detection, and ConCov "
                  "follows it.")
def conb_then_concov_immediate(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and each r_c of Fig. 5 (500 and 1000 m), averaged over team sizes:
    ConB's immediate notification minus each other planner's lies above 0, and ConCov's minus
    that of mTSP, CovB and mTSP-ConB lies above 0."""
    v = Verdict()
    _order(v, t, "conb", _others("conb"), FIG5_RANGES, "immediate", higher=True)
    _order(v, t, "concov", ("mtsp", "covb", "mtsp-conb"), FIG5_RANGES, "immediate", higher=True)
    return v


@_claim("Fig. 5", "mTSP's immediate notification is the lowest, about 0.2 at low r_c.")
def mtsp_immediate_lowest(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and each r_c of Fig. 5 (500 and 1000 m): for every other planner, the
    average over team sizes of mTSP's immediate notification minus the other's lies below 0
    (mTSP-ConB is compared only above N_r = 6 drones, where it differs from mTSP). And at
    r_c = 500 m, mTSP's immediate notification averaged over team sizes is about 0.2 (its
    interval within [0.1, 0.3]; contradicted if outside)."""
    v = Verdict()
    _order(v, t, "mtsp", _others("mtsp"), FIG5_RANGES, "immediate", higher=False)
    rc = FIG5_RANGES[0]
    level = average(t.main.at("immediate", "mtsp", n, rc, TD_LONG) for n in DRONES)
    v.test(level.within(0.2 - ABOUT, 0.2 + ABOUT),
           f"{_rc(rc)}: mTSP's immediate notification averaged over N_m: {level}")
    return v


@_claim("Fig. 5", "At the largest range every scheme's immediate notification approaches 1.")
def immediate_near_one_far(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and the largest r_c (2000 m, which Fig. 5 leaves out for this reason):
    every planner's immediate notification lies above 0.9 at every team size (holds if every
    interval does, contradicted if one lies below)."""
    v = Verdict()
    rc = RANGES[-1]
    for p in PAPER_PLANNERS:
        e = {n: t.main.at("immediate", p, n, rc, TD_LONG) for n in DRONES}
        lowest = min(e, key=lambda n: e[n].value)
        v.test(worst(x.above(NEAR_ONE) for x in e.values()),
               f"{_rc(rc)}, {_label(p)}: lowest immediate notification {e[lowest]} "
               f"at N_m = {lowest}")
    return v


# -- Fig. 6 --------------------------------------------------------------------------------------


@_claim("Fig. 6", "At small r_c every scheme has low target reachability, and ConB the best.")
def low_reachability_conb_best(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and the smallest r_c (500 m): every planner's target reachability is
    low, below a quarter of t_d, at every team size (holds if every interval lies below 0.25,
    contradicted if one lies above); and ConB's minus each other planner's, averaged over team
    sizes, lies above 0."""
    v = Verdict()
    rc = RANGES[0]
    for p in PAPER_PLANNERS:
        e = {n: t.main.at("reachability", p, n, rc, TD_LONG) for n in DRONES}
        highest = max(e, key=lambda n: e[n].value)
        v.test(worst(x.below(LOW) for x in e.values()),
               f"{_rc(rc)}, {_label(p)}: highest reachability {e[highest]} at N_m = {highest}")
    _order(v, t, "conb", _others("conb"), [rc], "reachability", higher=True)
    return v


@_claim("Fig. 6", "As r_c grows, CovB and ConCov overtake ConB as N_m grows.")
def coverage_overtakes_conb(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and each larger r_c (1000 and 2000 m), for CovB and for ConCov: its
    target reachability minus ConB's lies above 0 at the largest team (22), and this
    difference grows from the smallest team (2) to the largest (the change, with the interval
    of its extreme bounds, above 0)."""
    v = Verdict()
    for rc in RANGES[1:]:
        for p in ("covb", "concov"):
            d = {n: t.main.at("reachability", p, n, rc, TD_LONG).minus(
                    t.main.at("reachability", "conb", n, rc, TD_LONG))
                 for n in (DRONES[0], DRONES[-1])}
            small, large = d[DRONES[0]], d[DRONES[-1]]
            v.test(large.above(0.0), f"{_rc(rc)}: {_label(p)} − ConB reachability at "
                                     f"N_m = {DRONES[-1]}: {large}")
            v.test(change(small, large).above(0.0),
                   f"{_rc(rc)}: its change from N_m = {DRONES[0]} ({small}): "
                   f"{change(small, large)}")
    return v


@_claim("Fig. 6", "mTSP has the worst target reachability at every range.")
def mtsp_reachability_worst(t: SummaryTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and every r_c, averaged over team sizes: mTSP's target reachability
    minus each other planner's lies below 0 (mTSP-ConB compared only above N_r = 6 drones,
    where it differs from mTSP)."""
    v = Verdict()
    _order(v, t, "mtsp", _others("mtsp"), RANGES, "reachability", higher=False)
    return v


# -- Fig. 7 --------------------------------------------------------------------------------------


@_claim("Fig. 7a", "With ideal sensing mTSP, CovB, mTSP-ConB and ConCov detect the target with "
                   "probability above 0.9.", ("miss",))
def ideal_detection(t: SummaryTables, s: Settings) -> Verdict:
    """In Fig. 7a's setting (N_m = 10, r_c = 500 m, t_d = 1000 s) with ideal sensing
    (p_miss = 0): P_d lies above 0.9 for mTSP, CovB, mTSP-ConB and ConCov."""
    v = Verdict()
    for p in ("mtsp", "covb", "mtsp-conb", "concov"):
        e = t.miss.at("P_d", p, 0.0)
        v.test(e.above(NEAR_ONE), f"{_label(p)}: P_d at p_miss = 0: {e}")
    return v


@_claim("Fig. 7a", "Detection falls with the miss probability, little while it is small, with "
                   "the same trend for every scheme.", ("miss",))
def detection_falls_with_miss(t: SummaryTables, s: Settings) -> Verdict:
    """In Fig. 7a, for every planner (the same rule for each is what "the same trend for every
    scheme" asks): P_d at the largest miss probability (0.9) minus P_d at 0 lies below 0, and
    P_d never rises significantly from one miss probability to the next (contradicted if a
    step's Newcombe interval lies above 0); and while the miss probability is small (up to
    0.2) P_d stays within 0.1 of its ideal value (P_d(p_miss) − P_d(0) above −0.1: holds if
    its interval is, contradicted if its interval lies below)."""
    v = Verdict()
    for p in PAPER_PLANNERS:
        e = {q: t.miss.at("P_d", p, q) for q in P_MISS}
        rises = [f"{a:g} to {b:g}" for a, b in itertools.pairwise(P_MISS)
                 if e[b].minus(e[a]).lo > 0]
        fall = e[P_MISS[-1]].minus(e[0.0])
        v.test(Outcome.CONTRADICTED if rises else fall.below(0.0),
               f"{_label(p)}: P_d {e[0.0]} at p_miss = 0, {e[P_MISS[-1]]} at "
               f"{P_MISS[-1]:g}; change {fall}"
               + (f"; rises significantly from {', '.join(rises)}" if rises else ""))
        for q in (q for q in P_MISS if 0 < q <= SMALL_MISS):
            drop = e[q].minus(e[0.0])
            v.test(drop.above(-SMALL), f"{_label(p)}: P_d at p_miss = {q:g} minus at 0: {drop}")
    return v


@_claim("Fig. 7b", "Under shadowing the trends of Fig. 5 remain, with slightly higher immediate "
                   "notification for the mTSP schemes.", ("main", "shadowing"))
def shadowing_keeps_trends(t: SummaryTables, s: Settings) -> Verdict:
    """At Fig. 7b's r_c (1000 m) and t_d = 4000 s, immediate notification averaged over team
    sizes, with log-normal shadowing (Fig. 7b) and without (Fig. 5): for every pair of planners
    whose order is significant without shadowing (the Newcombe interval of their averaged
    difference excludes 0), the difference with shadowing lies on the same side of 0
    (contradicted if it lies on the other); and for mTSP and mTSP-ConB, the immediate
    notification with shadowing minus without, averaged over team sizes, is slightly higher:
    within [0, 0.1] (contradicted if its interval lies outside)."""
    v = Verdict()
    rc = float(t.tables["shadowing"]["rc"].iloc[0])
    for a, b in itertools.combinations(PAPER_PLANNERS, 2):
        same = _same_up_to(a, b)
        disc = t.main.gap(a, b, rc, TD_LONG, "immediate", same)
        shadowed = t.shadowing.gap(a, b, rc, TD_LONG, "immediate", same)
        pair = (f"{_rc(rc)}: {_label(a)} − {_label(b)} immediate notification averaged over "
                f"N_m, without shadowing {disc}, with {shadowed}")
        order = disc.above(0.0)
        if order is Outcome.UNDECIDED:
            v.note(pair + " (no significant order without shadowing)")
        else:
            v.test(shadowed.above(0.0) if order is Outcome.HOLDS else shadowed.below(0.0), pair)
    for p in ("mtsp", "mtsp-conb"):
        rise = average(t.shadowing.at("immediate", p, n, rc, TD_LONG).minus(
            t.main.at("immediate", p, n, rc, TD_LONG)) for n in DRONES)
        v.test(rise.within(0.0, SMALL), f"{_rc(rc)}, {_label(p)}: immediate notification with "
                                        f"shadowing minus without, averaged over N_m: {rise}")
    return v
