"""The ``drift`` target motion against the Leeway model's own formulas (docs/model.md,
Target motion, ``drift``).

The expectations are computed here from the published coefficients (OBJECTPROP.DAT's rows,
typed in again) and the model's equations, not from the implementation: the mean and the
spread of many targets' displacements after a day under a constant wind and current, the
jibe rate, and the forcing tables' interpolation, with the hooks called directly. Then one
kernel (CovB with a drifting target) against the reference's drift (tests/naive.py), and
``sweep`` and ``design`` storing the drift settings.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from naive import simulate_naive
from sarlink import Mission, load, simulate
from sarlink.cli import app
from sarlink.config import ConfigError
from sarlink.config.leeway import LEEWAY_CLASSES, forcing_table, leeway_class
from sarlink.engine.target_motion.drift import (
    STATE,
    drift_params,
    drift_targets,
    forcing_at,
    start,
)
from sarlink.testing import check_target_motion

# OBJECTPROP.DAT rows: downwind, crosswind right, crosswind left (slope %, offset cm/s, std cm/s)
PUBLISHED = {
    "PIW-1": ((0.96, 0.00, 12.00), (0.54, 0.00, 9.40), (-0.54, 0.00, 9.40)),
    "PIW-4": ((1.71, 1.12, 3.93), (1.36, -3.30, 1.71), (-0.13, -2.65, 1.62)),
}
WIND = (6.0, 8.0)      # 10 m/s towards 37 degrees east of north
CURRENT = (0.10, -0.05)
DT, STEPS, TARGETS = 600.0, 144, 4000  # a day in ten-minute steps
JIBE = 0.04


def _phi(x: float) -> float:
    return math.exp(-0.5 * x * x) / math.sqrt(2 * math.pi)


def _cdf(x: float) -> float:
    return 0.5 * (1 + math.erf(x / math.sqrt(2)))


def expected(name: str, w: float, n: int, dt: float) -> dict[str, float]:
    """Mean and variance of the downwind and crosswind displacement (m) after ``n`` steps.

    Per step, downwind ``(a W + b + r sigma g) / 100`` m/s with ``g = W/20 + 1/2`` and ``r``
    standard normal cut below at ``-20 a / sigma``; crosswind ``A_s + r_c B_s`` on side ``s``,
    ``A_s = (a_s W + b_s) / 100``, ``B_s = sigma_s g / 100``. The side is a symmetric
    two-state chain that flips with probability ``q`` per step from a fair first side, so the
    number ``n_R`` of steps on the right has mean ``n / 2`` and variance
    ``sum_ij rho^|i-j| / 4``, ``rho = 1 - 2 q``.
    """
    (ad, bd, sd), (ar, br, sr), (al, bl, sl) = PUBLISHED[name]
    g = w / 20 + 0.5
    alpha = -20 * ad / sd
    lam = _phi(alpha) / (1 - _cdf(alpha))
    r_mean, r_var = lam, 1 + alpha * lam - lam * lam
    t = n * dt
    down_mean = t * (ad * w + bd + r_mean * sd * g) / 100
    down_var = (t * sd * g / 100) ** 2 * r_var
    q = 1 - (1 - JIBE) ** (dt / 3600)
    rho = 1 - 2 * q
    v = (n + 2 * sum((n - k) * rho**k for k in range(1, n))) / 4
    a_r, a_l = (ar * w + br) / 100, (al * w + bl) / 100
    b_r, b_l = sr * g / 100, sl * g / 100
    cross_mean = dt * n / 2 * (a_r + a_l)
    cross_var = dt**2 * ((a_r - a_l) ** 2 * v + (n / 2 * (b_r + b_l)) ** 2 + (b_r - b_l) ** 2 * v)
    return {"down_mean": down_mean, "down_var": down_var, "cross_mean": cross_mean,
            "cross_var": cross_var}


def drifted(name: str, wind: tuple[float, float], current: tuple[float, float], steps: int,
            dt: float, targets: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Positions and states of ``targets`` targets started at the origin after ``steps``."""
    tp = drift_params(name, wind, current)
    rng = np.random.default_rng(seed)
    xy, state = np.zeros((targets, 2)), np.zeros((targets, STATE))
    for i in range(targets):
        start(xy[i], state[i], tp, rng)
    drift_targets(xy, state, 0.0, dt, steps, tp, rng)
    return xy, state


def test_the_table_holds_the_published_rows() -> None:
    for name, (dw, cwr, cwl) in PUBLISHED.items():
        assert LEEWAY_CLASSES[name].coefficients == (*dw, *cwr, *cwl)
    assert len(LEEWAY_CLASSES) >= 15 and "PIW-1" in LEEWAY_CLASSES


@pytest.mark.parametrize("name", ["PIW-1", "PIW-4"])
def test_a_day_of_drift_agrees_with_the_leeway_formulas(name: str) -> None:
    xy, _ = drifted(name, WIND, CURRENT, STEPS, DT, TARGETS, seed=1)
    t = STEPS * DT
    d = xy - np.array(CURRENT) * t
    w = math.hypot(*WIND)
    ux, uy = WIND[0] / w, WIND[1] / w
    down, cross = d @ np.array([ux, uy]), d @ np.array([uy, -ux])  # cross: right of downwind
    exp = expected(name, w, STEPS, DT)
    for label, sample in (("down", down), ("cross", cross)):
        mean, var = float(sample.mean()), float(sample.var(ddof=1))
        m4 = float(((sample - mean) ** 4).mean())
        mean_se = math.sqrt(exp[f"{label}_var"] / TARGETS)
        var_se = math.sqrt((m4 - var * var) / TARGETS)
        assert abs(mean - exp[f"{label}_mean"]) < 4 * mean_se, (label, mean, exp)
        assert abs(var - exp[f"{label}_var"]) < 4 * var_se, (label, var, exp)
    assert abs(float(np.corrcoef(down, cross)[0, 1])) < 4 / math.sqrt(TARGETS)


@pytest.mark.parametrize("dt", [3600.0, 600.0])
def test_targets_jibe_at_the_published_rate_per_hour(dt: float) -> None:
    tp = drift_params("PIW-1", WIND, (0.0, 0.0))
    rng = np.random.default_rng(2)
    targets, steps = 2000, 60
    xy, state = np.zeros((targets, 2)), np.zeros((targets, STATE))
    for i in range(targets):
        start(xy[i], state[i], tp, rng)
    assert abs(float((state[:, 0] > 0).mean()) - 0.5) < 4 * 0.5 / math.sqrt(targets)
    jibes = 0
    for k in range(steps):
        before = state[:, 0].copy()
        drift_targets(xy, state, k * dt, dt, 1, tp, rng)
        jibes += int((state[:, 0] != before).sum())
    q = 1 - (1 - JIBE) ** (dt / 3600)
    n = targets * steps
    assert abs(jibes - n * q) < 4 * math.sqrt(n * q * (1 - q))


def test_an_object_without_windage_moves_with_the_current_and_calm_air_adds_nothing() -> None:
    xy, _ = drifted("SLDMB", WIND, CURRENT, 10, 60.0, 5, seed=3)
    np.testing.assert_allclose(xy, np.tile(np.array(CURRENT) * 600.0, (5, 1)), rtol=1e-12)
    xy, _ = drifted("PIW-1", (0.0, 0.0), CURRENT, 10, 60.0, 5, seed=3)
    np.testing.assert_allclose(xy, np.tile(np.array(CURRENT) * 600.0, (5, 1)), rtol=1e-12)


def test_forcing_tables_are_linear_between_rows_and_held_at_the_ends() -> None:
    wind = ((0.0, 2.0, -4.0), (3600.0, 6.0, 0.0), (7200.0, 6.0, 10.0))
    current = (0.3, 0.1)
    tp = drift_params("PIW-1", wind, current)
    rows = 3
    for t, want in ((-5.0, (2.0, -4.0)), (0.0, (2.0, -4.0)), (900.0, (3.0, -3.0)),
                    (3600.0, (6.0, 0.0)), (5400.0, (6.0, 5.0)), (9e9, (6.0, 10.0))):
        assert forcing_at(tp, 12, rows, t) == pytest.approx(want, abs=1e-12)
    assert forcing_at(tp, 12 + 3 * rows, 1, 1234.0) == pytest.approx(current)


@pytest.mark.parametrize(("value", "table"), [
    ((3, -1.5), ((0.0, 3.0, -1.5),)),
    ("3,-1.5", ((0.0, 3.0, -1.5),)),
    ([[0, 1, 2], [60, 3, 4]], ((0.0, 1.0, 2.0), (60.0, 3.0, 4.0))),
    ("0,1,2; 60,3,4", ((0.0, 1.0, 2.0), (60.0, 3.0, 4.0))),
    ([[0.0, 1.0, 2.0]], ((0.0, 1.0, 2.0),)),
])
def test_a_pair_is_a_one_row_table_and_text_reads_as_arrays(value: object, table: object) -> None:
    assert forcing_table(value) == table


@pytest.mark.parametrize(("value", "said"), [
    ([[0, 1, 2], [3600, 1, 2], [1800, 0, 0]], "times out of order (1800 s after 3600 s)"),
    ("0,1,2;0,3,4", "times out of order (0 s after 0 s)"),
    ([[0, 1], [60, 2]], "expected a pair east,north"),
    ("5;0", "expected a pair east,north"),
    ("east", "expected a pair east,north"),
    ("", "expected a pair east,north"),
    ([], "expected a pair east,north"),
    ([1, 2, 3, 4], "expected a pair east,north"),
    ([float("nan"), 1.0], "expected a pair east,north"),
    ("inf,1", "expected a pair east,north"),
    ([True, 1.0], "expected a pair east,north"),
    ([[0, 1, 2], "3,4"], "expected a pair east,north"),
])
def test_a_malformed_table_says_what_is_allowed(value: object, said: str) -> None:
    with pytest.raises(ConfigError) as caught:
        forcing_table(value)
    assert said in str(caught.value) and "\n" not in str(caught.value)


def test_an_unknown_object_class_names_the_known_ones() -> None:
    with pytest.raises(ConfigError, match=r"unknown Leeway object class 'PIW-9'; "
                                          r"known: PIW-1, PIW-2"):
        leeway_class("PIW-9")


# -- in the kernel, in storage, on the command line (one kernel: covb with a drifting target) --

DRIFTING = {"planner": "covb", "drones": 3, "horizon": 300.0, "motion": "drift",
            "drift_object": "PIW-2", "drift_wind": (8.0, 6.0),
            "drift_current": "0,0.2,-0.1; 200,0,0.3"}


def test_the_kernel_drifts_the_target_as_the_reference_does() -> None:
    """The kernel starts the target where it was drawn, drifts it through the delay, then once
    per step: its track, step by step, and the runs' events against the reference's drift
    written from the model's text (tests/naive.py)."""
    mission = Mission.build(delay=120.0, **DRIFTING)  # type: ignore[arg-type]
    same = 0
    for run in range(4):
        fast = simulate(mission, seed=3, run=run, trajectory=True)
        slow = simulate_naive(mission, 3, run, record=True)
        assert fast.trajectory is not None and fast.trajectory.target is not None
        track = fast.trajectory.target[:, 0, :]
        np.testing.assert_allclose(track, np.array(slow.target_track), rtol=0.0, atol=1e-6)
        assert np.hypot(*(track[-1] - track[0])) > 10.0  # it went somewhere
        same += (fast.t_detect, fast.t_notify) == (slow.t_detect, slow.t_notify)
    assert same >= 3


def test_a_sweep_over_drift_settings_stores_and_loads_them(tmp_path: Path) -> None:
    """Pairs, tables and text of wind and current are one Parquet type: lists of rows."""
    (tmp_path / "e.toml").write_text(
        "seed = 1\nruns = 2\n[mission.team]\nplanner = 'covb'\ndrones = 3\n"
        "[mission.timing]\nhorizon = 60\n[mission.target]\nmotion = 'drift'\n"
        "drift_object = 'PIW-2'\ndrift_current = '0.2,-0.1'\n"
        "[grid]\ndrift_wind = [[8, 6], [[0, 8, 6], [600, 0, 10]]]\n")
    out = CliRunner().invoke(app, ["sweep", str(tmp_path / "e.toml"), "--out",
                                   str(tmp_path / "o"), "--workers", "1"])
    assert out.exit_code == 0, out.output
    rows = load(tmp_path / "o")
    assert len(rows) == 4 and set(rows["drift_object"]) == {"PIW-2"}
    winds = [tuple(tuple(r) for r in w) for w in rows.groupby("point")["drift_wind"].first()]
    assert winds == [((0.0, 8.0, 6.0),), ((0.0, 8.0, 6.0), (600.0, 0.0, 10.0))]
    assert all(tuple(tuple(r) for r in c) == ((0.0, 0.2, -0.1),) for c in rows["drift_current"])


def test_design_takes_the_drift_flags(tmp_path: Path) -> None:
    config = tmp_path / "drift.toml"
    config.write_text("[target]\nmotion = 'drift'\n")
    out = CliRunner().invoke(app, [
        "design", "--config", str(config), "--drift-object", "PIW-3", "--wind", "8,6",
        "--current", "0,0,0.1; 300,0.2,0", "--size", "2000", "--rc", "500", "--td", "300",
        "--ps", "0.5", "--planner", "covb", "--max-drones", "3", "--min-drones", "3",
        "--option", "on_detect=continue", "--first-runs", "10", "--candidate-runs", "10",
        "--workers", "1", "--out", str(tmp_path / "runs"), "--json"])
    assert out.exit_code == 0, out.output
    (folder,) = (tmp_path / "runs").glob("seed-*/*")  # the design's one candidate mission
    rows = load(folder)
    assert set(rows["drift_object"]) == {"PIW-3"} and set(rows["motion"]) == {"drift"}
    assert [tuple(r) for r in rows["drift_current"].iloc[0]] == [(0.0, 0.0, 0.1),
                                                                 (300.0, 0.2, 0.0)]


def test_drift_keeps_the_target_motion_contract() -> None:
    check_target_motion("drift", drift_wind="0,8,6; 600,-3,9", drift_current=(0.2, -0.1))
