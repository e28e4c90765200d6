"""The paper's five planners, on the same public seams as any plug-in (Sections 3.1-3.3)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from sarlink.engine.rules import CONB, CONCOV, COVB
from sarlink.planners.base import RoutePlanner, RulePlanner

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["CONB_PLANNER", "CONCOV_PLANNER", "COVB_PLANNER", "MTSP", "MTSP_CONB", "MTSP_PLANNERS",
           "PAPER"]


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


MTSP = RoutePlanner("mtsp", "mTSP", mtsp_routes, colour="#1f77b4", marker="o", mtsp=True)
COVB_PLANNER = RulePlanner("covb", "CovB", COVB, colour="#ff7f0e", marker="s")
CONB_PLANNER = RulePlanner("conb", "ConB", CONB, colour="#2ca02c", marker="^")
MTSP_CONB = RulePlanner("mtsp-conb", "mTSP-ConB", CONB, colour="#d62728", marker="D",
                        routes=mtsp_conb_routes, mtsp=True)
CONCOV_PLANNER = RulePlanner("concov", "ConCov", CONCOV, colour="#9467bd", marker="v")

PAPER = (MTSP, COVB_PLANNER, CONB_PLANNER, MTSP_CONB, CONCOV_PLANNER)
"""The paper's planners in the order of its legends."""

MTSP_PLANNERS = (MTSP.name, MTSP_CONB.name)
"""The planners that fly mTSP plans (``[mtsp]`` settings reach them)."""
