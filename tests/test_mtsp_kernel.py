"""The GA kernel reuses costs, yet its plans are the plain kernel's, bit for bit.

Two independent references: the kernel as it was (``tests/ga_reference.py``, every child costed
afresh), compared on random instances, and plans made by main's own code and stored in
``tests/ga_main_plans.json``, compared on the paper's grid through ``solve`` and a run's own
routes (``readings.mtsp_plan = per-run``). That file was written by main (ab53e80) with

    NUMBA_CACHE_DIR=/tmp/numba-main /work/main/.venv/bin/python tests/test_mtsp_kernel.py \\
        tests/ga_main_plans.json
"""

from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from ga_reference import ga_kernel as reference_kernel

MAIN_PLANS = Path(__file__).with_name("ga_main_plans.json")
PAPER_CASES = [(n, objective, seed) for n in (2, 10, 16, 22) for objective in ("minsum", "minmax")
               for seed in (0, 7)]
"""The paper's grid (64 cells, BS at the centre): N = 2 and 16 leave the breaks no freedom."""
RUN_CASES = [("mtsp", 2, 0, 0), ("mtsp", 10, 0, 1), ("mtsp", 22, 3, 5), ("mtsp-conb", 10, 0, 2)]
"""(planner, drones, seed, run) of a run's own routes under the default reading."""


def _digest(arrays: Any) -> str:
    return hashlib.sha256(b"".join(np.ascontiguousarray(a, dtype=float).tobytes()
                                   for a in arrays)).hexdigest()


def _main_plans() -> dict[str, Any]:
    """What main's code plans on the paper's grid (run under any sarlink that has ``solve``)."""
    from sarlink import Mission
    from sarlink.mtsp import grid_cells, solve
    from sarlink.planners.base import _own_routes
    from sarlink.planners.registry import get_planner

    cells = grid_cells(4000.0, 500.0)
    plans = [{"drones": n, "objective": objective, "seed": seed,
              **_plan_record(solve(cells, (2000.0, 2000.0), n, objective=objective, seed=seed))}
             for n, objective, seed in PAPER_CASES]
    runs = []
    for planner, drones, seed, run in RUN_CASES:
        mission = Mission.build(drones=drones, planner=planner)
        routes = _own_routes(get_planner(planner), mission, seed, run)
        runs.append({"planner": planner, "drones": drones, "seed": seed, "run": run,
                     "reading": mission.readings.mtsp_plan, "routes_sha256": _digest(routes)})
    return {"plans": plans, "runs": runs}


def _plan_record(plan: Any) -> dict[str, Any]:
    return {"tours": [list(t) for t in plan.tours],
            "history_sha256": hashlib.sha256(plan.history.tobytes()).hexdigest()}


@st.composite
def instances(draw: st.DrawFn) -> tuple[np.ndarray, int, int, int, int, bool, int]:
    """Random cities (on a small grid, so that equal distances and ties occur, or anywhere),
    salesmen, min_cells, population, iterations, objective and seed."""
    from sarlink.mtsp import grid_cells
    from sarlink.mtsp.plan import distance_matrix

    if draw(st.booleans()):
        side = draw(st.integers(2, 6))
        points = grid_cells(side * 100.0, 100.0)
    else:
        k = draw(st.integers(1, 30))
        points = np.array(draw(st.lists(st.tuples(st.floats(0, 1000), st.floats(0, 1000)),
                                        min_size=k, max_size=k)))
    k = len(points)
    salesmen = draw(st.integers(1, min(k, 8)))
    min_cells = draw(st.integers(1, k // salesmen))
    depot = (draw(st.floats(0, 1000)), draw(st.floats(0, 1000)))
    return (distance_matrix(points, depot), salesmen, min_cells, 8 * draw(st.integers(1, 4)),
            draw(st.integers(1, 80)), draw(st.booleans()), draw(st.integers(0, 2**63 - 1)))


def _both(dmat: np.ndarray, salesmen: int, min_cells: int, population: int, iterations: int,
          minmax: bool, seed: int) -> tuple[Any, Any]:
    from sarlink.mtsp.ga import _ga_kernel

    args = (dmat, salesmen, min_cells, population, iterations, minmax)
    return (_ga_kernel(*args, np.random.default_rng(seed)),
            reference_kernel(*args, np.random.default_rng(seed)))


def _assert_same(new: Any, old: Any) -> None:
    for name, a, b in zip(("route", "breaks", "history"), new[:3], old, strict=True):
        assert np.array_equal(a, b), name
    assert new[2].tobytes() == old[2].tobytes()  # the history bit for bit (-0.0, NaN aside)


@given(instances())
def test_the_kernel_plans_as_the_plain_kernel_on_random_instances(
        instance: tuple[np.ndarray, int, int, int, int, bool, int]) -> None:
    new, old = _both(*instance)
    _assert_same(new, old)
    _, _, _, population, iterations, _, _ = instance
    assert new[3] == population * iterations  # Kirk's evaluations (Fig. 1's work count)


@pytest.mark.parametrize("salesmen", [2, 5, 10, 16, 22, 40])
@pytest.mark.parametrize("minmax", [False, True])
def test_the_kernel_plans_as_the_plain_kernel_on_the_paper_grid(salesmen: int,
                                                               minmax: bool) -> None:
    """The paper's 80 x 5000, with min_cells floor(64 / N) (N = 40: min_cells 1, the uniform
    breaks) and with min_cells 1."""
    from sarlink.mtsp import grid_cells
    from sarlink.mtsp.plan import distance_matrix

    dmat = distance_matrix(grid_cells(4000.0, 500.0), (2000.0, 2000.0))
    for min_cells in sorted({64 // salesmen, 1}):
        _assert_same(*_both(dmat, salesmen, min_cells, 80, 5000, minmax, 100 + salesmen))


def test_solve_makes_the_plans_main_made() -> None:
    from sarlink.mtsp import grid_cells, solve

    stored = json.loads(MAIN_PLANS.read_text())["plans"]
    assert [(p["drones"], p["objective"], p["seed"]) for p in stored] == PAPER_CASES
    cells = grid_cells(4000.0, 500.0)
    for p in stored:
        plan = solve(cells, (2000.0, 2000.0), p["drones"], objective=p["objective"],
                     seed=p["seed"])
        assert _plan_record(plan) == {k: p[k] for k in ("tours", "history_sha256")}, p


def test_a_run_flies_the_routes_main_gave_it(tmp_path: Path,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    from sarlink import Mission
    from sarlink.planners.base import _own_routes
    from sarlink.planners.registry import get_planner

    stored = json.loads(MAIN_PLANS.read_text())["runs"]
    assert [(r["planner"], r["drones"], r["seed"], r["run"]) for r in stored] == RUN_CASES
    monkeypatch.setenv("SARLINK_CACHE_DIR", str(tmp_path))  # solved here, not read from disk
    for r in stored:
        mission = Mission.build(drones=r["drones"], planner=r["planner"])
        assert mission.readings.mtsp_plan == r["reading"] == "per-run"
        routes = _own_routes(get_planner(r["planner"]), mission, r["seed"], r["run"])
        assert _digest(routes) == r["routes_sha256"], r


if __name__ == "__main__":
    made = _main_plans()
    Path(sys.argv[1]).write_text("{\n" + ",\n".join(
        f' "{key}": [\n' + ",\n".join(f"  {json.dumps(r)}" for r in made[key]) + "\n ]"
        for key in made) + "\n}\n")
