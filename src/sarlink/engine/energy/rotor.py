"""The rotary-wing power model of Zeng, Xu and Zhang (IEEE Trans. Wireless Commun. 18(4),
2019, eq. (12)), with climb and descent, as Numba-compilable hooks.

Level flight at ground speed ``V`` (no wind), eq. (12):
``P(V) = P0 (1 + 3 V² / U_tip²) + Pi (sqrt(1 + V⁴ / (4 v0⁴)) - V² / (2 v0²))^½
+ ½ d0 ρ s A V³``: blade profile, induced and parasite power; at ``V = 0`` the hover power
``P0 + Pi``.

Straight up at ``vz > 0``: momentum theory of a rotor in axial climb (Leishman, *Principles
of Helicopter Aerodynamics*, 2nd ed., section 2.9): the rotor's induced velocity is
``v_i = sqrt(vz² / 4 + v0²) - vz / 2`` and the power ``P0 + (1 + k) W v_i + W vz``, the
blade profile as in hover, the induced power with Zeng's correction ``1 + k`` (so
``(1 + k) W = Pi / v0``) and the work against gravity. At ``vz = 0`` it is the hover power.

Straight down (``vz < 0``): the hover power. Momentum theory fails in slow descent (the
rotor works in its own wake, the vortex ring state; Leishman, section 2.13), where measured
powers stay near hover; counting a descent at hover power never under-counts the landing.

Parameters (``ep``, :data:`PARAMS`): ``P0, Pi, U_tip, v0, d0, rho, s, A, W, scale``; every
power is multiplied by ``scale``, so a preset can be another drone's measured level on the
same curve (:data:`RODRIGUES2021`).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["PARAMS", "RODRIGUES2021", "ZENG2019", "level", "no_power", "vertical"]

PARAMS = ("P0", "Pi", "U_tip", "v0", "d0", "rho", "s", "A", "W", "scale")
"""The names of the parameter array's entries, in order."""

ZENG2019 = (79.86, 88.63, 120.0, 4.03, 0.6, 1.225, 0.05, 0.503, 20.0, 1.0)
"""Zeng, Xu and Zhang's Table I: blade profile power P0 = 79.86 W and induced power
Pi = 88.63 W in hover, rotor tip speed 120 m/s, mean induced velocity in hover 4.03 m/s,
fuselage drag ratio 0.6, air density 1.225 kg/m³, rotor solidity 0.05, rotor disc area
0.503 m², aircraft weight W = 20 N."""

MEASURED_J_PER_M = 80.0
"""Rodrigues et al. (Patterns 3(8), 2022, from the flights of their Scientific Data 8, 2021
data set): a small quadcopter with a 0.5 kg package uses about 0.08 MJ/km."""
MEASURED_SPEEDS = (4.0, 6.0, 8.0, 10.0, 12.0)
"""The data set's programmed cruise speeds, m/s (Rodrigues et al., Scientific Data 2021)."""


@njit(cache=True, inline="always", error_model="numpy")
def level(v: float, ep: np.ndarray) -> float:
    """Power (W) in level flight at ground speed ``v`` (m/s); ``v = 0`` is hover."""
    p0, pi, tip, v0, d0, rho, s, a = ep[0], ep[1], ep[2], ep[3], ep[4], ep[5], ep[6], ep[7]
    v2 = v * v
    blade = p0 * (1.0 + 3.0 * v2 / (tip * tip))
    ratio = v2 / (2.0 * v0 * v0)
    induced = pi * math.sqrt(max(math.sqrt(1.0 + ratio * ratio) - ratio, 0.0))
    parasite = 0.5 * d0 * rho * s * a * v2 * v
    return ep[9] * (blade + induced + parasite)


def _calibrated_scale() -> float:
    """The factor that puts Zeng's curve at the measured level: its mean energy per metre
    over the data set's cruise speeds equals :data:`MEASURED_J_PER_M`."""
    ep = np.array(ZENG2019)
    mean = sum(level.py_func(v, ep) / v for v in MEASURED_SPEEDS) / len(MEASURED_SPEEDS)
    return MEASURED_J_PER_M / mean


RODRIGUES2021 = (*ZENG2019[:-1], _calibrated_scale())
"""Zeng's curve scaled to a measured small quadcopter (a DJI Matrice 100, Rodrigues et al.):
by the factor (about 4.0) that makes its mean energy per metre over the measured cruise
speeds 4 to 12 m/s the published 80 J/m (docs/model.md, Energy)."""


@njit(cache=True, inline="always", error_model="numpy")
def vertical(vz: float, ep: np.ndarray) -> float:
    """Power (W) flying straight up (``vz > 0``, m/s) or down (``vz < 0``): momentum theory
    in climb, the hover power in descent (module docstring)."""
    p0, pi, v0, w = ep[0], ep[1], ep[3], ep[8]
    if vz <= 0.0:
        return ep[9] * (p0 + pi)
    induced = math.sqrt(0.25 * vz * vz + v0 * v0) - 0.5 * vz
    return ep[9] * (p0 + pi * induced / v0 + w * vz)


@njit(cache=True, inline="always", error_model="numpy")
def no_power(v: float, ep: np.ndarray) -> float:
    """No power at any speed: the paper's drones, which fly without a battery."""
    return 0.0
