"""The claims of the conclusions."""

from __future__ import annotations

from sarlink.paper.claim import Settings, claim
from sarlink.paper.evidence import Verdict
from sarlink.paper.experiments import DRONES, FIG5_RANGES, RANGES, TD_LONG, TD_SHORT
from sarlink.paper.findings.helpers import (
    CONNECTIVITY,
    COVERAGE,
    _above,
    _averaged,
    _below,
    _gaps,
    _spread,
)
from sarlink.paper.paired import PairedTables


@claim("Conclusions", "5. Conclusions",
       "Our results indicate that the impact of connectivity on the mission success "
       "probability and total mission times is most evident when communication resources "
       "(i.e. range and spatial density) are highly stringent.",
       "The planners differ most in P_s and mission time at small r_c and few drones.")
def stringent_resources_matter_most(t: PairedTables, s: Settings) -> Verdict:
    """"the impact of connectivity on the mission success probability and total mission times
    is most evident when communication resources (i.e. range and spatial density) are highly
    stringent", paired: the spread of the planners' P_s at Fig. 3's t_d (the highest minus the
    lowest, picked by value), averaged over team sizes, at r_c = 500 m minus at 2000 m lies
    above 0; and the spread of their mean mission times at t_d = 4000 s (over the runs the two
    picked both notify) at (500 m, N_m = 2) minus at (2000 m, N_m = 22) lies above 0."""
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
       "mTSP and CovB, but detect later.",
       mechanism={"sarlink-3": (
       "At r_c = 2000 m ConCov's drones are in reach of the BS almost everywhere, where its "
       "connectivity term keeps the heading, so it searches as CovB does and detects no "
       "later."),
       "sarlink-4": (
       "At r_c = 2000 m the BS's disc covers most of the area, so connectivity slows no drone: "
       "ConB's and ConCov's drones turn at the disc's rim and sweep its outer ring, and with small "
       "teams they find more by 1000 s than CovB's, which fly on to the area's edge.")})
def connectivity_aware_tradeoff(t: PairedTables, s: Settings) -> Verdict:
    """For ConB and ConCov against mTSP and CovB, averaged over team sizes (paired): at t_d =
    4000 s and Fig. 5's ranges, the immediate notification ("simultaneous detection and
    notification") and the target reachability ("good target reachability") differences lie
    above 0; "it suffers from longer search times": at t_d = 1000 s and every r_c, the P_d
    difference lies below 0."""
    v = Verdict()
    _gaps(v, t, "immediate", CONNECTIVITY, COVERAGE, FIG5_RANGES, TD_LONG, _above())
    _gaps(v, t, "reachability", CONNECTIVITY, COVERAGE, FIG5_RANGES, TD_LONG, _above())
    _gaps(v, t, "P_d", CONNECTIVITY, COVERAGE, RANGES, TD_SHORT, _below())
    return v


@claim("Conclusions", "5. Conclusions",
       "On the other hand, mTSP schemes can find the targets fast, but require more "
       "tolerance to notification delays.",
       "mTSP and mTSP-ConB detect sooner than ConB and ConCov but notify later after "
       "detection.",
       mechanism={"sarlink-4": (
       "At r_c = 500 m ConCov notifies at detection hardly more often than mTSP and mTSP-ConB, and "
       "its other finds wait for a drone to come back within reach; mTSP's drones land at their "
       "tours' ends sooner, and mTSP-ConB's six tours end after 1000–1300 s, a wait ConCov's beats "
       "only from 16 drones.")})
def mtsp_fast_but_delayed(t: PairedTables, s: Settings) -> Verdict:
    """For mTSP and mTSP-ConB (above N_r, where it is not mTSP) against ConB and ConCov,
    averaged over team sizes (paired): "can find the targets fast", at t_d = 1000 s and every
    r_c the P_d difference lies above 0; "require more tolerance to notification delays", at
    t_d = 4000 s and Fig. 5's ranges the mean notification delay difference, over the runs both
    notify, lies above 0."""
    v = Verdict()
    _gaps(v, t, "P_d", ("mtsp", "mtsp-conb"), CONNECTIVITY, RANGES, TD_SHORT, _above())
    _gaps(v, t, "delay", ("mtsp", "mtsp-conb"), CONNECTIVITY, FIG5_RANGES, TD_LONG, _above())
    return v
