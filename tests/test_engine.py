"""The engine against cases with a known answer: geometry, relays, budgets, equivalences."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from sarlink import Mission, Scenario, prepare, simulate
from sarlink.engine.codes import Mode
from sarlink.engine.streams import run_streams

BS = (2000.0, 2000.0)


@given(
    distance=st.floats(600, 1900),
    offset=st.floats(0, 450),
    angle=st.floats(0, 2 * math.pi),
)
def test_a_drone_on_a_straight_path_detects_when_geometry_says(
    distance: float, offset: float, angle: float
) -> None:
    """One drone flies straight from the BS; the target lies ``offset`` m beside its path."""
    mission = Mission.build(drones=1, planner="covb", horizon=500.0)
    reach = distance - math.sqrt(500.0**2 - offset**2)  # path length at which it is in range
    steps = reach / 5.0
    assume(abs(steps - round(steps)) > 1e-6)  # not on a step boundary: rounding would decide
    ux, uy = math.cos(angle), math.sin(angle)
    target = (BS[0] + distance * ux - offset * uy, BS[1] + distance * uy + offset * ux)
    assume(0 <= target[0] <= 4000 and 0 <= target[1] <= 4000)
    result = simulate(mission, scenario=Scenario(target=target, headings=np.array([angle])))
    expected = max(0, math.ceil(steps)) * 1.0
    # the path stays 2000 m from the walls for 400 s, so no boundary turn interferes
    assert result.t_detect == (expected if expected <= 500 else None)


@pytest.mark.parametrize("planner", ["covb", "conb", "concov"])
def test_with_single_hop_range_every_detection_is_notified_at_once(planner: str) -> None:
    """r_c >= 2829 m links every point of the area to the BS at the centre."""
    mission = Mission.build(drones=6, planner=planner, rc=2829.0, horizon=2000.0)
    detected = 0
    for run in range(20):
        result = simulate(mission, seed=3, run=run)
        assert result.t_notify == result.t_detect
        assert result.immediate == (result.t_detect is not None)
        detected += result.t_detect is not None
    assert detected >= 10  # the claim is not vacuous


def _line(xs: list[float], target: tuple[float, float]) -> tuple[Mission, Scenario]:
    """Drones hand-placed on the line y = 2000 east of a BS at (0, 2000), flying north."""
    mission = Mission.build(drones=len(xs), planner="covb", bs=(0.0, 2000.0), rc=1000.0,
                            horizon=10.0)
    scenario = Scenario(target=target, positions=np.array([[x, 2000.0] for x in xs]),
                        headings=np.full(len(xs), math.pi / 2))
    return mission, scenario


def test_a_chain_of_drones_relays_to_the_bs_in_the_same_step() -> None:
    mission, scenario = _line([900, 1800, 2700, 3600], target=(3600, 1700))
    result = simulate(mission, scenario=scenario, trajectory=True)
    assert (result.t_detect, result.t_notify, result.immediate, result.detector) == (
        0.0, 0.0, True, 3)
    assert result.trajectory is not None
    assert result.trajectory.knows[0].all()
    assert result.trajectory.bs_route[0].all()


def test_a_broken_chain_does_not_reach_the_bs() -> None:
    # the gap between 1800 and 2850 m exceeds r_c = 1000 m; the drones fly north in parallel
    mission, scenario = _line([900, 1800, 2850, 3600], target=(3600, 1700))
    result = simulate(mission, scenario=scenario, trajectory=True)
    assert result.t_detect == 0.0
    assert result.t_notify is None and not result.immediate
    assert result.trajectory is not None
    # knowledge floods the detector's side of the gap only
    assert result.trajectory.knows[0].tolist() == [False, False, True, True]
    assert result.trajectory.bs_route[0].tolist() == [True, True, False, False]
    # the target links to the last drone, which has no route: not reachable
    assert result.t_reachable() == 0.0


def test_the_target_is_reachable_through_the_chain() -> None:
    mission, scenario = _line([900, 1800, 2700, 3600], target=(3600, 1700))
    assert simulate(mission, scenario=scenario).t_reachable() == 10.0


def test_drones_spend_their_budget_and_land_at_the_bs() -> None:
    mission = Mission.build(drones=5, planner="covb", flight_time=600.0, horizon=800.0)
    result = simulate(mission, seed=1, trajectory=True)
    traj = result.trajectory
    assert traj is not None
    landed = traj.mode == Mode.LANDED
    assert landed[-1].all()
    np.testing.assert_array_equal(traj.positions[-1], np.tile(BS, (5, 1)))
    # a drone lands once it has flown home, within the budget, and not long before it
    first = landed.argmax(axis=0) * mission.timing.dt
    assert (first <= 600.0).all() and (first >= 600.0 - 3 * mission.timing.dt).all()
    # landed drones stay put
    assert all((traj.positions[landed[:, i], i] == BS).all() for i in range(5))


@pytest.mark.parametrize(("alpha", "same_as"), [(1.0, "covb"), (0.0, "conb")])
def test_concov_at_the_ends_of_alpha_is_covb_or_conb(alpha: float, same_as: str) -> None:
    for run in range(3):
        a = simulate(Mission.build(drones=10, planner="concov", alpha=alpha, rc=500.0,
                                   horizon=1500.0), seed=5, run=run, trajectory=True)
        b = simulate(Mission.build(drones=10, planner=same_as, rc=500.0, horizon=1500.0),
                     seed=5, run=run, trajectory=True)
        assert a.trajectory is not None and b.trajectory is not None
        np.testing.assert_array_equal(a.trajectory.positions, b.trajectory.positions)
        assert (a.t_detect, a.t_notify) == (b.t_detect, b.t_notify)


def test_concov_in_between_differs_from_both() -> None:
    runs = {p: simulate(Mission.build(drones=10, planner=p, alpha=0.5, rc=500.0,
                                      horizon=1000.0), seed=5, trajectory=True)
            for p in ("covb", "conb", "concov")}
    pos = {p: r.trajectory.positions for p, r in runs.items() if r.trajectory is not None}
    assert not np.array_equal(pos["concov"], pos["covb"])
    assert not np.array_equal(pos["concov"], pos["conb"])


def test_conb_keeps_more_drones_connected_than_covb() -> None:
    """ConB's purpose (Section 3.2): drones stay attached to the BS's part of the network."""
    def connected(planner: str) -> float:
        mission = Mission.build(drones=10, planner=planner, rc=500.0, horizon=2000.0)
        return float(np.mean([simulate(mission, seed=2, run=k).connected_fraction()
                              for k in range(10)]))

    assert connected("conb") > connected("covb") + 0.2


@pytest.mark.parametrize("planner", ["covb", "conb", "mtsp-conb"])
def test_a_run_stopped_at_an_event_is_the_full_run_up_to_it(planner: str) -> None:
    """``stop`` ends a run early without changing anything that happened before the stop
    (under sarlink-2, whose eight runs stop early often enough)."""
    full_mission = Mission.build(reading="sarlink-2", drones=6, planner=planner, rc=1000.0,
                                 horizon=3000.0)
    stopped = 0
    for run in range(8):
        full = simulate(full_mission, seed=5, run=run, trajectory=True)
        for stop, at in (("detected", full.t_detect), ("notified", full.t_notify)):
            early = simulate(full_mission.replace(stop=stop), seed=5, run=run, trajectory=True)
            assert early.t_detect == full.t_detect
            assert early.t_notify in ((full.t_notify,) if stop == "notified" or
                                      full.t_notify == full.t_detect else (None,))
            assert early.immediate == (full.immediate and early.t_notify is not None)
            assert early.trajectory is not None and full.trajectory is not None
            steps = len(early.trajectory.t)
            assert steps == (len(full.trajectory.t) if at is None else int(at) + 1)
            np.testing.assert_array_equal(early.trajectory.positions,
                                          full.trajectory.positions[:steps])
            recorded = early.checkpoints <= (3000.0 if at is None else at)
            np.testing.assert_array_equal(early.reach_cum[recorded], full.reach_cum[recorded])
            assert np.isnan(early.reach_cum[~recorded]).all()
            assert np.isnan(early.connected_cum[~recorded]).all()
            for snapshot in ("depth", "farthest"):  # the BS's network, taken until the stop
                np.testing.assert_array_equal(getattr(early, snapshot)[recorded],
                                              getattr(full, snapshot)[recorded])
                assert np.isnan(getattr(early, snapshot)[~recorded]).all()
            stopped += at is not None and at < 3000.0
    assert stopped >= 8  # most runs did stop early: the claim is not vacuous


@pytest.mark.parametrize(("planner", "extra", "target"), [
    ("mtsp", {}, None),
    ("covb", {"horizon": 4500.0}, None),
    # beside the BS, where the landed team keeps looking and, after a while, sees it
    ("mtsp", {"p_miss": 0.9999, "look": "per-period", "horizon": 20000.0},
     (BS[0] + 100.0, BS[1])),
])
def test_a_run_whose_team_has_landed_skips_to_the_horizon_with_the_same_records(
        planner: str, extra: dict[str, object], target: tuple[float, float] | None) -> None:
    """Once every drone has landed (and none still looks for the target) nothing changes
    any more, and the engine jumps to the horizon; a recorded run never jumps, so the two
    must agree on every event and record."""
    mission = Mission.build(drones=8, planner=planner, rc=1000.0, iterations=200, **extra)
    prepared = prepare(mission)
    settled = late = 0
    for run in range(6):
        scenario = None if target is None else Scenario(target=target)
        fast = prepared.run(3, run, scenario=scenario)
        full = prepared.run(3, run, scenario=scenario, trajectory=True)
        assert (fast.t_detect, fast.t_notify, fast.immediate) == (
            full.t_detect, full.t_notify, full.immediate)
        np.testing.assert_array_equal(fast.reach_cum, full.reach_cum)
        np.testing.assert_array_equal(fast.connected_cum, full.connected_cum)
        np.testing.assert_array_equal(fast.depth, full.depth)  # the landed team's network
        np.testing.assert_array_equal(fast.farthest, full.farthest)  # repeats to the horizon
        assert full.trajectory is not None
        landed = (full.trajectory.mode == Mode.LANDED).all(axis=1)
        settled += bool(landed[-2])
        late += full.t_detect is not None and bool(landed[int(full.t_detect) - 1])
    assert settled == 6  # every run landed before the horizon: the jump was taken
    assert target is None or late >= 3  # the landed team did see the target


PURPOSES = ("scenario", "turn", "shadow", "look", "takeoff", "plan", "rule")


@given(seed=st.integers(0, 2**63), run=st.integers(0, 10**6))
def test_each_stream_is_its_child_of_the_run_s_seed_sequence(seed: int, run: int) -> None:
    """A run's streams are numpy's own ``spawn`` children of ``SeedSequence(seed, (run,))``,
    in the order the purposes were added, whichever of them a run makes and in what order."""
    children = np.random.SeedSequence(seed, spawn_key=(run,)).spawn(len(PURPOSES))
    streams = run_streams(seed, run)
    for purpose, child in reversed(list(zip(PURPOSES, children, strict=True))):
        expected = np.random.Generator(np.random.PCG64(child)).integers(2**63, size=4)
        np.testing.assert_array_equal(getattr(streams, purpose).integers(2**63, size=4),
                                      expected)
