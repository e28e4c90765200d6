"""``rays``: every drone flies from the BS along its own ray to the edge of the area and back.

A route planner is a function of the mission that returns one array of (x, y) waypoints per
drone; sarlink flies them in turn and lands the drone at the BS.
"""

from __future__ import annotations

import math

import numpy as np

from sarlink import Mission, RoutePlanner


def edge_point(bs: tuple[float, float], angle: float, size: float) -> tuple[float, float]:
    """Where the ray from ``bs`` at ``angle`` leaves the square ``[0, size]²``."""
    dx, dy = math.cos(angle), math.sin(angle)
    tx = (size - bs[0]) / dx if dx > 1e-12 else -bs[0] / dx if dx < -1e-12 else math.inf
    ty = (size - bs[1]) / dy if dy > 1e-12 else -bs[1] / dy if dy < -1e-12 else math.inf
    t = min(tx, ty)
    return min(max(bs[0] + t * dx, 0.0), size), min(max(bs[1] + t * dy, 0.0), size)


def rays(mission: Mission) -> list[np.ndarray]:
    """Drone ``i`` flies out at angle ``2 pi i / N`` and back."""
    n, size, bs = mission.team.drones, mission.area.size, mission.area.bs_xy
    return [np.array([edge_point(bs, 2 * math.pi * i / n, size), bs]) for i in range(n)]


RAYS = RoutePlanner("rays", "Rays", rays, colour="#e377c2", marker="h")
