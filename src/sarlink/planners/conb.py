"""ConB: distributed planner that keeps drones attached to the BS (Section 3.2, Eqs. 9-11)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from sarlink.engine.codes import Rule
from sarlink.planners.base import Steering

if TYPE_CHECKING:
    from sarlink.config import Mission


@dataclass(frozen=True)
class ConB:
    name: str = "conb"
    label: str = "ConB"
    colour: str = "#2ca02c"
    marker: str = "^"
    rule: Rule = Rule.CONB

    def steering(self, mission: Mission) -> Steering:
        return Steering(rule=self.rule, alpha=0.0)
