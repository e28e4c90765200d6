"""The planners by name (:class:`sarlink.registry.Registry` of kind ``planner``): the paper's,
the IAMSAR search patterns, those registered in code, and those of installed packages (entry
point group ``sarlink.planners``; docs/plugins.md)."""

from __future__ import annotations

from typing import Any

from sarlink.config import ConfigError
from sarlink.planners.base import Planner
from sarlink.registry import Entry, Registry, caller_origin

__all__ = ["PAPER_PLANNERS", "PLANNERS", "Entry", "get_planner", "planner_entries",
           "planner_names", "register_planner"]

PAPER_PLANNERS: tuple[str, ...] = ("mtsp", "covb", "conb", "mtsp-conb", "concov")
"""The names of the paper's planners, in the order of its legends: what its figures draw, and
the first of every listing."""

_ATTRIBUTES = ("name", "label", "colour", "marker", "kind", "rule", "steering")


def _check(obj: object, origin: str) -> None:
    if not all(hasattr(obj, a) for a in _ATTRIBUTES):
        raise ConfigError(f"register_planner takes a planner (sarlink.RoutePlanner, "
                          f"sarlink.RulePlanner or one with their attributes), got {obj!r}")


def _describe(planner: Planner) -> dict[str, Any]:
    return {"kind": planner.kind, "label": planner.label,
            "rule": planner.rule.name if planner.rule else None,
            "paper": planner.name in PAPER_PLANNERS}


PLANNERS: Registry[Planner] = Registry("planner", label="planner", field="team.planner",
                                       check=_check, describe=_describe, first=PAPER_PLANNERS)
"""Every planner, by name."""


def register_planner(planner: Planner, *, replace: bool = False) -> Planner:
    """Make ``planner`` known by its name everywhere a planner is named (missions, grids, the
    CLI, design, replays); returns it. A name taken by another planner needs ``replace``.

    Register at the top level of an importable module: worker processes import it again.
    """
    return PLANNERS.register(planner, replace=replace, origin=caller_origin())


def planner_entries() -> dict[str, Entry[Planner]]:
    """Every planner with its origin, by name, the paper's first."""
    return PLANNERS.entries()


def planner_names() -> list[str]:
    """Names of the registered planners, the paper's first, in the order of its legends."""
    return PLANNERS.names()


def get_planner(name: str) -> Planner:
    """The planner registered as ``name``; a :class:`ConfigError` naming the known ones else."""
    return PLANNERS.get(name)
