"""Relay strategies written outside sarlink.

``MIDPOINT`` is the example of docs/plugins.md: every relay holds the midpoint between the BS
and the searcher farthest from it where the BS last heard of them. ``FAULTY`` is wrong in the
way its mission's ``team.alpha`` (which CovB's searchers never read) chooses, so that one
compiled kernel serves every fault: at 0.25 its points are NaN, at 0.75 they are drawn from
Numba's global random state, which no ``(seed, run)`` resets; else it is ``MIDPOINT``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink import Observation, Params, RelayStrategy
from sarlink.engine.graph import has
from sarlink.engine.params import LANDED, RELAYING


@njit
def prepare(p: Params, obs: Observation) -> np.ndarray:
    """Where the BS last heard of each drone, ``(2, N)``: at take-off to start with."""
    n = obs.hx.shape[0]
    heard = np.empty((2, n))
    heard[0], heard[1] = obs.px[:n], obs.py[:n]
    return heard


@njit
def place(k: int, p: Params, obs: Observation, ws: np.ndarray, edges: np.ndarray,
          gx: np.ndarray, gy: np.ndarray) -> None:
    n = gx.shape[0]
    far, fx, fy = -1.0, p.bs_x, p.bs_y
    for i in range(n):
        if has(obs.routed, i):  # the BS hears drone i this step
            ws[0, i], ws[1, i] = obs.px[i], obs.py[i]
        if obs.mode[i] != RELAYING and obs.mode[i] != LANDED:
            d = math.hypot(ws[0, i] - p.bs_x, ws[1, i] - p.bs_y)
            if d > far:
                far, fx, fy = d, ws[0, i], ws[1, i]
    for i in range(n):
        if obs.mode[i] == RELAYING:
            gx[i], gy[i] = (p.bs_x + fx) / 2, (p.bs_y + fy) / 2


@njit
def place_faulty(k: int, p: Params, obs: Observation, ws: np.ndarray, edges: np.ndarray,
                 gx: np.ndarray, gy: np.ndarray) -> None:
    place(k, p, obs, ws, edges, gx, gy)
    for i in range(gx.shape[0]):
        if obs.mode[i] == RELAYING and p.alpha == 0.25:
            gx[i] = np.nan
        elif obs.mode[i] == RELAYING and p.alpha == 0.75:
            gx[i], gy[i] = np.random.random() * p.size, np.random.random() * p.size  # noqa: NPY002


MIDPOINT = RelayStrategy("midpoint", place, prepare=prepare)
FAULTY = RelayStrategy("faulty", place_faulty, prepare=prepare)
