"""The radio models (sarlink.engine.radios) called directly: the disc's thresholds, and
log-normal shadowing against Eq. 13 evaluated on the same normal draws, its coherence time,
and the distribution of its fades (docs/model.md, Communication)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy import stats

from phase_inputs import padded
from phase_inputs import params as mission_params
from sarlink.engine.codes import Shadowing
from sarlink.engine.params import Params
from sarlink.engine.radios import DISC, SHADOWING, lognormal

EMPTY = np.zeros(0)  # the built-in models take no parameter array


def params(**changes: object) -> Params:
    """The scalars with fades redrawn every coherence time (``readings.shadowing =
    period``); the other forms are tested in test_readings.py."""
    return mission_params(**{"shadowing": int(Shadowing.PERIOD), **changes})


@given(m=st.integers(2, 80), rc=st.floats(1.0, 5000.0), k=st.integers(0, 100))
def test_the_disc_is_rc_squared_between_nodes_and_nothing_to_the_padding(
        m: int, rc: float, k: int) -> None:
    p = params(rc=rc)
    thr2 = lognormal.init(p, EMPTY, m, padded(m))
    assert thr2.shape == (m, padded(m))
    assert (thr2[:, :m] == rc * rc).all() and (thr2[:, m:] == 0.0).all()
    rng, twin = np.random.default_rng(k), np.random.default_rng(k)
    before = thr2.copy()
    lognormal.update(thr2, p, EMPTY, k, rng)
    np.testing.assert_array_equal(thr2, before)
    assert rng.bit_generator.state == twin.bit_generator.state  # it draws nothing
    assert lognormal.nominal(p, EMPTY) == rc
    assert lognormal.static(p, EMPTY)  # sigma = 0: the links never change
    assert not lognormal.static(p._replace(sigma=3.0), EMPTY)
    assert DISC.hooks() == SHADOWING.hooks()  # one model, one kernel


def _fades(m: int, seed: int, p: object) -> np.ndarray:
    """Shadowing's thresholds after the draw of step 0."""
    thr2 = lognormal.init(p, EMPTY, m, padded(m))
    lognormal.update(thr2, p, EMPTY, 0, np.random.default_rng(seed))
    return thr2


@given(m=st.integers(2, 30), rc=st.floats(100.0, 3000.0), sigma=st.floats(0.5, 12.0),
       exponent=st.floats(1.0, 5.0), seed=st.integers(0, 2**32 - 1))
def test_shadowing_follows_eq_13_for_the_drawn_fades(m: int, rc: float, sigma: float,
                                                     exponent: float, seed: int) -> None:
    """With the fades ``S = sigma z`` of the standard normals the generator gives, pair by
    pair in row order, a link at distance d exists exactly when
    ``10 n log10(d / r_c) + S <= 0``; thresholds are symmetric, none to the padding."""
    p = params(rc=rc, sigma=sigma, pathloss_exponent=exponent)
    thr2 = _fades(m, seed, p)
    z = np.random.default_rng(seed).standard_normal(m * (m - 1) // 2)
    upper = np.triu_indices(m, 1)
    s = sigma * z
    np.testing.assert_allclose(thr2[upper], rc * rc * 10.0 ** (-s / (5.0 * exponent)),
                               rtol=1e-12)
    np.testing.assert_array_equal(thr2[:, :m], thr2[:, :m].T)
    assert (thr2[:, m:] == 0.0).all()
    assert lognormal.nominal(p, EMPTY) == rc  # planners cannot foresee the fades
    # Eq. 13 at distances around each link's edge
    d = rc * np.exp(np.random.default_rng(seed + 1).uniform(-1.0, 1.0, len(s)))
    budget = 10.0 * exponent * np.log10(d / rc) + s
    clear = np.abs(budget) > 1e-9  # not on the edge itself, where rounding decides
    np.testing.assert_array_equal((d * d <= thr2[upper])[clear], (budget <= 0.0)[clear])


def test_zero_sigma_is_the_disc_bit_for_bit() -> None:
    p = params(rc=1234.5, sigma=0.0, pathloss_exponent=3.0)
    np.testing.assert_array_equal(_fades(12, 3, p), lognormal.init(p, EMPTY, 12, padded(12)))


def test_fades_are_redrawn_only_every_coherence_time() -> None:
    """With a coherence of 3 steps the thresholds change at steps 0, 3, 6, 9 and the
    generator is drawn from only then (one normal per pair)."""
    m, pairs = 6, 15
    p = params(sigma=4.0, coherence_steps=3)
    thr2 = lognormal.init(p, EMPTY, m, padded(m))
    rng, twin = np.random.default_rng(8), np.random.default_rng(8)
    previous = thr2.copy()
    for k in range(10):
        lognormal.update(thr2, p, EMPTY, k, rng)
        redrawn = k % 3 == 0
        if redrawn:
            twin.standard_normal(pairs)
        assert rng.bit_generator.state == twin.bit_generator.state, k
        assert (thr2 != previous).any() == redrawn, k
        previous = thr2.copy()


@pytest.mark.parametrize(("sigma", "exponent"), [(3.0, 1.75), (8.0, 3.0)])
def test_the_fades_are_normal_with_the_mission_s_sigma(sigma: float, exponent: float) -> None:
    """The fade behind each threshold, ``S = -5 n log10(thr2 / r_c²)``, over 100 nodes and four
    coherence times (19 800 links), is N(0, sigma²) by a Kolmogorov-Smirnov test at 0.1 %
    (fixed seed); the same test tells a sigma 10 % off, so it is not blind."""
    m = 100
    p = params(rc=1000.0, sigma=sigma, pathloss_exponent=exponent, coherence_steps=1)
    thr2 = lognormal.init(p, EMPTY, m, padded(m))
    rng = np.random.default_rng(2024)
    upper = np.triu_indices(m, 1)
    fades = []
    for k in range(4):
        lognormal.update(thr2, p, EMPTY, k, rng)
        fades.append(-5.0 * exponent * np.log10(thr2[upper] / 1000.0**2))
    s = np.concatenate(fades)
    assert stats.kstest(s / sigma, "norm").pvalue > 1e-3
    assert stats.kstest(s / (1.1 * sigma), "norm").pvalue < 1e-3
    assert abs(math.fsum(s) / len(s)) < 4 * sigma / math.sqrt(len(s))
