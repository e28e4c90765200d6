"""A lost person walking on land (docs/model.md, Target motion): a constant speed, a
correlated random heading, and a time after which the person stops for good.

The heading is a random walk: each step adds a normal turn of standard deviation
``turn · sqrt(dt / 60 s)`` to it (``turn`` is the spread of the heading's change over one
minute, so the walk does not depend on the time step). The person stops ``T`` seconds after
the last sighting, ``T`` log-normal with median ``mobile`` and log-spread ``spread``, drawn
once per target. A step that would leave the area or enter a hole is not taken as it is:
the person turns to a uniformly random heading whose step stays inside (drawn again until one
fits, at most :data:`~sarlink.engine.area.TRIES` times, as a drone's boundary rule does), and
stands still for the step if none does.

Parameters (``tp``, :data:`PARAMS`): ``speed`` (m/s), ``turn`` (rad per minute),
``mobile`` (s, the median time mobile), ``spread`` (the standard deviation of ln T). State:
``heading`` (rad), ``stop`` (s since the last sighting).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from numba import njit

from sarlink.engine.area import TRIES, clear
from sarlink.engine.area import contains as area_contains

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["PARAMS", "STATE", "mission_params", "move", "start"]

PARAMS = ("speed", "turn", "mobile", "spread")
"""The names of the parameter array's entries, in order."""
STATE = ("heading", "stop")
"""The names of a target's state entries, in order."""


def mission_params(mission: Mission) -> tuple[float, ...]:
    """The parameters (:data:`PARAMS`) from the mission's ``[target]`` group."""
    t = mission.target
    return (t.walk_speed, t.walk_turn, t.walk_mobile, t.walk_spread)


@njit(cache=True, inline="always", error_model="numpy")
def fits(x: float, y: float, nx: float, ny: float, edges: np.ndarray, size: float) -> bool:
    """Whether a step from ``(x, y)`` to ``(nx, ny)`` stays in the area: the square
    ``[0, size]²`` when ``edges`` is empty, else inside the polygon without touching its
    outline or a hole on the way."""
    if edges.shape[0] == 0:
        return 0.0 <= nx <= size and 0.0 <= ny <= size
    return area_contains(nx, ny, edges) and clear(x, y, nx, ny, edges)


@njit(cache=True, inline="always", error_model="numpy")
def start(xy: np.ndarray, state: np.ndarray, tp: np.ndarray, rng: np.random.Generator) -> None:
    """A first heading, uniform, and the time the person stops."""
    state[0] = rng.random() * 2.0 * math.pi
    state[1] = tp[2] * math.exp(tp[3] * rng.standard_normal())


@njit(cache=True, inline="always", error_model="numpy")
def move(xy: np.ndarray, state: np.ndarray, t: float, dt: float, tp: np.ndarray,
         edges: np.ndarray, size: float, rng: np.random.Generator) -> None:
    """One step of the walk (module docstring); a person who has stopped draws nothing."""
    if t >= state[1]:
        return
    step = tp[0] * min(dt, state[1] - t)
    heading = state[0] + tp[1] * math.sqrt(dt / 60.0) * rng.standard_normal()
    x, y = xy[0], xy[1]
    nx, ny = x + step * math.cos(heading), y + step * math.sin(heading)
    tries = 0
    while not fits(x, y, nx, ny, edges, size):
        if tries == TRIES:  # boxed in: stand still for this step
            nx, ny = x, y
            break
        tries += 1
        heading = rng.random() * 2.0 * math.pi
        nx, ny = x + step * math.cos(heading), y + step * math.sin(heading)
    state[0] = heading
    xy[0], xy[1] = nx, ny
