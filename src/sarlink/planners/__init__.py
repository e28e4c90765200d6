"""Planner registry: planners are looked up by name (``covb``, ``conb``, ``concov``, ...)."""

from __future__ import annotations

from sarlink.planners.base import Planner, Steering
from sarlink.planners.conb import ConB
from sarlink.planners.concov import ConCov
from sarlink.planners.covb import CovB
from sarlink.planners.mtsp import Mtsp
from sarlink.planners.mtsp_conb import MtspConB
from sarlink.planners.patterns import PATTERNS

__all__ = ["PLANNERS", "Planner", "Steering", "get_planner", "planner_names"]

PLANNERS: dict[str, Planner] = {
    p.name: p for p in (Mtsp(), CovB(), ConB(), MtspConB(), ConCov(), *PATTERNS)}
"""Every planner by name: the paper's, in the order of its legends, then the IAMSAR search
patterns; figures draw planners in this order."""


def planner_names() -> list[str]:
    """Names of the registered planners, in registration order (the paper's first)."""
    return list(PLANNERS)


def get_planner(name: str) -> Planner:
    """The planner registered as ``name``."""
    try:
        return PLANNERS[name]
    except KeyError:
        raise KeyError(f"unknown planner {name!r}; known: {', '.join(PLANNERS)}") from None
