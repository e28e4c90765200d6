"""Plug-ins that are wrong in the ways a plug-in author's can be."""

from __future__ import annotations

import numpy as np

from sarlink import Mission


def decide_too_few(k, p, obs, ws, deciding, vx):  # type: ignore[no-untyped-def]
    pass


def decide_untyped(k, p, obs, ws, deciding, vx, vy):  # type: ignore[no-untyped-def]
    vx[0] = obs.no_such_field


def routes_raise(mission: Mission) -> list[np.ndarray]:
    raise RuntimeError("the solver licence expired")


def routes_outside(mission: Mission) -> list[np.ndarray]:
    return [np.array([[100.0, 100.0], [mission.area.size + 50.0, 10.0]])] * mission.team.drones


def routes_diagonal(mission: Mission) -> list[np.ndarray]:
    """A good route function: each drone to a point of the diagonal and back."""
    a, n = mission.area.size, mission.team.drones
    return [np.array([[a * (i + 1) / (n + 1)] * 2]) for i in range(n)]


def routes_too_few(mission: Mission) -> list[np.ndarray]:
    return [np.array([[100.0, 100.0]])]
