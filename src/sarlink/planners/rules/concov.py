"""ConCov: CovB's coverage and ConB's connectivity terms blended by α (Eq. 12, Algorithm 2),
shaped like a plug-in built from the two rules' parts: its hooks, its rule and its planner,
registered by :func:`sarlink.register_planner`.

At ``α = 1`` (``0``) Eq. 12 is exactly the CovB (ConB) direction and is used as such, so those
trajectories are identical to the pure rules'; only the terms that α weighs are computed.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from sarlink.engine.geometry import unit
from sarlink.engine.hooks import DistributedRule
from sarlink.engine.observation import Observation
from sarlink.engine.params import (
    CONNECTED_NONE,
    CONTINUOUS,
    COVB_PRINTED,
    FALLBACK_CONNECTIVITY,
    Params,
)
from sarlink.planners.base import RulePlanner
from sarlink.planners.registry import register_planner
from sarlink.planners.rules import conb, covb


class Workspace(NamedTuple):
    """CovB's flying drones, ConB's arrays, and ConB's directions before the blend."""

    flying: np.ndarray
    conb: conb.Workspace
    con_x: np.ndarray
    con_y: np.ndarray


@njit(cache=True, inline="always", error_model="numpy")
def blend(p: Params, cx: float, cy: float, vx: float, vy: float, hx: float,
          hy: float) -> tuple[float, float]:
    """ConCov's ``α R_cov + (1 − α) R_con`` re-scaled to length 1 (Eq. 12), from CovB's unit
    force ``(cx, cy)`` and ConB's ``(vx, vy)``.

    Where the two terms cancel, the drone keeps its heading or, with
    ``concov_fallback = connectivity``, follows ConB's term.
    """
    if p.alpha == 1.0:
        return cx, cy
    if p.alpha == 0.0:
        return vx, vy
    if p.concov_fallback == FALLBACK_CONNECTIVITY:
        hx, hy = vx, vy
    return unit(p.alpha * cx + (1.0 - p.alpha) * vx, p.alpha * cy + (1.0 - p.alpha) * vy,
                hx, hy)


@njit(cache=True, inline="always", error_model="numpy")
def prepare(p: Params, obs: Observation) -> Workspace:
    """The workspace of a ConCov team."""
    n = obs.hx.shape[0]
    return Workspace(covb.prepare(p, obs), conb.workspace(obs), np.zeros(n), np.zeros(n))


@njit(cache=True, inline="always", error_model="numpy")
def due(k: int, p: Params, obs: Observation, ws: Workspace, deciding: np.ndarray) -> bool:
    """ConB's continuous check, when the connectivity term counts (``α < 1``)."""
    return conb.check_continuously(k, p, obs, ws.conb, deciding,
                                   p.alpha < 1.0 and p.conb_check == CONTINUOUS)


@njit(cache=True, inline="always", error_model="numpy")
def decide(k: int, p: Params, obs: Observation, ws: Workspace, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    """Eq. 12's direction for every deciding drone."""
    if p.alpha < 1.0:
        no_term = p.concov_connected == CONNECTED_NONE and p.alpha > 0.0
        conb.directions(p, obs, ws.conb, deciding, no_term, ws.con_x, ws.con_y)
    if p.alpha > 0.0:
        covb.flying_drones(obs.mode, ws.flying)
    for i in range(deciding.shape[0]):
        if deciding[i]:
            cx, cy = obs.hx[i], obs.hy[i]
            if p.alpha > 0.0:
                cx, cy = covb.covb_force(i, obs.px, obs.py, obs.hx, obs.hy, obs.near, ws.flying,
                                         p.r, p.covb_direction == COVB_PRINTED)
            vx[i], vy[i] = blend(p, cx, cy, ws.con_x[i], ws.con_y[i], obs.hx[i], obs.hy[i])


CONCOV = DistributedRule("concov", decide, prepare=prepare, due=due, near=True,
                         readings=(*conb.CONB.readings, "covb_direction", "concov_fallback",
                                   "concov_connected"),
                         ignores_reporting=True)
"""ConCov's blend of the two (Eq. 12)."""

PLANNER = register_planner(RulePlanner("concov", "ConCov", CONCOV, colour="#9467bd",
                                       marker="v"))
