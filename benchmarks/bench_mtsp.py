"""mTSP solvers: GA speed, plan quality of the GA and OR-Tools, and the strong min-max solver.

The paper's grid (64 cells of 500 m, BS at the centre), minimum cells floor(64 / N). Run with

    python benchmarks/bench_mtsp.py --out benchmarks/results/mtsp.md --reference-time 15

Targets: the GA's 80 x 5000 on 64 cells in about a second after compilation (issue 3); OR-Tools'
min-max plans within 1 % of the best known longest tour for every N from 2 to 22, in a few
seconds (issue 16). The best known is the shortest longest tour found by any plan this script
makes (GA and OR-Tools, both objectives, and a longer OR-Tools run of --reference-time s),
never below the floor: twice the distance from the BS to the farthest cell centre.
"""

from __future__ import annotations

import argparse
import platform
import statistics
import time
from importlib.metadata import version
from pathlib import Path

from sarlink.mtsp import ORTOOLS_TIME_LIMIT, grid_cells, solve
from sarlink.mtsp.plan import distance_matrix

CELLS = grid_cells(4000.0, 500.0)
BS = (2000.0, 2000.0)
RUNS = (("ga", "minsum"), ("ga", "minmax"), ("ortools", "minsum"), ("ortools", "minmax"))
FLOOR = 2 * float(distance_matrix(CELLS, BS)[0].max())
"""No tour can be shorter than the round trip to the farthest cell: a floor for every N."""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="timed GA solves for the speed")
    parser.add_argument("--time-limit", type=float, default=ORTOOLS_TIME_LIMIT,
                        help="OR-Tools search time per plan, s")
    parser.add_argument("--reference-time", type=float, default=0.0,
                        help="seconds of a longer OR-Tools min-max run per N for the best "
                             "known (0: none)")
    parser.add_argument("--out", type=Path, default=None, help="write a Markdown table here")
    args = parser.parse_args()

    solve(CELLS, BS, 6, iterations=10)  # compile or load the Numba cache outside the timing
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
                         time_limit=args.time_limit)
            found.setdefault(drones, []).append(plan.longest)
            cells.append(f"{plan.total / 1000:.2f} / {plan.longest / 1000:.2f}, "
                         f"{plan.seconds:.2f}")
        lines.append("| " + " | ".join(cells) + " |")
        print(lines[-1], flush=True)

    strong = ["| N | longest (m) | s | best known (m) | above best known | above floor |",
              "|---:|---:|---:|---:|---:|---:|"]
    for drones in range(2, 23):
        plan = solve(CELLS, BS, drones, solver="ortools", objective="minmax",
                     time_limit=args.time_limit)
        known = [*found.get(drones, []), plan.longest]
        if args.reference_time > 0:
            known.append(solve(CELLS, BS, drones, solver="ortools", objective="minmax",
                               time_limit=args.reference_time).longest)
        best = min(known)
        strong.append(f"| {drones} | {plan.longest:.0f} | {plan.seconds:.2f} | {best:.0f} | "
                      f"{plan.longest / best - 1:.2%} | {plan.longest / FLOOR - 1:.2%} |")
        print(strong[-1], flush=True)

    text = "\n".join([
        f"mTSP benchmark: `python benchmarks/bench_mtsp.py --time-limit {args.time_limit:g}` on "
        f"{platform.processor() or platform.machine()}, Python {platform.python_version()}, "
        f"numba {version('numba')}, ortools {version('ortools')}.",
        "",
        speed,
        "",
        "Plans on the paper's grid, BS at the centre, minimum cells floor(64 / N). GA: seed 0; "
        f"OR-Tools: {args.time_limit:g} s of guided local search per plan. The longest tour at "
        "5 m/s is the search time (20 km = 4000 s).",
        "",
        *lines,
        "",
        f"The strong solver, OR-Tools min-max with {args.time_limit:g} s per plan, for every N. "
        f"Floor: {FLOOR:.0f} m. Best known: the shortest longest tour of any plan above for "
        "that N" + (f" and of an OR-Tools min-max run of {args.reference_time:g} s"
                    if args.reference_time > 0 else "") + ".",
        "",
        *strong,
        "",
    ])
    if args.out is not None:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(text)
        print(f"written to {args.out}")


if __name__ == "__main__":
    main()
