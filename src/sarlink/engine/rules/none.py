"""The rule of a team without distributed drones (every drone flies a route): it never runs.

Its hooks are also the defaults of a rule that leaves one out (:mod:`sarlink.engine.build`).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.observation import Observation
from sarlink.engine.params import Params


@njit(cache=True, inline="always", error_model="numpy")
def prepare(p: Params, obs: Observation) -> np.ndarray:
    """No workspace."""
    return np.zeros(0)


@njit(cache=True, inline="always", error_model="numpy")
def due(k: int, p: Params, obs: Observation, ws: np.ndarray, deciding: np.ndarray) -> bool:
    """The default of a rule without a ``due`` hook (never called: the kernel skips it)."""
    return False


@njit(cache=True, inline="always", error_model="numpy")
def decide(k: int, p: Params, obs: Observation, ws: np.ndarray, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    """Nothing to decide: no drone runs a rule."""
