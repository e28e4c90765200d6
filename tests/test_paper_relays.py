"""Beyond the paper: searchers and relays against the paper's planners (Fig. 11): its sweep,
its tables, the paired comparison and its sentences, the figure and the report's section."""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sarlink.config import Experiment, Mission
from sarlink.execution import sweep_all
from sarlink.metrics import wilson
from sarlink.paper.experiments import (
    DRONES,
    EXPERIMENTS,
    QUICK_RUNS,
    RANGES,
    RELAY_COUNTS,
    RELAY_FIG,
    RELAY_TDS,
    RUNS,
    SEED,
    relay_label,
)
from sarlink.paper.figures import FIGURES, RELAY_STYLES
from sarlink.paper.relays import relay_points, relays_summary, relays_table, relays_text
from sarlink.paper.report import write_report
from sarlink.planners import PAPER_PLANNERS, get_planner
from sarlink.simulation import simulate

RELAYS = EXPERIMENTS["relays"]


def test_the_sweep_flies_covb_searchers_and_relays_at_the_paper_team_sizes_and_ranges() -> None:
    """Every team size of the paper's grid that leaves a searcher beside three relays, every
    range, relay counts 1-3, CovB planning the searchers alone; runs stop at notification or
    at the last t_d the figure reads; and ``--figures 11`` sweeps ``main`` too, which the
    comparison needs."""
    built = RELAYS.build(10)
    assert (built.seed, built.runs) == (SEED, 10)
    assert built.mission.timing.stop == "notified"
    assert built.mission.timing.horizon == max(RELAY_TDS) == 2000.0
    points = built.points()
    assert len(points) == len([n for n in DRONES if n >= 4]) * len(RANGES) * len(RELAY_COUNTS)
    assert {(p["drones"], p["rc"], p["relays"]) for p, _ in points} == set(itertools.product(
        range(4, 23, 2), RANGES, (1, 2, 3)))
    for params, mission in points:
        assert mission.team.planner == "covb"
        assert mission.searching().team.drones == params["drones"] - params["relays"] >= 1
        assert mission.searching().team.relays == 0
    assert RELAY_FIG == 11 and RELAYS.figures == (RELAY_FIG,)
    assert RELAY_FIG in EXPERIMENTS["main"].figures


def test_a_quick_reproduction_flies_a_quarter_of_the_relay_runs_and_a_full_one_all() -> None:
    assert RELAYS.runs(QUICK_RUNS, quick=True) == 25
    assert RELAYS.runs(10, quick=True) == 3
    assert RELAYS.runs(1, quick=True) == 1
    assert RELAYS.runs(RUNS, quick=False) == RUNS
    assert all(e.runs(QUICK_RUNS, quick=True) == QUICK_RUNS for e in EXPERIMENTS.values()
               if e.name not in ("relays", "moving"))  # moving: tests/test_paper_moving.py


def test_run_k_searches_for_the_same_target_whatever_the_team() -> None:
    """The pairing the comparison rests on: run k's target depends on the seed and k alone,
    not on the planner, the team size or the relays."""
    base = Mission.build(rc=500.0, horizon=200.0)
    for run in range(3):
        targets = {simulate(base.replace(planner=planner, drones=n, relays=k), seed=SEED,
                            run=run).target
                   for planner, n, k in (("covb", 10, 0), ("covb", 10, 3), ("conb", 6, 0),
                                         ("covb", 4, 1))}
        assert len(targets) == 1, targets


def test_the_tables_are_the_runs_summarised_per_team_and_relay_count(tmp_path: Path) -> None:
    """``relays`` has P_s at each t_d per team and relay count, the share of its runs notified
    by then; ``relays_runs`` every run's own times, for the paired comparison."""
    built = RELAYS.build(6)
    small = Experiment(name="relays", seed=SEED, runs=6, mission=built.mission,
                       grid={**built.grid, "drones": [4], "rc": [500.0], "relays": [1, 3]})
    (runs,) = sweep_all([(small, tmp_path / "runs")], workers=1, progress=False)
    tables = RELAYS.tables(runs)
    summary, each = tables["relays"], tables["relays_runs"]
    assert len(summary) == 2 * len(RELAY_TDS) and len(each) == 2 * 6
    for k, td in itertools.product((1, 3), RELAY_TDS):
        row = summary[(summary["relays"] == k) & (summary["td"] == td)].iloc[0]
        mine = each[each["relays"] == k]
        assert sorted(mine["run"]) == list(range(6))
        assert row["P_s"] == pytest.approx(float((mine["t_notify"] <= td).mean()))


# -- the paired comparison, on made-up runs ------------------------------------------------------

def _runs(notified: dict[tuple[str, int], range], runs: int = 100, drones: int = 10,
          rc: float = 500.0) -> pd.DataFrame:
    """Made-up per-run values: each (planner, relays) notifies in the runs listed, at 500 s,
    and never in the others."""
    rows = []
    for (planner, k), hits in notified.items():
        for run in range(runs):
            rows.append({"planner": planner, "drones": drones, "rc": rc, "relays": k,
                         "run": run, "t_detect": 100.0,
                         "t_notify": 500.0 if run in hits else np.nan, "immediate": False})
    return pd.DataFrame(rows)


def _main(notified: dict[str, range], runs: int = 100) -> pd.DataFrame:
    return _runs({(p, 0): hits for p, hits in notified.items()}, runs).drop(columns="relays")


def test_each_point_is_compared_with_the_best_of_the_paper_run_by_run() -> None:
    """CovB + 2 relays notify in runs 0-79, mTSP (the best of the paper) in 0-59, CovB with
    every drone searching in 0-49: 20 and 30 discordant runs, all won by the relays."""
    main = _main({"mtsp": range(60), "covb": range(50), "conb": range(10)})
    relays = _runs({("covb", 2): range(80)})
    (point,) = relay_points(main, relays, tds=[1000.0])
    nested = point
    assert (point.relays, point.drones, point.rc, point.td, point.best) == (
        2, 10, 500.0, 1000.0, "mtsp")
    assert point.mine.value == pytest.approx(0.8)
    assert (point.mine.lo, point.mine.hi) == pytest.approx([float(b) for b in wilson(80, 100)])
    assert point.theirs.value == pytest.approx(0.6)
    assert point.gain.value == pytest.approx(0.2) and point.gain.lo > 0
    assert point.alone.value == pytest.approx(0.3) and point.alone.lo > 0
    # the same levels, the relays' successes on other targets: 40 won and 20 lost of 60
    # discordant runs, a less certain gain than 20 won of 20 (unpaired, both would be alike)
    (point,) = relay_points(main, _runs({("covb", 2): range(20, 100)}), tds=[1000.0])
    assert point.gain.value == pytest.approx(0.2)
    assert point.gain.lo < nested.gain.lo and point.gain.hi > nested.gain.hi


def test_a_tie_is_not_a_win_and_a_loss_is_named() -> None:
    main = _main({"mtsp": range(60), "covb": range(60)})
    same = relay_points(main, _runs({("covb", 1): range(60)}), tds=[1000.0])[0]
    assert same.gain.tied and same.gain.value == 0.0
    worse = relay_points(main, _runs({("covb", 3): range(30)}), tds=[1000.0])[0]
    assert worse.gain.hi < 0 and worse.best == "mtsp"  # the first of equals in legend order


def test_a_quick_reproduction_pairs_the_relays_with_the_first_runs_of_main() -> None:
    """The relays flew runs 0-24 only: the paper's planners are read over the same 25."""
    main = _main({"mtsp": range(25, 100), "covb": range(10)})
    (point,) = relay_points(main, _runs({("covb", 1): range(20)}, runs=25), tds=[1000.0])
    assert point.best == "covb" and point.theirs.value == pytest.approx(10 / 25)
    assert point.gain.value == pytest.approx(10 / 25) and point.gain.lo > 0
    with pytest.raises(ValueError, match="not among the main sweep's"):
        relay_points(_main({"covb": range(10)}, runs=20), _runs({("covb", 1): range(5)}, 25))


def test_the_sentences_and_tables_say_where_the_relays_win_and_lose() -> None:
    main = _main({"mtsp": range(60), "covb": range(50)})
    relays = pd.concat([_runs({("covb", 1): range(80)}), _runs({("covb", 2): range(30)})])
    points = relay_points(main, relays, tds=[1000.0, 2000.0])
    lines = relays_text(points)
    assert lines[0].startswith(
        "CovB + 1 relay (N_m − 1 searchers): above the best of the paper's planners at 2 of 2 "
        "points and below it at 0; closest to it or above: 0.200 [")
    assert "(against mTSP)" in lines[0]
    assert lines[0].endswith("Against CovB with every drone searching, P_s is higher with the "
                             "relays at 2 of 2 points and lower at 0.")
    assert "CovB + 2 relays (N_m − 2 searchers): above the best of the paper's planners at 0 "\
           "of 2 points and below it at 2" in lines[1]
    assert lines[-1].startswith("So at 2 of 2 points (N_m, r_c, t_d) some relay count beats "
                                "the best of the paper's planners at equal team size, and at 0 "
                                "every relay count is beaten by it")
    summary = relays_summary(points)
    assert summary.to_dict("records") == [
        {"team": "CovB + 1 relay", "r_c (m)": "500", "above the best of the paper": "2 of 2",
         "below the best of the paper": "0 of 2", "above CovB alone": "2 of 2",
         "below CovB alone": "0 of 2"},
        {"team": "CovB + 2 relays", "r_c (m)": "500", "above the best of the paper": "0 of 2",
         "below the best of the paper": "2 of 2", "above CovB alone": "0 of 2",
         "below CovB alone": "2 of 2"}]
    table = relays_table(points)
    assert len(table) == 4 and set(table["best of the paper"]) == {"mTSP"}
    assert table["P_s"].str.startswith(("0.800 [", "0.300 [")).all()
    assert relays_text([]) == []


def test_the_report_has_the_section_when_both_run_tables_are_there(tmp_path: Path) -> None:
    main = _main({p: range(50) for p in PAPER_PLANNERS})
    relays = _runs({("covb", 1): range(70)})
    md, _ = write_report(tmp_path, runs=100, quick=True, figures={},
                         tables={"main_runs": main, "relays_runs": relays}, findings=[],
                         stages=[], seconds=1.0, workers="this process")
    text = md.read_text()
    section = text[text.index("## Beyond the paper: how many drones should hold the link?"):]
    for line in relays_text(relay_points(main, relays)):
        assert f"- {line}" in section
    assert "over 100 runs per point" in section
    assert "Every point: the 2 paired comparisons" in section
    md, _ = write_report(tmp_path, runs=100, quick=True, figures={}, tables={"main_runs": main},
                         findings=[], stages=[], seconds=1.0, workers="this process")
    assert "hold the link" not in md.read_text()


# -- the figure ----------------------------------------------------------------------------------

def _summary(p_s: dict[tuple[str, int], float], drones: tuple[int, ...] = (4, 10, 22)
             ) -> pd.DataFrame:
    """A made-up summary table: P_s of each (planner, relays) at every point, with Wilson
    bounds, a little higher at every larger team."""
    rows = []
    for (planner, k), value in p_s.items():
        for n, rc, td in itertools.product(drones, RANGES, RELAY_TDS):
            p = min(1.0, value + 0.01 * n)
            lo, hi = wilson(round(p * 100), 100)
            rows.append({"planner": planner, "drones": n, "rc": rc, "relays": k, "td": td,
                         "runs": 100, "P_s": p, "P_s_lo": float(lo), "P_s_hi": float(hi)})
    return pd.DataFrame(rows)


def test_fig11_draws_each_relay_count_solid_beside_the_paper_planners_dashed(
        tmp_path: Path) -> None:
    main = _summary({(p, 0): 0.5 for p in PAPER_PLANNERS}, drones=(2, 4, 10, 22)).drop(
        columns="relays")
    relays = _summary({("covb", k): 0.1 * k for k in RELAY_COUNTS})
    spec = FIGURES[RELAY_FIG]
    assert spec.tables == ("main", "relays")
    fig = spec.draw(main, relays)
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert labels == ([relay_label(k) for k in RELAY_COUNTS]
                      + [get_planner(p).label for p in PAPER_PLANNERS])
    assert labels[:3] == ["CovB + 1 relay", "CovB + 2 relays", "CovB + 3 relays"]
    panels = len(RANGES) * len(RELAY_TDS)
    for k, (colour, marker) in zip(RELAY_COUNTS, RELAY_STYLES, strict=True):
        lines = [line for ax in fig.axes for line in ax.get_lines()
                 if line.get_label() == relay_label(k)]
        assert len(lines) == panels
        assert {(line.get_color(), line.get_marker(), line.get_linestyle())
                for line in lines} == {(colour, marker, "-")}
        for line in lines:  # the table's P_s, at its team sizes (shifted sideways a little)
            np.testing.assert_allclose(line.get_ydata(), [min(1.0, 0.1 * k + 0.01 * n)
                                                          for n in (4, 10, 22)])
            assert np.abs(line.get_xdata() - np.array([4, 10, 22])).max() <= 0.2 + 1e-9
    dashed = [line for ax in fig.axes for line in ax.get_lines() if line.get_linestyle() == "--"]
    assert len(dashed) == len(PAPER_PLANNERS) * panels
    assert all(len(line.get_xdata()) == 3 for line in dashed)  # equal team sizes only
    fig.savefig(tmp_path / "fig11.png")
    assert (tmp_path / "fig11.png").stat().st_size > 10_000
    (_, values), = spec.values(main, relays)
    assert len(values) == (len(PAPER_PLANNERS) + len(RELAY_COUNTS)) * 3 * panels
    assert list(values.columns[:5]) == ["r_c (m)", "t_d (s)", "N_m", "relays", "planner"]
