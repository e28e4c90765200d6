"""What a mission planner asks: a mission, a deadline, a required success probability.

Every field is checked when the request is made; errors raise :class:`ConfigError` naming the
field and its allowed range (the CLI shows the field as its option, ``ps`` as ``--ps``).
"""

from __future__ import annotations

import itertools
from typing import Any, Self

from pydantic import Field, field_validator, model_validator

from sarlink.config import Checked, ConfigError, Mission, param_groups
from sarlink.design.candidates import Candidate, PlannerVariant
from sarlink.design.sequential import Schedule
from sarlink.planners import planner_names

__all__ = ["DesignRequest"]

_SET_BY_DESIGN = ("planner", "drones", "horizon", "stop")
"""Mission parameters the design sets itself, so not options."""


class DesignRequest(Checked):
    """The question ``sarlink design`` answers, and how much work it may spend on it.

    ``P_s(td)`` of each candidate must reach ``ps``, judged at ``confidence``: a team is said
    to meet the requirement when its ``P_s`` is at least ``ps`` with that confidence.
    """

    mission: Mission = Field(default_factory=Mission,
                             description="the base mission: area, BS, r_c, sensing, ...")
    td: float = Field(gt=0, description="target duration t_d, s")
    ps: float = Field(gt=0, lt=1, description="required P_s(t_d)")
    planners: tuple[str, ...] = Field(default_factory=lambda: tuple(planner_names()),
                                      description="planners to consider")
    options: dict[str, list[Any]] = Field(
        default_factory=lambda: {"on_detect": ["continue", "report"]},
        description="extra flat mission parameters -> values; every planner is also tried "
        "with each combination; default: with and without drones that report "
        "(on_detect = continue, report; continue alone with several targets, as reporting "
        "follows one)")
    max_drones: int = Field(22, ge=1, le=1000, description="largest team considered")
    min_drones: int = Field(1, ge=1, le=1000, description="smallest team considered; equal to "
                            "max_drones: that team alone (with split: its best split)")
    split: bool = Field(False, description="tune the team's split: at every team size, every "
                        "relay count from 0 to all but one drone (team.relays), each planner's "
                        "own setting held at the mission's value")
    confidence: float = Field(0.95, gt=0.5, lt=1,
                              description="two-sided confidence of the interval on P_s")
    first_runs: int = Field(50, ge=10, description="runs of a candidate at its first look")
    candidate_runs: int = Field(6400, ge=10,
                                description="most runs of one candidate (the last look)")
    max_runs: int = Field(400_000, ge=1, description="budget: runs used by the whole design")
    margin: float = Field(0.01, gt=0, lt=1, description="settings whose P_s is shown to be "
                          "within this margin of the best are equally good")
    alpha_step: float = Field(0.1, gt=0, le=0.5, description="ConCov alpha grid spacing")
    alpha_tol: float = Field(0.025, gt=0, le=0.5,
                             description="finest alpha spacing of the refinement")
    seed: int = Field(2024, ge=0, description="seed of every run: run k of every candidate "
                      "has the same target")
    every_planner: bool = Field(False, description="answer for every planner (its smallest "
                                "team and setting); else the recommendation alone, for which "
                                "no team larger than the smallest one proven gets runs")

    @model_validator(mode="before")
    @classmethod
    def _several_targets_continue(cls, data: Any) -> Any:
        """With several targets (``target.count > 1``) drones do not report (docs/model.md,
        Several targets): the default options are ``on_detect = continue`` alone."""
        if not isinstance(data, dict) or "options" in data:
            return data
        mission = data.get("mission")
        if isinstance(mission, Mission):
            count = mission.target.count
        else:
            count = ((mission or {}).get("target") or {}).get("count", 1)
        if isinstance(count, int) and count > 1:
            return {**data, "options": {"on_detect": ["continue"]}}
        return data

    @field_validator("planners")
    @classmethod
    def _known_planners(cls, planners: tuple[str, ...]) -> tuple[str, ...]:
        if not planners:
            raise ValueError(f"name at least one planner of {', '.join(planner_names())}")
        for name in planners:
            if name not in planner_names():
                raise ValueError(f"unknown planner {name!r}; known: {', '.join(planner_names())}")
        if len(set(planners)) < len(planners):
            raise ValueError("a planner is named twice")
        return planners

    @field_validator("options")
    @classmethod
    def _known_options(cls, options: dict[str, list[Any]]) -> dict[str, list[Any]]:
        known = param_groups()
        for name, values in options.items():
            if name in _SET_BY_DESIGN:
                raise ValueError(f"{name!r} is set by the design itself, not an option")
            if name not in known:
                raise ValueError(f"unknown mission parameter {name!r}; "
                                 f"known: {', '.join(sorted(set(known) - set(_SET_BY_DESIGN)))}")
            if not values:
                raise ValueError(f"{name!r} lists no values")
        return options

    @field_validator("alpha_step")
    @classmethod
    def _divides_one(cls, step: float) -> float:
        if abs(1 / step - round(1 / step)) > 1e-9:
            raise ValueError(f"must divide 1 into equal parts (0.1, 0.125, 0.25, ...), got {step}")
        return step

    @model_validator(mode="after")
    def _consistent(self) -> Self:
        horizon = self.mission.timing.horizon
        if self.td > horizon:
            raise ValueError(f"td: {self.td:g} s is beyond the mission's horizon of "
                             f"{horizon:g} s (timing.horizon)")
        if self.first_runs > self.candidate_runs:
            raise ValueError(f"first_runs: {self.first_runs} exceeds candidate_runs "
                             f"({self.candidate_runs})")
        if self.min_drones > self.max_drones:
            raise ValueError(f"min_drones: {self.min_drones} exceeds max_drones "
                             f"({self.max_drones})")
        if self.split and "relays" in self.options:
            raise ValueError("split: tunes the relay count, which options fix (relays = "
                             f"{', '.join(map(str, self.options['relays']))}): give one or "
                             "the other")
        if self.split and self.max_drones < 2:
            raise ValueError("split: a team of one drone has no split (its drone searches); "
                             "allowed with max_drones of 2 or more")
        try:
            self.base()
        except ConfigError as exc:
            raise ValueError(f"td: {self.td:g} s does not fit the mission: {exc}") from None
        for variant in self.variants():  # every combination must be a valid mission
            try:  # at the largest team, where the fewest values are out of range
                Candidate(variant, self.max_drones, 0 if variant.split else None
                          ).mission(self.mission)
            except ConfigError as exc:
                relays = self.mission.team.relays
                if not variant.split and "relays" not in dict(variant.fixed) and \
                        relays >= self.max_drones:
                    raise ValueError(f"max_drones: {self.max_drones} drones leave no searcher "
                                     f"beside the mission's team.relays = {relays}; allowed: "
                                     f"more than {relays}") from None
                raise ValueError(f"options: {variant.label}: {exc}") from None
        return self

    def base(self) -> Mission:
        """The mission every candidate starts from: simulated to ``td`` and no further, and
        only until the BS is notified, the one event ``P_s(td)`` reads; an mTSP team flies
        the one plan of its size that would be exported (``mtsp_plan = shared``, seed
        ``mtsp.plan_seed``), solved once, not a plan per run."""
        return self.mission.replace(horizon=self.td, stop="notified", mtsp_plan="shared")

    def variants(self) -> list[PlannerVariant]:
        """Every planner with every combination of the options, in request order."""
        names = list(self.options)
        return [PlannerVariant(planner, tuple(zip(names, values, strict=True)), self.split)
                for planner in self.planners
                for values in itertools.product(*self.options.values())]

    def sizes(self, variant: PlannerVariant) -> range:
        """The team sizes considered for ``variant``: ``min_drones`` to ``max_drones``, none
        so small that its fixed relays leave no searcher."""
        return range(max(self.min_drones, variant.fewest(self.mission)), self.max_drones + 1)

    def schedule(self) -> Schedule:
        """When a candidate is looked at: ``first_runs``, then doubling up to
        ``candidate_runs``."""
        return Schedule(self.first_runs, self.candidate_runs)

    @property
    def error(self) -> float:
        """The one-sided error of the two-sided ``confidence`` interval (0.025 at 95 %)."""
        return (1 - self.confidence) / 2
