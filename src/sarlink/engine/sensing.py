"""The target sensor (Eq. 2) and its imperfection (Section 4.3): who looks, who detects."""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.params import PER_PERIOD, Params


@njit(cache=True, error_model="numpy")
def sense(px: np.ndarray, py: np.ndarray, k: int, p: Params, in_range: np.ndarray,
          pass_start: np.ndarray, knows: np.ndarray, rng: np.random.Generator) -> int:
    """Let every drone with the target in range look; return the first to detect, or -1.

    A look happens when a drone's range newly covers the target (a pass starts) and, with
    per-period looks, every ``t_s`` of the pass; each look misses with ``p_miss``. A detector
    knows the target's location from then on. The target is node ``N + 1`` of ``px, py``.
    """
    n = knows.shape[0]
    tx, ty = px[n + 1], py[n + 1]
    r2 = p.r * p.r
    first = -1
    for i in range(n):
        dx, dy = px[i] - tx, py[i] - ty
        now_in = dx * dx + dy * dy <= r2
        if now_in:
            look = not in_range[i]
            if look:
                pass_start[i] = k
            elif p.look == PER_PERIOD and (k - pass_start[i]) % p.ts_steps == 0:
                look = True
            if look and rng.random() >= p.p_miss:
                knows[i] = True
                if first < 0:
                    first = i
        in_range[i] = now_in
    return first
