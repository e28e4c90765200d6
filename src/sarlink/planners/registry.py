"""The planners by name: the paper's, the IAMSAR search patterns, those registered in code,
and those of installed packages (entry point group ``sarlink.planners``, loaded on first use;
docs/plugins.md)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import cast

from sarlink.config import ConfigError
from sarlink.entrypoints import discover
from sarlink.planners.base import Planner
from sarlink.planners.paper import PAPER
from sarlink.planners.patterns import PATTERNS

__all__ = ["Entry", "adopt", "broken_plugins", "get_planner", "planner_entries", "planner_names",
           "register_planner", "registered_in_code"]


@dataclass(frozen=True)
class Entry:
    """A registered planner and where it comes from."""

    planner: Planner
    origin: str  # "sarlink", "code (<module>)" or "<distribution> <version> (entry point ...)"


_ENTRIES: dict[str, Entry] = {p.name: Entry(p, "sarlink") for p in (*PAPER, *PATTERNS)}
_BROKEN: dict[str, str] = {}
_LOADED = False


def _is_planner(obj: object) -> bool:
    return all(hasattr(obj, a) for a in ("name", "label", "colour", "marker", "kind", "rule",
                                          "steering"))


def _load_plugins() -> None:
    global _LOADED
    if _LOADED:
        return
    _LOADED = True
    for found in discover("sarlink.planners"):
        if found.error is not None:
            _BROKEN[found.name] = f"{found.origin}: {found.error}"
        for obj in found.objects:
            if not _is_planner(obj):
                _BROKEN[found.name] = f"{found.origin}: gave {obj!r}, not a planner"
            else:
                planner = cast(Planner, obj)
                _ENTRIES.setdefault(planner.name, Entry(planner, found.origin))


def register_planner(planner: Planner, *, replace: bool = False) -> Planner:
    """Make ``planner`` known by its name everywhere a planner is named (missions, grids, the
    CLI, design, replays); returns it. A name taken by another planner needs ``replace``.

    Register at the top level of an importable module: worker processes import it again.
    """
    if not _is_planner(planner):
        raise ConfigError(f"register_planner takes a planner (sarlink.RoutePlanner, "
                          f"sarlink.RulePlanner or one with their attributes), got {planner!r}")
    _load_plugins()
    taken = _ENTRIES.get(planner.name)
    if taken is not None and taken.planner != planner and not replace:
        raise ConfigError(f"planner name {planner.name!r} is taken (from {taken.origin}); "
                          "pass replace=True to replace it")
    module = type(planner).__module__
    for attr in ("routes", "rule"):
        fn = getattr(planner, attr, None)
        fn = getattr(fn, "decide", fn)
        if callable(fn) and getattr(fn, "__module__", None):
            module = fn.__module__
            break
    _ENTRIES[planner.name] = Entry(planner, f"code ({module})")
    return planner


def registered_in_code() -> tuple[Planner, ...]:
    """The planners registered in this process by :func:`register_planner`: what worker
    processes must register too (they import neither the caller's script nor its tests)."""
    return tuple(e.planner for e in _ENTRIES.values() if e.origin.startswith("code ("))


def adopt(planners: tuple[Planner, ...]) -> None:
    """Register, in a worker process, the planners its parent registered in code."""
    for planner in planners:
        if _ENTRIES.get(planner.name, Entry(planner, "")).planner != planner:
            raise ConfigError(f"planner name {planner.name!r} means another planner in the "
                              "worker process than in the caller")
        register_planner(planner)


def broken_plugins() -> dict[str, str]:
    """The entry points of ``sarlink.planners`` that failed to load, with why."""
    _load_plugins()
    return dict(_BROKEN)


def planner_entries() -> dict[str, Entry]:
    """Every planner with its origin, by name, the paper's first."""
    _load_plugins()
    return dict(_ENTRIES)


def planner_names() -> list[str]:
    """Names of the registered planners, the paper's first, in the order of its legends."""
    return list(planner_entries())


def get_planner(name: str) -> Planner:
    """The planner registered as ``name``; a :class:`ConfigError` naming the known ones else."""
    entries = planner_entries()
    if name in entries:
        return entries[name].planner
    broken = "".join(f"; plug-in {k} failed to load: {v}" for k, v in _BROKEN.items())
    raise ConfigError(f"team.planner: unknown planner {name!r}; known: "
                      f"{', '.join(entries)}{broken}")
