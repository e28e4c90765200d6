"""sarlink: plan and simulate search-and-rescue drone teams that must notify their base station."""

import importlib
import sys
import types
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
    RelayStrategy,
    Scenario,
    TargetMotion,
    radio_names,
    register_radio,
    register_relay_strategy,
    register_target_motion,
    relay_strategy_names,
    target_motion_names,
)
from sarlink.engine.energy import EnergyModel, energy_model_names, register_energy_model
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
    from sarlink.at_range import at_range
    from sarlink.design import design
    from sarlink.execution import sweep
    from sarlink.storage import load

_LAZY = {"sweep": "sarlink.execution", "load": "sarlink.storage", "design": "sarlink.design",
         "at_range": "sarlink.at_range"}
"""Names whose modules import pandas and pyarrow (most of a second): loaded on first use, so
that a single simulation starts without them."""


def __getattr__(name: str) -> object:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'sarlink' has no attribute {name!r}")


class _Package(types.ModuleType):
    """The package ``sarlink``, whose names ``design`` and ``at_range`` stay the functions.

    Importing the module of the same name (``from sarlink.design import DesignRequest``)
    would otherwise bind ``sarlink.design`` to it, and ``sarlink.design(...)`` would call a
    module; as when a package imports such a function eagerly, the module stays importable by
    its full name (``from sarlink.design import search``).
    """

    def __setattr__(self, name: str, value: object) -> None:
        if _LAZY.get(name) == f"sarlink.{name}" and isinstance(value, types.ModuleType):
            return
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package


__version__ = "0.1.0"

__all__ = [
    "Area",
    "Channel",
    "ConfigError",
    "DistributedRule",
    "EnergyModel",
    "Experiment",
    "Mission",
    "MtspSettings",
    "Observation",
    "Params",
    "RadioModel",
    "RelayStrategy",
    "Replay",
    "RoutePlanner",
    "RulePlanner",
    "RunResult",
    "Scenario",
    "Sensing",
    "TargetMotion",
    "Team",
    "Timing",
    "Trajectory",
    "at_range",
    "design",
    "energy_model_names",
    "get_planner",
    "load",
    "planner_names",
    "prepare",
    "radio_names",
    "register_energy_model",
    "register_planner",
    "register_radio",
    "register_relay_strategy",
    "register_target_motion",
    "relay_strategy_names",
    "replay",
    "simulate",
    "sweep",
    "target_motion_names",
]
