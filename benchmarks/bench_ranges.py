"""CPU of a sweep over 8 communication ranges against a sweep over one.

A range-free team (here CovB) flies once per run for every range of a grid over ``rc``,
scanned at each range as it flies (:mod:`sarlink.engine.critical_ranges`); a sweep over one
range flies as it always did. This script sweeps CovB over 8 ranges and over one, at the paper's
team sizes, with the sweep's own code (planning, jobs, tables, Parquet files, the experiment's
default chunk) but its jobs run in this process, so that the CPU time is that of the work,
without a worker's start-up; it also sweeps the 8 ranges one by one and checks that the rows
are equal. It also times the engine alone per run: a plain flight, a flight scanned at one
range and at 8, and a traced flight scanned at 8 with the staircase.
Run with

    python benchmarks/bench_ranges.py --runs 400 --out benchmarks/results/ranges.md
"""

from __future__ import annotations

import argparse
import math
import operator
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pandas as pd

import results_file
from inprocess import InProcess
from sarlink import Experiment, Mission, prepare, storage
from sarlink.engine import Prepared
from sarlink.execution import sweep_all
from sarlink.simulation import plugins_in_code

ROUNDS = 31
RANGES = [250.0, 500.0, 750.0, 1000.0, 1250.0, 1500.0, 2000.0, 3000.0]


def experiment(rcs: list[float], runs: int, drones: int) -> Experiment:
    return Experiment.from_dict({"name": "ranges", "seed": 7, "runs": runs,
                                 "mission": {"team": {"planner": "covb", "drones": drones}},
                                 "grid": {"rc": rcs}})


assert not any(plugins_in_code().values())  # nothing to hand to a worker: one process is the same


def timed_sweep(rcs: list[float], runs: int, drones: int, folder: Path) -> tuple[float,
                                                                                 pd.DataFrame]:
    """CPU seconds of a sweep whose jobs run in this process, and its rows."""
    start = time.process_time()
    (rows,) = sweep_all([(experiment(rcs, runs, drones), folder)], progress=False,
                        pool=InProcess())
    return time.process_time() - start, rows


def split_sweep(rcs: list[float], runs: int, drones: int, folder: Path) -> dict[str, float]:
    """CPU seconds of one more sweep (untimed as a whole) spent in the engine's flights and
    readings, in building the result tables, in writing them, and in everything else."""
    spent = {"flights and readings": 0.0, "tables (storage.run_table)": 0.0,
             "Parquet files (Store.write)": 0.0}
    places = [(Prepared, "run", "flights and readings"),
              (Prepared, "run_ranges", "flights and readings"),
              (storage, "run_table", "tables (storage.run_table)"),
              (storage.Store, "write", "Parquet files (Store.write)")]
    originals = [getattr(owner, name) for owner, name, _ in places]

    def timed(work: Callable[..., Any], label: str) -> Callable[..., Any]:
        def run(*args: Any, **kwargs: Any) -> Any:
            start = time.process_time()
            try:
                return work(*args, **kwargs)
            finally:
                spent[label] += time.process_time() - start
        return run

    for (owner, name, label), work in zip(places, originals, strict=True):
        setattr(owner, name, timed(work, label))
    try:
        total, _ = timed_sweep(rcs, runs, drones, folder)
    finally:
        for (owner, name, _), work in zip(places, originals, strict=True):
            setattr(owner, name, work)
    return {**spent, "the rest (rows, planning, loading back)": total - sum(spent.values())}


def engine_ms(drones: int, runs: int) -> list[float]:
    """CPU ms per run: a flight, scanned at one range, at 8 ranges, and at 8 ranges with the
    staircase (the best of three rounds, interleaved)."""
    prepared = prepare(Mission.build(planner="covb", drones=drones, rc=1000.0))
    works = [lambda k: prepared.run(0, k),
             lambda k: prepared.run_ranges(0, k, [1000.0]),
             lambda k: prepared.run_ranges(0, k, RANGES),
             lambda k: prepared.run_ranges(0, k, RANGES, staircase=True)]
    best = [math.inf] * len(works)
    for _ in range(3):
        for w, work in enumerate(works):
            work(0)
            start = time.process_time()
            for k in range(runs):
                work(k)
            best[w] = min(best[w], 1e3 * (time.process_time() - start) / runs)
    return best


def compare(runs: int, drones: int, root: Path) -> dict[str, Any]:
    """The two sweeps' CPU (every round), whether the rows agree, and the engine's times."""
    for rcs in ([1000.0], RANGES):  # compile or load the kernel and the scan
        timed_sweep(rcs, 2, drones, root / f"warm{drones}-{len(rcs)}")
    ones, eights = [], []
    for i in range(ROUNDS):  # the host's speed drifts: interleaved, each first in turn
        if i % 2:
            eight, together = timed_sweep(RANGES, runs, drones, root / f"eight{drones}-{i}")
        ones.append(timed_sweep([1000.0], runs, drones, root / f"one{drones}-{i}")[0])
        if not i % 2:
            eight, together = timed_sweep(RANGES, runs, drones, root / f"eight{drones}-{i}")
        eights.append(eight)
    apart = pd.concat([timed_sweep([rc], runs, drones, root / f"{drones}-{rc:g}")[1]
                       for rc in RANGES])
    key = ["rc", "run"]
    equal = together.drop(columns="point").sort_values(key).reset_index(drop=True).equals(
        apart.drop(columns="point").sort_values(key).reset_index(drop=True))
    return {"ones": ones, "eights": eights, "equal": equal,
            "engine": engine_ms(drones, min(runs, 50))}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=400)
    parser.add_argument("--drones", type=int, nargs="+", default=[4, 10, 22])
    parser.add_argument("--out", type=Path, default=Path("benchmarks/results/ranges.md"))
    args = parser.parse_args()
    chunk = experiment([1000.0], args.runs, 1).chunk
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        found = {n: compare(args.runs, n, root) for n in args.drones}
        middle = args.drones[len(args.drones) // 2]
        parts = {n: split_sweep(rcs, args.runs, middle, root / f"split{n}")
                 for n, rcs in ((1, [1000.0]), (len(RANGES), RANGES))}
    lines = [
        "The sweeps' jobs run in the benchmark's process: CPU time of the whole sweep "
        "(flights, tables, files), without "
        f"a worker's start-up; the best of {ROUNDS} rounds, the two sweeps interleaved, each "
        "first in every other round (and the median of the ratios of the two sweeps of each "
        "round, taken a few seconds apart).",
        "",
        f"CovB, {args.runs} runs per point of 4000 s, chunks of {chunk} runs (the default); "
        f"8 ranges: {', '.join(f'{r:g}' for r in RANGES)} m; one range: 1000 m.",
        "",
        "| N | one range, CPU s | 8 ranges, CPU s | ratio | median of the rounds' ratios | "
        "rows equal to 8 one-range sweeps | all rounds, one range / 8 ranges (s) |",
        "|---|---|---|---|---|---|---|",
        *(f"| {n} | {min(f['ones']):.2f} | {min(f['eights']):.2f} | "
          f"**{min(f['eights']) / min(f['ones']):.2f}×** | "
          f"{statistics.median(map(operator.truediv, f['eights'], f['ones'])):.2f}× | "
          f"{f['equal']} | "
          f"{' '.join(f'{t:.2f}' for t in f['ones'])} / "
          f"{' '.join(f'{t:.2f}' for t in f['eights'])} |" for n, f in found.items()),
        "",
        f"Where the CPU of each sweep goes (N = {middle}, one more sweep of each, its parts "
        "timed), ms per run:",
        "",
        "| part | one range | 8 ranges |",
        "|---|---|---|",
        *(f"| {part} | {1e3 * parts[1][part] / args.runs:.2f} | "
          f"{1e3 * parts[len(RANGES)][part] / args.runs:.2f} |" for part in parts[1]),
        "",
        f"The engine alone, CPU ms per run (mean of {min(args.runs, 50)} runs, the best of "
        "three rounds):",
        "",
        "| N | plain flight (`Prepared.run`) | scanned at 1 range (`Prepared.run_ranges`) | "
        "scanned at 8 ranges | traced, scanned at 8 ranges with the staircase |",
        "|---|---|---|---|---|",
        *(f"| {n} | {' | '.join(f'{t:.2f}' for t in f['engine'])} |"
          for n, f in found.items()),
        "",
    ]
    print("\n".join(lines))
    results_file.write(args.out, "One flight, every range: CPU of a sweep over 8 ranges "
                       "against one", "\n".join(lines))


if __name__ == "__main__":
    main()
