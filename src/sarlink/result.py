"""What one run produces: event times, cumulative records and, on request, the trajectory."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np


@dataclass(frozen=True)
class Trajectory:
    """The state at every step ``t`` (arrays indexed ``[step, drone]``)."""

    t: np.ndarray
    positions: np.ndarray
    """(steps, N, 2) metres"""
    headings: np.ndarray
    """(steps, N) radians"""
    knows: np.ndarray
    """(steps, N) whether the drone knows the target's location"""
    bs_route: np.ndarray
    """(steps, N) whether the drone has a multihop route to the BS"""
    mode: np.ndarray
    """(steps, N) :class:`sarlink.engine.codes.Mode`"""
    links: np.ndarray
    """(steps, N + 2, N + 2) whether two nodes are linked (drones ``0 .. N-1``, the BS ``N``,
    the target ``N + 1``), as the links were at that step (with shadowing, as drawn)"""


@dataclass(frozen=True)
class RunResult:
    """Outcome of one run, read for any target duration ``t_d`` up to the horizon.

    Times are in seconds from take-off; ``None`` means the event did not happen within the
    horizon. ``reach_cum[c]`` is the time the target was reachable during
    ``[0, checkpoints[c])``; ``connected_cum[c]`` the time integral of the fraction of drones
    with a route to the BS over the same interval.
    """

    seed: int
    run: int
    target: tuple[float, float]
    t_detect: float | None
    t_notify: float | None
    immediate: bool
    detector: int | None
    checkpoints: np.ndarray
    reach_cum: np.ndarray
    connected_cum: np.ndarray
    trajectory: Trajectory | None = None
    notify_times: np.ndarray | None = None
    """A range-free run's notification staircase (:mod:`sarlink.engine.ranges`), when asked
    for: at any range ``r_c`` the BS is notified at ``notify_times[j]`` for the first ``j``
    with ``notify_rc2[j] <= r_c * r_c`` (never, if there is none); None otherwise."""
    notify_rc2: np.ndarray | None = None
    """The squared ranges of that staircase, m², strictly falling."""

    @property
    def horizon(self) -> float:
        """The last checkpoint, s: the time the run covers."""
        return float(self.checkpoints[-1])

    def _upto(self, td: float | None) -> float:
        td = self.horizon if td is None else td
        if not 0 < td <= self.horizon:
            raise ValueError(f"td must be in (0, {self.horizon}], got {td}")
        return td

    def detected(self, td: float | None = None) -> bool:
        """Whether the target was detected by ``t_d`` (Eq. 2)."""
        return self.t_detect is not None and self.t_detect <= self._upto(td)

    def notified(self, td: float | None = None) -> bool:
        """Mission success: the BS was notified by ``t_d`` (Eq. 1)."""
        return self.t_notify is not None and self.t_notify <= self._upto(td)

    def t_reachable(self, td: float | None = None) -> float:
        """Seconds of ``[0, t_d]`` during which the target had a route to the BS."""
        return float(np.interp(self._upto(td), self.checkpoints, self.reach_cum))

    def connected_fraction(self, td: float | None = None) -> float:
        """Mean fraction of drones with a route to the BS over ``[0, t_d]``."""
        td = self._upto(td)
        return float(np.interp(td, self.checkpoints, self.connected_cum)) / td

    def row(self) -> dict[str, Any]:
        """A flat record for tables: missing event times are NaN; a staircase as two more
        columns."""
        return {
            "seed": self.seed,
            "run": self.run,
            "target_x": self.target[0],
            "target_y": self.target[1],
            "t_detect": math.nan if self.t_detect is None else self.t_detect,
            "t_notify": math.nan if self.t_notify is None else self.t_notify,
            "immediate": self.immediate,
            "detector": -1 if self.detector is None else self.detector,
            "t_reachable": self.t_reachable(),
            "connected_fraction": self.connected_fraction(),
            "checkpoints": self.checkpoints.tolist(),
            "reach_cum": self.reach_cum.tolist(),
            "connected_cum": self.connected_cum.tolist(),
            **({} if self.notify_times is None or self.notify_rc2 is None else {
                "notify_times": self.notify_times.tolist(),
                "notify_rc2": self.notify_rc2.tolist()}),
        }
