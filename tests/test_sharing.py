"""Missions that share their flights (sarlink.engine.sharing) against flying each alone.

A run whose drones report (``on_detect = report``) is taken from the same run without
reporting wherever no drone ever reports (nothing detected, or the BS told in the step of the
first detection): it must then be, bit for bit, the run the engine flies, at hypothesis-drawn
teams, ranges, fades and stops; a rule that reads what differs is flown.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sarlink import Experiment, Mission, execution, register_planner, storage
from sarlink.engine import sharing
from sarlink.execution import sweep, sweep_all
from sarlink.simulation import prepare
from test_critical_ranges import same_outcome

sys.path.insert(0, str(Path(__file__).parent / "plugins"))
from homebound import HOMEBOUND

STOPS = ["horizon", "detected", "notified"]


@given(planner=st.sampled_from(["conb", "concov", "covb", "mtsp", "mtsp-conb", "sector"]),
       drones=st.integers(1, 9), rc=st.floats(150.0, 2500.0), sigma=st.sampled_from([0.0, 3.0]),
       stops=st.tuples(st.sampled_from(STOPS), st.sampled_from(STOPS)),
       reporters=st.sampled_from(["knowers", "detector"]), p_miss=st.sampled_from([0.0, 0.3]))
def test_a_reporting_run_taken_from_the_run_without_is_the_run_flown(
        planner: str, drones: int, rc: float, sigma: float, stops: tuple[str, str],
        reporters: str, p_miss: float) -> None:
    base = Mission.build(planner=planner, drones=drones, rc=rc, sigma=sigma, horizon=1500.0,
                         p_miss=p_miss, nr=3, stop=stops[0], reading="sarlink-2")
    twin = base.replace(on_detect="report", reporters=reporters, stop=stops[1])
    pb, pt = prepare(base), prepare(twin)
    assert sharing._base_of([pb, pt], 1, [0, 1]) == (0 if stops[1] != "horizon" or stops[0] ==
                                             "horizon" else None)
    for run in range(4):
        row = pb.run(7, run)
        taken = sharing.reporting_twin(row, pb, pt)
        if taken is not None:
            flown = pt.run(7, run)
            same_outcome(taken, flown)
            np.testing.assert_array_equal(taken.depth, flown.depth)  # NaN after a stop too
            np.testing.assert_array_equal(taken.farthest, flown.farthest)
            assert taken.notify_times is None
        else:  # a drone knew before the BS did, or the base ended at the detection
            assert row.t_detect is not None


def test_most_of_conb_s_reporting_runs_are_taken() -> None:
    """ConB keeps its drones linked to the BS: the BS hears of a detection at once, so its
    reporting runs are its runs (and the same as flown); mTSP's drones are often out of
    touch, and report."""
    for planner, share in (("conb", 0.9), ("mtsp", 0.0)):
        base = Mission.build(planner=planner, drones=10, rc=500.0, horizon=2000.0)
        pb, pt = prepare(base), prepare(base.replace(on_detect="report", stop="notified"))
        taken = 0
        for run in range(10):
            row = sharing.reporting_twin(pb.run(3, run), pb, pt)
            if row is not None:
                same_outcome(row, pt.run(3, run))
                taken += 1
        assert taken >= 10 * share if share else taken < 10


def _experiment(name: str, planner: str, **mission: object) -> Experiment:
    return Experiment.from_dict({
        "name": name, "seed": 11, "runs": 6, "chunk": 3, "staircase": name == "main",
        "mission": {"team": {"planner": planner, "drones": 6, **mission.pop("team", {})},
                    "timing": {"horizon": 1500.0, **mission.pop("timing", {})}},
        "grid": {"rc": [300.0, 1200.0]}})


@pytest.mark.parametrize("planner", ["conb", "mtsp"])
def test_sweeps_with_and_without_reporting_share_their_runs(
        planner: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The paper's ``main`` and ``report``, swept together: one job per chunk and team (mTSP's
    ranges too), the same rows as swept apart, and fewer reporting runs flown; a folder
    swept twice in one call gets the same rows."""
    main = _experiment("main", planner)
    report = _experiment("report", planner, team={"on_detect": "report"},
                         timing={"stop": "notified"})
    with storage.open_store(tmp_path / "m", main) as a, \
            storage.open_store(tmp_path / "r", report) as b:
        tasks = [*execution._plan(a, 6, 3, True), *execution._plan(b, 6, 3)]
    jobs = execution._jobs(tasks)
    assert sorted(len(job) for job in jobs) == ([2] * 4 if planner == "conb" else [4] * 2)
    flown = []  # the flights of the jobs, run in this process
    original = sharing.Prepared.run

    def counted(self: sharing.Prepared, *args: object, **kwargs: object) -> object:
        if self.steering.per_run is None:  # a flight (not the call that makes a run's plan)
            flown.append(self.mission.team.on_detect)
        return original(self, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(sharing.Prepared, "run", counted)
    for call in execution._calls(jobs):
        execution._run_chunk(*call)
    monkeypatch.setattr(sharing.Prepared, "run", original)
    if planner == "conb":  # flown per range: 6 runs at 2 ranges, and some reporting runs
        assert flown.count("continue") == 6 * 2
        assert flown.count("report") < 6 * 2
    else:  # main scanned at every range as it flies; reporting runs flown where one reports
        assert flown.count("continue") == 0 and flown.count("report") < 6 * 2
    *together, again = sweep_all([(main, tmp_path / "main"), (report, tmp_path / "report"),
                                  (main, tmp_path / "main-again")], workers=1, progress=False)
    apart = [sweep(main, tmp_path / "main-apart", workers=1, progress=False),
             sweep(report, tmp_path / "report-apart", workers=1, progress=False)]
    for a, b in zip(together, apart, strict=True):
        pd.testing.assert_frame_equal(a, b)
    pd.testing.assert_frame_equal(again, apart[0])  # the same mission twice in one call


@pytest.mark.usefixtures("fresh_registries")
def test_a_rule_that_reads_on_detect_is_flown() -> None:
    """Homebound heads for the BS when its team will report: its reporting runs part from the
    others at take-off. Undeclared, it is flown; declared (a lie), the run taken differs."""
    register_planner(HOMEBOUND)
    base = Mission.build(planner="homebound", drones=3, rc=200.0, horizon=600.0)
    pb, pt = prepare(base), prepare(base.replace(on_detect="report", stop="notified"))
    assert sharing._base_of([pb, pt], 1, [0, 1]) is None
    rule = pt.steering.rule
    assert rule is not None
    lying = replace(pt, steering=replace(pt.steering, rule=replace(rule, ignores_reporting=True)))
    assert sharing._base_of([pb, lying], 1, [0, 1]) == 0
    rows = [(sharing.reporting_twin(pb.run(1, k), pb, lying), pt.run(1, k)) for k in range(3)]
    assert any(taken is not None and not
               (taken.connected_cum == flown.connected_cum).all() for taken, flown in rows)
