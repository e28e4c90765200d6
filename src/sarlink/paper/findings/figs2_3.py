"""The claims of Figs. 2 and 3: P_s against t_d, and against the team size."""

from __future__ import annotations

import itertools

from sarlink.paper.claim import Settings, claim
from sarlink.paper.evidence import Outcome, Verdict
from sarlink.paper.experiments import DRONES, FIG2_DRONES, RANGES, TD_LONG, TD_SHORT
from sarlink.paper.findings.helpers import (
    COVERAGE,
    HYBRID_SMALL_TEAMS,
    HYBRIDS,
    SMALL,
    _above,
    _averaged,
    _below,
    _change,
    _gaps,
    _grid_picture,
    _label,
    _own,
    _rc,
    _sizes,
    _stat,
    _trend,
)
from sarlink.paper.paired import PairedTables, Stat, mean_of
from sarlink.planners import PAPER_PLANNERS


@claim("Figs. 2–3", "4.2. Performance comparison",
       "Observe from the figures that as r_c becomes larger mission success probability "
       "approaches 1 even with short target durations.",
       "As r_c grows, P_s at a short t_d rises toward 1.")
def larger_range_short_td(t: PairedTables, s: Settings) -> Verdict:
    """"as r_c becomes larger mission success probability approaches 1 even with short target
    durations": a trend, at the short t_d = 1000 s, for every planner and each team size of
    Fig. 2 (10 and 22): P_s at r_c = 2000 m minus at 500 m (paired) lies above 0 (equal in
    every run, both at 1 say, is not testable), and P_s falls from no range to the next by more
    than 0.02 (a fall the figure shows: contradicted if one does)."""
    v = Verdict()
    for n in FIG2_DRONES:
        for p in PAPER_PLANNERS:
            _trend(v, {rc: _stat(t, "P_s", p, n, rc, TD_SHORT) for rc in RANGES}, +1, 1.0,
                   f"N_m = {n}, {_label(p)}, P_s({TD_SHORT:g} s)", "r_c = {:g} m")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "In the case of ConB, the drones are allowed to spread more with higher transmission "
       "ranges.", "ConB covers more of the area (P_d) as r_c grows.")
def conb_spreads_with_range(t: PairedTables, s: Settings) -> Verdict:
    """"the drones are allowed to spread more with higher transmission ranges": for ConB at t_d
    = 4000 s: P_d at each larger r_c minus at the next smaller one, averaged over team sizes
    (paired), lies above 0."""
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
    """"with smaller r_c the drones can inform the BS mostly on their return path": at the
    smallest r_c (500 m) and t_d = 4000 s, for mTSP and CovB: the immediate notification
    probability (the share of detections notified at once), averaged over team sizes, lies
    below 0.5: most notifications come later."""
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
    """"the mission success probability of mTSP in this case is 1": for every r_c, every run of
    mTSP with N_m = 2 notifies the BS within t_d = 4000 s. A single run not notified
    contradicts the claim at any sample size."""
    v = Verdict()
    for rc in RANGES:
        e = _stat(t, "P_s", "mtsp", 2, rc, TD_LONG)
        k, n = e.counts or (0, 0)
        v.test(Outcome.HOLDS if k == n else Outcome.CONTRADICTED,
               f"{_rc(rc)}: {k} of {n} runs notified, P_s = {e.estimate()}")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "Due to the constraints on connectivity, adding more drones does not help ConB",
       "More drones do not help ConB.",
       mechanism={"sarlink-3": (
       "ConB's drones leave the BS together at one speed and reach r_c together; with the BS "
       "as the only routed neighbour Eq. 9's two unit vectors cancel and they turn back, so "
       "they fly diameters through the BS and never leave the disc of radius r_c: more "
       "drones sweep that disc sooner, and at r_c = 1000 and 2000 m the disc and its sensing "
       "rim hold much of the area, so ConB's P_s grows with N_m."),
       "sarlink-4": (
       "Where Eq. 9 vanishes ConB's drones turn along the rim of their routed neighbour's range "
       "instead of back, so each added drone can hang one hop farther out: at r_c = 500 m the BS's "
       "network at 1000 s is 4.2 hops deep with 22 drones and 1.2 with 2, and P_s(2000 s) for "
       "targets beyond 1000 m rises from 0.04 to 0.89.")})
def drones_do_not_help_conb(t: PairedTables, s: Settings) -> Verdict:
    """"adding more drones does not help ConB": at Fig. 3's t_d and every r_c, ConB's gain in
    P_s from N_m = 2 to 22 (paired) lies below 0.1."""
    v = Verdict()
    for rc in RANGES:
        e = _change(t, "P_s", "conb", (DRONES[0], rc, s.td_fig3),
                    (DRONES[-1], rc, s.td_fig3)).estimate()
        _below(SMALL).test(v, e, f"{_rc(rc)}: ConB's gain in P_s({s.td_fig3:g} s) from "
                                 f"N_m = {DRONES[0]} to {DRONES[-1]}: {e}")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "higher spatial density (due to higher r_c and/or N_m) improves the performance of "
       "mTSP and coverage-based schemes, significantly",
       "More drones, and a larger r_c, raise mTSP's and CovB's P_s.")
def density_helps_coverage(t: PairedTables, s: Settings) -> Verdict:
    """"higher spatial density (due to higher r_c and/or N_m) improves the performance of mTSP
    and coverage-based schemes": at Fig. 3's t_d, for mTSP and CovB (paired): the gain in P_s
    from N_m = 2 to 22 lies above 0 at every r_c, and the gain from r_c = 500 to 2000 m,
    averaged over team sizes, lies above 0."""
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
    """"The hybrid schemes highly benefit from integrating connectivity": at Fig. 3's t_d and
    every r_c, for ConCov and for mTSP-ConB: its P_s minus ConB's, averaged over team sizes
    (paired; mTSP-ConB above N_r, where it is a hybrid), lies above 0."""
    v = Verdict()
    _gaps(v, t, "P_s", HYBRIDS, ["conb"], RANGES, s.td_fig3, _above())
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "The performance improvement of both schemes over ConB is most evident when r_c is "
       "low.", "The hybrids' advantage over ConB is largest at the smallest r_c.")
def hybrids_gain_most_at_low_range(t: PairedTables, s: Settings) -> Verdict:
    """"The performance improvement of both schemes over ConB is most evident when r_c is low":
    at Fig. 3's t_d, for ConCov and for mTSP-ConB: its advantage over ConB in P_s at r_c = 500
    m minus the advantage at each larger r_c, averaged over team sizes (all paired: the same
    runs; mTSP-ConB above N_r, where it is a hybrid), lies above 0."""
    v = Verdict()
    td = s.td_fig3
    for h in HYBRIDS:
        def gain(n: int, rc: float, h: str = h) -> Stat:
            return _stat(t, "P_s", h, n, rc, td) - _stat(t, "P_s", "conb", n, rc, td)
        for rc in RANGES[1:]:
            per = {n: gain(n, RANGES[0]) - gain(n, rc) for n in _own(h)}
            _averaged(v, per, _above(), f"{_label(h)}'s advantage over ConB in P_s({td:g} s) "
                                        f"at {RANGES[0]:g} m minus at {rc:g} m")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "Between ConCov and mTSP-Con schemes, we observe that as N_m is increased ConCov "
       "significantly outperforms mTSP-Con, implying that while mTSP-Con guarantees search "
       "time it still suffers from delayed notification.",
       "With more drones ConCov pulls ahead of mTSP-ConB.")
def concov_beats_mtsp_conb(t: PairedTables, s: Settings) -> Verdict:
    """"as N_m is increased ConCov significantly outperforms mTSP-Con": read where the paper
    observes it, P_s against N_m (Fig. 3's t_d), at every r_c: ConCov's P_s minus mTSP-ConB's
    at the largest team (22) lies above 0, and it grows from mTSP-ConB's smallest own team (8
    drones, the first above N_r) to 22 (paired change above 0)."""
    v = Verdict()
    first, last, td = HYBRID_SMALL_TEAMS[0], DRONES[-1], s.td_fig3
    for rc in RANGES:
        d = {n: _stat(t, "P_s", "concov", n, rc, td)
             - _stat(t, "P_s", "mtsp-conb", n, rc, td) for n in (first, last)}
        e, growth = d[last].estimate(), (d[last] - d[first]).estimate()
        v.test(e.above(), f"{_rc(rc)}: ConCov − mTSP-ConB in P_s({td:g} s) at "
                          f"N_m = {last}: {e}")
        v.test(growth.above(), f"{_rc(rc)}: its change from N_m = {first} "
                               f"({d[first].estimate()}): {growth}")
    return v


@claim("Figs. 2–3", "4.2. Performance comparison",
       "Due to the equal weight given to the search and connectivity components of ConCov, "
       "the drones can simultaneously spread out and stay connected.",
       "ConCov keeps more drones connected than CovB and covers more than ConB.")
def concov_spreads_and_connects(t: PairedTables, s: Settings) -> Verdict:
    """ConCov weighs CovB's search and ConB's connectivity equally, so each half is held
    against the component without it. At t_d = 4000 s and every r_c, averaged over team sizes
    (paired): "stay connected", ConCov's mean fraction of drones connected to the BS minus
    CovB's lies above 0; "spread out", its P_d minus ConB's lies above 0."""
    v = Verdict()
    _gaps(v, t, "connected", ["concov"], ["covb"], RANGES, TD_LONG, _above())
    _gaps(v, t, "P_d", ["concov"], ["conb"], RANGES, TD_LONG, _above())
    return v


def _dominated(t: PairedTables, planners: tuple[str, str]) -> list[tuple[int, float]]:
    """The grid points (N_m, r_c) where detection dominates the mission times of both
    ``planners``: the search share of each (Fig. 4b, t_d = 4000 s) lies above one half."""
    return [(n, rc) for rc in RANGES for n in _sizes(*planners)
            if all(_stat(t, "search_share", p, n, rc, TD_LONG).estimate().lo > 0.5
                   for p in planners)]


@claim("Figs. 2–3", "4.2. Performance comparison",
       "These results imply that while hybrid schemes utilize the available resources "
       "better than ConB, they might still require more resources than mTSP and CovB, "
       "especially when the detection task dominates the mission times.",
       "Where detection dominates, the hybrids trail mTSP and CovB.",
       mechanism={"sarlink-3": (
       "Where detection dominates, mTSP-ConB succeeds in the same runs as mTSP by Fig. 3's "
       "t_d and no later than CovB: its N_r = 6 tour drones search as mTSP's do and its "
       "other drones cost it no search there.")})
def hybrids_trail_coverage(t: PairedTables, s: Settings) -> Verdict:
    """"when the detection task dominates the mission times": at the grid points (N_m, r_c)
    where the search share of the mission time (Fig. 4b, t_d = 4000 s) of both compared
    planners lies above one half. There, "they might still require more resources than mTSP and
    CovB": for each hybrid against each of mTSP and CovB, the hybrid's P_s at Fig. 3's t_d
    minus the other's, averaged over those points (paired; mTSP-ConB above N_r, where it is a
    hybrid), lies below 0; with no such point, not testable."""
    v = Verdict()
    td = s.td_fig3
    for h in HYBRIDS:
        for c in COVERAGE:
            points = _dominated(t, (h, c))
            what = f"{_label(h)} − {_label(c)} in P_s({td:g} s)"
            if not points:
                v.test(Outcome.NOT_TESTABLE, f"{what}: detection dominates the mission times "
                                             "of both at no grid point")
                continue
            per = {point: _stat(t, "P_s", h, *point, td) - _stat(t, "P_s", c, *point, td)
                   for point in points}
            avg = mean_of(per.values()).estimate()
            v.test(avg.below(), f"{what}, averaged over the {len(points)} points where "
                                f"detection dominates both: {avg}; "
                                f"{_grid_picture(per, _below())}")
    return v
