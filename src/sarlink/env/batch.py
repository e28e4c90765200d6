"""Many runs of a mission stepped in one call, arrays in and arrays out (for learners that
evaluate a population or a batch of episodes at once)."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from sarlink.config import ConfigError, Mission
from sarlink.env.actions import ActionKind, allowed
from sarlink.env.episode import EngineState, stepping_mission
from sarlink.env.rewards import Rewards
from sarlink.env.stepper import Stepper
from sarlink.result import RunResult


class BatchStep(NamedTuple):
    """What :meth:`BatchEnv.step` returns; ``B`` missions of ``N`` drones."""

    observations: np.ndarray
    """``(B, N, width)`` float32, as the parallel environment's."""
    rewards: np.ndarray
    """``(B, N)``: zero for a mission that had already ended."""
    terminated: np.ndarray
    """``(B,)``: the BS has been notified."""
    truncated: np.ndarray
    """``(B,)``: the horizon was reached first."""
    deciding: np.ndarray
    """``(B, N)`` bool: the drones whose next action is used."""


class BatchEnv:
    """``batch`` runs of ``mission``, runs ``first_run ..`` of one seed, stepped together.

    The options are :func:`~sarlink.env.parallel_env`'s. Each mission advances to its own
    next step at which drones decide; one that has ended stays ended (its actions are
    ignored, its rewards zero) until :meth:`reset`.
    """

    def __init__(self, mission: Mission | None = None, batch: int = 8, *,
                 actions: ActionKind = "continuous", directions: int = 8, neighbours: int = 4,
                 rewards: Rewards | None = None) -> None:
        if batch < 1:
            raise ConfigError(f"batch must be at least 1, got {batch}")
        prepared = stepping_mission(Mission() if mission is None else mission)
        rewards = Rewards() if rewards is None else rewards
        self.steppers = [Stepper(prepared, actions, directions, neighbours, rewards)
                         for _ in range(batch)]
        self.kind, self.directions = actions, directions
        self.batch, self.drones = batch, prepared.mission.team.drones
        self.action_space = self.steppers[0].action_space
        """One drone's action space."""
        self.observation_space = self.steppers[0].observation_space
        """One drone's observation space."""
        self._ended = np.zeros(batch, dtype=bool)

    def reset(self, seed: int = 0, first_run: int = 0) -> BatchStep:
        """Start runs ``first_run .. first_run + batch - 1`` of seed ``seed``."""
        if seed < 0 or first_run < 0:
            raise ConfigError(f"seed and first_run must be >= 0, got {seed} and {first_run}")
        obs = np.stack([s.start(seed, first_run + b) for b, s in enumerate(self.steppers)])
        self._ended[:] = False
        zeros = np.zeros(self.batch, dtype=bool)
        return BatchStep(obs, np.zeros((self.batch, self.drones)), zeros, zeros.copy(),
                         self._deciding())

    def _deciding(self) -> np.ndarray:
        return np.stack([s.live.state.deciding for s in self.steppers])

    def _check(self, actions: np.ndarray) -> np.ndarray:
        a = np.asarray(actions)
        shape = (self.batch, self.drones, 2) if self.kind == "continuous" else (
            self.batch, self.drones)
        if a.shape != shape:
            raise ConfigError(f"actions have shape {a.shape}; expected {shape} (missions, "
                              f"drones{', direction' if self.kind == 'continuous' else ''})")
        if self.kind == "continuous":
            if not np.issubdtype(a.dtype, np.number):
                raise ConfigError(f"continuous actions must be numbers, got {a.dtype}; "
                                  f"allowed: {allowed(self.action_space)}")
            bad = ~np.all(np.isfinite(a) & (np.abs(a) <= 1.0), axis=-1)
        else:
            if not np.issubdtype(a.dtype, np.integer):
                raise ConfigError(f"discrete actions must be integers, got {a.dtype}; "
                                  f"allowed: {allowed(self.action_space)}")
            bad = (a < 0) | (a >= self.directions)
        if bad.any():
            b, i = np.argwhere(bad)[0]
            raise ConfigError(f"actions[{b}, {i}] (drone_{i} of mission {b}) is "
                              f"{a[b, i].tolist()}: outside the action space; allowed: "
                              f"{allowed(self.action_space)}")
        return a

    def step(self, actions: np.ndarray) -> BatchStep:
        """Apply ``actions[b, i]`` to every deciding drone ``i`` of every mission ``b`` that has
        not ended, and run each to its next step at which drones decide."""
        a = self._check(actions)
        obs = np.empty((self.batch, self.drones, self.steppers[0].width), dtype=np.float32)
        rewards = np.zeros((self.batch, self.drones))
        terminated = np.zeros(self.batch, dtype=bool)
        truncated = np.zeros(self.batch, dtype=bool)
        for b, s in enumerate(self.steppers):
            if self._ended[b]:
                obs[b] = s.observe()
            else:
                obs[b], rewards[b] = s.step(a[b])
            terminated[b], truncated[b] = s.outcome()
        self._ended |= terminated | truncated
        return BatchStep(obs, rewards, terminated, truncated, self._deciding())

    @property
    def states(self) -> list[EngineState]:
        """Every mission's engine state (for policies that call a rule's hooks)."""
        return [s.live.state for s in self.steppers]

    def results(self) -> list[RunResult | None]:
        """Every mission's records once it has ended (``None`` while it runs)."""
        return [s.live.result() if s.live.done else None for s in self.steppers]
