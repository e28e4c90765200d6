"""The search patterns SAR teams fly (IAMSAR Manual Vol. II), as route planners.

Each pattern is a module with one pure function ``routes(mission)`` (one route per drone,
ending at the BS); :data:`PATTERNS` names them as planners.
"""

from __future__ import annotations

from sarlink.planners.patterns import expanding, parallel, sector
from sarlink.planners.patterns.base import RoutePattern, Search

__all__ = ["PATTERNS", "RoutePattern", "Search"]

PATTERNS = (
    RoutePattern("parallel", "Parallel track", "#8c564b", "P", parallel.routes),
    RoutePattern("expanding-square", "Expanding square", "#17becf", "X", expanding.routes),
    RoutePattern("sector", "Sector", "#bcbd22", "*", sector.routes),
)
"""The patterns as planners, with their labels and styles in figures."""
