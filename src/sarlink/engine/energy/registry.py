"""The energy models by name (:class:`sarlink.registry.Registry` of kind ``energy_model``):
the built-in ones (:mod:`sarlink.engine.energy`), those registered in code, and those of
installed packages (entry point group ``sarlink.energy_models``)."""

from __future__ import annotations

from typing import Any

from sarlink.config import ConfigError
from sarlink.engine.energy.model import EnergyModel
from sarlink.registry import Registry, caller_origin

__all__ = ["ENERGY_MODELS", "energy_model_names", "get_energy_model", "register_energy_model"]


def _check(obj: object, origin: str) -> None:
    if not isinstance(obj, EnergyModel):
        raise ConfigError(f"register_energy_model takes a sarlink EnergyModel, got {obj!r}")


def _describe(model: EnergyModel) -> dict[str, Any]:
    """The listing's columns: the hover power and the best-range speed, at a glance."""
    if not model.draws_power:
        return {"hover W": 0.0, "range speed m/s": None, "source": model.source}
    return {"hover W": round(model.power(0.0), 1),
            "range speed m/s": round(model.range_speed(), 1), "source": model.source}


ENERGY_MODELS: Registry[EnergyModel] = Registry(
    "energy_model", label="energy model", field="battery.energy_model", check=_check,
    describe=_describe, first=("none", "zeng2019", "rodrigues2021"))
"""Every energy model, by name."""


def register_energy_model(model: EnergyModel, *, replace: bool = False) -> EnergyModel:
    """Make ``model`` selectable as ``battery.energy_model = "<name>"``; returns it. A name
    taken by another model (``none``, ``zeng2019``, ...) needs ``replace``."""
    return ENERGY_MODELS.register(model, replace=replace, origin=caller_origin())


def energy_model_names() -> list[str]:
    """Every energy model's name."""
    return ENERGY_MODELS.names()


def get_energy_model(name: str) -> EnergyModel:
    """The energy model called ``name``; a :class:`ConfigError` naming the known ones else."""
    return ENERGY_MODELS.get(name)
