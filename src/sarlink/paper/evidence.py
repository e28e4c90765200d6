"""The evidence a claim is decided on: estimates with 95% intervals and four outcomes.

A part of a claim *holds* only where its interval supports it and is *contradicted* only where
the interval excludes it; in between it is *undecided at this sample size*, which more runs
per point can settle; and it is *not testable at this setting* where what it compares is equal
in every run (:attr:`Estimate.tied`), which no number of runs can settle.

- An *estimate* is a value with a 95% interval: the Wilson interval of a probability, or
  mean ± 1.96 standard errors of a mean (:meth:`sarlink.metrics.Measure.interval`). The
  claims' comparisons are paired (:mod:`sarlink.paper.paired`); the unpaired tools here serve
  summary tables alone (beyond the paper, :mod:`sarlink.paper.beyond`) and Fig. 1's timings.
- A *difference* of two independent estimates has Newcombe's hybrid score interval
  ``d − √((a − a_lo)² + (b_hi − b)²) .. d + √((a_hi − a)² + (b − b_lo)²)`` (for means it is
  ``d ± 1.96 √(se_a² + se_b²)``).
- An *average* of estimates averages their bounds too. The half-width of a sum is at most the
  sum of half-widths whatever the correlations (Minkowski), so this interval is conservative;
  a *peak* takes the largest of each bound, the interval of the largest true value when every
  interval covers its own.
- A claim of several parts is contradicted if any part is, undecided if any part is, and
  holds if a part holds; parts not testable decide nothing unless every part is.
- An *existence* claim ("at some team size ...") holds where a candidate holds; candidates
  not testable (equal in every run) are no candidates, and it is contradicted only where every
  testable candidate is (:func:`exists`).
- A threshold the paper does not state ("highly likely", "about x", "small") is a
  :class:`Level`: sarlink's value decides the part, and the part also records how it comes
  out at the most lenient value a reader could defend, so that a contradiction the threshold
  alone decides is told apart from one that no defensible threshold removes.
"""

from __future__ import annotations

import enum
import functools
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from scipy import stats

from sarlink.metrics import MEASURES, format_interval
from sarlink.paper.experiments import DRONES

__all__ = ["Estimate", "Grid", "Level", "Outcome", "Part", "PlanTimes", "SummaryTables",
           "Verdict", "average", "exists", "peak", "worst"]


class Outcome(enum.Enum):
    """How a claim, or one part of it, came out."""

    HOLDS = "holds"
    CONTRADICTED = "contradicted"
    UNDECIDED = "undecided at this sample size"
    NOT_TESTABLE = "not testable at this setting"
    """Nothing at this setting can separate what is compared: two planners that fly alike on
    every run (both notify in every run, say). More runs cannot settle it; another setting
    can."""


def worst(outcomes: Iterable[Outcome]) -> Outcome:
    """The outcome of parts together: contradicted if any is, otherwise undecided if any is,
    otherwise holds if any does; parts not testable at their setting decide nothing, and a
    claim none of whose parts can be tested is not testable."""
    found = set(outcomes)
    if not found:
        raise ValueError("a claim needs at least one tested part")
    for outcome in (Outcome.CONTRADICTED, Outcome.UNDECIDED, Outcome.HOLDS):
        if outcome in found:
            return outcome
    return Outcome.NOT_TESTABLE


def exists(candidates: Iterable[Outcome]) -> Outcome:
    """The outcome of "at some candidate": holds if a candidate holds; candidates not testable
    at their setting (what they compare is equal in every run) can show nothing either way and
    are dropped; contradicted if every remaining candidate is; not testable if none remains;
    undecided otherwise."""
    testable = [o for o in candidates if o is not Outcome.NOT_TESTABLE]
    if Outcome.HOLDS in testable:
        return Outcome.HOLDS
    if not testable:
        return Outcome.NOT_TESTABLE
    return (Outcome.CONTRADICTED if all(o is Outcome.CONTRADICTED for o in testable)
            else Outcome.UNDECIDED)


@dataclass(frozen=True)
class Level:
    """A threshold the paper does not state, which a criterion had to choose to give its
    words a meaning."""

    word: str
    """The paper's words it gives a meaning to (``'"highly likely"'``)."""
    value: float
    """sarlink's choice, which decides the part."""
    lenient: float
    """The most lenient value a reader could defend from the words alone (the side that
    contradicts less): the part is decided again there."""
    meaning: str
    """What the level bounds, with ``{}`` for the number (``"a probability above {}"``)."""

    def __str__(self) -> str:
        return (f"{self.word} taken as {self.meaning.format(f'{self.value:g}')} "
                f"(a reader could defend {self.lenient:g})")


@dataclass(frozen=True)
class Estimate:
    """A value with its 95% interval."""

    value: float
    lo: float
    hi: float
    digits: int = 3
    """Decimals when printed."""
    tied: bool = False
    """A paired difference that is zero in every run: nothing here can separate the two, so
    every comparison with it is not testable at this setting."""

    def __str__(self) -> str:
        text = format_interval(self.value, self.lo, self.hi, self.digits)
        return text + " (equal in every run)" if self.tied else text

    def scaled(self, k: float) -> Estimate:
        """``k`` times the estimate, ``k`` ≥ 0."""
        return Estimate(k * self.value, k * self.lo, k * self.hi, self.digits)

    def mapped(self, f: Callable[[float], float], digits: int) -> Estimate:
        """The estimate through an increasing function (a log ratio to a ratio, say)."""
        return Estimate(f(self.value), f(self.lo), f(self.hi), digits)

    def absolute(self) -> Estimate:
        """The estimate of ``|value|``: its interval mirrored where it lies below 0, from 0
        where it straddles 0."""
        if self.lo >= 0:
            return self
        if self.hi <= 0:
            return Estimate(-self.value, -self.hi, -self.lo, self.digits, self.tied)
        return Estimate(abs(self.value), 0.0, max(-self.lo, self.hi), self.digits, self.tied)

    def minus(self, other: Estimate) -> Estimate:
        """Newcombe's interval of the difference (see the module docstring)."""
        d = self.value - other.value
        return Estimate(d, d - math.hypot(self.value - self.lo, other.hi - other.value),
                        d + math.hypot(self.hi - self.value, other.value - other.lo),
                        self.digits)

    def above(self, x: float = 0.0) -> Outcome:
        """Is the value above ``x``: holds if the interval is, contradicted if it lies below."""
        if self.tied:
            return Outcome.NOT_TESTABLE
        return (Outcome.HOLDS if self.lo > x else Outcome.CONTRADICTED if self.hi < x
                else Outcome.UNDECIDED)

    def below(self, x: float = 0.0) -> Outcome:
        """Is the value below ``x``: holds if the interval is, contradicted if it lies above."""
        if self.tied:
            return Outcome.NOT_TESTABLE
        return (Outcome.HOLDS if self.hi < x else Outcome.CONTRADICTED if self.lo > x
                else Outcome.UNDECIDED)

    def within(self, lo: float, hi: float) -> Outcome:
        """Is the value within ``[lo, hi]``: holds if the whole interval is, contradicted if
        the interval misses it."""
        if self.tied:
            return Outcome.NOT_TESTABLE
        if lo <= self.lo and self.hi <= hi:
            return Outcome.HOLDS
        return Outcome.CONTRADICTED if self.hi < lo or self.lo > hi else Outcome.UNDECIDED


def _combined(items: Sequence[Estimate], combine: Callable[[list[float]], float]) -> Estimate:
    """Value, lower and upper bound each combined across ``items`` by ``combine``."""
    value, lo, hi = (combine([getattr(e, f) for e in items]) for f in ("value", "lo", "hi"))
    return Estimate(value, lo, hi, items[0].digits)


def _unknown(items: Sequence[Estimate]) -> bool:
    """Whether an estimate is NaN (a point with no notified run, say): what it enters into is
    NaN too, and decides nothing."""
    return any(math.isnan(e.value) for e in items)


_NOTHING = Estimate(math.nan, math.nan, math.nan)


def average(estimates: Iterable[Estimate]) -> Estimate:
    """The mean of estimates with the mean of their bounds: conservative under any correlation."""
    return _combined(list(estimates), lambda xs: float(np.mean(xs)))


def peak(estimates: Iterable[Estimate]) -> Estimate:
    """The largest value, with the interval of the largest true value when every interval
    covers its own."""
    items = list(estimates)
    return _NOTHING if _unknown(items) else _combined(items, max)


class Grid:
    """A summary table looked up by its grid columns, as estimates.

    ``keys`` name the columns of a grid point; :meth:`gap` needs the keys ``planner``,
    ``drones``, ``rc``, ``td`` (the tables of Figs. 3–6 and 7b).
    """

    def __init__(self, name: str, frame: pd.DataFrame, keys: Sequence[str]) -> None:
        self.name = name
        self.keys = list(keys)
        self.rows = frame.set_index(self.keys).sort_index()

    def row(self, *key: object) -> pd.Series:
        try:
            return self.rows.loc[key]
        except KeyError:
            point = ", ".join(f"{k} = {v}" for k, v in zip(self.keys, key, strict=True))
            raise KeyError(f"the {self.name} table has no row for {point}") from None

    def at(self, column: str, *key: object) -> Estimate:
        """The measure ``column`` at a grid point, with its 95% interval."""
        measure = MEASURES[column]
        return Estimate(*measure.interval(self.row(*key)), measure.digits)

    def gap(self, a: str, b: str, rc: float, td: float, column: str,
            same_up_to: int = 0) -> Estimate:
        """The average over team sizes of ``a − b``, leaving out the sizes up to
        ``same_up_to`` (where mTSP-ConB flies mTSP's mission)."""
        return average(self.at(column, a, n, rc, td).minus(self.at(column, b, n, rc, td))
                       for n in DRONES if n > same_up_to)


class PlanTimes:
    """Fig. 1's measured plan times: seconds per planner, team size and repeat.

    Times are compared on a log scale (a ratio of times is what Fig. 1's log axis shows), with
    Student t intervals, since a few repeats per point are all there is.
    """

    def __init__(self, frame: pd.DataFrame) -> None:
        self.frame = frame

    def _logs(self, planner: str, drones: int | None = None) -> pd.DataFrame:
        rows = self.frame[self.frame["planner"] == planner]
        if drones is not None:
            rows = rows[rows["drones"] == drones]
        if rows.empty:
            raise KeyError(f"the plan_times table has no timing of {planner}"
                           + ("" if drones is None else f" with N_m = {drones}"))
        return pd.DataFrame({"drones": rows["drones"], "log": np.log(rows["seconds"])})

    def team_sizes(self) -> list[int]:
        return sorted(int(n) for n in self.frame["drones"].unique())

    def log_ratio(self, a: str, b: str, drones: int) -> Estimate:
        """``log(time_a / time_b)`` at one team size: the difference of mean log times with
        Welch's 95% interval (NaN with fewer than two repeats each)."""
        x, y = self._logs(a, drones)["log"], self._logs(b, drones)["log"]
        ci = stats.ttest_ind(x, y, equal_var=False).confidence_interval(0.95)
        return Estimate(float(x.mean() - y.mean()), float(ci.low), float(ci.high))

    def trend(self, planner: str) -> Estimate:
        """The factor by which ``planner``'s time changes from the smallest team to the
        largest: ``exp(slope · (N_max − N_min))`` of a least-squares line through the log times
        of every repeat against N_m, with the 95% t interval of the slope."""
        logs = self._logs(planner)
        fit = stats.linregress(logs["drones"], logs["log"])
        span = float(logs["drones"].max() - logs["drones"].min())
        half = float(stats.t.ppf(0.975, len(logs) - 2)) * fit.stderr
        return Estimate(fit.slope * span, (fit.slope - half) * span,
                        (fit.slope + half) * span).mapped(math.exp, 2)


@dataclass(frozen=True)
class Part:
    """One tested part of a claim: what was compared, with its numbers, and how it came out."""

    outcome: Outcome
    text: str
    levels: tuple[Level, ...] = ()
    """The thresholds the paper does not state that decide this part."""
    lenient: Outcome | None = None
    """The outcome with every one of ``levels`` at its lenient value (None without levels)."""


@dataclass
class Verdict:
    """What a check found: its tested parts, and numbers shown for context only."""

    parts: list[Part] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def test(self, outcome: Outcome, text: str, levels: Sequence[Level] = (),
             lenient: Outcome | None = None) -> None:
        """Record a part; one decided by ``levels`` also gives its ``lenient`` outcome."""
        if bool(levels) != (lenient is not None):
            raise ValueError("a part decided by a level gives its outcome at the lenient value")
        self.parts.append(Part(outcome, text, tuple(levels), lenient))

    def note(self, text: str) -> None:
        self.notes.append(text)


class SummaryTables:
    """The reproduction's summary tables (by name, as :mod:`sarlink.paper.experiments` makes
    them), wrapped for lookup when a claim first reads them."""

    def __init__(self, tables: Mapping[str, pd.DataFrame]) -> None:
        self.tables = tables

    @functools.cached_property
    def main(self) -> Grid:
        """Figs. 3–6: planner × N_m × r_c at every t_d of the checks."""
        return Grid("main", self.tables["main"], ["planner", "drones", "rc", "td"])

    @functools.cached_property
    def shadowing(self) -> Grid:
        """Fig. 7b: planner × N_m at one r_c, with shadowing."""
        return Grid("shadowing", self.tables["shadowing"], ["planner", "drones", "rc", "td"])

    @functools.cached_property
    def miss(self) -> Grid:
        """Fig. 7a: planner × miss probability at one N_m, r_c and t_d."""
        return Grid("miss", self.tables["miss"], ["planner", "p_miss"])

    @functools.cached_property
    def plan_times(self) -> PlanTimes:
        """Fig. 1: every timed plan."""
        return PlanTimes(self.tables["plan_times"])
