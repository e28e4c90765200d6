"""Plug-ins of installed packages, found through entry points (``sarlink.planners``,
``sarlink.radios``; docs/plugins.md)."""

from __future__ import annotations

from collections.abc import Iterator
from importlib.metadata import entry_points
from typing import NamedTuple


class Found(NamedTuple):
    """One entry point: the objects it gave (or the error that loading it raised)."""

    name: str
    origin: str  # "<distribution> <version> (entry point <name>)"
    objects: tuple[object, ...]
    error: str | None


def discover(group: str) -> Iterator[Found]:
    """Every entry point of ``group``, loaded: an object, or a list or tuple of them."""
    for ep in entry_points(group=group):
        dist = getattr(ep, "dist", None)
        who = f"{dist.name} {dist.version}" if dist is not None else ep.value
        origin = f"{who} (entry point {ep.name})"
        try:
            loaded = ep.load()
        except Exception as exc:  # a broken plug-in must not break sarlink: it is reported
            yield Found(ep.name, origin, (), f"{type(exc).__name__}: {exc}")
            continue
        objects = tuple(loaded) if isinstance(loaded, list | tuple) else (loaded,)
        yield Found(ep.name, origin, objects, None)
