"""Plan computation time (Fig. 1) measures what it says it measures, and counts the work the
paper's sentences name."""

from __future__ import annotations

import time
from types import SimpleNamespace

import pytest

import sarlink.plantime as plantime
from sarlink import Mission
from sarlink.mtsp import MtspPlan
from sarlink.simulation import prepare


@pytest.mark.parametrize(("planner", "solves"), [("mtsp", [8]), ("covb", []), ("conb", []),
                                                   ("mtsp-conb", [4])])
def test_plan_time_solves_mtsp_afresh_and_only_for_the_planned_drones(
    planner: str, solves: list[int], monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: list[int] = []
    real = plantime.solve_for

    def counting(mission: Mission, salesmen: int) -> MtspPlan:
        if mission.mtsp.iterations > 1:  # not the GA's warm-up
            calls.append(salesmen)
        return real(mission, salesmen)

    monkeypatch.setattr(plantime, "solve_for", counting)
    mission = Mission.build(planner=planner, drones=8, nr=4, rc=500.0, horizon=1000.0,
                            iterations=200)
    cost = plantime.plan_cost(mission)
    assert cost.seconds > 0
    assert calls == solves
    # the GA's evaluations, population x iterations; the searches of ConB's part, counted
    # by the engine run that generated its paths
    assert cost.evaluations == (80 * 200 if solves else 0)
    assert cost.expansions == (prepare(mission).run_record(0, 0).work
                               if planner in ("conb", "mtsp-conb") else 0)
    assert (cost.expansions > 0) == (planner in ("conb", "mtsp-conb"))


def test_a_conb_team_within_range_of_the_bs_expands_the_bs_alone() -> None:
    """At r_c = 3000 m every point of the 4000 m square is within range of the BS (its
    farthest is 2828 m away), so every search of the continuous check holds every node
    after the BS's links: one expansion per increment, t_s / dt = 2 increments at each of the
    1000 steps that decide (the last step, the horizon, only observes)."""
    mission = Mission.build(planner="conb", drones=5, rc=3000.0, horizon=1000.0)
    assert plantime.plan_cost(mission).expansions == 2 * 1000


def test_plan_time_counts_computation_not_waiting(monkeypatch: pytest.MonkeyPatch) -> None:
    """A plan that waits 0.3 s (as on a machine busy with other work) costs no CPU: the clock
    is the process's CPU time, not the wall clock."""
    monkeypatch.setattr(plantime, "solve_for", lambda mission, salesmen: time.sleep(0.3)
                        or SimpleNamespace(evaluations=None))
    cost = plantime.plan_cost(Mission.build(planner="mtsp", drones=2, iterations=10))
    assert 0 <= cost.seconds < 0.1


def test_the_ga_is_compiled_before_the_clock_starts(monkeypatch: pytest.MonkeyPatch) -> None:
    """Fig. 1's first repeat costs what the others cost: a one-iteration solve of the same
    problem (which compiles the GA) comes before the clock is read, the timed solve after."""
    events: list[str] = []
    real_solve, real_clock = plantime.solve_for, time.process_time

    def solving(mission: Mission, salesmen: int) -> MtspPlan:
        events.append(f"solve {mission.mtsp.iterations}")
        return real_solve(mission, salesmen)

    def clock() -> float:
        events.append("clock")
        return real_clock()

    monkeypatch.setattr(plantime, "solve_for", solving)
    monkeypatch.setattr(plantime.time, "process_time", clock)
    plantime.plan_cost(Mission.build(planner="mtsp-conb", drones=6, nr=3, iterations=50))
    assert events == ["solve 1", "clock", "solve 50", "clock"]
