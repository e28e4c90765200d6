"""The mTSP planners in flight: the paper's claims about them and the per-pass look model."""

from __future__ import annotations

import math

import numpy as np
import pytest

from sarlink import Mission, simulate
from sarlink.simulation import prepare


def test_two_drones_find_and_report_every_target_within_4000_s() -> None:
    """Section 4.2: with t_d = 4000 s, mTSP succeeds with probability 1 even with 2 drones."""
    mission = Mission.build(planner="mtsp", drones=2, rc=500.0)
    prepared = prepare(mission)
    results = [prepared.run(11, k) for k in range(150)]
    assert all(r.detected(4000.0) for r in results)
    assert all(r.notified(4000.0) for r in results)  # at the latest when the drones come home


def _passes(mission: Mission, seed: int, run: int) -> int:
    """How many times some drone's sensing range newly covers the target by the horizon."""
    result = simulate(mission, seed=seed, run=run, trajectory=True)
    assert result.trajectory is not None
    d = np.linalg.norm(result.trajectory.positions - np.asarray(result.target), axis=2)
    inside = np.vstack([np.zeros((1, d.shape[1]), bool), d <= mission.sensing.r])
    return int((np.diff(inside.astype(int), axis=0) == 1).sum())


@pytest.mark.parametrize("planner", ["mtsp", "covb"])
def test_per_pass_looks_detect_with_probability_one_minus_p_miss_to_the_passes(
    planner: str,
) -> None:
    """Trajectories do not depend on detection, so a target covered in K passes by t_d is
    detected with probability 1 - p_miss**K. With K = 1 for every target this would be the
    (1 - p_miss) x ideal of a plan without overlap; the paper's mTSP cells are r wide while
    the sensing disc has radius r, so neighbouring legs of a tour both pass most targets."""
    p_miss, runs = 0.6, 400
    ideal = Mission.build(planner=planner, drones=10, rc=500.0, horizon=1000.0)
    predicted = np.mean([1 - p_miss ** _passes(ideal, 3, k) for k in range(runs)])
    imperfect = prepare(ideal.replace(p_miss=p_miss))
    observed = np.mean([imperfect.run(3, k).t_detect is not None for k in range(runs)])
    tolerance = 4 * math.sqrt(predicted * (1 - predicted) / runs)
    assert abs(observed - predicted) <= tolerance
    # and the overlap is real: far more detections than (1 - p_miss) x ideal
    assert observed > (1 - p_miss) + tolerance
