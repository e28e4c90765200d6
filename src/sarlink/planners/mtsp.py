"""mTSP: every drone flies its part of one centralized plan (Section 3.1.1)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from sarlink.engine.codes import Rule
from sarlink.planners.base import Steering

if TYPE_CHECKING:
    from sarlink.config import Mission


@dataclass(frozen=True)
class Mtsp:
    name: str = "mtsp"
    label: str = "mTSP"
    colour: str = "#1f77b4"
    marker: str = "o"
    rule: Rule = Rule.NONE

    def steering(self, mission: Mission) -> Steering:
        # imported here so that the registry loads without Numba kernels or OR-Tools
        from sarlink.mtsp import plan_for

        routes = plan_for(mission, mission.team.drones).routes()
        return Steering(rule=self.rule, routes=routes)
