"""What a search pattern is planned from, and the planner that flies one.

A pattern is a pure function ``routes(mission) -> tuple[np.ndarray, ...]``: one route per
drone, each ending at the BS (the engine's route format, :class:`sarlink.engine.Steering`).
:data:`sarlink.planners.patterns.PATTERNS` makes each a :class:`~sarlink.RoutePlanner`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from sarlink.planners.patterns.geometry import Rect, fit_budget

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["Search"]


@dataclass(frozen=True)
class Search:
    """A mission as the patterns see it: the area, the BS, the team, the track spacing and
    the flight budget."""

    area: Rect
    bs: tuple[float, float]
    drones: int
    spacing: float
    """Track spacing S, m: the sweep width of a definite-range sensor of range r, 2 r (an
    IAMSAR coverage factor of 1)."""
    budget: float
    """Metres a drone may fly, landing included: V (T_max − 2 dt), the two steps of margin
    the engine gives a distributed drone's return home."""

    @classmethod
    def of(cls, mission: Mission) -> Search:
        team, timing = mission.team, mission.timing
        return cls(area=Rect.square(mission.area.size), bs=mission.area.bs_xy,
                   drones=team.drones, spacing=2.0 * mission.sensing.r,
                   budget=team.speed * (team.flight_time - 2.0 * timing.dt))

    def fit(self, routes: tuple[np.ndarray, ...]) -> tuple[np.ndarray, ...]:
        """Each route cut where its drone must turn home to land within the budget."""
        return tuple(fit_budget(self.bs, route, self.budget) for route in routes)
