"""The claims of Fig. 6: target reachability."""

from __future__ import annotations

from sarlink.paper.claim import Settings, claim
from sarlink.paper.evidence import Verdict, worst
from sarlink.paper.experiments import DRONES, RANGES, TD_LONG
from sarlink.paper.findings.helpers import LOW, _above, _below, _gaps, _label, _others, _rc, _stat
from sarlink.paper.paired import PairedTables
from sarlink.planners import PAPER_PLANNERS


@claim("Fig. 6", "4.2. Performance comparison",
       "Observe from Figure 6 that for small r_c all schemes have low target reachability as "
       "expected.", "At small r_c every scheme has low target reachability.")
def low_reachability_small_range(t: PairedTables, s: Settings) -> Verdict:
    """"for small r_c all schemes have low target reachability": at t_d = 4000 s and the
    smallest r_c (500 m): every planner's target reachability lies below a quarter of t_d at
    every team size (holds if every interval does, contradicted if one lies above)."""
    v = Verdict()
    rc = RANGES[0]
    low = _below(LOW)
    for p in PAPER_PLANNERS:
        e = {n: _stat(t, "reachability", p, n, rc, TD_LONG).estimate() for n in DRONES}
        highest = max(e, key=lambda n: e[n].value)
        v.test(worst(low(x) for x in e.values()),
               f"{_rc(rc)}, {_label(p)}: highest reachability {e[highest]} at N_m = {highest}",
               low.levels, worst(low.rule(x, True) for x in e.values()))
    return v


@claim("Fig. 6", "4.2. Performance comparison",
       "The ConB scheme outperforms the others in this case.",
       "At small r_c ConB has the best target reachability.")
def conb_reachability_best(t: PairedTables, s: Settings) -> Verdict:
    """"The ConB scheme outperforms the others in this case": at t_d = 4000 s and r_c = 500 m:
    ConB's target reachability minus each other planner's, averaged over team sizes (paired;
    mTSP-ConB above N_r, where it is not mTSP), lies above 0."""
    v = Verdict()
    _gaps(v, t, "reachability", ["conb"], _others("conb"), RANGES[:1], TD_LONG, _above())
    return v


@claim("Fig. 6", "4.2. Performance comparison",
       "As r_c is increased, we observe that ConCov and CovB's performance starts exceeding "
       "that of ConB as N_m increases, since ConB still suffers from lower detection "
       "probability.", "As r_c grows, CovB and ConCov overtake ConB as N_m grows.")
def coverage_overtakes_conb(t: PairedTables, s: Settings) -> Verdict:
    """"As r_c is increased": at t_d = 4000 s and each larger r_c (1000 and 2000 m), for CovB
    and for ConCov, "starts exceeding that of ConB as N_m increases": its target reachability
    minus ConB's lies above 0 at the largest team (22), and this difference grows from the
    smallest team (2) to the largest (paired change above 0)."""
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
    """"The mTSP scheme is the worst of all schemes even with higher r_c": at t_d = 4000 s and
    every r_c, averaged over team sizes (paired): mTSP's target reachability minus each other
    planner's lies below 0 (mTSP-ConB compared above N_r)."""
    v = Verdict()
    _gaps(v, t, "reachability", ["mtsp"], _others("mtsp"), RANGES, TD_LONG, _below())
    return v
