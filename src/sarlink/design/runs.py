"""A design's runs, kept by the sweep layer: one results folder per candidate.

Each candidate is a one-point experiment (its mission, the design's seed) swept into
``<out>/seed-<seed>/<mission hash>/``, the layout of :mod:`sarlink.storage`. Growing a
candidate from 100 to 400 runs adds runs 100..399 and keeps the first 100; a design started
again, or another design whose candidates include the same mission, reuses every stored run.
Each folder can be read with :func:`sarlink.load` and ``sarlink summarize``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from sarlink.config import Experiment, Mission, mission_hash
from sarlink.execution import Workers, sweep_all
from sarlink.metrics import wilson

__all__ = ["Runs", "Tally"]


@dataclass(frozen=True)
class Tally:
    """The outcomes of runs ``0 .. n-1`` of one candidate at the design's ``t_d``."""

    success: np.ndarray
    """Whether run ``k`` notified the BS within ``t_d`` (bool)."""
    t_notify: np.ndarray
    """When it did, s (NaN if not)."""

    @classmethod
    def empty(cls) -> Tally:
        """No runs yet."""
        return cls(np.zeros(0, dtype=bool), np.zeros(0))

    @property
    def runs(self) -> int:
        """Runs counted."""
        return len(self.success)

    @property
    def successes(self) -> int:
        """Runs whose BS was notified by ``t_d``."""
        return int(np.count_nonzero(self.success))

    @property
    def p(self) -> float:
        """The success rate, NaN with no runs."""
        return self.successes / self.runs if self.runs else float("nan")

    def interval(self) -> tuple[float, float]:
        """The 95 % Wilson interval of ``P_s``, as ``sarlink summarize`` reports it."""
        lo, hi = wilson(self.successes, self.runs)
        return float(lo), float(hi)

    @property
    def mission_time(self) -> float:
        """Mean notification time of the successful runs, s (NaN if none)."""
        return float(np.mean(self.t_notify[self.success])) if self.successes else float("nan")

    def first(self, n: int) -> Tally:
        """The tally of runs ``0 .. n-1``: for comparing candidates on the same runs."""
        return Tally(self.success[:n], self.t_notify[:n])


class Runs:
    """Runs of missions stored under ``root``; :meth:`grow` runs what is missing on ``pool``
    (kept for every round of a design), or on workers started for each call."""

    def __init__(self, root: str | Path, seed: int, td: float, *, pool: Workers | None = None,
                 on_runs: Callable[[int], None] | None = None) -> None:
        self.folder = Path(root) / f"seed-{seed}"
        self.seed = seed
        self.td = td
        self.pool = pool
        self._on_runs = on_runs
        self._tallies: dict[str, Tally] = {}
        self.simulated = 0
        """Runs simulated by this object (the rest of those it used were stored already)."""

    def tally(self, mission: Mission) -> Tally:
        """The runs of ``mission`` grown so far (none before its first :meth:`grow`)."""
        return self._tallies.get(mission_hash(mission), Tally.empty())

    def grow(self, wanted: Sequence[tuple[Mission, int]]) -> None:
        """Bring each mission to the given number of runs: stored ones are read, the rest run
        in one pool of workers, each finished chunk stored at once."""
        if not wanted:
            return
        jobs = [(Experiment(name=f"design candidate {mission_hash(m)}", seed=self.seed,
                            runs=n, mission=m), self.folder / mission_hash(m))
                for m, n in wanted]

        def count(runs: int) -> None:
            self.simulated += runs
            if self._on_runs is not None:
                self._on_runs(runs)

        frames = sweep_all(jobs, progress=False, on_runs=count, pool=self.pool)
        for (mission, _), frame in zip(wanted, frames, strict=True):
            t_notify = frame["t_notify"].to_numpy(dtype=float)
            self._tallies[mission_hash(mission)] = Tally(t_notify <= self.td, t_notify)
