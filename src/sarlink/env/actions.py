"""What an agent does: its new direction, as a heading vector or one of a few directions."""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
from gymnasium import spaces

from sarlink.config import ConfigError

ActionKind = Literal["continuous", "discrete"]

UNIT_TOLERANCE = 1e-12
"""A continuous action whose squared length is within this of 1 is taken as it is (a rule's
own unit vectors pass unchanged); any other is scaled to unit length."""


def action_space(kind: ActionKind, directions: int) -> spaces.Space[Any]:
    """``continuous``: a direction ``(x, y)`` in ``[-1, 1]²`` (float64); ``discrete``: one of
    ``directions`` headings ``2 pi a / directions`` counter-clockwise from the x axis."""
    if kind == "continuous":
        return spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float64)
    if kind == "discrete":
        if directions < 2:
            raise ConfigError(f"directions must be at least 2, got {directions}")
        return spaces.Discrete(directions)
    raise ConfigError(f"actions must be 'continuous' or 'discrete', got {kind!r}")


def allowed(space: spaces.Space[Any]) -> str:
    """The allowed values of ``space`` in words, for error messages."""
    if isinstance(space, spaces.Discrete):
        return f"an integer in 0..{int(space.n) - 1}"
    return "a direction (x, y): an array of 2 numbers, each in [-1, 1], not both 0"


def direction(kind: ActionKind, directions: int, action: Any, hx: float,
              hy: float) -> tuple[float, float]:
    """The unit direction an (already checked) action asks for; a zero vector keeps the
    heading ``(hx, hy)``."""
    if kind == "discrete":
        angle = 2.0 * math.pi * int(action) / directions
        return math.cos(angle), math.sin(angle)
    x, y = float(action[0]), float(action[1])
    n2 = x * x + y * y
    if abs(n2 - 1.0) <= UNIT_TOLERANCE:
        return x, y
    if n2 == 0.0:
        return hx, hy
    n = math.sqrt(n2)
    return x / n, y / n


def check_action(agent: str, space: spaces.Space[Any], action: Any) -> None:
    """Raise a :class:`ConfigError` naming ``agent`` unless ``action`` is in ``space``."""
    value = action
    if isinstance(space, spaces.Box):
        value = np.asarray(action)
        ok = (value.shape == (2,) and np.issubdtype(value.dtype, np.number)
              and bool(np.all(np.isfinite(value))) and bool(np.all(np.abs(value) <= 1.0)))
    else:
        ok = isinstance(action, (int, np.integer)) and space.contains(action)
    if not ok:
        raise ConfigError(f"the action of {agent} is {action!r}: outside its action space "
                          f"{space}; allowed: {allowed(space)}")
