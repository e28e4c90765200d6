"""The target-motion seam: how a target moves while the drones search, as two
Numba-compilable hooks with a parameter array and a small state per target.

Hook contract (``xy`` is one target's position, a float64 array of shape ``(2,)``, metres;
``state`` its own float64 array of ``TargetMotion.state`` entries, zeros before ``start``;
``tp`` the model's parameter array, ``TargetMotion.params(mission)``; ``rng`` a
``numpy.random.Generator`` on the run's target stream
(:attr:`sarlink.engine.streams.Streams.target`): draw from it with ``rng.random()``,
``rng.standard_normal()`` and the like, and from nothing else):

- ``start(xy, state, tp, rng) -> None``: once per run and target, at the point where it was
  last seen (drawn from the mission's prior): draw what stays fixed for this target (a stop
  time, a leeway slope, a first heading) into ``state``. It may not move the target.
- ``move(xy, state, t, dt, tp, edges, size, rng) -> None``: move the target from time ``t``
  to ``t + dt`` (seconds since it was last seen: the mission's ``target.delay`` before
  take-off comes first), writing ``xy`` and ``state`` in place. ``edges`` is the search
  area's boundary as the kernel has it (:mod:`sarlink.engine.area`: the ``(E, 4)`` segments of
  the outline and the holes; empty for the paper's ``[0, size]²`` square); a model of a person
  on land keeps ``xy`` inside it (:func:`sarlink.engine.area.contains`,
  :func:`sarlink.engine.geometry.inside`), a model of drift at sea may leave it.

The kernel calls ``start`` and then ``move`` once per step of the delay and once per step of
the mission, at the end of the step's move phase: a step's sensing sees the target where it is
at that step's time (docs/model.md, Target motion). A model with neither hook (``still``, the
default) is no seam at all: the kernel is compiled without the target's motion, bit for bit
the kernel of a still target.

The hooks are plain or ``numba.njit`` functions at the top level of a module, compiled inline
into the kernel as a rule's are (:mod:`sarlink.engine.build`); Python code (tests/naive.py,
:func:`sarlink.testing.check_target_motion`) calls the same functions.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from sarlink.config import ConfigError
from sarlink.engine.hooks import _OptionalHooks

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["TargetMotion"]

_HOOKS = {"start": 4, "move": 8}


@dataclass(frozen=True)
class TargetMotion(_OptionalHooks):
    """How a target moves (docs/model.md, Target motion): ``move`` and ``start`` (module
    docstring; both ``None``: a still target, and the kernel without the seam).

    ``state`` is the number of float entries each target keeps between steps; ``params``
    maps a mission to the hooks' parameter array ``tp`` (default: none); ``on_land``
    declares that the model keeps the target inside the area and out of its holes (the
    contract checks it); ``source`` says where the model and its numbers come from, for
    listings.
    """

    name: str
    move: Callable[..., Any] | None = None
    start: Callable[..., Any] | None = None
    state: int = 0
    params: Callable[[Mission], Sequence[float]] | None = None
    on_land: bool = False
    source: str = ""

    _KIND: ClassVar[str] = "target motion"
    _HOOKS: ClassVar[dict[str, int]] = _HOOKS

    def __post_init__(self) -> None:
        super().__post_init__()
        if (self.move is None) != (self.start is None):
            raise ConfigError(f"target motion {self.name!r}: give both hooks, start and move, "
                              "or neither (a still target)")
        if not isinstance(self.state, int) or self.state < 0:
            raise ConfigError(f"target motion {self.name!r}: state must be an int >= 0 "
                              f"(floats kept per target), got {self.state!r}")

    @property
    def moves(self) -> bool:
        """Whether the target moves at all (the kernel is compiled with the seam)."""
        return self.move is not None

    def array(self, mission: Mission) -> np.ndarray:
        """The hooks' parameter array ``tp`` for ``mission``."""
        tp = np.asarray(self.params(mission) if self.params else (), dtype=float).ravel()
        if not all(math.isfinite(v) for v in tp.tolist()):
            raise ConfigError(f"target motion {self.name!r}: params must be finite numbers, "
                              f"got {tp.tolist()!r}")
        return tp
