"""What the engine needs from a planner: a rule for the distributed drones, routes for the rest."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from sarlink.engine.codes import Rule


@dataclass(frozen=True)
class Steering:
    """How a team is steered: a rule for the distributed drones, routes for the others.

    ``routes[i]`` is drone ``i``'s waypoint array of shape ``(k, 2)`` (ending at the BS), or an
    empty ``(0, 2)`` array when drone ``i`` runs the distributed ``rule``. A team of routes
    only has ``rule = Rule.NONE``.
    """

    rule: Rule
    alpha: float = 0.0
    routes: tuple[np.ndarray, ...] = field(default=())

    def distributed(self, drones: int) -> np.ndarray:
        """Boolean mask of the drones that run the distributed rule."""
        mask = np.ones(drones, dtype=bool)
        for i, route in enumerate(self.routes):
            mask[i] = len(route) == 0
        return mask
