"""A target that moves (issue 44, docs/model.md, Target motion): the seam, the walk against
the reference and its invariants, and a still target bit for bit what it was."""

from __future__ import annotations

import hashlib
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numba import njit

from naive import simulate_naive
from sarlink import ConfigError, Mission, simulate
from sarlink.config import mission_hash
from sarlink.engine.area import contains, edge_array
from sarlink.engine.target_motion import (
    TargetMotion,
    register_target_motion,
    target_motion_names,
    walk,
)
from sarlink.registry import KINDS
from sarlink.testing import check_target_motion

STILL_BEFORE = [  # covb, 4 drones, 300 s, seed 3: main at 36d00d6, before targets moved
    (None, None, [0.0, 0.0, 0.0, 32.0, 82.0, 83.0, 83.0],
     "3ee8ed96d10f358896b3769d80260fe38da91efee95bb456f76ff1f4e75dd027"),
    (52.0, 52.0, [0.0, 50.0, 100.0, 150.0, 200.0, 201.0, 201.0],
     "a659cdb952a48eb8546d556e5f75d3037e6bbd05818c6bfbc33e6a699dc9cac5"),
    (263.0, None, [0.0, 0.0, 0.0, 5.0, 55.0, 56.0, 56.0],
     "5e6a986f63b21c46961cf2b803bb0fd4ef5b1feafb1c52a750c93476338c372e"),
]


def test_a_still_target_flies_the_runs_of_before_bit_for_bit() -> None:
    """``still`` (with a delay and walk settings, which a still target ignores) gives the runs
    stored from main before the seam, trajectory and all, and hashes as the paper's mission."""
    plain = Mission.build(planner="covb", drones=4, horizon=300.0)
    still = plain.replace(motion="still", delay=600.0, walk_speed=3.0)
    for run, (t_detect, t_notify, reach, positions) in enumerate(STILL_BEFORE):
        got = simulate(still, seed=3, run=run, trajectory=True)
        assert got.trajectory is not None and got.trajectory.target is None
        assert (got.t_detect, got.t_notify, got.reach_cum.tolist()) == (t_detect, t_notify, reach)
        assert hashlib.sha256(got.trajectory.positions.tobytes()).hexdigest() == positions
    assert mission_hash(plain.replace(motion="still", delay=0.0)) == mission_hash(plain)


WALK = {"planner": "covb", "drones": 4, "rc": 1000.0, "horizon": 600.0, "motion": "walk",
        "delay": 120.0, "walk_speed": 2.5, "walk_turn": 1.0, "walk_mobile": 500.0}
WALK_RUNS = 12


@pytest.fixture(scope="module", params=[10.0, 0.0], ids=["step-10s", "every-step"])
def walked(request: pytest.FixtureRequest) -> list[tuple[object, object]]:
    """Runs of a walking target (fast enough to reach the square's walls) flown by the kernel
    and by the reference, moving every 10 s (the default time step) and at every time step:
    one kernel compiled for the file."""
    mission = Mission.build(**WALK, motion_step=request.param)  # type: ignore[arg-type]
    return [(simulate(mission, seed=2024, run=k, trajectory=True),
             simulate_naive(mission, 2024, k, record=True)) for k in range(WALK_RUNS)]


def test_the_kernel_walks_the_target_as_the_reference_does(walked: list) -> None:
    """The target's track of every run, step by step, and the runs' events, against the
    reference's walk written from the model's text (tests/naive.py)."""
    same = 0
    stopped = 0
    for fast, slow in walked:
        track = fast.trajectory.target[:, 0, :]
        np.testing.assert_allclose(track, np.array(slow.target_track), rtol=0.0, atol=1e-6)
        same += (fast.t_detect, fast.t_notify) == (slow.t_detect, slow.t_notify)
        stopped += bool((track[-1] == track[-11]).all())  # no move in its last 10 s
    assert same >= 0.75 * WALK_RUNS
    assert 0 < stopped < WALK_RUNS  # some stop within the run, others walk on


def test_the_target_moves_once_a_step_of_its_own_and_stands_in_between() -> None:
    """With ``target.motion_step = 10 s`` (dt = 1 s) and a delay of 125 s, the track changes
    only where 10 s since the sighting have passed: between the records of steps k and k + 1
    when 125 + k + 1 is a multiple of 10; a step of 0 and a step of dt are the same runs."""
    mission = Mission.build(**{**WALK, "delay": 125.0, "walk_mobile": 1e6})  # type: ignore
    track = simulate(mission, seed=2024, run=1, trajectory=True).trajectory.target[:, 0, :]
    moved = np.flatnonzero((np.diff(track, axis=0) != 0).any(axis=1))
    assert moved.size > 0 and ((125 + moved + 1) % 10 == 0).all()
    assert moved.size == len([k for k in range(track.shape[0] - 1) if (125 + k + 1) % 10 == 0])
    every, dt = (simulate(mission.replace(motion_step=step), seed=2024, run=1, trajectory=True)
                 for step in (0.0, 1.0))
    assert np.array_equal(every.trajectory.target, dt.trajectory.target)
    assert (every.t_detect, every.t_notify) == (dt.t_detect, dt.t_notify)


def test_detection_uses_the_target_where_it_is_at_that_step(walked: list) -> None:
    """With perfect sensing, the first detection is at the first step at which a drone is
    within r of the target's position at that step (not where it was last seen)."""
    r = Mission.build(**WALK).sensing.r  # type: ignore[arg-type]
    found = 0
    for fast, _ in walked:
        traj = fast.trajectory
        gap = np.hypot(*(traj.positions - traj.target).transpose(2, 0, 1))  # (steps, N)
        within = np.flatnonzero((gap <= r).any(axis=1))
        if fast.t_detect is None:
            assert within.size == 0
            continue
        found += 1
        assert traj.t[within[0]] == fast.t_detect
        assert gap[within[0], fast.detector] <= r
    assert found > 0


HOLED = edge_array([np.array([[0.0, 0.0], [900.0, 0.0], [900.0, 900.0], [0.0, 900.0],
                              [0.0, 0.0]]),
                    np.array([[300.0, 300.0], [300.0, 600.0], [600.0, 600.0], [600.0, 300.0],
                              [300.0, 300.0]])])


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), speed=st.floats(0.1, 60.0),
       turn=st.floats(0.0, 6.0), dt=st.sampled_from([0.5, 1.0, 5.0]),
       holes=st.booleans(), x=st.floats(1.0, 899.0), y=st.floats(1.0, 299.0))
def test_a_walking_target_never_leaves_the_area_or_enters_a_hole(
        seed: int, speed: float, turn: float, dt: float, holes: bool, x: float,
        y: float) -> None:
    """The compiled hooks, from a point below the hole, at any speed up to a step far longer
    than the hole is wide: every position inside the area and out of the hole."""
    edges = HOLED if holes else np.empty((0, 4))
    tp = np.array([speed, turn, 1e9, 0.0])
    xy, state = np.array([x, y]), np.zeros(len(walk.STATE))
    rng = np.random.default_rng(seed)
    walk.start(xy, state, tp, rng)
    for k in range(200):
        walk.move(xy, state, k * dt, dt, tp, edges, 900.0, rng)
        assert 0.0 <= xy[0] <= 900.0 and 0.0 <= xy[1] <= 900.0
        assert not holes or contains.py_func(xy[0], xy[1], HOLED), (k, xy)


def test_a_walker_stops_at_its_drawn_time_and_covers_speed_times_it() -> None:
    """Far from the walls, the path's length is the speed times the drawn stop time (the
    last step cut short), and nothing moves after."""
    tp = np.array([1.0, 0.3, 100.0, 0.5])
    xy, state = np.array([5000.0, 5000.0]), np.zeros(2)
    rng = np.random.default_rng(5)
    walk.start(xy, state, tp, rng)
    track = [xy.copy()]
    for k in range(400):
        walk.move(xy, state, k * 1.0, 1.0, tp, np.empty((0, 4)), 1e4, rng)
        track.append(xy.copy())
    length = np.hypot(*np.diff(np.array(track), axis=0).T).sum()
    assert length == pytest.approx(state[1] * 1.0, rel=1e-12)
    assert (np.array(track[math.ceil(state[1]):]) == track[-1]).all()


def test_the_walks_stop_times_are_the_stated_log_normal() -> None:
    """ln T over many targets: mean ln(median), standard deviation the spread (within three
    standard errors)."""
    tp = np.array([1.0, 0.3, 14400.0, 0.8])
    rng = np.random.default_rng(11)
    logs = []
    for _ in range(4000):
        state = np.zeros(2)
        walk.start(np.zeros(2), state, tp, rng)
        logs.append(math.log(state[1]))
    assert abs(np.mean(logs) - math.log(14400.0)) <= 3 * 0.8 / math.sqrt(4000)
    assert abs(np.std(logs) - 0.8) <= 3 * 0.8 / math.sqrt(2 * 4000)


@pytest.mark.parametrize("name", target_motion_names())
def test_every_registered_model_keeps_the_contract(name: str) -> None:
    check_target_motion(name)


def test_a_fast_walker_keeps_the_contract_at_the_walls() -> None:
    check_target_motion("walk", walk_speed=20.0, walk_mobile=1e6)


@njit
def _start(xy: np.ndarray, state: np.ndarray, tp: np.ndarray, rng: np.random.Generator) -> None:
    pass


@njit
def _east(xy: np.ndarray, state: np.ndarray, t: float, dt: float, tp: np.ndarray,
          edges: np.ndarray, size: float, rng: np.random.Generator) -> None:
    xy[0] += 50.0 * dt


@pytest.mark.usefixtures("fresh_registries")
def test_the_contract_catches_a_model_on_land_that_walks_off_it() -> None:
    model = TargetMotion("east-off", _east, _start, on_land=True)
    register_target_motion(model, replace=True)
    with pytest.raises(AssertionError, match="declared on_land but target"):
        check_target_motion("east-off")


def test_the_seam_is_a_plugin_kind_with_its_entry_point_group() -> None:
    assert KINDS["target_motion"].group == "sarlink.target_motions"
    with pytest.raises(ConfigError, match="give both hooks"):
        TargetMotion("half", _east)
    with pytest.raises(ConfigError, match="must take exactly 8"):
        TargetMotion("short", _start, _start)


def test_simulate_json_says_where_a_walking_target_went() -> None:
    """The command line flies the kernel this file compiled (covb, a walking target)."""
    from typer.testing import CliRunner

    from sarlink.cli import app

    args = ["simulate", "--planner", "covb", "--drones", "4", "--td", "600",
            "--target-motion", "walk", "--delay", "120", "--walk-speed", "2.5", "--json"]
    out = CliRunner().invoke(app, args)
    assert out.exit_code == 0, out.output
    got = json.loads(out.stdout)
    assert (got["target_motion"], got["target_delay"]) == ("walk", 120.0)
    assert all(0.0 <= v <= 4000.0 for v in got["target_at_end"])
    assert got["target_at_end"] != got["target"]  # 2.5 m/s for 720 s unless it stopped at once


def test_replays_and_plots_carry_the_targets_track(walked: list, tmp_path) -> None:
    """The replay page's frames hold the track (float32) and decode to it; ``--plot``'s
    figure draws it."""
    import matplotlib

    matplotlib.use("Agg")
    from sarlink.playback import replay
    from sarlink.playback.encoding import decode, encode
    from sarlink.plots.run import plot_run

    result = walked[0][0]
    traj = result.trajectory
    back = decode(encode(traj)).target
    assert back is not None and back.shape == traj.target.shape
    np.testing.assert_allclose(back, traj.target, rtol=1e-6, atol=1e-3)
    mission = Mission.build(**WALK)  # type: ignore[arg-type]
    page = replay(result, mission).write(tmp_path / "walk.html").read_text()
    assert '"target":"' in page  # the encoded track, not the empty string of a still target
    ax = plot_run(result, mission)
    labels = ax.get_legend_handles_labels()[1]
    assert "the target's track (walk)" in labels and "target last seen" in labels
