"""The rewards of the environment: the mission's outcome, and optional shaping terms."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

from sarlink.config import ConfigError


@dataclass(frozen=True)
class Rewards:
    """What each agent is paid at each step (a team reward is paid to every drone).

    The default is the mission: ``notify`` to every drone when the BS is notified, scaled by
    ``1 - t_notify / horizon`` if ``timed`` (an earlier notification is worth more), and
    nothing else. The shaping terms are off by default; they are sampled at the steps at
    which drones decide, over the time since the previous one (from take-off on).
    """

    notify: float = 1.0
    """Team reward when the BS is notified (the episode then terminates)."""
    timed: bool = True
    """Scale ``notify`` by ``1 - t_notify / horizon``."""
    detect: float = 0.0
    """Team reward, once, at the first step at which a drone knows where the target is."""
    routed: float = 0.0
    """Per drone, per second during which it has a route to the BS."""
    time: float = 0.0
    """Per drone, per second (a negative value is a cost of time)."""

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name != "timed" and not (isinstance(value, (int, float))
                                          and math.isfinite(value)):
                raise ConfigError(f"Rewards.{f.name} must be a finite number, got {value!r}")

    def notified(self, t_notify: float, horizon: float) -> float:
        """The team reward of a notification at ``t_notify``."""
        return self.notify * (1.0 - t_notify / horizon if self.timed else 1.0)
