"""Paired timing of a run's own mTSP plan (``readings.mtsp_plan = per-run``) against another git
revision: the GA kernel alone, and the whole per-run path (a mission with the run's plan seed,
the planner's steering, ``plan_for`` with its lock and JSON file, the checked routes).

The host's speed drifts within minutes, so each plan is made by both revisions back to back,
in alternating order, and the speed-up is the median of the paired ratios old / new; the
old revision's package is loaded beside the working tree's (``bench_paired.load_revision``,
compiled without disk cache), and as code compiled first in a process runs faster, each
team size is measured in two processes, one per compile order, and the speed-ups are the
geometric means of their two medians. Every plan is checked to be the same, bit for bit
(kernel: route, breaks and history; path: the routes flown). Each side's per-run plans go to
a cache folder of its own that starts empty, so every call of the path solves. Run with

    python benchmarks/bench_per_run_plans.py ab53e80 --drones 2,10,22 --runs 8 --rounds 2 \\
        --out benchmarks/results/per-run-plans.md

The paper's mission (``sarlink.config`` defaults: 64 cells, BS at the centre, GA 80 x 5000,
minsum), planner ``mtsp``; run ``r`` of round ``k`` is run ``r`` of experiment seed ``k``.
"""

from __future__ import annotations

import argparse
import importlib
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

import results_file
from bench_paired import load_revision
from sarlink.engine.streams import plan_seed
from sarlink.mtsp import grid_cells
from sarlink.mtsp.plan import distance_matrix

PLANNER = "mtsp"


def _timed(fn: Any) -> tuple[float, float, Any]:
    """Wall and CPU seconds of ``fn()``, and what it returned."""
    wall, cpu = time.perf_counter(), time.process_time()
    out = fn()
    return time.perf_counter() - wall, time.process_time() - cpu, out


class Side:
    """One revision's kernel and per-run path (package ``name``), with a plan cache folder of
    its own."""

    def __init__(self, name: str, folder: Path) -> None:
        self.package = importlib.import_module(name)
        self.kernel = importlib.import_module(f"{name}.mtsp.ga")._ga_kernel
        self.own = importlib.import_module(f"{name}.planners.base")._own_routes
        self.planner = importlib.import_module(f"{name}.planners.registry").get_planner(PLANNER)
        self.folder = folder

    def solve(self, dmat: np.ndarray, drones: int, seed: int) -> tuple[float, float, Any]:
        """The kernel alone on the paper's grid with min_cells floor(64 / N): its route,
        breaks and history (a kernel that counts its evaluations returns them fourth)."""
        return _timed(lambda: self.kernel(dmat, drones, 64 // drones, 80, 5000, False,
                                          np.random.default_rng(seed))[:3])

    def own_routes(self, drones: int, seed: int, run: int) -> tuple[float, float, Any]:
        """The routes of run ``run`` of experiment ``seed``, planned from scratch."""
        os.environ["SARLINK_CACHE_DIR"] = str(self.folder)
        mission = self.package.Mission.build(drones=drones, planner=PLANNER)
        assert mission.readings.mtsp_plan == "per-run"
        return _timed(lambda: self.own(self.planner, mission, seed, run))


def _same(a: Any, b: Any) -> bool:
    """Whether two sequences of arrays are equal, the float ones bit for bit."""
    for x, y in zip(a, b, strict=True):
        x, y = np.asarray(x), np.asarray(y)
        if x.dtype.kind == "f":
            if x.dtype != y.dtype or x.shape != y.shape or x.tobytes() != y.tobytes():
                return False
        elif not np.array_equal(x, y):
            return False
    return True


def measure(rev: str, drones: int, runs: int, rounds: int, new_first: bool) -> dict[str, Any]:
    """Both revisions' times for one team size, with the kernels compiled in one order."""
    with tempfile.TemporaryDirectory() as tmp:
        load_revision(rev, Path(tmp))
        sides = {"old": Side("sarlink_rev", Path(tmp) / "old"),
                 "new": Side("sarlink", Path(tmp) / "new")}
        dmat = distance_matrix(grid_cells(4000.0, 500.0), (2000.0, 2000.0))
        order = ("new", "old") if new_first else ("old", "new")
        for tag in order:  # compile in that order
            sides[tag].solve(dmat, 3, 0)
            sides[tag].own_routes(3, 10**6, 0)
        times: dict[str, dict[str, list[float]]] = {
            part: {f"{tag}_{clock}": [] for tag in ("old", "new") for clock in ("wall", "cpu")}
            for part in ("kernel", "path")}
        same = {"kernel": 0, "path": 0}
        for rnd in range(rounds):
            for run in range(runs):
                pair = ["old", "new"][:: 1 if (rnd + run) % 2 == 0 else -1]
                seed = plan_seed(rnd, run)
                out = {}
                for tag in pair:
                    wall, cpu, out[tag] = sides[tag].solve(dmat, drones, seed)
                    times["kernel"][f"{tag}_wall"].append(wall)
                    times["kernel"][f"{tag}_cpu"].append(cpu)
                same["kernel"] += _same(out["old"], out["new"])
                for tag in pair[::-1]:
                    wall, cpu, out[tag] = sides[tag].own_routes(drones, rnd, run)
                    times["path"][f"{tag}_wall"].append(wall)
                    times["path"][f"{tag}_cpu"].append(cpu)
                same["path"] += _same(out["old"], out["new"])
    return {"times": times, "same": same, "plans": runs * rounds}


def write_costs(repeats: int) -> tuple[float, float]:
    """Median wall ms of writing one per-run plan's file with and without ``fsync`` (paired,
    alternating), in the working tree's cache code: what skipping it saves a plan."""
    from sarlink import Mission
    from sarlink.mtsp.cache import _checked_params, _write_plan, solve_for

    mission = Mission.build(drones=10)
    plan = replace(solve_for(mission, 10), history=np.empty(0))  # as plan_for stores it
    params = {**_checked_params(mission, 10)[1], "history": False}
    times: dict[bool, list[float]] = {True: [], False: []}
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(repeats):
            for sync in (True, False)[:: 1 if k % 2 == 0 else -1]:
                path = Path(tmp) / f"{k}-{sync}.json"
                start = time.perf_counter()
                _write_plan(path, params, plan, sync=sync)
                times[sync].append(time.perf_counter() - start)
    return 1e3 * float(np.median(times[True])), 1e3 * float(np.median(times[False]))


def _summary(results: dict[str, dict[str, Any]], part: str) -> dict[str, float]:
    """Medians (ms) over both orders and the geometric mean of the two orders' median paired
    ratios, by wall and by CPU time."""
    out: dict[str, float] = {}
    for clock in ("wall", "cpu"):
        for tag in ("old", "new"):
            values = [v for r in results.values() for v in r["times"][part][f"{tag}_{clock}"]]
            out[f"{tag}_{clock}"] = 1e3 * float(np.median(values))
        ratios = [float(np.median(np.array(r["times"][part][f"old_{clock}"])
                                  / np.array(r["times"][part][f"new_{clock}"])))
                  for r in results.values()]
        out[f"speedup_{clock}"] = math.sqrt(ratios[0] * ratios[1])
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rev", help="git revision to compare with (e.g. ab53e80)")
    parser.add_argument("--drones", default="2,10,22", help="team sizes, comma-separated")
    parser.add_argument("--runs", type=int, default=8)
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--out", type=Path, help="write the results here (markdown)")
    parser.add_argument("--one", choices=["old-first", "new-first"], help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one:  # one team size in one compile order, in a process of its own
        print(json.dumps(measure(args.rev, int(args.drones), args.runs, args.rounds,
                                 args.one == "new-first")))
        return
    load_before = os.getloadavg()
    rows = []
    for drones in (int(n) for n in args.drones.split(",")):
        results = {}
        for order in ("old-first", "new-first"):
            out = subprocess.run([sys.executable, __file__, args.rev, "--drones", str(drones),
                                  "--runs", str(args.runs), "--rounds", str(args.rounds),
                                  "--one", order], check=True, capture_output=True, text=True)
            results[order] = json.loads(out.stdout)
        same = {part: sum(r["same"][part] for r in results.values()) for part in ("kernel",
                                                                                  "path")}
        plans = sum(r["plans"] for r in results.values())
        for part in ("kernel", "path"):
            s = _summary(results, part)
            rows.append(f"| {drones} | {part} | {same[part]}/{plans} | {s['old_wall']:.1f} | "
                        f"{s['new_wall']:.1f} | {s['speedup_wall']:.2f} | {s['old_cpu']:.1f} | "
                        f"{s['new_cpu']:.1f} | {s['speedup_cpu']:.2f} |")
            print(rows[-1], flush=True)
    synced, unsynced = write_costs(4 * args.runs * args.rounds)
    text = "\n".join([
        f"Load average {load_before[0]:.1f} before (the header's is after). "
        f"Medians in ms over both compile orders; speed-up = old / new, the geometric mean "
        f"of the two orders' medians of the paired ratios; same = plans identical bit for "
        f"bit. `kernel`: the GA alone (80 x 5000, 64 cells, min_cells floor(64 / N)); `path`: "
        f"a run's routes from an empty cache (`planners.base._own_routes`, planner "
        f"`{PLANNER}`).", "",
        "| N | part | same | old wall ms | new wall ms | speed-up (wall) | old CPU ms | "
        "new CPU ms | speed-up (CPU) |",
        "|---:|---|---:|---:|---:|---:|---:|---:|---:|", *rows, "",
        f"Writing one per-run plan's file (N = 10, the working tree's `_write_plan`, "
        f"{4 * args.runs * args.rounds} pairs): {synced:.2f} ms with `fsync`, {unsynced:.2f} "
        f"ms without (median wall time; per-run plans are written without).", ""])
    print(text)
    if args.out:
        results_file.write(args.out, f"A run's own mTSP plan: this tree against {args.rev}",
                           text)


if __name__ == "__main__":
    main()
