"""sarlink: plan and simulate search-and-rescue drone teams that must notify their base station."""

import importlib
from typing import TYPE_CHECKING

from sarlink.config import (
    Area,
    Channel,
    ConfigError,
    Experiment,
    Mission,
    MtspSettings,
    Sensing,
    Team,
    Timing,
)
from sarlink.engine import (
    DistributedRule,
    Observation,
    Params,
    RadioModel,
    Scenario,
    radio_names,
    register_radio,
)
from sarlink.planners import (
    RoutePlanner,
    RulePlanner,
    get_planner,
    planner_names,
    register_planner,
)
from sarlink.playback import Replay, replay
from sarlink.result import RunResult, Trajectory
from sarlink.simulation import prepare, simulate

if TYPE_CHECKING:
    from sarlink.execution import sweep
    from sarlink.ranges import at_range
    from sarlink.sizing import design
    from sarlink.storage import load

_LAZY = {"sweep": "sarlink.execution", "load": "sarlink.storage", "design": "sarlink.sizing",
         "at_range": "sarlink.ranges"}
"""Names whose modules import pandas and pyarrow (most of a second): loaded on first use, so
that a single simulation starts without them."""


def __getattr__(name: str) -> object:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'sarlink' has no attribute {name!r}")


__version__ = "0.1.0"

__all__ = [
    "Area",
    "Channel",
    "ConfigError",
    "DistributedRule",
    "Experiment",
    "Mission",
    "MtspSettings",
    "Observation",
    "Params",
    "RadioModel",
    "Replay",
    "RoutePlanner",
    "RulePlanner",
    "RunResult",
    "Scenario",
    "Sensing",
    "Team",
    "Timing",
    "Trajectory",
    "at_range",
    "design",
    "get_planner",
    "load",
    "planner_names",
    "prepare",
    "radio_names",
    "register_planner",
    "register_radio",
    "replay",
    "simulate",
    "sweep",
]
