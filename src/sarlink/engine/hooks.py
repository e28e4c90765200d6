"""The engine's plug-in seams: a distributed rule, a radio model and a relay strategy
(docs/plugins.md).

All are plain descriptions of Numba-compilable functions. The kernel is compiled once per
pair of rule and radio model with their functions inlined (:mod:`sarlink.engine.build`), so a
plug-in runs at the speed of the built-in ones, which are written on these same seams
(:mod:`sarlink.planners.rules`, :mod:`sarlink.engine.radios`).

Hook signatures (``p`` is :class:`~sarlink.engine.params.Params`, ``obs`` an
:class:`~sarlink.engine.observation.Observation`, ``ws`` whatever ``prepare`` returned):

- rule ``prepare(p, obs) -> ws``: once per run, the rule's own arrays;
- rule ``due(k, p, obs, ws, deciding) -> bool`` (optional): after the sensing-period schedule
  has marked ``deciding``, mark drones that must decide now as well (setting their
  ``obs.last_change[i] = k``); return whether any drone decides;
- rule ``decide(k, p, obs, ws, deciding, vx, vy) -> None``: write the new unit direction
  ``(vx[i], vy[i])`` of every drone ``i`` with ``deciding[i]``; the boundary rule applies after;
- radio ``init(p, rp, m, mp) -> thr2``: the squared link range of every pair of the ``m``
  nodes in its first ``m`` rows, shape ``(m, mp)`` (zero towards the ``mp - m`` padding
  nodes); rows past ``m``, if any, are the model's own state (the links never read them);
- radio ``update(thr2, p, rp, k, rng) -> None``: refill ``thr2`` at step ``k`` where it changes;
- radio ``nominal(p, rp) -> float``: the range planners predict with, m;
- radio ``static(p, rp) -> bool`` (or a plain ``bool``): whether ``thr2`` never changes after
  ``init`` (a team that has settled can then jump to the horizon);
- relay ``prepare(p, obs) -> ws``: once per run, the strategy's own arrays;
- relay ``place(k, p, obs, ws, edges, gx, gy) -> None``: every step, the BS's side of the
  relays: write the point ``(gx[i], gy[i])`` that relay ``i`` (``obs.mode[i] == RELAYING``)
  is to fly to and hold; ``edges`` is the area (:mod:`sarlink.engine.area`). The kernel
  delivers a new point only to a relay the BS can reach this step (``obs.routed``), moves
  points into the area, and flies the relays there.

``rp`` is the radio's parameter array (``RadioModel.params``).
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

from sarlink.config import ConfigError

if TYPE_CHECKING:
    from sarlink.config import Mission

_RULE_HOOKS = {"prepare": 2, "due": 5, "decide": 7}
_RADIO_HOOKS = {"init": 4, "update": 5, "nominal": 2, "static": 2}
_RELAY_HOOKS = {"prepare": 2, "place": 7}


def python_function(fn: Any) -> Callable[..., Any]:
    """The Python function behind ``fn`` (a Numba dispatcher's ``py_func``, or ``fn``)."""
    return getattr(fn, "py_func", fn)


def check_hook(kind: str, name: str, hook: str, fn: Any, arity: int) -> None:
    """Raise a :class:`ConfigError` naming the plug-in unless ``fn`` is a module-level function
    of ``arity`` positional parameters (the kernel imports it by its module and name)."""
    py = python_function(fn)
    where = f"{kind} {name!r}: {hook}"
    if not inspect.isfunction(py):
        raise ConfigError(f"{where} must be a function (plain or numba.njit), got {fn!r}")
    params = inspect.signature(py).parameters.values()
    positional = [q for q in params if q.kind in (q.POSITIONAL_ONLY, q.POSITIONAL_OR_KEYWORD)]
    if len(positional) != arity or len(positional) != len(params):
        raise ConfigError(f"{where}{inspect.signature(py)} must take exactly {arity} "
                          f"positional parameters (docs/plugins.md)")
    if "<locals>" in py.__qualname__ or py.__module__ is None:
        raise ConfigError(f"{where} must be defined at the top level of a module, so that "
                          f"compiled kernels can import it; {py.__qualname__} is not")


class _OptionalHooks:
    """A plug-in whose hooks (``_HOOKS``: name -> arity) may be ``None``, the engine's
    default: each given one is checked on construction."""

    _KIND: ClassVar[str]
    _HOOKS: ClassVar[dict[str, int]]

    def __post_init__(self) -> None:
        for hook, arity in self._HOOKS.items():
            fn = getattr(self, hook)
            if fn is not None:
                check_hook(self._KIND, getattr(self, "name"), hook, fn, arity)  # noqa: B009

    def hooks(self) -> dict[str, Callable[..., Any] | None]:
        """The hook functions by name (``None``: the engine's default)."""
        return {hook: getattr(self, hook) for hook in self._HOOKS}


@dataclass(frozen=True)
class DistributedRule(_OptionalHooks):
    """A direction-update rule for the drones that do not fly routes.

    ``near`` asks the engine to fill ``obs.near`` (pairs within the sensing range) on the
    steps at which drones decide; ``readings`` names the fields of
    :class:`sarlink.config.Readings` that change its runs (the sensitivity analysis reruns
    only the rules a choice reaches). ``range_free`` declares that its decisions never read
    the links or the range (``obs.adj``, ``obs.routed``, ``obs.spread``, ``obs.knows``,
    ``obs.rc``): a team of it flies the same at every range and is flown once for all
    of them (:mod:`sarlink.engine.critical_ranges`); default False, the safe answer.
    ``ignores_reporting`` declares that its hooks never read ``p.on_detect``,
    ``p.reporters`` or ``p.stop``: a run of it whose drones report is then the same flight as
    without reporting until a drone reports, and is taken from that run where none ever does
    (:mod:`sarlink.engine.sharing`); default False.
    """

    name: str
    decide: Callable[..., Any]
    prepare: Callable[..., Any] | None = None
    due: Callable[..., Any] | None = None
    near: bool = False
    readings: tuple[str, ...] = ()
    range_free: bool = False
    ignores_reporting: bool = False

    _KIND: ClassVar[str] = "rule"
    _HOOKS: ClassVar[dict[str, int]] = _RULE_HOOKS


@dataclass(frozen=True)
class RadioModel:
    """A channel model: which pairs of nodes are linked, step by step.

    ``static`` says the thresholds never change after ``init`` (a team that has settled can
    then jump to the horizon): a ``bool``, or a hook of the mission when it depends on it;
    ``params`` maps a mission to the model's parameter array
    ``rp`` (default: none: the built-in models read the mission's ``channel`` scalars from
    ``p``). ``range_free`` declares that a link exists iff ``d² ≤ r_c² f`` with fades ``f``
    drawn independently of ``r_c``, as the range scan redraws them: only the built-in
    log-normal model's hooks do, and the radio registry refuses the declaration from outside
    sarlink with other hooks (:mod:`sarlink.engine.radios.registry`), so plug-in models are
    flown at every range.
    """

    name: str
    init: Callable[..., Any]
    update: Callable[..., Any]
    nominal: Callable[..., Any]
    static: bool | Callable[..., Any] = False
    params: Callable[[Mission], Sequence[float]] | None = None
    range_free: bool = False

    def __post_init__(self) -> None:
        for hook, arity in _RADIO_HOOKS.items():
            fn = getattr(self, hook)
            if not isinstance(fn, bool):
                check_hook("radio model", self.name, hook, fn, arity)

    def hooks(self) -> dict[str, Callable[..., Any]]:
        """The hook functions by name (a ``bool`` ``static`` is not one)."""
        return {hook: getattr(self, hook) for hook in _RADIO_HOOKS
                if not isinstance(getattr(self, hook), bool)}


@dataclass(frozen=True)
class RelayStrategy(_OptionalHooks):
    """Where a team's relay drones stand (``team.relays``, docs/model.md, Relays): their
    points, chosen at the BS from what it knows of the searchers. Its hooks are compiled
    into the kernel of a team with relays only: a team without flies the kernel without them.
    """

    name: str
    place: Callable[..., Any]
    prepare: Callable[..., Any] | None = None

    _KIND: ClassVar[str] = "relay strategy"
    _HOOKS: ClassVar[dict[str, int]] = _RELAY_HOOKS


def radio_identity(radio: RadioModel) -> tuple[object, ...]:
    """What a kernel depends on of ``radio``: its hooks (models that share them, the disc and
    log-normal shadowing, share kernels)."""
    return (*(python_function(f) for f in radio.hooks().values()), radio.static)
