"""One registry per plug-in kind (planners, radio models, ...): the same way to register, find,
list and hand to worker processes every kind of plug-in (docs/plugins.md).

A kind is one :class:`Registry` instance, made where its objects are defined (the planners'
in :mod:`sarlink.planners.registry`, the radio models' in :mod:`sarlink.engine.radios`). Its
objects come from three places, each named by the entry's origin: sarlink itself
(``"sarlink"``: the built-ins register through the same public call as a plug-in), code
(``"code (<module>)"``: ``register_<kind>(obj)`` called in that module), and installed
packages (``"<distribution> <version> (entry point <name>)"``, group ``sarlink.<kind>s``,
loaded on the first look-up). A name is taken once: another object under it needs
``replace=True``; an entry point never replaces anything and is reported as broken instead.

This module is a low layer: it imports only :mod:`sarlink.config` and
:mod:`sarlink.entrypoints`, so that engine code can make a registry of its own.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Any, Generic, Protocol, TypeVar, cast

from sarlink.config import ConfigError
from sarlink.entrypoints import discover

__all__ = ["KINDS", "SARLINK", "Entry", "Named", "Plugins", "Registry", "adopt_plugins",
           "caller_origin", "plugins_in_code"]



class Named(Protocol):
    """What every plug-in is: something with a name."""

    @property
    def name(self) -> str: ...


T = TypeVar("T", bound=Named)

SARLINK = "sarlink"
"""The origin of what sarlink registers itself."""

KINDS: dict[str, Registry[Any]] = {}
"""Every registry by kind, in the order they were made: what ``sarlink plugins`` lists."""


@dataclass(frozen=True)
class Entry(Generic[T]):
    """A registered object and where it comes from."""

    obj: T
    origin: str


Plugins = dict[str, tuple[Entry[Any], ...]]
"""What was registered in code in a process, by kind: what its worker processes adopt."""


def caller_origin(depth: int = 2) -> str:
    """The origin of a registration made by the module ``depth`` frames up (2: the caller of
    the function that calls this): ``"sarlink"`` for sarlink's own modules, else
    ``"code (<module>)"``."""
    module = sys._getframe(depth).f_globals.get("__name__", "?")
    return SARLINK if module == SARLINK or module.startswith(SARLINK + ".") else f"code ({module})"


class Registry(Generic[T]):
    """The objects of one plug-in kind by name.

    ``kind`` names the kind (``"planner"``) and its entry point group (``sarlink.planners``);
    ``label`` is how messages call one (``"radio model"``); ``field`` is the mission setting
    that names one (``"channel.radio"``). ``check(obj, origin)`` raises a
    :class:`ConfigError` saying why ``obj`` cannot be registered from ``origin`` (not of the
    kind, a declaration it may not make). ``describe(obj)`` gives the columns of its listing
    beyond name and origin. ``first`` lists names that come first in the listing, in that
    order (the paper's planners, in the order of its legends); the rest follow in the order
    they were registered.
    """

    def __init__(self, kind: str, *, label: str, field: str,
                 check: Callable[[object, str], None],
                 describe: Callable[[T], dict[str, Any]] = lambda obj: {},
                 first: Iterable[str] = ()) -> None:
        if kind in KINDS:
            raise ValueError(f"a registry of kind {kind!r} exists already")
        self.kind, self.label, self.field = kind, label, field
        self.group = f"sarlink.{kind}s"
        self.check, self.describe, self.first = check, describe, tuple(first)
        self._entries: dict[str, Entry[T]] = {}
        self._broken: dict[str, str] = {}
        self._loaded = False
        KINDS[kind] = self

    @property
    def plural(self) -> str:
        """How listings call several: ``radio models``, ``relay strategies``."""
        return self.label[:-1] + "ies" if self.label.endswith("y") else self.label + "s"

    def register(self, obj: T, *, replace: bool = False, origin: str | None = None) -> T:
        """Make ``obj`` known by its name; returns it. Registering the same object again
        changes nothing; another object under a taken name needs ``replace``.

        ``origin`` defaults to the calling module's (:func:`caller_origin`).
        """
        origin = origin or caller_origin()
        self.check(obj, origin)
        name = obj.name
        taken = self._entries.get(name)
        if taken is not None and taken.obj == obj:
            return taken.obj
        if taken is not None and not replace:
            raise ConfigError(f"{self.label} name {name!r} is taken (from {taken.origin}); "
                              "pass replace=True to replace it")
        self._entries[name] = Entry(obj, origin)
        return obj

    def _load(self) -> None:
        """Register the objects of the installed packages' entry points, once."""
        if self._loaded:
            return
        self._loaded = True
        for found in discover(self.group):
            if found.error is not None:
                self._broken[found.name] = f"{found.origin}: {found.error}"
            for found_obj in found.objects:
                try:
                    self.check(found_obj, found.origin)
                    obj = cast(T, found_obj)
                    taken = self._entries.get(obj.name)
                    if taken is not None and taken.obj != obj:
                        raise ConfigError(f"{self.label} name {obj.name!r} is taken (from "
                                          f"{taken.origin})")
                except ConfigError as exc:
                    self._broken[found.name] = f"{found.origin}: {exc}"
                    continue
                self._entries.setdefault(obj.name, Entry(obj, found.origin))

    def entries(self) -> dict[str, Entry[T]]:
        """Every object with its origin, by name, in the order of the listing."""
        self._load()
        ordered = {name: self._entries[name] for name in self.first if name in self._entries}
        return {**ordered, **self._entries}

    def names(self) -> list[str]:
        """The registered names, in the order of the listing."""
        return list(self.entries())

    def get(self, name: str) -> T:
        """The object registered as ``name``; a :class:`ConfigError` naming the known ones
        (and the plug-ins that failed to load) else."""
        entries = self.entries()
        if name in entries:
            return entries[name].obj
        broken = "".join(f"; plug-in {k} failed to load: {v}" for k, v in self._broken.items())
        raise ConfigError(f"{self.field}: unknown {self.label} {name!r}; known: "
                          f"{', '.join(entries)}{broken}")

    def broken(self) -> dict[str, str]:
        """The entry points of the kind's group that failed to load or were refused, with why."""
        self._load()
        return dict(self._broken)

    def in_code(self) -> tuple[Entry[T], ...]:
        """What was registered in code in this process: what worker processes must register
        too (they import neither the caller's script nor its tests)."""
        return tuple(e for e in self._entries.values() if e.origin.startswith("code ("))

    def adopt(self, entries: Iterable[Entry[T]]) -> None:
        """Register, in a worker process, what its parent registered in code."""
        for entry in entries:
            name = entry.obj.name
            taken = self._entries.get(name)
            if taken is not None and taken.obj != entry.obj:
                raise ConfigError(f"{self.label} name {name!r} means another {self.label} in "
                                  "the worker process than in the caller")
            self.register(entry.obj, origin=entry.origin)


def plugins_in_code() -> Plugins:
    """What was registered in code in this process, every kind."""
    return {kind: registry.in_code() for kind, registry in KINDS.items()}


def adopt_plugins(plugins: Mapping[str, Iterable[Entry[Any]]]) -> None:
    """Register, in a worker process, what :func:`plugins_in_code` found in its parent."""
    for kind, entries in plugins.items():
        KINDS[kind].adopt(entries)
