"""Sequential tests on success counts: when a candidate has had enough runs.

A candidate's runs are looked at on a fixed schedule of run counts (:class:`Schedule`: 50,
100, 200, ... up to a cap). At each look its success count gives exact Clopper–Pearson bounds
on ``P_s``; each look spends an equal share of the error (Bonferroni over the looks), so the
chance that a candidate is ever misjudged, however many looks it gets, stays within the error
asked for. Exact bounds rather than Wilson's: Wilson's coverage dips below nominal at some
``n``, which a guarantee cannot allow; at a stricter level they are also wider than the 95 %
Wilson interval, so a candidate judged to meet the requirement here also has its 95 % Wilson
lower bound at or above it.

Settings of one planner are compared run by run (common random numbers) with the exact
McNemar test and an exact bound on how much worse one can be than another.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

import numpy as np
from scipy.stats import beta, binomtest

from sarlink.metrics import wilson

__all__ = ["Decision", "Schedule", "decide", "lower_bound", "not_worse_by", "upper_bound",
           "worse"]


@dataclass(frozen=True)
class Schedule:
    """Run counts at which a candidate is looked at: ``first``, doubling, ending at ``cap``."""

    first: int
    cap: int

    def __post_init__(self) -> None:
        if not 1 <= self.first <= self.cap:
            raise ValueError(f"need 1 <= first <= cap, got first={self.first}, cap={self.cap}")

    @property
    def looks(self) -> tuple[int, ...]:
        counts = []
        n = self.first
        while n < self.cap:
            counts.append(n)
            n *= 2
        return (*counts, self.cap)

    def after(self, runs: int) -> int | None:
        """The look after ``runs`` runs, or None once the cap is reached."""
        return next((n for n in self.looks if n > runs), None)


class Decision(enum.StrEnum):
    """What the sequential test decides from the runs so far about ``P_s`` against the
    requirement (the ``verdict`` of an estimate and of a team size in the answer)."""

    MEETS = "meets"
    FAILS = "fails"
    OPEN = "open"
    """Not decided yet: more runs may decide."""
    BORDERLINE = "borderline"
    """Not decided at the cap: ``P_s`` is too close to the requirement to tell."""
    OUTRANKED = "outranked"
    """Not decided, and set aside: at the smallest team that meets, its upper bound on
    ``P_s`` is below the estimate of the best candidate that meets there, so it cannot be
    the recommendation (the recommendation alone)."""


def lower_bound(successes: int, runs: int, error: float) -> float:
    """Exact (Clopper–Pearson) lower bound on a proportion: wrong with probability <= error."""
    if successes == 0:
        return 0.0
    return float(beta.ppf(error, successes, runs - successes + 1))


def upper_bound(successes: int, runs: int, error: float) -> float:
    """Exact (Clopper–Pearson) upper bound on a proportion: wrong with probability <= error."""
    if successes == runs:
        return 1.0
    return float(beta.ppf(1 - error, successes + 1, runs - successes))


def decide(successes: int, runs: int, required: float, *, meets_error: float,
           fails_error: float, final: bool) -> Decision:
    """Judge ``P_s >= required`` from ``successes`` of ``runs``.

    "Meets" also needs the 95 % Wilson lower bound, which the answer reports, at or above
    ``required`` (the exact bound is nearly always the stricter; not at ``successes = runs``).
    ``meets_error`` bounds the chance of "meets" when ``P_s < required``, ``fails_error`` that
    of "fails" when ``P_s >= required`` (per look: the caller divides by the looks). ``final``:
    this is the last look, so an undecided candidate is borderline rather than open.
    """
    if lower_bound(successes, runs, meets_error) >= required and float(
            wilson(successes, runs)[0]) >= required:  # the interval reported agrees
        return Decision.MEETS
    if upper_bound(successes, runs, fails_error) < required:
        return Decision.FAILS
    return Decision.BORDERLINE if final else Decision.OPEN


def worse(a: np.ndarray, b: np.ndarray, error: float) -> bool:
    """Whether the runs show setting ``a`` less successful than ``b`` (paired, same runs).

    The exact McNemar test: only the runs where one succeeded and the other failed tell them
    apart, and under equal ``P_s`` each such run goes either way with probability 1/2.
    """
    b_only = int(np.count_nonzero(b & ~a))
    a_only = int(np.count_nonzero(a & ~b))
    if b_only == 0:
        return False
    return bool(binomtest(b_only, b_only + a_only, 0.5, alternative="greater").pvalue < error)


def not_worse_by(a: np.ndarray, b: np.ndarray, margin: float, error: float) -> bool:
    """Whether the runs show ``P_s(b) - P_s(a) < margin`` (paired, same runs).

    The difference is ``d · (2q - 1)``, with ``d`` the probability that exactly one of the two
    succeeds and ``q`` the chance that it is ``b`` when one does. Exact upper bounds on ``d``
    (from the discordant runs among all) and on ``q`` (from ``b``'s share of the discordant
    runs, conditionally exact), each wrong with probability at most ``error / 2``, bound it.
    """
    b_only = int(np.count_nonzero(b & ~a))
    discordant = b_only + int(np.count_nonzero(a & ~b))
    if discordant == 0:
        return upper_bound(0, len(a), error / 2) < margin
    edge = 2 * upper_bound(b_only, discordant, error / 2) - 1
    return edge <= 0 or upper_bound(discordant, len(a), error / 2) * edge < margin
