"""Planners: the two kinds (:class:`RoutePlanner`, :class:`RulePlanner`), the paper's five,
and the registry that finds any of them by name (docs/plugins.md)."""

from __future__ import annotations

from sarlink.planners.base import Planner, RoutePlanner, RulePlanner, Steering
from sarlink.planners.paper import MTSP_PLANNERS, PAPER
from sarlink.planners.registry import (
    get_planner,
    planner_entries,
    planner_names,
    register_planner,
)

__all__ = ["MTSP_PLANNERS", "PAPER", "PAPER_PLANNERS", "Planner", "RoutePlanner", "RulePlanner",
           "Steering", "get_planner", "planner_entries", "planner_names", "register_planner"]

PAPER_PLANNERS: tuple[str, ...] = tuple(p.name for p in PAPER)
"""The names of the paper's planners, in the order of its legends: what its figures draw."""
