"""The claims of Fig. 7: imperfect sensing (7a) and shadowing (7b)."""

from __future__ import annotations

import itertools

from sarlink.paper.claim import Settings, claim
from sarlink.paper.evidence import Outcome, Verdict
from sarlink.paper.experiments import DRONES, P_MISS, TD_LONG, TD_SHORT
from sarlink.paper.findings.helpers import (
    NEAR_ONE,
    SMALL,
    SMALL_MISS,
    _averaged,
    _label,
    _rc,
    _sizes,
    _stat,
)
from sarlink.paper.paired import PairedTables, mean_of
from sarlink.planners import PAPER_PLANNERS


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
