"""``on_detect = report``: drones that learn where the target is fly to the BS to tell it."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sarlink import ConfigError, Mission, Scenario, simulate
from sarlink.engine.codes import Mode

BS = (2000.0, 2000.0)


def _lone_drone(on_detect: str, planner: str = "covb") -> tuple[Mission, Scenario]:
    """One drone 1000 m east of the BS's range edge flying north towards a target 1000 m ahead.

    It senses the target (r = 500 m) after 500 m, at (3500, 1500), 1581 m from the BS, whose
    range r_c = 200 m is far below that distance.
    """
    mission = Mission.build(drones=1, planner=planner, rc=200.0, horizon=1500.0,
                            on_detect=on_detect)
    scenario = Scenario(target=(3500.0, 2000.0), positions=np.array([[3500.0, 1000.0]]),
                        headings=np.array([math.pi / 2]))
    return mission, scenario


def test_a_lone_reporter_notifies_after_the_straight_flight_to_the_bs_range() -> None:
    mission, scenario = _lone_drone("report")
    result = simulate(mission, scenario=scenario, trajectory=True)
    assert result.t_detect == 100.0  # 500 m at 5 m/s
    straight = (math.hypot(3500.0 - BS[0], 1500.0 - BS[1]) - 200.0) / 5.0
    assert result.t_notify is not None
    assert 0.0 <= result.t_notify - (result.t_detect + straight) < 1.0  # within one step
    traj = result.trajectory
    assert traj is not None
    reporting = traj.mode[:, 0] == Mode.REPORTING
    # it reports from the step after it learns until the BS is notified (a step's record is
    # its observed state: the step of the notification still shows it reporting)
    first, last = np.flatnonzero(reporting)[[0, -1]]
    assert (first, last) == (101, round(result.t_notify))
    # along the straight line to the BS
    to_bs = np.array(BS) - traj.positions[first:last + 1, 0]
    heading = np.array([3500.0 - BS[0], 1500.0 - BS[1]]) / math.hypot(1500.0, 500.0)
    cross = to_bs[:, 0] * heading[1] - to_bs[:, 1] * heading[0]
    assert np.abs(cross).max() < 1e-6
    continuing = simulate(mission.replace(on_detect="continue"), scenario=scenario)
    assert continuing.t_detect == result.t_detect
    assert continuing.t_notify is None or continuing.t_notify > result.t_notify


def test_a_reporting_route_drone_flies_back_to_where_it_left_its_tour() -> None:
    """mTSP, two drones, only the detector reports: after the notification it returns to its
    leave point and finishes its tour, which lands it later by the detour (there and back)
    within a step."""
    mission = Mission.build(drones=2, planner="mtsp", rc=300.0, iterations=200,
                            reporters="detector", horizon=6000.0)  # both tours end
    for run in range(40):  # the first run in which the detector must leave its tour
        report = simulate(mission.replace(on_detect="report"), seed=3, run=run,
                          trajectory=True)
        if report.t_notify is not None and report.t_notify > report.t_detect + 10:
            break
    else:
        pytest.fail("no run in which the detector had to leave its tour")
    cont = simulate(mission, seed=3, run=run, trajectory=True)
    traj, i = report.trajectory, report.detector
    assert traj is not None and cont.trajectory is not None and i is not None
    k_det, k_not = round(report.t_detect) + 1, round(report.t_notify)
    leave, notified_at = traj.positions[k_det - 1, i], traj.positions[k_not, i]
    back = traj.positions[k_not:, i]
    assert np.min(np.hypot(*(back - leave).T)) < 1e-6  # it passes through the leave point
    landed = [np.flatnonzero(t.mode[:, i] == Mode.LANDED)[0]
              for t in (cont.trajectory, traj)]
    detour = 2 * math.hypot(*(notified_at - leave)) / 5.0
    assert abs(landed[1] - landed[0] - detour) <= 1.0


@pytest.mark.parametrize("planner", ["covb", "conb", "concov", "mtsp", "mtsp-conb"])
def test_continue_is_the_default_and_report_changes_nothing_without_a_detection(
        planner: str) -> None:
    mission = Mission.build(planner=planner, drones=4, rc=500.0, horizon=300.0, iterations=200)
    assert mission.team.on_detect == "continue"
    # a target in a corner that nobody reaches within 300 s
    scenario = Scenario(target=(50.0, 50.0))
    a = simulate(mission, seed=1, scenario=scenario, trajectory=True)
    b = simulate(mission.replace(on_detect="report"), seed=1, scenario=scenario,
                 trajectory=True)
    assert a.t_detect is None and b.t_detect is None
    assert a.trajectory is not None and b.trajectory is not None
    np.testing.assert_array_equal(a.trajectory.positions, b.trajectory.positions)


@given(planner=st.sampled_from(["covb", "conb", "concov", "mtsp", "mtsp-conb"]),
       drones=st.integers(1, 4), rc=st.sampled_from([300.0, 600.0, 1000.0]),
       run=st.integers(0, 10_000), reporters=st.sampled_from(["knowers", "detector"]))
def test_report_and_continue_agree_until_the_detection(planner: str, drones: int, rc: float,
                                                       run: int, reporters: str) -> None:
    """Same seed and run: identical paths up to the first detection, the same detection,
    never a notification before it, every drone inside the area; a lone drone that reports
    never notifies later than one that continues."""
    base = Mission.build(planner=planner, drones=drones, rc=rc, horizon=1500.0,
                         iterations=200, nr=max(1, drones - 1), reporters=reporters)
    cont = simulate(base, seed=7, run=run, trajectory=True)
    rep = simulate(base.replace(on_detect="report"), seed=7, run=run, trajectory=True)
    assert cont.t_detect == rep.t_detect
    assert cont.trajectory is not None and rep.trajectory is not None
    upto = len(rep.trajectory.t) if rep.t_detect is None else round(rep.t_detect) + 1
    np.testing.assert_array_equal(cont.trajectory.positions[:upto],
                                  rep.trajectory.positions[:upto])
    pos = rep.trajectory.positions
    assert pos.min() >= 0.0 and pos.max() <= 4000.0
    if rep.t_notify is not None:
        assert rep.t_detect is not None and rep.t_notify >= rep.t_detect
    if drones == 1 and cont.t_notify is not None:
        assert rep.t_notify is not None and rep.t_notify <= cont.t_notify


def test_only_the_detector_reports_when_asked() -> None:
    mission = Mission.build(planner="covb", drones=6, rc=400.0, horizon=1500.0,
                            on_detect="report", reporters="detector")
    for run in range(30):
        result = simulate(mission, seed=2, run=run, trajectory=True)
        traj = result.trajectory
        assert traj is not None
        reporting = (traj.mode == Mode.REPORTING).any(axis=0)
        assert set(np.flatnonzero(reporting)) <= {result.detector}


def test_bad_values_name_the_field() -> None:
    with pytest.raises(ConfigError, match=r"team\.on_detect"):
        Mission.build(on_detect="shout")
    with pytest.raises(ConfigError, match=r"team\.reporters"):
        Mission.build(reporters="everyone")
