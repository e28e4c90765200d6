"""The paper's mTSP planners (Section 3.1.1, Algorithm 1), on the same public seams as any
plug-in; its distributed rules are in :mod:`sarlink.planners.rules`."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from sarlink.planners.base import RoutePlanner, RulePlanner
from sarlink.planners.registry import register_planner
from sarlink.planners.rules.conb import CONB

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["MTSP", "MTSP_CONB", "MTSP_PLANNERS"]


def mtsp_routes(mission: Mission) -> tuple[np.ndarray, ...]:
    """Section 3.1.1: every drone flies its tour of one centralized mTSP plan."""
    # imported here so that the registry loads without Numba kernels or OR-Tools
    from sarlink.mtsp import flyable, plan_for

    return flyable(mission, plan_for(mission, mission.team.drones, compact=_compact(mission))
                   .routes())


def mtsp_conb_routes(mission: Mission) -> tuple[np.ndarray, ...]:
    """Algorithm 1: ``N_r`` drones fly an mTSP plan; the others run ConB."""
    from sarlink.mtsp import flyable, plan_for

    salesmen = min(mission.team.nr, mission.team.drones)
    return flyable(mission, plan_for(mission, salesmen, compact=_compact(mission)).routes())


def _compact(mission: Mission) -> bool:
    """Plans made per run are stored without their GA history, and not kept in memory."""
    return mission.readings.mtsp_plan == "per-run"


MTSP = register_planner(RoutePlanner("mtsp", "mTSP", mtsp_routes, colour="#1f77b4", marker="o",
                                     mtsp=True))
MTSP_CONB = register_planner(RulePlanner("mtsp-conb", "mTSP-ConB", CONB, colour="#d62728",
                                         marker="D", routes=mtsp_conb_routes, mtsp=True))

MTSP_PLANNERS = (MTSP.name, MTSP_CONB.name)
"""The planners that fly mTSP plans (``[mtsp]`` settings reach them)."""
