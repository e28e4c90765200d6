"""Sweep layer: overhead over pure kernel time, and the speed-up of 2 workers over 1.

A sweep of 20,000 runs (the paper's setting: 10 drones, 4000 s; CovB and ConB x r_c 500 and
1000 m, 5000 runs each) is timed against the bare kernel doing the same runs on as many cores:

- bare kernel on ``w`` cores: ``w`` processes, started and warmed up beforehand, each call
  ``prepare`` once per grid point and ``Prepared.run`` for an equal share of the runs, and
  nothing else; the wall time from a common start to the last one's end;
- ``sweep`` with ``w`` workers, from the call to the returned DataFrame: worker start-up,
  tasks, result rows, transfer, Parquet files, the DataFrame.

Overhead with ``w`` workers = sweep wall time / bare-kernel wall time on ``w`` cores - 1: what
the sweep layer adds. Comparing with the kernel on as many cores (not with one core times
``w``) keeps out what the machine itself loses when all its cores are busy. Run with

    python benchmarks/bench_sweep.py --out benchmarks/results/sweep.md

Targets: overhead < 5%; 2 workers >= 1.8x faster than 1 on 2 cores. Other programs
on the machine, and a virtual machine's neighbours, slow phases down unevenly. So the phases
run ``--repeats`` times, interleaved, and the fastest of each counts; the report gives, per
phase, the CPU time the rest of the machine used meanwhile (from /proc/stat, Linux) and the
time stolen by the hypervisor; and each step the sweep adds to a run is also timed alone.
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import pickle
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Any

import results_file
from sarlink import Experiment, prepare, sweep
from sarlink.storage import open_store, run_table


def _machine() -> tuple[float, float]:
    """Busy and stolen CPU seconds of the whole machine so far (0, 0 without /proc/stat)."""
    stat = Path("/proc/stat")
    if not stat.exists():
        return 0.0, 0.0
    user, nice, system, _, _, irq, softirq, steal = map(
        int, stat.read_text().split("\n", 1)[0].split()[1:9])
    tick = os.sysconf("SC_CLK_TCK")
    return (user + nice + system + irq + softirq) / tick, steal / tick


@dataclass(frozen=True)
class Phase:
    wall: float
    others: float
    """CPU seconds used meanwhile by the rest of the machine (beyond our ``cores``)"""
    stolen: float


def measure(work: Callable[[], float | None], cores: int) -> Phase:
    """Time ``work``; it may return its own, more exact wall time."""
    start, (busy, steal) = time.perf_counter(), _machine()
    inner = work()
    wall = time.perf_counter() - start
    busy_after, steal_after = _machine()
    others = max(busy_after - busy - cores * wall, 0.0)  # our processes keep `cores` busy
    return Phase(wall if inner is None else inner, others, steal_after - steal)


def _kernel_share(experiment_json: str, share: int, of: int, barrier: Any, spans: Any) -> None:
    """Runs ``share, share + of, ...`` of every grid point, after a common start."""
    experiment = Experiment.model_validate_json(experiment_json)
    prepared = [prepare(mission) for _, mission in experiment.points()]
    for p in prepared:
        p.run(0, 0)  # load the Numba cache before the start
    barrier.wait()
    start, cpu = time.monotonic(), time.process_time()
    for p in prepared:
        for run in range(share, experiment.runs, of):
            p.run(experiment.seed, run)
    spans.put((start, time.monotonic(), time.process_time() - cpu))


def bare_kernel(experiment: Experiment, cores: int) -> tuple[float, float]:
    """Wall time and total CPU time of the bare kernel doing the experiment's runs on
    ``cores`` processes."""
    context = multiprocessing.get_context("spawn")
    barrier, spans = context.Barrier(cores), context.Queue()
    procs = [context.Process(target=_kernel_share, args=(
        experiment.model_dump_json(), i, cores, barrier, spans)) for i in range(cores)]
    for proc in procs:
        proc.start()
    done = [spans.get() for _ in procs]
    for proc in procs:
        proc.join()
    return max(end for _, end, _ in done) - min(s for s, _, _ in done), sum(c for *_, c in done)


def run_sweep(experiment: Experiment, out: Path, workers: int) -> None:
    df = sweep(experiment, out, workers=workers, progress=False)
    assert len(df) == experiment.runs * len(experiment.points())


def per_run_costs(experiment: Experiment, repeats: int = 20) -> dict[str, float]:
    """CPU seconds per run of each step the sweep layer adds to a run, measured one by one.

    Robust to other programs where the differences of whole phases are not: each step is
    short, timed alone, and the fastest of ``repeats`` chunks is kept.
    """
    runs = experiment.chunk
    _, mission = experiment.points()[0]
    prepared = prepare(mission)
    results = [prepared.run(experiment.seed, k) for k in range(runs)]
    table = run_table(mission, experiment.seed, results)
    best: dict[str, float] = {}
    with tempfile.TemporaryDirectory() as tmp, open_store(tmp, experiment) as store:
        steps: dict[str, Callable[[], object]] = {
            "runs to an Arrow table (storage.run_table)": lambda: run_table(
                mission, experiment.seed, results),
            "table to the sweeping process (pickle both ways)": lambda: pickle.loads(
                pickle.dumps(table)),
            "Parquet file, atomic, fsync (Store.write)": lambda: store.write(
                store.points[0], range(runs), table),
        }
        for name, step in steps.items():
            times = []
            for _ in range(repeats):
                start = time.process_time()
                step()
                times.append(time.process_time() - start)
            best[name] = min(times) / runs
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5000, help="runs per grid point (4 points)")
    parser.add_argument("--repeats", type=int, default=3,
                        help="interleaved rounds of every phase; the fastest of each counts")
    parser.add_argument("--out", type=Path, default=None, help="write a Markdown report here")
    args = parser.parse_args()

    experiment = Experiment.from_dict({
        "name": "bench", "seed": 1, "runs": args.runs,
        "mission": {"team": {"drones": 10}, "timing": {"horizon": 4000.0}},
        "grid": {"planner": ["covb", "conb"], "rc": [500.0, 1000.0]},
    })
    total = args.runs * len(experiment.points())
    kernel_cpu = float("inf")
    samples: dict[str, list[Phase]] = {}
    size = 0

    def sample(name: str, work: Callable[[], float | None], cores: int) -> None:
        samples.setdefault(name, []).append(measure(work, cores))

    def kernel(cores: int) -> float:
        nonlocal kernel_cpu
        wall, cpu = bare_kernel(experiment, cores)
        kernel_cpu = min(kernel_cpu, cpu)
        return wall

    for _ in range(args.repeats):  # interleaved, so that a slow spell hits every phase alike
        for workers in (1, 2):
            sample(f"bare kernel, {workers} core{'s' * (workers > 1)}",
                   partial(kernel, workers), workers)
            with tempfile.TemporaryDirectory() as tmp:
                again = partial(run_sweep, experiment, Path(tmp), workers)
                sample(f"sweep, {workers} worker{'s' * (workers > 1)}", again, workers)
                if workers == 2:
                    sample("resume of the finished sweep (check every file)", again, 1)
                    size = sum(p.stat().st_size for p in Path(tmp).rglob("*.parquet"))
        with tempfile.TemporaryDirectory() as tmp:
            sample("start-up: a sweep of 1 run per point, 2 workers", partial(
                run_sweep, experiment.model_copy(update={"runs": 1}), Path(tmp), 2), 2)
        print({name: round(s[-1].wall, 1) for name, s in samples.items()}, flush=True)
    best = {name: min(s, key=lambda p: p.wall) for name, s in samples.items()}
    walls = {w: (best[f"bare kernel, {w} core{'s' * (w > 1)}"].wall,
                 best[f"sweep, {w} worker{'s' * (w > 1)}"].wall) for w in (1, 2)}
    costs = per_run_costs(experiment)

    lines = [
        f"{total:,} runs: CovB and ConB x r_c 500 and 1000 m, 10 drones, 4000 s, chunks of "
        f"{experiment.chunk} runs; bare kernel {kernel_cpu / total * 1e3:.2f} ms CPU per run. "
        f"Every phase ran {args.repeats} times, interleaved; the fastest counts.",
        "",
        "| phase | wall (s), fastest | CPU of the rest of the machine (s) | stolen (s) "
        "| all walls (s) |",
        "|---|---|---|---|---|",
        *(f"| {name} | {p.wall:.1f} | {p.others:.1f} | {p.stolen:.1f} | "
          f"{', '.join(f'{q.wall:.1f}' for q in samples[name])} |" for name, p in best.items()),
        "",
        "| result | 1 worker | 2 workers | target |",
        "|---|---|---|---|",
        "| overhead: sweep wall / bare-kernel wall on as many cores - 1 | "
        + " | ".join(f"{sweep_wall / bare - 1:+.1%}" for bare, sweep_wall in walls.values())
        + " | < 5% |",
        "| runs per second | " + " | ".join(f"{total / s:,.0f}" for _, s in walls.values())
        + " | |",
        f"| speed-up of the sweep, 2 workers over 1 | | {walls[1][1] / walls[2][1]:.2f}x "
        "| >= 1.8x |",
        f"| speed-up of the bare kernel, 2 cores over 1 | | {walls[1][0] / walls[2][0]:.2f}x | |",
        "",
        f"Parquet on disk: {size / 2**20:.1f} MiB ({size / total:,.0f} bytes per run).",
        "",
        f"Per-run work of the sweep layer, each step timed alone (fastest of 20 chunks of "
        f"{experiment.chunk} runs, CPU time), against the bare kernel's CPU time per run:",
        "",
        "| step | µs per run | share of the kernel |",
        "|---|---|---|",
        *(f"| {name} | {cost * 1e6:.1f} | {cost * total / kernel_cpu:.2%} |"
          for name, cost in costs.items()),
        f"| all | {sum(costs.values()) * 1e6:.1f} "
        f"| {sum(costs.values()) * total / kernel_cpu:.2%} |",
        "",
    ]
    print("\n".join(lines))
    if args.out is not None:
        results_file.write(args.out, "Sweep benchmark", "\n".join(lines))


if __name__ == "__main__":
    main()
