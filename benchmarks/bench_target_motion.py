"""What a moving target costs and changes (docs/model.md, Target motion): CovB's N_m = 10 at
the paper's setting (r_c = 1000 m) with a still target and with a walking one (the walk's
defaults, half an hour's walk before take-off), the same runs (seed 2024, runs 0 .. RUNS-1,
each kernel compiled and warmed first, the two flown in alternating order). Reports each's
median time per run, the median of the paired ratios, and P(detected) and P(notified) by the
horizon. A walking target keeps a settled team from being carried to the horizon, so part of
its cost is the steps a still target's run skips. Writes
``benchmarks/results/target-motion.md``.

    .venv/bin/python benchmarks/bench_target_motion.py [RUNS]
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path

import results_file
from alternating import fly_alternately

SEED = 2024
CASES = {"still": {}, "walk, 1800 s delay": {"motion": "walk", "delay": 1800.0}}


def main() -> None:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 40
    times, results = fly_alternately(CASES, SEED, runs)
    still, walk = list(CASES)
    ratio = statistics.median(w / s for w, s in zip(times[walk], times[still], strict=True))
    lines = ["| target | median ms per run | P(detected by 4000 s) | P(notified by 4000 s) |",
             "|---|---|---|---|"]
    for name in CASES:
        got = results[name]
        lines.append(f"| {name} | {1000 * statistics.median(times[name]):.1f} | "
                     f"{sum(r.t_detect is not None for r in got) / runs:.2f} | "
                     f"{sum(r.t_notify is not None for r in got) / runs:.2f} |")
    body = "\n".join([
        f"CovB, N_m = 10, r_c = 1000 m, the paper's 4 km square and 4000 s; seed {SEED}, runs "
        f"0-{runs - 1}, flown alternately; the walk's defaults (0.5 m/s, 0.5 rad a minute, "
        "median 4 h mobile), 1800 s between the sighting and take-off.", "", *lines, "",
        f"Median of the paired time ratios walk / still: {ratio:.2f}."])
    results_file.write(Path(__file__).parent / "results" / "target-motion.md",
                       "A moving target: cost and outcome", body)


if __name__ == "__main__":
    main()
