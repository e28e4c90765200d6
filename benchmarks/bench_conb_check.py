"""What ConB's connectivity check at every increment costs against the check once per period.

``conb_check`` is a parameter of the same kernel, so both readings of a case are flown in one
process, run by run in alternating order, and the cost is the median of the paired time ratios
(continuous / period): the host's drift, which moves timings taken minutes apart by tens of
percent, cancels. The two checks fly different trajectories; the ratio is what a run costs
under each. Writes ``benchmarks/results/conb-check.md``. Run with

    python benchmarks/bench_conb_check.py --cases conb:10,conb:22,conb:10:500,conb:22:500
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

import results_file
from sarlink import Mission, prepare
from sarlink.engine.run import Prepared
from sarlink.engine.scenario import draw_scenario
from sarlink.engine.streams import run_streams

RESULTS = Path(__file__).resolve().parent / "results" / "conb-check.md"


def seconds(prepared: Prepared, run: int) -> float:
    """CPU seconds of the kernel for run ``run`` (seed 1) of a prepared mission."""
    streams = run_streams(1, run)
    scenario = draw_scenario(prepared.mission, streams.scenario)
    args = prepared.arguments(streams, scenario)
    kernel = prepared.kernel
    start = time.process_time()
    kernel(*args)
    return time.process_time() - start


def measure(case: str, reading: str, runs: int, rounds: int) -> tuple[float, float, float]:
    """Median ms per run under the continuous and the periodic check, and the median of the
    paired ratios."""
    planner, drones, *rest = case.split(":")
    both = {check: prepare(Mission.build(reading=reading, planner=planner, drones=int(drones),
                                         rc=float(rest[0]) if rest else 1000.0,
                                         conb_check=check))
            for check in ("continuous", "period")}
    for prepared in both.values():
        seconds(prepared, 0)  # compile or load the kernel
    times: dict[str, list[float]] = {"continuous": [], "period": []}
    ratios = []
    for rnd in range(rounds):
        for r in range(runs):
            order = ["continuous", "period"][:: 1 if (rnd + r) % 2 == 0 else -1]
            pair = {check: seconds(both[check], r) for check in order}
            for check, t in pair.items():
                times[check].append(t)
            ratios.append(pair["continuous"] / pair["period"])
    return (1e3 * float(np.median(times["continuous"])), 1e3 * float(np.median(times["period"])),
            float(np.median(ratios)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", default="conb:10,conb:22,conb:10:500,conb:22:500",
                        help="planner:drones[:rc] items, comma-separated")
    parser.add_argument("--reading", default="sarlink-3")
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    lines = ["| case | ms per run, continuous | ms per run, period | continuous / period |",
             "|---|---|---|---|"]
    for case in args.cases.split(","):
        cont, period, ratio = measure(case, args.reading, args.runs, args.rounds)
        lines.append(f"| {case} | {cont:.2f} | {period:.2f} | {ratio:.2f} |")
        print(lines[-1], flush=True)
    results_file.write(
        RESULTS, "ConB's check at every increment against the check once per period",
        f"CPU time of the kernel per 4000 s run under {args.reading} (seed 1, runs "
        f"0-{args.runs - 1}, medians over {args.rounds} rounds), both checks in one process, "
        "pair by pair; the last column is the median of the paired ratios.\n\n"
        + "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
