"""The claims of Fig. 4: mission times and the shares of their phases."""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from sarlink.paper.claim import Settings, claim
from sarlink.paper.evidence import Estimate, Outcome, Verdict, peak
from sarlink.paper.experiments import DRONES, FIG5_RANGES, RANGES, TD_FIG3, TD_LONG
from sarlink.paper.findings.helpers import (
    COVERAGE,
    HYBRIDS,
    SMALL_TEAMS,
    _about,
    _above,
    _gap,
    _gaps,
    _half,
    _label,
    _level,
    _others,
    _rc,
    _spread,
    _stat,
)
from sarlink.paper.paired import PairedTables, Stat, mean_of
from sarlink.planners import PAPER_PLANNERS


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
