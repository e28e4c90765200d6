"""One mission as an environment: an :class:`~sarlink.env.episode.Episode` with observations,
actions and rewards as arrays, shared by the PettingZoo form and the batched form."""

from __future__ import annotations

import numpy as np

from sarlink.config import ConfigError
from sarlink.engine.run import Prepared
from sarlink.env.actions import ActionKind, action_space, directions
from sarlink.env.episode import Episode
from sarlink.env.features import NEIGHBOUR, OWN, features, observation_space
from sarlink.env.rewards import Rewards


class Stepper:
    """Runs of one prepared mission, stepped decision by decision, with arrays in and out."""

    def __init__(self, prepared: Prepared, actions: ActionKind, directions: int,
                 neighbours: int, rewards: Rewards) -> None:
        if neighbours < 0:
            raise ConfigError(f"neighbours must be >= 0, got {neighbours}")
        self.prepared = prepared
        self.kind, self.directions, self.rewards = actions, directions, rewards
        self.n = prepared.mission.team.drones
        self.action_space = action_space(actions, directions)
        self.observation_space = observation_space(
            neighbours, prepared.params.size / prepared.mission.channel.rc)
        self.width = len(OWN) + neighbours * len(NEIGHBOUR)
        self.horizon = prepared.params.n_steps * prepared.params.dt
        self.episode: Episode | None = None

    def start(self, seed: int, run: int) -> np.ndarray:
        """Start run ``run`` of seed ``seed``; the first observation ``(N, width)``."""
        self.episode = Episode(self.prepared, seed, run)
        self._detected = False
        self._paid = False
        self._k = 0  # the step up to which the time-based rewards are paid
        return self.observe()

    @property
    def live(self) -> Episode:
        """The current episode."""
        if self.episode is None:
            raise RuntimeError("reset() first")
        return self.episode

    def observe(self) -> np.ndarray:
        """Every drone's observation of the current step, float32 ``(N, width)``."""
        s = self.live.state
        out = np.empty((self.n, self.width))
        features(s.k, s.params, s.obs, s.deciding, out)
        return out.astype(np.float32)

    def step(self, actions: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Apply every deciding drone's (checked) action, ``actions[i]`` for drone ``i``
        (``(N, 2)`` directions or ``(N,)`` choices), and run to the next decision; the new
        observation and every drone's reward."""
        ep = self.live
        if not ep.done:
            s = ep.state
            vx, vy = directions(self.kind, self.directions, actions, s.obs.hx, s.obs.hy)
            ep.decide(vx, vy)
        return self.observe(), self._rewards()

    def _rewards(self) -> np.ndarray:
        ep, r = self.live, self.rewards
        s = ep.state
        elapsed = (s.k - self._k) * s.params.dt
        self._k = s.k
        out = np.full(self.n, r.time * elapsed)
        if r.routed:
            bits = np.unpackbits(s.obs.routed.astype("<u8").view(np.uint8), bitorder="little")
            out += r.routed * elapsed * bits[:self.n]
        if not self._detected and s.obs.knows.any():
            self._detected = True
            out += r.detect
        if ep.record is not None and ep.record.t_notify >= 0 and not self._paid:
            self._paid = True
            out += r.notified(ep.record.t_notify, self.horizon)
        return out

    def outcome(self) -> tuple[bool, bool]:
        """``(terminated, truncated)``: notified, or out of time, at the current step."""
        rec = self.live.record
        if rec is None:
            return False, False
        return rec.t_notify >= 0, rec.t_notify < 0
