"""Target motion: how the target moves while the drones search (:mod:`.model`, the seam),
the built-in models, registered by :func:`register_target_motion` as a plug-in model is, and
the registry that finds them by name (:mod:`.registry`). docs/model.md, Target motion."""

from __future__ import annotations

from sarlink.engine.target_motion import drift, walk
from sarlink.engine.target_motion.model import TargetMotion
from sarlink.engine.target_motion.registry import (
    TARGET_MOTIONS,
    get_target_motion,
    register_target_motion,
    target_motion_names,
)

STILL = register_target_motion(TargetMotion(
    "still", on_land=True, source="the paper: the target stays where it was drawn"))
"""The paper's target: no motion, and the kernel compiled without the seam."""
WALK = register_target_motion(TargetMotion(
    "walk", walk.move, walk.start, state=len(walk.STATE), params=walk.mission_params, on_land=True,
    source="a lost person: a heading random walk at a constant speed, stopping after a "
           "log-normal time"))
"""A lost person on land (:mod:`.walk`)."""

DRIFT = register_target_motion(TargetMotion(
    "drift", move=drift.move, start=drift.start, state=drift.STATE, params=drift.mission_params,
    source="Leeway (Allen and Plourde 1999; Allen 2005) with OpenDrift's OBJECTPROP.DAT "
    "coefficients, plus the current"))
"""A person or an object at sea: leeway and current (:mod:`.drift`)."""

__all__ = ["DRIFT", "STILL", "TARGET_MOTIONS", "WALK", "TargetMotion", "get_target_motion",
           "register_target_motion", "target_motion_names"]
