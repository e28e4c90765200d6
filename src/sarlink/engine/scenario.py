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
    take-off from the BS for every drone: for hand-made situations and tests. ``others``
    are where the targets after the first were last seen (``target.count > 1``).
    """

    target: tuple[float, float]
    heading_offset: float = 0.0
    positions: np.ndarray | None = None
    headings: np.ndarray | None = None
    others: tuple[tuple[float, float], ...] = ()

    @property
    def targets(self) -> np.ndarray:
        """Every target's last-seen position, ``(K, 2)``, the first first."""
        return np.array([self.target, *self.others], dtype=float).reshape(-1, 2)

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
        count = mission.target.count
        if len(self.others) != count - 1:
            raise ConfigError(f"scenario.others must give the {count - 1} targets after the "
                              f"first (target.count = {count}), got {len(self.others)}")
        if self.others and not _inside(area, size, np.array(self.others, dtype=float)):
            raise ConfigError(f"scenario.others must lie inside {where}")
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


def _draw_target(mission: Mission, rng: np.random.Generator) -> tuple[float, float]:
    prior = target_prior(mission)
    if prior is None:
        size = mission.area.size
        return rng.random() * size, rng.random() * size
    return prior.draw(rng)


def draw_scenario(mission: Mission, rng: np.random.Generator,
                  others: np.random.Generator | None = None) -> Scenario:
    """A target from the mission's prior (uniform in the square by default, drawn as the
    paper's runs always were) and a uniform take-off heading offset; with
    ``target.count = K > 1``, the other ``K - 1`` targets from the same prior, in order, from
    ``others`` (the run's targets stream), so that no draw of ``rng`` changes."""
    x, y = _draw_target(mission, rng)
    offset = rng.random() * 2 * math.pi
    count = mission.target.count
    if count > 1 and others is None:
        raise ValueError(f"target.count = {count} draws the other targets from the run's "
                         "targets stream: pass it")
    rest = tuple(_draw_target(mission, others) for _ in range(count - 1)) if others else ()
    return Scenario(target=(x, y), heading_offset=offset, others=rest)


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
