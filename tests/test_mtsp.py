"""mTSP: the cells, both solvers against brute force and each other, the plan cache, planners."""

from __future__ import annotations

import itertools
import json
import math
import time
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from filelock import FileLock

import sarlink.mtsp as mtsp
import sarlink.mtsp.cache as plan_cache
from sarlink import Mission
from sarlink.config import ConfigError
from sarlink.mtsp import MtspPlan, grid_cells, plan_for, solve
from sarlink.planners import get_planner
from sarlink.planners.rules.conb import CONB

GRID = grid_cells(4000.0, 500.0)
BS = (2000.0, 2000.0)
FAST = {"iterations": 300}
"""GA settings for tests whose property does not need a converged plan."""

# TSPLIB eil51 (Christofides/Eilon); optimal tour 426 with edges rounded to integers
EIL51 = np.array([
    (37, 52), (49, 49), (52, 64), (20, 26), (40, 30), (21, 47), (17, 63), (31, 62), (52, 33),
    (51, 21), (42, 41), (31, 32), (5, 25), (12, 42), (36, 16), (52, 41), (27, 23), (17, 33),
    (13, 13), (57, 58), (62, 42), (42, 57), (16, 57), (8, 52), (7, 38), (27, 68), (30, 48),
    (43, 67), (58, 48), (58, 27), (37, 69), (38, 46), (46, 10), (61, 33), (62, 63), (63, 69),
    (32, 22), (45, 35), (59, 15), (5, 6), (10, 17), (21, 10), (5, 64), (30, 15), (39, 10),
    (32, 39), (25, 32), (25, 55), (48, 28), (56, 37), (30, 40),
], dtype=float)


def cost(plan: MtspPlan, objective: str) -> float:
    return plan.total if objective == "minsum" else plan.longest


def naive_lengths(points: np.ndarray, depot: tuple[float, float],
                  tours: tuple[tuple[int, ...], ...]) -> list[float]:
    lengths = []
    for tour in tours:
        stops = [depot, *(tuple(points[i]) for i in tour), depot]
        lengths.append(sum(math.dist(a, b) for a, b in itertools.pairwise(stops)))
    return lengths


def brute_force(points: np.ndarray, depot: tuple[float, float], salesmen: int, min_cells: int,
                objective: str) -> float:
    """The optimum over every assignment of points to salesmen and every visiting order."""
    best_tour: dict[tuple[int, ...], float] = {}

    def tsp(subset: tuple[int, ...]) -> float:
        if subset not in best_tour:
            best_tour[subset] = min(naive_lengths(points, depot, (order,))[0]
                                    for order in itertools.permutations(subset))
        return best_tour[subset]

    best = math.inf
    for labels in itertools.product(range(salesmen), repeat=len(points)):
        parts = [tuple(i for i, lab in enumerate(labels) if lab == s) for s in range(salesmen)]
        if min(map(len, parts)) < min_cells:
            continue
        lengths = [tsp(part) for part in parts]
        best = min(best, sum(lengths) if objective == "minsum" else max(lengths))
    return best


# -- cells ------------------------------------------------------------------------------------


def test_grid_cells_of_the_paper_are_64_row_major_centres_covering_the_area() -> None:
    assert GRID.shape == (64, 2)
    assert GRID[0].tolist() == [250, 250]
    assert GRID[1].tolist() == [750, 250]
    assert GRID[8].tolist() == [250, 750]
    assert GRID[63].tolist() == [3750, 3750]
    fine = np.stack(np.meshgrid(np.linspace(0, 4000, 81), np.linspace(0, 4000, 81)), -1)
    nearest = np.linalg.norm(fine.reshape(-1, 1, 2) - GRID[None], axis=-1).min(axis=1)
    assert nearest.max() <= 500 * math.sqrt(2) / 2 + 1e-9  # inside a cell: sensed from its centre


def test_grid_cells_when_size_is_not_a_multiple_of_r() -> None:
    cells = grid_cells(4200.0, 500.0)
    assert cells.shape == (81, 2)  # ceil(4200 / 500) = 9 per side
    assert cells.min() == 250 and cells.max() == 3950  # last column moved inwards to a - r/2
    assert len(np.unique(cells, axis=0)) == 81
    assert grid_cells(300.0, 500.0).tolist() == [[150.0, 150.0]]  # r > a: one centred cell


# -- plans are valid --------------------------------------------------------------------------


@pytest.mark.parametrize("salesmen", [1, 3, 7])
@pytest.mark.parametrize("objective", ["minsum", "minmax"])
@pytest.mark.parametrize("solver", ["ga", "ortools"])
def test_plan_visits_every_cell_once_from_and_to_the_bs(solver: str, objective: str,
                                                        salesmen: int) -> None:
    plan = solve(GRID, BS, salesmen, solver=solver, objective=objective, budget=300, **FAST)
    assert sorted(i for tour in plan.tours for i in tour) == list(range(64))
    assert len(plan.tours) == salesmen
    assert min(map(len, plan.tours)) >= 64 // salesmen == plan.min_cells
    routes = plan.routes()
    for tour, route in zip(plan.tours, routes, strict=True):
        assert route.shape == (len(tour) + 1, 2)
        np.testing.assert_array_equal(route[:-1], GRID[list(tour)])
        assert tuple(route[-1]) == BS  # lands at the BS; took off there, so not repeated first
    np.testing.assert_allclose(plan.lengths, naive_lengths(GRID, BS, plan.tours), rtol=1e-12)
    assert plan.total == pytest.approx(plan.lengths.sum())
    assert plan.longest == plan.lengths.max()


def test_min_cells_holds_when_given() -> None:
    for solver in ("ga", "ortools"):
        plan = solve(GRID, BS, 4, solver=solver, min_cells=12, budget=100, **FAST)
        assert min(map(len, plan.tours)) >= 12


@pytest.mark.parametrize("objective", ["minsum", "minmax"])
def test_ga_best_cost_never_rises_and_ends_at_the_plan(objective: str) -> None:
    plan = solve(GRID, BS, 5, objective=objective, iterations=1000)
    assert plan.history.shape == (1000,)
    assert (np.diff(plan.history) <= 0).all()
    assert plan.history[0] > plan.history[-1]  # it does improve
    assert plan.history[-1] == pytest.approx(cost(plan, objective), rel=1e-12)


def test_the_ga_counts_population_times_iterations_evaluations() -> None:
    """Fig. 1's work count of the GA: every individual of every iteration's population is
    costed once (the population rounded down to Kirk's groups of 8); the other solvers count
    none."""
    assert solve(GRID, BS, 4, population=86, iterations=37).evaluations == 80 * 37
    assert solve(GRID, BS, 4, population=8, iterations=1).evaluations == 8
    assert solve(GRID, BS, 4, solver="ortools", budget=5).evaluations is None


def test_ga_is_reproducible_with_a_seed_and_differs_across_seeds() -> None:
    a, b = (solve(GRID, BS, 4, seed=3, **FAST) for _ in range(2))
    c = solve(GRID, BS, 4, seed=4, **FAST)
    assert a.tours == b.tours
    np.testing.assert_array_equal(a.history, b.history)
    assert a.tours != c.tours


def test_two_drones_finish_the_paper_search_within_the_flight_budget() -> None:
    plan = solve(GRID, BS, 2)  # the paper's GA: min-sum, 80 x 5000, min cells 32
    assert plan.longest / 5.0 <= 4000.0


# -- optimality -------------------------------------------------------------------------------


INSTANCES = [(7, 2, 1), (8, 3, 2), (7, 2, 3)]
"""(points, salesmen, min_cells): small enough to enumerate every plan."""


@pytest.mark.parametrize("objective", ["minsum", "minmax"])
@pytest.mark.parametrize(("n", "salesmen", "min_cells"), INSTANCES)
def test_both_solvers_find_the_brute_force_optimum(n: int, salesmen: int, min_cells: int,
                                                   objective: str) -> None:
    rng = np.random.default_rng(n * 10 + salesmen)
    points = rng.random((n, 2)) * 1000
    depot = (float(rng.random() * 1000), float(rng.random() * 1000))
    best = brute_force(points, depot, salesmen, min_cells, objective)
    for solver in ("ga", "ortools"):
        plan = solve(points, depot, salesmen, solver=solver, objective=objective,
                     min_cells=min_cells, iterations=1000, budget=1000)
        assert cost(plan, objective) == pytest.approx(best, rel=1e-6), solver


@pytest.mark.parametrize("salesmen", [6, 14, 22])
def test_ortools_longest_tour_is_never_worse_than_the_ga_under_minmax(salesmen: int) -> None:
    ga = solve(GRID, BS, salesmen, objective="minmax")
    ortools = solve(GRID, BS, salesmen, solver="ortools", objective="minmax")
    assert ortools.longest <= ga.longest + 1e-6


def test_ortools_reaches_the_tsplib_optimum_of_eil51() -> None:
    plan = solve(EIL51[1:], tuple(EIL51[0]), 1, solver="ortools", budget=300)
    order = [EIL51[0], *EIL51[1:][list(plan.tours[0])], EIL51[0]]
    rounded = sum(round(math.dist(a, b)) for a, b in itertools.pairwise(order))
    assert rounded <= 426 * 1.01


# -- invalid arguments ------------------------------------------------------------------------


@pytest.mark.parametrize(("kwargs", "name"), [
    ({"points": np.zeros((4, 3))}, "points"),
    ({"points": np.zeros((0, 2))}, "points"),
    ({"points": np.array([[0.0, np.nan]] * 4)}, "points"),
    ({"depot": (1.0, 2.0, 3.0)}, "depot"),
    ({"depot": (np.inf, 0.0)}, "depot"),
    ({"salesmen": 0}, "salesmen"),
    ({"salesmen": 65}, "salesmen"),
    ({"salesmen": 2.0}, "salesmen"),
    ({"salesmen": True}, "salesmen"),
    ({"solver": "lkh"}, "solver"),
    ({"objective": "mean"}, "objective"),
    ({"min_cells": 0}, "min_cells"),
    ({"min_cells": 33}, "min_cells"),  # 2 salesmen x 33 > 64 points
    ({"population": 7}, "population"),
    ({"iterations": 0}, "iterations"),
    ({"seed": -1}, "seed"),
    ({"budget": 0}, "budget"),
    ({"budget": 1.5}, "budget"),
])
def test_invalid_arguments_are_named(kwargs: dict, name: str) -> None:
    args = {"points": GRID, "depot": BS, "salesmen": 2} | kwargs
    with pytest.raises(ValueError, match=f"^{name} must"):
        solve(args.pop("points"), args.pop("depot"), args.pop("salesmen"), **args)


def test_min_cells_error_gives_the_allowed_range() -> None:
    with pytest.raises(ValueError, match=r"min_cells must be an integer in \[1, 32 = floor"):
        solve(GRID, BS, 2, min_cells=33)


def test_a_plan_checks_itself() -> None:
    with pytest.raises(ValueError, match="exactly once"):
        MtspPlan(points=GRID[:3], depot=BS, tours=((0, 1), (1, 2)))
    with pytest.raises(ValueError, match="min_cells"):
        MtspPlan(points=GRID[:3], depot=BS, tours=((0, 1), (2,)), min_cells=2)
    plan = MtspPlan(points=GRID[:3], depot=BS, tours=((0, 1), (2,)))
    with pytest.raises(ValueError, match="read-only"):
        plan.lengths[0] = 0.0


# -- the cache --------------------------------------------------------------------------------


@dataclass
class Cache:
    dir: Path
    calls: list[int] = field(default_factory=list)

    @property
    def solves(self) -> int:
        return len(self.calls)


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Cache]:
    """A private, empty plan cache that counts the solves behind :func:`plan_for`."""
    monkeypatch.setenv("SARLINK_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(plan_cache, "STRONG_BUDGET", 200)
    state = Cache(tmp_path / "plans")
    real = mtsp.solve

    def counting(*args: Any, **kwargs: Any) -> MtspPlan:
        state.calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(plan_cache, "solve", counting)
    mtsp.clear_cache(disk=False)
    yield state
    mtsp.clear_cache(disk=False)


BASE = Mission.build(iterations=100, population=16)


def test_cache_round_trips_through_disk(cache: Cache) -> None:
    first = plan_for(BASE, 3)
    files = list(cache.dir.glob("*.json"))
    assert len(files) == 1 and not list(cache.dir.glob("*.tmp"))
    assert plan_for(BASE, 3) is first  # memoised: not even read again
    mtsp.clear_cache(disk=False)
    again = plan_for(BASE, 3)
    assert again is not first and cache.solves == 1  # read from disk, not solved again
    assert again.tours == first.tours and again.seconds == first.seconds
    np.testing.assert_array_equal(again.lengths, first.lengths)
    np.testing.assert_array_equal(again.history, first.history)
    np.testing.assert_array_equal(again.points, GRID)


@pytest.mark.parametrize("change", [
    {"size": 3000.0}, {"r": 400.0}, {"bs": (1000.0, 1500.0)}, {"solver": "ortools"},
    {"objective": "minmax"}, {"min_cells": 5}, {"population": 24}, {"iterations": 101},
    {"plan_seed": 1},
])
def test_a_changed_plan_parameter_misses_the_cache(cache: Cache, change: dict) -> None:
    plan_for(BASE, 3)
    plan_for(BASE.replace(**change), 3)
    assert cache.solves == 2 and len(list(cache.dir.glob("*.json"))) == 2


@pytest.mark.parametrize("objective", ["minsum", "minmax"])
def test_the_strong_solver_s_budget_is_in_the_cache_key(cache: Cache,
                                                        monkeypatch: pytest.MonkeyPatch,
                                                        objective: str) -> None:
    """A plan is a function of its budget (never of the time): another budget, another key."""
    mission = BASE.replace(solver="ortools", objective=objective)
    plan_for(mission, 3)
    (path,) = cache.dir.glob("*.json")
    assert json.loads(path.read_text())["params"]["budget"] == 200
    monkeypatch.setattr(plan_cache, "STRONG_BUDGET", 201)
    mtsp.clear_cache(disk=False)
    plan_for(mission, 3)
    assert cache.solves == 2 and len(list(cache.dir.glob("*.json"))) == 2


def test_the_default_budget_is_resolved_in_the_key(cache: Cache,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """None and the default it stands for share a plan; the GA's budget is its iterations."""
    mission = BASE.replace(solver="ortools", objective="minmax")
    monkeypatch.setattr(plan_cache, "STRONG_BUDGET", None)
    monkeypatch.setattr(mtsp.ruin, "RUIN_ITERATIONS", 200)  # keep the test quick
    plan_for(mission, 3)
    monkeypatch.setattr(plan_cache, "STRONG_BUDGET", 200)
    mtsp.clear_cache(disk=False)
    plan_for(mission, 3)
    assert cache.solves == 1
    assert mtsp.budget_of("ga", "minsum", 64, 3, 101, 7) == 101


def test_other_changes_hit_the_cache(cache: Cache) -> None:
    plan_for(BASE, 3)
    mtsp.clear_cache(disk=False)
    plan_for(BASE.replace(rc=500.0, p_miss=0.1, drones=22, planner="mtsp"), 3)
    plan_for(BASE.replace(min_cells=64 // 3), 3)  # the default, spelled out
    assert cache.solves == 1
    plan_for(BASE, 4)  # another number of drones is another plan
    assert cache.solves == 2


@pytest.mark.parametrize("damage", ["", "{\"params\": ", "not json", "{\"params\": {}}",
                                    "{\"tours\": [[0]]}"])
def test_a_corrupt_cache_file_is_a_miss_and_is_rewritten(cache: Cache, damage: str) -> None:
    first = plan_for(BASE, 3)
    (path,) = cache.dir.glob("*.json")
    path.write_text(damage)
    mtsp.clear_cache(disk=False)
    again = plan_for(BASE, 3)
    assert cache.solves == 2 and again.tours == first.tours  # the GA is seeded
    assert json.loads(path.read_text())["tours"] == [list(t) for t in first.tours]


def test_only_a_mission_s_plan_is_synced_to_disk_and_a_lost_per_run_plan_is_made_again(
        cache: Cache, monkeypatch: pytest.MonkeyPatch) -> None:
    """A power cut may leave a per-run plan, written without fsync, empty or partial: it is
    then a miss, solved again to the same tours."""
    synced: list[int] = []
    monkeypatch.setattr(plan_cache.os, "fsync", synced.append)
    plan_for(BASE, 3)
    assert len(synced) == 1
    compact = plan_for(BASE, 4, compact=True)
    assert len(synced) == 1 and cache.solves == 2
    (path,) = [f for f in cache.dir.glob("*.json") if "history" in json.loads(f.read_text())
               ["params"]]
    text = path.read_text()
    for left in ("", text[: len(text) // 2]):
        path.write_text(left)
        assert plan_for(BASE, 4, compact=True).tours == compact.tours
    assert cache.solves == 4


def test_a_cache_file_with_bad_tours_is_a_miss(cache: Cache) -> None:
    plan_for(BASE, 3)
    (path,) = cache.dir.glob("*.json")
    data = json.loads(path.read_text())
    data["tours"][0] = data["tours"][0][1:]  # a cell lost
    path.write_text(json.dumps(data))
    mtsp.clear_cache(disk=False)
    assert sorted(itertools.chain(*plan_for(BASE, 3).tours)) == list(range(64))
    assert cache.solves == 2


def test_a_plan_being_solved_elsewhere_is_waited_for_and_not_solved_again(cache: Cache) -> None:
    """Workers that need one plan at once solve it once: the others wait for the lock."""
    solved = plan_for(BASE, 3)
    (path,) = cache.dir.glob("*.json")
    stored = path.read_text()
    path.unlink()
    mtsp.clear_cache(disk=False)
    with ThreadPoolExecutor(1) as pool:
        with FileLock(path.with_suffix(".lock")):  # another process is solving the plan ...
            waiter = pool.submit(plan_for, BASE, 3)
            time.sleep(0.5)
            assert not waiter.done()
            path.write_text(stored)  # ... and stores it, then lets go
        assert waiter.result(timeout=60).tours == solved.tours
    assert cache.solves == 1


def test_an_unwritable_cache_warns_and_still_plans(tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("SARLINK_CACHE_DIR", str(blocker))  # plans/ cannot be made in a file
    mtsp.clear_cache(disk=False)
    with pytest.warns(UserWarning, match="could not cache"):
        plan = plan_for(BASE, 2)
    assert len(plan.tours) == 2
    mtsp.clear_cache(disk=False)


def test_clear_cache_deletes_the_stored_plans(cache: Cache) -> None:
    plan_for(BASE, 2)
    plan_for(BASE, 3)
    assert mtsp.clear_cache() == 2
    assert not list(cache.dir.glob("*.json"))


def test_plan_for_names_the_setting_when_no_plan_exists(cache: Cache) -> None:
    with pytest.raises(ConfigError, match="1 to 64 drones"):
        plan_for(BASE, 65)
    with pytest.raises(ConfigError, match=r"mtsp.min_cells must be at most 10"):
        plan_for(BASE.replace(min_cells=11), 6)


# -- planners ---------------------------------------------------------------------------------


def test_mtsp_planner_routes_every_drone_through_the_plan(cache: Cache) -> None:
    mission = BASE.replace(planner="mtsp", drones=5)
    steering = get_planner("mtsp").steering(mission)
    plan = plan_for(mission, 5)
    assert len(steering.routes) == 5
    for route, expected in zip(steering.routes, plan.routes(), strict=True):
        np.testing.assert_array_equal(route, expected)
    assert not steering.distributed(5).any()


@pytest.mark.parametrize(("drones", "planned"), [(10, 6), (4, 4), (6, 6)])
def test_mtsp_conb_planner_reserves_nr_drones_for_the_plan(cache: Cache, drones: int,
                                                           planned: int) -> None:
    mission = BASE.replace(planner="mtsp-conb", drones=drones, nr=6)
    steering = get_planner("mtsp-conb").steering(mission)
    assert steering.rule is CONB
    assert len(steering.routes) == planned  # the drones past the routes run ConB
    covered = sorted(i for tour in plan_for(mission, planned).tours for i in tour)
    assert covered == list(range(64))
    for i, route in enumerate(steering.routes):
        assert route.shape[1] == 2
        assert (len(route) > 0) == (i < planned)
        if len(route):
            assert tuple(route[-1]) == BS
    np.testing.assert_array_equal(steering.distributed(drones), np.arange(drones) >= planned)
