"""``tether``: CovB's repulsion while a drone has a route to the BS; without one, back to it.

A distributed rule is a Numba function that reads the observed state (``obs``: positions,
headings, the neighbour and route-to-BS bitsets, ...) and writes the new unit direction of
every drone that decides this step. sarlink compiles it into its kernel.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink import DistributedRule, Observation, Params, RulePlanner
from sarlink.engine.graph import has


@njit
def decide(k: int, p: Params, obs: Observation, ws: np.ndarray, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    n = deciding.shape[0]
    bs = n  # node indices: the drones, then the BS, then the target
    for i in range(n):
        if not deciding[i]:
            continue
        if not has(obs.routed, i):  # cut off from the BS: head home
            fx, fy = obs.px[bs] - obs.px[i], obs.py[bs] - obs.py[i]
        else:  # repelled by the drones within the sensing range, 1/d each
            fx, fy = obs.hx[i] / p.r, obs.hy[i] / p.r
            for j in range(n):
                if j != i and has(obs.near[i], j):
                    dx, dy = obs.px[i] - obs.px[j], obs.py[i] - obs.py[j]
                    dd = dx * dx + dy * dy
                    if dd >= 1.0:
                        fx += dx / dd
                        fy += dy / dd
        norm = math.sqrt(fx * fx + fy * fy)
        if norm > 1e-12:
            vx[i], vy[i] = fx / norm, fy / norm


TETHER = RulePlanner("tether", "Tether",
                     DistributedRule("tether", decide, near=True, ignores_reporting=True),
                     colour="#aec7e8", marker="p")
"""The rule reads the links (``obs.routed``), so it is not ``range_free``; it never reads
``p.on_detect``, so it declares ``ignores_reporting`` (the contract checks both in flight)."""
