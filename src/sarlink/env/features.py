"""What an agent observes: a flat vector per drone, computed from the engine's state.

Lengths are scaled so that a policy sees numbers near one: positions by the area's side ``a``,
relative positions of neighbours by the nominal range ``r_c``, times by the horizon and the
flight budget. The layout (:data:`OWN`, then :data:`NEIGHBOUR` per neighbour slot):
"""

from __future__ import annotations

import math

import numpy as np
from gymnasium import spaces
from numba import njit

from sarlink.engine.graph import has
from sarlink.engine.observation import Observation
from sarlink.engine.params import Params

OWN: tuple[tuple[str, float, float, str], ...] = (
    ("x", 0.0, 1.0, "own position x / a (the mission's local frame, the square [0, a]²)"),
    ("y", 0.0, 1.0, "own position y / a"),
    ("heading_x", -1.0, 1.0, "own unit heading, x"),
    ("heading_y", -1.0, 1.0, "own unit heading, y"),
    ("time", 0.0, 1.0, "t / horizon"),
    ("budget", 0.0, 1.0, "remaining flight budget, max(0, T_f - t) / T_f"),
    ("knows", 0.0, 1.0, "1 if the drone knows where the target is"),
    ("routed", 0.0, 1.0, "1 if the drone has a multihop route to the BS"),
    ("bs_dx", -1.0, 1.0, "the BS's position relative to the drone, x / a"),
    ("bs_dy", -1.0, 1.0, "the same, y / a"),
    ("decides", 0.0, 1.0, "1 if the drone decides at this step (its action is used)"),
)
"""The drone's own features: name, low, high, meaning."""

NEIGHBOUR: tuple[tuple[str, float, float, str], ...] = (
    ("present", 0.0, 1.0, "1 if the slot holds a neighbour (else the slot is all zeros)"),
    ("dx", -math.inf, math.inf, "its position relative to the drone, x / r_c (within "
                                "+-a / r_c)"),
    ("dy", -math.inf, math.inf, "the same, y / r_c"),
    ("heading_x", -1.0, 1.0, "its unit heading, x"),
    ("heading_y", -1.0, 1.0, "its unit heading, y"),
    ("routed", 0.0, 1.0, "1 if it has a route to the BS"),
)
"""One neighbour slot: the linked drones (this step's radio links; within r_c for the disc
model), nearest first, padded with zero slots."""


_OWN = len(OWN)
_PER = len(NEIGHBOUR)


def feature_names(neighbours: int) -> list[str]:
    """The name of every entry of an observation with ``neighbours`` slots."""
    return [f[0] for f in OWN] + [f"n{s}_{f[0]}" for s in range(neighbours) for f in NEIGHBOUR]


def observation_space(neighbours: int, reach: float) -> spaces.Box:
    """The space of one agent's observation (float32); ``reach = a / r_c`` bounds the
    neighbours' relative positions (drones stay in the square ``[0, a]²``)."""
    rows = list(OWN) + list(NEIGHBOUR) * neighbours
    low = np.array([max(r[1], -reach) for r in rows], dtype=np.float32)
    high = np.array([min(r[2], reach) for r in rows], dtype=np.float32)
    return spaces.Box(low, high, dtype=np.float32)


@njit(cache=True, error_model="numpy")
def features(k: int, p: Params, obs: Observation, deciding: np.ndarray,
             out: np.ndarray) -> None:
    """Fill ``out`` (shape ``(N, len(OWN) + slots * len(NEIGHBOUR))``) from the state."""
    n = deciding.shape[0]
    own, per = _OWN, _PER
    slots = (out.shape[1] - own) // per
    t = k * p.dt
    horizon = p.n_steps * p.dt
    a = p.size
    out[:] = 0.0
    d2 = np.empty(n)
    order = np.empty(n, dtype=np.int64)
    for i in range(n):
        x, y = obs.px[i], obs.py[i]
        row = out[i]
        row[0], row[1] = x / a, y / a
        row[2], row[3] = obs.hx[i], obs.hy[i]
        row[4] = min(1.0, t / horizon)
        row[5] = max(0.0, p.flight_time - t) / p.flight_time
        row[6] = 1.0 if obs.knows[i] else 0.0
        row[7] = 1.0 if has(obs.routed, i) else 0.0
        row[8], row[9] = (p.bs_x - x) / a, (p.bs_y - y) / a
        row[10] = 1.0 if deciding[i] else 0.0
        found = 0
        for j in range(n):
            if j != i and has(obs.adj[i], j):
                dx, dy = obs.px[j] - x, obs.py[j] - y
                d2[found] = dx * dx + dy * dy
                order[found] = j
                found += 1
        rank = np.argsort(d2[:found], kind="mergesort")  # nearest first, ties by index
        for s in range(min(slots, found)):
            j = order[rank[s]]
            c = own + s * per
            row[c] = 1.0
            row[c + 1] = (obs.px[j] - x) / obs.rc
            row[c + 2] = (obs.py[j] - y) / obs.rc
            row[c + 3], row[c + 4] = obs.hx[j], obs.hy[j]
            row[c + 5] = 1.0 if has(obs.routed, j) else 0.0
