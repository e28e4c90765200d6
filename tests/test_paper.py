"""The paper's reproduction: a quick end-to-end run, its report's numbers, and the findings checks.

The end-to-end run (10 runs per grid point) is shared by the smoke tests; the findings checks
are tested on made-up summary tables built so that a claim holds or fails by a clear margin.
"""

from __future__ import annotations

import importlib
import inspect
import json
import math
import re
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from sarlink import ConfigError, load
from sarlink.cli import app
from sarlink.metrics import summarize, wilson
from sarlink.paper import ReproductionResult, check_all, reproduce
from sarlink.paper.experiments import DRONES, PLANNERS, RANGES, plan_time_missions
from sarlink.paper.findings import (
    CHECKS,
    Finding,
    _Estimate,
    conb_mission_time,
    concov_beats_mtsp_conb,
    drones_help,
    hybrids_beat_conb,
    larger_range_short_td,
    mtsp_immediate_lowest,
    mtsp_two_drones,
    reachability_order,
)

# -- the end-to-end run --------------------------------------------------------------------------


@pytest.fixture(scope="module")
def quick(tmp_path_factory: pytest.TempPathFactory) -> ReproductionResult:
    """``reproduce --quick --runs 10``, with a short GA for Fig. 1's timing."""
    return reproduce(tmp_path_factory.mktemp("reproduction"), quick=True, runs=10,
                     progress=False, plan_iterations=100)


def test_every_figure_and_both_reports_exist(quick: ReproductionResult) -> None:
    out = quick.out
    for n in range(1, 8):
        for ext in ("png", "svg"):
            path = out / "figures" / f"fig{n}.{ext}"
            assert path.stat().st_size > 10_000, path
    assert sorted(quick.figures) == list(range(1, 8))
    assert quick.report_md == out / "report.md"
    page = quick.report_html.read_text()
    assert page.count("data:image/png;base64,") == 7
    assert not re.search(r"""(src|href)=["']?(https?:|//|figures/)""", page)  # self-contained
    for name in ("main", "curve", "miss", "shadowing", "plan_times"):
        assert (out / "tables" / f"{name}.csv").exists()
        assert (out / "tables" / f"{name}.parquet").exists()


def test_the_report_links_a_replay_of_every_planner_at_rc_500(quick: ReproductionResult
                                                              ) -> None:
    assert quick.replay == quick.out / "replay-rc500.html"
    data = re.search(r'id="sarlink-data">(.*?)</script>', quick.replay.read_text(), re.S)
    assert data is not None
    panels = json.loads(data.group(1))["panels"]
    assert sorted(p["planner"] for p in panels) == sorted(PLANNERS)
    assert all(p["rc"] == 500.0 and p["tNotify"] is not None for p in panels)
    assert "(replay-rc500.html)" in quick.report_md.read_text()
    assert 'href="replay-rc500.html"' in quick.report_html.read_text()


def test_stored_tables_equal_the_summaries_recomputed_from_the_runs(
        quick: ReproductionResult) -> None:
    runs = load(quick.out / "runs" / "main")
    assert len(runs) == 10 * len(PLANNERS) * len(DRONES) * len(RANGES)
    recomputed = summarize(runs, td=[1000.0, 2000.0, 4000.0], by=["planner", "drones", "rc"])
    stored = pd.read_csv(quick.out / "tables" / "main.csv")
    cols = ["P_s", "P_s_lo", "immediate", "mission_time", "mission_time_se", "reachability"]
    np.testing.assert_allclose(stored[cols], recomputed[cols], rtol=1e-12)
    assert (stored["planner"] == recomputed["planner"]).all()
    pd.testing.assert_frame_equal(pd.read_parquet(quick.out / "tables" / "main.parquet"),
                                  recomputed)


def _report_table(md: str, heading: str) -> list[list[str]]:
    """The rows of the first table after ``heading`` in the Markdown report."""
    section = md[md.index(heading):]
    table = section[section.index("\n|"):].split("\n\n")[0]
    return [[c.strip() for c in line.strip("|").split("|")]
            for line in table.strip().splitlines()[2:]]


def test_report_numbers_equal_those_recomputed_from_the_stored_runs(
        quick: ReproductionResult) -> None:
    md = quick.report_md.read_text()
    main = summarize(load(quick.out / "runs" / "main"), td=[2000.0, 4000.0],
                     by=["planner", "drones", "rc"])
    labels = {"mTSP": "mtsp", "CovB": "covb", "ConB": "conb", "mTSP-ConB": "mtsp-conb",
              "ConCov": "concov"}

    fig3 = _report_table(md, "### Figure 3")
    assert len(fig3) == len(PLANNERS) * len(DRONES) * len(RANGES)
    for rc, label, n, cell in fig3:
        row = main[(main["planner"] == labels[label]) & (main["drones"] == int(n))
                   & (main["rc"] == float(rc)) & (main["td"] == 2000.0)].iloc[0]
        assert cell == f"{row['P_s']:.3f} [{row['P_s_lo']:.3f}, {row['P_s_hi']:.3f}]"

    for rc, label, n, cell in _report_table(md, "### Figure 6"):
        row = main[(main["planner"] == labels[label]) & (main["drones"] == int(n))
                   & (main["rc"] == float(rc)) & (main["td"] == 4000.0)].iloc[0]
        assert cell == f"{row['reachability']:.3f} ± {row['reachability_se']:.3f}"

    miss = summarize(load(quick.out / "runs" / "miss"), by=["planner", "p_miss"])
    fig7a = _report_table(md, "### Figure 7")
    assert len(fig7a) == len(miss)
    for label, p_miss, cell in fig7a:
        row = miss[(miss["planner"] == labels[label])
                   & np.isclose(miss["p_miss"], float(p_miss))].iloc[0]
        assert cell == f"{row['P_d']:.3f} [{row['P_d_lo']:.3f}, {row['P_d_hi']:.3f}]"


def test_findings_are_those_of_the_recomputed_table_and_the_report_says_so(
        quick: ReproductionResult) -> None:
    recomputed = summarize(load(quick.out / "runs" / "main"), td=[1000.0, 2000.0, 4000.0],
                           by=["planner", "drones", "rc"])
    assert quick.findings == check_all(recomputed)
    md = quick.report_md.read_text()
    held = sum(f.holds for f in quick.findings)
    assert f"{held} of {len(CHECKS)} of the paper's findings hold" in md
    for f in quick.findings:
        verdict = "holds" if f.holds else "does not hold"
        assert f"{f.claim} — {verdict}" in md


def test_a_second_call_reuses_the_stored_runs_and_plan_times(quick: ReproductionResult) -> None:
    files = {p: p.stat().st_mtime_ns for p in (quick.out / "runs").rglob("*.parquet")}
    plan_times = (quick.out / "plan_times.json").stat().st_mtime_ns
    again = reproduce(quick.out, quick=True, runs=10, figures=[1, 3], progress=False,
                      plan_iterations=100)
    assert {p: p.stat().st_mtime_ns for p in (quick.out / "runs").rglob("*.parquet")} == files
    assert (quick.out / "plan_times.json").stat().st_mtime_ns == plan_times
    pd.testing.assert_frame_equal(again.tables["plan_times"], quick.tables["plan_times"])
    pd.testing.assert_frame_equal(again.tables["main"], quick.tables["main"])
    assert sorted(again.figures) == [1, 3]
    assert "miss" not in again.tables  # only what the figures need


def test_cli_reports_where_the_report_is(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # the package's ``reproduce`` is the function; the module is found by its full name
    module = importlib.import_module("sarlink.paper.reproduce")
    monkeypatch.setattr(module, "plan_time_missions",
                        lambda iterations=None: plan_time_missions(100))
    result = CliRunner().invoke(app, ["reproduce", "--figures", "1", "--out", str(tmp_path),
                                      "--quiet"])
    assert result.exit_code == 0, result.output
    assert "report.html" in result.output
    assert "findings not checked" in result.output
    assert (tmp_path / "figures" / "fig1.png").exists()


@pytest.mark.parametrize(("args", "message"), [
    (["--figures", "1,8"], "figures must be among"),
    (["--figures", "one"], "--figures takes figure numbers"),
    (["--runs", "0"], "runs must be at least 1"),
])
def test_cli_rejects_bad_arguments_in_one_line(tmp_path: Path, args: list[str],
                                               message: str) -> None:
    result = CliRunner().invoke(app, ["reproduce", "--out", str(tmp_path), *args])
    assert result.exit_code == 2
    assert message in result.output
    assert not (tmp_path / "runs").exists()


def test_api_rejects_unknown_figures(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="figures must be among"):
        reproduce(tmp_path, figures=[0])


# -- the findings checks on made-up tables -------------------------------------------------------

Rule = Callable[[str, int, float, float], float]
"""A made-up value of a measure at (planner, N_m, r_c, t_d)."""

RUNS = 2000


def made_up(P_s: Rule = lambda *_: 0.5, immediate: Rule = lambda *_: 0.5,
            mission_time: Rule = lambda *_: 1000.0,
            reachability: Rule = lambda *_: 0.3) -> pd.DataFrame:
    """A main summary table over the paper's grid; probabilities are counts out of 2000 runs
    with their Wilson intervals, means have plausible standard errors."""
    rows = []
    for planner in PLANNERS:
        for n in DRONES:
            for rc in RANGES:
                for td in (1000.0, 2000.0, 4000.0):
                    row: dict[str, object] = {"planner": planner, "drones": n, "rc": rc,
                                              "td": td, "runs": RUNS}
                    for name, rule in (("P_s", P_s), ("immediate", immediate)):
                        k = round(rule(planner, n, rc, td) * RUNS)
                        lo, hi = wilson(k, RUNS)
                        row |= {name: k / RUNS, f"{name}_lo": float(lo), f"{name}_hi": float(hi)}
                        if name == "P_s":
                            row["notified"] = k
                    for name, rule, sd in (("mission_time", mission_time, 600.0),
                                           ("reachability", reachability, 0.2)):
                        row |= {name: rule(planner, n, rc, td), f"{name}_se": sd / math.sqrt(RUNS)}
                    rows.append(row)
    return pd.DataFrame(rows)


def _by_range(values: dict[float, float]) -> Rule:
    return lambda p, n, rc, td: values[rc]


CASES = [
    # larger r_c: P_s(1000 s) rises to near 1 at 2000 m / stays below 0.9 for ConB / falls
    (larger_range_short_td, made_up(P_s=_by_range({500.0: 0.5, 1000.0: 0.8, 2000.0: 0.97})),
     True),
    (larger_range_short_td, made_up(P_s=lambda p, n, rc, td: 0.85 if p == "conb" and rc == 2000
                                    else {500.0: 0.5, 1000.0: 0.8, 2000.0: 0.97}[rc]), False),
    (larger_range_short_td, made_up(P_s=lambda p, n, rc, td: 0.99 if rc == 500 else 0.95),
     False),
    # mTSP with 2 drones: every run notified / one run missed
    (mtsp_two_drones, made_up(P_s=lambda p, n, rc, td: 1.0 if p == "mtsp" and n == 2 else 0.5),
     True),
    (mtsp_two_drones, made_up(P_s=lambda p, n, rc, td: (0.9995 if rc == 1000 else 1.0)
                              if p == "mtsp" and n == 2 else 0.5), False),
    # drones help mTSP and CovB, not ConB / ConB gains 0.2 / CovB gains nothing
    (drones_help, made_up(P_s=lambda p, n, rc, td: 0.4 if p == "conb" else 0.3 + 0.03 * n),
     True),
    (drones_help, made_up(P_s=lambda p, n, rc, td: 0.3 + 0.01 * n if p == "conb"
                          else 0.3 + 0.03 * n), False),
    (drones_help, made_up(P_s=lambda p, n, rc, td: 0.3 + 0.03 * n if p == "mtsp" else 0.4),
     False),
    # hybrids over ConB: largest at 500 m / the same at every range
    (hybrids_beat_conb, made_up(P_s=lambda p, n, rc, td: 0.4 + (
        {500.0: 0.3, 1000.0: 0.15, 2000.0: 0.02}[rc] if p in ("concov", "mtsp-conb") else 0)),
     True),
    (hybrids_beat_conb, made_up(P_s=lambda p, n, rc, td: 0.6 if p in ("concov", "mtsp-conb")
                                else 0.4), False),
    # ConCov over mTSP-ConB: grows with N_m / never / ahead but not growing / both at 1
    (concov_beats_mtsp_conb, made_up(P_s=lambda p, n, rc, td: 0.3 + 0.03 * n if p == "concov"
                                     else 0.3 + 0.01 * n), True),
    (concov_beats_mtsp_conb, made_up(P_s=lambda p, n, rc, td: 0.3 + 0.02 * n), False),
    (concov_beats_mtsp_conb, made_up(P_s=lambda p, n, rc, td: 0.6 if p == "concov" else 0.4),
     False),
    (concov_beats_mtsp_conb, made_up(P_s=lambda p, n, rc, td: 1.0 if n == 22 else 0.3), False),
    # ConB's mission time: a third of the others' / 0.58 of them
    (conb_mission_time, made_up(mission_time=lambda p, n, rc, td: 400.0 if p == "conb"
                                else 1200.0), True),
    (conb_mission_time, made_up(mission_time=lambda p, n, rc, td: 700.0 if p == "conb"
                                else 1200.0), False),
    # mTSP's immediate notification: lowest at 0.2 / tied with CovB / lowest but 0.05
    (mtsp_immediate_lowest, made_up(immediate=lambda p, n, rc, td: 0.2 if p == "mtsp" else 0.6),
     True),
    (mtsp_immediate_lowest, made_up(immediate=lambda p, n, rc, td: 0.2 if p in ("mtsp", "covb")
                                    else 0.6), False),
    (mtsp_immediate_lowest, made_up(immediate=lambda p, n, rc, td: 0.05 if p == "mtsp"
                                    else 0.6), False),
    # reachability: ConB best, mTSP worst / ConB no better than ConCov / mTSP not worst
    (reachability_order, made_up(reachability=lambda p, n, rc, td: {"conb": 0.5, "mtsp": 0.1}
                                 .get(p, 0.3)), True),
    (reachability_order, made_up(reachability=lambda p, n, rc, td: {"conb": 0.5, "mtsp": 0.1,
                                                                     "concov": 0.5}.get(p, 0.3)),
     False),
    (reachability_order, made_up(reachability=lambda p, n, rc, td: {"conb": 0.5, "covb": 0.1,
                                                                     "mtsp": 0.1}.get(p, 0.3)),
     False),
]


@pytest.mark.parametrize(("check", "table", "holds"), CASES,
                         ids=[f"{c.__name__}-{'holds' if h else 'fails'}" for c, _, h in CASES])
def test_finding_check_decides_from_the_table(check: Callable[[pd.DataFrame], Finding],
                                              table: pd.DataFrame, holds: bool) -> None:
    finding = check(table)
    assert finding.holds is holds
    assert finding.evidence
    assert bool(finding.instead) is not holds
    assert finding.criterion == inspect.getdoc(check)


def test_every_check_is_tested_both_ways() -> None:
    assert {(c.__name__, h) for c, _, h in CASES} == {(c.__name__, h) for c in CHECKS
                                                      for h in (True, False)}


def test_difference_interval_is_newcombes() -> None:
    # Newcombe (1998), Table II, example (a): 56/70 - 48/80 = 0.2, method 10: 0.0524 to 0.3339
    a, b = (_Estimate(k / n, *map(float, wilson(k, n))) for k, n in ((56, 70), (48, 80)))
    d = a.minus(b)
    assert d.value == pytest.approx(0.2)
    assert (d.lo, d.hi) == pytest.approx((0.0524, 0.3339), abs=5e-5)
