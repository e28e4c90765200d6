"""The teams a design considers: planner variants, their tunable setting, team sizes.

A *variant* is a planner with fixed extra mission parameters (``{"look": "per-period"}``, or a
team option added later such as ``on_detect``): a new option is a parameter of the request,
not a change here. A planner may have one tunable *setting* (:data:`SETTINGS`), searched at
every team size unless the variant fixes it. A *candidate* is a variant, a team size and a
value of the setting: one mission, whose runs are stored like a sweep's grid point.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from sarlink.config import Mission
from sarlink.planners import get_planner

__all__ = ["SETTINGS", "Candidate", "PlannerVariant", "Setting", "refinements"]


@dataclass(frozen=True)
class Setting:
    """A planner's tunable mission parameter and the values it may take.

    A continuous setting (ConCov's ``alpha`` in [0, 1]) is searched on a grid that the search
    refines; a discrete one (mTSP-ConB's ``nr`` in 1..N_m) is tried at every value.
    """

    name: str
    continuous: bool

    def grid(self, drones: int, step: float) -> tuple[float | int, ...]:
        """The values tried at team size ``drones``: every ``step`` in [0, 1], or 1..drones."""
        if self.continuous:
            count = round(1 / step)
            return tuple(float(v) for v in np.round(np.linspace(0.0, 1.0, count + 1), 12))
        return tuple(range(1, drones + 1))

    def size(self, drones: int, step: float, finest: float) -> int:
        """How many values can ever be tried at ``drones``: the grid, and two more for each
        halving of ``step`` down to ``finest`` (the search refines only around the best)."""
        if not self.continuous:
            return drones
        return len(self.grid(drones, step)) + 2 * refinements(step, finest)


def refinements(step: float, finest: float) -> int:
    """How often ``step`` can be halved before it falls below ``finest``."""
    count = 0
    while step / 2 >= finest * (1 - 1e-9):
        step /= 2
        count += 1
    return count


SETTINGS: dict[str, Setting] = {
    "concov": Setting("alpha", continuous=True),
    "mtsp-conb": Setting("nr", continuous=False),
}
"""The tunable setting of each planner that has one (Eq. 12's alpha; the mTSP-ConB N_r)."""


@dataclass(frozen=True)
class PlannerVariant:
    """A planner with fixed extra mission parameters; tuned over ``setting`` if it has one."""

    planner: str
    fixed: tuple[tuple[str, Any], ...] = ()

    @property
    def setting(self) -> Setting | None:
        """The setting tuned for this planner (ConCov's alpha, mTSP-ConB's nr), unless it is
        one of the fixed parameters."""
        setting = SETTINGS.get(self.planner)
        if setting is None or setting.name in dict(self.fixed):
            return None
        return setting

    @property
    def label(self) -> str:
        """The planner's label with the fixed parameters, for tables."""
        extra = ", ".join(f"{k}={v}" for k, v in self.fixed)
        name = get_planner(self.planner).label
        return f"{name} ({extra})" if extra else name

    def params(self) -> dict[str, Any]:
        """The variant's flat mission parameters."""
        return {"planner": self.planner, **dict(self.fixed)}


@dataclass(frozen=True)
class Candidate:
    """A variant flying ``drones`` drones with its setting at ``value`` (None: no setting)."""

    variant: PlannerVariant
    drones: int
    value: float | int | None = None

    def mission(self, base: Mission) -> Mission:
        """``base`` flown by this candidate's planner, team and setting."""
        params = {**self.variant.params(), "drones": self.drones}
        setting = self.variant.setting
        if setting is not None and self.value is not None:
            params[setting.name] = self.value
        return base.replace(**params)
