"""CPU of a sweep over 8 communication ranges against a sweep over one (issue 22).

A range-free team (here CovB) flies once per run for every range of a grid over ``rc``
(:mod:`sarlink.engine.ranges`); a sweep over one range flies as it always did. This script
sweeps CovB over 8 ranges and over one with the sweep's own code (planning, jobs, tables,
Parquet files) but its jobs run in this process, so that the CPU time is that of the work,
without a worker's start-up; it also sweeps the 8 ranges one by one and checks that the rows
are equal. It also times the engine alone per run: a plain flight, a traced flight with its
critical ranges read at one range, and read at 8 ranges.
Run with

    python benchmarks/bench_ranges.py --runs 200 --out benchmarks/results/ranges.md
"""

from __future__ import annotations

import argparse
import datetime
import math
import platform
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pandas as pd

from sarlink import Experiment, Mission, execution, prepare, storage
from sarlink.engine import Prepared
from sarlink.execution import sweep_all
from sarlink.simulation import plugins_in_code

ROUNDS = 3
RANGES = [250.0, 500.0, 750.0, 1000.0, 1250.0, 1500.0, 2000.0, 3000.0]


def experiment(rcs: list[float], runs: int, drones: int) -> Experiment:
    return Experiment.from_dict({"name": "ranges", "seed": 7, "runs": runs, "chunk": 50,
                                 "mission": {"team": {"planner": "covb", "drones": drones}},
                                 "grid": {"rc": rcs}})


class InProcess:
    """Workers that run every job in this process, one after the other."""

    def results(self, jobs):  # type: ignore[no-untyped-def]
        for call, job in zip(execution._calls(jobs), jobs, strict=True):
            yield job, execution._run_chunk(*call)


assert plugins_in_code() == ((), ())  # nothing to hand to a worker: one process is the same


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
    return {**spent, "the rest (rows, planning, reading back)": total - sum(spent.values())}


def engine_ms(drones: int, runs: int) -> list[float]:
    """CPU ms per run: a flight, a traced flight alone, read at one range, at 8 ranges, and
    at 8 ranges with the staircase (the best of three rounds, interleaved)."""
    prepared = prepare(Mission.build(planner="covb", drones=drones, rc=1000.0))

    def traced(k: int) -> None:
        streams, scenario = prepared._start(0, k, None)
        prepared.record(streams, scenario, traced_at=RANGES[0])

    works = [lambda k: prepared.run(0, k), traced,
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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=200)
    parser.add_argument("--drones", type=int, default=10)
    parser.add_argument("--out", type=Path, default=Path("benchmarks/results/ranges.md"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        for rcs in ([1000.0], RANGES):  # compile or load the kernel and the reading
            timed_sweep(rcs, 2, args.drones, root / f"warm{len(rcs)}")
        ones, eights = [], []
        for i in range(ROUNDS):  # the host's speed drifts: interleaved, the best of each
            ones.append(timed_sweep([1000.0], args.runs, args.drones, root / f"one{i}")[0])
            eight, together = timed_sweep(RANGES, args.runs, args.drones, root / f"eight{i}")
            eights.append(eight)
        one, eight = min(ones), min(eights)
        apart = pd.concat([timed_sweep([rc], args.runs, args.drones, root / f"{rc:g}")[1]
                           for rc in RANGES])
        parts = {n: split_sweep(rcs, args.runs, args.drones, root / f"split{n}")
                 for n, rcs in ((1, [1000.0]), (len(RANGES), RANGES))}
    key = ["rc", "run"]
    equal = together.drop(columns="point").sort_values(key).reset_index(drop=True).equals(
        apart.drop(columns="point").sort_values(key).reset_index(drop=True))
    flight, traced, read1, read8, stairs8 = engine_ms(args.drones, min(args.runs, 50))
    lines = [
        "# One flight, every range: CPU of a sweep over 8 ranges against one",
        "",
        f"`python benchmarks/bench_ranges.py --runs {args.runs} --drones {args.drones}`, "
        f"{datetime.date.today()}, {platform.processor() or platform.machine()}, "
        "the sweeps' jobs run in the benchmark's process: CPU time of the whole sweep "
        "(flights, tables, files), without a worker's start-up; the best of "
        f"{ROUNDS} rounds, the two sweeps interleaved (all rounds, s: one range "
        f"{' '.join(f'{t:.2f}' for t in ones)}; 8 ranges {' '.join(f'{t:.2f}' for t in eights)}).",
        "",
        f"CovB, N = {args.drones}, {args.runs} runs per point of 4000 s, chunks of 50 runs.",
        "",
        "| sweep | CPU s | per run and range, ms |",
        "|---|---|---|",
        f"| rc = 1000 m | {one:.2f} | {1e3 * one / args.runs:.2f} |",
        f"| rc over {len(RANGES)} values ({', '.join(f'{r:g}' for r in RANGES)} m) | "
        f"{eight:.2f} | {1e3 * eight / args.runs / len(RANGES):.2f} |",
        "",
        f"Ratio of the 8-range sweep to the one-range sweep: **{eight / one:.2f}×**.",
        f"Rows of the 8-range sweep equal those of 8 one-range sweeps: **{equal}**.",
        "",
        "Where the CPU of each sweep goes (one more sweep of each, its parts timed), ms per "
        "run:",
        "",
        "| part | one range | 8 ranges |",
        "|---|---|---|",
        *(f"| {part} | {1e3 * parts[1][part] / args.runs:.2f} | "
          f"{1e3 * parts[len(RANGES)][part] / args.runs:.2f} |" for part in parts[1]),
        "",
        "The engine alone, CPU ms per run (mean of "
        f"{min(args.runs, 50)} runs, N = {args.drones}, the best of three rounds):",
        "",
        "| work | ms per run |",
        "|---|---|",
        f"| plain flight (`Prepared.run`, what a one-range sweep flies) | {flight:.2f} |",
        f"| traced flight alone (positions only, `Params.trace`) | {traced:.2f} |",
        f"| traced flight read at one range (`Prepared.run_ranges`) | {read1:.2f} |",
        f"| traced flight read at 8 ranges (`Prepared.run_ranges`) | {read8:.2f} |",
        f"| traced flight read at 8 ranges with the staircase | {stairs8:.2f} |",
        "",
    ]
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
