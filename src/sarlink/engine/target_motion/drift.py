"""``drift``: a person or an object at sea, moved by the Leeway model plus the surface current
(docs/model.md, Target motion, ``drift``).

The leeway of an object (Allen and Plourde 1999; Allen 2005) is linear in the 10 m wind speed
``W`` (m/s): downwind ``L_d = a_d W + b_d`` and crosswind ``L_c = a_s W + b_s`` on the object's
side ``s`` of downwind, right (``CWR``) or left (``CWL``), with the coefficients of its class
(:data:`sarlink.config.leeway.LEEWAY_CLASSES`, from OpenDrift's OBJECTPROP.DAT). The target
moves by ``L_d`` along the wind, ``L_c`` at right angles to it (positive to the right of
downwind, as the right-side fits have positive slopes; OpenDrift's ``Leeway.update`` turns a
positive crosswind to the left, the same for classes whose sides mirror each other), and by
the current.

Each target draws its own fit once, at ``start``, as OpenDrift's ``Leeway.seed_elements`` does
(opendrift/models/leeway.py): two standard normal numbers ``r_d`` and ``r_c``; the error
``eps = r sigma`` of each component (``sigma`` the fit's standard error, cm/s) is added as
``eps / 20`` to the slope and ``eps / 2`` to the offset, so the perturbation is ``eps`` at
``W = 10`` m/s; ``r_d`` is drawn again while the perturbed downwind slope is negative (an
object drifts downwind). Unlike OpenDrift, which alternates sides by element index, the first
side is drawn (right or left with probability 1/2 each). The target jibes (changes side)
after each step with probability ``1 - (1 - p)^(dt / 3600)``, ``p`` = 0.04 per hour,
OpenDrift's default ``seed:jibe_probability``; a jibe takes the other side's slope, offset
and standard error with the same ``r_c``. (OpenDrift flips the slope alone and keeps the
first side's offset and error; for classes whose sides mirror each other, PIW-1 among them,
the two are the same.) In calm air (``W = 0``) there is no downwind direction and no leeway.

Wind and current are tables of rows ``(t, east, north)`` (:func:`sarlink.config.leeway.
forcing_table`), read at the step's start time by linear interpolation, held at the ends.
The motion is forward Euler over the step, as OpenDrift's is; the target may leave the area.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from numba import njit

from sarlink.config.leeway import forcing_table, leeway_class

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["JIBE_PER_HOUR", "STATE", "drift_params", "drift_targets", "forcing_at",
           "leeway", "mission_params", "move", "start"]

JIBE_PER_HOUR = 0.04
"""The probability that an object jibes within an hour (OpenDrift's default)."""

STATE = 3
"""Per target: the side (+1 right of downwind, -1 left), ``r_d`` and ``r_c``."""

# The parameter array tp: nine coefficients (OBJECTPROP.DAT's order), the jibe probability per
# hour, the wind's and the current's row counts, then their rows (t, east, north).
_JIBE, _N_WIND, _N_CURRENT, _ROWS = 9, 10, 11, 12


def drift_params(object_class: str, wind: object, current: object,
                 jibe_per_hour: float = JIBE_PER_HOUR) -> np.ndarray:
    """The hooks' parameter array for ``object_class`` under ``wind`` and ``current``
    (each a pair, a table or their text, :func:`sarlink.config.leeway.forcing_table`)."""
    w, c = forcing_table(wind), forcing_table(current)
    head = [*leeway_class(object_class).coefficients, jibe_per_hour, len(w), len(c)]
    return np.array(head + [v for row in (*w, *c) for v in row], dtype=float)


def mission_params(mission: Mission) -> list[float]:
    """The hooks' parameters for ``mission``'s target (``[target]`` drift fields)."""
    target = mission.target
    return drift_params(target.drift_object, target.drift_wind, target.drift_current).tolist()


@njit(cache=True, inline="always", error_model="numpy")
def forcing_at(tp: np.ndarray, first: int, rows: int, t: float) -> tuple[float, float]:
    """The (east, north) of the table of ``rows`` rows at ``tp[first:]`` at time ``t``:
    linear between rows, held before the first and after the last."""
    if rows == 1 or t <= tp[first]:
        return tp[first + 1], tp[first + 2]
    last = first + 3 * (rows - 1)
    if t >= tp[last]:
        return tp[last + 1], tp[last + 2]
    i = first
    while tp[i + 3] < t:
        i += 3
    f = (t - tp[i]) / (tp[i + 3] - tp[i])
    return tp[i + 1] + f * (tp[i + 4] - tp[i + 1]), tp[i + 2] + f * (tp[i + 5] - tp[i + 2])


@njit(cache=True, inline="always", error_model="numpy")
def leeway(wx: float, wy: float, state: np.ndarray, tp: np.ndarray) -> tuple[float, float]:
    """The leeway velocity (east, north), m/s, of a target with ``state`` in the wind
    ``(wx, wy)``."""
    w = math.sqrt(wx * wx + wy * wy)
    if w == 0.0:
        return 0.0, 0.0
    side, rd, rc = state[0], state[1], state[2]
    c = 3 if side > 0.0 else 6
    ed, ec = rd * tp[2], rc * tp[c + 2]
    down = ((tp[0] + ed / 20.0) * w + tp[1] + ed / 2.0) * 0.01
    cross = ((tp[c] + ec / 20.0) * w + tp[c + 1] + ec / 2.0) * 0.01
    ux, uy = wx / w, wy / w  # downwind; its right is (uy, -ux)
    return down * ux + cross * uy, down * uy - cross * ux


@njit(cache=True, inline="always", error_model="numpy")
def start(xy: np.ndarray, state: np.ndarray, tp: np.ndarray, rng: np.random.Generator) -> None:
    """Draw the target's side and its two fit errors (module docstring)."""
    state[0] = 1.0 if rng.random() < 0.5 else -1.0
    rd = rng.standard_normal()
    while tp[0] + rd * tp[2] / 20.0 < 0.0:
        rd = rng.standard_normal()
    state[1] = rd
    state[2] = rng.standard_normal()


@njit(cache=True, inline="always", error_model="numpy")
def move(xy: np.ndarray, state: np.ndarray, t: float, dt: float, tp: np.ndarray,
         edges: np.ndarray, size: float, rng: np.random.Generator) -> None:
    """Drift from ``t`` to ``t + dt`` with the leeway and the current at ``t``, then jibe."""
    n_wind = int(tp[_N_WIND])
    wx, wy = forcing_at(tp, _ROWS, n_wind, t)
    cx, cy = forcing_at(tp, _ROWS + 3 * n_wind, int(tp[_N_CURRENT]), t)
    lx, ly = leeway(wx, wy, state, tp)
    xy[0] += (lx + cx) * dt
    xy[1] += (ly + cy) * dt
    if rng.random() < 1.0 - (1.0 - tp[_JIBE]) ** (dt / 3600.0):
        state[0] = -state[0]


@njit(cache=True, error_model="numpy")
def drift_targets(xy: np.ndarray, state: np.ndarray, t: float, dt: float, steps: int,
                  tp: np.ndarray, rng: np.random.Generator) -> None:
    """Move the targets ``xy`` ``(K, 2)`` with their states ``(K, STATE)`` by ``steps`` steps
    of ``dt`` from time ``t``, each by :func:`move` (no area): the drift alone, for checks
    against the Leeway formulas and OpenDrift (benchmarks/drift_opendrift.py)."""
    edges = np.empty((0, 4))
    for k in range(steps):
        for i in range(xy.shape[0]):
            move(xy[i], state[i], t + k * dt, dt, tp, edges, 0.0, rng)
