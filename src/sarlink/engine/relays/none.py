"""The relay hooks of a team without relays: the defaults of a strategy that leaves one out
(:mod:`sarlink.engine.build`); the kernel of such a team never calls them."""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.observation import Observation
from sarlink.engine.params import Params


@njit(cache=True, inline="always", error_model="numpy")
def prepare(p: Params, obs: Observation) -> np.ndarray:
    """No workspace."""
    return np.zeros((0, 0))


@njit(cache=True, inline="always", error_model="numpy")
def place(k: int, p: Params, obs: Observation, ws: np.ndarray, edges: np.ndarray,
          gx: np.ndarray, gy: np.ndarray) -> None:
    """Nothing to place: every relay holds the point it has."""
