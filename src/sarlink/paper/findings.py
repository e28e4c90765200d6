"""Checks of the paper's findings (docs/reproduce.md, How the findings are decided).

Each check reads the main summary table (:func:`sarlink.metrics.summarize` of the main sweep at
``t_d`` = 1000, 2000 and 4000 s, grouped by ``planner``, ``drones`` and ``rc``) and returns a
:class:`Finding`: the claim, whether the data support it, the numbers that decide it with their
95% intervals, and, when it does not hold, what the data show instead. Its docstring is the
exact criterion; the report quotes it.

The statistics are deliberately conservative, so that "holds" means the intervals support the
claim, not merely that the point estimates lean its way:

- An *estimate* is a value with a 95% interval: the Wilson interval of a probability, or
  mean ± 1.96 standard errors of a mean.
- A *difference* of two estimates has Newcombe's hybrid score interval
  ``d − √((a − a_lo)² + (b_hi − b)²) .. d + √((a_hi − a)² + (b − b_lo)²)`` (for means it is
  ``d ± 1.96 √(se_a² + se_b²)``). It treats the two grid points as independent; with common
  random numbers their runs search for the same targets and are positively correlated, so the
  interval is wider than a paired one: conservative.
- An *average over team sizes* of estimates averages their bounds too. The half-width of a sum
  is at most the sum of half-widths whatever the correlations (Minkowski), so this interval is
  conservative as well.
- "A exceeds B" means the interval of A − B lies above 0; "A does not exceed B by δ" means it
  lies below δ. With few runs per point the intervals are wide and a check can fail for want
  of evidence; its ``instead`` then says so through the numbers.
"""

from __future__ import annotations

import functools
import inspect
import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd

from sarlink.config import Mission
from sarlink.metrics import Z95
from sarlink.paper.experiments import (
    DRONES,
    FIG2_DRONES,
    FIG5_RANGES,
    PLANNERS,
    RANGES,
    TD_FIG3,
    TD_LONG,
    TD_SHORT,
)
from sarlink.planners import get_planner

__all__ = ["CHECKS", "Finding", "check_all"]

NEAR_ONE = 0.9
"""A success probability whose interval lies at or above this is "near 1"."""
NO_HELP = 0.1
"""A gain in P_s whose interval lies below this (10 points) is "no help"."""
ABOUT = (0.1, 0.3)
"""What "about 0.2" admits: the interval must lie within it."""
SMALL_TEAMS = (2, 4)
"""The "small N_m" of the mission-time claim: the two smallest teams."""
NR = Mission().team.nr
"""mTSP-ConB's mTSP drones: up to this team size it flies exactly the mTSP plan."""


@dataclass(frozen=True)
class Finding:
    """One of the paper's findings checked against sarlink's results."""

    claim: str
    holds: bool
    evidence: str
    """The numbers that decide it, one per line, with their 95% intervals."""
    instead: str
    """What the data show where the claim fails (empty when it holds)."""
    criterion: str
    """The exact rule applied (the check's docstring)."""


@dataclass(frozen=True)
class _Estimate:
    """A value with its 95% interval."""

    value: float
    lo: float
    hi: float

    def __str__(self) -> str:
        return f"{_number(self.value)} [{_number(self.lo)}, {_number(self.hi)}]"

    def scaled(self, k: float) -> _Estimate:
        return _Estimate(k * self.value, k * self.lo, k * self.hi)

    def minus(self, other: _Estimate) -> _Estimate:
        """Newcombe's interval of the difference (see the module docstring)."""
        d = self.value - other.value
        return _Estimate(d, d - math.hypot(self.value - self.lo, other.hi - other.value),
                         d + math.hypot(self.hi - self.value, other.value - other.lo))


def _number(x: float) -> str:
    if math.isnan(x):
        return "n/a"
    return f"{x:.0f}" if abs(x) >= 10 else f"{x:.3f}"


def _average(estimates: Iterable[_Estimate]) -> _Estimate:
    """The mean of estimates with the mean of their bounds: conservative under any correlation."""
    items = list(estimates)
    return _Estimate(*(float(np.mean([getattr(e, f) for e in items]))
                       for f in ("value", "lo", "hi")))


def _label(planner: str) -> str:
    return get_planner(planner).label


def _rc(rc: float) -> str:
    return f"r_c = {rc:g} m"


class _Table:
    """The main summary table, indexed by planner, team size, range and t_d."""

    def __init__(self, main: pd.DataFrame) -> None:
        self.rows = main.set_index(["planner", "drones", "rc", "td"]).sort_index()

    def row(self, planner: str, drones: int, rc: float, td: float) -> pd.Series:
        try:
            return self.rows.loc[(planner, drones, rc, td)]
        except KeyError:
            raise KeyError(f"the summary table has no row for {planner}, N_m = {drones}, "
                           f"{_rc(rc)}, t_d = {td:g} s") from None

    def at(self, planner: str, drones: int, rc: float, td: float, metric: str) -> _Estimate:
        """A probability with its Wilson interval, or a mean ± 1.96 standard errors."""
        r = self.row(planner, drones, rc, td)
        value = float(r[metric])
        if f"{metric}_lo" in r:
            return _Estimate(value, float(r[f"{metric}_lo"]), float(r[f"{metric}_hi"]))
        half = Z95 * float(r[f"{metric}_se"])
        return _Estimate(value, value - half, value + half)

    def gap(self, a: str, b: str, rc: float, td: float, metric: str) -> _Estimate:
        """The average over team sizes of ``a − b``, leaving out the sizes where the two
        planners fly the same mission (mTSP and mTSP-ConB up to N_r drones)."""
        same = {a, b} == {"mtsp", "mtsp-conb"}
        return _average(self.at(a, n, rc, td, metric).minus(self.at(b, n, rc, td, metric))
                        for n in DRONES if not (same and n <= NR))


_Verdict = tuple[bool, list[str], list[str]]
"""Whether a claim holds, the evidence lines, and the lines saying what the data show instead."""

CHECKS: list[Callable[[pd.DataFrame], Finding]] = []
"""Every check, in the order of the paper's findings."""


def _finding(claim: str) -> Callable[[Callable[[_Table], _Verdict]],
                                     Callable[[pd.DataFrame], Finding]]:
    """Register a check of ``claim``; its docstring becomes the finding's criterion."""
    def register(check: Callable[[_Table], _Verdict]) -> Callable[[pd.DataFrame], Finding]:
        @functools.wraps(check)
        def run(main: pd.DataFrame) -> Finding:
            holds, evidence, instead = check(_Table(main))
            return Finding(claim, holds, "\n".join(evidence),
                           "" if holds else "\n".join(instead), inspect.getdoc(check) or "")
        CHECKS.append(run)
        return run
    return register


def check_all(main: pd.DataFrame) -> list[Finding]:
    """Every finding, checked against the main summary table."""
    return [check(main) for check in CHECKS]


def _others(planner: str) -> Sequence[str]:
    return [p for p in PLANNERS if p != planner]


@_finding("Larger r_c drives P_s toward 1 even for short t_d.")
def larger_range_short_td(t: _Table) -> _Verdict:
    """At the short t_d = 1000 s, for every planner and each team size of Fig. 2 (10 and 22):
    P_s never falls significantly as r_c grows (the interval at the larger range is not
    entirely below the one at the smaller), and at r_c = 2000 m its lower bound is at
    least 0.9."""
    evidence, instead = [], []
    for n in FIG2_DRONES:
        for p in PLANNERS:
            e = [t.at(p, n, rc, TD_SHORT, "P_s") for rc in RANGES]
            evidence.append(f"N_m = {n}, {_label(p)}: P_s(1000 s) at r_c = "
                            + ", ".join(f"{rc:g} m: {x}" for rc, x in zip(RANGES, e, strict=True)))
            for i in range(len(RANGES) - 1):
                if e[i + 1].hi < e[i].lo:
                    instead.append(f"{_label(p)}, N_m = {n}: P_s(1000 s) falls from {e[i]} at "
                                   f"{RANGES[i]:g} m to {e[i + 1]} at {RANGES[i + 1]:g} m")
            if not e[-1].lo >= NEAR_ONE:
                instead.append(f"{_label(p)}, N_m = {n}: P_s(1000 s) at r_c = {RANGES[-1]:g} m "
                               f"is {e[-1]}, not shown to be at least {NEAR_ONE}")
    return not instead, evidence, instead


@_finding("At t_d = 4000 s mTSP succeeds with probability 1 even with 2 drones.")
def mtsp_two_drones(t: _Table) -> _Verdict:
    """For every r_c, every run of mTSP with N_m = 2 notifies the BS within t_d = 4000 s, so
    that P_s = 1 and its Wilson interval reaches 1 (its lower bound says how close to 1 the
    sample size can vouch for)."""
    evidence, instead = [], []
    for rc in RANGES:
        r = t.row("mtsp", 2, rc, TD_LONG)
        line = (f"{_rc(rc)}: {int(r['notified'])} of {int(r['runs'])} runs notified, "
                f"P_s = {t.at('mtsp', 2, rc, TD_LONG, 'P_s')}")
        evidence.append(line)
        if r["notified"] != r["runs"]:
            instead.append(line)
    return not instead, evidence, instead


@_finding("More drones do not help ConB, but help mTSP and CovB.")
def drones_help(t: _Table) -> _Verdict:
    """At Fig. 3's t_d = 2000 s and for every r_c, the gain in P_s from N_m = 2 to N_m = 22
    lies above 0 for mTSP and for CovB, and below 0.1 for ConB (Newcombe intervals)."""
    evidence, instead = [], []
    for rc in RANGES:
        for p in ("mtsp", "covb", "conb"):
            small, large = (t.at(p, n, rc, TD_FIG3, "P_s") for n in (DRONES[0], DRONES[-1]))
            gain = large.minus(small)
            line = (f"{_rc(rc)}, {_label(p)}: P_s(2000 s) {small} at N_m = {DRONES[0]}, "
                    f"{large} at N_m = {DRONES[-1]}; gain {gain}")
            evidence.append(line)
            helped = gain.lo > 0
            if (p == "conb" and not gain.hi < NO_HELP) or (p != "conb" and not helped):
                instead.append(line)
    return not instead, evidence, instead


@_finding("Both hybrids beat ConB most clearly at small r_c.")
def hybrids_beat_conb(t: _Table) -> _Verdict:
    """At Fig. 3's t_d = 2000 s, for ConCov and for mTSP-ConB: the advantage over ConB in P_s,
    averaged over team sizes, lies above 0 at r_c = 500 m, is largest there (point estimate),
    and its interval there lies entirely above the one at r_c = 2000 m."""
    evidence, instead = [], []
    for h in ("concov", "mtsp-conb"):
        gaps = [t.gap(h, "conb", rc, TD_FIG3, "P_s") for rc in RANGES]
        evidence.append(f"{_label(h)} − ConB, P_s(2000 s) averaged over N_m: "
                        + ", ".join(f"{_rc(rc)}: {g}" for rc, g in zip(RANGES, gaps, strict=True)))
        low, high = gaps[0], gaps[-1]
        if not low.lo > 0:
            instead.append(f"{_label(h)} is not shown to beat ConB at {_rc(RANGES[0])}: {low}")
        if max(g.value for g in gaps) > low.value:
            best = RANGES[int(np.argmax([g.value for g in gaps]))]
            instead.append(f"{_label(h)}'s advantage over ConB is largest at {_rc(best)}")
        if not low.lo > high.hi:
            instead.append(f"{_label(h)}'s advantage at {_rc(RANGES[0])} ({low}) is not shown to "
                           f"exceed the one at {_rc(RANGES[-1])} ({high})")
    return not instead, evidence, instead


@_finding("ConCov beats mTSP-ConB as N_m grows.")
def concov_beats_mtsp_conb(t: _Table) -> _Verdict:
    """At Fig. 3's t_d = 2000 s, for every r_c: ConCov's P_s at N_m = 22 exceeds mTSP-ConB's
    (Newcombe interval above 0), and this advantage exceeds the one at N_m = 2 (the interval
    of their difference, taken conservatively as [lo_22 − hi_2, hi_22 − lo_2], above 0)."""
    evidence, instead = [], []
    for rc in RANGES:
        d = {n: t.at("concov", n, rc, TD_FIG3, "P_s").minus(t.at("mtsp-conb", n, rc, TD_FIG3,
                                                                  "P_s"))
             for n in DRONES}
        small, large = d[DRONES[0]], d[DRONES[-1]]
        growth = _Estimate(large.value - small.value, large.lo - small.hi,
                           large.hi - small.lo)
        evidence.append(f"{_rc(rc)}: ConCov − mTSP-ConB in P_s(2000 s) at N_m = "
                        + ", ".join(f"{n}: {e}" for n, e in d.items()))
        if large.lo > 0 and growth.lo > 0:
            continue
        behind = [n for n, e in d.items() if e.hi < 0]
        instead.append(f"{_rc(rc)}: ConCov − mTSP-ConB is {small} at N_m = {DRONES[0]} and "
                       f"{large} at N_m = {DRONES[-1]}"
                       + (f"; mTSP-ConB is ahead at N_m = {', '.join(map(str, behind))}"
                          if behind else ""))
    return not instead, evidence, instead


@_finding("ConB's mission time is under half of the others' for small N_m.")
def conb_mission_time(t: _Table) -> _Verdict:
    """At t_d = 4000 s, for every r_c and N_m in {2, 4}, and against each other planner P:
    half of P's mean mission time minus ConB's lies above 0 (interval from the standard
    errors). Mission time is the mean notification time of the runs notified within t_d."""
    evidence, instead = [], []
    for rc in RANGES:
        for n in SMALL_TEAMS:
            conb = t.at("conb", n, rc, TD_LONG, "mission_time")
            others = {p: t.at(p, n, rc, TD_LONG, "mission_time") for p in _others("conb")}
            evidence.append(f"{_rc(rc)}, N_m = {n}: ConB {conb} s; "
                            + ", ".join(f"{_label(p)} {e} s" for p, e in others.items()))
            for p, e in others.items():
                margin = e.scaled(0.5).minus(conb)
                if not margin.lo > 0:
                    instead.append(f"{_rc(rc)}, N_m = {n}: ConB's {conb} s is not shown to be "
                                   f"under half of {_label(p)}'s {e} s")
    return not instead, evidence, instead


@_finding("mTSP's immediate notification is the lowest (about 0.2 at low r_c).")
def mtsp_immediate_lowest(t: _Table) -> _Verdict:
    """At t_d = 4000 s and each r_c of Fig. 5 (500 and 1000 m): for every other planner, the
    average over team sizes of mTSP's immediate notification minus the other's lies below 0
    (mTSP-ConB is compared only above N_r = 6 drones, where it differs from mTSP). And at
    r_c = 500 m, mTSP's immediate notification averaged over team sizes has its interval within
    [0.1, 0.3]."""
    evidence, instead = [], []
    for rc in FIG5_RANGES:
        for p in _others("mtsp"):
            g = t.gap("mtsp", p, rc, TD_LONG, "immediate")
            evidence.append(f"{_rc(rc)}: mTSP − {_label(p)}, averaged over N_m: {g}")
            if not g.hi < 0:
                instead.append(f"{_rc(rc)}: mTSP's immediate notification is not shown to be "
                               f"below {_label(p)}'s (difference {g})")
    level = _average(t.at("mtsp", n, RANGES[0], TD_LONG, "immediate") for n in DRONES)
    evidence.append(f"{_rc(RANGES[0])}: mTSP's immediate notification averaged over N_m: {level}")
    if not (ABOUT[0] <= level.lo and level.hi <= ABOUT[1]):
        instead.append(f"{_rc(RANGES[0])}: mTSP's immediate notification averages {level}, "
                       f"not within [{ABOUT[0]}, {ABOUT[1]}]")
    return not instead, evidence, instead


@_finding("ConB reaches the best target reachability at small r_c, mTSP the worst.")
def reachability_order(t: _Table) -> _Verdict:
    """At t_d = 4000 s and r_c = 500 m, averaged over team sizes: ConB's target reachability
    minus each other planner's lies above 0, and mTSP's minus each other planner's lies below 0
    (mTSP-ConB compared only above N_r = 6 drones)."""
    rc = RANGES[0]
    evidence, instead = [], []
    for best_or_worst, planner, sign in (("best", "conb", 1), ("worst", "mtsp", -1)):
        for p in _others(planner):
            g = t.gap(planner, p, rc, TD_LONG, "reachability")
            evidence.append(f"{_rc(rc)}: {_label(planner)} − {_label(p)} reachability, "
                            f"averaged over N_m: {g}")
            if not (g.lo > 0 if sign > 0 else g.hi < 0):
                instead.append(f"{_label(planner)} is not shown to be {best_or_worst}: "
                               f"{_label(planner)} − {_label(p)} = {g}")
    for p in PLANNERS:
        evidence.append(f"{_rc(rc)}: {_label(p)} reachability averaged over N_m: "
                        f"{_average(t.at(p, n, rc, TD_LONG, 'reachability') for n in DRONES)}")
    return not instead, evidence, instead
