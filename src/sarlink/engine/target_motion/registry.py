"""The target-motion models by name (:class:`sarlink.registry.Registry` of kind
``target_motion``): the built-in ones (:mod:`sarlink.engine.target_motion`), those registered
in code, and those of installed packages (entry point group ``sarlink.target_motions``)."""

from __future__ import annotations

from typing import Any

from sarlink.config import ConfigError
from sarlink.engine.target_motion.model import TargetMotion
from sarlink.registry import Registry, caller_origin

__all__ = ["TARGET_MOTIONS", "get_target_motion", "register_target_motion",
           "target_motion_names"]


def _check(obj: object, origin: str) -> None:
    if not isinstance(obj, TargetMotion):
        raise ConfigError(f"register_target_motion takes a sarlink TargetMotion, got {obj!r}")


def _describe(model: TargetMotion) -> dict[str, Any]:
    return {"moves": model.moves, "on land": model.on_land, "source": model.source}


TARGET_MOTIONS: Registry[TargetMotion] = Registry(
    "target_motion", label="target motion model", field="target.motion", check=_check,
    describe=_describe, first=("still", "walk", "drift"))
"""Every target-motion model, by name."""


def register_target_motion(model: TargetMotion, *, replace: bool = False) -> TargetMotion:
    """Make ``model`` selectable as ``target.motion = "<name>"``; returns it. A name taken by
    another model (``still``, ``walk``, ...) needs ``replace``."""
    return TARGET_MOTIONS.register(model, replace=replace, origin=caller_origin())


def target_motion_names() -> list[str]:
    """Every target-motion model's name."""
    return TARGET_MOTIONS.names()


def get_target_motion(name: str) -> TargetMotion:
    """The target-motion model called ``name``; a :class:`ConfigError` naming the known ones
    else."""
    return TARGET_MOTIONS.get(name)
