"""mTSP-ConB: ``N_r`` drones fly an mTSP plan, the others run ConB (Algorithm 1)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from sarlink.engine.codes import Rule
from sarlink.planners.base import Steering

if TYPE_CHECKING:
    from sarlink.config import Mission


@dataclass(frozen=True)
class MtspConB:
    name: str = "mtsp-conb"
    label: str = "mTSP-ConB"
    colour: str = "#d62728"
    marker: str = "D"
    rule: Rule = Rule.CONB

    def steering(self, mission: Mission) -> Steering:
        # imported here so that the registry loads without Numba kernels or OR-Tools
        from sarlink.mtsp import plan_for

        drones = mission.team.drones
        planned = min(mission.team.nr, drones)
        routes = plan_for(mission, planned).routes()
        relays = tuple(np.empty((0, 2)) for _ in range(drones - planned))
        return Steering(rule=self.rule, alpha=0.0, routes=routes + relays)
