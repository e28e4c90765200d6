"""The claims of Fig. 4: mission times and the shares of their phases."""

from __future__ import annotations

from collections.abc import Sequence

from sarlink.paper.claim import Settings, claim
from sarlink.paper.evidence import Estimate, Outcome, Verdict, peak
from sarlink.paper.experiments import DRONES, FIG5_RANGES, RANGES, TD_FIG3, TD_LONG
from sarlink.paper.findings.helpers import (
    COVERAGE,
    HYBRIDS,
    SMALL_TEAMS,
    _about,
    _about_band,
    _above,
    _exists_part,
    _gap,
    _gaps,
    _half,
    _jointly,
    _label,
    _level,
    _others,
    _rc,
    _spread,
    _stat,
    _trend,
)
from sarlink.paper.paired import PairedTables, mean_of
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
    """"as N_m increases the performance of all schemes converge": at t_d = 4000 s and every
    r_c: the spread of the planners' mean mission times (the longest minus the shortest, the
    two picked by value, over the runs both notify) at the smallest team (2) minus at the
    largest (22), paired, lies above 0."""
    v = Verdict()
    _converge(v, t, TD_LONG)
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "However, the mission time of ConB is less than half of that of the other schemes for "
       "small N_m.", "ConB's mission time is under half of the others' for small N_m.",
       mechanism={"sarlink-3": (
       "On the same targets ConB is no faster than mTSP and CovB: it notifies only the "
       "targets near the BS, which they notify as soon."),
       "sarlink-4": (
       "ConB is under half only with 2 drones at r_c = 500 and 1000 m against mTSP and CovB, which "
       "notify late the targets near the BS it keeps to; ConCov's 2 drones stay near the BS too "
       "and notify them within 1.5 times ConB's time; with 4 drones ConB's chains reach the "
       "farther targets late; at 2000 m all notify at detection and ConB detects no sooner.")})
def conb_mission_time(t: PairedTables, s: Settings) -> Verdict:
    """"the mission time of ConB is less than half of that of the other schemes for small N_m":
    at t_d = 4000 s, for every r_c and N_m in {2, 4}, and against each other planner P
    (mTSP-ConB only above N_r, where it is not mTSP): half of P's mean mission time minus
    ConB's lies above 0, both over the runs both notify within t_d (paired: the same targets)."""
    v = Verdict()
    for rc in RANGES:
        _half(t, v, ["conb"], _others("conb"), rc, TD_LONG, {"conb": SMALL_TEAMS})
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "Even when connectivity is added to the decision, total mission time is still higher "
       "for ConCov and mTSP-Con due to the time spent searching.",
       "ConCov's and mTSP-ConB's mission times stay above ConB's.",
       mechanism={"sarlink-3": (
       "ConB's drones leave the BS together at one speed and reach r_c together; with the BS "
       "as the only routed neighbour Eq. 9's two unit vectors cancel and they turn back, so "
       "they fly diameters through the BS and never leave the disc of radius r_c; ConCov's "
       "drones, repelling each other, reach the targets near the BS (the only ones ConB "
       "notifies) sooner than ConB's drones passing back and forth, so on the same targets "
       "ConCov's mission time is the shorter."),
       "sarlink-4": (
       "ConB's chains search slowly: on the targets both notify, ConCov and mTSP-ConB detect "
       "sooner than ConB (averaged over N_m, by about 450 s at r_c = 500 m and 160–220 s at 1000 "
       "m), more than their later notification costs them; at 2000 m all notify at detection.")})
def hybrid_times_above_conb(t: PairedTables, s: Settings) -> Verdict:
    """"total mission time is still higher for ConCov and mTSP-Con": at t_d = 4000 s and every
    r_c, for ConCov and for mTSP-ConB (above N_r, where it is a hybrid): its mean mission time
    minus ConB's, over the runs both notify (paired), averaged over team sizes, lies above 0."""
    v = Verdict()
    _gaps(v, t, "mission_time", HYBRIDS, ["conb"], RANGES, TD_LONG, _above())
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "For small N_m, the search time is dominant due to low resources. For higher N_m, "
       "search time also dominates [...]. However, in between, the time spent for "
       "notification phase is highly significant for the native coverage schemes",
       "mTSP's and CovB's search share is higher at the smallest and largest teams than in "
       "between.")
def search_share_dips_in_between(t: PairedTables, s: Settings) -> Verdict:
    """A U-shape, "For small N_m, the search time is dominant", "For higher N_m, search time
    also dominates", "in between, the time spent for notification phase is highly significant":
    at t_d = 4000 s and every r_c, for mTSP and CovB, the search share of the mission time
    (Fig. 4b) at N_m = 2 minus its least value over the teams in between (4 to 20, the least
    picked by value), and at N_m = 22 minus that least value, each over the runs both notify
    (paired), lie above 0."""
    v = Verdict()
    for rc in RANGES:
        for p in COVERAGE:
            inside = {n: _stat(t, "search_share", p, n, rc, TD_LONG) for n in DRONES[1:-1]}
            low = min(inside, key=lambda n: inside[n].value)
            for n in (DRONES[0], DRONES[-1]):
                e = (_stat(t, "search_share", p, n, rc, TD_LONG) - inside[low]).estimate()
                v.test(e.above(), f"{_rc(rc)}, {_label(p)}: search share at N_m = {n} minus "
                                  f"its least value in between (N_m = {low}, "
                                  f"{inside[low].estimate()}): {e}")
    return v


def _notification_share(t: PairedTables, planner: str, rc: float) -> Estimate:
    """The largest notification share (1 − the search share) over the team sizes."""
    shares = (_stat(t, "search_share", planner, n, rc, TD_LONG).estimate() for n in DRONES)
    return peak(Estimate(1 - e.value, 1 - e.hi, 1 - e.lo) for e in shares)



def _shares(v: Verdict, t: PairedTables, cases: Sequence[tuple[str, float, float]],
            versus: Sequence[float] = ()) -> None:
    for p, rc, level in cases:
        share = _notification_share(t, p, rc)
        others = [x for x in versus if x != level]
        lo, hi = _about_band(level, False, others)
        _about(level, others).test(v, share, f"{_rc(rc)}, {_label(p)}: largest notification "
                                             f"share over N_m {share} (about {level:g}: "
                                             f"{lo:g} to {hi:g})")


@claim("Fig. 4", "4.2. Performance comparison",
       "ConCov has better notification times (30% of mission time compared to 45%, when "
       "r_c = 1000 m)",
       "At r_c = 1000 m notification takes about 30 % of ConCov's mission, about 45 % of "
       "mTSP's and CovB's.")
def concov_notification_share(t: PairedTables, s: Settings) -> Verdict:
    """"30% of mission time compared to 45%, when r_c = 1000 m": at t_d = 4000 s and r_c = 1000
    m, the notification share of the mission time (1 − the search share of Fig. 4b) at its
    largest over the team sizes (the sizes "in between" where the paper finds notification
    significant; the interval is that of the largest true share when every interval covers its
    own): about 0.3 for ConCov and about 0.45 for mTSP and for CovB, "about x" meaning x ± 0.1
    but no nearer the other value than half the gap (0.3 ± 0.075, 0.45 ± 0.075): holds if the
    interval lies within it, contradicted if it lies outside."""
    v = Verdict()
    _shares(v, t, [("concov", 1000.0, 0.3), ("mtsp", 1000.0, 0.45), ("covb", 1000.0, 0.45)],
            versus=(0.3, 0.45))
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "however, still much lower than ConB (10% of total mission time for higher r_c)",
       "At the larger ranges notification takes about 10 % of ConB's mission.",
       mechanism={"sarlink-3": (
       "ConB's drones leave the BS together at one speed and reach r_c together; with the BS "
       "as the only routed neighbour Eq. 9's two unit vectors cancel and they turn back, so "
       "they fly diameters through the BS and never leave the disc of radius r_c, so every "
       "detection is in reach and notified at once: notification takes no share of ConB's "
       "mission."),
       "sarlink-4": (
       "At r_c = 1000 and 2000 m ConB's chains keep a route to the BS 96–100 % of the time, so "
       "97–100 % of its detections are notified at once: notification takes at most 2 % of its "
       "mission at 1000 m and none at 2000 m.")})
def conb_notification_share(t: PairedTables, s: Settings) -> Verdict:
    """"10% of total mission time for higher r_c": at t_d = 4000 s and r_c = 1000 and 2000 m,
    ConB's notification share of the mission time at its largest over the team sizes (as for
    ConCov's) is about 0.1: within [0.05, 0.15] ("about x" is never wider than x ± x/2, so that
    0 is not "about 10 %")."""
    v = Verdict()
    _shares(v, t, [("conb", rc, 0.1) for rc in RANGES[1:]])
    return v


def _falls(v: Verdict, t: PairedTables, td: float) -> None:
    for rc in RANGES:
        for p in PAPER_PLANNERS:
            _trend(v, {n: _stat(t, "mission_time", p, n, rc, td) for n in DRONES}, -1, td,
                   f"{_rc(rc)}, {_label(p)}, t_d = {td:g} s", "N_m = {:g}", " s")


@claim("Fig. 4", "4.2. Performance comparison",
       "Observe that while the total mission time decreases monotonically with increasing "
       "N_m", "The total mission time falls monotonically with N_m.")
def mission_time_falls(t: PairedTables, s: Settings) -> Verdict:
    """"the total mission time decreases monotonically with increasing N_m": at t_d = 4000 s,
    for every planner and r_c, the mean mission time against N_m, each step over the runs both
    team sizes notify (paired): contradicted if it rises from one team size to the next by more
    than 2 % of the figure's axis (0 to t_d: 80 s), which a figure shows; holds if it falls
    significantly from the smallest team to the largest and rises visibly nowhere; undecided
    otherwise."""
    v = Verdict()
    _falls(v, t, TD_LONG)
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "there exists a number of drones that minimize the detection phase duration of the "
       "mission", "The search share of every planner has its minimum at a team in between.")
def detection_phase_has_a_minimum(t: PairedTables, s: Settings) -> Verdict:
    """"there exists a number of drones that minimize the detection phase duration": at t_d =
    4000 s, for every planner and r_c: at some team size in between (4 to 20) the search share
    of the mission time (Fig. 4b) lies below both its value at N_m = 2 and at 22 (paired over
    the runs both notify, Bonferroni over the teams in between and the two ends). A team equal
    to an end in every run cannot show it and is no candidate; contradicted if at every other
    team in between it lies significantly above an end; not testable if no team is left."""
    v = Verdict()
    middle = DRONES[1:-1]
    level = _level(2 * len(middle))
    for rc in RANGES:
        for p in PAPER_PLANNERS:
            ends = [_stat(t, "search_share", p, n, rc, TD_LONG) for n in (DRONES[0], DRONES[-1])]
            outcomes = {f"N_m = {n}": _jointly(
                (_stat(t, "search_share", p, n, rc, TD_LONG) - end).estimate(level).below()
                for end in ends) for n in middle}
            _exists_part(v, outcomes, f"{_rc(rc)}, {_label(p)}: search share below both "
                                      f"ends, in between")
    return v


@claim("Fig. 4", "4.2. Performance comparison",
       "While omitted here, similar trends have been observed for shorter t_d as well.",
       "At t_d = 2000 s mission times converge, fall with N_m, and ConB's is under half.",
       mechanism={"sarlink-3": (
       "Within t_d = 2000 s the 2-drone mTSP plan notifies only targets its two tours pass "
       "early, and the 4-drone plan, its tours laid out afresh, reaches some of those same "
       "targets later: over the same targets the mission time rises from 2 to 4 drones."),
       "sarlink-4": (
       "Within t_d = 2000 s the planners notify mostly targets near the BS (the 2-drone mTSP plan "
       "only 12.5 % of all at r_c = 500 m), which mTSP and CovB notify soon after detection, "
       "mostly within 100 s: on the targets both notify their mission times are 0.7–1.8 times "
       "ConB's, never twice.")})
def fig4_trends_at_shorter_td(t: PairedTables, s: Settings) -> Verdict:
    """"similar trends have been observed for shorter t_d as well": at t_d = 2000 s the
    criteria of Fig. 4a's three trends: the spread of the planners' mean mission times shrinks
    from N_m = 2 to 22, every planner's mean mission time rises nowhere by more than 2 % of the
    axis (40 s) and falls from 2 to 22 drones, and half of every other planner's mission time
    minus ConB's at N_m = 2 and 4 lies above 0 (mTSP-ConB above N_r; all paired, over the runs
    both notify, every r_c)."""
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
    """"depending on the priority of connectivity and tolerance to delays in notification, the
    choice of best path planning scheme changes": at t_d = 4000 s and Fig. 5's ranges: with A
    the planner of the highest P_s averaged over team sizes (delay tolerated) and B the planner
    of the highest immediate notification (connectivity first): A differs from B (contradicted
    if not), A's P_s minus B's and B's immediate notification minus A's, averaged over team
    sizes (paired), lie above 0."""
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
