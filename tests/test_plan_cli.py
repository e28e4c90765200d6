"""``sarlink plan``, driven through Typer as a user would."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

import sarlink.mtsp as mtsp
import sarlink.mtsp.cache as plan_cache
from sarlink import Mission
from sarlink.cli.plan import plan

app = typer.Typer()
app.command()(plan)


@app.callback()
def main() -> None:
    """Stands in for the sarlink app, so that ``plan`` is a subcommand."""


runner = CliRunner()
FAST = ["--iterations", "200"]


@pytest.fixture(autouse=True)
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    monkeypatch.setenv("SARLINK_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(plan_cache, "STRONG_BUDGET", 200)
    mtsp.clear_cache(disk=False)
    yield
    mtsp.clear_cache(disk=False)


def test_json_reports_the_plan_of_the_api() -> None:
    out = runner.invoke(app, ["plan", "--drones", "6", "--seed", "3", "--speed", "4", "--json",
                              *FAST])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    expected = mtsp.plan_for(Mission.build(drones=6, plan_seed=3, iterations=200), 6)
    assert data["tours"] == [list(t) for t in expected.tours]
    assert data["lengths"] == expected.lengths.tolist()
    assert data["total"] == expected.total and data["longest"] == expected.longest
    assert data["longest_time"] == expected.longest / 4
    assert data["min_cells"] == 10 and data["cells"] == 64


@pytest.mark.parametrize("objective", ["minsum", "minmax"])
def test_the_same_command_gives_the_same_tours(objective: str) -> None:
    """Every solver stops at a budget, never at a time: two solves from an empty cache agree
    (benchmarks/bench_mtsp.py --busy checks it with the other core loaded)."""
    args = ["plan", "--drones", "10", "--solver", "ortools", "--objective", objective, "--json"]
    tours = []
    for _ in range(2):
        mtsp.clear_cache()
        out = runner.invoke(app, args)
        assert out.exit_code == 0, out.output
        tours.append(json.loads(out.stdout)["tours"])
    assert tours[0] == tours[1]


def test_ortools_minmax_with_min_cells() -> None:
    out = runner.invoke(app, ["plan", "--drones", "4", "--solver", "ortools", "--objective",
                              "minmax", "--min-cells", "12", "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    assert data["solver"] == "ortools" and data["objective"] == "minmax"
    assert min(map(len, data["tours"])) >= 12
    assert sorted(i for tour in data["tours"] for i in tour) == list(range(64))


def test_summary_table_and_plot(tmp_path: Path) -> None:
    png = tmp_path / "plan.png"
    out = runner.invoke(app, ["plan", "--drones", "3", "--size", "3000", "--r", "500",
                              "--plot", str(png), *FAST])
    assert out.exit_code == 0, out.output
    assert "36 cells" in out.stdout and "longest" in out.stdout and "s of flight" in out.stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(("args", "message"), [
    (["--solver", "lkh"], "mtsp.solver"),
    (["--objective", "mean"], "mtsp.objective"),
    (["--drones", "6", "--min-cells", "11"], "mtsp.min_cells must be at most 10"),
    (["--drones", "65"], "1 to 64 drones"),
    (["--r", "-1"], "sensing.r"),
])
def test_mistakes_are_one_line_and_exit_2(args: list[str], message: str) -> None:
    out = runner.invoke(app, ["plan", *args])
    assert out.exit_code == 2
    assert message in out.output and "Traceback" not in out.output
