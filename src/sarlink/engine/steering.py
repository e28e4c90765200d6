"""What the engine needs from a planner: a rule for the distributed drones, routes for the rest."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from sarlink.engine.hooks import DistributedRule


@dataclass(frozen=True)
class Steering:
    """How a team is steered: a rule for the distributed drones, routes for the others.

    ``routes[i]`` is drone ``i``'s waypoint array of shape ``(k, 2)`` (ending at the BS), or an
    empty ``(0, 2)`` array when drone ``i`` runs the distributed ``rule``; drones past the end
    of ``routes`` run the rule too. A team of routes only has ``rule = None``. ``per_run``,
    if given, makes each run's own routes from ``(seed, run)`` (one mTSP plan per run,
    ``readings.mtsp_plan``); ``routes`` are then those of the shared plan, which decide only
    which drones fly routes.
    """

    rule: DistributedRule | None
    routes: tuple[np.ndarray, ...] = field(default=())
    per_run: Callable[[int, int], tuple[np.ndarray, ...]] | None = None

    def distributed(self, drones: int) -> np.ndarray:
        """Boolean mask of the drones that run the distributed rule."""
        mask = np.ones(drones, dtype=bool)
        for i, route in enumerate(self.routes):
            mask[i] = len(route) == 0
        return mask
