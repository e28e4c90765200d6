"""The cities of the search: square cells of side ``r`` covering the area."""

from __future__ import annotations

import math

import numpy as np

__all__ = ["grid_cells"]


def grid_cells(size: float, r: float) -> np.ndarray:
    """Centres of the square cells of side ``r`` that cover the area ``[0, size]²``.

    There are ``n = ceil(size / r)`` cells per side (8 for the paper's 4000 m and 500 m, so 64
    cells). Cell ``k`` lies in column ``k % n`` (x) and row ``k // n`` (y), rows counted from
    ``y = 0``: row-major order. When ``size / r`` is not an integer, the last column and row
    are moved inwards so that their centres stay ``r / 2`` from the border (the last cells then
    overlap their neighbours instead of sticking out of the area); when ``r > size`` the single
    cell is centred in the area.

    Returns
    -------
    np.ndarray
        Shape ``(n², 2)``, the cell centres (x, y) in metres.
    """
    if not (math.isfinite(size) and size > 0):
        raise ValueError(f"size must be a finite number > 0, got {size}")
    if not (math.isfinite(r) and r > 0):
        raise ValueError(f"r must be a finite number > 0, got {r}")
    n = max(1, math.ceil(size / r - 1e-9))
    centres = np.minimum((np.arange(n) + 0.5) * r, max(size - r / 2, size / 2))
    xs, ys = np.meshgrid(centres, centres)
    return np.column_stack([xs.ravel(), ys.ravel()])
