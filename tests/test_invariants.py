"""Invariants of every run, over random missions (hypothesis)."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from sarlink import Mission, RunResult, simulate
from sarlink.engine.codes import Mode

missions = st.builds(
    lambda planner, drones, rc, alpha, p_miss, sigma, flight: Mission.build(
        planner=planner, drones=drones, rc=rc, alpha=alpha, p_miss=p_miss, sigma=sigma,
        flight_time=flight, horizon=900.0),
    planner=st.sampled_from(["covb", "conb", "concov"]),
    drones=st.integers(1, 14),
    rc=st.sampled_from([500.0, 1000.0, 2000.0]),
    alpha=st.floats(0, 1),
    p_miss=st.sampled_from([0.0, 0.3]),
    sigma=st.sampled_from([0.0, 3.0]),
    flight=st.sampled_from([700.0, 4000.0]),
)
seeds = st.integers(0, 2**32)
runs = st.integers(0, 10_000)


def _run(mission: Mission, seed: int, run: int) -> RunResult:
    return simulate(mission, seed=seed, run=run, trajectory=True)


@given(missions, seeds, runs)
def test_drones_stay_in_the_area_at_constant_speed(mission: Mission, seed: int, run: int) -> None:
    traj = _run(mission, seed, run).trajectory
    assert traj is not None
    size = mission.area.size
    assert (traj.positions >= 0).all() and (traj.positions <= size).all()
    step = np.linalg.norm(np.diff(traj.positions, axis=0), axis=2)
    flying = traj.mode[1:] != Mode.LANDED  # still airborne after the move
    np.testing.assert_allclose(step[flying], mission.team.speed * mission.timing.dt, rtol=1e-9)
    assert (step[~flying] <= mission.team.speed * mission.timing.dt + 1e-9).all()


@given(missions, seeds, runs)
def test_notification_never_precedes_detection(mission: Mission, seed: int, run: int) -> None:
    result = _run(mission, seed, run)
    if result.t_notify is not None:
        assert result.t_detect is not None and result.t_notify >= result.t_detect
    assert result.immediate == (result.t_notify is not None and result.t_notify == result.t_detect)


@given(missions, seeds, runs)
def test_a_drone_that_knows_keeps_knowing(mission: Mission, seed: int, run: int) -> None:
    result = _run(mission, seed, run)
    knows = result.trajectory.knows if result.trajectory is not None else None
    assert knows is not None
    assert (np.diff(knows.astype(int), axis=0) >= 0).all()
    first = np.flatnonzero(knows.any(axis=1))
    assert (result.t_detect is None) == (first.size == 0)
    if first.size:
        assert first[0] * mission.timing.dt == result.t_detect


@given(missions, seeds, runs)
def test_cumulative_records_grow_no_faster_than_time(
    mission: Mission, seed: int, run: int
) -> None:
    result = _run(mission, seed, run)
    for cum in (result.reach_cum, result.connected_cum):
        growth = np.diff(cum)
        assert (growth >= -1e-9).all()
        assert (growth <= np.diff(result.checkpoints) + 1e-9).all()
    assert 0 <= result.connected_fraction() <= 1


@given(missions, seeds, runs)
def test_same_seed_and_run_give_identical_results(mission: Mission, seed: int, run: int) -> None:
    a, b = _run(mission, seed, run), _run(mission, seed, run)
    assert a.row() == b.row()
    assert a.trajectory is not None and b.trajectory is not None
    np.testing.assert_array_equal(a.trajectory.positions, b.trajectory.positions)


@given(missions, seeds, runs)
def test_different_runs_differ(mission: Mission, seed: int, run: int) -> None:
    a, b = _run(mission, seed, run), _run(mission, seed, run + 1)
    assert a.target != b.target
    assert a.trajectory is not None and b.trajectory is not None
    assert not np.array_equal(a.trajectory.positions, b.trajectory.positions)
