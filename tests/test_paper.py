"""The paper's reproduction: a quick end-to-end run, its report's numbers, and the claims.

The end-to-end run (10 runs per grid point) is shared by the smoke tests; every claim's check
is tested on made-up summary tables built so that it holds, is contradicted, or is undecided
because the intervals straddle its threshold.
"""

from __future__ import annotations

import importlib
import itertools
import json
import math
import os
import re
import shutil
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from sarlink import ConfigError, simulate
from sarlink.cli import app
from sarlink.config import READINGS, Experiment, Mission
from sarlink.engine.streams import plan_seed
from sarlink.execution import sweep_all
from sarlink.metrics import MEASURES, run_values, summarize, wilson
from sarlink.paper import ReproductionResult, check_all, load_runs, reproduce, tally
from sarlink.paper.evidence import Estimate, Outcome
from sarlink.paper.experiments import (
    DRONES,
    EXPERIMENTS,
    MOVING_DRONES,
    MOVING_FIG,
    MOVING_RC,
    PLAN_TIME_PLANNERS,
    RANGES,
    RELAY_PLANNER,
    RELAY_TDS,
    TD_LONG,
    mtsp_plans,
    plan_time_missions,
)
from sarlink.paper.figures import FIGURES, fig3
from sarlink.paper.findings import CLAIMS, Claim, fig1, section3
from sarlink.paper.report import write_report
from sarlink.planners import (
    PAPER_PLANNERS,
    RulePlanner,
    get_planner,
    planner_names,
    register_planner,
)
from sarlink.planners.patterns import PATTERNS
from sarlink.planners.rules.covb import COVB

# -- the end-to-end run --------------------------------------------------------------------------


@pytest.fixture(scope="module")
def quick(tmp_path_factory: pytest.TempPathFactory) -> ReproductionResult:
    """``reproduce --quick --runs 10`` of Figs. 1-11, with a short GA for Fig. 1's timing.
    Fig. 12 is left out: its sweep compiles eight kernels of its own (four rules, with a
    walking and with a drifting target), minutes of the suite for code that
    ``tests/test_paper_moving.py`` and the test of the moving sweep's still target below
    check without them; the presets are asked of Figs. 2-3 alone, below."""
    return reproduce(tmp_path_factory.mktemp("reproduction"), quick=True, runs=10,
                     progress=False, plan_iterations=100, figures=range(1, MOVING_FIG))


def test_every_figure_and_both_reports_exist(quick: ReproductionResult) -> None:
    out = quick.out
    for n in range(1, MOVING_FIG):  # the paper's seven, Figs. 8-11 beyond the paper
        for ext in ("png", "svg"):
            path = out / "figures" / f"fig{n}.{ext}"
            assert path.stat().st_size > 10_000, path
    assert sorted(quick.figures) == list(range(1, MOVING_FIG))
    assert quick.report_md == out / "report.md"
    page = quick.report_html.read_text()
    assert page.count("data:image/png;base64,") == MOVING_FIG - 1
    assert "Beyond the paper: drones that go and tell" in page
    assert "Beyond the paper: the search patterns SAR teams fly" in page
    assert "Beyond the paper: how many drones should hold the link?" in page
    assert "Beyond the paper: targets that move" not in page  # Fig. 12 not asked for
    assert not re.search(r"""(src|href)=["']?(https?:|//|figures/)""", page)  # self-contained
    for name in ("main", "curve", "miss", "shadowing", "plan_times", "report", "report_curve",
                 "others", "range_curve", "relays"):
        assert (out / "tables" / f"{name}.csv").exists()
        assert (out / "tables" / f"{name}.parquet").exists()


def test_the_report_links_a_replay_of_every_planner_at_rc_500(quick: ReproductionResult
                                                              ) -> None:
    assert quick.replay == quick.out / "replay-rc500.html"
    data = re.search(r'id="sarlink-data">(.*?)</script>', quick.replay.read_text(), re.S)
    assert data is not None
    panels = json.loads(data.group(1))["panels"]
    assert sorted(p["planner"] for p in panels) == sorted(PAPER_PLANNERS)
    assert all(p["rc"] == 500.0 and p["tNotify"] is not None for p in panels)
    assert "(replay-rc500.html)" in quick.report_md.read_text()
    assert 'href="replay-rc500.html"' in quick.report_html.read_text()


def test_stored_tables_equal_the_summaries_recomputed_from_the_runs(
        quick: ReproductionResult) -> None:
    runs = load_runs(quick.out, "main")
    assert len(runs) == 10 * len(PAPER_PLANNERS) * len(DRONES) * len(RANGES)
    recomputed = summarize(runs, td=[1000.0, 2000.0, 4000.0], by=["planner", "drones", "rc"])
    stored = pd.read_csv(quick.out / "tables" / "main.csv")
    cols = ["P_s", "P_s_lo", "immediate", "mission_time", "mission_time_se", "reachability"]
    np.testing.assert_allclose(stored[cols], recomputed[cols], rtol=1e-12)
    assert (stored["planner"] == recomputed["planner"]).all()
    pd.testing.assert_frame_equal(pd.read_parquet(quick.out / "tables" / "main.parquet"),
                                  recomputed)


def test_the_range_figure_agrees_with_the_flown_ranges(quick: ReproductionResult) -> None:
    """Fig. 10's P_s at a continuous range, evaluated from one flight per run, equals the main
    table's at the three ranges flown; the teams flown per range are not in it."""
    curve = pd.read_csv(quick.out / "tables" / "range_curve.csv")
    main = pd.read_csv(quick.out / "tables" / "main.csv")
    both = curve.merge(main, on=["planner", "drones", "rc", "td"], suffixes=("", "_main"))
    assert len(both) == len(curve[curve["rc"].isin(RANGES)]) > 0
    np.testing.assert_array_equal(both["P_s"], both["P_s_main"])
    assert set(curve["planner"]) == {"mtsp", "covb", "mtsp-conb"}
    assert set(curve[curve["planner"] == "mtsp-conb"]["drones"]) == {4}  # N_m <= N_r = 6
    assert curve.groupby(["planner", "drones", "td"])["P_s"].apply(
        lambda p: bool((np.diff(p.to_numpy()) >= 0).all())).all()  # more range, no less P_s


def test_the_quick_relay_sweep_flies_a_quarter_of_the_runs_and_its_tables_are_theirs(
        quick: ReproductionResult) -> None:
    """``--quick`` at 10 runs per point flies the first 3 of the relays' (a quarter, rounded
    up); the stored table is their summary, and the report compares them over those runs."""
    runs = load_runs(quick.out, "relays")
    assert sorted(set(runs["run"])) == [0, 1, 2]
    assert len(runs) == 3 * len(EXPERIMENTS["relays"].build(1).points())
    recomputed = summarize(runs, td=list(RELAY_TDS), by=["planner", "drones", "rc", "relays"])
    pd.testing.assert_frame_equal(pd.read_parquet(quick.out / "tables" / "relays.parquet"),
                                  recomputed)
    assert "over 3 runs per point, paired run by run" in quick.report_md.read_text()


def test_the_moving_sweep_flies_a_still_target_as_the_main_sweep() -> None:
    """A still target's points of Fig. 12's sweep are the main sweep's missions at
    N_m = 10, r_c = 500 m (but for their stop at notification and the target's group: the
    drift's forcing, and the delay) under the same seed, whatever
    the delay, which a still target ignores; so their runs are the main sweep's, run by run
    (flown here for CovB and mTSP, whose kernels need no compile of their own)."""
    moving, main = EXPERIMENTS["moving"].build(3), EXPERIMENTS["main"].build(3)
    assert moving.seed == main.seed
    mains = {(m.team.planner, m.team.drones, m.channel.rc): m for _, m in main.points()}
    stills = [m for _, m in moving.points() if m.target.motion == "still"]
    assert {m.team.planner for m in stills} >= set(PAPER_PLANNERS)
    for mission in stills:
        if mission.team.planner not in PAPER_PLANNERS:
            continue
        twin = mains[(mission.team.planner, MOVING_DRONES, MOVING_RC)]
        assert mission.model_copy(update={"target": twin.target, "timing": twin.timing}) == twin
        assert mission.timing.model_copy(update={"stop": twin.timing.stop}) == twin.timing
    for planner in ("covb", "mtsp"):
        twin = mains[(planner, MOVING_DRONES, MOVING_RC)]
        for mission in (m for m in stills if m.team.planner == planner):
            for run in range(3):
                assert (simulate(mission, seed=moving.seed, run=run).t_notify
                        == simulate(twin, seed=main.seed, run=run).t_notify)


def _report_table(md: str, heading: str) -> list[list[str]]:
    """The rows of the first table after ``heading`` in the Markdown report."""
    section = md[md.index(heading):]
    table = section[section.index("\n|"):].split("\n\n")[0]
    return [[c.strip() for c in line.strip("|").split("|")]
            for line in table.strip().splitlines()[2:]]


def test_report_numbers_equal_those_recomputed_from_the_stored_runs(
        quick: ReproductionResult) -> None:
    md = quick.report_md.read_text()
    main = summarize(load_runs(quick.out, "main"), td=[2000.0, 4000.0],
                     by=["planner", "drones", "rc"])
    labels = {"mTSP": "mtsp", "CovB": "covb", "ConB": "conb", "mTSP-ConB": "mtsp-conb",
              "ConCov": "concov"}

    fig3 = _report_table(md, "### Figure 3")
    assert len(fig3) == len(PAPER_PLANNERS) * len(DRONES) * len(RANGES)
    for rc, label, n, cell in fig3:
        row = main[(main["planner"] == labels[label]) & (main["drones"] == int(n))
                   & (main["rc"] == float(rc)) & (main["td"] == 2000.0)].iloc[0]
        assert cell == f"{row['P_s']:.3f} [{row['P_s_lo']:.3f}, {row['P_s_hi']:.3f}]"

    for rc, label, n, cell in _report_table(md, "### Figure 6"):
        row = main[(main["planner"] == labels[label]) & (main["drones"] == int(n))
                   & (main["rc"] == float(rc)) & (main["td"] == 4000.0)].iloc[0]
        assert cell == f"{row['reachability']:.3f} ± {row['reachability_se']:.3f}"

    miss = summarize(load_runs(quick.out, "miss"), by=["planner", "p_miss"])
    fig7a = _report_table(md, "### Figure 7")
    assert len(fig7a) == len(miss)
    for label, p_miss, cell in fig7a:
        row = miss[(miss["planner"] == labels[label])
                   & np.isclose(miss["p_miss"], float(p_miss))].iloc[0]
        assert cell == f"{row['P_d']:.3f} [{row['P_d_lo']:.3f}, {row['P_d_hi']:.3f}]"


def test_claims_are_those_of_the_recomputed_tables_and_the_report_says_so(
        quick: ReproductionResult) -> None:
    recomputed = run_values(load_runs(quick.out, "main"), [1000.0, 2000.0, 4000.0],
                            ["planner", "drones", "rc"])
    assert quick.findings == check_all({**quick.tables, "main_runs": recomputed})
    assert [f.claim for f in quick.findings] == [c.text for c in CLAIMS]  # every claim checked
    md = quick.report_md.read_text()
    assert f"{len(CLAIMS)} of the paper's claims checked: {tally(quick.findings)}." in md
    for f in quick.findings:
        assert f"#### {f.claim} — {f.outcome.value}" in md
        assert f"The paper, {f.section}: “{f.sentence}”" in md
    groups = [f"### {g}" for g in dict.fromkeys(c.figure for c in CLAIMS)]
    assert [line for line in md.splitlines() if line in groups] == groups


def test_the_report_gives_the_tally_under_every_preset(quick: ReproductionResult,
                                                       tmp_path: Path) -> None:
    """``--presets`` on Figs. 2-3, in a copy of the quick reproduction's runs (hard links:
    a sweep replaces a file, never writes into it), which the sweep under the default can
    reuse; the other presets' sweep is Figs. 2-3's alone."""
    shutil.copytree(quick.out / "runs", tmp_path / "runs", copy_function=os.link)
    again = reproduce(tmp_path, quick=True, runs=10, progress=False, figures=[2, 3],
                      presets=True)
    assert list(again.presets) == list(READINGS)
    assert again.presets[again.reading] == again.findings
    md = again.report_md.read_text()
    for name, found in again.presets.items():  # the claims Figs. 2-3 decide, under each
        assert [f.name for f in found] == [f.name for f in again.findings]
        assert re.search(rf"\| {re.escape(name)}( \(this report\))? \|.*\| "
                         rf"{re.escape(tally(found))} \|", md), name


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
    assert again.presets == {again.reading: again.findings}  # --quick leaves the presets out
    assert "tallied under this reading only" in again.report_md.read_text()


def test_cli_reports_where_the_report_is(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # the package's ``reproduce`` is the function; the module is found by its full name
    module = importlib.import_module("sarlink.paper.reproduce")
    monkeypatch.setattr(module, "plan_time_missions",
                        lambda iterations=None: plan_time_missions(100))
    result = CliRunner().invoke(app, ["reproduce", "--figures", "1", "--out", str(tmp_path),
                                      "--quiet"])
    assert result.exit_code == 0, result.output
    assert "report.html" in result.output
    fig1_claims = [c for c in CLAIMS if set(c.tables) <= {"plan_times"}]  # and the area's
    assert f"{len(fig1_claims)} of the paper's claims checked: " in result.output
    assert (tmp_path / "figures" / "fig1.png").exists()


@pytest.mark.parametrize(("args", "message"), [
    (["--figures", f"1,{max(FIGURES) + 1}"], "figures must be among"),  # one past the last
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


# -- the claims' checks on made-up tables ------------------------------------------------------

Rule = Callable[[str, int, float, float], float]
"""A made-up value of a measure at (planner, N_m, r_c, t_d)."""

SD = {"mission_time": 600.0, "search_share": 0.2, "reachability": 0.2}
"""Standard deviations of a run's value of each mean, for plausible standard errors."""


def _estimates(grid: pd.DataFrame, rules: dict[str, Rule], runs: int) -> pd.DataFrame:
    """``grid`` with each measure's rule applied to its rows: probabilities as counts out of
    ``runs`` with their Wilson intervals, means with the standard error of ``runs`` runs."""
    grid = grid.assign(runs=runs)
    keys = zip(*(grid[k] if k in grid else [None] * len(grid)
                 for k in ("planner", "drones", "rc", "td")), strict=True)
    points = list(keys)
    for name, rule in rules.items():
        values = np.array([rule(*point) for point in points], dtype=float)
        if MEASURES[name].probability:
            k = np.round(values * runs)
            lo, hi = wilson(k, runs)
            grid[name], grid[f"{name}_lo"], grid[f"{name}_hi"] = k / runs, lo, hi
            if name == "P_s":
                grid["notified"] = k.astype(int)
        else:
            grid[name], grid[f"{name}_se"] = values, SD[name] / math.sqrt(runs)
    return grid


def made_up(runs: int = 2000, **rules: Rule) -> pd.DataFrame:
    """A main summary table over the paper's grid, each measure given by a rule (defaults:
    P_s and immediate 0.5, mission time 1000 s, search share 0.7, reachability 0.3)."""
    rules = {"P_s": lambda *_: 0.5, "immediate": lambda *_: 0.5,
             "mission_time": lambda *_: 1000.0, "search_share": lambda *_: 0.7,
             "reachability": lambda *_: 0.3} | rules
    grid = pd.DataFrame(list(itertools.product(PAPER_PLANNERS, DRONES, RANGES,
                                               (1000.0, 2000.0, 4000.0))),
                        columns=["planner", "drones", "rc", "td"])
    return _estimates(grid, rules, runs)


JITTER = (1.0, 1.05, 1.1)
"""Three repeats of a plan timing, a few percent apart."""


def made_up_plan_times(seconds: Callable[[str, int], float],
                       jitter: Sequence[float] = JITTER) -> pd.DataFrame:
    return pd.DataFrame([{"planner": p, "drones": n, "rc": 500.0, "repeat": k,
                          "seconds": seconds(p, n) * j}
                         for p in PLAN_TIME_PLANNERS for n in DRONES
                         for k, j in enumerate(jitter)])


def _by_range(values: dict[float, float]) -> Rule:
    return lambda p, n, rc, td: values[rc]


def _by_planner(values: dict[str, float], other: float) -> Rule:
    return lambda p, n, rc, td: values.get(p, other)


HOLDS, CONTRADICTED, UNDECIDED = Outcome.HOLDS, Outcome.CONTRADICTED, Outcome.UNDECIDED


@dataclass(frozen=True)
class Case:
    claim: Claim
    tables: dict[str, pd.DataFrame]
    outcome: Outcome
    why: str


def _plan(seconds: dict[str, Callable[[int], float]], jitter: Sequence[float] = JITTER
          ) -> dict[str, pd.DataFrame]:
    return {"plan_times": made_up_plan_times(lambda p, n: seconds[p](n), jitter)}


def _main(**rules: Rule) -> dict[str, pd.DataFrame]:
    return {"main": made_up(**rules)}


_HYBRIDS = {"mtsp-conb": lambda n: 0.001 + 0.00015 * n, "concov": lambda n: 0.001 + 0.00015 * n}
_FAST = {"mtsp": lambda n: 0.2, "covb": lambda n: 0.001, "conb": lambda n: 0.003} | _HYBRIDS

CASES = [
    # Fig. 1
    Case(fig1.covb_plans_fastest, _plan(_FAST), HOLDS, "CovB a third of ConB's time"),
    Case(fig1.covb_plans_fastest, _plan(_FAST | {"conb": lambda n: 0.0005}), CONTRADICTED,
         "ConB twice as fast"),
    Case(fig1.covb_plans_fastest, _plan(_FAST | {"conb": lambda n: 0.001}), UNDECIDED,
         "ConB as fast, repeats scattered alike"),
    Case(fig1.mtsp_plan_time_flat, _plan(_FAST), HOLDS, "constant"),
    Case(fig1.mtsp_plan_time_flat, _plan(_FAST | {"mtsp": lambda n: 0.01 * n}),
         CONTRADICTED, "proportional to N_m"),
    Case(fig1.mtsp_plan_time_flat, _plan(_FAST, (0.25, 1.0, 4.0)), UNDECIDED,
         "constant, but repeats a factor 16 apart"),
    Case(fig1.conb_plan_time_grows, _plan(_FAST | {"conb": lambda n: 0.001 * n}), HOLDS,
         "proportional to N_m"),
    Case(fig1.conb_plan_time_grows, _plan(_FAST | {"conb": lambda n: 0.01 / n}),
         CONTRADICTED, "inversely proportional"),
    Case(fig1.conb_plan_time_grows, _plan(_FAST), UNDECIDED, "constant"),
    Case(fig1.hybrid_plan_times, _plan(_FAST | _HYBRIDS), HOLDS,
         "grow with N_m, like ConB's at 22 drones, 2.5 times CovB's"),
    Case(fig1.hybrid_plan_times, _plan(_FAST | {"conb": lambda n: 0.001 * n} | dict.fromkeys(
        _HYBRIDS, lambda n: 0.05 + 0.001 * n)), HOLDS,
         "26 times ConB's with 2 drones, 3.3 times with 22: approaching, though not within 2"),
    Case(fig1.hybrid_plan_times, _plan(_FAST | {"conb": lambda n: 0.001 * n} | dict.fromkeys(
        _HYBRIDS, lambda n: 0.001 * n * n)), CONTRADICTED,
         "as ConB's with 2 drones, 11 times with 22: moving away"),
    Case(fig1.hybrid_plan_times, _plan(_FAST | _HYBRIDS | {"concov": lambda n: 0.001}),
         CONTRADICTED, "ConCov as fast as CovB, flat"),
    Case(fig1.hybrid_plan_times, _plan(_FAST | _HYBRIDS | {
        "concov": lambda n: 0.0011 * n}, (0.1, 1.0, 10.0)), UNDECIDED,
         "repeats a factor 100 apart"),
    Case(section3.concov_plans_slower_than_covb, _plan(_FAST | _HYBRIDS), HOLDS, "slower"),
    Case(section3.concov_plans_slower_than_covb,
         _plan(_FAST | _HYBRIDS | {"concov": lambda n: 0.0005}), CONTRADICTED, "faster"),
    Case(section3.concov_plans_slower_than_covb,
         _plan(_FAST | _HYBRIDS | {"concov": lambda n: 0.001}), UNDECIDED, "as fast"),
]
"""Fig. 1's claims, on made-up timings (the claims on runs: tests/test_claims.py)."""


@pytest.mark.parametrize("case", CASES, ids=[f"{c.claim.name}-{c.outcome.name.lower()}-"
                                             f"{c.why.replace(' ', '_')}" for c in CASES])
def test_plan_time_claim_is_decided_from_the_timings(case: Case) -> None:
    finding = case.claim(case.tables)
    assert finding.outcome is case.outcome, [(p.outcome, p.text) for p in finding.parts]
    assert finding.criterion and finding.criterion in " ".join(
        (case.claim.check.__doc__ or "").split())


def test_fig1_values_list_the_work_counted_beside_the_time() -> None:
    """Fig. 1's table of values: the search expansions and GA evaluations of each planner and
    team size beside its times, "–" where a planner has no such part."""
    relaying = ["conb", "mtsp-conb", "concov"]
    times = made_up_plan_times(lambda p, n: 0.1).assign(
        expansions=lambda f: np.where(f["planner"].isin(relaying), 1000 * f["drones"], 0),
        evaluations=lambda f: np.where(f["planner"].isin(["mtsp", "mtsp-conb"]), 400_000, 0))
    (_, values), = FIGURES[1].values(times)
    cells = values.set_index(["planner", "N_m"])[["search expansions", "GA evaluations"]]
    assert cells.loc[("ConB", 22)].tolist() == ["22,000", "–"]
    assert cells.loc[("mTSP-ConB", 4)].tolist() == ["4,000", "400,000"]
    assert cells.loc[("mTSP", 10)].tolist() == ["–", "400,000"]
    assert cells.loc[("CovB", 2)].tolist() == ["–", "–"]


def test_every_plan_time_claim_is_tested_every_way() -> None:
    tested = {(c.claim.name, c.outcome) for c in CASES}
    expected = {(c.name, o) for c in CLAIMS if c.tables == ("plan_times",)
                for o in (HOLDS, CONTRADICTED, UNDECIDED)}
    assert tested == expected


def test_difference_interval_is_newcombes() -> None:
    # Newcombe (1998), Table II, example (a): 56/70 - 48/80 = 0.2, method 10: 0.0524 to 0.3339
    a, b = (Estimate(k / n, *map(float, wilson(k, n))) for k, n in ((56, 70), (48, 80)))
    d = a.minus(b)
    assert d.value == pytest.approx(0.2)
    assert (d.lo, d.hi) == pytest.approx((0.0524, 0.3339), abs=5e-5)


# -- the paper layer follows the planner registry ----------------------------------------------


MADE_UP = RulePlanner("made-up", "MadeUp", COVB, colour="#123456", marker="h")
"""A made-up planner: CovB's rule under another name, colour and marker."""


@pytest.mark.usefixtures("fresh_registries")
def test_the_paper_figures_fly_the_paper_planners_and_a_new_one_joins_beyond_the_paper() -> None:
    register_planner(MADE_UP)
    assert planner_names()[-1] == "made-up"
    others = set(planner_names()) - set(PAPER_PLANNERS)
    assert {p.name for p in PATTERNS} | {"made-up"} <= others
    for exp in EXPERIMENTS.values():
        experiment = exp.build(10)
        flown = {mission.team.planner for _, mission in experiment.points()}
        if exp.name == "others":
            assert flown == others
            assert experiment.grid["on_detect"] == ["continue", "report"]
        elif exp.name == "relays":
            assert flown == {RELAY_PLANNER}
        elif exp.name == "moving":
            assert flown == set(PAPER_PLANNERS) | others
        else:
            assert flown == set(PAPER_PLANNERS)

    table = pd.concat([made_up(), made_up().query("planner == 'covb'").assign(planner="made-up")])
    fig = fig3(table)
    legend = fig.legends[0]
    assert [t.get_text() for t in legend.get_texts()][-1] == "MadeUp"
    drawn = [line for ax in fig.axes for line in ax.get_lines() if line.get_label() == "MadeUp"]
    assert len(drawn) == len(RANGES)
    assert {(line.get_color(), line.get_marker()) for line in drawn} == {("#123456", "h")}
    (_, values), = FIGURES[3].values(table)
    assert (values["planner"] == "MadeUp").sum() == len(DRONES) * len(RANGES)


@pytest.mark.parametrize("name", ["report", "others", "relays"])
def test_the_sweeps_beyond_the_paper_stop_at_notification_and_their_figures_lose_nothing(
        name: str, tmp_path: Path) -> None:
    """Figs. 8, 9 and 11 read only measures settled at notification from these sweeps: their
    tables from runs stopped there equal those from runs flown to the horizon, but for the
    reachability, connected fraction and BS's network, which runs stopped before ``t_d`` do
    not have (NaN: never a wrong value)."""
    exp = EXPERIMENTS[name]
    built = exp.build(6)
    assert built.mission.timing.stop == "notified"
    grid = {**built.grid, "drones": [4], "rc": [500.0]}
    tables = [exp.tables(runs) for runs in sweep_all(
        [(Experiment(name=name, seed=built.seed, runs=6,
                     mission=built.mission.replace(stop=stop), grid=grid), tmp_path / stop)
         for stop in ("notified", "horizon")], workers=1, progress=False)]
    records = ("reach", "connected", "depth", "farthest")  # per run too: reach@1000, ...
    lost = [c for c in tables[0][name] if c.startswith(records)]
    kept = tables[0][name][lost].notna()
    assert lost and not kept.all().all() and tables[1][name][lost].notna().all().all()
    pd.testing.assert_frame_equal(tables[0][name][lost][kept], tables[1][name][lost][kept])
    for table in tables[0]:
        gone = [c for c in tables[0][table] if c.startswith(records)]
        pd.testing.assert_frame_equal(tables[0][table].drop(columns=gone),
                                      tables[1][table].drop(columns=gone))
    stopped = tables[0][name]
    assert (stopped["P_s"] < 1).any() and (stopped["P_s"] > 0).any()  # both kinds of run


def test_the_report_tabulates_the_bs_network_of_the_relaying_planners(tmp_path: Path) -> None:
    """The report's section "do chains form?": for ConB, mTSP-ConB and ConCov (not CovB, which
    relays nothing by design) at every t_d of the main table, the mean depth of the BS's
    component and distance of its farthest connected drone, as the summary of the runs has
    them."""
    mission = Mission.build(drones=10, rc=500.0, horizon=1000.0, iterations=100)
    experiment = Experiment(name="network", seed=3, runs=3, mission=mission,
                            grid={"planner": ["conb", "mtsp-conb", "concov", "covb"]})
    (runs,) = sweep_all([(experiment, tmp_path / "runs")], workers=1, progress=False)
    main = summarize(runs, td=[500.0, 1000.0], by=["planner", "drones", "rc"])
    md, _ = write_report(tmp_path, runs=3, quick=True, figures={}, tables={"main": main},
                         findings=[], stages=[], seconds=1.0, workers="this process")
    rows = _report_table(md.read_text(), "## The BS's network: do chains form?")
    labels = {get_planner(p).label: p for p in ("conb", "mtsp-conb", "concov")}
    assert sorted((label, td) for _, label, _, td, _, _ in rows) == sorted(
        (label, td) for label in labels for td in ("500", "1000"))
    for rc, label, n, td, depth, farthest in rows:
        row = main[(main["planner"] == labels[label]) & (main["td"] == float(td))].iloc[0]
        assert (rc, n) == ("500", "10")
        assert depth == MEASURES["depth"].text(row) != "–"
        assert farthest == MEASURES["farthest"].text(row) != "–"


def test_fig9_draws_the_other_planners_solid_beside_the_paper_planners_dashed() -> None:
    paper = made_up()
    others = pd.concat([made_up().query("planner == 'covb'").assign(planner=p.name,
                                                                     on_detect=mode)
                        for p in PATTERNS for mode in ("continue", "report")])
    fig = FIGURES[9].draw(paper, paper, others)
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert labels == [p.label for p in PATTERNS] + [get_planner(p).label for p in PAPER_PLANNERS]
    for pattern in PATTERNS:
        lines = [line for ax in fig.axes for line in ax.get_lines()
                 if line.get_color() == pattern.colour]
        assert len(lines) == 2 * len(RANGES)  # both ways, every range
        assert {(line.get_marker(), line.get_linestyle()) for line in lines} == {
            (pattern.marker, "-")}
    dashed = [line for ax in fig.axes for line in ax.get_lines() if line.get_linestyle() == "--"]
    assert len(dashed) == len(PAPER_PLANNERS) * 2 * len(RANGES)
    (_, values), = FIGURES[9].values(paper, paper, others)
    assert len(values) == (len(PAPER_PLANNERS) + len(PATTERNS)) * 2 * len(RANGES) * len(DRONES) * 2


def _longest_flight(routes: tuple[np.ndarray, ...], bs: tuple[float, float],
                    speed: float) -> float:
    """The longest route's flight time, from the BS through its waypoints."""
    return max(float(np.hypot(*np.diff(np.vstack([bs, r]), axis=0).T).sum()) for r in routes
               ) / speed


def test_the_plan_table_describes_the_plans_the_runs_fly() -> None:
    """Under per-run plans, the 2-drone row summarises the runs' own routes (measured here
    from their waypoints); under shared plans, the one plan of the mission's seed."""
    mission = Mission.build(planner="mtsp", drones=2, horizon=TD_LONG)
    runs = pd.DataFrame({"planner": "mtsp", "drones": 2, "seed": 7, "run": [0, 1, 2],
                         "mtsp_plan": "per-run"})
    row = mtsp_plans(runs).set_index("drones").loc[2]
    mtsp = get_planner("mtsp")
    flights = [_longest_flight(mtsp.steering(mission.replace(plan_seed=plan_seed(7, k))).routes,
                               mission.area.bs_xy, mission.team.speed) for k in range(3)]
    assert row["plans"] == 3 and row["cells"] == 64
    assert row["longest_min_s"] == pytest.approx(min(flights), rel=1e-9)
    assert row["longest_max_s"] == pytest.approx(max(flights), rel=1e-9)
    assert row["longest_s"] == pytest.approx(np.mean(flights), rel=1e-9)
    shared = mtsp_plans(runs.assign(mtsp_plan="shared")).set_index("drones").loc[2]
    one = _longest_flight(mtsp.steering(mission.replace(mtsp_plan="shared")).routes,
                          mission.area.bs_xy, mission.team.speed)
    assert shared["plans"] == 1 and shared["longest_s"] == pytest.approx(one, rel=1e-9)
