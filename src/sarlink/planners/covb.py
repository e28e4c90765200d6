"""CovB: distributed coverage by mutual repulsion (Section 3.1.2, Eqs. 6-8)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from sarlink.engine.codes import Rule
from sarlink.planners.base import Steering

if TYPE_CHECKING:
    from sarlink.config import Mission


@dataclass(frozen=True)
class CovB:
    name: str = "covb"
    label: str = "CovB"
    colour: str = "#ff7f0e"
    marker: str = "s"
    rule: Rule = Rule.COVB

    def steering(self, mission: Mission) -> Steering:
        return Steering(rule=self.rule, alpha=1.0)
