"""A random walk: each deciding drone turns to a heading drawn uniformly from its rule's own
random stream (``obs.rng``, docs/plugins.md), the baseline of random search. The tests check
that its draws come from ``(seed, run)`` only and change nothing else in the run."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink import DistributedRule, Observation, Params, RulePlanner


@njit
def decide(k: int, p: Params, obs: Observation, ws: np.ndarray, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    for i in range(deciding.shape[0]):
        if deciding[i]:
            heading = 2.0 * math.pi * obs.rng.random()
            vx[i], vy[i] = math.cos(heading), math.sin(heading)


RANDOM_WALK = RulePlanner("random-walk", "Random walk",
                          DistributedRule("random-walk", decide, range_free=True))
