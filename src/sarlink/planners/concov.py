"""ConCov: coverage and connectivity forces blended by ``alpha`` (Eq. 12, Algorithm 2)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from sarlink.engine.codes import Rule
from sarlink.planners.base import Steering

if TYPE_CHECKING:
    from sarlink.config import Mission


@dataclass(frozen=True)
class ConCov:
    name: str = "concov"
    label: str = "ConCov"
    colour: str = "#9467bd"
    marker: str = "v"
    rule: Rule = Rule.CONCOV

    def steering(self, mission: Mission) -> Steering:
        return Steering(rule=self.rule, alpha=mission.team.alpha)
