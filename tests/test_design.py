"""``sarlink design`` on cases whose answer is known, against a brute-force sweep, and resumed.

The cases are kept small (a 2 km area, short t_d, few drones) so that each takes seconds.
"""

from __future__ import annotations

import json
import math
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from sarlink import ConfigError, Experiment, Mission, load, sweep
from sarlink.cli import app
from sarlink.config import mission_hash
from sarlink.design import Decision, DesignAnswer, DesignRequest, design
from sarlink.design.sequential import worse
from sarlink.metrics import summarize

SMALL = Mission.build(reading="sarlink-2", size=2000.0, rc=500.0)
"""The small setting the expectations below were measured on, under the reading of then."""
PAPER = {"on_detect": ["continue"]}
"""The paper's behaviour only: one variant per planner (the default also tries reporting)."""


def small(**fields: Any) -> DesignRequest:
    return DesignRequest(**{"mission": SMALL, "max_drones": 5, "candidate_runs": 1600,
                            "options": PAPER, "every_planner": True, **fields})


def candidate_runs(out: Path, answer: DesignAnswer) -> pd.DataFrame:
    """Every run the design stored, read back with the sweep layer's own reader."""
    folders = sorted((out / f"seed-{answer.request.seed}").iterdir())
    return pd.concat([load(f) for f in folders], ignore_index=True)


# -- answers known without simulation ----------------------------------------------------------


def test_a_requirement_no_team_can_reach_is_not_reachable(tmp_path: Path) -> None:
    """In t_d = 100 s a drone flies 500 m from the BS and senses 500 m around it, so no team
    detects a target farther than 1000 m from the BS: P_s <= π 1000² / 4000² < 0.2."""
    request = DesignRequest(td=100.0, ps=0.5, max_drones=4)
    answer = design(request, tmp_path, progress=False)
    assert answer.recommendation is None
    assert answer.ended_by == "statistics"
    for planner in answer.planners:
        assert planner.status == "not reachable"
        assert planner.smallest is None and planner.undecided == ()
        assert [s.drones for s in planner.team_sizes] == [1, 2, 3, 4]
        assert all(s.verdict is Decision.FAILS for s in planner.team_sizes)
    bound = math.pi * 1000.0**2 / 4000.0**2
    runs = candidate_runs(tmp_path, answer)
    far = np.hypot(runs["target_x"] - 2000.0, runs["target_y"] - 2000.0) > 1000.0
    assert not (runs["t_notify"] <= 100.0)[far].any()
    assert (runs["t_notify"] <= 100.0).mean() < bound


def test_with_single_hop_range_success_is_detection(tmp_path: Path) -> None:
    """r_c >= 2829 m reaches the BS from anywhere in the 4 km area: notified = detected."""
    request = DesignRequest(mission=Mission.build(rc=2829.0), td=800.0, ps=0.5,
                            planners=("covb", "conb"), max_drones=6, options=PAPER)
    answer = design(request, tmp_path, progress=False)
    runs = candidate_runs(tmp_path, answer)
    assert len(runs) > 0
    np.testing.assert_array_equal(runs["t_notify"].to_numpy(), runs["t_detect"].to_numpy())
    table = summarize(runs, td=800.0, by=["planner", "drones"])
    np.testing.assert_array_equal(table["P_s"], table["P_d"])
    for planner in answer.planners:
        for size in planner.team_sizes:
            row = table[(table["planner"] == planner.planner)
                        & (table["drones"] == size.drones)].iloc[0]
            assert size.best.runs == row["runs"]
            assert size.best.successes == row["detected"]


def test_mtsp_with_two_drones_always_succeeds_by_the_flight_budget(tmp_path: Path) -> None:
    """The paper: at t_d = 4000 s mTSP finishes the search with 2 drones, so P_s = 1."""
    request = DesignRequest(td=4000.0, ps=0.95, planners=("mtsp",), max_drones=3,
                            options=PAPER)
    answer = design(request, tmp_path, progress=False)
    (mtsp,) = answer.planners
    assert mtsp.status == "reached" and mtsp.smallest == 2
    assert mtsp.chosen is not None and mtsp.chosen.successes == mtsp.chosen.runs
    assert mtsp.team_sizes[0].drones == 1 and mtsp.team_sizes[0].verdict is Decision.FAILS


# -- the adaptive answer against a brute-force sweep ---------------------------------------------

BRUTE_RUNS = 1000
REQUIRED = 0.78


@pytest.fixture(scope="module")
def brute_force(tmp_path_factory: pytest.TempPathFactory) -> pd.DataFrame:
    """Every ConCov candidate of the grid with many runs (alpha = 1 flies exactly as CovB)."""
    mission = SMALL.replace(planner="concov", horizon=600.0, stop="notified")
    experiment = Experiment(name="brute force", seed=2024, runs=BRUTE_RUNS, mission=mission,
                            grid={"drones": [1, 2, 3, 4, 5], "alpha": [0.0, 0.5, 1.0]})
    return sweep(experiment, tmp_path_factory.mktemp("brute"), progress=False)


@pytest.fixture(scope="module")
def adaptive(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, DesignAnswer]:
    out = tmp_path_factory.mktemp("adaptive")
    request = small(td=600.0, ps=REQUIRED, planners=("covb", "concov"), alpha_step=0.5,
                    alpha_tol=0.5)
    return out, design(request, out, progress=False)


def test_the_adaptive_answer_is_the_brute_force_answer(
        brute_force: pd.DataFrame, adaptive: tuple[Path, DesignAnswer]) -> None:
    table = summarize(brute_force, td=600.0, by=["drones", "alpha"])
    best = table.groupby("drones")["P_s"].max()
    # the brute force decides clearly: the team below the smallest is well short of it
    smallest = int(table[table["P_s_lo"] >= REQUIRED]["drones"].min())
    below = table[table["drones"] == smallest - 1]
    assert (below["P_s_hi"] < REQUIRED).all()
    covb = table[table["alpha"] == 1.0].set_index("drones")
    covb_smallest = int(covb.index[covb["P_s_lo"] >= REQUIRED].min())
    assert covb.loc[covb_smallest - 1, "P_s_hi"] < REQUIRED

    _, answer = adaptive
    by_planner = {p.planner: p for p in answer.planners}
    assert by_planner["concov"].smallest == smallest
    assert by_planner["covb"].smallest == covb_smallest
    assert answer.recommendation is not None and answer.recommendation.smallest == smallest

    # the same best alpha: the brute force's best is among those the design could not tell
    # from its best, and the design's best is not significantly worse than the brute force's
    tuning = by_planner["concov"].tuning
    assert tuning is not None
    at = brute_force[brute_force["drones"] == smallest]
    success = {a: (g.sort_values("run")["t_notify"] <= 600.0).to_numpy()
               for a, g in at.groupby("alpha")}
    brute_best = float(best.loc[smallest])
    brute_alpha = max(success, key=lambda a: (success[a].mean(), -a))
    assert success[brute_alpha].mean() == brute_best
    assert brute_alpha in tuning.equivalent
    assert not worse(success[float(tuning.best.value or 0)], success[brute_alpha], 0.05)
    assert answer.runs_used < 0.5 * BRUTE_RUNS * answer.grid_points


def test_a_design_started_again_reuses_every_run(
        tmp_path: Path, adaptive: tuple[Path, DesignAnswer]) -> None:
    """Cut short by its budget, then run again with the full budget: the same answer as the
    uninterrupted design, and no run simulated twice."""
    _, full = adaptive
    cut = design(full.request.model_copy(update={"max_runs": full.runs_used // 3}), tmp_path,
                 progress=False)
    assert cut.ended_by == "budget" and cut.runs_used <= full.runs_used // 3
    again = design(full.request, tmp_path, progress=False)
    assert again.to_json()["planners"] == full.to_json()["planners"]
    assert cut.runs_simulated + again.runs_simulated == full.runs_used
    assert design(full.request, tmp_path, progress=False).runs_simulated == 0


def test_each_candidate_folder_is_a_sweep_of_its_mission(
        adaptive: tuple[Path, DesignAnswer]) -> None:
    out, answer = adaptive
    concov = next(p for p in answer.planners if p.planner == "concov")
    assert concov.chosen is not None
    mission = (SMALL.replace(planner="concov", drones=concov.chosen.drones,
                             alpha=concov.chosen.value, horizon=600.0, stop="notified"))
    runs = load(out / "seed-2024" / mission_hash(mission))
    assert len(runs) == concov.chosen.runs
    assert int((runs["t_notify"] <= 600.0).sum()) == concov.chosen.successes


# -- the same answer on any machine ------------------------------------------------------------


def test_the_answer_is_the_same_with_one_and_two_workers(tmp_path: Path) -> None:
    """And with both cores busy: two processes spinning beside the design's workers."""
    request = DesignRequest(mission=SMALL, td=600.0, ps=0.6, planners=("covb",),
                            options=PAPER, max_drones=3, candidate_runs=200)
    one = design(request, tmp_path / "one", workers=1, progress=False)
    two = design(request, tmp_path / "two", workers=2, progress=False)
    assert one.runs_simulated == two.runs_simulated == one.runs_used > 0
    assert one.to_json() == two.to_json()
    spinners = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(2)]
    try:
        busy = design(request, tmp_path / "busy", workers=2, progress=False)
    finally:
        for spinner in spinners:
            spinner.kill()
            spinner.wait()
    assert busy.to_json() == one.to_json()


def test_a_time_budget_stops_between_rounds_at_the_answer_of_those_runs(
        tmp_path: Path) -> None:
    """``max_seconds = 0`` stops after the first round: its answer is that of a run budget
    of exactly those runs (stored and reused, so none is simulated again)."""
    request = DesignRequest(mission=SMALL, td=600.0, ps=0.6, planners=("covb",),
                            options=PAPER, max_drones=3, candidate_runs=200)
    timed = design(request, tmp_path, progress=False, max_seconds=0.0)
    assert timed.ended_by == "time"
    assert timed.runs_used == request.first_runs * len(timed.planners[0].team_sizes)
    budget = design(request.model_copy(update={"max_runs": timed.runs_used}), tmp_path,
                    progress=False)
    assert budget.ended_by == "budget" and budget.runs_simulated == 0
    assert budget.to_json()["planners"] == timed.to_json()["planners"]


# -- options and bad requests --------------------------------------------------------------------


def test_the_default_tries_every_planner_with_and_without_reporting() -> None:
    variants = DesignRequest(td=600.0, ps=0.5, planners=("covb", "mtsp")).variants()
    assert sorted((v.planner, v.params()["on_detect"]) for v in variants) == [
        ("covb", "continue"), ("covb", "report"), ("mtsp", "continue"), ("mtsp", "report")]


def test_options_make_variants_of_every_planner() -> None:
    request = DesignRequest(td=600.0, ps=0.5, planners=("covb", "concov"),
                            options={"look": ["per-pass", "per-period"], "alpha": [0.3]})
    variants = request.variants()
    assert [v.label for v in variants] == [
        "CovB (look=per-pass, alpha=0.3)", "CovB (look=per-period, alpha=0.3)",
        "ConCov (look=per-pass, alpha=0.3)", "ConCov (look=per-period, alpha=0.3)"]
    assert all(v.setting is None for v in variants)  # alpha is fixed by the option
    assert DesignRequest(td=600.0, ps=0.5, planners=("concov",)).variants()[0].setting


@pytest.mark.parametrize(("fields", "message"), [
    ({"ps": 1.0}, "ps: Input should be less than 1"),
    ({"ps": 0.0}, "ps: Input should be greater than 0"),
    ({"planners": ()}, "planners: name at least one planner"),
    ({"planners": ("fast",)}, "unknown planner 'fast'"),
    ({"max_drones": 0}, "max_drones: Input should be greater than or equal to 1"),
    ({"td": 5000.0}, "td: 5000 s is beyond the mission's horizon of 4000 s"),
    ({"td": 600.5}, "td: 600.5 s does not fit the mission"),
    ({"options": {"drones": [2]}}, "'drones' is set by the design itself"),
    ({"options": {"p_miss": [2.0]}}, "sensing.p_miss"),
])
def test_bad_requests_name_the_field(fields: dict[str, Any], message: str) -> None:
    with pytest.raises(ConfigError, match=message):
        DesignRequest.from_dict({"td": 600.0, "ps": 0.9, **fields})


@pytest.mark.parametrize(("args", "message"), [
    (["--ps", "1.5"], "--ps: Input should be less than 1 (got 1.5)"),
    (["--ps", "0"], "--ps: Input should be greater than 0 (got 0.0)"),
    (["--planner", "fast"], "--planner: unknown planner 'fast'"),
    (["--max-drones", "0"], "--max-drones: Input should be greater than or equal to 1 (got 0)"),
    (["--td", "5000"], "--td: 5000 s is beyond the mission's horizon of 4000 s"),
    (["--option", "look"], "--option: expected NAME=VALUE[,VALUE...], got 'look'"),
    (["--rc", "-1"], "--rc (channel.rc): Input should be greater than 0"),
])
def test_cli_errors_are_one_line_naming_the_option(tmp_path: Path, args: list[str],
                                                   message: str) -> None:
    base = {"--td": "600", "--ps": "0.9"}
    for flag, value in zip(args[::2], args[1::2], strict=True):
        base[flag] = value
    argv = ["design", *[x for kv in base.items() for x in kv], "--out", str(tmp_path)]
    result = CliRunner().invoke(app, argv)
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and message in lines[0] and "Traceback" not in result.output


def test_cli_prints_json_and_draws_the_figure(tmp_path: Path) -> None:
    figure = tmp_path / "design.png"
    result = CliRunner().invoke(app, [
        "design", "--size", "2000", "--rc", "500", "--td", "600", "--ps", "0.6",
        "--planner", "covb", "--planner", "concov", "--alpha-step", "0.5", "--alpha-tol", "0.5",
        "--max-drones", "3", "--option", "on_detect=continue", "--out", str(tmp_path / "runs"),
        "--every-planner", "--json", "--plot", str(figure)])
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert data["recommendation"]["smallest"] in (1, 2, 3)  # a size within --max-drones
    assert data["runs"]["used"] == data["runs"]["simulated"] > 0
    assert [p["planner"] for p in data["planners"]] == ["covb", "concov"]
    assert data["planners"][1]["tuning"]["setting"] == "alpha"
    assert figure.stat().st_size > 10_000


def test_a_killed_design_resumes_to_the_same_answer(
        tmp_path: Path, adaptive: tuple[Path, DesignAnswer]) -> None:
    """SIGKILL in the middle of a design: every finished chunk is kept and the rerun gives the
    uninterrupted answer without simulating them again."""
    _, full = adaptive
    argv = [sys.executable, "-c", "from sarlink.cli import app; app()", "design",
            "--size", "2000", "--rc", "500", "--td", "600", "--ps", str(REQUIRED),
            "--reading", "sarlink-2",  # SMALL's reading
            "--planner", "covb", "--planner", "concov",
            "--alpha-step", "0.5", "--alpha-tol", "0.5", "--max-drones", "5",
            "--candidate-runs", "1600", "--option", "on_detect=continue", "--workers", "1",
            "--every-planner", "--out", str(tmp_path), "--quiet"]
    process = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while len(list(tmp_path.glob("seed-2024/*/points/*/runs-*.parquet"))) < 5:
        assert process.poll() is None and time.monotonic() < deadline
        time.sleep(0.02)
    process.send_signal(signal.SIGKILL)
    process.wait()
    stored = sum(len(load(f)) for f in (tmp_path / "seed-2024").iterdir()
                 if (f / "experiment.json").exists())
    assert 0 < stored < full.runs_used
    again = design(full.request, tmp_path, progress=False)
    assert again.to_json()["planners"] == full.to_json()["planners"]
    assert again.runs_simulated == full.runs_used - stored


def test_sarlink_design_and_at_range_stay_the_functions_beside_their_modules() -> None:
    """Importing ``sarlink.design`` or ``sarlink.at_range`` (the modules) would bind the
    package's names to them; ``sarlink.design(...)`` still calls the function."""
    import sarlink
    import sarlink.at_range
    import sarlink.design.answer
    from sarlink.at_range import at_range

    assert sarlink.design is design and sarlink.at_range is at_range
    assert type(sys.modules["sarlink.design"]).__name__ == "module"  # still importable
