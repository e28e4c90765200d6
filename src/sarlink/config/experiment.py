"""Experiments: a base mission, a grid over its parameters, many runs per grid point.

Common random numbers: every grid point uses the experiment's one seed and the run indices
``0 .. runs-1``, and run ``k`` draws its target and take-off from ``(seed, k)`` alone. So run
``k`` of every grid point searches for the same target, differences between points are not
blurred by different targets, and no row depends on how the runs were cut into tasks or spread
over workers. Running an experiment is :func:`sarlink.sweep` (:mod:`sarlink.execution`).
"""

from __future__ import annotations

import hashlib
import itertools
import math
from pathlib import Path
from typing import Any, Self

from pydantic import Field, field_validator, model_validator
from pydantic_core import to_json

from sarlink.config.base import Checked, ConfigError, read_toml
from sarlink.config.mission import Mission, param_groups
from sarlink.config.readings import EARLIER_CHOICES

__all__ = ["MAX_POINTS", "MAX_RUNS", "MAX_WORKERS", "Experiment", "mission_hash"]

MAX_POINTS = 100_000
"""Most grid points in one experiment: each is a folder of files and a line of the manifest."""
MAX_WORKERS = 1024
"""Most local worker processes: more than the cores only adds overhead, and each process is
a Python interpreter with its own memory."""
MAX_RUNS = 1_000_000_000
"""Most runs per grid point (run indices are stored as 64-bit integers, and even a fast run
takes a millisecond)."""


ADDED_LATER: dict[str, dict[str, Any]] = {
    "team": {"relays": 0, "relay_strategy": "tree", "relay_priority": "nearest-first",
             "relay_estimate": "reckoned"},
    "channel": {"radio": None, "decorrelation": 50.0},
    "readings": EARLIER_CHOICES,
    "battery": {"energy_model": None, "battery_wh": None, "reserve": 0.2, "swap_time": 120.0,
                "spares": None},
    "target": {"count": 1, "success": "all", "motion": "still", "delay": 0.0,
               "motion_step": 0.0, "walk_speed": 0.5, "walk_turn": 0.5, "walk_mobile": 14400.0,
               "walk_spread": 1.0, "drift_object": "PIW-1",
               "drift_wind": [[0.0, 0.0, 0.0]], "drift_current": [[0.0, 0.0, 0.0]]},
}
"""Parameters added after results were first stored, with the value that keeps the earlier
behaviour: left out of the hash at that value, so earlier results folders stay valid (a group
left empty so is left out too)."""


def mission_hash(mission: Mission) -> str:
    """A short content hash of every parameter of ``mission``: the name of its results folder."""
    data = mission.model_dump(mode="json")
    target = data.get("target", {})
    if target.get("motion", "still") == "still":  # it never moves, whatever its time step
        target.pop("motion_step", None)
    for group, fields in ADDED_LATER.items():
        for name, value in fields.items():
            if data.get(group, {}).get(name, value) == value:
                data.get(group, {}).pop(name, None)
        if data.get(group) == {}:
            data.pop(group)
    return hashlib.sha256(to_json(data)).hexdigest()[:16]  # the bytes of model_dump_json


def _label(params: dict[str, Any]) -> str:
    return ", ".join(f"{k}={v!r}" for k, v in params.items()) or "(the base mission)"


class Experiment(Checked):
    """A base mission, a grid of parameter values, and ``runs`` runs of every grid point.

    ``grid`` maps flat mission parameters (``planner``, ``drones``, ``rc``, ``p_miss``, ...; see
    :meth:`Mission.params`) to the values to try; the grid points are their cartesian product.
    ``Experiment.from_toml`` reads ``name`` (default: the file's name without ``.toml``),
    ``seed``, ``runs``, ``chunk``, ``[mission.*]`` (the tables of :class:`Mission`) and
    ``[grid]``.
    """

    name: str = Field("experiment", min_length=1,
                      description="a name for people; not part of the identity")
    seed: int = Field(ge=0, le=2**63 - 1, strict=True,
                      description="the one seed of every run of every grid point, an integer >= 0")
    runs: int = Field(ge=1, le=MAX_RUNS, strict=True,
                      description="runs per grid point, indices 0 .. runs-1, an integer >= 1")
    chunk: int = Field(100, ge=1, le=MAX_RUNS, strict=True,
                       description="runs per task; results do not depend on it")
    mission: Mission = Field(default_factory=Mission, description="the base mission")
    grid: dict[str, list[Any]] = Field(default_factory=dict,
                                       description="flat parameter -> values to try")
    staircase: bool = Field(False, description=(
        "rows of teams that fly the same at every range carry their notification staircase "
        "(notify_times, notify_rc2), which sarlink.at_range evaluates at any range; costs most "
        "of a flight per run unless the grid has several rc of the point"))

    @classmethod
    def from_toml(cls, path: str | Path) -> Self:
        """Read an experiment file; without a ``name`` it is named after the file."""
        data = read_toml(path)
        data.setdefault("name", Path(path).stem or "experiment")
        return cls.from_file_data(path, data)

    @field_validator("grid")
    @classmethod
    def _known_parameters(cls, grid: dict[str, list[Any]]) -> dict[str, list[Any]]:
        known = param_groups()
        for name, values in grid.items():
            if name not in known:
                raise ValueError(f"unknown mission parameter {name!r}; "
                                 f"known: {', '.join(sorted(known))}")
            if not values:
                raise ValueError(f"{name!r} lists no values")
        size = math.prod(len(values) for values in grid.values())
        if size > MAX_POINTS:
            raise ValueError(f"the grid has {size:,} points; at most {MAX_POINTS:,} are allowed")
        return grid

    @model_validator(mode="after")
    def _valid_points(self) -> Self:
        self.points()
        return self

    def points(self) -> list[tuple[dict[str, Any], Mission]]:
        """Every grid point, in grid order (the last parameter varies fastest).

        Each point is its grid values, as the mission holds them (``rc = 500`` reads ``500.0``),
        and its mission. Raises ``ValueError`` naming the point if one is not a valid mission
        or two points are the same mission.
        """
        names = list(self.grid)
        points: list[tuple[dict[str, Any], Mission]] = []
        seen: dict[str, dict[str, Any]] = {}
        for values in itertools.product(*self.grid.values()):
            raw = dict(zip(names, values, strict=True))
            try:
                mission = self.mission.replace(**raw)
            except ConfigError as exc:
                raise ValueError(f"grid point {_label(raw)}: {exc}") from None
            flat = mission.params()
            params = {name: flat[name] for name in names}
            key = mission_hash(mission)
            if key in seen:
                raise ValueError(f"grid points {_label(seen[key])} and {_label(params)} are the "
                                 "same mission")
            seen[key] = params
            points.append((params, mission))
        return points
