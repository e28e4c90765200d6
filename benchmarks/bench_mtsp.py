"""mTSP solvers: GA speed, and plan quality of the GA and OR-Tools for 2 to 22 drones.

The paper's grid (64 cells of 500 m, BS at the centre), minimum cells floor(64 / N). Run with

    python benchmarks/bench_mtsp.py --out benchmarks/results/mtsp.md

Target (issue 3): the GA's 80 x 5000 on 64 cells in about a second after compilation.
"""

from __future__ import annotations

import argparse
import platform
import statistics
import time
from importlib.metadata import version
from pathlib import Path

from sarlink.mtsp import ORTOOLS_TIME_LIMIT, grid_cells, solve

CELLS = grid_cells(4000.0, 500.0)
BS = (2000.0, 2000.0)
RUNS = (("ga", "minsum"), ("ga", "minmax"), ("ortools", "minsum"), ("ortools", "minmax"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="timed GA solves for the speed")
    parser.add_argument("--time-limit", type=float, default=ORTOOLS_TIME_LIMIT,
                        help="OR-Tools search time per plan, s")
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
    for drones in range(2, 23, 2):
        cells = [str(drones)]
        for solver, objective in RUNS:
            plan = solve(CELLS, BS, drones, solver=solver, objective=objective,
                         time_limit=args.time_limit)
            cells.append(f"{plan.total / 1000:.2f} / {plan.longest / 1000:.2f}, "
                         f"{plan.seconds:.2f}")
        lines.append("| " + " | ".join(cells) + " |")
        print(lines[-1], flush=True)

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
    ])
    if args.out is not None:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(text)
        print(f"written to {args.out}")


if __name__ == "__main__":
    main()
