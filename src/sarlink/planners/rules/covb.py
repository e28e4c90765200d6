"""CovB: distributed coverage by mutual repulsion (Section 3.1.2, Eqs. 6-8), shaped like a
plug-in: its hooks, its rule and its planner, registered by :func:`sarlink.register_planner`.

A deciding drone turns to Eq. 6's resultant: its own heading over r plus a 1/d push from each
flying drone within the sensing range r. The rule asks for the ``near`` bitsets (pairs within
r) on the steps at which drones decide.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink.engine.geometry import unit
from sarlink.engine.graph import add, lowest
from sarlink.engine.hooks import DistributedRule
from sarlink.engine.observation import Observation
from sarlink.engine.params import COVB_PRINTED, LANDED, Params
from sarlink.planners.base import RulePlanner
from sarlink.planners.registry import register_planner

_ONE = np.uint64(1)


@njit(cache=True, inline="always", error_model="numpy")
def covb_force(i: int, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
               near: np.ndarray, flying: np.ndarray, r: float,
               printed: bool) -> tuple[float, float]:
    """Unit direction of Eq. 6 for drone ``i``: own heading / r plus a 1/d push from each
    flying drone within r (``near & flying``), added in increasing drone order; a pull
    towards it with ``printed`` (Eq. 8's θ_ij as printed, from i to j:
    ``readings.covb_direction``). No neighbour: keep the heading."""
    sign = -1.0 if printed else 1.0
    fx, fy = hx[i] / r, hy[i] / r
    neighbours = False
    for w in range(flying.shape[0]):
        bits = near[i, w] & flying[w]
        while bits:
            j = w * 64 + lowest(bits)
            bits &= bits - _ONE
            neighbours = True
            dx = px[i] - px[j]
            dy = py[i] - py[j]
            dd = dx * dx + dy * dy
            if dd >= 1.0:  # (1/d) * (p_i - p_j)/d; pairs closer than 1 m exert no force
                fx += sign * dx / dd
                fy += sign * dy / dd
    ux, uy = hx[i], hy[i]
    if neighbours:
        ux, uy = unit(fx, fy, ux, uy)
    return ux, uy


@njit(cache=True, inline="always", error_model="numpy")
def flying_drones(mode: np.ndarray, flying: np.ndarray) -> None:
    """``flying``: the bitset of the drones that have not landed (they exert the push)."""
    flying[:] = 0
    for i in range(mode.shape[0]):
        if mode[i] != LANDED:
            add(flying, i)


@njit(cache=True, inline="always", error_model="numpy")
def prepare(p: Params, obs: Observation) -> np.ndarray:
    """The workspace: the bitset of flying drones."""
    return np.zeros(obs.adj.shape[1], dtype=np.uint64)


@njit(cache=True, inline="always", error_model="numpy")
def decide(k: int, p: Params, obs: Observation, flying: np.ndarray, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    """Eq. 6's direction for every deciding drone."""
    flying_drones(obs.mode, flying)
    px, py, hx, hy, near = obs.px, obs.py, obs.hx, obs.hy, obs.near
    for i in range(deciding.shape[0]):
        if deciding[i]:
            vx[i], vy[i] = covb_force(i, px, py, hx, hy, near, flying, p.r,
                                      p.covb_direction == COVB_PRINTED)


COVB = DistributedRule("covb", decide, prepare=prepare, near=True,
                       readings=("covb_direction", "takeoff"), range_free=True,
                       ignores_reporting=True)
"""CovB's repulsion (Eqs. 6-8): it reads the pairs within the sensing range, never a link."""

PLANNER = register_planner(RulePlanner("covb", "CovB", COVB, colour="#ff7f0e", marker="s"))
