"""The energy-model seam: the power a drone draws as a function of how it flies, as two
Numba-compilable hooks with a parameter array, and what Python code asks of a model (the
energy of a flight, its best speeds).

Hook signatures (``ep`` is the model's parameter array, ``EnergyModel.params``):

- ``level(v, ep) -> float``: the power (W) in level flight at ground speed ``v >= 0`` (m/s);
  ``v = 0`` is hover;
- ``vertical(vz, ep) -> float``: the power (W) flying straight up (``vz > 0``, m/s) or down
  (``vz < 0``).

The kernel can call them as it calls a radio model's (:mod:`sarlink.engine.hooks`): plain or
``numba.njit`` functions at the top level of a module. Python code here calls the same
functions (their ``py_func``), so a prediction and a simulation read one model.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from sarlink.config import ConfigError
from sarlink.engine.hooks import check_hook, python_function

__all__ = ["CLIMB_RATE", "DESCENT_RATE", "EnergyModel", "Flight"]

CLIMB_RATE = 1.5
"""Vertical speed of a take-off, m/s: PX4's default (``MPC_TKO_SPEED``); ArduPilot climbs
faster (``WPNAV_SPEED_UP``, 2.5 m/s), so the slower one is the safe prediction."""
DESCENT_RATE = 0.7
"""Vertical speed of a landing, m/s: PX4's default final descent (``MPC_LAND_SPEED``)."""

_HOOKS = {"level": 2, "vertical": 2}


@dataclass(frozen=True)
class EnergyModel:
    """How much power a drone draws: in level flight by ground speed, straight up or down by
    vertical speed (docs/model.md, Energy). ``params`` is the hooks' parameter array;
    ``source`` says where the model and its numbers come from, for listings."""

    name: str
    level: Callable[..., Any]
    vertical: Callable[..., Any]
    params: tuple[float, ...] = ()
    source: str = ""

    def __post_init__(self) -> None:
        for hook, arity in _HOOKS.items():
            check_hook("energy model", self.name, hook, getattr(self, hook), arity)
        if not all(isinstance(p, int | float) and math.isfinite(p) for p in self.params):
            raise ConfigError(f"energy model {self.name!r}: params must be finite numbers, "
                              f"got {self.params!r}")

    def hooks(self) -> dict[str, Callable[..., Any]]:
        """The hook functions by name."""
        return {hook: getattr(self, hook) for hook in _HOOKS}

    @property
    def array(self) -> np.ndarray:
        """The parameter array the hooks take."""
        return np.asarray(self.params, dtype=float)

    @property
    def draws_power(self) -> bool:
        """Whether a flight drains a battery at all (``none``'s does not): every drone that
        flies on a battery draws power hovering."""
        return self.power(0.0) > 0.0

    def power(self, speed: float) -> float:
        """Power in level flight at ``speed`` (m/s; 0: hover), W."""
        return float(python_function(self.level)(float(speed), self.array))

    def vertical_power(self, vz: float) -> float:
        """Power flying straight up (``vz > 0``) or down (``vz < 0``), W."""
        return float(python_function(self.vertical)(float(vz), self.array))

    def climb(self, altitude: float) -> float:
        """Joules of a take-off's climb to ``altitude`` (m) at :data:`CLIMB_RATE`."""
        return self.vertical_power(CLIMB_RATE) * altitude / CLIMB_RATE

    def descent(self, altitude: float) -> float:
        """Joules of a landing's descent from ``altitude`` (m) at :data:`DESCENT_RATE`."""
        return self.vertical_power(-DESCENT_RATE) * altitude / DESCENT_RATE

    def per_metre(self, speed: float) -> float:
        """Energy per metre of level flight at ``speed > 0``, J/m."""
        return self.power(speed) / speed

    def endurance_speed(self, top: float = 40.0) -> float:
        """The speed of least power (the longest flight time), m/s, in ``[0, top]``."""
        return _argmin(self.power, 0.0, top)

    def range_speed(self, top: float = 40.0) -> float:
        """The speed of least energy per metre (the longest range), m/s, in ``(0, top]``."""
        return _argmin(self.per_metre, 1e-3, top)


@dataclass(frozen=True)
class Flight:
    """One flight from take-off to landing: ``length`` metres of level flight at ``speed``,
    climbing to ``altitude`` first and descending from it last."""

    length: float
    speed: float
    altitude: float

    @property
    def duration(self) -> float:
        """Seconds from take-off to landing."""
        return self.length / self.speed + self.altitude / CLIMB_RATE + \
            self.altitude / DESCENT_RATE

    def energy(self, model: EnergyModel) -> float:
        """Joules the flight takes under ``model``: the climb at :data:`CLIMB_RATE`, the
        level flight, the descent at :data:`DESCENT_RATE`."""
        return model.climb(self.altitude) + model.power(self.speed) * self.length / self.speed \
            + model.descent(self.altitude)


def _argmin(f: Callable[[float], float], lo: float, hi: float) -> float:
    """The minimiser of ``f`` on ``[lo, hi]``: the best of a grid of 400 points, then a
    golden-section search between its neighbours (the power curves have one minimum)."""
    grid = np.linspace(lo, hi, 401)
    k = int(np.argmin([f(float(x)) for x in grid]))
    a, b = float(grid[max(k - 1, 0)]), float(grid[min(k + 1, len(grid) - 1)])
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    c, d = b - ratio * (b - a), a + ratio * (b - a)
    fc, fd = f(c), f(d)
    while b - a > 1e-9 * max(1.0, abs(b)):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - ratio * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + ratio * (b - a)
            fd = f(d)
    return (a + b) / 2.0
