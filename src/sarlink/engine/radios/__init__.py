"""The radio models: the built-in ones, on the same seam as plug-in ones (:class:`RadioModel`),
and the registry that finds them by name."""

from __future__ import annotations

from sarlink.config import ConfigError
from sarlink.engine.hooks import RadioModel, python_function
from sarlink.engine.radios import lognormal
from sarlink.entrypoints import discover

__all__ = ["DISC", "SHADOWING", "broken_radios", "get_radio", "radio_names", "radio_origin",
           "radios_in_code", "register_radio"]

DISC = RadioModel("disc", lognormal.init, lognormal.update, lognormal.nominal,
                  static=lognormal.static, range_free=True)
"""Eq. 4: linked within r_c (the model below with ``sigma = 0``: one kernel for both)."""
SHADOWING = RadioModel("shadowing", lognormal.init, lognormal.update, lognormal.nominal,
                       static=lognormal.static, range_free=True)
"""Eq. 13: log-normal fades per link, changing as ``readings.shadowing`` says (every
coherence time, once per run, or correlated over the distance flown)."""


class _Registry:
    """The radio models by name: the built-in ones, those registered in code, and those of
    installed packages (entry point group ``sarlink.radios``), loaded on first use."""

    def __init__(self) -> None:
        self.models: dict[str, RadioModel] = {DISC.name: DISC, SHADOWING.name: SHADOWING}
        self.origins: dict[str, str] = {DISC.name: "sarlink", SHADOWING.name: "sarlink"}
        self.broken: dict[str, str] = {}
        self.loaded = False

    def load(self) -> None:
        if self.loaded:
            return
        self.loaded = True
        for found in discover("sarlink.radios"):
            if found.error is not None:
                self.broken[found.name] = f"{found.origin}: {found.error}"
            for model in found.objects:
                if not isinstance(model, RadioModel):
                    self.broken[found.name] = (f"{found.origin}: gave {model!r}, not a "
                                               "sarlink RadioModel")
                elif model.name not in self.models:
                    self.add(model, found.origin)

    def add(self, model: RadioModel, origin: str) -> None:
        self.models[model.name] = model
        self.origins[model.name] = origin


_REGISTRY = _Registry()


def register_radio(model: RadioModel, *, origin: str | None = None) -> RadioModel:
    """Make ``model`` selectable as ``channel.radio = "<name>"``; returns it."""
    if not isinstance(model, RadioModel):
        raise ConfigError(f"register_radio takes a sarlink RadioModel, got {model!r}")
    _REGISTRY.add(model, origin or f"code ({python_function(model.update).__module__})")
    return model


def radios_in_code() -> tuple[RadioModel, ...]:
    """The radio models registered in this process by :func:`register_radio`."""
    return tuple(_REGISTRY.models[name] for name, origin in _REGISTRY.origins.items()
                 if origin.startswith("code ("))


def broken_radios() -> dict[str, str]:
    """The entry points of ``sarlink.radios`` that failed to load, with why."""
    _REGISTRY.load()
    return dict(_REGISTRY.broken)


def radio_names() -> list[str]:
    """Every radio model's name."""
    _REGISTRY.load()
    return list(_REGISTRY.models)


def get_radio(name: str) -> RadioModel:
    """The radio model called ``name``; a :class:`ConfigError` naming the known ones else."""
    _REGISTRY.load()
    try:
        return _REGISTRY.models[name]
    except KeyError:
        broken = "".join(f"; plug-in {k} failed to load: {v}" for k, v in _REGISTRY.broken.items())
        raise ConfigError(f"channel.radio: unknown radio model {name!r}; known: "
                          f"{', '.join(_REGISTRY.models)}{broken}") from None


def radio_origin(name: str) -> str:
    """Where the radio model ``name`` comes from."""
    _REGISTRY.load()
    return _REGISTRY.origins[name]
