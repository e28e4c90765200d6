"""Sweep layer: overhead over pure kernel time, and the speed-up of 2 workers over 1.

A sweep of 20,000 runs (the paper's setting: 10 drones, 4000 s; CovB and ConB x r_c 500 and
1000 m, 5000 runs each) is timed three ways:

- kernel: ``prepare`` once per grid point and ``Prepared.run`` per run, in this process, CPU
  time: the work no sweep can avoid;
- ``sweep`` with 1 worker and with 2 workers, from the call to the returned DataFrame: worker
  start-up, task transfer, result rows, Parquet files, progress, and loading the results.

Overhead with ``w`` workers = (wall time x w) / kernel time - 1: the share of the workers'
core time not spent in the kernel. Other programs running on the machine inflate it, so the
CPU time of the sweeping process and of its (finished) workers is reported too, and the
overhead by CPU time = that CPU time / kernel time - 1. Run with

    python benchmarks/bench_sweep.py --out benchmarks/results/sweep.md

Targets (issue 4): overhead < 5%; 2 workers >= 1.8x faster than 1 on 2 cores. The load
average is reported before and after: numbers taken on a busy machine are not comparable.
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import tempfile
import time
from pathlib import Path

from sarlink import Experiment, prepare, sweep


def kernel_seconds(experiment: Experiment) -> float:
    """CPU time of the simulations alone, in this process."""
    start = time.process_time()
    for _, mission in experiment.points():
        prepared = prepare(mission)
        for run in range(experiment.runs):
            prepared.run(experiment.seed, run)
    return time.process_time() - start


def children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed_sweep(experiment: Experiment, out: Path, workers: int) -> tuple[float, float]:
    """Wall time and CPU time (this process and its finished workers) of one sweep."""
    wall, cpu, workers_cpu = time.perf_counter(), time.process_time(), children_cpu()
    df = sweep(experiment, out, workers=workers, progress=False)
    wall = time.perf_counter() - wall
    cpu = time.process_time() - cpu + children_cpu() - workers_cpu
    assert len(df) == experiment.runs * len(experiment.points())
    return wall, cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5000, help="runs per grid point (4 points)")
    parser.add_argument("--out", type=Path, default=None, help="write a Markdown report here")
    args = parser.parse_args()

    experiment = Experiment.from_dict({
        "name": "bench", "seed": 1, "runs": args.runs, "chunk": 50,
        "mission": {"team": {"drones": 10}, "timing": {"horizon": 4000.0}},
        "grid": {"planner": ["covb", "conb"], "rc": [500.0, 1000.0]},
    })
    total = args.runs * len(experiment.points())
    load_before = os.getloadavg()
    for _, mission in experiment.points():  # compile or load the Numba cache outside the timing
        prepare(mission).run(0, 0)
    kernel = kernel_seconds(experiment)
    print(f"kernel: {kernel:.1f} s CPU for {total} runs ({kernel / total * 1e3:.2f} ms/run)",
          flush=True)
    with tempfile.TemporaryDirectory() as tmp:
        start_up, _ = timed_sweep(experiment.model_copy(update={"runs": 1}), Path(tmp), 2)
    times, resume, size = {}, 0.0, 0
    for workers in (1, 2):
        with tempfile.TemporaryDirectory() as tmp:
            times[workers] = timed_sweep(experiment, Path(tmp), workers)
            if workers == 2:
                resume, _ = timed_sweep(experiment, Path(tmp), workers)  # all stored
                size = sum(p.stat().st_size for p in Path(tmp).rglob("*.parquet"))
        wall, cpu = times[workers]
        print(f"sweep, {workers} worker(s): {wall:.1f} s wall, {cpu:.1f} s CPU; overhead "
              f"{wall * workers / kernel - 1:+.1%} by wall time, {cpu / kernel - 1:+.1%} by "
              "CPU time", flush=True)
    load_after = os.getloadavg()
    speedup = times[1][0] / times[2][0]
    print(f"speed-up 2 vs 1 worker: {speedup:.2f}x; start-up {start_up:.1f} s; "
          f"resume of a finished sweep {resume:.1f} s", flush=True)

    lines = [
        f"Sweep benchmark: `python benchmarks/bench_sweep.py --runs {args.runs}` on "
        f"{platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}.",
        "",
        f"{total:,} runs: CovB and ConB x r_c 500 and 1000 m, 10 drones, 4000 s, "
        f"chunks of {experiment.chunk} runs.",
        "",
        "| measure | 1 worker | 2 workers |",
        "|---|---|---|",
        f"| kernel CPU time (prepare + run, one process) | {kernel:.1f} s "
        f"({kernel / total * 1e3:.2f} ms/run) | |",
        "| sweep wall time | " + " | ".join(
            f"{w:.1f} s ({total / w:,.0f} runs/s)" for w, _ in times.values()) + " |",
        "| sweep CPU time, all processes | " + " | ".join(
            f"{c:.1f} s" for _, c in times.values()) + " |",
        "| overhead by wall time (wall x workers / kernel - 1) | " + " | ".join(
            f"{w * n / kernel - 1:+.1%}" for n, (w, _) in times.items()) + " |",
        "| overhead by CPU time (CPU / kernel - 1) | " + " | ".join(
            f"{c / kernel - 1:+.1%}" for _, c in times.values()) + " |",
        f"| speed-up, 2 workers over 1 | | {speedup:.2f}x |",
        "",
        f"- Fixed start-up cost (a sweep of one run per point, 2 workers): {start_up:.1f} s.",
        f"- Resume of the finished sweep (check every file, then load): {resume:.1f} s.",
        f"- Parquet on disk: {size / 2**20:.1f} MiB ({size / total:,.0f} bytes per run).",
        "- Load average (1, 5, 15 min) before / after: "
        f"{' '.join(f'{v:.2f}' for v in load_before)} / "
        f"{' '.join(f'{v:.2f}' for v in load_after)}.",
        "",
    ]
    if args.out is not None:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text("\n".join(lines))
        print(f"written to {args.out}")


if __name__ == "__main__":
    main()
