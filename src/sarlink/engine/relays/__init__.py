"""Relay drones: where they stand (:mod:`.placement`), the built-in strategy that chooses their
points in flight (:mod:`.tree`), registered by :func:`register_relay_strategy` as a plug-in
strategy is, the registry that finds strategies by name (:mod:`.registry`), and how the
kernel flies them (:mod:`.flight`)."""

from __future__ import annotations

from sarlink.engine.hooks import RelayStrategy
from sarlink.engine.relays import tree
from sarlink.engine.relays.registry import (
    RELAY_STRATEGIES,
    get_relay_strategy,
    register_relay_strategy,
    relay_strategy_names,
)

TREE = register_relay_strategy(RelayStrategy("tree", place=tree.place, prepare=tree.prepare))
"""The tree over the BS and the searchers where the BS last heard of them (:mod:`.tree`)."""

__all__ = ["RELAY_STRATEGIES", "TREE", "get_relay_strategy", "register_relay_strategy",
           "relay_strategy_names"]
