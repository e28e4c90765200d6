"""Imperfect sensing and log-normal shadowing (Section 4.3, Eq. 13)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sarlink import Mission, simulate
from sarlink.engine.graph import linked, links
from sarlink.engine.radios.lognormal import draw_shadowing
from sarlink.simulation import prepare

PLANNERS = ["covb", "conb", "concov"]


def _rows(mission: Mission, runs: int = 12, seed: int = 9) -> list[dict]:
    prepared = prepare(mission)
    return [prepared.run(seed, k).row() for k in range(runs)]


@pytest.mark.parametrize("planner", PLANNERS)
def test_zero_sigma_is_the_disc_model_run_for_run(planner: str) -> None:
    disc = Mission.build(planner=planner, drones=8, rc=500.0, horizon=1500.0)
    faded = disc.replace(sigma=0.0, pathloss_exponent=3.0, coherence=10.0)
    assert _rows(faded) == _rows(disc)


@pytest.mark.parametrize("planner", PLANNERS)
def test_zero_miss_probability_is_ideal_sensing_run_for_run(planner: str) -> None:
    ideal = Mission.build(planner=planner, drones=8, rc=500.0, horizon=1500.0)
    for look in ("per-pass", "per-period"):
        assert _rows(ideal.replace(p_miss=0.0, look=look)) == _rows(ideal)


@pytest.mark.parametrize("look", ["per-pass", "per-period"])
def test_certain_misses_never_detect(look: str) -> None:
    mission = Mission.build(planner="covb", drones=10, horizon=2000.0, p_miss=1.0, look=look)
    assert all(math.isnan(row["t_detect"]) and math.isnan(row["t_notify"])
               for row in _rows(mission))


@given(low=st.floats(0, 1), high=st.floats(0, 1), planner=st.sampled_from(PLANNERS),
       look=st.sampled_from(["per-pass", "per-period"]), run=st.integers(0, 1000))
def test_detection_never_comes_earlier_with_a_higher_miss_probability(
    low: float, high: float, planner: str, look: str, run: int
) -> None:
    low, high = sorted((low, high))
    base = Mission.build(planner=planner, drones=6, horizon=1500.0, look=look)
    t_low = simulate(base.replace(p_miss=low), seed=4, run=run).t_detect
    t_high = simulate(base.replace(p_miss=high), seed=4, run=run).t_detect
    assert (math.inf if t_low is None else t_low) <= (math.inf if t_high is None else t_high)


def test_per_period_looks_detect_more_than_per_pass_looks() -> None:
    """A drone lingering in range gets one look per t_s instead of one per pass."""
    base = Mission.build(planner="conb", drones=10, rc=500.0, horizon=1000.0, p_miss=0.8)
    detected = {look: sum(not math.isnan(r["t_detect"])
                          for r in _rows(base.replace(look=look), runs=60))
                for look in ("per-pass", "per-period")}
    assert detected["per-period"] > detected["per-pass"]


def _phi(x: float) -> float:
    return 0.5 * (1 + math.erf(x / math.sqrt(2)))


@pytest.mark.parametrize(("sigma", "exponent"), [(3.0, 1.75), (8.0, 3.0)])
def test_fraction_of_links_up_at_distance_d_is_the_normal_cdf(sigma: float,
                                                              exponent: float) -> None:
    """P(10 n log10(d/r_c) + S <= 0) = Phi(-10 n log10(d/r_c) / sigma) for every kind of link."""
    rc, h = 1000.0, 100.0
    mission = Mission.build(drones=3, rc=rc, sigma=sigma, pathloss_exponent=exponent,
                            altitude=h)
    params = prepare(mission).params
    # drones 0-2, BS (3), target (4): distances from 0.5 r_c to 1.4 r_c
    px = np.array([0.0, 800.0, 0.0, 1300.0, 0.0])
    py = np.array([0.0, 0.0, 1150.0, 0.0, 500.0])
    pz = np.array([h, h, h, 0.0, 0.0])  # drones fly at h, the BS and target are on the ground
    n, m, draws = 3, 5, 4000
    thr2 = np.empty((m, m))
    adj = np.zeros((m, 1), dtype=np.uint64)
    up = np.zeros((m, m))
    rng = np.random.default_rng(17)
    for _ in range(draws):
        draw_shadowing(thr2, params, rng)
        links(px, py, pz, thr2, adj, 0.0, adj, False)
        up += [[linked(adj, a, b) for b in range(m)] for a in range(m)]
    for a in range(m):
        for b in range(a + 1, m):
            d = math.hypot(px[a] - px[b], py[a] - py[b])
            if (a < n) != (b < n):
                d = math.hypot(d, h)  # drone-ground links are slant
            expected = _phi(-10 * exponent * math.log10(d / rc) / sigma)
            tolerance = 4 * math.sqrt(expected * (1 - expected) / draws) + 1e-3
            assert abs(up[a, b] / draws - expected) <= tolerance, (a, b, d)
            assert up[a, b] == up[b, a]
