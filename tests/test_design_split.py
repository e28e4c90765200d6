"""``sarlink design`` with relays: the split tuned as a setting, fixed relay counts, and the
error shares of the Bonferroni accounting.

The missions are small (a 2 km area, t_d = 600 s, CovB, at most 4 drones): every run with
relays re-plans them every t_s, and each kernel (CovB with and without relays) compiles once
per session.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from sarlink import ConfigError, Mission, load
from sarlink.cli import app
from sarlink.config import mission_hash
from sarlink.design import Decision, DesignAnswer, DesignRequest, PlannerVariant, design
from sarlink.design.candidates import RELAYS, SETTINGS
from sarlink.design.search import errors
from sarlink.design.sequential import lower_bound, upper_bound

BASE = Mission.build(size=2000.0, rc=500.0)
"""The mission of ``sarlink design --size 2000 --rc 500``."""
PAPER = {"on_detect": ["continue"]}
TD, PS, LARGEST = 600.0, 0.7, 4


def request(**fields: Any) -> DesignRequest:
    return DesignRequest(**{"mission": BASE, "td": TD, "ps": PS, "planners": ("covb",),
                            "options": PAPER, "max_drones": LARGEST, "candidate_runs": 800,
                            **fields})


def flown(answer: DesignAnswer, drones: int, **params: Any) -> Mission:
    """The mission a candidate of ``answer`` flew (the design's horizon and stop)."""
    return answer.request.base().replace(planner="covb", drones=drones, on_detect="continue",
                                         **params)


# -- the counts: settings per team size and the error each decision is judged at ----------------


def test_the_split_tries_every_relay_count_but_the_team() -> None:
    """0 relays (all search) to N - 1 (one searcher): N settings; mTSP-ConB's N_r keeps 1..N."""
    for n in range(1, 8):
        assert RELAYS.grid(n, 0.1) == tuple(range(n))
        assert RELAYS.size(n, 0.1, 0.025) == n
        assert SETTINGS["mtsp-conb"].grid(n, 0.1) == tuple(range(1, n + 1))


@pytest.mark.parametrize(("planner", "fields", "drones", "settings"), [
    ("covb", {}, 5, 1),                                    # no setting
    ("covb", {"split": True}, 5, 5),                       # relays 0..4
    ("concov", {}, 5, 11 + 2 * 2),                         # alpha every 0.1, refined twice
    ("concov", {"split": True}, 5, 5),                     # alpha held: the relays alone
    ("mtsp-conb", {}, 5, 5),                               # N_r = 1..5
    ("mtsp-conb", {"options": {"relays": [2]}}, 5, 3),     # N_r of the 3 searchers
    ("mtsp-conb", {"mission": BASE.replace(relays=1)}, 5, 4),
])
def test_each_decision_is_judged_at_its_bonferroni_share(
        planner: str, fields: dict[str, Any], drones: int, settings: int) -> None:
    """With K looks and G settings at a size: meets at δ/(K·G), fails at δ/K, a setting
    dropped from the race at δ/(K·(G-1))."""
    r = DesignRequest(**{"td": TD, "ps": PS, "planners": (planner,), "options": {},
                         "max_drones": 8, **fields})
    (variant,) = r.variants()
    looks = len(r.schedule().looks)
    e = errors(r, variant, drones)
    assert e.settings == settings
    assert e.meets == pytest.approx(0.025 / (looks * settings))
    assert e.fails == pytest.approx(0.025 / looks)
    assert e.drops == pytest.approx(0.025 / (looks * max(settings - 1, 1)))


def test_fixed_relays_start_the_team_sizes_at_one_searcher_beside_them() -> None:
    """A team of N with N or more relays has no searcher: not a candidate, not undecided."""
    r = request(options={**PAPER, "relays": [0, 2]})
    assert [(v.label, list(r.sizes(v))) for v in r.variants()] == [
        ("CovB (on_detect=continue, relays=0)", [1, 2, 3, 4]),
        ("CovB (on_detect=continue, relays=2)", [3, 4])]
    configured = request(mission=BASE.replace(relays=1), min_drones=1)
    assert [list(configured.sizes(v)) for v in configured.variants()] == [[2, 3, 4]]
    split = request(mission=BASE.replace(relays=3), split=True)  # the split replaces it
    assert [list(split.sizes(v)) for v in split.variants()] == [[1, 2, 3, 4]]
    assert list(request(min_drones=3).sizes(request().variants()[0])) == [3, 4]


@pytest.mark.parametrize(("fields", "message"), [
    ({"split": True, "options": {"relays": [1]}},
     "split: tunes the relay count, which options fix"),
    ({"split": True, "max_drones": 1}, "split: a team of one drone has no split"),
    ({"options": {"relays": [4]}}, r"options: CovB \(relays=4\): .*allowed: 0 to 3"),
    ({"mission": BASE.replace(relays=4)},
     "max_drones: 4 drones leave no searcher beside the mission's team.relays = 4"),
    ({"min_drones": 5}, r"min_drones: 5 exceeds max_drones \(4\)"),
])
def test_bad_split_requests_name_the_field(fields: dict[str, Any], message: str) -> None:
    with pytest.raises(ConfigError, match=message):
        DesignRequest.from_dict({"mission": BASE, "td": TD, "ps": PS, "planners": ["covb"],
                                 "max_drones": LARGEST, **fields})


def test_the_held_setting_is_reported_without_a_run(tmp_path: Path) -> None:
    """A budget of one run stops the design before its first look: nothing is decided, and
    ConCov's alpha is still reported as held at the mission's value."""
    answer = design(request(planners=("concov",), split=True, max_runs=1,
                            mission=BASE.replace(alpha=0.3)), tmp_path, progress=False)
    (concov,) = answer.planners
    assert concov.held == {"alpha": 0.3} and concov.tuning is None
    assert concov.status == "undecided" and concov.undecided == (1, 2, 3, 4)
    assert answer.ended_by == "budget" and answer.runs_simulated == 0
    assert PlannerVariant("concov").own == SETTINGS["concov"]
    assert PlannerVariant("concov", split=True).setting == RELAYS


# -- designs that fly relays ----------------------------------------------------------------------


@pytest.fixture(scope="module")
def split(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, DesignAnswer]:
    out = tmp_path_factory.mktemp("split")
    return out, design(request(split=True, every_planner=True), out, progress=False)


def test_the_split_is_tuned_at_the_smallest_team(split: tuple[Path, DesignAnswer]) -> None:
    out, answer = split
    (covb,) = answer.planners
    assert covb.status == "reached" and covb.smallest is not None and covb.chosen is not None
    assert covb.held == {}  # CovB has no setting of its own
    tuning = covb.tuning
    assert tuning is not None and tuning.setting == "relays"
    # every relay count of the smallest team was tried, and each flew that many relays
    assert [e.value for e in tuning.curve] == list(range(covb.smallest))
    for e in tuning.curve:
        assert e.relays == e.value and e.drones == covb.smallest
        runs = load(out / f"seed-{answer.request.seed}" /
                    mission_hash(flown(answer, e.drones, relays=e.relays)))
        assert len(runs) == e.runs
        assert int((runs["t_notify"] <= TD).sum()) == e.successes
    assert covb.chosen == tuning.best and covb.chosen.relays in tuning.equivalent
    assert covb.chosen.searchers == covb.chosen.drones - covb.chosen.relays
    # a full grid: every relay count of every team size
    assert answer.grid_points == sum(range(1, LARGEST + 1))


def test_each_size_of_the_split_is_judged_over_its_relay_counts(
        split: tuple[Path, DesignAnswer]) -> None:
    """Recomputed from the counts: a relay count of N drones meets when its exact lower bound
    at δ/(K·N) reaches P_s, fails when its upper bound at δ/K is below it."""
    _, answer = split
    (covb,) = answer.planners
    assert covb.tuning is not None
    looks = len(answer.request.schedule().looks)
    assert all(s.settings == s.drones for s in covb.team_sizes)
    failed = [s.best for s in covb.team_sizes if s.verdict is Decision.FAILS]
    assert failed  # the smallest sizes fail: the check below is not empty
    meets = [e for e in covb.tuning.curve if e.verdict is Decision.MEETS]
    assert meets
    for e in meets:
        assert lower_bound(e.successes, e.runs, 0.025 / (looks * e.drones)) >= PS
    for e in failed + [e for e in covb.tuning.curve if e.verdict is Decision.FAILS]:
        assert upper_bound(e.successes, e.runs, 0.025 / looks) < PS


def test_fixed_relay_counts_skip_the_teams_they_leave_without_a_searcher(
        tmp_path: Path) -> None:
    answer = design(request(options={**PAPER, "relays": [0, 2]}, max_drones=3), tmp_path,
                    progress=False)
    none, two = answer.planners
    assert two.fixed == {"on_detect": "continue", "relays": 2}
    assert [s.drones for s in two.team_sizes][:1] == [3]  # 1 and 2 drones are no team
    assert all(n >= 3 for n in two.undecided)
    assert all(s.best.relays == 2 for s in two.team_sizes)
    assert all(s.best.relays == 0 for s in none.team_sizes)
    assert answer.grid_points == 3 + 1


# -- the command line -----------------------------------------------------------------------------


def test_the_cli_prints_the_split(split: tuple[Path, DesignAnswer]) -> None:
    """The same request from the command line: it reuses the runs and prints the split."""
    out, answer = split
    (covb,) = answer.planners
    assert covb.chosen is not None
    result = CliRunner().invoke(app, [
        "design", "--size", "2000", "--rc", "500", "--td", str(TD), "--ps", str(PS),
        "--planner", "covb", "--option", "on_detect=continue", "--max-drones", str(LARGEST),
        "--candidate-runs", "800", "--split", "--every-planner", "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    text = " ".join(result.output.split())
    chosen = covb.chosen
    relays = f"{chosen.relays} relay{'' if chosen.relays == 1 else 's'}"
    assert (f"Recommendation: CovB (on_detect=continue) with {chosen.drones} drones "
            f"({chosen.searchers} searching, {relays})") in text
    assert f"{chosen.searchers} + {chosen.relays}" in text
    assert f"at {covb.smallest} drones: P_s against relays" in text
    assert f"Runs: {answer.runs_used:,} used (0 simulated now" in text


def test_a_configured_relay_count_flies_from_the_cli(tmp_path: Path) -> None:
    """``team.relays`` in --config: the teams start at one searcher beside the relays."""
    config = tmp_path / "mission.toml"
    config.write_text("[area]\nsize = 2000.0\n[channel]\nrc = 500.0\n[team]\nrelays = 1\n")
    result = CliRunner().invoke(app, [
        "design", "--config", str(config), "--td", str(TD), "--ps", str(PS),
        "--planner", "covb", "--option", "on_detect=continue", "--max-drones", "3",
        "--candidate-runs", "200", "--out", str(tmp_path / "runs"), "--json"])
    assert result.exit_code == 0, result.output
    (covb,) = json.loads(result.output)["planners"]
    assert [s["drones"] for s in covb["team_sizes"]][:1] == [2]
    assert all(s["best"]["relays"] == 1 for s in covb["team_sizes"])


@pytest.mark.parametrize(("args", "message"), [
    (["--rc", "500", "--split", "--option", "relays=1"],
     "--split: tunes the relay count, which options fix (relays = 1)"),
    (["--rc", "500", "--split", "--max-drones", "1"], "--split: a team of one drone"),
    (["--split"], "--split needs --rc"),
    (["--min-drones", "2"], "--min-drones applies with --rc only"),
    (["--rc", "500", "--min-drones", "5", "--max-drones", "4"],
     "--min-drones: 5 exceeds max_drones (4)"),
])
def test_cli_split_errors_are_one_line(tmp_path: Path, args: list[str], message: str) -> None:
    result = CliRunner().invoke(app, ["design", "--td", "600", "--ps", "0.9", *args,
                                      "--out", str(tmp_path)])
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and message in lines[0] and "Traceback" not in result.output


def test_the_range_design_refuses_configured_relays(tmp_path: Path) -> None:
    config = tmp_path / "mission.toml"
    config.write_text("[team]\nrelays = 2\n")
    result = CliRunner().invoke(app, ["design", "--config", str(config), "--td", "600",
                                      "--ps", "0.9", "--out", str(tmp_path)])
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and "team.relays = 2 needs --rc" in lines[0]
