"""What a polygon area costs: ms per run on the example valley against the paper's square.

Full runs (t_d = 1800 s, r_c = 1000 m, the default reading), one process, CPU time, the same
run indices; the valley (examples/valley.geojson, 14 edges, one hole) with its prior. The
polygon's boundary rule tests every increment of a searching drone against every edge, and a
drone flying home looks for the way round the hole, so a run costs more than on the square.
Run with

    python benchmarks/bench_missions.py --out benchmarks/results/missions.md
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import results_file
from sarlink import Mission, prepare

ROOT = Path(__file__).resolve().parents[1]


def ms_per_run(mission: Mission, runs: int) -> float:
    prepared = prepare(mission)
    prepared.run(0, 0)  # compile or load the cache outside the timing
    start = time.process_time()
    for run in range(runs):
        prepared.run(1, run)
    return (time.process_time() - start) / runs * 1e3


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=100)
    parser.add_argument("--out", type=Path, default=None, help="write a Markdown table here")
    args = parser.parse_args()
    region = {"area": str(ROOT / "examples/valley.geojson"),
              "prior": str(ROOT / "examples/valley-prior.geojson")}
    rows = []
    for planner, drones in (("covb", 10), ("conb", 10), ("mtsp-conb", 10), ("covb", 22)):
        base = {"team": {"planner": planner, "drones": drones}, "channel": {"rc": 1000.0},
                "timing": {"horizon": 1800.0}}
        square = ms_per_run(Mission.from_dict(base), args.runs)
        valley = ms_per_run(Mission.from_dict({**base, "region": region}), args.runs)
        rows.append((planner, drones, square, valley))
        print(f"{planner:10s} N={drones:2d}: square {square:6.2f} ms/run, valley "
              f"{valley:6.2f} ms/run ({valley / square:.2f}x)", flush=True)
    lines = [
        "CPU time, one process; t_d = 1800 s, r_c = 1000 m.",
        "",
        "| planner | N | square, ms per run | valley, ms per run | ratio |",
        "|---|---|---|---|---|",
        *(f"| {p} | {n} | {s:.2f} | {v:.2f} | {v / s:.2f} |" for p, n, s, v in rows),
    ]
    if args.out is not None:
        results_file.write(args.out, "Polygon areas", "\n".join(lines))


if __name__ == "__main__":
    main()
