"""What an agent does: its new direction, as a heading vector or one of a few directions."""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
from gymnasium import spaces
from numba import njit

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
    return "a direction (x, y): an array of 2 numbers, each in [-1, 1] ((0, 0) keeps the heading)"


def directions(kind: ActionKind, count: int, actions: np.ndarray, hx: np.ndarray,
               hy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The unit directions that (already checked) actions ask for, one per drone: ``(N, 2)``
    vectors or ``(N,)`` choices among ``count``; a zero vector keeps the heading ``(hx, hy)``."""
    if kind == "discrete":
        angle = 2.0 * np.pi * actions / count
        return np.cos(angle), np.sin(angle)
    vx, vy = np.empty(hx.shape[0]), np.empty(hx.shape[0])
    _unit_directions(np.asarray(actions, dtype=np.float64), hx, hy, vx, vy)
    return vx, vy


@njit(cache=True, error_model="numpy")
def _unit_directions(a: np.ndarray, hx: np.ndarray, hy: np.ndarray, vx: np.ndarray,
                     vy: np.ndarray) -> None:
    for i in range(a.shape[0]):
        x, y = a[i, 0], a[i, 1]
        n2 = x * x + y * y
        if abs(n2 - 1.0) <= UNIT_TOLERANCE:
            vx[i], vy[i] = x, y
        elif n2 == 0.0:
            vx[i], vy[i] = hx[i], hy[i]
        else:
            n = math.sqrt(n2)
            vx[i], vy[i] = x / n, y / n


def check_actions(agents: list[str], space: spaces.Space[Any], actions: list[Any]) -> None:
    """:func:`check_action` of every agent's action (all at once when all are fine)."""
    try:
        values = np.asarray(actions) if actions else np.zeros(0)
    except ValueError:  # ragged: some action has the wrong shape
        values = np.zeros(0, dtype=object)
    if isinstance(space, spaces.Box):
        if (values.shape == (len(actions), 2) and np.issubdtype(values.dtype, np.number)
                and np.isfinite(values).all() and (np.abs(values) <= 1.0).all()):
            return
    elif (isinstance(space, spaces.Discrete) and values.ndim == 1
          and np.issubdtype(values.dtype, np.integer)
          and ((values >= 0) & (values < int(space.n))).all()):
        return
    for agent, action in zip(agents, actions, strict=True):
        check_action(agent, space, action)


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
