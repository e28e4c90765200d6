"""The still target: the paper's, where it was drawn for the whole run. Its hooks are what
the kernel's template imports when a mission's target does not move; they are never called
(``TARGET_MOVES = False`` prunes them, :mod:`sarlink.engine.build`)."""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, inline="always", error_model="numpy")
def start(xy: np.ndarray, state: np.ndarray, tp: np.ndarray, rng: np.random.Generator) -> None:
    """Nothing to draw."""


@njit(cache=True, inline="always", error_model="numpy")
def move(xy: np.ndarray, state: np.ndarray, t: float, dt: float, tp: np.ndarray,
         edges: np.ndarray, size: float, rng: np.random.Generator) -> None:
    """Stay."""
