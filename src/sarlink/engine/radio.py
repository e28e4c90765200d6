"""The radio channel: the squared range of every link, the one place a channel model goes.

A link between nodes ``a`` and ``b`` exists when their squared distance is at most
``thr2[a, b]``. The disc model (Eq. 4) is a fixed ``r_c²``; log-normal shadowing (Eq. 13)
redraws every pair's threshold each coherence time. ConB's predictions use the shadow-free
``disc2``: a drone cannot foresee fading. A new channel model fills ``thr2`` here, at the
step it changes, and the rest of the engine is unchanged.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.params import Params

_LN10 = math.log(10.0)


@njit(cache=True, inline="always", error_model="numpy")
def disc_ranges(p: Params, m: int, mp: int) -> np.ndarray:
    """Squared link ranges of the disc model among the ``m`` nodes; none to the padding."""
    disc2 = np.zeros((m, mp))
    disc2[:, :m] = p.rc * p.rc
    return disc2


@njit(cache=True, inline="always", error_model="numpy")
def draw_shadowing(thr2: np.ndarray, p: Params, rng: np.random.Generator) -> None:
    """Redraw the per-link squared range: ``10 n log10(d/rc) + S <= 0  <=>  d² <= rc² 10^(-S/5n)``.

    With ``S = 0`` the factor is exactly 1, so ``sigma = 0`` is the disc model bit for bit.
    """
    m = thr2.shape[0]
    rc2 = p.rc * p.rc
    scale = -_LN10 / (5.0 * p.pathloss_exponent)
    for a in range(m):
        for b in range(a + 1, m):
            s = p.sigma * rng.standard_normal()
            v = rc2 * math.exp(scale * s)
            thr2[a, b] = v
            thr2[b, a] = v


@njit(cache=True, inline="always", error_model="numpy")
def update_channel(thr2: np.ndarray, p: Params, k: int, rng: np.random.Generator) -> None:
    """The link ranges of step ``k``: shadowing is redrawn every coherence time."""
    if p.sigma > 0.0 and k % p.coherence_steps == 0:
        draw_shadowing(thr2, p, rng)
