"""mTSP solvers: GA speed, plan quality of the GA and the strong solver, and the strong solver's
min-max plans for every team size.

The paper's grid (64 cells of 500 m, BS at the centre), minimum cells floor(64 / N). Run with

    python benchmarks/bench_mtsp.py --seeds 5 --busy --out benchmarks/results/mtsp.md

Targets: the GA's 80 x 5000 on 64 cells in about a second after compilation; the strong
solver's (``ortools``) min-max plans within 1 % of the best known longest tour for every N from
2 to 22, within a budget of steps that takes at most 3 s per plan on 2 cores, and the same plan
whatever the load (``--busy`` solves seed 0 again with a process
spinning on every other core and compares the tours). The best known is the shortest longest
tour of :data:`BEST_KNOWN` and of every plan this script makes, never below the floor: twice
the distance from the BS to the farthest cell centre.
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import statistics
import time
from collections.abc import Iterator
from contextlib import contextmanager
from importlib.metadata import version
from pathlib import Path
from typing import Any

import results_file
from sarlink.mtsp import ORTOOLS_SOLUTIONS, RUIN_ITERATIONS, MtspPlan, grid_cells, solve
from sarlink.mtsp.plan import distance_matrix

CELLS = grid_cells(4000.0, 500.0)
BS = (2000.0, 2000.0)
RUNS = (("ga", "minsum"), ("ga", "minmax"), ("ortools", "minsum"), ("ortools", "minmax"))
FLOOR = 2 * float(distance_matrix(CELLS, BS)[0].max())
"""No tour can be shorter than the round trip to the farthest cell: a floor for every N."""

BEST_KNOWN = {
    2: 16207.1, 3: 11207.1, 4: 8644.1, 5: 7351.2, 6: 6351.2, 7: 6058.3, 8: 5725.5, 9: 5479.5,
    10: 5343.5, 11: 5312.5, 12: 5068.2, 13: 4955.4, **{n: FLOOR for n in range(14, 23)},
}
"""Shortest longest tour (m) known for N drones: the best plan of the long runs recorded in
benchmarks/results/mtsp.md, with their tours (the ruin-and-recreate search with 10 x 300,000
iterations and OR-Tools' routing for up to 60 s; 5,343.5 m for N = 10 is the issue's 5,344 m);
N >= 14 reach the floor. Upper bounds on the optimum, rounded down to 0.1 m; a shorter plan of
this script's own is taken instead."""


LONG_RUNS = "## Best known: the long runs"
"""Heading of the part of the --out file that records how BEST_KNOWN was found; rewriting the
file keeps it."""


def _spin() -> None:
    while True:
        pass


@contextmanager
def busy(on: bool) -> Iterator[None]:
    """With ``on``, keep every core but one busy (a spinning process each) meanwhile."""
    procs = [multiprocessing.Process(target=_spin, daemon=True)
             for _ in range(max(1, (os.cpu_count() or 2) - 1) if on else 0)]
    for proc in procs:
        proc.start()
    try:
        yield
    finally:
        for proc in procs:
            proc.terminate()
            proc.join()


def timed(drones: int, **kwargs: Any) -> tuple[MtspPlan, float]:
    """A plan of the paper's grid and the CPU time of its solve, s (the plan's own
    ``seconds`` is wall time)."""
    start = time.process_time()
    plan = solve(CELLS, BS, drones, **kwargs)
    return plan, time.process_time() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="timed GA solves for the speed")
    parser.add_argument("--budget", type=int, default=None,
                        help="strong solver's budget: OR-Tools solutions (minsum), steps per "
                             "ruin-and-recreate search (minmax); default the solver's")
    parser.add_argument("--seeds", type=int, default=1,
                        help="min-max plans per N with plan seeds 0..SEEDS-1; the table shows "
                             "seed 0 and the worst")
    parser.add_argument("--busy", action="store_true",
                        help="solve each min-max plan of seed 0 again with the other cores "
                             "busy and compare the tours")
    parser.add_argument("--out", type=Path, default=None, help="write a Markdown table here")
    args = parser.parse_args()

    solve(CELLS, BS, 6, iterations=10)  # compile or load the Numba caches outside the timing
    solve(CELLS, BS, 6, solver="ortools", objective="minmax", budget=10)
    times = []
    for seed in range(args.repeats):
        start = time.perf_counter()
        solve(CELLS, BS, 6, seed=seed)
        times.append(time.perf_counter() - start)
    speed = (f"GA, population 80 x 5000 iterations, 64 cells, 6 drones: median "
             f"{statistics.median(times):.3f} s, best {min(times):.3f} s over {args.repeats} "
             f"seeds (after compilation).")
    print(speed, flush=True)

    header = ["N"] + [f"{s} {o}: total / longest (km), s" for s, o in RUNS]
    lines = ["| " + " | ".join(header) + " |", "|" + "---:|" * len(header)]
    found: dict[int, list[float]] = {}
    for drones in range(2, 23, 2):
        cells = [str(drones)]
        for solver, objective in RUNS:
            plan = solve(CELLS, BS, drones, solver=solver, objective=objective,
                         budget=args.budget)
            found.setdefault(drones, []).append(plan.longest)
            cells.append(f"{plan.total / 1000:.2f} / {plan.longest / 1000:.2f}, "
                         f"{plan.seconds:.2f}")
        lines.append("| " + " | ".join(cells) + " |")
        print(lines[-1], flush=True)

    columns = ["N", "longest (m)", "CPU s", "wall s", "best known (m)", "above best known",
               "above floor"]
    if args.seeds > 1:
        columns += [f"worst of seeds 0-{args.seeds - 1} (m)", "worst above best known",
                    "most CPU s"]
    if args.busy:
        columns += ["busy: wall s", "busy: same tours"]
    strong = ["| " + " | ".join(columns) + " |", "|" + "---:|" * len(columns)]
    beaten, differ = [], []
    strong_args = {"solver": "ortools", "objective": "minmax", "budget": args.budget}
    for drones in range(2, 23):
        runs = [timed(drones, seed=seed, **strong_args)
                for seed in range(args.seeds)]
        plans = [plan for plan, _ in runs]
        longest = [p.longest for p in plans]
        best = min(BEST_KNOWN[drones], *found.get(drones, []), *longest)
        if best < BEST_KNOWN[drones] - 0.05:
            beaten.append(f"N = {drones}: {best:.1f} m")
        row = [f"{drones}", f"{longest[0]:.0f}", f"{runs[0][1]:.2f}", f"{plans[0].seconds:.2f}",
               f"{best:.0f}", f"{longest[0] / best - 1:.2%}", f"{longest[0] / FLOOR - 1:.2%}"]
        if args.seeds > 1:
            row += [f"{max(longest):.0f}", f"{max(longest) / best - 1:.2%}",
                    f"{max(cpu for _, cpu in runs):.2f}"]
        if args.busy:
            with busy(True):
                again = solve(CELLS, BS, drones, seed=0, **strong_args)
            same = again.tours == plans[0].tours
            if not same:
                differ.append(str(drones))
            row += [f"{again.seconds:.2f}", "yes" if same else "**no**"]
        strong.append("| " + " | ".join(row) + " |")
        print(strong[-1], flush=True)
    if beaten:
        print("shorter than BEST_KNOWN, update it: " + "; ".join(beaten))
    if differ:
        print("tours differ under load for N = " + ", ".join(differ))

    minsum = f"{args.budget or ORTOOLS_SOLUTIONS:,} solutions"
    minmax = f"3 x {args.budget or RUIN_ITERATIONS:,} steps"
    text = "\n".join([
        f"numba {version('numba')}, ortools {version('ortools')}.",
        "",
        speed,
        "",
        "Plans on the paper's grid, BS at the centre, minimum cells floor(64 / N), seed 0, "
        "wall seconds. "
        f"ortools minsum: OR-Tools' guided local search, {minsum} per plan; "
        f"ortools minmax: the ruin-and-recreate search ({minmax}). The longest "
        "tour at 5 m/s is the search time (20 km = 4000 s).",
        "",
        *lines,
        "",
        "The strong solver's min-max plans (`solver=\"ortools\", objective=\"minmax\"`, "
        f"{minmax}) for every N, plan seed 0"
        + (f" and the worst of seeds 0-{args.seeds - 1}" if args.seeds > 1 else "")
        + f". Floor: {FLOOR:.0f} m. Best known: the shortest of BEST_KNOWN in "
        "bench_mtsp.py (long runs, below) and of every plan of this run. CPU s: the solve's "
        "CPU time; wall s: its wall time on this shared machine"
        + ("; busy: seed 0 solved again with a process spinning on the other core, its wall "
           "time and whether its tours are those of the first solve" if args.busy else "")
        + ".",
        "",
        *strong,
        "",
    ])
    if args.out is not None:
        old = args.out.read_text() if args.out.exists() else ""
        kept = old.find(LONG_RUNS)  # the record of the long runs is not made by this script
        results_file.write(args.out, "mTSP benchmark",
                           text + ("\n" + old[kept:] if kept >= 0 else ""))


if __name__ == "__main__":
    main()
