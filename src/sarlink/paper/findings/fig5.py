"""The claims of Fig. 5: immediate notification."""

from __future__ import annotations

from sarlink.paper.claim import Settings, claim
from sarlink.paper.evidence import Verdict
from sarlink.paper.experiments import DRONES, FIG5_RANGES, RANGES, TD_LONG, TD_SHORT
from sarlink.paper.findings.helpers import (
    HIGHLY_LIKELY,
    NEAR_ONE,
    V_M,
    _about,
    _above,
    _averaged,
    _below,
    _change,
    _gaps,
    _label,
    _others,
    _rc,
    _stat,
)
from sarlink.paper.paired import PairedTables
from sarlink.planners import PAPER_PLANNERS


@claim("Fig. 5", "4.2. Performance comparison",
       "For short t_d, since the target is detected only if it is closer to the BS, immediate "
       "notification is highly likely.",
       "At a short t_d every planner's immediate notification is highly likely.")
def short_td_immediate_likely(t: PairedTables, s: Settings) -> Verdict:
    """"For short t_d, since the target is detected only if it is closer to the BS": a target
    is detected by t_d only within V_m t_d + r of the BS, and "closer to the BS" is within
    reach of it, so the short t_d is the time a drone takes to fly one communication range from
    the BS, t_d = r_c / V_m (100 s at 500 m, 200 s at 1000 m). At that t_d and Fig. 5's ranges,
    for every planner, "immediate notification is highly likely": the immediate notification
    probability, averaged over team sizes, lies above 0.75."""
    v = Verdict()
    for rc in FIG5_RANGES:
        td = rc / V_M
        for p in PAPER_PLANNERS:
            per = {n: _stat(t, "immediate", p, n, rc, td) for n in DRONES}
            _averaged(v, per, _above(HIGHLY_LIKELY), f"{_rc(rc)}, {_label(p)}: immediate "
                                                     f"notification at t_d = {td:g} s")
    return v


@claim("Fig. 5", "4.2. Performance comparison",
       "However, as t_d increases, targets that are located farther from the BS can also be "
       "detected and the issue of notification becomes more critical.",
       "Immediate notification falls as t_d grows.")
def notification_more_critical_later(t: PairedTables, s: Settings) -> Verdict:
    """At Fig. 5's ranges, for every planner, "as t_d increases", "the issue of notification
    becomes more critical": the immediate notification probability at t_d = 4000 s minus at
    1000 s, averaged over team sizes (paired), lies below 0."""
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
    """At t_d = 4000 s and Fig. 5's ranges, averaged over team sizes (paired; mTSP-ConB above
    N_r, where it is not mTSP): "much more likely to inform the BS at the time of detection",
    ConB's immediate notification minus each other planner's lies above 0; "suffering from
    lower detection probabilities", its P_d minus each other's lies below 0."""
    v = Verdict()
    _gaps(v, t, "immediate", ["conb"], _others("conb"), FIG5_RANGES, TD_LONG, _above())
    _gaps(v, t, "P_d", ["conb"], _others("conb"), FIG5_RANGES, TD_LONG, _below())
    return v


@claim("Fig. 5", "4.2. Performance comparison", "ConCov follows ConB.",
       "ConCov's immediate notification is second to ConB's.",
       mechanism={"sarlink-4": (
       "At r_c = 500 m ConCov's team flies out of the BS's range at take-off (from 8 drones, no "
       "drone has a route at 150 s in any run), so like CovB it notifies at once only the targets "
       "within r_c + r of the BS, while mTSP-ConB's ConB drones form chains that relay its "
       "detections from farther out.")})
def concov_follows_conb(t: PairedTables, s: Settings) -> Verdict:
    """"ConCov follows ConB": at t_d = 4000 s and Fig. 5's ranges, averaged over team sizes
    (paired; mTSP-ConB above N_r, where it is not mTSP): ConCov's immediate notification minus
    mTSP's, CovB's and mTSP-ConB's lies above 0."""
    v = Verdict()
    _gaps(v, t, "immediate", ["concov"], ("mtsp", "covb", "mtsp-conb"), FIG5_RANGES, TD_LONG,
          _above())
    return v


@claim("Fig. 5", "4.2. Performance comparison",
       "For lower r_c, the immediate notification probability of mTSP is the lowest (around "
       "0.2), indicating that the BS is most likely notified on the return paths of drones.",
       "At the lower r_c mTSP's immediate notification is the lowest, about 0.2.",
       mechanism={"sarlink-4": (
       "mTSP's immediate notification is about 0.2 but not the lowest: CovB's and ConCov's teams "
       "fly out of the BS's range at take-off and notify at once only the targets within r_c + r "
       "of it (about 0.20 from 8 drones), while a large mTSP team leaves the BS together along its "
       "tours and relays its early finds up to 1500 m out (0.30 with 22 drones).")})
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
    _averaged(v, per, _about(0.2), f"{_rc(rc)}: mTSP's immediate notification")
    return v


@claim("Fig. 5", "4.2. Performance comparison",
       "For high r_c the performance of all schemes converges to 1; hence these results are "
       "omitted.", "At high r_c every scheme's immediate notification approaches 1.")
def immediate_near_one_far(t: PairedTables, s: Settings) -> Verdict:
    """"For high r_c the performance of all schemes converges to 1", a limit: at t_d = 4000 s
    and the largest r_c (2000 m), for every planner, the immediate notification at the densest
    team (22 drones, the setting closest to the limit) lies above 0.9, and its value at 2000 m
    minus at 1000 m, averaged over team sizes (paired), lies above 0 (it rises toward 1 with
    r_c; equal in every run is not testable)."""
    v = Verdict()
    far, near = RANGES[-1], RANGES[-2]
    for p in PAPER_PLANNERS:
        e = _stat(t, "immediate", p, DRONES[-1], far, TD_LONG).estimate()
        _above(NEAR_ONE).test(v, e, f"{_rc(far)}, N_m = {DRONES[-1]}, {_label(p)}: immediate "
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
    """"If some notification delay can be tolerated": at t_d = 4000 s and Fig. 5's ranges,
    "mTSP preserves its advantage [...] in terms of mission success": mTSP's P_s minus each
    other planner's, averaged over team sizes (paired; mTSP-ConB above N_r), lies above 0;
    equal in every run (both always succeed) is not testable at this setting."""
    v = Verdict()
    _gaps(v, t, "P_s", ["mtsp"], _others("mtsp"), FIG5_RANGES, TD_LONG, _above())
    return v
