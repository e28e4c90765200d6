"""What ``sarlink design`` answers: typed records, and their JSON form."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from sarlink.config import Mission
from sarlink.design.request import DesignRequest
from sarlink.design.runs import Tally
from sarlink.design.sequential import Decision

__all__ = ["CandidateEstimate", "DesignAnswer", "PlannerAnswer", "TeamSize", "Tuning"]

GRID_RUNS = 2000
"""Runs per grid point of the full sweep a design is compared with: the paper's."""


@dataclass(frozen=True)
class CandidateEstimate:
    """``P_s(t_d)`` of one candidate from its runs so far, with the 95 % Wilson interval and
    the sequential test's decision."""

    drones: int
    relays: int
    """Relays among the ``drones``; the others search."""
    value: float | int | None
    """The setting tuned (``alpha``, ``nr``, ``relays``), or None."""
    runs: int
    successes: int
    p: float
    lo: float
    hi: float
    mission_time: float
    """Mean notification time of the successful runs, s."""
    verdict: Decision

    @classmethod
    def of(cls, mission: Mission, value: float | int | None, tally: Tally,
           verdict: Decision) -> CandidateEstimate:
        """The estimate of the candidate flying ``mission`` (its setting at ``value``) from
        its runs' ``tally``, with its Wilson interval."""
        lo, hi = tally.interval()
        return cls(mission.team.drones, mission.team.relays, value, tally.runs,
                   tally.successes, tally.p, lo, hi, tally.mission_time, verdict)

    @property
    def searchers(self) -> int:
        """The drones that search: all but the relays."""
        return self.drones - self.relays


@dataclass(frozen=True)
class TeamSize:
    """One team size of one planner: its verdict and its most successful setting."""

    drones: int
    verdict: Decision
    best: CandidateEstimate
    settings: int
    """How many settings were tried at this size."""


@dataclass(frozen=True)
class Tuning:
    """The planner's setting at its smallest team: the best value and the curve behind it."""

    setting: str
    best: CandidateEstimate
    equivalent: tuple[float | int, ...]
    """Values whose ``P_s`` is not shown to be below the best's (within the margin, or not
    told apart at the cap or when the budget ran out), the best included."""
    curve: tuple[CandidateEstimate, ...]
    """Every value tried, in increasing order."""
    ended_by: str
    """``statistics``: one value is best or the rest are within the margin; ``cap``: every
    value left had its most runs; ``budget``: the budget ran out; ``time``: the time did."""


@dataclass(frozen=True)
class PlannerAnswer:
    """One planner variant: its smallest team meeting the requirement, and its setting there
    (with the split tuned: the relay count, ``chosen.relays``)."""

    planner: str
    label: str
    fixed: dict[str, Any]
    """The variant's extra mission parameters."""
    status: str
    """``reached``, ``not reachable`` (every team size fails), ``undecided``, or for the
    recommendation alone ``larger`` (every size up to the recommended team fails; larger
    ones were not tried) or ``outranked`` (every size below the recommended team fails, and
    at it the planner is shown less successful than the recommendation)."""
    smallest: int | None
    chosen: CandidateEstimate | None
    """The candidate at the smallest team, at its best setting."""
    undecided: tuple[int, ...]
    """Smaller team sizes that stayed borderline or open, or were outranked below this
    planner's smallest: the true smallest may be one."""
    team_sizes: tuple[TeamSize, ...]
    tuning: Tuning | None
    held: dict[str, Any]
    """With the split tuned, the planner's own setting held at the base mission's value
    (``{"alpha": 0.5}``); empty otherwise."""


@dataclass(frozen=True)
class DesignAnswer:
    """What :func:`sarlink.design` found: per planner its smallest team and setting, the
    recommendation, and the runs it took."""

    request: DesignRequest
    planners: tuple[PlannerAnswer, ...]
    recommended: int | None
    """Index in ``planners`` of the recommendation, or None if no planner reaches ``ps``."""
    runs_used: int
    """Runs the decisions rest on (stored earlier or simulated now)."""
    runs_simulated: int
    grid_points: int
    """Candidates of the full grid at the finest setting resolution the design reached."""
    ended_by: str
    """``statistics``, ``budget`` when ``max_runs`` stopped runs the search wanted, or
    ``time`` when ``max_seconds`` stopped the search after a round."""

    @property
    def recommendation(self) -> PlannerAnswer | None:
        """The planner recommended (the smallest team overall), or None if none reaches
        ``ps``."""
        return None if self.recommended is None else self.planners[self.recommended]

    @property
    def grid_runs(self) -> int:
        """Runs of a full grid sweep at the paper's 2000 runs per point."""
        return self.grid_points * GRID_RUNS

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready dict (NaN as null)."""
        data = {
            "request": self.request.model_dump(mode="json"),
            "recommendation": (None if self.recommendation is None
                               else asdict(self.recommendation)),
            "planners": [asdict(p) for p in self.planners],
            "runs": {"used": self.runs_used, "simulated": self.runs_simulated,
                     "reused": self.runs_used - self.runs_simulated,
                     "budget": self.request.max_runs, "grid_points": self.grid_points,
                     "grid_runs": self.grid_runs, "grid_runs_per_point": GRID_RUNS},
            "ended_by": self.ended_by,
        }
        return _finite(data)


def _finite(value: Any) -> Any:
    """``value`` with NaN floats as None (JSON has no NaN)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_finite(v) for v in value]
    return value
