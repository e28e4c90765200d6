"""Target motion: how the target moves while the drones search (:mod:`.model`, the seam),
the built-in models, registered by :func:`register_target_motion` as a plug-in model is, and
the registry that finds them by name (:mod:`.registry`). docs/model.md, Target motion."""

from __future__ import annotations

from sarlink.engine.target_motion.model import TargetMotion
from sarlink.engine.target_motion.registry import (
    TARGET_MOTIONS,
    get_target_motion,
    register_target_motion,
    target_motion_names,
)

STILL = register_target_motion(TargetMotion(
    "still", source="the paper: the target stays where it was drawn"))
"""The paper's target: no motion, and the kernel compiled without the seam."""

__all__ = ["STILL", "TARGET_MOTIONS", "TargetMotion", "get_target_motion",
           "register_target_motion", "target_motion_names"]
