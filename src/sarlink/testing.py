"""The contract every planner passes, for sarlink's tests and a plug-in author's own.

``check_planner("my-planner")`` flies a registered planner on a few teams and runs and raises
an ``AssertionError`` naming what broke: drones leave the area, the BS is notified before the
target is detected, the same ``(seed, run)`` flies differently, or the planner's runs cannot
be replayed in the browser page. In a plug-in's test suite::

    from sarlink.testing import check_planner

    def test_my_planner_keeps_the_contract():
        check_planner("my-planner")
"""

from __future__ import annotations

import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from sarlink.config import Mission
from sarlink.planners import get_planner
from sarlink.playback import replay
from sarlink.result import RunResult
from sarlink.simulation import simulate

__all__ = ["check_planner", "check_run"]


def check_run(result: RunResult, mission: Mission) -> None:
    """The invariants of one run flown with its trajectory."""
    name = mission.team.planner
    traj = result.trajectory
    assert traj is not None, "check_run needs a run simulated with trajectory=True"
    size = mission.area.size
    pos = traj.positions
    assert np.isfinite(pos).all(), f"{name}: a drone position is not finite"
    outside = (pos < -1e-9) | (pos > size + 1e-9)
    if outside.any():
        step, drone, _ = np.argwhere(outside)[0]
        raise AssertionError(f"{name}: drone {drone} leaves the area [0, {size:g}]² at "
                             f"t = {traj.t[step]:g} s: {tuple(pos[step, drone])}")
    if result.t_notify is not None:
        assert result.t_detect is not None and result.t_notify >= result.t_detect, (
            f"{name}: the BS is notified at {result.t_notify} s, before any detection "
            f"({result.t_detect})")


def _same(a: RunResult, b: RunResult) -> bool:
    ra, rb = a.row(), b.row()
    rows = ra.keys() == rb.keys() and all(
        np.array_equal(np.asarray(ra[k]), np.asarray(rb[k]), equal_nan=True) for k in ra)
    assert a.trajectory is not None and b.trajectory is not None
    return rows and np.array_equal(a.trajectory.positions, b.trajectory.positions)


def check_planner(name: str, *, drones: Sequence[int] = (1, 4, 10), runs: int = 2,
                  horizon: float = 1500.0, seed: int = 7, **params: Any) -> None:
    """Fly the registered planner ``name`` and check the contract (module docstring).

    ``params`` are further flat mission parameters (``rc=500.0``, ``on_detect="report"``).
    """
    planner = get_planner(name)
    for n in drones:
        mission = Mission.build(planner=name, drones=n, horizon=horizon, **params)
        steering = planner.steering(mission)
        assert len(steering.routes) <= n, f"{name}: {len(steering.routes)} routes for {n} drones"
        for run in range(runs):
            result = simulate(mission, seed=seed, run=run, trajectory=True)
            check_run(result, mission)
            again = simulate(mission, seed=seed, run=run, trajectory=True)
            assert _same(result, again), (f"{name}: run {run} of seed {seed} with {n} drones "
                                          "differs when flown again")
    with tempfile.TemporaryDirectory() as tmp:
        page = replay(result, mission).write(Path(tmp) / "replay.html").read_text()
    assert planner.label in page, f"{name}: the replay page does not name {planner.label!r}"
