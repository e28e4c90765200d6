"""Planners: the two kinds (:class:`RoutePlanner`, :class:`RulePlanner`), the registry that finds
any of them by name (docs/plugins.md), and the built-in ones, which register through it as a
plug-in does: the paper's (:mod:`.paper`, :mod:`.rules`) and the search patterns
(:mod:`.patterns`)."""

from __future__ import annotations

from sarlink.planners import paper, patterns, rules  # noqa: F401  (they register the built-ins)
from sarlink.planners.base import Planner, RoutePlanner, RulePlanner, Steering
from sarlink.planners.paper import MTSP_PLANNERS
from sarlink.planners.registry import (
    PAPER_PLANNERS,
    get_planner,
    planner_entries,
    planner_names,
    register_planner,
)

__all__ = ["MTSP_PLANNERS", "PAPER_PLANNERS", "Planner", "RoutePlanner", "RulePlanner",
           "Steering", "get_planner", "planner_entries", "planner_names", "register_planner"]
