"""The mission as a PettingZoo environment: one agent per drone (``drone_0``, ...).

Each step of the environment is a step of the engine at which drones decide: every drone
observes (:mod:`sarlink.env.features`), the drones that decide (those the planner's rule
would have decide then: ``decides`` in the observation) turn to their action's direction, and
the engine runs its own phases up to the next such step. The episode terminates when the BS
is notified and is truncated at the horizon.
"""

from __future__ import annotations

from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces
from pettingzoo import AECEnv, ParallelEnv
from pettingzoo.utils import parallel_to_aec, wrappers

from sarlink.config import ConfigError, Mission
from sarlink.env.actions import ActionKind, allowed, check_actions
from sarlink.env.episode import EngineState, stepping_mission
from sarlink.env.render import FPS, RENDER_MODES, Renderer, RenderMode
from sarlink.env.rewards import Rewards
from sarlink.env.stepper import Stepper
from sarlink.result import RunResult


def result_info(result: RunResult) -> dict[str, Any]:
    """A run's records for ``info``: plain values, the cumulative records up to the run's
    end (a run stopped at notification has none after it)."""
    upto = np.isfinite(result.reach_cum)
    return {"seed": result.seed, "run": result.run, "target": result.target,
            "t_detect": result.t_detect, "t_notify": result.t_notify,
            "detector": result.detector, "immediate": result.immediate,
            "checkpoints": result.checkpoints[upto], "reach_cum": result.reach_cum[upto],
            "connected_cum": result.connected_cum[upto], "depth": result.depth[upto],
            "farthest": result.farthest[upto]}


class SarlinkParallelEnv(ParallelEnv[str, np.ndarray, Any]):
    """A mission whose drones are agents (PettingZoo's parallel API); see :func:`parallel_env`.
    """

    metadata: dict[str, Any] = {"name": "sarlink_v0",  # noqa: RUF012
                                "render_modes": list(RENDER_MODES), "render_fps": FPS,
                                "is_parallelizable": True}

    def __init__(self, mission: Mission | None = None, *, actions: ActionKind = "continuous",
                 directions: int = 8, neighbours: int = 4, rewards: Rewards | None = None,
                 render_mode: RenderMode | None = None) -> None:
        if render_mode is not None and render_mode not in RENDER_MODES:
            raise ConfigError(f"render_mode {render_mode!r} is not one of "
                              f"{', '.join(RENDER_MODES)} (or None: no pictures)")
        self.mission = Mission() if mission is None else mission
        self.stepper = Stepper(stepping_mission(self.mission), actions, directions, neighbours,
                               Rewards() if rewards is None else rewards)
        self.possible_agents = [f"drone_{i}" for i in range(self.mission.team.drones)]
        self._index = {agent: i for i, agent in enumerate(self.possible_agents)}
        self._action_spaces = {a: action_space_copy(self.stepper.action_space)
                               for a in self.possible_agents}
        self.agents: list[str] = []
        self.current_seed, self.current_run = 0, -1
        self.render_mode = render_mode
        self._renderer = None if render_mode is None else Renderer(self.mission, render_mode)

    # -- spaces ---------------------------------------------------------------------------

    def _agent(self, agent: str) -> int:
        if agent not in self._index:
            last = self.possible_agents[-1]
            raise ConfigError(f"unknown agent {agent!r}; the agents are drone_0 .. {last}")
        return self._index[agent]

    def observation_space(self, agent: str) -> spaces.Space[Any]:
        """Every agent's observation space (:mod:`sarlink.env.features`)."""
        self._agent(agent)
        return self.stepper.observation_space

    def action_space(self, agent: str) -> spaces.Space[Any]:
        """``agent``'s action space (:mod:`sarlink.env.actions`)."""
        return self._action_spaces[self.possible_agents[self._agent(agent)]]

    # -- the episode ----------------------------------------------------------------------

    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None
              ) -> tuple[dict[str, np.ndarray], dict[str, dict[str, Any]]]:
        """Start run ``options["run"]`` of the experiment seeded with ``seed``: the target and
        take-off of ``sarlink simulate --seed seed --run run``. Without a seed, the next run of
        the same seed (0 at first); with a seed and no run, run 0."""
        run = (options or {}).get("run")
        if run is None:
            run = 0 if seed is not None else self.current_run + 1
        for name, value in (("seed", seed), ("options['run']", run)):
            if value is not None and (not isinstance(value, (int, np.integer))
                                      or isinstance(value, bool) or value < 0):
                raise ConfigError(f"{name} must be an integer >= 0, got {value!r}")
        if seed is not None:
            self.current_seed = int(seed)
        self.current_run = int(run)
        obs = self.stepper.start(self.current_seed, self.current_run)
        self.agents = list(self.possible_agents)
        return self._observations(obs), self._infos()

    def step(self, actions: dict[str, Any]) -> tuple[
            dict[str, np.ndarray], dict[str, float], dict[str, bool], dict[str, bool],
            dict[str, dict[str, Any]]]:
        """Apply the actions (every deciding drone needs one; the others' are checked and
        ignored) and run the engine to the next step at which drones decide."""
        if not self.agents:
            raise ConfigError("step() after the episode ended (the BS was notified, or the "
                              "horizon was reached): call reset()")
        state = self.stepper.live.state
        for agent in actions:
            self._agent(agent)
        given = list(actions)
        check_actions(given, self.stepper.action_space, [actions[a] for a in given])
        if not self.stepper.live.done:
            for d in np.flatnonzero(state.deciding):
                agent = self.possible_agents[d]
                if agent not in actions:
                    raise ConfigError(f"{agent} decides at this step and has no action; "
                                      f"allowed: {allowed(self.action_space(agent))}")
        n = len(self.possible_agents)
        chosen = np.zeros((n, 2)) if self.stepper.kind == "continuous" else np.zeros(
            n, dtype=np.int64)
        for agent in given:
            chosen[self._index[agent]] = actions[agent]
        obs, rewards = self.stepper.step(chosen)
        terminated, truncated = self.stepper.outcome()
        observations = self._observations(obs)
        infos = self._infos()
        agents = self.agents
        if terminated or truncated:
            self.agents = []
        return (observations, {a: float(rewards[self._index[a]]) for a in agents},
                dict.fromkeys(agents, terminated), dict.fromkeys(agents, truncated), infos)

    def _observations(self, obs: np.ndarray) -> dict[str, np.ndarray]:
        return {a: obs[self._index[a]] for a in self.agents}

    def _infos(self) -> dict[str, dict[str, Any]]:
        ep = self.stepper.live
        common: dict[str, Any] = {"t": ep.t}
        if ep.done:
            common["result"] = result_info(ep.result())
        return {a: {**common, "decides": bool(ep.state.deciding[self._index[a]])}
                for a in self.agents}

    # -- what the engine sees -------------------------------------------------------------

    @property
    def engine_state(self) -> EngineState:
        """The engine's own state at this step (for policies that call a rule's hooks)."""
        return self.stepper.live.state

    def result(self) -> RunResult:
        """The run's records, as :func:`sarlink.simulate` returns them (once it has ended)."""
        return self.stepper.live.result()

    def render(self) -> np.ndarray | None:
        """A picture of the current step (:mod:`sarlink.env.render`): the image as an
        ``(H, W, 3)`` ``uint8`` array with ``render_mode="rgb_array"``, a window with
        ``"human"``; nothing without a render mode (the records are ``info["result"]``)."""
        if self._renderer is None:
            gymnasium.logger.warn("render() without a render_mode: pass render_mode="
                                  f"{' or '.join(map(repr, RENDER_MODES))} to the environment")
            return None
        if self.stepper.episode is None:
            raise ConfigError("render() before reset(): there is no step to draw yet")
        return self._renderer.draw(self.stepper.live.state, self.stepper.live.t)

    def close(self) -> None:
        """Close the render window, if any."""
        if self._renderer is not None:
            self._renderer.close()


def action_space_copy(space: spaces.Space[Any]) -> spaces.Space[Any]:
    """A space of its own for each agent (each is seeded on its own)."""
    if isinstance(space, spaces.Discrete):
        return spaces.Discrete(int(space.n))
    assert isinstance(space, spaces.Box)
    return spaces.Box(space.low, space.high, dtype=space.dtype)


def parallel_env(mission: Mission | None = None, *, actions: ActionKind = "continuous",
                 directions: int = 8, neighbours: int = 4, rewards: Rewards | None = None,
                 render_mode: RenderMode | None = None) -> SarlinkParallelEnv:
    """``mission`` (default ``Mission()``) as a PettingZoo parallel environment.

    Parameters
    ----------
    mission
        The mission; its planner must be a distributed one (CovB, ConB, ...): the drones
        decide when its rule would have them decide, and the actions replace its decisions.
        Runs stop at the BS's notification.
    actions
        ``"continuous"``: a direction ``(x, y)`` in ``[-1, 1]²``, scaled to unit length;
        ``"discrete"``: one of ``directions`` headings, evenly spaced from the x axis.
    neighbours
        How many of the nearest linked drones each observation holds.
    rewards
        The reward terms (:class:`~sarlink.env.rewards.Rewards`; default: the mission's
        outcome only).
    render_mode
        ``"rgb_array"``: :meth:`~SarlinkParallelEnv.render` returns the step's picture;
        ``"human"``: it shows it in a window; ``None``: no pictures.
    """
    return SarlinkParallelEnv(mission, actions=actions, directions=directions,
                              neighbours=neighbours, rewards=rewards, render_mode=render_mode)


def env(mission: Mission | None = None, **options: Any) -> AECEnv[str, np.ndarray, Any]:
    """The same environment in PettingZoo's AEC form (agents act in turn; the engine steps
    once all have acted); ``options`` as :func:`parallel_env`'s."""
    return wrappers.OrderEnforcingWrapper(parallel_to_aec(parallel_env(mission, **options)))


