"""``sarlink design`` without ``--rc``: the smallest range each team size needs.

The needed range of a run is checked against direct flights just above and below it; the
bound on the quantile against its guarantee on distributions whose quantile is known.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from sarlink import Experiment, Mission
from sarlink.at_range import needed_ranges
from sarlink.cli import app
from sarlink.design.needed_range import smallest_range
from sarlink.design.sequential import lower_bound, upper_bound
from sarlink.execution import sweep
from sarlink.simulation import prepare


def test_a_runs_needed_range_is_where_a_flight_starts_to_succeed(tmp_path: Path) -> None:
    """At the needed range (rounded up) a direct flight notifies by t_d; a metre below, not."""
    td = 1200.0
    runs = sweep(Experiment.from_dict({
        "name": "need", "seed": 4, "runs": 8, "staircase": True,
        "mission": {"team": {"planner": "covb", "drones": 6},
                    "timing": {"horizon": td}, "channel": {"rc": 900.0}}}),
        tmp_path, workers=1, progress=False)
    needed = needed_ranges(runs, td)
    mission = Mission.build(planner="covb", drones=6, horizon=td)
    checked = 0
    for k, rho in enumerate(needed):
        if not math.isfinite(rho):  # not found by t_d: no range notifies
            assert not prepare(mission.replace(rc=3000.0)).run(4, k).notified(td)
            continue
        assert prepare(mission.replace(rc=math.ceil(rho))).run(4, k).notified(td)
        if rho > 1.0:
            assert not prepare(mission.replace(rc=math.floor(rho) - 1.0)).run(4, k).notified(td)
            checked += 1
    assert checked >= 4


@settings(deadline=None)
@given(n=st.integers(10, 400), ps=st.floats(0.5, 0.99), seed=st.integers(0, 2**32 - 1),
       lost=st.floats(0.0, 0.2))
def test_the_reported_range_meets_its_bound(n: int, ps: float, seed: int, lost: float) -> None:
    needed = np.random.default_rng(seed).exponential(800.0, n)
    needed[np.random.default_rng(seed + 1).random(n) < lost] = math.inf
    reached, estimate, below = smallest_range(needed, ps, 0.025)
    if reached is not None:
        count = int(np.count_nonzero(needed <= reached))
        assert lower_bound(count, n, 0.025) >= ps
        if reached >= 1.0:  # a smaller whole range is not shown to meet
            assert lower_bound(int(np.count_nonzero(needed <= reached - 1.0)), n, 0.025) < ps
    else:
        assert lower_bound(int(np.count_nonzero(np.isfinite(needed))), n, 0.025) < ps
    if below is not None:
        assert upper_bound(int(np.count_nonzero(needed <= below)), n, 0.025) < ps
        assert reached is None or below < reached
    if estimate is not None and reached is not None:
        assert estimate <= reached


@pytest.mark.parametrize(("ps", "n"), [(0.5, 50), (0.9, 200)])
def test_the_guarantee_holds_on_known_quantiles(ps: float, n: int) -> None:
    """Over many designs on a distribution with a known ps-quantile, the reported range
    falls below it (a design that is wrong) at most as often as the error allows."""
    rng = np.random.default_rng(12)
    trials = 2000
    truth = -800.0 * math.log(1 - ps)  # the exponential's ps-quantile
    wrong = sum(1 for _ in range(trials)
                if (r := smallest_range(rng.exponential(800.0, n), ps, 0.025)[0]) is not None
                and r < truth)
    assert wrong / trials <= 0.025 + 3 * math.sqrt(0.025 * 0.975 / trials)


def test_design_without_rc_on_the_command_line(tmp_path: Path) -> None:
    out = CliRunner().invoke(app, [
        "design", "--td", "1200", "--ps", "0.8", "--planner", "mtsp", "--planner", "conb",
        "--sizes", "3", "--range-runs", "20", "--out", str(tmp_path), "--json"])
    assert out.exit_code == 0, out.output
    answer = json.loads(out.output)
    mtsp, conb = answer["planners"]
    (need,) = mtsp["needs"]
    assert need["drones"] == 3 and need["runs"] == 20 and need["front"] == (
        need["range"] is not None)
    assert conb["needs"] == [] and "give --rc" in conb["reason"]
    again = CliRunner().invoke(app, [  # the same runs, read again from the folder
        "design", "--td", "1200", "--ps", "0.8", "--planner", "mtsp", "--sizes", "3",
        "--range-runs", "20", "--out", str(tmp_path), "--json"])
    assert json.loads(again.output)["planners"][0]["needs"] == [need]


@pytest.mark.parametrize(("args", "message"), [
    (["--sizes", "0,4"], "--sizes: team sizes must be between 1 and --max-drones (22)"),
    (["--sizes", "four"], "--sizes: expected team sizes like 4,10,22"),
    (["--option", "look=per-period"], "--option applies with --rc only"),
    (["--range-runs", "3"], "--range-runs must be at least 10"),
])
def test_bad_input_of_a_design_without_rc(args: list[str], message: str) -> None:
    out = CliRunner().invoke(app, ["design", "--td", "1200", "--ps", "0.8", *args])
    assert out.exit_code == 2
    assert message in out.output
