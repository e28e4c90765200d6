"""Plane geometry the phases share: unit vectors, the area, and the padding of node arrays."""

from __future__ import annotations

import math

from numba import njit

TINY = 1e-12
"""Below this length a vector has no direction."""
PAD = 8
"""Position arrays are padded to a multiple of this many nodes, which the link loops then
cover in whole vectors: at N = 10 the scalar remainder of 12 nodes cost more than the rest."""
FAR = 1e18
"""Where the padding nodes sit: farther than any range, so no link or sensing bit is set."""


@njit(cache=True, error_model="numpy")
def unit(x: float, y: float, fx: float, fy: float) -> tuple[float, float]:
    """``(x, y)`` scaled to length 1, or the fallback ``(fx, fy)`` if it vanishes."""
    n = math.sqrt(x * x + y * y)
    if n < TINY:
        return fx, fy
    return x / n, y / n


@njit(cache=True, error_model="numpy")
def d2(xa: float, ya: float, za: float, xb: float, yb: float, zb: float) -> float:
    """The squared distance from node a to node b, in the link pass's arithmetic
    (:func:`sarlink.engine.graph.links`), whose bits every other test of a link must match."""
    dx = xa - xb
    dy = ya - yb
    dz = za - zb
    return dx * dx + dy * dy + dz * dz


@njit(cache=True, error_model="numpy")
def inside(x: float, y: float, size: float) -> bool:
    """Whether ``(x, y)`` lies in the square area ``[0, size]²``."""
    return 0.0 <= x <= size and 0.0 <= y <= size


TURNED = 1e-9
"""The smallest change of heading, rad, that counts as a turn: a rule's sums of unit vectors
round in their last bits."""


@njit(cache=True, error_model="numpy")
def turned(hx: float, hy: float, nx: float, ny: float) -> bool:
    """Whether the unit heading ``(nx, ny)`` is another than ``(hx, hy)``, by more than
    :data:`TURNED`."""
    return abs(hx * ny - hy * nx) > TURNED or hx * nx + hy * ny < 0.0
