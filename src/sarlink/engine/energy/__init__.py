"""Energy models: the power a drone draws as it flies (:mod:`.model`, the seam), the built-in
presets (:mod:`.rotor`), registered by :func:`register_energy_model` as a plug-in model is,
and the registry that finds them by name (:mod:`.registry`). docs/model.md, Energy."""

from __future__ import annotations

from sarlink.engine.energy import rotor
from sarlink.engine.energy.model import CLIMB_RATE, DESCENT_RATE, EnergyModel, Flight
from sarlink.engine.energy.registry import (
    ENERGY_MODELS,
    energy_model_names,
    get_energy_model,
    register_energy_model,
)

NONE = register_energy_model(EnergyModel(
    "none", rotor.no_power, rotor.no_power, source="the paper: no battery"))
"""The paper's drones: no battery, so no energy to count."""
ZENG2019 = register_energy_model(EnergyModel(
    "zeng2019", rotor.level, rotor.vertical, rotor.ZENG2019,
    source="Zeng, Xu, Zhang, IEEE TWC 2019, eq. (12) and Table I"))
"""Zeng, Xu and Zhang's rotary-wing model with their published parameters (:mod:`.rotor`)."""
RODRIGUES2021 = register_energy_model(EnergyModel(
    "rodrigues2021", rotor.level, rotor.vertical, rotor.RODRIGUES2021,
    source="zeng2019 scaled to 80 J/m, the measured DJI Matrice 100 (Rodrigues et al. 2021)"))
"""Zeng's curve at the level measured on a small quadcopter (:data:`.rotor.RODRIGUES2021`)."""

__all__ = ["CLIMB_RATE", "DESCENT_RATE", "ENERGY_MODELS", "NONE",
           "RODRIGUES2021", "ZENG2019", "EnergyModel", "Flight", "energy_model_names",
           "get_energy_model", "register_energy_model"]
