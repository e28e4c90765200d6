"""mTSP plans for the centralized planners (Section 3.1.1 of the paper; docs/mtsp.md).

The search area is cut into square cells whose centres are the cities (:mod:`.grid`); a multiple
travelling salesmen plan sends every drone from the base station (BS, the depot) through its own
cells and back (:mod:`.plan`). :func:`solve` checks the arguments and hands them to a solver:

``ga`` (:mod:`.ga`)
    The paper's genetic algorithm, after Joseph Kirk's MATLAB ``mtspf_ga``, compiled with Numba:
    faithful, seeded, a tenth of a second for 80 × 5000 on 64 cells.
``ortools`` (:mod:`.ortools`, :mod:`.ruin`)
    The strong solver to measure the GA against: OR-Tools routing with guided local search for
    ``minsum``, a seeded ruin-and-recreate search for ``minmax`` (where OR-Tools stalls).

Every solver stops at a budget (GA iterations, OR-Tools solutions, ruin-and-recreate steps:
:func:`budget_of`), never at a time, so a plan is a function of its inputs and seed only.
:func:`plan_for` makes each mission's plan once and caches it on disk (:mod:`.cache`).
"""

from sarlink.mtsp.cache import CACHE_VERSION, cache_dir, clear_cache, plan_for, solve_for
from sarlink.mtsp.clip import area_cells, flyable
from sarlink.mtsp.grid import grid_cells
from sarlink.mtsp.ortools import ORTOOLS_SOLUTIONS
from sarlink.mtsp.plan import MtspPlan, Objective, Solver
from sarlink.mtsp.ruin import RUIN_ITERATIONS
from sarlink.mtsp.solvers import budget_of, solve

__all__ = [
    "CACHE_VERSION",
    "ORTOOLS_SOLUTIONS",
    "RUIN_ITERATIONS",
    "MtspPlan",
    "Objective",
    "Solver",
    "area_cells",
    "budget_of",
    "cache_dir",
    "clear_cache",
    "flyable",
    "grid_cells",
    "plan_for",
    "solve",
    "solve_for",
]
