"""The radio models by name (:class:`sarlink.registry.Registry` of kind ``radio``): the built-in
ones (:mod:`.lognormal`), those registered in code, and those of installed packages (entry
point group ``sarlink.radios``)."""

from __future__ import annotations

from typing import Any

from sarlink.config import ConfigError
from sarlink.engine.hooks import RadioModel, python_function
from sarlink.registry import SARLINK, Registry, caller_origin

__all__ = ["RADIOS", "get_radio", "radio_names", "register_radio"]


def _check(obj: object, origin: str) -> None:
    """A radio model, declaring ``range_free`` only with the hooks of one of sarlink's own
    range-free models: the range scan redraws their fades, not the model's."""
    if not isinstance(obj, RadioModel):
        raise ConfigError(f"register_radio takes a sarlink RadioModel, got {obj!r}")
    if obj.range_free and origin != SARLINK and (obj.params is not None or not any(
            e.origin == SARLINK and e.obj.range_free and _fades(e.obj) == _fades(obj)
            for e in RADIOS.entries().values())):
        raise ConfigError(f"radio model {obj.name!r}: range_free is only for the built-in "
                          "log-normal hooks (the range scan redraws their fades); leave it False")


def _fades(model: RadioModel) -> tuple[object, ...]:
    """The hooks that draw a model's thresholds, which the range scan replaces by its own."""
    return tuple(python_function(f) for f in (model.init, model.update, model.nominal))


def _describe(model: RadioModel) -> dict[str, Any]:
    return {"range_free": model.range_free}


RADIOS: Registry[RadioModel] = Registry("radio", label="radio model", field="channel.radio",
                                        check=_check, describe=_describe)
"""Every radio model, by name."""


def register_radio(model: RadioModel, *, replace: bool = False) -> RadioModel:
    """Make ``model`` selectable as ``channel.radio = "<name>"``; returns it. A name taken by
    another model (``disc``, ``shadowing``, ...) needs ``replace``."""
    return RADIOS.register(model, replace=replace, origin=caller_origin())


def radio_names() -> list[str]:
    """Every radio model's name."""
    return RADIOS.names()


def get_radio(name: str) -> RadioModel:
    """The radio model called ``name``; a :class:`ConfigError` naming the known ones else."""
    return RADIOS.get(name)
