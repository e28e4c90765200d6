"""The relay strategies by name (:class:`sarlink.registry.Registry` of kind ``relay``): the
built-in one (:mod:`.tree`), those registered in code, and those of installed packages (entry
point group ``sarlink.relays``)."""

from __future__ import annotations

from sarlink.config import ConfigError
from sarlink.engine.hooks import RelayStrategy
from sarlink.registry import Registry, caller_origin

__all__ = ["RELAY_STRATEGIES", "get_relay_strategy", "register_relay_strategy",
           "relay_strategy_names"]


def _check(obj: object, origin: str) -> None:
    if not isinstance(obj, RelayStrategy):
        raise ConfigError(f"register_relay_strategy takes a sarlink RelayStrategy, got {obj!r}")


RELAY_STRATEGIES: Registry[RelayStrategy] = Registry(
    "relay", label="relay strategy", field="team.relay_strategy", check=_check)
"""Every relay strategy, by name."""


def register_relay_strategy(strategy: RelayStrategy, *, replace: bool = False
                            ) -> RelayStrategy:
    """Make ``strategy`` selectable as ``team.relay_strategy = "<name>"``; returns it. A name
    taken by another strategy (``tree``) needs ``replace``."""
    return RELAY_STRATEGIES.register(strategy, replace=replace, origin=caller_origin())


def relay_strategy_names() -> list[str]:
    """Every relay strategy's name."""
    return RELAY_STRATEGIES.names()


def get_relay_strategy(name: str) -> RelayStrategy:
    """The relay strategy called ``name``; a :class:`ConfigError` naming the known ones else."""
    return RELAY_STRATEGIES.get(name)
