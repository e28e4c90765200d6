"""Shared by the claims' checks: the thresholds that give the paper's loose words a
meaning (the conventions of :mod:`sarlink.paper.findings`), and the statistics and
wording the checks have in common."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence

from sarlink.config import Mission
from sarlink.metrics import MEASURES
from sarlink.paper.evidence import Estimate, Outcome, Verdict, average
from sarlink.paper.experiments import DRONES, RANGES
from sarlink.paper.paired import PairedTables, Stat, mean_of
from sarlink.planners import PAPER_PLANNERS, get_planner

NEAR_ONE = 0.9
"""A probability whose interval lies above this is "near 1" (the paper's "higher than 90%")."""
ABOUT = 0.1
"""What "about x" admits for a probability or share: x ± this, at most ± x / 2."""
SMALL = 0.1
"""A change of a probability smaller than this (ten points) is "small", "slight", "no help"."""
HIGHLY_LIKELY = 0.75
"""A probability above this (three times as likely as not) is "highly likely"."""
LOW = 0.25
"""Target reachability below this share of t_d (a quarter) is "low"."""
FLAT = 2.0
"""A plan time that changes by less than this factor over Fig. 1's team sizes (2 to 22, an
11-fold team) "does not change significantly"; Fig. 1's log axis spans decades. A plan time
this many times another's is "much higher"."""
SMALL_MISS = 0.2
"""The largest miss probability that is "small" (Fig. 7a)."""
SMALL_TEAMS = (2, 4)
"""The "small N_m" / "lower number of drones": the two smallest teams."""
NR = Mission().team.nr
"""mTSP-ConB's mTSP drones: up to this team size it flies exactly the mTSP plan."""
HYBRID_SMALL_TEAMS = tuple(n for n in DRONES if n > NR)[:2]
"""mTSP-ConB's smallest teams that are not mTSP's: its "lower number of drones"."""
COVERAGE = ("mtsp", "covb")
"""The coverage-based schemes (Section 3.1)."""
CONNECTIVITY = ("conb", "concov")
"""The connectivity-aware distributed schemes."""
HYBRIDS = {"mtsp-conb": "mtsp", "concov": "covb"}
"""Each hybrid and its native coverage scheme (Section 3.3)."""

_MARK = {Outcome.HOLDS: "+", Outcome.CONTRADICTED: "−", Outcome.UNDECIDED: "?",
         Outcome.NOT_TESTABLE: "="}
_WHAT = {**{k: m.label for k, m in MEASURES.items()}, "detection_time": "mean detection time",
         "delay": "notification delay (t_notify − t_detect)"}

Decide = Callable[[Estimate], Outcome]


def _label(planner: str) -> str:
    return get_planner(planner).label


def _rc(rc: float) -> str:
    return f"r_c = {rc:g} m"


def _others(planner: str) -> list[str]:
    return [p for p in PAPER_PLANNERS if p != planner]


def _above(x: float = 0.0) -> Decide:
    return lambda e: e.above(x)


def _below(x: float = 0.0) -> Decide:
    return lambda e: e.below(x)


def _level(tests: int) -> float:
    """The confidence level of each of ``tests`` intervals that hold jointly at 95%."""
    return 1 - 0.05 / tests


def _sizes(a: str, b: str) -> list[int]:
    """The team sizes at which ``a`` and ``b`` can differ (mTSP-ConB is mTSP up to N_r)."""
    return [n for n in DRONES if {a, b} != {"mtsp", "mtsp-conb"} or n > NR]


def _stat(t: PairedTables, measure: str, planner: str, drones: int, rc: float, td: float
          ) -> Stat:
    return t.runs.stat(measure, planner, drones, rc, td=td)


def _picture(per: Mapping[int, Estimate], decide: Decide) -> str:
    return "per N_m: " + " ".join(f"{n}{_MARK[decide(e)]}" for n, e in per.items())


def _averaged(v: Verdict, per: Mapping[int, Stat], decide: Decide, what: str) -> Estimate:
    """Test ``decide`` on the average of ``per`` (a statistic per team size), showing each."""
    avg = mean_of(per.values()).estimate()
    v.test(decide(avg), f"{what}, averaged over N_m: {avg}; "
                        f"{_picture({n: s.estimate() for n, s in per.items()}, decide)}")
    return avg


def _gap(v: Verdict, t: PairedTables, measure: str, a: str, b: str, rc: float, td: float,
         decide: Decide) -> None:
    """Test ``decide`` on ``a − b`` in ``measure``, paired, averaged over team sizes."""
    per = {n: _stat(t, measure, a, n, rc, td) - _stat(t, measure, b, n, rc, td)
           for n in _sizes(a, b)}
    _averaged(v, per, decide, f"{_rc(rc)}, t_d = {td:g} s: {_label(a)} − {_label(b)} "
                              f"{_WHAT[measure]}")


def _gaps(v: Verdict, t: PairedTables, measure: str, firsts: Iterable[str],
          seconds: Iterable[str], ranges: Iterable[float], td: float, decide: Decide) -> None:
    seconds = list(seconds)
    for rc in ranges:
        for a in firsts:
            for b in seconds:
                if a != b:
                    _gap(v, t, measure, a, b, rc, td, decide)


def _change(t: PairedTables, measure: str, planner: str, start: tuple[int, float, float],
            end: tuple[int, float, float]) -> Stat:
    """``measure`` at ``end`` minus at ``start``, each (N_m, r_c, t_d), paired."""
    return _stat(t, measure, planner, *end) - _stat(t, measure, planner, *start)


def _spread(t: PairedTables, measure: str, drones: int, rc: float, td: float) -> Stat:
    """The largest minus the smallest planner's ``measure`` (the two picked by value)."""
    stats = [_stat(t, measure, p, drones, rc, td) for p in PAPER_PLANNERS]
    if any(math.isnan(s.value) for s in stats):
        return Stat(math.nan, 0 * stats[0].influence, stats[0].digits, contrast=True)
    ordered = sorted(stats, key=lambda s: s.value)
    return ordered[-1] - ordered[0]


def _every_run(v: Verdict, t: PairedTables, event: str, planner: str, td: float) -> None:
    """Test that every run of ``planner`` at every point has ``event`` within ``td`` (one run
    without it contradicts at any sample size)."""
    for rc in RANGES:
        short = {n: _stat(t, event, planner, n, rc, td) for n in DRONES}
        missed = {n: s.counts[1] - s.counts[0] for n, s in short.items() if s.counts
                  and s.counts[0] < s.counts[1]}
        v.test(Outcome.CONTRADICTED if missed else Outcome.HOLDS,
               f"{_rc(rc)}, {_label(planner)}: {_WHAT[event]} within {td:g} s in every run "
               "at every N_m" if not missed else
               f"{_rc(rc)}, {_label(planner)}: runs without it: "
               + ", ".join(f"N_m = {n}: {k}" for n, k in missed.items()))


def _half(t: PairedTables, v: Verdict, fast: Sequence[str], slow: Sequence[str],
          rc: float, td: float, sizes: Mapping[str, Sequence[int]]) -> None:
    """Test at each team size of ``sizes[f]``: half of each ``slow`` planner's mission time
    minus ``f``'s lies above 0."""
    for f in fast:
        for n in sizes[f]:
            mine = _stat(t, "mission_time", f, n, rc, td)
            for p in slow:
                other = _stat(t, "mission_time", p, n, rc, td)
                e = (other.scaled(0.5) - mine).estimate()
                v.test(e.above(), f"{_rc(rc)}, N_m = {n}, t_d = {td:g} s: half of "
                                  f"{_label(p)}'s mission time {other.estimate().scaled(0.5)} s "
                                  f"minus {_label(f)}'s {mine.estimate()} s: {e} s")


def _plan_ratio(t: PairedTables, a: str, b: str) -> Estimate:
    """``a``'s plan time over ``b``'s, a geometric mean over the timed team sizes: per team
    size the difference of mean log times with Welch's interval, bounds averaged."""
    times = t.plan_times
    return average(times.log_ratio(a, b, n) for n in times.team_sizes()).mapped(math.exp, 2)


def _about(level: float) -> tuple[float, float]:
    """What "about ``level``" admits (see the module docstring)."""
    half = min(ABOUT, level / 2)
    return level - half, level + half
