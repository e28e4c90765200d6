"""Hand-made runs for testing the claims' checks: every grid point of the paper's experiments,
each run's values made by rules from shared and independent random numbers.

Run ``k`` draws one uniform ``u[k]`` shared by every point (common random numbers: a planner
that succeeds where ``u`` is small succeeds in the same runs everywhere) and, per point, an
independent uniform ``w``. A *rule* turns them into a column's values at a point. The default
world is bland: every planner alike (so most comparisons are equal in every run); a test
overrides the columns it needs for the planners it needs.
"""

from __future__ import annotations

import itertools
import zlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from sarlink.paper.experiments import DRONES, P_MISS, RANGES, TD_FIG3, TD_LONG, TD_SHORT
from sarlink.planners import PAPER_PLANNERS

TDS = (TD_SHORT, TD_FIG3, TD_LONG)
COLUMNS = ("t_detect", "t_notify", "immediate", "reach", "connected")

Point = tuple[str, int, float]
"""(planner, N_m, r_c); Fig. 7a's points put p_miss in the place of N_m."""
Rule = Callable[[Point, np.ndarray, np.ndarray], np.ndarray]
"""Values of one column at a point from the shared ``u`` and the point's own ``w``."""


def times(p1: float, p2: float, p4: float, *, shared: bool = True) -> Rule:
    """Event times with ``Pr{t ≤ 1000 s} = p1``, ``≤ 2000 s: p2``, ``≤ 4000 s: p4`` (500,
    1500 or 3000 s, NaN beyond)."""
    def rule(point: Point, u: np.ndarray, w: np.ndarray) -> np.ndarray:
        x = u if shared else w
        return np.where(x < p1, 500.0, np.where(x < p2, 1500.0, np.where(x < p4, 3000.0,
                                                                         np.nan)))
    return rule


def flag(q: float, *, shared: bool = True) -> Rule:
    """A per-run flag, true with probability ``q``."""
    return lambda point, u, w: (u if shared else w) < q


def level(x: float, spread: float = 0.0) -> Rule:
    """A value ``x``, plus ``spread`` × an independent uniform in [−1, 1] (noise)."""
    return lambda point, u, w: x + spread * (2 * w - 1)


def by_planner(rules: Mapping[str, Rule], other: Rule) -> Rule:
    return lambda point, u, w: rules.get(point[0], other)(point, u, w)


DEFAULTS: dict[str, Rule] = {
    "t_detect": times(0.6, 0.8, 0.95),
    "t_notify": lambda point, u, w: times(0.6, 0.8, 0.95)(point, u, w) + 200.0,
    "immediate": flag(0.5),
    "reach": level(0.3),
    "connected": level(0.5),
}


@dataclass
class World:
    """Columns' rules (defaults :data:`DEFAULTS`), and how many runs each point has."""

    rules: dict[str, Rule] = field(default_factory=dict)
    runs: int = 1000
    shadowed: dict[str, Rule] = field(default_factory=dict)
    """Rules of the shadowing sweep (Fig. 7b) where they differ from the main sweep's."""

    def _frame(self, points: list[Point], keys: list[str], tds: tuple[float, ...]
               ) -> pd.DataFrame:
        rules = DEFAULTS | self.rules
        u = np.random.default_rng(1).random(self.runs)
        columns: dict[str, list[np.ndarray]] = {c: [] for c in (
            *keys, "run", "t_detect", "t_notify", "immediate",
            *(f"{name}@{td:g}" for td in tds for name in ("reach", "connected")))}
        for point in points:
            w = np.random.default_rng(zlib.crc32(repr(point).encode())).random(self.runs)
            for k, value in zip(keys, point, strict=True):
                columns[k].append(np.full(self.runs, value, dtype=object))
            columns["run"].append(np.arange(self.runs))
            for column in ("t_detect", "t_notify"):
                columns[column].append(rules[column](point, u, w).astype(float))
            columns["immediate"].append(rules["immediate"](point, u, w).astype(bool))
            reach, connected = rules["reach"](point, u, w), rules["connected"](point, u, w)
            for td in tds:
                columns[f"reach@{td:g}"].append(reach.astype(float))
                columns[f"connected@{td:g}"].append(connected.astype(float))
        frame = pd.DataFrame({c: np.concatenate(v) for c, v in columns.items()})
        return frame.astype({k: type(points[0][i]) for i, k in enumerate(keys)})

    def main(self) -> pd.DataFrame:
        points = list(itertools.product(PAPER_PLANNERS, DRONES, RANGES))
        return self._frame(points, ["planner", "drones", "rc"], TDS)

    def miss(self) -> pd.DataFrame:
        points = [(p, q, 500.0) for p, q in itertools.product(PAPER_PLANNERS, P_MISS)]
        frame = self._frame(points, ["planner", "p_miss", "rc"], (TD_SHORT,))
        return frame.drop(columns="rc")

    def shadowing(self, rc: float = 1000.0) -> pd.DataFrame:
        points = list(itertools.product(PAPER_PLANNERS, DRONES, [rc]))
        with_shadowing = World(self.rules | self.shadowed, self.runs)
        return with_shadowing._frame(points, ["planner", "drones", "rc"], (TD_LONG,))

    def tables(self) -> dict[str, pd.DataFrame]:
        return {"main_runs": self.main(), "miss_runs": self.miss(),
                "shadowing_runs": self.shadowing()}


def world(shadowed: Mapping[str, Rule] | None = None, **rules: Rule
          ) -> Callable[[], dict[str, pd.DataFrame]]:
    """The tables of a world with these columns' rules (and ``shadowed``'s in the shadowing
    sweep), made when called (so that a test module's cases cost nothing to collect)."""
    return lambda: World(dict(rules), shadowed=dict(shadowed or {})).tables()
