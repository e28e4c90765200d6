"""The readings of the paper: each rule variant on a hand-placed case that only it passes, and
the presets (docs/model.md, Readings).

Drones are placed by hand around a BS at the centre (2000, 2000) and fly 5 m per 1 s step; the
take-off counts as a direction change at t = 0, so the first periodic update is at step 2 and
a recorded heading at step k + 1 is the one decided at step k.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from sarlink import ConfigError, Mission, Scenario, load, simulate
from sarlink.cli import app
from sarlink.config import DEFAULT_READING, READINGS, Readings
from sarlink.paper import ReproductionResult, reproduce
from sarlink.paper.variants import SYMBOL, variants
from sarlink.planners import get_planner

FAR_TARGET = (100.0, 3900.0)  # never sensed in these few steps


def _headings(planner: str, positions: list[tuple[float, float]], angles: list[float],
              steps: int = 6, **choices: object) -> np.ndarray:
    """The recorded headings of a hand-placed team as unit vectors ``(step, drone, 2)``."""
    mission = Mission.build(planner=planner, drones=len(positions), horizon=float(steps),
                            **choices)
    scenario = Scenario(target=FAR_TARGET, positions=np.array(positions),
                        headings=np.array(angles))
    trajectory = simulate(mission, scenario=scenario, trajectory=True).trajectory
    assert trajectory is not None
    return np.stack([np.cos(trajectory.headings), np.sin(trajectory.headings)], axis=-1)


def test_the_continuous_check_turns_a_drone_about_to_leave_at_once() -> None:
    """A lone ConB drone 996 m east of the BS flies east: one increment on, it is 1001 m away,
    out of r_c = 1000 m. Checked at every increment, it turns at step 0 towards its only
    contact, the BS (Eq. 9's two unit terms cancel: it turns to θ_ij, due west); checked only
    when t_s has elapsed, at step 2 it has no neighbour left and flies on east."""
    args = ("conb", [(2996.0, 2000.0)], [0.0])
    continuous = _headings(*args, rc=1000.0, conb_check="continuous")
    period = _headings(*args, rc=1000.0, conb_check="period")
    assert continuous[1, 0] == pytest.approx((-1.0, 0.0))
    assert period[1:, 0] == pytest.approx(np.tile((1.0, 0.0), (len(period) - 1, 1)))


def test_contacts_all_follows_the_longest_contact_even_without_a_route() -> None:
    """Drone 0 (at 3885 m, flying east) will lose its only routed neighbour, drone 1 (flying
    west, 975 m away, towards the BS). Drone 2, 600 m north of drone 0, flies with it (equal
    velocities: the contact never ends) but has no route to the BS. Among routed neighbours
    (``routed``) drone 0 turns back towards drone 1 (the terms cancel: due west); among all
    (``all``) it keeps on with drone 2, nearly east."""
    positions = [(3885.0, 2000.0), (2910.0, 2000.0), (3885.0, 2600.0)]
    angles = [0.0, math.pi, 0.0]
    routed = _headings("conb", positions, angles, rc=1000.0, conb_check="period",
                       contacts="routed")
    every = _headings("conb", positions, angles, rc=1000.0, conb_check="period", contacts="all")
    assert routed[3, 0] == pytest.approx((-1.0, 0.0))
    # towards where drone 2 will be at T_max, from drone 0's next position, plus the heading
    cx, cy = 3895.0 + 5.0 * 4000.0, 2600.0
    dx, dy = cx - 3900.0, cy - 2000.0
    ux, uy = dx / math.hypot(dx, dy), dy / math.hypot(dx, dy)
    rx, ry = 1.0 + ux, uy
    assert every[3, 0] == pytest.approx((rx / math.hypot(rx, ry), ry / math.hypot(rx, ry)))


def test_an_isolated_drone_keeps_its_heading_or_turns_home() -> None:
    """A lone ConB drone 1500 m east of the BS (r_c = 500 m) flies north with no neighbour:
    at its update (step 2) it keeps its heading, or turns to the BS with ``isolated = home``."""
    args = ("conb", [(3500.0, 2000.0)], [math.pi / 2])
    keep = _headings(*args, rc=500.0, conb_check="period", isolated="keep")
    home = _headings(*args, rc=500.0, conb_check="period", isolated="home")
    assert keep[3, 0] == pytest.approx((0.0, 1.0))
    x, y = 3500.0, 2000.0 + 2 * 5.0  # where it is at step 2
    d = math.hypot(2000.0 - x, 2000.0 - y)
    assert home[3, 0] == pytest.approx(((2000.0 - x) / d, (2000.0 - y) / d))
    assert home[1:3, 0] == pytest.approx(np.array([(0.0, 1.0)] * 2))  # it flies on between updates


def test_a_vanishing_concov_resultant_keeps_the_heading_or_follows_connectivity() -> None:
    """A lone ConCov drone flies east, 995 m from the BS at its update (r_c = 1000 m) and out of
    range at t + t_s: CovB's term is its heading (no neighbour within r), ConB's points back to
    the BS, and with α = 0.5 Eq. 12 is exactly zero. It keeps its heading or, with
    ``concov_fallback = connectivity``, turns back with the connectivity term."""
    args = ("concov", [(2985.0, 2000.0)], [0.0])
    heading = _headings(*args, rc=1000.0, concov_fallback="heading")
    connectivity = _headings(*args, rc=1000.0, concov_fallback="connectivity")
    assert heading[3, 0] == pytest.approx((1.0, 0.0))
    assert connectivity[3, 0] == pytest.approx((-1.0, 0.0))


def test_a_connected_concov_drone_with_no_connectivity_term_follows_coverage() -> None:
    """Two ConCov drones near the BS (both routed), 200 m apart east-west, fly north. Drone 0's
    CovB resultant (Eq. 6) is its heading / r plus drone 1's push; with ``concov_connected =
    heading`` Eq. 12 adds its heading as R_con (Algorithm 2), with ``none`` nothing."""
    positions = [(2200.0, 2000.0), (2400.0, 2000.0)]
    angles = [math.pi / 2, math.pi / 2]
    with_heading = _headings("concov", positions, angles, concov_connected="heading")
    without = _headings("concov", positions, angles, concov_connected="none")
    y = 2000.0 + 2 * 5.0  # both at step 2
    fx, fy = 0.0 + (2200.0 - 2400.0) / 200.0**2, 1.0 / 500.0 + (y - y) / 200.0**2
    cx, cy = fx / math.hypot(fx, fy), fy / math.hypot(fx, fy)
    bx, by = 0.5 * cx, 0.5 * cy + 0.5
    assert without[3, 0] == pytest.approx((cx, cy))
    assert with_heading[3, 0] == pytest.approx((bx / math.hypot(bx, by),
                                                by / math.hypot(bx, by)))


def test_the_default_reading_is_what_a_mission_gives() -> None:
    assert Mission().readings.model_dump() == READINGS[DEFAULT_READING].choices
    for reading in READINGS.values():
        assert set(reading.choices) == set(Readings.model_fields)


def test_a_reading_preset_sets_the_choices_and_explicit_values_win() -> None:
    literal = Mission.build(reading="literal")
    assert literal.readings.model_dump() == READINGS["literal"].choices
    assert Mission.build(reading="literal", contacts="routed").readings.contacts == "routed"
    with pytest.raises(ConfigError, match="unknown reading 'nope'; known: literal, sarlink-1"):
        Mission.build(reading="nope")


def test_readings_reach_only_the_planners_whose_rules_they_change() -> None:
    """CovB and mTSP runs are the same under every reading: no choice touches their rules."""
    for planner in ("covb", "mtsp"):
        runs = {name: simulate(Mission.build(reading=name, planner=planner, drones=4,
                                             rc=500.0, horizon=1500.0), seed=5, run=1)
                for name in READINGS}
        first, *rest = runs.values()
        assert all(r.t_notify == first.t_notify and r.t_detect == first.t_detect and
                   np.array_equal(r.reach_cum, first.reach_cum) for r in rest)


# -- the readings in a reproduction -----------------------------------------------------------


def test_the_variants_change_one_choice_to_each_other_value() -> None:
    names = [v.name for v in variants(READINGS["sarlink-1"])]
    assert names == ["conb_check=continuous", "contacts=all", "isolated=home",
                     "concov_fallback=connectivity", "concov_connected=none", "td_fig3=1000",
                     "td_fig3=4000"]
    assert [v.name for v in variants(READINGS["literal"])][:2] == ["conb_check=period",
                                                                   "contacts=routed"]


@pytest.fixture(scope="module")
def study(tmp_path_factory: pytest.TempPathFactory) -> ReproductionResult:
    """Fig. 7 (its sweeps stop early: seconds) with the sensitivity analysis, 3 runs a point."""
    return reproduce(tmp_path_factory.mktemp("sensitivity"), runs=3, figures=[7],
                     progress=False, workers=1, reading="sarlink-1", sensitivity_analysis=True)


def test_a_change_reruns_only_the_planners_it_reaches(study: ReproductionResult) -> None:
    folders = {p.name: sorted(f.name for f in p.iterdir())
               for p in (study.out / "runs" / "miss").iterdir()}
    assert folders["covb"] == folders["mtsp"] == ["any"]
    presets = {"-".join(r.choices[c] for c in ("conb_check", "contacts", "isolated"))
               for r in READINGS.values()}  # the report tallies the claims under each preset
    assert folders["conb"] == folders["mtsp-conb"] == sorted(
        {"period-routed-keep", "continuous-routed-keep", "period-all-keep", "period-routed-home"}
        | presets)
    reach = [c for c in READINGS["sarlink-1"].choices
             if c in get_planner("concov").rule.readings]  # type: ignore[union-attr]
    concov = {"-".join(r.choices[c] for c in reach) for r in READINGS.values()}
    assert len(folders["concov"]) == len(concov | {"-".join(
        {**READINGS["sarlink-1"].choices, v.choice: v.value}[c] for c in reach)
        for v in study.variants if v.choice != "td_fig3"})  # the reading, its changes, presets


def test_a_changed_reading_s_runs_are_those_of_its_missions(study: ReproductionResult) -> None:
    """The stored runs of ConB under the continuous check are those simulated directly."""
    runs = load(study.out / "runs" / "miss" / "conb" / "continuous-routed-keep")
    for row in runs.itertuples():
        mission = Mission.build(reading="sarlink-1", conb_check="continuous", planner="conb",
                                drones=10, rc=500.0, horizon=1000.0, stop="detected",
                                p_miss=row.p_miss)
        direct = simulate(mission, seed=row.seed, run=row.run)
        assert (direct.t_detect or math.nan) == pytest.approx(row.t_detect, nan_ok=True)


def test_the_report_holds_the_matrix_and_every_flip(study: ReproductionResult) -> None:
    matrix = pd.read_csv(study.out / "tables" / "sensitivity.csv")
    changes = [v.name for v in study.variants]
    assert list(matrix.columns) == ["figure", "claim", "default", *changes]
    assert list(matrix["default"]) == [SYMBOL[f.outcome] for f in study.findings]
    flipped = int((matrix[changes].to_numpy() != matrix[["default"]].to_numpy()).sum())
    md = study.report_md.read_text()
    section = md[md.index("## What each finding depends on"):].split("\n## ")[0]
    assert f"Flipped outcomes ({flipped})" in section
    assert section.count("\n- ") == max(flipped, 1)


def test_reproduce_names_an_unknown_reading(tmp_path: Path) -> None:
    out = CliRunner().invoke(app, ["reproduce", "--reading", "nope", "--out", str(tmp_path)])
    assert out.exit_code == 2
    assert "unknown reading 'nope'; known: literal, sarlink-1" in out.output
