"""Search, then relay (``on_detect = relay``; docs/model.md, Search, then relay): the engine
against the slow reference run by run, the chain's invariants on whole runs, and what must
not take it (the range-free shortcut, the sharing of reporting runs, the stepping env)."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from polygons import areas
from sarlink import Mission, simulate
from sarlink.config import ConfigError
from sarlink.config.region import area_polygon
from sarlink.engine import sharing
from sarlink.engine.codes import Mode
from sarlink.env.episode import stepping_mission
from sarlink.simulation import prepare
from test_reference import agreeing_runs
from test_relays import WALL

CHAIN_RUNS = 16
CHAIN_CASES = {
    "covb": {"planner": "covb"},
    "covb-landing": {"planner": "covb", "flight_time": 900.0},
    "mtsp": {"planner": "mtsp", "mtsp_plan": "shared", "iterations": 200},
}


def chain_points(bs: tuple[float, float], found: tuple[float, float],
                 rc: float) -> list[tuple[float, float]]:
    """The chain's points from the model's text: the fewest that cut the segment from the BS
    to the detection point into hops of at most r_c, evenly spaced (the square: all inside)."""
    count = max(0, math.ceil((math.dist(bs, found) - 1e-9) / rc) - 1)
    return [(bs[0] + j / (count + 1) * (found[0] - bs[0]),
             bs[1] + j / (count + 1) * (found[1] - bs[1])) for j in range(1, count + 1)]


@pytest.mark.parametrize("case", CHAIN_CASES)
def test_the_chain_agrees_with_the_reference_run_by_run(case: str) -> None:
    """Eight drones at r_c = 500 m: the reference forms the chain from the model's text (the
    detector's hold, the points, the share-out per component, the points nearest the BS
    first, homing), the engine through its kernel; in all but a few runs (knife edges,
    tests/test_reference.py) the two fly every drone the same and record the same detection
    and notification. The chain is exercised: drones other than the detector take points."""
    base = Mission.build(drones=8, rc=500.0, horizon=1500.0, on_detect="relay",
                         **CHAIN_CASES[case])
    same = chained = 0
    for _, fast, _ in agreeing_runs(base, CHAIN_RUNS):
        flown = fast.trajectory
        assert flown is not None
        same += 1
        holding = flown.mode == Mode.CHAINING
        if fast.detector is not None:
            holding[:, fast.detector] = False
        chained += bool(holding.any())
    assert same >= 0.9 * CHAIN_RUNS
    assert chained >= CHAIN_RUNS // 4


def test_once_the_chain_holds_its_links_are_within_range_and_the_bs_is_told() -> None:
    """The square, eight drones at r_c = 500 m (the BS at the centre: up to five points): at
    every step at which a drone of the chain stands on each of its points (the model's, from
    the detection point) and the detector holds the detection point, every hop from the BS to
    the detector is within r_c, and the BS has been notified by then. The chain holds in most
    runs with a find."""
    mission = Mission.build(drones=8, rc=500.0, horizon=3000.0, on_detect="relay")
    held = found = 0
    for k in range(12):
        run = simulate(mission, seed=11, run=k, trajectory=True)
        traj = run.trajectory
        assert traj is not None
        if run.t_detect is None or run.immediate:
            continue
        found += 1
        kd = round(run.t_detect / mission.timing.dt)
        spot = tuple(traj.positions[kd, run.detector].tolist())
        points = chain_points(mission.area.bs_xy, spot, mission.channel.rc)
        for step in range(kd + 1, traj.mode.shape[0]):  # the hold starts after its step
            chain = traj.mode[step] == Mode.CHAINING
            where = traj.positions[step]
            if not (chain[run.detector] and np.allclose(where[run.detector], spot)):
                break  # its budget turned it home
            on = [np.flatnonzero(chain & np.all(np.isclose(where, p, rtol=0.0, atol=1e-6),
                                                axis=1)) for p in points]
            if not all(len(o) for o in on):
                continue
            hops = [mission.area.bs_xy, *(tuple(where[o[0]]) for o in on), spot]
            assert all(math.dist(a, b) <= mission.channel.rc + 1e-6
                       for a, b in itertools.pairwise(hops))
            assert run.t_notify is not None and run.t_notify <= step * mission.timing.dt
            held += 1
            break
    assert found >= 4 and held >= found // 2


@pytest.mark.parametrize(("planner", "relays"), [("covb", 0), ("mtsp", 0), ("covb", 1)])
@settings(max_examples=4, deadline=None)
@given(area=st.one_of(st.sampled_from([None, WALL]), areas()), run=st.integers(0, 1000))
def test_the_detector_holds_and_no_drone_leaves_the_area(planner: str, relays: int,
                                                         area: Mission | None,
                                                         run: int) -> None:
    """The square, a wall or a random polygon with holes, a rule or mTSP routes, with or
    without a relay (which joins the chain once it knows): the detector, searching or
    relaying when it finds the target, stays at the detection point as a chain drone until
    its budget turns it home, and never takes a point again; every drone's every leg lies in
    the area and out of its holes; and with a budget shorter than the run every drone that
    joined the chain has landed at the BS (route drones have no budget rule, docs/model.md)."""
    flown = (area or Mission()).replace(
        planner=planner, drones=6, relays=relays, rc=300.0, flight_time=1500.0,
        horizon=1900.0, on_detect="relay", mtsp_plan="shared", iterations=200)
    result = simulate(flown, seed=5, run=run, trajectory=True)
    traj = result.trajectory
    assert traj is not None
    pos = traj.positions
    legs = shapely.linestrings(np.stack([pos[:-1], pos[1:]], axis=2).reshape(-1, 2, 2))
    inside = area_polygon(flown.region, flown.area.size).buffer(1e-6)
    assert shapely.covers(inside, legs).all()
    joined = (traj.mode == Mode.CHAINING).any(axis=0)
    assert (traj.mode[-1, joined] == Mode.LANDED).all()
    if result.t_detect is not None:
        kd = round(result.t_detect / flown.timing.dt)
        i = result.detector
        if traj.mode[kd, i] in (Mode.SEARCHING, Mode.RELAYING):
            after = traj.mode[kd + 1:, i]
            left = np.flatnonzero(after != Mode.CHAINING)
            end = int(left[0]) if left.size else after.shape[0]
            assert np.isin(after[end:], [Mode.RETURNING, Mode.LANDED]).all()
            assert (pos[kd + 1:kd + 1 + end, i] == pos[kd, i]).all()


def test_a_chain_flies_at_its_range_and_is_never_taken_from_another_run() -> None:
    """The chain's points depend on r_c, so a CovB team forming one is not range-free (its
    runs are not scanned at several ranges), and its runs are never taken from the same
    team's runs without it (as a reporting team's may be): :func:`sharing.fly` flies them,
    the same as alone."""
    chain = prepare(Mission.build(drones=6, rc=500.0, horizon=1500.0, on_detect="relay"))
    plain = prepare(chain.mission.replace(on_detect="continue"))
    assert plain.range_free and not chain.range_free
    shared = sharing.fly([plain, chain], [False, False], seed=3, runs=range(6))
    alone = [chain.run(3, k) for k in range(6)]
    assert [(r.t_detect, r.t_notify) for r in shared[1]] == [
        (r.t_detect, r.t_notify) for r in alone]
    assert [(r.t_detect, r.t_notify) for r in shared[1]] != [
        (r.t_detect, r.t_notify) for r in shared[0]]


def test_the_stepping_env_refuses_the_chain_in_one_line() -> None:
    with pytest.raises(ConfigError, match=r"^team.on_detect = 'relay': .*allowed: continue, "
                                          r"report$"):
        stepping_mission(Mission.build(on_detect="relay"))
