"""The random initial conditions of a run: where the target is and how the drones take off."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from sarlink.config import ConfigError, Mission
from sarlink.config.region import EDGE, area_polygon, is_polygon
from sarlink.engine.targets import target_prior


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
        region = mission.region
        square = not is_polygon(region)
        where = f"[0, {size}]²" if square else "the area (its polygon, out of its holes)"
        area = None if square else area_polygon(region, size)
        if not _inside(area, size, np.array([[x, y]])):
            raise ConfigError(f"scenario.target must lie inside {where}, got ({x}, {y})")
        for name, arr, shape in (("positions", self.positions, (n, 2)),
                                 ("headings", self.headings, (n,))):
            if arr is not None and np.shape(arr) != shape:
                raise ConfigError(f"scenario.{name} must have shape {shape}, "
                                  f"got {np.shape(arr)}")
        if self.positions is not None and not _inside(area, size, np.asarray(self.positions)):
            raise ConfigError(f"scenario.positions must lie inside {where}")


def _inside(area: shapely.Polygon | None, size: float, xy: np.ndarray) -> bool:
    if area is None:
        return bool(((xy >= 0) & (xy <= size)).all())
    return bool(shapely.dwithin(area, shapely.points(xy), EDGE).all())


def draw_scenario(mission: Mission, rng: np.random.Generator) -> Scenario:
    """A target from the mission's prior (uniform in the square by default, drawn as the
    paper's runs always were) and a uniform take-off heading offset."""
    prior = target_prior(mission)
    if prior is None:
        size = mission.area.size
        x, y = rng.random() * size, rng.random() * size
    else:
        x, y = prior.draw(rng)
    return Scenario(target=(x, y), heading_offset=rng.random() * 2 * math.pi)


HEADING_ERROR = math.radians(5.0)
"""Largest heading error of a drone, at take-off (``readings.takeoff = jitter``) and at each
commanded change (``readings.turns = jitter``): a few degrees, what a drone's compass and
heading control hold (docs/model.md, Readings)."""


def takeoff_headings(scenario: Scenario, distributed: np.ndarray, takeoff: str = "even",
                     rng: np.random.Generator | None = None) -> np.ndarray:
    """Take-off headings of the distributed drones, by ``readings.takeoff``: evenly spaced and
    rotated by the scenario's offset (``even``), each then off by a uniform error of at most
    :data:`HEADING_ERROR` (``jitter``), or independent and uniform (``random``). The random
    draws come from ``rng`` (the run's take-off stream), one per drone, so a team's draws
    depend on neither its rule nor which drones fly routes."""
    if scenario.headings is not None:
        return np.asarray(scenario.headings, dtype=float)
    headings = np.zeros(distributed.size)
    k = int(distributed.sum())
    if k == 0:
        return headings
    if takeoff == "even":
        headings[distributed] = 2 * math.pi * np.arange(k) / k + scenario.heading_offset
        return headings
    if rng is None:
        raise ValueError(f"readings.takeoff = {takeoff!r} draws from the run's take-off stream")
    u = rng.random(distributed.size)[distributed]
    if takeoff == "random":
        headings[distributed] = 2 * math.pi * u
    else:
        headings[distributed] = (2 * math.pi * np.arange(k) / k + scenario.heading_offset
                                 + HEADING_ERROR * (2 * u - 1))
    return headings
