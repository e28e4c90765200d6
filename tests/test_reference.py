"""The engine against the slow, obvious reference in ``naive.py``.

Both draw from the same per-run streams, so most runs agree exactly; the ones that do not
diverge where a drone sits at exactly ``r`` or ``r_c`` (radial take-off at 5 m/s puts drones at
whole hundreds of metres) and the two implementations' last bits decide differently. So the
test asks for a high run-by-run agreement and for statistics that agree within binomial error.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest

from naive import network, simulate_naive
from sarlink import Mission, RunResult, simulate
from sarlink.engine.codes import Mode
from sarlink.simulation import prepare

RUNS = 60
CASES = {
    "covb": {"planner": "covb"},
    "conb": {"planner": "conb"},
    "concov": {"planner": "concov"},
    "concov-shadowing": {"planner": "concov", "sigma": 3.0},
    "covb-misses-per-period": {"planner": "covb", "p_miss": 0.4, "look": "per-period"},
    "conb-landing": {"planner": "conb", "flight_time": 700.0},
    # the readings of the paper (docs/model.md, Readings)
    "conb-literal-home": {"planner": "conb", "reading": "literal", "isolated": "home"},
    "concov-sarlink-2-none": {"planner": "concov", "reading": "sarlink-2",
                              "concov_connected": "none"},
    "covb-sarlink-2": {"planner": "covb", "reading": "sarlink-2"},
    "conb-sarlink-2": {"planner": "conb", "reading": "sarlink-2"},
    "covb-printed-random": {"planner": "covb", "covb_direction": "printed",
                            "takeoff": "random"},
    "conb-even-heading": {"planner": "conb", "takeoff": "even", "conb_fallback": "heading"},
    "concov-direct-run-shadowing": {"planner": "concov", "sigma": 3.0, "shadowing": "run",
                                    "reachability": "direct"},
    "conb-period-shadowing": {"planner": "conb", "sigma": 3.0, "shadowing": "period"},
    "conb-check-period": {"planner": "conb", "conb_check": "period"},
    "concov-fallback-heading": {"planner": "concov", "concov_fallback": "heading",
                                "takeoff": "even"},  # radial: resultants cancel
    "conb-limit-exact": {"planner": "conb", "turns": "exact", "takeoff": "even"},
    "conb-landing-relay": {"planner": "conb", "flight_time": 700.0, "parked": "relay"},
    "concov-mean-area-shadowing": {"planner": "concov", "sigma": 3.0,
                                   "shadow_calibration": "mean-area"},
}


def _tolerance(p: float, runs: int) -> float:
    """Three standard errors of a difference of two independent proportions, plus one run."""
    return 3 * math.sqrt(2 * max(p * (1 - p), 0.25 / runs) / runs) + 1 / runs


@pytest.mark.parametrize("case", CASES)
def test_engine_agrees_with_the_reference(case: str) -> None:
    mission = Mission.build(drones=6, rc=1000.0, horizon=1000.0, **CASES[case])
    fast = [simulate(mission, seed=2024, run=k) for k in range(RUNS)]
    slow = [simulate_naive(mission, 2024, k) for k in range(RUNS)]

    pairs = zip(fast, slow, strict=True)
    same = sum((f.t_detect, f.t_notify) == (s.t_detect, s.t_notify) for f, s in pairs)
    assert same >= 0.75 * RUNS

    for td in (250.0, 500.0, 1000.0):
        for event in ("t_detect", "t_notify"):
            p_fast = np.mean([(getattr(f, event) or math.inf) <= td for f in fast])
            p_slow = np.mean([(getattr(s, event) or math.inf) <= td for s in slow])
            assert abs(p_fast - p_slow) <= _tolerance((p_fast + p_slow) / 2, RUNS), (event, td)
    reach_fast = np.array([f.t_reachable() for f in fast])
    reach_slow = np.array([s.t_reachable for s in slow])
    se = math.sqrt((reach_fast.var() + reach_slow.var()) / RUNS)
    assert abs(reach_fast.mean() - reach_slow.mean()) <= 3 * se + 1.0
    conn_fast = np.array([f.connected_fraction() for f in fast])
    conn_slow = np.array([s.connected_time / 1000.0 for s in slow])
    se = math.sqrt((conn_fast.var() + conn_slow.var()) / RUNS)
    assert abs(conn_fast.mean() - conn_slow.mean()) <= 3 * se + 1e-3


NETWORK_RUNS = 30


@pytest.mark.parametrize("case", ["conb", "concov", "conb-landing", "conb-check-period",
                                  "concov-shadowing"])
def test_the_bs_network_agrees_with_the_reference_run_by_run(case: str) -> None:
    """The depth of the BS's component and its farthest connected drone at every checkpoint,
    against the reference's breadth-first search on its own links, in every run whose flight
    the reference flies the same (all but a few: knife edges, above). ``conb-landing``'s
    drones park at the BS from about 700 s: they are hop 0, and the landed team's records
    are carried to the horizon."""
    mission = Mission.build(drones=6, rc=1000.0, horizon=1000.0, **CASES[case])
    same = parked = 0
    for k in range(NETWORK_RUNS):
        fast = simulate(mission, seed=2024, run=k)
        flown = simulate(mission, seed=2024, run=k, trajectory=True).trajectory
        slow = simulate_naive(mission, 2024, k, record=True)
        assert flown is not None
        if not np.allclose(flown.positions, np.array(slow.positions), rtol=0.0, atol=1e-6):
            continue
        same += 1
        assert fast.depth.tolist() == slow.depth
        np.testing.assert_allclose(fast.farthest, slow.farthest, rtol=0.0, atol=1e-6)
        parked += bool((flown.mode[-1] == Mode.LANDED).any())
    assert same >= 0.9 * NETWORK_RUNS
    assert parked == (same if case == "conb-landing" else 0)


@pytest.mark.parametrize("team", [{"planner": "mtsp-conb", "drones": 8, "nr": 4},
                                  {"planner": "mtsp", "drones": 4}],
                         ids=lambda team: team["planner"])
def test_the_bs_network_of_route_teams_is_the_reference_search_on_the_flown_graph(
        team: dict[str, object]) -> None:
    """mTSP's routes end at the BS, where its drones park (the reference flies no routes): the
    records of a run, carried to the horizon once the team has landed, against the
    reference's breadth-first search on the graph the same run records step by step, at
    every checkpoint; some checkpoints have parked and airborne drones at once (the distances
    agree to the last bits, where Numba's ``hypot`` and Python's may round differently)."""
    mission = Mission.build(rc=500.0, iterations=200, **team)  # type: ignore[arg-type]
    prepared = prepare(mission)
    mixed = 0
    for run in range(3):
        fast = prepared.run(3, run)
        flown = prepared.run(3, run, trajectory=True).trajectory
        assert flown is not None
        for c, t in enumerate(fast.checkpoints.tolist()):
            k = round(t / mission.timing.dt)
            landed = flown.mode[k] == Mode.LANDED
            want = network(flown.links[k].tolist(), landed.tolist(),
                           [tuple(xy) for xy in flown.positions[k].tolist()],
                           mission.area.bs_xy)
            assert fast.depth[c] == want[0], t
            assert fast.farthest[c] == pytest.approx(want[1], rel=1e-12), t  # Numba's hypot
            mixed += bool(landed.any() and not landed.all())
    assert mixed > 0



RELAY_RUNS = 16
RELAY_CASES = {
    "covb-reckoned": {"planner": "covb"},
    "covb-reckoned-k-bottleneck": {"planner": "covb", "relay_priority": "k-bottleneck"},
    "covb-most-connected-landing": {"planner": "covb", "relay_priority": "most-connected",
                                    "flight_time": 700.0},
    "mtsp-reckoned": {"planner": "mtsp", "mtsp_plan": "shared", "iterations": 200},
    "mtsp-heard": {"planner": "mtsp", "mtsp_plan": "shared", "iterations": 200,
                   "relay_estimate": "heard"},
}
"""CovB with ``relay_estimate = heard`` is left out: its searchers are last heard within
r_c of the BS (they fly out radially, and nothing brings them back into contact), so the tree
needs no relay and the relays never leave the BS."""


def agreeing_runs(base: Mission, runs: int) -> Iterator[tuple[Mission, RunResult, Any]]:
    """Run ``k < runs`` of ``base`` (with plan seed ``k``, seed 2024) by the engine and by the
    reference, for the runs in which the two fly every drone the same (within 1e-6 m), their
    detection and notification checked equal; the others are knife edges (above)."""
    for k in range(runs):
        mission = base.replace(plan_seed=k)
        fast = simulate(mission, seed=2024, run=k, trajectory=True)
        slow = simulate_naive(mission, 2024, k, record=True,
                              routes=prepare(mission).steering.routes)
        assert fast.trajectory is not None
        if np.allclose(fast.trajectory.positions, np.array(slow.positions), rtol=0.0,
                       atol=1e-6):
            assert (fast.t_detect, fast.t_notify) == (slow.t_detect, slow.t_notify)
            yield mission, fast, slow


@pytest.mark.parametrize("case", RELAY_CASES)
def test_relays_agree_with_the_reference_run_by_run(case: str) -> None:
    """Five searchers and three relays (r_c = 500 m, the square; mTSP with a plan of its own
    per run): the reference flies the relays from the model's text (the BS's hearing, its
    estimate of the searchers, the re-plan every t_s, delivery to the relays it reaches,
    homing), the engine through its relay seam; in all but a few runs (knife edges, above)
    the two fly every drone the same and record the same events, reachability, connectivity
    and BS network. The relays do fly beyond r_c and out of the BS's reach: the estimate and
    the delivery are exercised, not idle."""
    base = Mission.build(drones=8, relays=3, rc=500.0, horizon=1000.0, **RELAY_CASES[case])
    same = 0
    away = cut = False
    for mission, fast, slow in agreeing_runs(base, RELAY_RUNS):
        flown = fast.trajectory
        assert flown is not None
        same += 1
        assert fast.t_reachable() == pytest.approx(slow.t_reachable, abs=1e-9)
        assert fast.connected_fraction() == pytest.approx(slow.connected_time / 1000.0,
                                                          abs=1e-9)
        assert fast.depth.tolist() == slow.depth
        np.testing.assert_allclose(fast.farthest, slow.farthest, rtol=0.0, atol=1e-6)
        relays = flown.mode[:, 5:] == Mode.RELAYING
        assert relays[0].all()
        home = np.hypot(*(flown.positions[:, 5:] - mission.area.bs_xy).transpose(2, 0, 1))
        away |= bool((home[relays] > mission.channel.rc).any())
        cut |= bool((relays & ~flown.bs_route[:, 5:]).any())
    assert same >= 0.9 * RELAY_RUNS
    assert away and cut
