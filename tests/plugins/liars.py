"""A rule whose declaration is false, for the contract (sarlink.testing.check_rule) to catch:
``CLINGY`` declares ``range_free`` but reads the links (a drone with no neighbour turns back to
the BS), so its flights part wherever the range changes who neighbours whom."""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink import DistributedRule, Observation, Params
from sarlink.engine.geometry import unit


@njit
def decide(k: int, p: Params, obs: Observation, ws: np.ndarray, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    n = deciding.shape[0]
    for i in range(n):
        if deciding[i] and not obs.adj[i].any():
            vx[i], vy[i] = unit(obs.px[n] - obs.px[i], obs.py[n] - obs.py[i], vx[i], vy[i])


CLINGY = DistributedRule("clingy", decide, range_free=True)
