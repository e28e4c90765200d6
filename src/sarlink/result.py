"""What one run produces: event times, cumulative records and, on request, the trajectory."""

from __future__ import annotations

import math
from collections.abc import Sequence
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
    target: np.ndarray | None = None
    """(steps, K, 2) metres: every moving target's position at every step (None: the targets
    stand still at :attr:`RunResult.target` and :attr:`RunResult.targets`)"""


@dataclass(frozen=True)
class RunResult:
    """Outcome of one run, read for any target duration ``t_d`` up to the horizon.

    Times are in seconds from take-off; ``None`` means the event did not happen within the
    horizon. ``reach_cum[c]`` is the time the target was reachable during
    ``[0, checkpoints[c])``; ``connected_cum[c]`` the time integral of the fraction of drones
    with a route to the BS over the same interval. ``depth[c]`` and ``farthest[c]`` are a
    snapshot of the BS's network at ``checkpoints[c]``: the most hops from the BS to an
    airborne drone with a route (parked drones are part of the BS) and the distance from the BS
    of the farthest such drone, m (0: none). All four are NaN after a run's stop; the snapshots
    are NaN too in a run read from a range scan, which builds no graph of its own.
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
    depth: np.ndarray
    farthest: np.ndarray
    trajectory: Trajectory | None = None
    notify_times: np.ndarray | None = None
    """A range-free run's notification staircase (:mod:`sarlink.engine.critical_ranges`), when asked
    for: at any range ``r_c`` the BS is notified at ``notify_times[j]`` for the first ``j``
    with ``notify_rc2[j] <= r_c * r_c`` (never, if there is none); None otherwise."""
    notify_rc2: np.ndarray | None = None
    """The squared ranges of that staircase, m², strictly falling."""
    sorties: np.ndarray | None = None
    """A team on batteries (``mission.battery``): each drone's sorties; None without one."""
    ground_time: np.ndarray | None = None
    """Each drone's time on the ground for battery swaps, s; None without a battery."""
    energy: np.ndarray | None = None
    """Each drone's energy drawn, J (climbs and descents included); None without a battery."""
    targets: np.ndarray | None = None
    """Several targets (``target.count = K > 1``): every target's last-seen position,
    ``(K, 2)`` m, the first at :attr:`target`; None with one target. ``t_detect``,
    ``t_notify``, ``immediate`` and ``detector`` are then the mission's, by
    ``target.success``, and the reachability records follow the first target."""
    t_detect_each: np.ndarray | None = None
    """Several targets: each one's first detection, s (NaN: never); None with one."""
    t_notify_each: np.ndarray | None = None
    """Several targets: when the BS first knew where each one is, s (NaN: never)."""
    detector_each: np.ndarray | None = None
    """Several targets: each one's first detector (-1: none)."""

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

    def found(self, td: float | None = None) -> int:
        """How many targets were detected by ``t_d`` (one target: 0 or 1)."""
        if self.t_detect_each is None:
            return int(self.detected(td))
        return int((self.t_detect_each <= self._upto(td)).sum())

    def told(self, td: float | None = None) -> int:
        """How many targets the BS had been told of by ``t_d`` (one target: 0 or 1)."""
        if self.t_notify_each is None:
            return int(self.notified(td))
        return int((self.t_notify_each <= self._upto(td)).sum())

    def t_reachable(self, td: float | None = None) -> float:
        """Seconds of ``[0, t_d]`` during which the target had a route to the BS."""
        return float(np.interp(self._upto(td), self.checkpoints, self.reach_cum))

    def connected_fraction(self, td: float | None = None) -> float:
        """Mean fraction of drones with a route to the BS over ``[0, t_d]``."""
        td = self._upto(td)
        return float(np.interp(td, self.checkpoints, self.connected_cum)) / td

    def row(self) -> dict[str, Any]:
        """A flat record for tables (the row of :func:`result_columns`): missing event times
        are NaN; a staircase as two more columns."""
        return {name: _plain(column[0]) for name, column in result_columns([self]).items()}


def _plain(value: np.ndarray | np.generic) -> Any:
    """A cell as Python: a missing time as ``math.nan`` itself, so that equal rows compare
    equal (``==`` on dicts takes an object for equal to itself, never one NaN for another)."""
    cell = value.tolist()
    return math.nan if isinstance(cell, float) and math.isnan(cell) else cell


def result_columns(results: Sequence[RunResult]) -> dict[str, Any]:
    """The columns of a table of runs with the same checkpoints (one mission's), a row per
    run: arrays, and the per-checkpoint records as 2-D arrays (run × checkpoint); a staircase,
    if every run has one, as a list of arrays. Built whole, not row by row, because a
    sweep's tables are made of them."""
    def times(values: list[float | None]) -> np.ndarray:
        return np.array([math.nan if v is None else v for v in values], dtype=float)

    checkpoints = np.stack([r.checkpoints for r in results])
    reach = np.stack([r.reach_cum for r in results])
    connected = np.stack([r.connected_cum for r in results])
    depth = np.stack([r.depth for r in results])
    farthest = np.stack([r.farthest for r in results])
    columns: dict[str, Any] = {
        "seed": np.array([r.seed for r in results], dtype=np.int64),
        "run": np.array([r.run for r in results], dtype=np.int64),
        "target_x": np.array([r.target[0] for r in results], dtype=float),
        "target_y": np.array([r.target[1] for r in results], dtype=float),
        "t_detect": times([r.t_detect for r in results]),
        "t_notify": times([r.t_notify for r in results]),
        "immediate": np.array([r.immediate for r in results], dtype=bool),
        "detector": np.array([-1 if r.detector is None else r.detector for r in results],
                             dtype=np.int64),
        # RunResult.t_reachable() and .connected_fraction() at the horizon, the last
        # checkpoint, where the interpolation gives the last record exactly
        "t_reachable": reach[:, -1].copy(),
        "connected_fraction": connected[:, -1] / checkpoints[:, -1],
        "checkpoints": checkpoints,
        "reach_cum": reach,
        "connected_cum": connected,
        "depth": depth,
        "farthest": farthest,
    }
    if all(r.notify_times is not None and r.notify_rc2 is not None for r in results):
        columns["notify_times"] = [r.notify_times for r in results]
        columns["notify_rc2"] = [r.notify_rc2 for r in results]
    for name in ("sorties", "ground_time", "energy"):  # a team on batteries, per drone
        values = [getattr(r, name) for r in results]
        if all(v is not None for v in values):
            columns[name] = values
    if all(r.targets is not None for r in results):  # several targets, per target
        columns["target_x_each"] = [r.targets[:, 0] for r in results]  # type: ignore[index]
        columns["target_y_each"] = [r.targets[:, 1] for r in results]  # type: ignore[index]
        for name in ("t_detect_each", "t_notify_each", "detector_each"):
            columns[name] = [np.asarray(getattr(r, name), dtype=float) for r in results]
    return columns
