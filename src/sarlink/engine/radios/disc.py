"""The disc model (Eq. 4): two nodes are linked within the communication range r_c."""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.params import Params


@njit(cache=True, inline="always", error_model="numpy")
def disc_ranges(rc: float, m: int, mp: int) -> np.ndarray:
    """Squared link ranges ``rc²`` among the ``m`` nodes; none to the padding."""
    thr2 = np.zeros((m, mp))
    thr2[:, :m] = rc * rc
    return thr2


@njit(cache=True, inline="always", error_model="numpy")
def init(p: Params, rp: np.ndarray, m: int, mp: int) -> np.ndarray:
    """``r_c²`` for every pair, for the whole run."""
    return disc_ranges(p.rc, m, mp)


@njit(cache=True, inline="always", error_model="numpy")
def update(thr2: np.ndarray, p: Params, rp: np.ndarray, k: int, rng: np.random.Generator) -> None:
    """The disc never changes."""


@njit(cache=True, inline="always", error_model="numpy")
def nominal(p: Params, rp: np.ndarray) -> float:
    """The range itself."""
    return p.rc
