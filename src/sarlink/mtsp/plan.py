"""The mTSP plan every solver returns, and the distances solvers work on."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np

__all__ = ["MtspPlan", "Objective", "Solver", "distance_matrix"]

Solver = Literal["ga", "ortools"]
"""``ga``: the paper's genetic algorithm; ``ortools``: the strong solver."""
Objective = Literal["minsum", "minmax"]
"""``minsum``: the total distance (the paper's); ``minmax``: the longest tour."""


@dataclass(frozen=True, eq=False)
class MtspPlan:
    """An mTSP plan: which points each salesman (drone) visits, in order, from and to the depot.

    The plan checks itself on construction: the tours must visit every point exactly once, each
    at least ``min_cells`` of them.
    Arrays are read-only, so a plan can be shared (it is memoised by :func:`plan_for`).
    """

    points: np.ndarray
    """The cities, shape ``(K, 2)``, metres."""
    depot: tuple[float, float]
    """Where every tour starts and ends (the BS)."""
    tours: tuple[tuple[int, ...], ...]
    """Per salesman, the indices into ``points`` in visiting order; the depot is not listed."""
    min_cells: int = 1
    """The least number of points any tour was allowed."""
    solver: Solver = "ga"
    objective: Objective = "minsum"
    history: np.ndarray = field(default_factory=lambda: np.empty(0))
    """GA: the best cost in each iteration's population (Kirk's ``dist_history``; the best of
    each group survives, so it never rises); empty for OR-Tools."""
    seconds: float = 0.0
    """Wall time of the solve that produced the plan (kept when the plan is read from cache)."""
    evaluations: int | None = None
    """GA: the individuals costed, population × iterations (Fig. 1's work count, which does
    not depend on the machine); None for the other solvers and for a plan read from cache."""
    lengths: np.ndarray = field(init=False)
    """Per salesman the tour length in metres, including the legs from and to the depot."""

    def __post_init__(self) -> None:
        points = np.array(self.points, dtype=float)
        depot = (float(self.depot[0]), float(self.depot[1]))
        tours = tuple(tuple(int(i) for i in tour) for tour in self.tours)
        visited = sorted(i for tour in tours for i in tour)
        if visited != list(range(len(points))):
            raise ValueError("tours must visit every point index exactly once")
        if min(map(len, tours), default=0) < self.min_cells:
            raise ValueError(f"every tour must visit at least min_cells = {self.min_cells} points")
        lengths = np.array([_tour_length(points, depot, tour) for tour in tours])
        history = np.array(self.history, dtype=float)
        for arr in (points, lengths, history):
            arr.setflags(write=False)
        for name, value in (("points", points), ("depot", depot), ("tours", tours),
                            ("history", history), ("lengths", lengths)):
            object.__setattr__(self, name, value)

    @property
    def total(self) -> float:
        """Total distance flown by all salesmen, m (the paper's objective)."""
        return float(self.lengths.sum())

    @property
    def longest(self) -> float:
        """Length of the longest tour, m: with the speed, the time the search takes."""
        return float(self.lengths.max())

    def routes(self) -> tuple[np.ndarray, ...]:
        """Per salesman the waypoints to fly, shape ``(k + 1, 2)``: its points, then the depot.

        The drone takes off at the depot, so the depot is not repeated at the start.
        """
        return tuple(np.vstack([self.points[list(tour)], self.depot]) for tour in self.tours)


def _tour_length(points: np.ndarray, depot: tuple[float, float], tour: tuple[int, ...]) -> float:
    path = np.vstack([depot, points[list(tour)], depot])
    return float(np.hypot(*np.diff(path, axis=0).T).sum())


def distance_matrix(points: np.ndarray, depot: tuple[float, float]) -> np.ndarray:
    """Euclidean distance matrix over the depot (index 0) and the points (1..K)."""
    coords = np.vstack([depot, points])
    diff = coords[:, None, :] - coords[None, :, :]
    return np.sqrt((diff**2).sum(axis=-1))
