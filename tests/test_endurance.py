"""Batteries in the simulation (``mission.battery``; docs/model.md, Endurance): the engine
against the slow reference run by run, the energy rebuilt from the trajectory alone (never
under the reserve in flight), route drones resuming where they left, the stock of spares, and
what must not take batteries (the range-free shortcut, the stepping env)."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from sarlink import Mission, simulate
from sarlink.cli import app
from sarlink.config import ConfigError
from sarlink.engine.codes import Mode
from sarlink.engine.energy import CLIMB_RATE, DESCENT_RATE, get_energy_model
from sarlink.metrics import summarize
from sarlink.result import RunResult
from sarlink.simulation import prepare
from sarlink.storage import run_table
from test_reference import agreeing_runs

ENDURANCE_RUNS = 12
BATTERY = {"battery_wh": 20.0, "energy_model": "zeng2019", "swap_time": 60.0, "altitude": 40.0}
"""A battery of some five minutes of flight at 5 m/s under Zeng's model, after the climb to
40 m and the descent: several sorties in a run."""
ENDURANCE_CASES = {
    "covb": {"planner": "covb"},
    "covb-relays": {"planner": "covb", "relays": 2},
    "covb-spares": {"planner": "covb", "spares": 3},
    "mtsp": {"planner": "mtsp", "mtsp_plan": "shared", "iterations": 200},
}


@pytest.mark.parametrize("case", ENDURANCE_CASES)
def test_endurance_agrees_with_the_reference_run_by_run(case: str) -> None:
    """Six drones at r_c = 500 m on batteries: the reference drains, turns home, swaps and
    takes off from the model's text, the engine through its kernel; in all but a few runs
    (knife edges, tests/test_reference.py) the two fly every drone the same and count the
    same sorties, time on the ground and energy. Swaps happen: some drone flies three
    sorties."""
    base = Mission.build(drones=6, rc=500.0, horizon=1500.0, **BATTERY, **ENDURANCE_CASES[case])
    same = most = 0
    for _, fast, slow in agreeing_runs(base, ENDURANCE_RUNS):
        same += 1
        assert fast.sorties is not None and fast.ground_time is not None
        assert fast.sorties.tolist() == slow.sorties
        np.testing.assert_allclose(fast.ground_time, slow.ground_time, rtol=0.0, atol=1e-9)
        np.testing.assert_allclose(fast.energy, slow.energy, rtol=1e-12)
        most = max(most, int(fast.sorties.max()))
    assert same >= ENDURANCE_RUNS - 2
    assert most >= 3 if case != "covb-spares" else most >= 2


def _powers(mission: Mission) -> tuple[float, float, float, float]:
    """Flying and holding power (W), a climb's and a descent's energy (J), from the model."""
    model = get_energy_model(mission.energy_model)
    h = mission.channel.altitude
    return (model.power(mission.team.speed), model.power(0.0),
            model.vertical_power(CLIMB_RATE) * h / CLIMB_RATE,
            model.vertical_power(-DESCENT_RATE) * h / DESCENT_RATE)


def rebuilt_energy(mission: Mission, result: RunResult) -> tuple[np.ndarray, np.ndarray]:
    """Each drone's energy left after every step it spent in the air, J (NaN for a step on
    the ground), and its energy drawn, rebuilt from the trajectory alone: a take-off gives a
    full battery less the climb (at the start of a step: the step is flown); a step in the
    air (or the one it landed in) costs the flying power for the time the way it came takes
    at V_m and the holding power for the rest; a landing the descent."""
    fly, hold, climb, descent = _powers(mission)
    capacity = mission.battery.battery_wh * 3600.0
    tr = result.trajectory
    assert tr is not None
    steps, n = tr.mode.shape
    dt = mission.timing.dt
    landed = tr.mode == Mode.LANDED
    left = np.full((steps, n), np.nan)
    used = np.full(n, climb)
    energy = np.full(n, capacity - climb)
    for k in range(1, steps):
        for i in range(n):
            if landed[k - 1, i]:  # on the ground from step k - 1 to k
                continue
            if k > 1 and landed[k - 2, i]:  # took off at the start of step k - 1
                energy[i] = capacity - climb
                used[i] += climb
            way = float(np.hypot(*(tr.positions[k, i] - tr.positions[k - 1, i])))
            flying = min(way / mission.team.speed, dt)
            drawn = fly * flying + hold * (dt - flying) + (descent if landed[k, i] else 0.0)
            energy[i] -= drawn
            used[i] += drawn
            left[k, i] = energy[i]
    used[landed[-2] & ~landed[-1]] += climb  # took off at the start of the last step
    return left, used


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(wh=st.floats(10.0, 40.0), reserve=st.floats(0.0, 0.4), swap=st.floats(10.0, 300.0),
       relays=st.integers(0, 2), run=st.integers(0, 10_000))
@example(wh=15.75, reserve=0.3671875, swap=266.0, relays=0, run=0)  # takes off at the last step
def test_no_drone_flies_on_its_reserve(wh: float, reserve: float, swap: float, relays: int,
                                       run: int) -> None:
    """For any battery, reserve and swap time: the energy rebuilt from the trajectory never
    goes below the reserve (it turns home in time, the landing paid), and the energy the
    engine counts is the rebuilt one."""
    mission = Mission.build(planner="covb", drones=5, relays=relays, rc=500.0, horizon=2000.0,
                            battery_wh=wh, reserve=reserve, swap_time=swap,
                            energy_model="zeng2019", altitude=40.0)
    result = simulate(mission, seed=7, run=run, trajectory=True)
    left, used = rebuilt_energy(mission, result)
    assert np.nanmin(left) >= reserve * wh * 3600.0 - 1e-6
    assert result.energy is not None
    np.testing.assert_allclose(result.energy, used, rtol=1e-9)


def test_a_route_drone_resumes_where_it_left_its_route() -> None:
    """Two mTSP drones whose tours outlast a 25-minute battery: each turns home, swaps, flies
    back to where it left its tour and flies the rest of it, so it passes over every waypoint
    of its tour in order, as without a battery, only later (within a step of each: it passes
    them between the steps recorded)."""
    mission = Mission.build(planner="mtsp", drones=2, rc=500.0, battery_wh=70.0,
                            energy_model="zeng2019", mtsp_plan="shared", iterations=200,
                            horizon=12000.0, flight_time=12000.0)
    routes = prepare(mission).steering.routes
    result = simulate(mission, seed=1, run=0, trajectory=True)
    tr = result.trajectory
    assert tr is not None and result.sorties is not None
    assert (result.sorties >= 2).all()
    for i, route in enumerate(routes):
        turned = np.flatnonzero((tr.mode[1:, i] == Mode.RETURNING)
                                & (tr.mode[:-1, i] != Mode.RETURNING))
        assert turned.size == result.sorties[i] - 1  # the tour ends before the next is due
        step = mission.team.speed * mission.timing.dt  # a point passed mid-step: within one
        for k in turned:  # the point it left is flown over again after the swap
            later = np.hypot(*(tr.positions[k + 2:, i] - tr.positions[k, i]).T)
            assert later.min() <= step + 1e-6
        k = 0
        for w in route:  # every waypoint, in order
            d = np.hypot(*(tr.positions[k:, i] - w).T)
            assert d.min() <= step + 1e-6, (i, w)
            k += int(np.argmin(d))


def test_without_spares_a_drone_parks_after_its_first_sortie() -> None:
    """No spare at the BS: every drone that comes home for a swap stays parked there."""
    mission = Mission.build(planner="covb", drones=4, rc=500.0, horizon=3000.0, spares=0,
                            **BATTERY)
    result = simulate(mission, seed=3, run=0, trajectory=True)
    assert result.sorties is not None and result.sorties.tolist() == [1, 1, 1, 1]
    assert result.trajectory is not None and (result.trajectory.mode[-1] == Mode.LANDED).all()
    assert (result.ground_time == 0.0).all()


def test_a_team_without_a_battery_flies_today_s_kernel() -> None:
    """No battery: the kernel is compiled without endurance, and the run has no sorties."""
    plain = prepare(Mission.build(planner="covb", drones=4))
    assert not plain.energy and "_energy" not in plain.kernel.__module__
    on = prepare(Mission.build(planner="covb", drones=4, **BATTERY))
    assert on.energy and "_energy" in on.kernel.__module__
    assert not on.range_free
    assert simulate(Mission.build(planner="covb", drones=4), seed=0, run=0).sorties is None


def test_simulate_prints_each_drone_s_sorties_ground_time_and_energy() -> None:
    """``sarlink simulate`` on a battery: the JSON carries the run's own records."""
    out = CliRunner().invoke(app, ["simulate", "--planner", "covb", "--drones", "4", "--td",
                                   "1500", "--battery-wh", "20", "--energy-model", "zeng2019",
                                   "--swap-time", "60", "--altitude", "40", "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    mission = Mission.build(planner="covb", drones=4, horizon=1500.0, **BATTERY)
    result = simulate(mission, seed=data["seed"], run=data["run"])
    assert result.sorties is not None and result.energy is not None
    assert data["sorties"] == result.sorties.tolist() and max(data["sorties"]) >= 2
    assert data["energy_wh"] == pytest.approx(result.energy / 3600.0, abs=1e-3)


def test_summarize_averages_sorties_and_energy_over_drones_and_runs() -> None:
    """A stored table of runs on batteries, beside runs of a team without: summarize gives
    each group's mean sorties and energy per drone from the runs' own records, and none for
    the group without batteries."""
    on = Mission.build(planner="covb", drones=4, horizon=1500.0, **BATTERY)
    off = Mission.build(planner="covb", drones=4, horizon=1500.0)
    flown = [simulate(on, seed=3, run=k) for k in range(4)]
    without = [simulate(off, seed=3, run=k) for k in range(4)]
    table = pd.concat([run_table(on, 3, flown).to_pandas(),
                       run_table(off, 3, without).to_pandas()], ignore_index=True)
    rows = summarize(table, td=[500.0, 1500.0], by=["battery_wh"])
    with_battery = rows[rows["battery_wh"].notna()]
    sorties = [float(np.mean(r.sorties)) for r in flown if r.sorties is not None]
    energy = [float(np.mean(r.energy)) / 3600.0 for r in flown if r.energy is not None]
    assert len(with_battery) == 2 and len(sorties) == len(energy) == 4
    assert with_battery["sorties"].tolist() == pytest.approx([np.mean(sorties)] * 2)
    assert with_battery["energy"].tolist() == pytest.approx([np.mean(energy)] * 2)
    assert with_battery["sorties_se"].iloc[0] == pytest.approx(np.std(sorties, ddof=1) / 2)
    assert rows[rows["battery_wh"].isna()]["sorties"].isna().all()
    assert "sorties" not in summarize(run_table(off, 3, without).to_pandas(), by=[]).columns


def test_a_battery_that_only_takes_off_and_lands_is_refused_in_one_line() -> None:
    """6 Wh with half in reserve: the climb to 40 m and the landing alone take more."""
    mission = Mission.build(planner="covb", drones=2, battery_wh=6.0, reserve=0.5,
                            energy_model="zeng2019", altitude=40.0)
    with pytest.raises(ConfigError, match=r"^battery.battery_wh = 6 with battery.reserve = 0.5 "
                                          r"leaves 3 Wh a sortie, .* allowed, more than"):
        simulate(mission, seed=0, run=0)
