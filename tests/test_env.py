"""sarlink.env: PettingZoo's own API and seed tests, the rules' decisions flown through the
environment against ``sarlink simulate`` bit for bit, the observation against a direct
computation, the rewards, and bad input."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from matplotlib.colors import to_rgb
from pettingzoo.test import (
    api_test,
    parallel_api_test,
    parallel_seed_test,
    render_test,
    seed_test,
)
from typer.testing import CliRunner

from sarlink import ConfigError, Mission, simulate
from sarlink.cli import app
from sarlink.env import OWN, BatchEnv, EngineState, Rewards, env, feature_names, parallel_env
from sarlink.planners.rules import conb, covb

SMALL = Mission.build(planner="covb", drones=5, rc=500.0, horizon=300.0)
RULES = {"covb": covb, "conb": conb}
RUNS = [(0, 0), (3, 1), (11, 4)]


def rule_directions(planner: str, s: EngineState) -> tuple[np.ndarray, np.ndarray]:
    """What the planner's own rule decides on the engine's state."""
    n = s.deciding.shape[0]
    vx, vy = np.zeros(n), np.zeros(n)
    rule = RULES[planner]
    ws = covb.prepare(s.params, s.obs) if planner == "covb" else s.ws
    rule.decide(s.k, s.params, s.obs, ws, s.deciding, vx, vy)
    return vx, vy


def same_result(a, b) -> bool:  # type: ignore[no-untyped-def]
    return (a.target == b.target and a.t_detect == b.t_detect and a.t_notify == b.t_notify
            and a.detector == b.detector and a.immediate == b.immediate
            and np.array_equal(a.checkpoints, b.checkpoints)
            and np.array_equal(a.reach_cum, b.reach_cum, equal_nan=True)
            and np.array_equal(a.connected_cum, b.connected_cum, equal_nan=True)
            and all(x is y is None or (x is not None and y is not None and np.array_equal(x, y))
                    for x, y in ((a.sorties, b.sorties), (a.energy, b.energy))))


@pytest.mark.parametrize("actions", ["continuous", "discrete"])
def test_parallel_api(actions: str) -> None:
    parallel_api_test(parallel_env(SMALL, actions=actions), num_cycles=400)


def test_aec_api() -> None:
    api_test(env(SMALL), num_cycles=400)


def test_seeds() -> None:
    seed_test(lambda: env(SMALL), num_cycles=50)
    parallel_seed_test(lambda: parallel_env(SMALL), num_cycles=50)


def test_render_modes() -> None:
    """PettingZoo's own render test: every declared mode, after reset and after steps."""
    render_test(lambda render_mode=None: env(SMALL, render_mode=render_mode))


def _pixel(e, x: float, y: float, image: np.ndarray) -> np.ndarray:  # type: ignore[no-untyped-def]
    """The colour of the image at the point ``(x, y)`` m of the picture's axes."""
    px, py = e._renderer.ax.transData.transform((x, y))
    return image[image.shape[0] - 1 - round(py), round(px)] / 255.0


def test_a_picture_shows_the_target_and_each_drone_where_they_are() -> None:
    """In the rgb_array picture, the pixel at the target's place is the target's red and the
    one at each drone's place (clear of the others) the colour of what the drone knows."""
    e = parallel_env(Mission.build(planner="covb", drones=4, rc=500.0, horizon=2000.0),
                     render_mode="rgb_array")
    e.reset(seed=3)
    for _ in range(60):
        e.step({a: np.array([math.cos(1.6 * int(a[-1])), math.sin(1.6 * int(a[-1]))])
                for a in e.agents})
    image = e.render()
    assert isinstance(image, np.ndarray) and image.dtype == np.uint8 and image.shape[2] == 3
    obs = e.engine_state.obs
    n = 4
    np.testing.assert_allclose(_pixel(e, obs.px[n + 1], obs.py[n + 1], image),
                               to_rgb("tab:red"), atol=0.02)
    xy = np.column_stack([obs.px[: n + 2], obs.py[: n + 2]])
    checked = 0
    for i in range(n):
        clear = np.delete(np.hypot(*(xy - xy[i]).T), i).min() > 150.0
        if clear:
            colour = "gold" if obs.knows[i] else ("tab:blue" if int(obs.routed[0]) >> i & 1
                                                 else "0.45")
            np.testing.assert_allclose(_pixel(e, *xy[i], image), to_rgb(colour), atol=0.02)
            checked += 1
    assert checked >= 2


def test_bad_render_requests_are_one_line() -> None:
    with pytest.raises(ConfigError, match="render_mode 'video' is not one of human, rgb_array"):
        parallel_env(SMALL, render_mode="video")  # type: ignore[arg-type]
    with pytest.raises(ConfigError, match="before reset"):
        parallel_env(SMALL, render_mode="rgb_array").render()


SEAMS = {"motion": "walk", "walk_speed": 2.0, "battery_wh": 60.0, "energy_model": "zeng2019",
         "swap_time": 60.0, "altitude": 40.0}
"""A walking target and batteries: the stepping kernel compiles the mission's seams. ConB flies
with them (one stepping kernel per rule: each costs minutes of the suite)."""


@pytest.mark.parametrize(("planner", "seams"), [("covb", {}), ("conb", SEAMS)])
def test_the_rules_own_decisions_fly_as_simulate(planner: str, seams: dict[str, object]
                                                  ) -> None:
    mission = Mission.build(planner=planner, drones=8, rc=500.0, horizon=1500.0, **seams)
    e = parallel_env(mission)
    notified = 0
    for seed, run in RUNS:
        e.reset(seed=seed, options={"run": run})
        while e.agents:
            vx, vy = rule_directions(planner, e.engine_state)
            e.step({a: np.array([vx[i], vy[i]]) for i, a in enumerate(e.possible_agents)})
        got = e.result()
        assert same_result(got, simulate(mission.replace(stop="notified"), seed, run))
        full = simulate(mission, seed, run)  # the mission's own stop: the same events
        assert (got.t_detect, got.t_notify, got.detector) == (
            full.t_detect, full.t_notify, full.detector)
        notified += got.t_notify is not None
    assert notified >= 1  # the runs reach the end that matters


def test_the_command_line_draws_the_same_run() -> None:
    mission = Mission.build(planner="covb", drones=8, rc=500.0, horizon=1500.0)
    e = parallel_env(mission)
    e.reset(seed=3, options={"run": 1})
    while e.agents:
        vx, vy = rule_directions("covb", e.engine_state)
        e.step({a: np.array([vx[i], vy[i]]) for i, a in enumerate(e.possible_agents)})
    out = CliRunner().invoke(app, ["simulate", "--planner", "covb", "--drones", "8", "--rc",
                                   "500", "--td", "1500", "--seed", "3", "--run", "1",
                                   "--json"])
    assert out.exit_code == 0, out.output
    cli = json.loads(out.output)
    got = e.result()
    assert (tuple(cli["target"]), cli["t_detect"], cli["t_notify"], cli["detector"]) == (
        got.target, got.t_detect, got.t_notify, got.detector)


@pytest.mark.parametrize(("planner", "seams"), [("covb", {}), ("conb", SEAMS)])
def test_the_batched_form_flies_as_simulate(planner: str, seams: dict[str, object]) -> None:
    mission = Mission.build(planner=planner, drones=8, rc=500.0, horizon=1500.0, **seams)
    batch = BatchEnv(mission, batch=3)
    step = batch.reset(seed=5, first_run=2)
    while not np.all(step.terminated | step.truncated):
        actions = np.zeros((3, 8, 2))
        for b, s in enumerate(batch.states):
            actions[b, :, 0], actions[b, :, 1] = rule_directions(planner, s)
        step = batch.step(actions)
    stopped = mission.replace(stop="notified")
    for b, got in enumerate(batch.results()):
        assert got is not None and same_result(got, simulate(stopped, 5, 2 + b))


def test_reset_maps_seeds_to_runs() -> None:
    e = parallel_env(SMALL)
    e.reset(seed=7)
    assert (e.current_seed, e.current_run) == (7, 0)
    assert e.stepper.live.target == simulate(SMALL, 7, 0).target
    e.reset()
    assert (e.current_seed, e.current_run) == (7, 1)
    assert e.stepper.live.target == simulate(SMALL, 7, 1).target


def test_the_observation_is_the_engine_state() -> None:
    """Own features and the nearest linked drones, computed again from the positions."""
    e = parallel_env(SMALL, neighbours=3)
    obs, _ = e.reset(seed=2)
    for _ in range(40):
        obs, *_ = e.step({a: e.action_space(a).sample() for a in e.agents})
    s = e.engine_state
    names = feature_names(3)
    a, rc, n = SMALL.area.size, SMALL.channel.rc, SMALL.team.drones
    for i, agent in enumerate(e.possible_agents):
        row = dict(zip(names, obs[agent].tolist(), strict=True))
        assert row["x"] == pytest.approx(s.obs.px[i] / a)
        assert row["heading_y"] == pytest.approx(s.obs.hy[i])
        assert row["time"] == pytest.approx(s.k * s.params.dt / 300.0)
        assert row["decides"] == float(s.deciding[i])
        d = np.hypot(s.obs.px[:n] - s.obs.px[i], s.obs.py[:n] - s.obs.py[i])
        linked = [j for j in np.argsort(d, kind="stable") if j != i and d[j] <= rc]
        for slot in range(3):
            if slot < len(linked):
                j = linked[slot]
                assert row[f"n{slot}_present"] == 1.0
                assert row[f"n{slot}_dx"] == pytest.approx((s.obs.px[j] - s.obs.px[i]) / rc)
            else:
                assert row[f"n{slot}_present"] == 0.0
    assert len(OWN) + 3 * 6 == e.observation_space("drone_0").shape[0]


def test_rewards_pay_the_notification_and_the_time() -> None:
    mission = Mission.build(planner="covb", drones=8, rc=500.0, horizon=1500.0)
    e = parallel_env(mission, rewards=Rewards(notify=2.0, time=-0.01))
    e.reset(seed=3, options={"run": 1})
    total = np.zeros(8)
    while e.agents:
        vx, vy = rule_directions("covb", e.engine_state)
        _, rewards, term, trunc, _ = e.step(
            {a: np.array([vx[i], vy[i]]) for i, a in enumerate(e.possible_agents)})
        total += [rewards[a] for a in e.possible_agents if a in rewards]
    t_notify = simulate(mission, 3, 1).t_notify
    assert t_notify is not None and all(term.values()) and not any(trunc.values())
    expected = 2.0 * (1.0 - t_notify / 1500.0) - 0.01 * t_notify
    assert total == pytest.approx(np.full(8, expected), rel=1e-12)


def test_the_horizon_truncates() -> None:
    e = parallel_env(Mission.build(planner="covb", drones=2, rc=200.0, horizon=60.0))
    e.reset(seed=1)
    while e.agents:
        _, rewards, term, trunc, infos = e.step(
            {a: e.action_space(a).sample() for a in e.agents})
    assert all(trunc.values()) and not any(term.values())
    assert set(rewards.values()) == {0.0}
    assert infos["drone_0"]["result"]["t_notify"] is None
    assert infos["drone_0"]["t"] == 60.0


@pytest.mark.parametrize(("action", "words"), [
    (np.array([1.5, 0.0]), "the action of drone_1 is array([1.5, 0. ]): outside"),
    (np.array([math.nan, 0.0]), "each in [-1, 1]"),
    (np.array([1.0, 0.0, 0.0]), "allowed: a direction (x, y)"),
    (3, "outside its action space"),
])
def test_an_action_outside_the_space_names_the_agent(action: object, words: str) -> None:
    e = parallel_env(SMALL)
    e.reset(seed=0)
    actions = {a: np.array([1.0, 0.0]) for a in e.agents}
    actions["drone_1"] = action
    with pytest.raises(ConfigError) as err:
        e.step(actions)
    assert words in str(err.value) and "drone_1" in str(err.value)


def test_discrete_actions_name_their_range() -> None:
    e = parallel_env(SMALL, actions="discrete", directions=6)
    e.reset(seed=0)
    with pytest.raises(ConfigError, match=r"drone_0 is 6: .* an integer in 0\.\.5"):
        e.step({a: 6 for a in e.agents})


def test_a_wrong_agent_or_a_missing_decision_is_named() -> None:
    e = parallel_env(SMALL)
    e.reset(seed=0)
    with pytest.raises(ConfigError, match=r"unknown agent 'drone_9'; the agents are drone_0 "
                                          r"\.\. drone_4"):
        e.step({"drone_9": np.array([1.0, 0.0])})
    with pytest.raises(ConfigError, match="drone_0 decides at this step and has no action"):
        e.step({})


def test_a_step_after_the_end_is_refused() -> None:
    e = parallel_env(Mission.build(planner="covb", drones=2, rc=200.0, horizon=20.0))
    e.reset(seed=0)
    while e.agents:
        e.step({a: np.array([0.0, 1.0]) for a in e.agents})
    with pytest.raises(ConfigError, match=r"step\(\) after the episode ended.*reset\(\)"):
        e.step({"drone_0": np.array([0.0, 1.0])})


def test_batched_actions_of_the_wrong_shape_or_range_are_named() -> None:
    batch = BatchEnv(SMALL, batch=2)
    batch.reset(seed=0)
    with pytest.raises(ConfigError, match=r"shape \(5, 2\); expected \(2, 5, 2\)"):
        batch.step(np.zeros((5, 2)))
    bad = np.zeros((2, 5, 2))
    bad[1, 3] = [0.0, -2.0]
    with pytest.raises(ConfigError, match=r"actions\[1, 3\] \(drone_3 of mission 1\)"):
        batch.step(bad)


def test_a_route_planner_is_refused() -> None:
    with pytest.raises(ConfigError, match=r"'sector' flies routes; sarlink\.env steers"):
        parallel_env(Mission.build(planner="sector", drones=3))


@pytest.mark.parametrize("make", [parallel_env, env, BatchEnv])
def test_a_team_with_relays_is_refused_in_one_line(make: object) -> None:
    """Every agent is a drone steered like a searcher: relays, which take no direction, are
    refused by each way of making the environment."""
    with pytest.raises(ConfigError, match=r"^team\.relays = 2: sarlink\.env steers every drone "
                       r"as a searcher and cannot take relays yet; allowed: team\.relays = 0$"):
        make(SMALL.replace(relays=2))  # type: ignore[operator]


def test_the_learning_example_runs(monkeypatch: pytest.MonkeyPatch,
                                   capsys: pytest.CaptureFixture[str]) -> None:
    """examples/learn_policy.py, tiny: one generation, a few short runs."""
    import runpy
    import sys
    from pathlib import Path

    example = Path(__file__).resolve().parents[1] / "examples" / "learn_policy.py"
    monkeypatch.setattr(sys, "argv", [str(example), "--drones", "3", "--horizon", "120",
                                      "--runs", "2", "--generations", "1", "--popsize", "2",
                                      "--test-runs", "2"])
    runpy.run_path(str(example), run_name="__main__")
    out = capsys.readouterr().out
    assert "generation 1: best reward" in out
    assert all(name in out for name in ("linear policy (CMA-ES)", "covb", "conb"))


def test_the_stepping_form_needs_the_templates_marks() -> None:
    """The stepping form is made from the kernel's text: a template without the marker (or
    the record's return, or the kernel) is refused rather than compiled wrong."""
    from sarlink.engine.build import stepping_source

    with pytest.raises(RuntimeError, match="0 stepping marks, 0 returns of its record and 0 "
                                           "kernels"):
        stepping_source("x = 1\n")


@pytest.mark.parametrize(("seed", "options", "words"), [
    (-1, None, "seed must be an integer >= 0, got -1"),
    (0, {"run": -2}, r"options\['run'\] must be an integer >= 0, got -2"),
    (0, {"run": 1.5}, r"options\['run'\] must be an integer >= 0, got 1.5"),
])
def test_a_bad_seed_or_run_is_named(seed: int, options: dict[str, object] | None,
                                    words: str) -> None:
    with pytest.raises(ConfigError, match=words):
        parallel_env(SMALL).reset(seed=seed, options=options)
