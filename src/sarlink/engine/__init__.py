"""The simulation engine: Numba kernels in the model's phases and their Python wrapper.

It takes a mission and a :class:`Steering` (rule and routes); the planners that make
steerings live above it (:mod:`sarlink.planners`, :mod:`sarlink.simulation`). Its plug-in
seams are :class:`DistributedRule`, :class:`RadioModel`, :class:`RelayStrategy` and
:class:`TargetMotion` (docs/plugins.md).
"""

from sarlink.engine.hooks import DistributedRule, RadioModel, RelayStrategy
from sarlink.engine.observation import Observation
from sarlink.engine.params import Params
from sarlink.engine.radios import get_radio, radio_names, register_radio
from sarlink.engine.relays import get_relay_strategy, register_relay_strategy, relay_strategy_names
from sarlink.engine.run import Prepared
from sarlink.engine.scenario import Scenario
from sarlink.engine.steering import Steering
from sarlink.engine.target_motion import (
    TargetMotion,
    get_target_motion,
    register_target_motion,
    target_motion_names,
)

__all__ = ["DistributedRule", "Observation", "Params", "Prepared", "RadioModel",
           "RelayStrategy", "Scenario", "Steering", "TargetMotion", "get_radio",
           "get_relay_strategy", "get_target_motion", "radio_names", "register_radio",
           "register_relay_strategy", "register_target_motion", "relay_strategy_names",
           "target_motion_names"]
