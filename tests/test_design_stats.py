"""The sequential tests of ``sarlink design``: exact bounds, error rates, paired comparisons."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import example, given
from hypothesis import strategies as st
from scipy.stats import binom

from sarlink.design.sequential import (
    Decision,
    Schedule,
    decide,
    lower_bound,
    not_worse_by,
    upper_bound,
    worse,
)
from sarlink.metrics import wilson

counts = st.integers(1, 3000).flatmap(lambda n: st.tuples(st.integers(0, n), st.just(n)))
errors = st.sampled_from([0.025, 0.005, 1e-4])


def test_schedule_doubles_up_to_the_cap() -> None:
    assert Schedule(50, 6400).looks == (50, 100, 200, 400, 800, 1600, 3200, 6400)
    assert Schedule(50, 1000).looks == (50, 100, 200, 400, 800, 1000)
    assert Schedule(10, 10).looks == (10,)
    assert Schedule(50, 1000).after(0) == 50
    assert Schedule(50, 1000).after(800) == 1000
    assert Schedule(50, 1000).after(1000) is None


@given(counts, errors)
def test_exact_bounds_are_where_the_binomial_tail_equals_the_error(kn: tuple[int, int],
                                                                    error: float) -> None:
    """Clopper–Pearson from its definition with the binomial distribution, not the beta."""
    k, n = kn
    lo, hi = lower_bound(k, n, error), upper_bound(k, n, error)
    if k > 0:
        assert math.isclose(binom.sf(k - 1, n, lo), error, rel_tol=1e-6)
    else:
        assert lo == 0
    if k < n:
        assert math.isclose(binom.cdf(k, n, hi), error, rel_tol=1e-6)
    else:
        assert hi == 1


@given(counts, st.floats(0.05, 0.99))
@example((368, 368), 0.99)  # the exact bound 0.9900 clears it, the Wilson bound 0.9897 does not
def test_a_team_that_meets_has_its_95_wilson_lower_bound_at_the_requirement(
        kn: tuple[int, int], required: float) -> None:
    k, n = kn
    for looks in (1, 8):
        v = decide(k, n, required, meets_error=0.025 / looks, fails_error=0.025 / looks,
                    final=False)
        lo, hi = wilson(k, n)
        if v is Decision.MEETS:
            assert lo >= required
        if v is Decision.FAILS:
            assert hi < required


def _misjudged(p: float, required: float, schedule: Schedule, error: float,
               trials: int) -> float:
    """How often the sequential procedure calls ``p`` on the wrong side of ``required``."""
    rng = np.random.default_rng(7)
    looks = len(schedule.looks)
    outcomes = rng.random((trials, schedule.cap)) < p
    wrong = Decision.MEETS if p < required else Decision.FAILS
    count = 0
    for row in outcomes:
        cumulative = np.cumsum(row)
        for n in schedule.looks:
            v = decide(int(cumulative[n - 1]), n, required, meets_error=error / looks,
                        fails_error=error / looks, final=n == schedule.cap)
            if v is not Decision.OPEN:
                count += v is wrong
                break
    return count / trials


def test_the_error_rate_holds_however_many_looks() -> None:
    """Just below and just above the requirement, where optional stopping would hurt most,
    the procedure misjudges a candidate at most as often as asked (here 2.5 %)."""
    schedule = Schedule(50, 1600)
    for p in (0.88, 0.92):
        assert _misjudged(p, 0.9, schedule, 0.025, 4000) <= 0.025


def test_naive_repeated_95_intervals_would_not_hold_it() -> None:
    """The check above can fail: one look's error at every look is too optimistic."""
    schedule = Schedule(50, 1600)
    looks = len(schedule.looks)
    assert _misjudged(0.895, 0.9, schedule, 0.025 * looks, 4000) > 0.025


@given(st.integers(0, 60), st.integers(0, 60), st.integers(0, 40))
def test_mcnemar_matches_the_binomial_sum(a_only: int, b_only: int, both: int) -> None:
    a = np.array([True] * a_only + [False] * b_only + [True] * both, dtype=bool)
    b = np.array([False] * a_only + [True] * b_only + [True] * both, dtype=bool)
    d = a_only + b_only
    p = sum(math.comb(d, i) for i in range(b_only, d + 1)) / 2**d if d else 1.0
    for error in (0.05, 0.01):
        assert worse(a, b, error) == (b_only > 0 and p < error)


def test_equal_settings_are_shown_within_the_margin_and_distant_ones_are_not() -> None:
    same = np.ones(2000, dtype=bool)
    assert not_worse_by(same, same, 0.01, 0.001)
    assert not not_worse_by(same[:100], same[:100], 0.01, 0.001)  # too few runs to tell
    rng = np.random.default_rng(1)
    b = rng.random(4000) < 0.9
    a = b & (rng.random(4000) < 0.9)  # about 9 points worse
    assert not not_worse_by(a, b, 0.05, 0.001)
    assert not_worse_by(b, a, 0.01, 0.001)  # b is better: the difference is negative
