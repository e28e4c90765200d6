"""The random initial conditions of a run: where the target is and how the drones take off."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sarlink.config import ConfigError, Mission


@dataclass(frozen=True)
class Scenario:
    """Initial conditions of one run.

    ``heading_offset`` rotates the evenly spaced take-off headings ``2πk/N + offset`` of the
    distributed drones. ``positions`` and ``headings`` (radians), when given, replace the
    take-off from the BS for every drone: for hand-made situations and tests.
    """

    target: tuple[float, float]
    heading_offset: float = 0.0
    positions: np.ndarray | None = None
    headings: np.ndarray | None = None

    def check(self, mission: Mission) -> None:
        """Raise :class:`ConfigError` if this scenario does not fit ``mission``."""
        size, n = mission.area.size, mission.team.drones
        x, y = self.target
        if not (0 <= x <= size and 0 <= y <= size):
            raise ConfigError(f"scenario.target must lie inside [0, {size}]², got ({x}, {y})")
        for name, arr, shape in (("positions", self.positions, (n, 2)),
                                 ("headings", self.headings, (n,))):
            if arr is not None and np.shape(arr) != shape:
                raise ConfigError(f"scenario.{name} must have shape {shape}, "
                                  f"got {np.shape(arr)}")
        if self.positions is not None:
            pos = np.asarray(self.positions)
            if (pos < 0).any() or (pos > size).any():
                raise ConfigError(f"scenario.positions must lie inside [0, {size}]²")


def draw_scenario(mission: Mission, rng: np.random.Generator) -> Scenario:
    """A uniform target in the area and a uniform take-off heading offset."""
    size = mission.area.size
    x, y = rng.random() * size, rng.random() * size
    return Scenario(target=(x, y), heading_offset=rng.random() * 2 * math.pi)


def takeoff_headings(scenario: Scenario, distributed: np.ndarray) -> np.ndarray:
    """Take-off headings: evenly spaced over the distributed drones, rotated by the offset."""
    if scenario.headings is not None:
        return np.asarray(scenario.headings, dtype=float)
    headings = np.zeros(distributed.size)
    k = int(distributed.sum())
    if k:
        headings[distributed] = 2 * math.pi * np.arange(k) / k + scenario.heading_offset
    return headings
