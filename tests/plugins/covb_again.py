"""CovB written again outside sarlink, on the public plug-in API only (docs/plugins.md).

Eq. 6: a deciding drone turns to its own heading over r plus, from every flying drone within
the sensing range r, a push of 1/d along the line between them. The tests check that it flies
exactly as the built-in CovB; ``benchmarks/bench_paired.py plugin`` times the two.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink import DistributedRule, Observation, Params, RulePlanner
from sarlink.engine.codes import Mode
from sarlink.engine.graph import has

LANDED = int(Mode.LANDED)


@njit
def prepare(p: Params, obs: Observation) -> np.ndarray:
    return np.zeros(0)


@njit
def decide(k: int, p: Params, obs: Observation, ws: np.ndarray, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    n = deciding.shape[0]
    for i in range(n):
        if not deciding[i]:
            continue
        fx, fy = obs.hx[i] / p.r, obs.hy[i] / p.r
        pushed = False
        for j in range(n):
            if obs.mode[j] == LANDED or not has(obs.near[i], j):
                continue
            pushed = True
            dx, dy = obs.px[i] - obs.px[j], obs.py[i] - obs.py[j]
            dd = dx * dx + dy * dy
            if dd >= 1.0:
                fx += dx / dd
                fy += dy / dd
        norm = math.sqrt(fx * fx + fy * fy)
        if pushed and norm >= 1e-12:
            vx[i], vy[i] = fx / norm, fy / norm
        else:
            vx[i], vy[i] = obs.hx[i], obs.hy[i]


COVB_AGAIN = DistributedRule("covb-again", decide, prepare=prepare, near=True)
PLANNER = RulePlanner("covb-again", "CovB (plug-in)", COVB_AGAIN)
