"""The planner contract: what a planner hands the engine for one mission."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

import numpy as np

from sarlink.engine.codes import Rule

if TYPE_CHECKING:
    from sarlink.config import Mission


@dataclass(frozen=True)
class Steering:
    """How a team is steered: a rule for the distributed drones, routes for the others.

    ``routes[i]`` is drone ``i``'s waypoint array of shape ``(k, 2)`` (ending at the BS), or an
    empty ``(0, 2)`` array when drone ``i`` runs the distributed ``rule``.
    """

    rule: Rule
    alpha: float
    routes: tuple[np.ndarray, ...] = field(default=())

    def distributed(self, drones: int) -> np.ndarray:
        """Boolean mask of the drones that run the distributed rule."""
        mask = np.ones(drones, dtype=bool)
        for i, route in enumerate(self.routes):
            mask[i] = len(route) == 0
        return mask


class Planner(Protocol):
    """A path planner, registered by name in :mod:`sarlink.planners`."""

    @property
    def name(self) -> str:
        """Registry key used in configs and the CLI (``covb``)."""
        ...

    @property
    def label(self) -> str:
        """Name as the paper writes it (``CovB``)."""
        ...

    @property
    def colour(self) -> str:
        """Its line colour in every figure (a Matplotlib colour)."""
        ...

    @property
    def marker(self) -> str:
        """Its marker in every figure (a Matplotlib marker)."""
        ...

    def steering(self, mission: Mission) -> Steering:
        """What the engine needs to fly ``mission`` with this planner."""
        ...
