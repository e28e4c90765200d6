"""A rule that reads the mission's ``on_detect``: in a team whose drones will report, every
drone searches heading for the BS from its first decision on, before anyone knows anything.
Legal, but its runs with and without reporting part at take-off, so it must not declare
``ignores_reporting``; the tests check that its reporting runs are flown, not taken from the
runs without reporting (sarlink.engine.sharing)."""

from __future__ import annotations

import numpy as np
from numba import njit

from sarlink import DistributedRule, Observation, Params, RulePlanner
from sarlink.engine.geometry import unit
from sarlink.engine.params import REPORT


@njit
def decide(k: int, p: Params, obs: Observation, ws: np.ndarray, deciding: np.ndarray,
           vx: np.ndarray, vy: np.ndarray) -> None:
    n = deciding.shape[0]
    for i in range(n):
        if deciding[i] and p.on_detect == REPORT:
            vx[i], vy[i] = unit(obs.px[n] - obs.px[i], obs.py[n] - obs.py[i], vx[i], vy[i])


HOMEBOUND = RulePlanner("homebound", "Homebound when reporting",
                        DistributedRule("homebound", decide))
