"""Paired statistics: comparisons made run by run, on common random numbers.

Every grid point of an experiment flies runs ``0 .. n−1`` of one seed, and run ``k`` searches
for the same target at every point (another planner, team size, range, miss probability, or
shadowing). So a difference between two points is best judged run by run: the run, not the
point, is the independent unit. Each measure of a point is a smooth function of per-run
means; its *influence* on run ``k`` (the first-order term of the delta method) makes any
linear combination of measures (a difference, an average over team sizes, a change from one
team size to another) a mean over runs of per-run *pseudo-values*, whose 95% interval is
Student's t (:func:`t_interval`: :func:`scipy.stats.ttest_1samp`'s, bit for bit). A
difference of two success indicators at one pair of points, ``d = (m/n)(2π − 1)``, is judged
on its discordant runs (``m`` of ``n``: one succeeds, the other not), of which the first wins
a share ``π``: π has the Clopper–Pearson interval (:func:`scipy.stats.binomtest`) and ``m/n``
the Wilson interval, each at 97.5% so that the interval of ``d`` from their extreme
combinations holds at 95% (Bonferroni). Its sign is McNemar's exact conditional test at
97.5%; its ends hold also where ``m`` is small. A difference that is zero in every run is
*tied*: nothing at this setting can separate the two (``Outcome.NOT_TESTABLE``).
A level (one point's measure alone) keeps its Wilson interval, or t for a mean.

A measure over the runs notified (mission time, its phases, the delay, the search share) is
compared between two points over the runs notified at *both*: each point's notified runs are
other targets (a planner that notifies only the targets near the BS has short mission times
for that reason alone), so the difference is that of the same targets, paired run by run.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import pandas as pd
from scipy import special, stats

from sarlink.metrics import wilson
from sarlink.paper.evidence import Estimate, SummaryTables

__all__ = ["MEASURE_DIGITS", "PairedTables", "RunGrid", "Stat", "mean_of", "on_common",
           "t_interval"]

MEASURE_DIGITS = {"P_s": 3, "P_d": 3, "immediate": 3, "mission_time": 0, "detection_time": 0,
                  "delay": 0, "search_share": 3, "reachability": 3, "connected": 3}
"""The measures a :class:`RunGrid` computes, with their decimals when printed."""


class Over(NamedTuple):
    """The runs a measure is over (a mask) and the measure over a subset of them."""

    runs: np.ndarray
    restrict: Callable[[np.ndarray], Stat]


@dataclass(frozen=True, eq=False)
class Stat:
    """A measure (or a combination of measures) of the runs: its value and its influence."""

    value: float
    influence: np.ndarray
    """Per run, mean 0: the estimate's error is, to first order, the mean of these."""
    digits: int = 3
    counts: tuple[int, int] | None = None
    """Successes and trials, for a proportion of one point alone (a Wilson interval)."""
    indicator: np.ndarray | None = None
    """The per-run 0/1 outcome of a plain proportion (P_s, P_d) of one point."""
    discordant: tuple[int, int] | None = None
    """A difference of two plain proportions: the runs only the first succeeds in, and only
    the second (McNemar)."""
    contrast: bool = False
    """A comparison (it came from a difference), which can be tied."""
    over: Over | None = None
    """For a measure over the runs notified: those runs, and the measure over fewer of them
    (a difference with another such measure is taken over the runs both are over)."""

    def __sub__(self, other: Stat) -> Stat:
        a, b = on_common([self, other])
        if a is not self or b is not other:
            return a - b
        discordant = None
        if self.indicator is not None and other.indicator is not None:
            discordant = (int(np.sum(self.indicator & ~other.indicator)),
                          int(np.sum(~self.indicator & other.indicator)))
        return Stat(self.value - other.value, self.influence - other.influence, self.digits,
                    discordant=discordant, contrast=True)

    def __add__(self, other: Stat) -> Stat:
        return Stat(self.value + other.value, self.influence + other.influence, self.digits,
                    contrast=self.contrast or other.contrast)

    def scaled(self, k: float) -> Stat:
        over = self.over
        return Stat(k * self.value, k * self.influence, self.digits, contrast=self.contrast,
                    over=None if over is None else Over(
                        over.runs, lambda subset: over.restrict(subset).scaled(k)))

    def estimate(self, level: float = 0.95) -> Estimate:
        """The value with its interval at ``level`` (see the module docstring)."""
        if math.isnan(self.value):
            return Estimate(math.nan, math.nan, math.nan, self.digits)
        runs = len(self.influence)
        if self.discordant is not None:
            first, second = self.discordant
            m = first + second
            if m == 0:
                return Estimate(0.0, 0.0, 0.0, self.digits, tied=True)
            # the difference is (m/n)(2π − 1): π, the share of discordant runs the first wins,
            # has its exact interval, m/n its Wilson interval, each at half the error rate
            inner = 1 - (1 - level) / 2
            low, high = _clopper_pearson(first, m, inner)
            few, many = (float(b) for b in wilson(m, runs, z=float(special.ndtri(
                0.5 + inner / 2))))
            lo, hi = 2 * low - 1, 2 * high - 1
            return Estimate(self.value, (many if lo < 0 else few) * lo,
                            (many if hi >= 0 else few) * hi, self.digits)
        if self.counts is not None:
            z = float(special.ndtri(0.5 + level / 2))
            bounds = wilson(*self.counts, z=z)
            return Estimate(self.value, float(bounds[0]), float(bounds[1]), self.digits)
        if np.allclose(self.influence, 0.0, rtol=0.0, atol=1e-12 * max(1.0, abs(self.value))):
            tied = self.contrast and abs(self.value) <= 1e-12
            return Estimate(self.value, self.value, self.value, self.digits, tied=tied)
        low, high = t_interval(self.value + self.influence, level)
        return Estimate(self.value, low, high, self.digits)


@functools.cache
def _clopper_pearson(k: int, n: int, level: float) -> tuple[float, float]:
    """SciPy's exact interval of a binomial proportion ``k/n`` at ``level``, kept: the same
    discordant counts recur over the claims and readings of a report."""
    ci = stats.binomtest(k, n).proportion_ci(level, method="exact")
    return float(ci.low), float(ci.high)


def t_interval(x: np.ndarray, level: float) -> tuple[float, float]:
    """Student's t interval of the mean of ``x`` at ``level``: the bits of
    ``scipy.stats.ttest_1samp(x, 0).confidence_interval(level)``, computed as SciPy does,
    without its per-call checks and result objects (most of the time of the tens of thousands
    of intervals a report's claims ask for)."""
    n = len(x)
    mean = np.mean(x)
    se = np.sqrt(np.mean((x - mean) ** 2) * (n / (n - 1)) / n)
    tail = (1 - level) / 2
    low, high = special.stdtrit(n - 1, np.array([tail, 1 - tail]))
    return float(low * se + mean), float(high * se + mean)


def on_common(stats: Sequence[Stat]) -> list[Stat]:
    """Measures over the runs notified (:attr:`Stat.over`), each over the runs all of them
    are over: the same targets, for a comparison; other statistics as they are."""
    overs = [s.over for s in stats if s.over is not None]
    if not overs or len(overs) < len(stats):
        return list(stats)
    common = np.logical_and.reduce([o.runs for o in overs])
    return [s if np.array_equal(o.runs, common) else o.restrict(common)
            for s, o in zip(stats, overs, strict=True)]


def mean_of(items: Iterable[Stat]) -> Stat:
    """The mean of statistics of the same runs (an average over team sizes, say)."""
    items = list(items)
    total = functools.reduce(lambda a, b: a + b, items)
    return total.scaled(1 / len(items))


class RunGrid:
    """The runs of an experiment by grid point, every point with the same runs in order."""

    def __init__(self, name: str, frame: pd.DataFrame, keys: Sequence[str]) -> None:
        self.name = name
        self.keys = list(keys)
        frame = frame.sort_values([*self.keys, "run"], kind="stable")
        columns = [c for c in frame.columns if c not in (*self.keys, "run")]
        self.points: dict[tuple[object, ...], dict[str, np.ndarray]] = {}
        runs = set()
        for key, group in frame.groupby(self.keys, sort=False):
            self.points[key if isinstance(key, tuple) else (key,)] = {
                c: group[c].to_numpy() for c in columns}
            runs.add(tuple(group["run"]))
        if len(runs) > 1:
            raise ValueError(f"the {name} runs differ between grid points: paired statistics "
                             "need the same runs at every point")

    def _point(self, key: tuple[object, ...]) -> dict[str, np.ndarray]:
        try:
            return self.points[key]
        except KeyError:
            point = ", ".join(f"{k} = {v}" for k, v in zip(self.keys, key, strict=True))
            raise KeyError(f"the {self.name} runs have no grid point {point}") from None

    def stat(self, measure: str, *key: object, td: float) -> Stat:
        """``measure`` (one of :data:`MEASURE_DIGITS`) at a grid point and target duration."""
        rows = self._point(tuple(key))
        digits = MEASURE_DIGITS[measure]
        t_det = rows["t_detect"].astype(float)
        t_not = rows["t_notify"].astype(float)
        detected, notified = t_det <= td, t_not <= td
        match measure:
            case "P_s" | "P_d":
                x = notified if measure == "P_s" else detected
                return _proportion(x, digits)
            case "immediate":
                return _conditional(rows["immediate"].astype(bool) & detected, detected, digits)
            case "mission_time":
                return _mean_where(t_not, notified, digits)
            case "detection_time":
                return _mean_where(t_det, notified, digits)
            case "delay":
                return _mean_where(t_not - t_det, notified, digits)
            case "search_share":
                return _ratio_where(t_det, t_not, notified, digits)
            case "reachability" | "connected":
                column = f"{'reach' if measure == 'reachability' else 'connected'}@{td:g}"
                x = rows[column].astype(float)
                return Stat(float(x.mean()), x - x.mean(), digits)
        raise KeyError(f"unknown measure {measure!r}")


def _proportion(x: np.ndarray, digits: int) -> Stat:
    p = float(x.mean())
    return Stat(p, x - p, digits, counts=(int(x.sum()), len(x)), indicator=x)


def _nothing(runs: int, digits: int) -> Stat:
    """The measure of a point where it is undefined (no run notified): NaN."""
    return Stat(math.nan, np.zeros(runs), digits)


def _conditional(event: np.ndarray, given: np.ndarray, digits: int) -> Stat:
    """``Pr{event | given}``: influence ``given · (event − q) / Pr{given}``."""
    k, n = int(event.sum()), int(given.sum())
    if n == 0:
        return _nothing(len(event), digits)
    q = k / n
    return Stat(q, given * (event - q) / given.mean(), digits, counts=(k, n))


def _mean_where(x: np.ndarray, where: np.ndarray, digits: int) -> Stat:
    """The mean of ``x`` over the runs ``where``: influence ``where · (x − m) / Pr{where}``."""
    if not where.any():
        return _nothing(len(x), digits)
    m = float(x[where].mean())
    return Stat(m, np.where(where, x - m, 0.0) / where.mean(), digits,
                over=Over(where, lambda subset: _mean_where(x, subset, digits)))


def _ratio_where(x: np.ndarray, y: np.ndarray, where: np.ndarray, digits: int) -> Stat:
    """The mean of ``x`` over the mean of ``y``, both over the runs ``where``."""
    if not where.any():
        return _nothing(len(x), digits)
    mx, my = float(x[where].mean()), float(y[where].mean())
    r = mx / my
    return Stat(r, np.where(where, x - r * y, 0.0) / (where.mean() * my), digits,
                over=Over(where, lambda subset: _ratio_where(x, y, subset, digits)))


class PairedTables(SummaryTables):
    """The summary tables, and the runs of each experiment by grid point for paired
    statistics (tables ``main_runs``, ``miss_runs``, ``shadowing_runs``)."""

    @functools.cached_property
    def runs(self) -> RunGrid:
        """Figs. 2–6: the main sweep's runs by planner, N_m and r_c."""
        return RunGrid("main", self.tables["main_runs"], ["planner", "drones", "rc"])

    @functools.cached_property
    def shadowed_runs(self) -> RunGrid:
        """Fig. 7b: the shadowing sweep's runs by planner, N_m and r_c."""
        return RunGrid("shadowing", self.tables["shadowing_runs"], ["planner", "drones", "rc"])

    @functools.cached_property
    def miss_runs(self) -> RunGrid:
        """Fig. 7a: the miss sweep's runs by planner and miss probability."""
        return RunGrid("miss", self.tables["miss_runs"], ["planner", "p_miss"])

