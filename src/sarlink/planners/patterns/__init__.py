"""The search patterns SAR teams fly (IAMSAR Manual Vol. II), as route planners.

Each pattern is a module with one pure function ``routes(mission)`` (one route per drone,
ending at the BS), made a planner on the public seam (:class:`~sarlink.RoutePlanner`) and
registered by :func:`sarlink.register_planner`.
"""

from __future__ import annotations

from sarlink.planners.base import RoutePlanner
from sarlink.planners.patterns import expanding, parallel, sector
from sarlink.planners.patterns.base import Search
from sarlink.planners.registry import register_planner

__all__ = ["PATTERNS", "Search"]

PATTERNS = tuple(register_planner(pattern) for pattern in (
    RoutePlanner("parallel", "Parallel track", parallel.routes, colour="#8c564b", marker="P"),
    RoutePlanner("expanding-square", "Expanding square", expanding.routes, colour="#17becf",
                 marker="X"),
    RoutePlanner("sector", "Sector", sector.routes, colour="#bcbd22", marker="*"),
))
"""The patterns as planners, with their labels and styles in figures."""
