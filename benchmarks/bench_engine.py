"""Engine speed: drone-steps per second per core, and the speed-up over the slow reference.

Full 4000 s runs of the paper's setting, r_c = 1000 m, one process, CPU time. Run with

    python benchmarks/bench_engine.py --out benchmarks/results/engine.md

Targets: CovB >= 15 M and ConB >= 8 M drone-steps/s/core at N = 22; >= 200x the
reference. The reference is timed on a few runs; the engine on the same runs and more.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable
from functools import partial
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import results_file
from naive import simulate_naive
from sarlink import Mission, prepare


def cpu_seconds_per_run(run_one: Callable[[int], object], runs: range) -> float:
    start = time.process_time()
    for run in runs:
        run_one(run)
    return (time.process_time() - start) / len(runs)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=200, help="engine runs per configuration")
    parser.add_argument("--reference-runs", type=int, default=2)
    parser.add_argument("--out", type=Path, default=None, help="write a Markdown table here")
    args = parser.parse_args()

    rows = []
    for planner in ("covb", "conb"):
        for drones in (10, 22):
            mission = Mission.build(planner=planner, drones=drones, rc=1000.0)
            prepared = prepare(mission)
            prepared.run(0, 0)  # compile or load the cache outside the timing
            steps = mission.n_steps * drones
            fast_run = partial(prepared.run, 1)
            engine = cpu_seconds_per_run(fast_run, range(args.runs))
            same = range(args.reference_runs)
            engine_same = cpu_seconds_per_run(fast_run, same)
            slow = cpu_seconds_per_run(partial(simulate_naive, mission, 1), same)
            rows.append((planner, drones, steps / engine / 1e6, engine * 1e3, slow,
                         slow / engine_same))
            print(f"{planner:6s} N={drones:2d}: {rows[-1][2]:6.2f} M drone-steps/s/core, "
                  f"{rows[-1][3]:6.2f} ms/run, reference {slow:.2f} s/run, "
                  f"speed-up {rows[-1][5]:.0f}x", flush=True)

    lines = [
        "| planner | N | M drone-steps/s/core | ms per 4000 s run | reference s/run | speed-up |",
        "|---|---|---|---|---|---|",
        *(f"| {p} | {n} | {rate:.2f} | {ms:.2f} | {slow:.2f} | {up:.0f}x |"
          for p, n, rate, ms, slow, up in rows),
    ]
    if args.out:
        results_file.write(args.out, "Engine benchmark", "\n".join(lines))


if __name__ == "__main__":
    main()
