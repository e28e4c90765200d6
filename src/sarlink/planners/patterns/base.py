"""What a search pattern is planned from, and the planner that flies one.

A pattern is a pure function ``routes(mission) -> tuple[np.ndarray, ...]``: one route per
drone, each ending at the BS (the engine's route format, :class:`sarlink.engine.Steering`).
:data:`sarlink.planners.patterns.PATTERNS` makes each a :class:`~sarlink.RoutePlanner`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from sarlink.config.region import area_polygon, is_polygon
from sarlink.planners.patterns.geometry import Rect, fit_budget
from sarlink.planners.patterns.polygon import Clipped

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["Search"]


@dataclass(frozen=True)
class Search:
    """A mission as the patterns see it: the area, the BS, the team, the track spacing and
    the flight budget."""

    area: Rect
    """The rectangle the pattern is laid over: the paper's square, or the bounding box of an
    area on the map (``on_map``)."""
    bs: tuple[float, float]
    drones: int
    spacing: float
    """Track spacing S, m: the sweep width of a definite-range sensor of range r, 2 r (an
    IAMSAR coverage factor of 1)."""
    budget: float
    """Metres a drone may fly, landing included: V (T_max − 2 dt), the two steps of margin
    the engine gives a distributed drone's return home."""
    on_map: Clipped | None = None
    """An area on the map (a polygon with holes), to which the routes are clipped
    (:mod:`.polygon`); ``None`` on the paper's square."""

    @classmethod
    def of(cls, mission: Mission) -> Search:
        team, timing = mission.team, mission.timing
        area, on_map = Rect.square(mission.area.size), None
        if is_polygon(mission.region):
            polygon = area_polygon(mission.region, mission.area.size)
            area, on_map = Rect(*polygon.bounds), Clipped(polygon, mission.area.bs_xy)
        return cls(area=area, bs=mission.area.bs_xy, drones=team.drones,
                   spacing=2.0 * mission.sensing.r,
                   budget=team.speed * (team.flight_time - 2.0 * timing.dt), on_map=on_map)

    def exit(self, angle: float) -> np.ndarray:
        """Where the ray from the BS at ``angle`` (radians) leaves the area."""
        if self.on_map is None:
            return self.area.exit(self.bs, angle)
        return self.on_map.exit(angle)

    def fit(self, routes: tuple[np.ndarray, ...]) -> tuple[np.ndarray, ...]:
        """Each route cut where its drone must turn home to land within the budget; on the
        map, first clipped to the area."""
        if self.on_map is None:
            return tuple(fit_budget(self.bs, route, self.budget) for route in routes)
        return tuple(self.on_map.fit(self.on_map.clip(route), self.budget) for route in routes)
