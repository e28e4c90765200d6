"""Beyond the paper: the planners against targets that walk or drift (Fig. 12): its sweep, the
paired comparison and its sentences, the figure and the report's section. The end-to-end run
(tests/test_paper.py) checks the sweep's still target against the main sweep's runs."""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sarlink.metrics import success_curve, wilson
from sarlink.paper.experiments import (
    EXPERIMENTS,
    MOTIONS,
    MOVING_CURRENT,
    MOVING_DELAYS,
    MOVING_DRONES,
    MOVING_FIG,
    MOVING_RC,
    MOVING_TDS,
    MOVING_WIND,
    QUICK_RUNS,
    RUNS,
    SEED,
    TD_LONG,
    other_planners,
)
from sarlink.paper.figures import FIGURES, MOTION_TITLES
from sarlink.paper.moving import best_text, moving_points, moving_table, moving_text
from sarlink.paper.report import write_report
from sarlink.planners import PAPER_PLANNERS, get_planner
from sarlink.simulation import simulate

MOVING = EXPERIMENTS["moving"]


def test_the_sweep_flies_every_planner_against_each_motion_at_the_paper_setting() -> None:
    """The paper's five planners and the others (the IAMSAR patterns) × still, walk, drift ×
    the delays, N_m = 10, r_c = 500 m, to t_d = 4000 s or notification; the drift under the
    stated wind and current, the walk with its defaults."""
    built = MOVING.build(10)
    assert (built.seed, built.runs) == (SEED, 10)
    assert MOVING_FIG == 12 and MOVING.figures == (MOVING_FIG,)
    timing = built.mission.timing
    assert (timing.stop, timing.horizon) == ("notified", TD_LONG)
    points = built.points()
    planners = [*PAPER_PLANNERS, *other_planners()]
    assert [(p["planner"], p["motion"], p["delay"]) for p, _ in points] == list(
        itertools.product(planners, MOTIONS, MOVING_DELAYS))
    assert {"parallel", "expanding-square", "sector"} <= set(other_planners())
    for _, mission in points:
        target = mission.target
        assert (mission.team.drones, mission.channel.rc) == (MOVING_DRONES, MOVING_RC) == (
            10, 500.0)
        assert target.drift_wind == ((0.0, *MOVING_WIND),)
        assert target.drift_current == ((0.0, *MOVING_CURRENT),)
        assert (target.walk_speed, target.walk_mobile, target.drift_object) == (
            0.5, 14400.0, "PIW-1")


def test_a_quick_reproduction_flies_a_quarter_of_the_moving_runs_and_a_full_one_all() -> None:
    assert MOVING.runs(QUICK_RUNS, quick=True) == 25
    assert MOVING.runs(10, quick=True) == 3
    assert MOVING.runs(RUNS, quick=False) == RUNS


def test_run_k_starts_from_the_same_point_whatever_the_motion() -> None:
    """The pairing the comparison rests on: run k's last-seen point depends on the seed and k
    alone; and a walker who barely moves is found when a still target is."""
    base = MOVING.build(1).mission.replace(planner="covb", horizon=1000.0)
    for run in range(3):
        found = {motion: simulate(base.replace(motion=motion, delay=delay), seed=SEED, run=run)
                 for motion, delay in (("still", 0.0), ("walk", 0.0), ("drift", 1800.0))}
        assert len({r.target for r in found.values()}) == 1
    still = [simulate(base, seed=SEED, run=k).t_notify for k in range(6)]
    crawl = [simulate(base.replace(motion="walk", walk_speed=1e-6), seed=SEED, run=k).t_notify
             for k in range(6)]
    assert crawl == still and any(t is not None for t in still)


# -- the paired comparison, on made-up runs ------------------------------------------------------

def _runs(notified: dict[tuple[str, str, float], range], runs: int = 100) -> pd.DataFrame:
    """Made-up per-run values: each (planner, motion, delay) notifies in the runs listed, at
    500 s, and never in the others."""
    rows = []
    for (planner, motion, delay), hits in notified.items():
        for run in range(runs):
            rows.append({"planner": planner, "drones": 10, "rc": 500.0, "motion": motion,
                         "delay": delay, "run": run, "t_detect": 100.0,
                         "t_notify": 500.0 if run in hits else np.nan, "immediate": False,
                         "horizon": TD_LONG})
    return pd.DataFrame(rows)


def test_each_motion_is_compared_with_a_still_target_run_by_run() -> None:
    """CovB finds a still target in runs 0-59 and a walker in 0-39: 20 discordant runs, all
    lost to the walk; the same levels on other targets are a less certain fall."""
    runs = _runs({("covb", "still", 0.0): range(60), ("covb", "walk", 0.0): range(40)})
    (point,) = moving_points(runs, tds=[1000.0])
    assert (point.planner, point.motion, point.delay, point.td) == ("covb", "walk", 0.0, 1000.0)
    assert point.mine.value == pytest.approx(0.4)
    assert (point.mine.lo, point.mine.hi) == pytest.approx([float(b) for b in wilson(40, 100)])
    assert point.still.value == pytest.approx(0.6)
    assert point.change.value == pytest.approx(-0.2) and point.change.hi < 0
    shuffled = _runs({("covb", "still", 0.0): range(60), ("covb", "walk", 0.0): range(50, 90)})
    (other,) = moving_points(shuffled, tds=[1000.0])
    assert other.change.value == pytest.approx(-0.2)
    assert other.change.lo < point.change.lo and other.change.hi > point.change.hi
    tied = moving_points(_runs({("covb", "still", 0.0): range(60),
                                ("covb", "drift", 0.0): range(60)}), tds=[1000.0])[0]
    assert tied.change.tied and tied.motion == "drift"


def test_the_sentences_name_the_falls_the_best_planners_and_the_patterns() -> None:
    """mTSP is the best against a still target (70 runs), Sector against a walker (65 of the
    walker's targets; CovB 50, mTSP 20): the best pattern is below the best of the paper's
    (mTSP) against the still target and above it (CovB) against the walker."""
    runs = _runs({("mtsp", "still", 0.0): range(70), ("mtsp", "walk", 0.0): range(20),
                  ("covb", "still", 0.0): range(50), ("covb", "walk", 0.0): range(50),
                  ("sector", "still", 0.0): range(30), ("sector", "walk", 0.0): range(65)})
    points = moving_points(runs, tds=[1000.0, 2000.0])
    assert [(p.planner, p.td) for p in points] == [
        (p, td) for p in ("mtsp", "covb", "sector") for td in (1000.0, 2000.0)]
    (line,) = moving_text(points)
    assert line.startswith(
        "Against a walking target, 0 s from the last sighting to take-off, P_s is lower than "
        "against a still one at 2 and higher at 2 of 6 points (3 planners × t_d = 1000, "
        "2000 s; paired, 95% intervals); the largest fall: mTSP, -0.500 [")
    assert line.endswith("at t_d = 1000 s (0.700 [0.604, 0.781] to 0.200 [0.133, 0.289]).")
    best = best_text(runs, td=1000.0)
    assert best[0].startswith("At t_d = 1000 s the highest P_s: a still target: mTSP, 0.700 [")
    assert "; a walking target, 0 s from the last sighting to take-off: Sector, 0.650 [" in best[0]
    assert best[1].startswith("So mTSP, the best against a still target, is beaten on the same "
                              "runs against a walking target, 0 s from the last sighting to "
                              "take-off (Sector by 0.450 [")
    assert best[2].startswith("The best IAMSAR pattern against the best of the paper's "
                              "planners at t_d = 1000 s (paired): a still target: Sector below "
                              "mTSP, -0.400 [")
    assert "take-off: Sector above CovB, 0.150 [" in best[2]
    (rising,) = moving_text(moving_points(_runs({("covb", "still", 0.0): range(50),
                                                 ("covb", "walk", 0.0): range(55)})))
    assert rising.endswith("; no planner's P_s is lower at any point.")
    table = moving_table(points)
    assert len(table) == 6 and list(table["planner"][:2]) == ["mTSP", "mTSP"]
    assert moving_text([]) == [] and best_text(runs.iloc[:0]) == []


def test_the_report_has_the_section_when_the_moving_runs_are_there(tmp_path: Path) -> None:
    runs = _runs({(p, m, d): range(40 if m == "still" else 30) for p in ("covb", "sector")
                  for m in MOTIONS for d in MOVING_DELAYS})
    md, _ = write_report(tmp_path, runs=100, quick=True, figures={},
                         tables={"moving_runs": runs}, findings=[], stages=[], seconds=1.0,
                         workers="this process")
    text = md.read_text()
    section = text[text.index("## Beyond the paper: targets that move"):]
    for line in [*moving_text(moving_points(runs)), *best_text(runs)]:
        assert f"- {line}" in section
    assert "over 100 runs per point" in section and "CovB, Sector search" in section
    points = 2 * 2 * len(MOVING_DELAYS) * len(MOVING_TDS)  # planners × motions × delays × t_d
    assert f"Every point: the {points} paired comparisons" in section
    md, _ = write_report(tmp_path, runs=100, quick=True, figures={}, tables={}, findings=[],
                         stages=[], seconds=1.0, workers="this process")
    assert "targets that move" not in md.read_text()


# -- the figure ----------------------------------------------------------------------------------

def test_fig12_draws_every_planner_in_a_panel_per_motion_and_delay(tmp_path: Path) -> None:
    planners = [*PAPER_PLANNERS, *other_planners()]
    runs = _runs({(p, m, d): range(10 * i + 5) for i, p in enumerate(planners)
                  for m in MOTIONS for d in MOVING_DELAYS})
    curve = success_curve(runs, np.arange(100.0, TD_LONG + 1, 100.0),
                          by=["planner", "drones", "rc", "motion", "delay"])
    spec = FIGURES[MOVING_FIG]
    assert spec.tables == ("moving_curve",)
    fig = spec.draw(curve)
    assert [t.get_text() for t in fig.legends[0].get_texts()] == [
        get_planner(p).label for p in planners]
    titles = [ax.get_title() for ax in fig.axes]
    assert titles == [f"{MOTION_TITLES[m]}, delay {d:g} s"
                      for d in MOVING_DELAYS for m in MOTIONS]
    for i, p in enumerate(planners):
        lines = [line for ax in fig.axes for line in ax.get_lines()
                 if line.get_label() == get_planner(p).label]
        assert len(lines) == len(MOTIONS) * len(MOVING_DELAYS)
        for line in lines:  # notified at 500 s in runs 0 .. 10 i + 4 of 100
            np.testing.assert_allclose(line.get_ydata(), np.where(
                np.asarray(line.get_xdata()) >= 500.0, (10 * i + 5) / 100, 0.0), atol=0)
    fig.savefig(tmp_path / "fig12.png")
    assert (tmp_path / "fig12.png").stat().st_size > 10_000
    (_, values), = spec.values(curve)
    assert len(values) == len(planners) * len(MOTIONS) * len(MOVING_DELAYS) * len(MOVING_TDS)
    assert list(values.columns[:4]) == ["delay (s)", "t_d (s)", "target", "planner"]
