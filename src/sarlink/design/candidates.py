"""The teams a design considers: planner variants, their tunable setting, team sizes.

A *variant* is a planner with fixed extra mission parameters (``{"look": "per-period"}``, or a
team option added later such as ``on_detect``): a new option is a parameter of the request,
not a change here. A variant has at most one tunable *setting*, searched at every team size:
the planner's own (:data:`SETTINGS`) unless the variant fixes it, or, for a variant that tunes
the *split*, the team's relay count (:data:`RELAYS`), the planner's own setting then held at
the base mission's value. A *candidate* is a variant, a team size and a value of the setting:
one mission, whose runs are stored like a sweep's grid point.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from sarlink.config import Mission
from sarlink.planners import get_planner

__all__ = ["RELAYS", "SETTINGS", "Candidate", "PlannerVariant", "Setting", "refinements"]


@dataclass(frozen=True)
class Setting:
    """A tunable mission parameter (a planner's own, or the team's split) and its values.

    A continuous setting (ConCov's ``alpha`` in [0, 1]) is searched on a grid that the search
    refines; a discrete one is tried at every value from ``low`` to ``drones - spare`` for a
    team of ``drones`` (mTSP-ConB's ``nr`` in 1..N_m, the relays in 0..N_m - 1).
    """

    name: str
    continuous: bool
    low: int = 1
    """A discrete setting's smallest value."""
    spare: int = 0
    """How far below the team a discrete setting's largest value stays."""

    def grid(self, drones: int, step: float) -> tuple[float | int, ...]:
        """The values tried at team size ``drones``: every ``step`` in [0, 1], or
        ``low..drones - spare``."""
        if self.continuous:
            count = round(1 / step)
            return tuple(float(v) for v in np.round(np.linspace(0.0, 1.0, count + 1), 12))
        return tuple(range(self.low, drones - self.spare + 1))

    def size(self, drones: int, step: float, finest: float) -> int:
        """How many values can ever be tried at ``drones``: the grid, and for a continuous
        setting two more for each halving of ``step`` down to ``finest`` (the search refines
        only around the best)."""
        extra = 2 * refinements(step, finest) if self.continuous else 0
        return len(self.grid(drones, step)) + extra


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

RELAYS = Setting("relays", continuous=False, low=0, spare=1)
"""The split of a team: how many of its drones are relays, from none to all but one searcher
(``team.relays``, docs/model.md, Relays)."""


@dataclass(frozen=True)
class PlannerVariant:
    """A planner with fixed extra mission parameters; tuned over ``setting`` if it has one.

    With ``split`` the setting is the team's relay count; otherwise the relays are fixed, by
    the variant or by the base mission, and a team must have a searcher beside them.
    """

    planner: str
    fixed: tuple[tuple[str, Any], ...] = ()
    split: bool = False

    @property
    def setting(self) -> Setting | None:
        """The setting tuned for this variant: the relay count if it tunes the split, else
        the planner's own (ConCov's alpha, mTSP-ConB's nr) unless it is a fixed parameter."""
        if self.split:
            return RELAYS
        return self.own

    @property
    def own(self) -> Setting | None:
        """The planner's own setting, unless the variant fixes it; when the split is tuned it
        is held at the base mission's value rather than tuned."""
        setting = SETTINGS.get(self.planner)
        if setting is None or setting.name in dict(self.fixed):
            return None
        return setting

    def relays(self, base: Mission) -> int:
        """The relay count of a variant that does not tune the split: its own, else the base
        mission's."""
        return int(dict(self.fixed).get("relays", base.team.relays))

    def fewest(self, base: Mission) -> int:
        """The smallest team this variant can fly: one searcher beside its fixed relays (any
        team, when the split is tuned: its relays start at none)."""
        return 1 if self.split else self.relays(base) + 1

    def span(self, drones: int, base: Mission) -> int:
        """The team size the setting ranges over at ``drones``: the whole team for the split;
        the searchers for the planner's own setting, since the planner plans them alone
        (:meth:`~sarlink.config.Mission.searching`)."""
        return drones if self.split else drones - self.relays(base)

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
