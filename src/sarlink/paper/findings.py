"""The paper's checkable statements, each decided from the reproduction's tables.

Every sentence of the abstract, the introduction's summary of results, Sections 3–4 and the
conclusions that a number can decide is a claim here, quoted with its section
(:mod:`sarlink.paper.claim`), in the paper's order. Each check's docstring is its exact
criterion; the criteria were written from the paper's words, not from the results.

Statistics: comparisons of planners, team sizes, ranges or target durations are *paired*
(:mod:`sarlink.paper.paired`): run ``k`` of every point searches for the same target, so a
difference is judged run by run. A level of one point keeps its Wilson interval. Conventions
where the paper is loose:

- A comparison the sentence states without a team size is decided on the average over the
  team sizes N_m = 2, ..., 22 (one paired statistic), and its part shows the per-team-size
  picture beside it: ``+`` holds, ``−`` contradicted, ``?`` undecided, ``=`` not testable
  (equal in every run). Statements about the level of every scheme ("all low") hold at every
  team size.
- mTSP-ConB flies exactly mTSP's mission up to N_r = 6 drones, so the two are compared only
  above N_r.
- "Near 1" is above :data:`NEAR_ONE`; "about x" is x ± :data:`ABOUT`, but never more than
  half of x (so "about 10 %" excludes 0); a "small" or "slight" change of a probability, and
  "no help", is less than :data:`SMALL`; "mostly" is more than half; "highly likely" above
  :data:`HIGHLY_LIKELY`.
- A trend ("as r_c becomes larger ... approaches 1") is tested as a change between settings,
  a limit ("for high r_c ... converges to 1") at the setting closest to it.
- "Somewhere" (an existence claim) is tested at every candidate point with Bonferroni's
  correction: 95% jointly.
- Fig. 3's t_d, which the paper does not state, is :attr:`Settings.td_fig3`; statements the
  paper ties to short target durations or to delayed notification are read at
  :data:`~sarlink.paper.experiments.TD_SHORT` (1000 s, the paper's own short t_d of Fig. 7a).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterable, Mapping, Sequence

import pandas as pd

from sarlink.config import Mission
from sarlink.metrics import MEASURES
from sarlink.paper.claim import (
    CLAIMS,
    DEFAULT_SETTINGS,
    Claim,
    Finding,
    Settings,
    claim,
    tally,
)
from sarlink.paper.evidence import Estimate, Outcome, Verdict, average, peak, worst
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
from sarlink.paper.paired import PairedTables, Stat, mean_of
from sarlink.planners import PAPER_PLANNERS, get_planner

__all__ = ["CLAIMS", "DEFAULT_SETTINGS", "Claim", "Finding", "Settings", "check_all", "tally"]

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


def check_all(tables: Mapping[str, pd.DataFrame],
              settings: Settings = DEFAULT_SETTINGS) -> list[Finding]:
    """Every claim whose tables are in ``tables``, decided on them."""
    wrapped = PairedTables(tables)
    return [c(wrapped, settings) for c in CLAIMS if c.checkable(tables)]


# -- helpers -----------------------------------------------------------------------------------


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


# -- Abstract and introduction --------------------------------------------------------------


@claim("Abstract", "Abstract",
       "even though the coverage path-planning leads to lower search times",
       "Coverage planners detect sooner than those that add connectivity.")
def coverage_searches_faster(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 1000 s (a search not yet finished) and every r_c: for mTSP and for CovB
    against each of ConB, ConCov and mTSP-ConB, the difference in P_d averaged over team
    sizes lies above 0 (mTSP against mTSP-ConB above N_r only)."""
    v = Verdict()
    _gaps(v, t, "P_d", COVERAGE, ("conb", "concov", "mtsp-conb"), RANGES, TD_SHORT, _above())
    return v


@claim("Abstract", "Abstract",
       "schemes that incorporate end-end connectivity into path planning result in at least "
       "50% better mission times for small communication ranges and lower number of drones",
       "ConB, ConCov and mTSP-ConB need at most half the mission time of mTSP and CovB at "
       "small r_c and few drones.")
def connectivity_halves_mission_time(t: PairedTables, s: Settings) -> Verdict:
    """At the smallest r_c (500 m) and t_d = 4000 s: for ConB and ConCov at N_m = 2 and 4, and
    for mTSP-ConB at its two smallest teams that are not mTSP's (8 and 10 drones), half of
    mTSP's and of CovB's mean mission time minus its own lies above 0 (paired)."""
    v = Verdict()
    sizes = {"conb": SMALL_TEAMS, "concov": SMALL_TEAMS, "mtsp-conb": HYBRID_SMALL_TEAMS}
    _half(t, v, list(sizes), COVERAGE, RANGES[0], TD_LONG, sizes)
    return v


@claim("Introduction", "1. Introduction",
       "as the number of drones increases, network connectivity improves significantly, "
       "allowing coverage-based schemes to have better success probabilities",
       "More drones connect more of mTSP's and CovB's team and raise their P_s.")
def connectivity_improves_with_drones(t: PairedTables, s: Settings) -> Verdict:
    """For mTSP and CovB at every r_c: the mean fraction of drones with a route to the BS
    over t_d = 4000 s, and P_s at Fig. 3's t_d, each at N_m = 22 minus at N_m = 2 (paired),
    lie above 0."""
    v = Verdict()
    first, last = DRONES[0], DRONES[-1]
    for rc in RANGES:
        for p in COVERAGE:
            for measure, td in (("connected", TD_LONG), ("P_s", s.td_fig3)):
                e = _change(t, measure, p, (first, rc, td), (last, rc, td)).estimate()
                v.test(e.above(), f"{_rc(rc)}, {_label(p)}: {_WHAT[measure]} at t_d = "
                                  f"{td:g} s, N_m = {last} minus N_m = {first}: {e}")
    return v


@claim("Introduction", "1. Introduction",
       "under stringent connectivity conditions, i.e. if the communication range and number "
       "of drones are low, connectivity-based distributed schemes outperform the "
       "coverage-aware centralized and distributed schemes by at least 50% by enabling "
       "notification as soon as the target is detected",
       "At small r_c and few drones ConB and ConCov need at most half the mission time of "
       "mTSP and CovB, and notify at detection more often.")
def stringent_connectivity_wins(t: PairedTables, s: Settings) -> Verdict:
    """At r_c = 500 m, t_d = 4000 s, N_m = 2 and 4: for ConB and ConCov against mTSP and
    CovB, half the other's mean mission time minus its own lies above 0, and its immediate
    notification minus the other's lies above 0 (paired, per team size)."""
    v = Verdict()
    rc = RANGES[0]
    _half(t, v, CONNECTIVITY, COVERAGE, rc, TD_LONG, dict.fromkeys(CONNECTIVITY, SMALL_TEAMS))
    for f in CONNECTIVITY:
        for p in COVERAGE:
            for n in SMALL_TEAMS:
                e = (_stat(t, "immediate", f, n, rc, TD_LONG)
                     - _stat(t, "immediate", p, n, rc, TD_LONG)).estimate()
                v.test(e.above(), f"{_rc(rc)}, N_m = {n}: {_label(f)} − {_label(p)} immediate "
                                  f"notification: {e}")
    return v


@claim("Introduction", "1. Introduction",
       "The proposed hybrid schemes overcome the limitations of path planning that consider "
       "only coverage or connectivity under certain conditions.",
       "Each hybrid beats both its coverage parent and ConB in P_s somewhere.")
def hybrids_beat_both_somewhere(t: PairedTables, s: Settings) -> Verdict:
    """For ConCov (against CovB and ConB) and mTSP-ConB (against mTSP and ConB): at some grid
    point (N_m, r_c, t_d = 1000, 2000 or 4000 s) its P_s exceeds both (paired, Bonferroni
    over the points and the two comparisons: 95% jointly). Contradicted if at every point it
    falls significantly below one of them; undecided otherwise."""
    v = Verdict()
    points = list(itertools.product(DRONES, RANGES, (TD_SHORT, TD_FIG3, TD_LONG)))
    level = _level(2 * len(points))
    for h, native in HYBRIDS.items():
        wins, losses = [], 0
        for n, rc, td in points:
            mine = _stat(t, "P_s", h, n, rc, td)
            d = [(mine - _stat(t, "P_s", o, n, rc, td)).estimate(level) for o in (native, "conb")]
            if all(e.lo > 0 and not e.tied for e in d):
                wins.append(f"N_m = {n}, {_rc(rc)}, t_d = {td:g} s ({d[0]}, {d[1]})")
            losses += any(e.hi < 0 for e in d)
        outcome = (Outcome.HOLDS if wins else Outcome.CONTRADICTED if losses == len(points)
                   else Outcome.UNDECIDED)
        v.test(outcome, f"{_label(h)} − {_label(native)} and − ConB in P_s: above both at "
                        f"{len(wins)} of {len(points)} points"
                        + (f", e.g. {wins[0]}" if wins else "")
                        + f"; significantly below one of them at {losses}")
    return v


@claim("Introduction", "1. Introduction",
       "coverage path planners might require notification delay tolerance",
       "mTSP's and CovB's notification comes later after detection than ConB's and ConCov's.")
def coverage_needs_delay_tolerance(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and Fig. 5's ranges (500, 1000 m): for mTSP and CovB against ConB and
    ConCov, the mean notification delay (t_notify − t_detect of the runs notified) minus the
    other's, averaged over team sizes, lies above 0."""
    v = Verdict()
    _gaps(v, t, "delay", COVERAGE, CONNECTIVITY, FIG5_RANGES, TD_LONG, _above())
    return v


# -- Section 3 ----------------------------------------------------------------------------------


@claim("Section 3", "3.1. Coverage-aware path planning",
       "the centralized schemes have a likelihood of missing a target since there is no "
       "redundancy (overlap) in the drone paths. [...] Distributed path-planning schemes on "
       "the other hand have an inherent redundancy.",
       "Missed looks cost the distributed CovB and ConCov less detection than mTSP.",
       ("miss_runs",))
def distributed_redundancy(t: PairedTables, s: Settings) -> Verdict:
    """In Fig. 7a's setting (N_m = 10, r_c = 500 m, t_d = 1000 s): for CovB and for ConCov,
    its change in P_d from p_miss = 0 to p_miss minus mTSP's change, averaged over the miss
    probabilities above 0 (paired), lies above 0: it loses less."""
    v = Verdict()
    miss = t.miss_runs
    for d in ("covb", "concov"):
        per = [(miss.stat("P_d", d, q, td=TD_SHORT) - miss.stat("P_d", d, 0.0, td=TD_SHORT))
               - (miss.stat("P_d", "mtsp", q, td=TD_SHORT)
                  - miss.stat("P_d", "mtsp", 0.0, td=TD_SHORT)) for q in P_MISS[1:]]
        e = mean_of(per).estimate()
        v.test(e.above(), f"{_label(d)}'s change in P_d minus mTSP's, averaged over p_miss: {e}")
    return v


@claim("Section 3", "Table 2",
       "Coverage: Guaranteed [mTSP]",
       "mTSP detects the target in every run within its flight budget.")
def mtsp_guarantees_coverage(t: PairedTables, s: Settings) -> Verdict:
    """Every run of mTSP, at every N_m and r_c, detects the target within t_d = 4000 s (the
    flight budget): one run without detection contradicts at any sample size."""
    v = Verdict()
    _every_run(v, t, "P_d", "mtsp", TD_LONG)
    return v


@claim("Section 3", "3.3. Joint connectivity and coverage-aware path planning",
       "Both hybrid schemes have advantages regarding notification performance over their "
       "native mTSP and CovB at the cost of search time.",
       "mTSP-ConB and ConCov notify at detection more often than mTSP and CovB, and detect "
       "later.")
def hybrids_trade_search_for_notification(t: PairedTables, s: Settings) -> Verdict:
    """For mTSP-ConB against mTSP (above N_r) and ConCov against CovB, averaged over team
    sizes: at t_d = 4000 s and Fig. 5's ranges the immediate notification difference lies
    above 0; at t_d = 1000 s and every r_c the P_d difference lies below 0."""
    v = Verdict()
    for h, native in HYBRIDS.items():
        _gaps(v, t, "immediate", [h], [native], FIG5_RANGES, TD_LONG, _above())
        _gaps(v, t, "P_d", [h], [native], RANGES, TD_SHORT, _below())
    return v


@claim("Section 3", "3.3. Joint connectivity and coverage-aware path planning",
       "An advantage of mTSP-ConB is that it guarantees coverage at a given time, which "
       "ConCov can guarantee only in probability.",
       "mTSP-ConB detects in every run within the flight budget; ConCov does not always.")
def mtsp_conb_guarantees_coverage(t: PairedTables, s: Settings) -> Verdict:
    """Every run of mTSP-ConB at every N_m and r_c detects within t_d = 4000 s (one miss
    contradicts); and ConCov misses the target in some run at some point (if it never does,
    this setting cannot show the difference: not testable)."""
    v = Verdict()
    _every_run(v, t, "P_d", "mtsp-conb", TD_LONG)
    missed = sum(k.counts[1] - k.counts[0] for n in DRONES for rc in RANGES
                 if (k := _stat(t, "P_d", "concov", n, rc, TD_LONG)).counts)
    v.test(Outcome.HOLDS if missed else Outcome.NOT_TESTABLE,
           f"ConCov: {missed} runs without detection within {TD_LONG:g} s over all points")
    return v


@claim("Section 3", "3.3. Joint connectivity and coverage-aware path planning",
       "Similarly, ConCov will suffer over CovB due to depth-first search.",
       "ConCov's plan computation time exceeds CovB's.", ("plan_times",))
def concov_plans_slower_than_covb(t: PairedTables, s: Settings) -> Verdict:
    """ConCov's plan computation time over CovB's, a geometric mean over the timed team sizes
    (per team size the difference of mean log times with Welch's 95% interval from the
    repeated timings, bounds averaged), lies above 1."""
    v = Verdict()
    ratio = _plan_ratio(t, "concov", "covb")
    v.test(ratio.above(1.0), f"ConCov / CovB plan time, geometric mean over N_m: {ratio}")
    return v


# -- Section 4.1 and Fig. 1 ---------------------------------------------------------------------


@claim("Section 4.1", "4.1. Simulation setup",
       "For the given r and a, the number of grid points for mTSP such that the search area "
       "is fully covered is 64.",
       "mTSP's plan visits 64 cells.", ("mtsp_plans",))
def mtsp_cells(t: PairedTables, s: Settings) -> Verdict:
    """Every mTSP plan (one per team size) visits exactly 64 cells."""
    v = Verdict()
    cells = sorted(set(int(c) for c in t.tables["mtsp_plans"]["cells"]))
    v.test(Outcome.HOLDS if cells == [64] else Outcome.CONTRADICTED,
           f"cells of the mTSP plans: {', '.join(map(str, cells))}")
    return v


@claim("Section 4.1", "4.1. Simulation setup",
       "The maximum flight time is computed according to the full-coverage path generated by "
       "mTSP for 2 UAVs",
       "T_max is the duration of the 2-drone mTSP plan.", ("mtsp_plans",))
def flight_budget_from_plan(t: PairedTables, s: Settings) -> Verdict:
    """The flight time of the longest tour of the 2-drone mTSP plan lies between 90 % of the
    flight budget T_max and T_max (it fits, and T_max is not much more); with a plan per run,
    their mean does, and every plan fits."""
    v = Verdict()
    row = t.tables["mtsp_plans"].set_index("drones").loc[2]
    longest, budget = float(row["longest_s"]), float(row["flight_time"])
    fits = float(row["longest_max_s"]) <= budget
    plans = int(row["plans"])
    spread = (f" (mean of {plans} plans, {row['longest_min_s']:.0f}-{row['longest_max_s']:.0f} s)"
              if plans > 1 else "")
    v.test(Outcome.HOLDS if 0.9 * budget <= longest and fits else Outcome.CONTRADICTED,
           f"longest tour of the 2-drone plan {longest:.0f} s{spread}, T_max {budget:g} s "
           f"({longest / budget:.1%})")
    return v


@claim("Section 4.1", "4.2. Performance comparison",
       "For this area size, a transmission range of r_c ≈ 2800 m would guarantee single-hop "
       "connectivity to all drones.",
       "The farthest point of the area is about 2800 m from the BS.", ())
def single_hop_range(t: PairedTables, s: Settings) -> Verdict:
    """The largest distance from the BS (at the centre) to a point of the square area, a/√2,
    is 2800 m to two significant figures."""
    v = Verdict()
    farthest = Mission().area.size / math.sqrt(2)
    v.test(Outcome.HOLDS if round(farthest, -2) == 2800 else Outcome.CONTRADICTED,
           f"a/√2 = {farthest:.0f} m")
    return v


@claim("Fig. 1", "4.2. Performance comparison",
       "Due to the distributed nature and fewer operations, the computation time of CovB is "
       "the lowest.", "CovB's plan computation time is the lowest.", ("plan_times",))
def covb_plans_fastest(t: PairedTables, s: Settings) -> Verdict:
    """For mTSP and for ConB: the ratio of its plan computation time to CovB's lies above 1.
    The ratio is a geometric mean over the timed team sizes: per team size, the difference of
    mean log times has Welch's 95% interval from the repeated timings, and the average over
    team sizes averages the bounds."""
    v = Verdict()
    for p in ("mtsp", "conb"):
        ratio = _plan_ratio(t, p, "covb")
        v.test(ratio.above(1.0), f"{_label(p)} / CovB plan time, geometric mean over N_m: "
                                 f"{ratio}")
    return v


@claim("Fig. 1", "4.2. Performance comparison",
       "The computation time of mTSP depends on the number of cities (cells), number of "
       "iterations, and the population size, and does not change significantly with N_m.",
       "mTSP's plan computation time does not change significantly with N_m.",
       ("plan_times",))
def mtsp_plan_time_flat(t: PairedTables, s: Settings) -> Verdict:
    """The factor by which mTSP's plan computation time changes from the smallest timed team
    to the largest (a least-squares line through the log times of every repeat against N_m,
    with the 95% t interval of its slope) lies within [1/2, 2]: holds if its interval does,
    contradicted if its interval lies outside."""
    v = Verdict()
    factor = t.plan_times.trend("mtsp")
    v.test(factor.within(1 / FLAT, FLAT), f"mTSP's plan time, largest over smallest team "
                                          f"(fitted): {factor}")
    return v


@claim("Fig. 1", "4.2. Performance comparison",
       "For ConB, on the other hand, N_m has a direct impact on the depth-first-search phase "
       "of the connectivity check to the BS.",
       "ConB's plan computation time grows with N_m.", ("plan_times",))
def conb_plan_time_grows(t: PairedTables, s: Settings) -> Verdict:
    """The factor by which ConB's plan computation time changes from the smallest timed team to
    the largest (a least-squares line through the log times of every repeat against N_m, with
    the 95% t interval of its slope) lies above 1."""
    v = Verdict()
    factor = t.plan_times.trend("conb")
    v.test(factor.above(1.0), f"ConB's plan time, largest over smallest team (fitted): {factor}")
    return v


@claim("Fig. 1", "4.2. Performance comparison",
       "The computation times of the hybrid schemes will also depend on N_m due to the "
       "connectivity component and will approach ConB as N_m increases and will be much "
       "higher than that of CovB.",
       "The hybrids' plan times grow with N_m, near ConB's at 22 drones, far above CovB's.",
       ("plan_times",))
def hybrid_plan_times(t: PairedTables, s: Settings) -> Verdict:
    """For mTSP-ConB and ConCov: the fitted factor of its plan time from the smallest timed
    team to the largest lies above 1; its time over ConB's at the largest team (Welch) lies
    within [1/2, 2]; and its time over CovB's, a geometric mean over team sizes, lies above 2
    ("much higher")."""
    v = Verdict()
    times = t.plan_times
    last = times.team_sizes()[-1]
    for h in HYBRIDS:
        factor = times.trend(h)
        v.test(factor.above(1.0), f"{_label(h)}'s plan time, largest over smallest team "
                                  f"(fitted): {factor}")
        near = times.log_ratio(h, "conb", last).mapped(math.exp, 2)
        v.test(near.within(1 / FLAT, FLAT), f"{_label(h)} / ConB plan time at N_m = {last}: "
                                            f"{near}")
        ratio = _plan_ratio(t, h, "covb")
        v.test(ratio.above(FLAT), f"{_label(h)} / CovB plan time, geometric mean over N_m: "
                                  f"{ratio}")
    return v


# -- Figs. 2-3 -----------------------------------------------------------------------------------


@claim("Figs. 2–3", "4.2. Performance comparison",
       "Observe from the figures that as r_c becomes larger mission success probability "
       "approaches 1 even with short target durations.",
       "As r_c grows, P_s at a short t_d rises toward 1.")
def larger_range_short_td(t: PairedTables, s: Settings) -> Verdict:
    """A trend, at the short t_d = 1000 s, for every planner and each team size of Fig. 2
    (10 and 22): P_s at r_c = 2000 m minus at 500 m (paired) lies above 0 (equal in every run,
    both at 1 say, is not testable), and P_s never falls significantly from one range to the
    next (contradicted if it does)."""
    v = Verdict()
    for n in FIG2_DRONES:
        for p in PAPER_PLANNERS:
            e = {rc: _stat(t, "P_s", p, n, rc, TD_SHORT) for rc in RANGES}
            falls = [f"{a:g} to {b:g} m" for a, b in itertools.pairwise(RANGES)
                     if (e[b] - e[a]).estimate().hi < 0]
            rise = (e[RANGES[-1]] - e[RANGES[0]]).estimate()
            v.test(Outcome.CONTRADICTED if falls else rise.above(),
                   f"N_m = {n}, {_label(p)}: P_s({TD_SHORT:g} s) "
                   + ", ".join(f"{rc:g} m {x.estimate()}" for rc, x in e.items())
                   + f"; rise from {RANGES[0]:g} to {RANGES[-1]:g} m {rise}"
                   + (f"; falls significantly from {', '.join(falls)}" if falls else ""))
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "In the case of ConB, the drones are allowed to spread more with higher transmission "
       "ranges.", "ConB covers more of the area (P_d) as r_c grows.")
def conb_spreads_with_range(t: PairedTables, s: Settings) -> Verdict:
    """For ConB at t_d = 4000 s: P_d at each larger r_c minus at the next smaller one,
    averaged over team sizes (paired), lies above 0."""
    v = Verdict()
    for a, b in itertools.pairwise(RANGES):
        per = {n: _stat(t, "P_d", "conb", n, b, TD_LONG) - _stat(t, "P_d", "conb", n, a, TD_LONG)
               for n in DRONES}
        _averaged(v, per, _above(), f"ConB's P_d at {b:g} m minus at {a:g} m")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "In the case of mTSP and CovB, with smaller r_c the drones can inform the BS mostly on "
       "their return path.",
       "At small r_c most of mTSP's and CovB's notifications come after detection.")
def coverage_notify_later_small_range(t: PairedTables, s: Settings) -> Verdict:
    """At the smallest r_c (500 m) and t_d = 4000 s, for mTSP and CovB: the immediate
    notification probability (the share of detections notified at once), averaged over team
    sizes, lies below 0.5: most notifications come later."""
    v = Verdict()
    rc = RANGES[0]
    for p in COVERAGE:
        per = {n: _stat(t, "immediate", p, n, rc, TD_LONG) for n in DRONES}
        _averaged(v, per, _below(0.5), f"{_rc(rc)}, {_label(p)}: immediate notification")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "When t_d = 4000 s, the mTSP scheme can finish the search mission even with 2 drones, "
       "and hence the mission success probability of mTSP in this case is 1.",
       "At t_d = 4000 s mTSP succeeds with probability 1 even with 2 drones.")
def mtsp_two_drones(t: PairedTables, s: Settings) -> Verdict:
    """For every r_c, every run of mTSP with N_m = 2 notifies the BS within t_d = 4000 s. A
    single run not notified contradicts the claim at any sample size."""
    v = Verdict()
    for rc in RANGES:
        e = _stat(t, "P_s", "mtsp", 2, rc, TD_LONG)
        k, n = e.counts or (0, 0)
        v.test(Outcome.HOLDS if k == n else Outcome.CONTRADICTED,
               f"{_rc(rc)}: {k} of {n} runs notified, P_s = {e.estimate()}")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "Due to the constraints on connectivity, adding more drones does not help ConB",
       "More drones do not help ConB.")
def drones_do_not_help_conb(t: PairedTables, s: Settings) -> Verdict:
    """At Fig. 3's t_d and every r_c, ConB's gain in P_s from N_m = 2 to 22 (paired) lies
    below 0.1."""
    v = Verdict()
    for rc in RANGES:
        e = _change(t, "P_s", "conb", (DRONES[0], rc, s.td_fig3),
                    (DRONES[-1], rc, s.td_fig3)).estimate()
        v.test(e.below(SMALL), f"{_rc(rc)}: ConB's gain in P_s({s.td_fig3:g} s) from "
                               f"N_m = {DRONES[0]} to {DRONES[-1]}: {e}")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "higher spatial density (due to higher r_c and/or N_m) improves the performance of "
       "mTSP and coverage-based schemes, significantly",
       "More drones, and a larger r_c, raise mTSP's and CovB's P_s.")
def density_helps_coverage(t: PairedTables, s: Settings) -> Verdict:
    """At Fig. 3's t_d, for mTSP and CovB (paired): the gain in P_s from N_m = 2 to 22 lies
    above 0 at every r_c, and the gain from r_c = 500 to 2000 m, averaged over team sizes,
    lies above 0."""
    v = Verdict()
    td = s.td_fig3
    for p in COVERAGE:
        for rc in RANGES:
            e = _change(t, "P_s", p, (DRONES[0], rc, td), (DRONES[-1], rc, td)).estimate()
            v.test(e.above(), f"{_rc(rc)}, {_label(p)}: gain in P_s({td:g} s) from "
                              f"N_m = {DRONES[0]} to {DRONES[-1]}: {e}")
        per = {n: _change(t, "P_s", p, (n, RANGES[0], td), (n, RANGES[-1], td))
               for n in DRONES}
        _averaged(v, per, _above(), f"{_label(p)}: gain in P_s({td:g} s) from "
                                    f"{_rc(RANGES[0])} to {RANGES[-1]:g} m")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "The hybrid schemes highly benefit from integrating connectivity in the search "
       "decisions.", "Both hybrids beat ConB in P_s.")
def hybrids_beat_conb(t: PairedTables, s: Settings) -> Verdict:
    """At Fig. 3's t_d and every r_c, for ConCov and for mTSP-ConB: its P_s minus ConB's,
    averaged over team sizes (paired), lies above 0."""
    v = Verdict()
    _gaps(v, t, "P_s", HYBRIDS, ["conb"], RANGES, s.td_fig3, _above())
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "The performance improvement of both schemes over ConB is most evident when r_c is "
       "low.", "The hybrids' advantage over ConB is largest at the smallest r_c.")
def hybrids_gain_most_at_low_range(t: PairedTables, s: Settings) -> Verdict:
    """At Fig. 3's t_d, for ConCov and for mTSP-ConB: its advantage over ConB in P_s at
    r_c = 500 m minus the advantage at each larger r_c, averaged over team sizes (all paired:
    the same runs), lies above 0."""
    v = Verdict()
    td = s.td_fig3
    for h in HYBRIDS:
        def gain(n: int, rc: float, h: str = h) -> Stat:
            return _stat(t, "P_s", h, n, rc, td) - _stat(t, "P_s", "conb", n, rc, td)
        for rc in RANGES[1:]:
            per = {n: gain(n, RANGES[0]) - gain(n, rc) for n in DRONES}
            _averaged(v, per, _above(), f"{_label(h)}'s advantage over ConB in P_s({td:g} s) "
                                        f"at {RANGES[0]:g} m minus at {rc:g} m")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "Between ConCov and mTSP-Con schemes, we observe that as N_m is increased ConCov "
       "significantly outperforms mTSP-Con, implying that while mTSP-Con guarantees search "
       "time it still suffers from delayed notification.",
       "With more drones ConCov pulls ahead of mTSP-ConB at a short t_d.")
def concov_beats_mtsp_conb(t: PairedTables, s: Settings) -> Verdict:
    """At the short t_d = 1000 s (where delayed notification costs success) and every r_c:
    ConCov's P_s minus mTSP-ConB's at the largest team (22) lies above 0, and it grows from
    mTSP-ConB's smallest own team (8 drones, the first above N_r) to 22 (paired change above
    0)."""
    v = Verdict()
    first, last = HYBRID_SMALL_TEAMS[0], DRONES[-1]
    for rc in RANGES:
        d = {n: _stat(t, "P_s", "concov", n, rc, TD_SHORT)
             - _stat(t, "P_s", "mtsp-conb", n, rc, TD_SHORT) for n in (first, last)}
        e, growth = d[last].estimate(), (d[last] - d[first]).estimate()
        v.test(e.above(), f"{_rc(rc)}: ConCov − mTSP-ConB in P_s({TD_SHORT:g} s) at "
                          f"N_m = {last}: {e}")
        v.test(growth.above(), f"{_rc(rc)}: its change from N_m = {first} "
                               f"({d[first].estimate()}): {growth}")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "Due to the equal weight given to the search and connectivity components of ConCov, "
       "the drones can simultaneously spread out and stay connected.",
       "ConCov keeps more drones connected than mTSP and CovB, and covers more than ConB.")
def concov_spreads_and_connects(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and every r_c, averaged over team sizes (paired): ConCov's mean
    fraction of drones connected to the BS minus mTSP's and minus CovB's lies above 0 (stays
    connected), and its P_d minus ConB's lies above 0 (spreads out)."""
    v = Verdict()
    _gaps(v, t, "connected", ["concov"], COVERAGE, RANGES, TD_LONG, _above())
    _gaps(v, t, "P_d", ["concov"], ["conb"], RANGES, TD_LONG, _above())
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "These results imply that while hybrid schemes utilize the available resources "
       "better than ConB, they might still require more resources than mTSP and CovB, "
       "especially when the detection task dominates the mission times.",
       "Where detection dominates, the hybrids trail mTSP and CovB.")
def hybrids_trail_coverage(t: PairedTables, s: Settings) -> Verdict:
    """Where detection dominates the mission: at the largest r_c (2000 m, where notification
    is quickest) and the short t_d = 1000 s (where the search is not finished), for each
    hybrid against each of mTSP and CovB, the hybrid's P_s minus the other's, averaged over
    team sizes (paired; mTSP-ConB against mTSP above N_r), lies below 0."""
    v = Verdict()
    _gaps(v, t, "P_s", HYBRIDS, COVERAGE, RANGES[-1:], TD_SHORT, _below())
    return v


# -- Fig. 4 --------------------------------------------------------------------------------------


def _converge(v: Verdict, t: PairedTables, td: float) -> None:
    for rc in RANGES:
        small, large = (_spread(t, "mission_time", n, rc, td) for n in (DRONES[0], DRONES[-1]))
        e = (small - large).estimate()
        v.test(e.above(), f"{_rc(rc)}, t_d = {td:g} s: spread of the planners' mean mission "
                          f"times at N_m = {DRONES[0]} {small.estimate()} s minus at "
                          f"{DRONES[-1]} {large.estimate()} s: {e} s")


@claim("Fig. 4", "4.2. Performance comparison",
       "Figure 4a shows that as N_m increases the performance of all schemes converge.",
       "The mission times of all schemes converge as N_m grows.")
def mission_times_converge(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and every r_c: the spread of the planners' mean mission times (the
    longest minus the shortest, the two picked by value) at the smallest team (2) minus at the
    largest (22), paired, lies above 0."""
    v = Verdict()
    _converge(v, t, TD_LONG)
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "However, the mission time of ConB is less than half of that of the other schemes for "
       "small N_m.", "ConB's mission time is under half of the others' for small N_m.")
def conb_mission_time(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s, for every r_c and N_m in {2, 4}, and against each other planner P:
    half of P's mean mission time minus ConB's lies above 0 (paired). Mission time is the
    mean notification time of the runs notified within t_d."""
    v = Verdict()
    for rc in RANGES:
        _half(t, v, ["conb"], _others("conb"), rc, TD_LONG, {"conb": SMALL_TEAMS})
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "Even when connectivity is added to the decision, total mission time is still higher "
       "for ConCov and mTSP-Con due to the time spent searching.",
       "ConCov's and mTSP-ConB's mission times stay above ConB's.")
def hybrid_times_above_conb(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and every r_c, for ConCov and for mTSP-ConB: its mean mission time
    minus ConB's, averaged over team sizes (paired), lies above 0."""
    v = Verdict()
    _gaps(v, t, "mission_time", HYBRIDS, ["conb"], RANGES, TD_LONG, _above())
    return v


def _interior(t: PairedTables, measure: str, planner: str, rc: float, td: float) -> Stat:
    return mean_of(_stat(t, measure, planner, n, rc, td) for n in DRONES[1:-1])


@claim("Fig. 4", "4.2. Performance comparison",
       "For small N_m, the search time is dominant due to low resources. For higher N_m, "
       "search time also dominates [...]. However, in between, the time spent for "
       "notification phase is highly significant for the native coverage schemes",
       "mTSP's and CovB's search share is higher at the smallest and largest teams than in "
       "between.")
def search_share_dips_in_between(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and every r_c, for mTSP and CovB: the search share of the mission time
    (Fig. 4b) at N_m = 2 minus its average over the teams in between (4 to 20), and at
    N_m = 22 minus that average, each lie above 0 (paired)."""
    v = Verdict()
    for rc in RANGES:
        for p in COVERAGE:
            middle = _interior(t, "search_share", p, rc, TD_LONG)
            for n in (DRONES[0], DRONES[-1]):
                e = (_stat(t, "search_share", p, n, rc, TD_LONG) - middle).estimate()
                v.test(e.above(), f"{_rc(rc)}, {_label(p)}: search share at N_m = {n} minus "
                                  f"its average over N_m = {DRONES[1]}–{DRONES[-2]} "
                                  f"({middle.estimate()}): {e}")
    return v


def _notification_share(t: PairedTables, planner: str, rc: float) -> Estimate:
    """The largest notification share (1 − the search share) over the team sizes."""
    shares = (_stat(t, "search_share", planner, n, rc, TD_LONG).estimate() for n in DRONES)
    return peak(Estimate(1 - e.value, 1 - e.hi, 1 - e.lo) for e in shares)


def _about(level: float) -> tuple[float, float]:
    """What "about ``level``" admits (see the module docstring)."""
    half = min(ABOUT, level / 2)
    return level - half, level + half


def _shares(v: Verdict, t: PairedTables, cases: Sequence[tuple[str, float, float]]) -> None:
    for p, rc, level in cases:
        share = _notification_share(t, p, rc)
        v.test(share.within(*_about(level)),
               f"{_rc(rc)}, {_label(p)}: largest notification share over N_m {share} "
               f"(about {level:g}: {'{:g} to {:g}'.format(*_about(level))})")


@claim("Fig. 4", "4.2. Performance comparison",
       "ConCov has better notification times (30% of mission time compared to 45%, when "
       "r_c = 1000 m)",
       "At r_c = 1000 m notification takes about 30 % of ConCov's mission, about 45 % of "
       "mTSP's and CovB's.")
def concov_notification_share(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and r_c = 1000 m, the notification share of the mission time (1 − the
    search share of Fig. 4b) at its largest over the team sizes (the sizes "in between" where
    the paper finds notification significant; the interval is that of the largest true share
    when every interval covers its own): about 0.3 for ConCov and about 0.45 for mTSP and for
    CovB, "about x" meaning x ± 0.1: holds if the interval lies within it, contradicted if it
    lies outside."""
    v = Verdict()
    _shares(v, t, [("concov", 1000.0, 0.3), ("mtsp", 1000.0, 0.45), ("covb", 1000.0, 0.45)])
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "however, still much lower than ConB (10% of total mission time for higher r_c)",
       "At the larger ranges notification takes about 10 % of ConB's mission.")
def conb_notification_share(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and r_c = 1000 and 2000 m, ConB's notification share of the mission
    time at its largest over the team sizes (as for ConCov's) is about 0.1: within
    [0.05, 0.15] ("about x" is never wider than x ± x/2, so that 0 is not "about 10 %")."""
    v = Verdict()
    _shares(v, t, [("conb", rc, 0.1) for rc in RANGES[1:]])
    return v


def _falls(v: Verdict, t: PairedTables, td: float) -> None:
    for rc in RANGES:
        for p in PAPER_PLANNERS:
            e = {n: _stat(t, "mission_time", p, n, rc, td) for n in DRONES}
            rises = [f"{a} to {b}" for a, b in itertools.pairwise(DRONES)
                     if (e[b] - e[a]).estimate().lo > 0]
            overall = (e[DRONES[-1]] - e[DRONES[0]]).estimate()
            v.test(Outcome.CONTRADICTED if rises else overall.below(),
                   f"{_rc(rc)}, {_label(p)}, t_d = {td:g} s: {e[DRONES[0]].estimate()} s at "
                   f"N_m = {DRONES[0]}, {e[DRONES[-1]].estimate()} s at N_m = {DRONES[-1]}, "
                   f"change {overall} s"
                   + (f"; rises significantly from N_m = {', '.join(rises)}" if rises else ""))


@claim("Fig. 4", "4.2. Performance comparison",
       "Observe that while the total mission time decreases monotonically with increasing "
       "N_m", "The total mission time falls monotonically with N_m.")
def mission_time_falls(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s, for every planner and r_c, the mean mission time against N_m
    (paired): contradicted if it rises significantly from one team size to the next; holds if
    it falls significantly from the smallest team to the largest and rises significantly
    nowhere; undecided otherwise."""
    v = Verdict()
    _falls(v, t, TD_LONG)
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "there exists a number of drones that minimize the detection phase duration of the "
       "mission", "The search share of every planner has its minimum at a team in between.")
def detection_phase_has_a_minimum(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s, for every planner and r_c: at some team size in between (4 to 20) the
    search share of the mission time (Fig. 4b) lies below both its value at N_m = 2 and at 22
    (paired, Bonferroni over the teams in between and the two ends). Contradicted if at every
    team in between it lies significantly above one of the ends."""
    v = Verdict()
    middle = DRONES[1:-1]
    level = _level(2 * len(middle))
    for rc in RANGES:
        for p in PAPER_PLANNERS:
            ends = [_stat(t, "search_share", p, n, rc, TD_LONG) for n in (DRONES[0], DRONES[-1])]
            below, above = [], 0
            for n in middle:
                mine = _stat(t, "search_share", p, n, rc, TD_LONG)
                d = [(mine - end).estimate(level) for end in ends]
                if all(e.hi < 0 for e in d):
                    below.append(n)
                above += any(e.lo > 0 for e in d)
            outcome = (Outcome.HOLDS if below else Outcome.CONTRADICTED
                       if above == len(middle) else Outcome.UNDECIDED)
            v.test(outcome, f"{_rc(rc)}, {_label(p)}: below both ends at N_m = "
                            f"{', '.join(map(str, below)) or 'none'}; significantly above an "
                            f"end at {above} of {len(middle)} teams in between")
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "While omitted here, similar trends have been observed for shorter t_d as well.",
       "At t_d = 2000 s mission times converge, fall with N_m, and ConB's is under half.")
def fig4_trends_at_shorter_td(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 2000 s the criteria of Fig. 4a's three trends: the spread of the planners'
    mean mission times shrinks from N_m = 2 to 22, every planner's mean mission time rises
    significantly nowhere and falls from 2 to 22 drones, and half of every other planner's
    mission time minus ConB's at N_m = 2 and 4 lies above 0 (all paired, every r_c)."""
    v = Verdict()
    _converge(v, t, TD_FIG3)
    _falls(v, t, TD_FIG3)
    for rc in RANGES:
        _half(t, v, ["conb"], _others("conb"), rc, TD_FIG3, {"conb": SMALL_TEAMS})
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "Therefore, depending on the priority of connectivity and tolerance to delays in "
       "notification, the choice of best path planning scheme changes.",
       "The planner best at success with delay tolerated is not the one best at immediate "
       "notification.")
def best_scheme_depends_on_priority(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and Fig. 5's ranges: with A the planner of the highest P_s averaged over
    team sizes (delay tolerated) and B the planner of the highest immediate notification
    (connectivity first): A differs from B (contradicted if not), A's P_s minus B's and B's
    immediate notification minus A's, averaged over team sizes (paired), lie above 0."""
    v = Verdict()
    for rc in FIG5_RANGES:
        def best(measure: str, rc: float = rc) -> str:
            return max(PAPER_PLANNERS, key=lambda p: mean_of(
                _stat(t, measure, p, n, rc, TD_LONG) for n in DRONES).value)
        a, b = best("P_s"), best("immediate")
        if a == b:
            v.test(Outcome.CONTRADICTED, f"{_rc(rc)}: {_label(a)} is best at both")
            continue
        _gap(v, t, "P_s", a, b, rc, TD_LONG, _above())
        _gap(v, t, "immediate", b, a, rc, TD_LONG, _above())
    return v


# -- Fig. 5 --------------------------------------------------------------------------------------


@claim("Fig. 5", "4.2. Performance comparison",
       "For short t_d, since the target is detected only if it is closer to the BS, immediate "
       "notification is highly likely.",
       "At a short t_d every planner's immediate notification is highly likely.")
def short_td_immediate_likely(t: PairedTables, s: Settings) -> Verdict:
    """At the short t_d = 1000 s and Fig. 5's ranges, for every planner: the immediate
    notification probability, averaged over team sizes, lies above 0.75."""
    v = Verdict()
    for rc in FIG5_RANGES:
        for p in PAPER_PLANNERS:
            per = {n: _stat(t, "immediate", p, n, rc, TD_SHORT) for n in DRONES}
            _averaged(v, per, _above(HIGHLY_LIKELY), f"{_rc(rc)}, {_label(p)}: immediate "
                                                     f"notification at {TD_SHORT:g} s")
    return v


@claim("Fig. 5", "4.2. Performance comparison",
       "However, as t_d increases, targets that are located farther from the BS can also be "
       "detected and the issue of notification becomes more critical.",
       "Immediate notification falls as t_d grows.")
def notification_more_critical_later(t: PairedTables, s: Settings) -> Verdict:
    """At Fig. 5's ranges, for every planner: the immediate notification probability at
    t_d = 4000 s minus at 1000 s, averaged over team sizes (paired), lies below 0."""
    v = Verdict()
    for rc in FIG5_RANGES:
        for p in PAPER_PLANNERS:
            per = {n: _change(t, "immediate", p, (n, rc, TD_SHORT), (n, rc, TD_LONG))
                   for n in DRONES}
            _averaged(v, per, _below(), f"{_rc(rc)}, {_label(p)}: immediate notification at "
                                        f"{TD_LONG:g} s minus at {TD_SHORT:g} s")
    return v


@claim("Fig. 5", "4.2. Performance comparison",
       "Observe that ConB, while suffering from lower detection probabilities, is much more "
       "likely to inform the BS at the time of detection.",
       "ConB detects less but notifies at detection more than every other planner.")
def conb_immediate_highest(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and Fig. 5's ranges, averaged over team sizes (paired): ConB's immediate
    notification minus each other planner's lies above 0, and its P_d minus each other's
    lies below 0."""
    v = Verdict()
    _gaps(v, t, "immediate", ["conb"], _others("conb"), FIG5_RANGES, TD_LONG, _above())
    _gaps(v, t, "P_d", ["conb"], _others("conb"), FIG5_RANGES, TD_LONG, _below())
    return v


@claim("Fig. 5", "4.2. Performance comparison", "ConCov follows ConB.",
       "ConCov's immediate notification is second to ConB's.")
def concov_follows_conb(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and Fig. 5's ranges, averaged over team sizes (paired): ConCov's
    immediate notification minus mTSP's, CovB's and mTSP-ConB's lies above 0."""
    v = Verdict()
    _gaps(v, t, "immediate", ["concov"], ("mtsp", "covb", "mtsp-conb"), FIG5_RANGES, TD_LONG,
          _above())
    return v


@claim("Fig. 5", "4.2. Performance comparison",
       "For lower r_c, the immediate notification probability of mTSP is the lowest (around "
       "0.2), indicating that the BS is most likely notified on the return paths of drones.",
       "At the lower r_c mTSP's immediate notification is the lowest, about 0.2.")
def mtsp_immediate_lowest(t: PairedTables, s: Settings) -> Verdict:
    """"For lower r_c" governs both halves: at r_c = 500 m and t_d = 4000 s, averaged over
    team sizes (paired), mTSP's immediate notification minus every other planner's lies
    below 0 (mTSP-ConB compared above N_r only), and mTSP's immediate notification averaged
    over team sizes is about 0.2 (within [0.1, 0.3]: holds if its interval is, contradicted
    if its interval lies outside)."""
    v = Verdict()
    rc = RANGES[0]
    _gaps(v, t, "immediate", ["mtsp"], _others("mtsp"), [rc], TD_LONG, _below())
    per = {n: _stat(t, "immediate", "mtsp", n, rc, TD_LONG) for n in DRONES}
    _averaged(v, per, lambda e: e.within(*_about(0.2)), f"{_rc(rc)}: mTSP's immediate "
                                                        "notification")
    return v


@claim("Fig. 5", "4.2. Performance comparison",
       "For high r_c the performance of all schemes converges to 1; hence these results are "
       "omitted.", "At high r_c every scheme's immediate notification approaches 1.")
def immediate_near_one_far(t: PairedTables, s: Settings) -> Verdict:
    """A limit: at t_d = 4000 s and the largest r_c (2000 m), for every planner, the immediate
    notification at the densest team (22 drones, the setting closest to the limit) lies above
    0.9, and its value at 2000 m minus at 1000 m, averaged over team sizes (paired), lies
    above 0 (it rises toward 1 with r_c; equal in every run is not testable)."""
    v = Verdict()
    far, near = RANGES[-1], RANGES[-2]
    for p in PAPER_PLANNERS:
        e = _stat(t, "immediate", p, DRONES[-1], far, TD_LONG).estimate()
        v.test(e.above(NEAR_ONE), f"{_rc(far)}, N_m = {DRONES[-1]}, {_label(p)}: immediate "
                                  f"notification {e}")
        per = {n: _change(t, "immediate", p, (n, near, TD_LONG), (n, far, TD_LONG))
               for n in DRONES}
        _averaged(v, per, _above(), f"{_label(p)}: immediate notification at {far:g} m minus "
                                    f"at {near:g} m")
    return v


@claim("Fig. 5", "4.2. Performance comparison",
       "If some notification delay can be tolerated, mTSP preserves its advantage of minimum "
       "traveled distances in terms of mission success.",
       "With t_d = 4000 s, mTSP's P_s is at least every other planner's.")
def mtsp_keeps_success_with_delay(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s (delay tolerated) and Fig. 5's ranges: mTSP's P_s minus each other
    planner's, averaged over team sizes (paired; mTSP-ConB above N_r), lies above 0; equal in
    every run (both always succeed) is not testable at this setting."""
    v = Verdict()
    _gaps(v, t, "P_s", ["mtsp"], _others("mtsp"), FIG5_RANGES, TD_LONG, _above())
    return v


# -- Fig. 6 --------------------------------------------------------------------------------------


@claim("Fig. 6", "4.2. Performance comparison",
       "Observe from Figure 6 that for small r_c all schemes have low target reachability as "
       "expected.", "At small r_c every scheme has low target reachability.")
def low_reachability_small_range(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and the smallest r_c (500 m): every planner's target reachability lies
    below a quarter of t_d at every team size (holds if every interval does, contradicted if
    one lies above)."""
    v = Verdict()
    rc = RANGES[0]
    for p in PAPER_PLANNERS:
        e = {n: _stat(t, "reachability", p, n, rc, TD_LONG).estimate() for n in DRONES}
        highest = max(e, key=lambda n: e[n].value)
        v.test(worst(x.below(LOW) for x in e.values()),
               f"{_rc(rc)}, {_label(p)}: highest reachability {e[highest]} at N_m = {highest}")
    return v


@claim("Fig. 6", "4.2. Performance comparison",
       "The ConB scheme outperforms the others in this case.",
       "At small r_c ConB has the best target reachability.")
def conb_reachability_best(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and r_c = 500 m: ConB's target reachability minus each other planner's,
    averaged over team sizes (paired), lies above 0."""
    v = Verdict()
    _gaps(v, t, "reachability", ["conb"], _others("conb"), RANGES[:1], TD_LONG, _above())
    return v


@claim("Fig. 6", "4.2. Performance comparison",
       "As r_c is increased, we observe that ConCov and CovB's performance starts exceeding "
       "that of ConB as N_m increases, since ConB still suffers from lower detection "
       "probability.", "As r_c grows, CovB and ConCov overtake ConB as N_m grows.")
def coverage_overtakes_conb(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and each larger r_c (1000 and 2000 m), for CovB and for ConCov: its
    target reachability minus ConB's lies above 0 at the largest team (22), and this
    difference grows from the smallest team (2) to the largest (paired change above 0)."""
    v = Verdict()
    for rc in RANGES[1:]:
        for p in ("covb", "concov"):
            d = {n: _stat(t, "reachability", p, n, rc, TD_LONG)
                 - _stat(t, "reachability", "conb", n, rc, TD_LONG)
                 for n in (DRONES[0], DRONES[-1])}
            small, large = d[DRONES[0]], d[DRONES[-1]]
            v.test(large.estimate().above(), f"{_rc(rc)}: {_label(p)} − ConB reachability at "
                                             f"N_m = {DRONES[-1]}: {large.estimate()}")
            growth = (large - small).estimate()
            v.test(growth.above(), f"{_rc(rc)}: its change from N_m = {DRONES[0]} "
                                   f"({small.estimate()}): {growth}")
    return v


@claim("Fig. 6", "4.2. Performance comparison",
       "The mTSP scheme is the worst of all schemes even with higher r_c.",
       "mTSP has the worst target reachability at every range.")
def mtsp_reachability_worst(t: PairedTables, s: Settings) -> Verdict:
    """At t_d = 4000 s and every r_c, averaged over team sizes (paired): mTSP's target
    reachability minus each other planner's lies below 0 (mTSP-ConB compared above N_r)."""
    v = Verdict()
    _gaps(v, t, "reachability", ["mtsp"], _others("mtsp"), RANGES, TD_LONG, _below())
    return v


# -- Fig. 7 --------------------------------------------------------------------------------------


@claim("Fig. 7a", "4.3. Impact of nonideal sensing and channel conditions",
       "Observe from Figure 7a that under ideal conditions when t_d = 1000 s, coverage-based "
       "and hybrid schemes (mTSP, CovB, mTSP-Con, ConCov) are able to detect the target with "
       "probability higher than 90%",
       "With ideal sensing mTSP, CovB, mTSP-ConB and ConCov detect with P_d above 0.9.",
       ("miss_runs",))
def ideal_detection(t: PairedTables, s: Settings) -> Verdict:
    """In Fig. 7a's setting (N_m = 10, r_c = 500 m, t_d = 1000 s) with ideal sensing
    (p_miss = 0): P_d lies above 0.9 for mTSP, CovB, mTSP-ConB and ConCov."""
    v = Verdict()
    for p in ("mtsp", "covb", "mtsp-conb", "concov"):
        e = t.miss_runs.stat("P_d", p, 0.0, td=TD_SHORT).estimate()
        v.test(e.above(NEAR_ONE), f"{_label(p)}: P_d at p_miss = 0: {e}")
    return v


@claim("Fig. 7a", "4.3. Impact of nonideal sensing and channel conditions",
       "When there are sensor errors, the detection probability decreases as expected. [...] "
       "Further observe that performance trends are changing in a similar manner for all "
       "schemes.", "Detection falls with the miss probability, for every scheme.",
       ("miss_runs",))
def detection_falls_with_miss(t: PairedTables, s: Settings) -> Verdict:
    """In Fig. 7a, for every planner (the same rule for each is what "a similar manner for all
    schemes" asks), paired: P_d at the largest miss probability (0.9) minus P_d at 0 lies
    below 0, and P_d never rises significantly from one miss probability to the next
    (contradicted if a step's interval lies above 0)."""
    v = Verdict()
    for p in PAPER_PLANNERS:
        e = {q: t.miss_runs.stat("P_d", p, q, td=TD_SHORT) for q in P_MISS}
        rises = [f"{a:g} to {b:g}" for a, b in itertools.pairwise(P_MISS)
                 if (e[b] - e[a]).estimate().lo > 0]
        fall = (e[P_MISS[-1]] - e[0.0]).estimate()
        v.test(Outcome.CONTRADICTED if rises else fall.below(),
               f"{_label(p)}: P_d {e[0.0].estimate()} at p_miss = 0, "
               f"{e[P_MISS[-1]].estimate()} at {P_MISS[-1]:g}; change {fall}"
               + (f"; rises significantly from {', '.join(rises)}" if rises else ""))
    return v


@claim("Fig. 7a", "4.3. Impact of nonideal sensing and channel conditions",
       "the detection probability is not significantly affected if the miss probability is "
       "not too high", "While the miss probability is small, detection barely changes.",
       ("miss_runs",))
def detection_robust_to_small_miss(t: PairedTables, s: Settings) -> Verdict:
    """In Fig. 7a, for every planner and each miss probability up to 0.2: P_d minus P_d at
    p_miss = 0 (paired) lies above −0.1 (holds if its interval does, contradicted if its
    interval lies below)."""
    v = Verdict()
    for p in PAPER_PLANNERS:
        ideal = t.miss_runs.stat("P_d", p, 0.0, td=TD_SHORT)
        for q in (q for q in P_MISS if 0 < q <= SMALL_MISS):
            drop = (t.miss_runs.stat("P_d", p, q, td=TD_SHORT) - ideal).estimate()
            v.test(drop.above(-SMALL), f"{_label(p)}: P_d at p_miss = {q:g} minus at 0: {drop}")
    return v


def _shadowing_rc(t: PairedTables) -> float:
    return float(t.tables["shadowing_runs"]["rc"].iloc[0])


@claim("Fig. 7b", "4.3. Impact of nonideal sensing and channel conditions",
       "Observe that the performance trends are similar to those of the simplified "
       "communication model", "Under shadowing the orders of Fig. 5 remain.",
       ("main_runs", "shadowing_runs"))
def shadowing_keeps_trends(t: PairedTables, s: Settings) -> Verdict:
    """At Fig. 7b's r_c (1000 m) and t_d = 4000 s, immediate notification averaged over team
    sizes (paired), with log-normal shadowing (Fig. 7b) and without (Fig. 5): for every pair
    of planners whose order is significant without shadowing, the difference with shadowing
    lies on the same side of 0 (contradicted if it lies on the other). With no significant
    order to keep, undecided (or not testable if every pair is equal in every run)."""
    v = Verdict()
    open_orders: set[Outcome] = set()
    rc = _shadowing_rc(t)
    for a, b in itertools.combinations(PAPER_PLANNERS, 2):
        sizes = _sizes(a, b)
        disc = mean_of(_stat(t, "immediate", a, n, rc, TD_LONG)
                       - _stat(t, "immediate", b, n, rc, TD_LONG) for n in sizes).estimate()
        shadowed = mean_of(t.shadowed_runs.stat("immediate", a, n, rc, td=TD_LONG)
                           - t.shadowed_runs.stat("immediate", b, n, rc, td=TD_LONG)
                           for n in sizes).estimate()
        pair = (f"{_rc(rc)}: {_label(a)} − {_label(b)} immediate notification averaged over "
                f"N_m, without shadowing {disc}, with {shadowed}")
        order = disc.above()
        if order in (Outcome.UNDECIDED, Outcome.NOT_TESTABLE):
            v.note(pair + " (no significant order without shadowing)")
            open_orders.add(order)
        else:
            v.test(shadowed.above() if order is Outcome.HOLDS else shadowed.below(), pair)
    if not v.parts:
        v.test(Outcome.UNDECIDED if Outcome.UNDECIDED in open_orders else Outcome.NOT_TESTABLE,
               "no pair of planners has a significant order without shadowing")
    return v


@claim("Fig. 7b", "4.3. Impact of nonideal sensing and channel conditions",
       "whereas the notification probability is improved slightly for mTSP schemes",
       "Shadowing raises mTSP's and mTSP-ConB's immediate notification slightly.",
       ("main_runs", "shadowing_runs"))
def shadowing_helps_mtsp_slightly(t: PairedTables, s: Settings) -> Verdict:
    """At Fig. 7b's r_c and t_d = 4000 s, for mTSP and mTSP-ConB: the immediate notification
    with shadowing minus without, averaged over team sizes (paired: the same runs' targets),
    lies within [0, 0.1] (holds if its interval does, contradicted if it lies outside)."""
    v = Verdict()
    rc = _shadowing_rc(t)
    for p in ("mtsp", "mtsp-conb"):
        per = {n: t.shadowed_runs.stat("immediate", p, n, rc, td=TD_LONG)
               - _stat(t, "immediate", p, n, rc, TD_LONG) for n in DRONES}
        _averaged(v, per, lambda e: e.within(0.0, SMALL),
                  f"{_rc(rc)}, {_label(p)}: immediate notification with shadowing minus "
                  "without")
    return v


# -- Conclusions ---------------------------------------------------------------------------------


@claim("Conclusions", "5. Conclusions",
       "Our results indicate that the impact of connectivity on the mission success "
       "probability and total mission times is most evident when communication resources "
       "(i.e. range and spatial density) are highly stringent.",
       "The planners differ most in P_s and mission time at small r_c and few drones.")
def stringent_resources_matter_most(t: PairedTables, s: Settings) -> Verdict:
    """Paired: the spread of the planners' P_s at Fig. 3's t_d (the highest minus the lowest,
    picked by value), averaged over team sizes, at r_c = 500 m minus at 2000 m lies above 0;
    and the spread of their mean mission times at t_d = 4000 s at (500 m, N_m = 2) minus at
    (2000 m, N_m = 22) lies above 0."""
    v = Verdict()
    low, high = RANGES[0], RANGES[-1]
    per = {n: _spread(t, "P_s", n, low, s.td_fig3) - _spread(t, "P_s", n, high, s.td_fig3)
           for n in DRONES}
    _averaged(v, per, _above(), f"spread of the planners' P_s({s.td_fig3:g} s) at {low:g} m "
                                f"minus at {high:g} m")
    e = (_spread(t, "mission_time", DRONES[0], low, TD_LONG)
         - _spread(t, "mission_time", DRONES[-1], high, TD_LONG)).estimate()
    v.test(e.above(), f"spread of the planners' mean mission times at {low:g} m with "
                      f"{DRONES[0]} drones minus at {high:g} m with {DRONES[-1]}: {e} s")
    return v


@claim("Conclusions", "5. Conclusions",
       "While connectivity-aware path planning can provide simultaneous detection and "
       "notification as well as good target reachability, it suffers from longer search "
       "times due to slower spreading than the coverage-based schemes.",
       "ConB and ConCov notify at detection more and keep the target reachable longer than "
       "mTSP and CovB, but detect later.")
def connectivity_aware_tradeoff(t: PairedTables, s: Settings) -> Verdict:
    """For ConB and ConCov against mTSP and CovB, averaged over team sizes (paired): at
    t_d = 4000 s and Fig. 5's ranges, the immediate notification and the target reachability
    differences lie above 0; at t_d = 1000 s and every r_c, the P_d difference lies below
    0."""
    v = Verdict()
    _gaps(v, t, "immediate", CONNECTIVITY, COVERAGE, FIG5_RANGES, TD_LONG, _above())
    _gaps(v, t, "reachability", CONNECTIVITY, COVERAGE, FIG5_RANGES, TD_LONG, _above())
    _gaps(v, t, "P_d", CONNECTIVITY, COVERAGE, RANGES, TD_SHORT, _below())
    return v


@claim("Conclusions", "5. Conclusions",
       "On the other hand, mTSP schemes can find the targets fast, but require more "
       "tolerance to notification delays.",
       "mTSP and mTSP-ConB detect sooner than ConB and ConCov but notify later after "
       "detection.")
def mtsp_fast_but_delayed(t: PairedTables, s: Settings) -> Verdict:
    """For mTSP and mTSP-ConB against ConB and ConCov, averaged over team sizes (paired): at
    t_d = 1000 s and every r_c the P_d difference lies above 0; at t_d = 4000 s and Fig. 5's
    ranges the mean notification delay difference lies above 0."""
    v = Verdict()
    _gaps(v, t, "P_d", ("mtsp", "mtsp-conb"), CONNECTIVITY, RANGES, TD_SHORT, _above())
    _gaps(v, t, "delay", ("mtsp", "mtsp-conb"), CONNECTIVITY, FIG5_RANGES, TD_LONG, _above())
    return v
