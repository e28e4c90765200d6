"""Paired timing of the kernel against the kernel of another git revision, on the same runs.

The host's speed drifts by tens of percent within an hour, so timings of two kernel versions
taken minutes apart cannot show a 10 % change. This script compiles both kernels side by side
(the working tree's and ``git show REV:src/sarlink/engine/kernel.py``, both without the disk
cache), runs every run with both back to back in alternating order, and reports the median of
the paired time ratios. It also counts the runs whose results are identical, bit for bit.

The kernel compiled first in a process runs faster, by 10-40 % for identical code (where the
machine code lands in memory matters), so each case is measured in two processes, one per
compile order, and the speed-up is the geometric mean of their two medians. Run with

    python benchmarks/bench_paired.py fff07f0 --cases covb:22,conb:22 --runs 10 --rounds 6

Both kernels must take the same arguments; the ``Params`` fields are matched by name, and
the results are compared in a common form (the 8-tuple of kernels before the split into
phases and the :class:`~sarlink.engine.records.RunRecord` since).
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import ModuleType

import numpy as np

from sarlink import Mission, prepare
from sarlink.engine.scenario import draw_scenario, takeoff_headings
from sarlink.engine.streams import run_streams

ROOT = Path(__file__).resolve().parents[1]
KERNEL = "src/sarlink/engine/kernel.py"


def load_kernel(source: str, name: str, folder: Path) -> ModuleType:
    """The kernel module compiled from ``source``, with Numba's disk cache off."""
    path = folder / f"{name}.py"
    path.write_text(source.replace("cache=True", "cache=False"))
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def outcome(out: tuple) -> list[np.ndarray]:
    """A kernel's result as a list of arrays: events, records, trajectory."""
    if hasattr(out, "track"):  # a RunRecord
        events = np.array([out.t_detect, out.t_notify, float(out.detector),
                           1.0 if out.immediate else 0.0])
        tr = out.track
        return [events, out.reach_cum, out.conn_cum, tr.positions, tr.headings, tr.knows,
                tr.bs_route, tr.mode]
    return [np.asarray(a) for a in out[:8]]


def run_once(kernel: ModuleType, mission: Mission, seed: int, run: int) -> tuple[float, tuple]:
    """Wall seconds of one kernel call and its result, from fresh random streams."""
    prepared = prepare(mission)
    streams = run_streams(seed, run)
    scenario = draw_scenario(mission, streams.scenario)
    pos0 = np.tile(np.asarray(mission.area.bs_xy, dtype=float), (mission.team.drones, 1))
    params = kernel.Params(**{f: getattr(prepared.params, f) for f in kernel.Params._fields})
    args = (params, float(scenario.target[0]),
            float(scenario.target[1]), pos0, takeoff_headings(scenario, prepared.distributed),
            prepared.waypoints, prepared.wp_start, prepared.cp_steps, streams.turn,
            streams.shadow, streams.look)
    start = time.perf_counter()
    out = kernel.simulate_kernel(*args)
    return time.perf_counter() - start, out


def case_mission(case: str, reading: str) -> Mission:
    """The mission of a ``planner:drones[:rc[:sigma]]`` case under a named reading."""
    planner, drones, *rest = case.split(":")
    return Mission.build(reading=reading, planner=planner, drones=int(drones),
                         rc=float(rest[0]) if rest else 1000.0,
                         sigma=float(rest[1]) if len(rest) > 1 else 0.0)


def measure(old_source: str, case: str, runs: int, rounds: int, new_first: bool,
            reading: str) -> None:
    """Print ``identical speed-up`` for one case, with the kernels compiled in one order."""
    mission = case_mission(case, reading)
    with tempfile.TemporaryDirectory() as tmp:
        sources = {"old": old_source, "new": (ROOT / KERNEL).read_text()}
        kernels = {tag: load_kernel(sources[tag], f"kernel_{tag}", Path(tmp))
                   for tag in (("new", "old") if new_first else ("old", "new"))}
        for tag in kernels:  # compile in that order
            run_once(kernels[tag], mission, 1, 0)
        same = sum(all(np.array_equal(a, b, equal_nan=a.dtype.kind == "f") for a, b in
                       zip(outcome(run_once(kernels["old"], mission, 1, r)[1]),
                           outcome(run_once(kernels["new"], mission, 1, r)[1]), strict=True))
                   for r in range(runs))
        ratios = []
        for rnd in range(rounds):
            for r in range(runs):
                order = ["old", "new"][:: 1 if (rnd + r) % 2 == 0 else -1]
                pair = {tag: run_once(kernels[tag], mission, 1, r)[0] for tag in order}
                ratios.append(pair["old"] / pair["new"])
    print(same, np.median(ratios))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rev", help="git revision of the kernel to compare with")
    parser.add_argument("--cases", default="covb:22,conb:22",
                        help="planner:drones[:rc[:sigma]] items, comma-separated")
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=6)
    parser.add_argument("--reading", default="sarlink-1",
                        help="the reading of the paper to fly (default: sarlink-1, the rules "
                             "of kernels before readings were selectable)")
    parser.add_argument("--one", choices=["old-first", "new-first"], help=argparse.SUPPRESS)
    args = parser.parse_args()
    old_source = subprocess.run(["git", "show", f"{args.rev}:{KERNEL}"], cwd=ROOT, check=True,
                                capture_output=True, text=True).stdout
    if args.one:  # one compile order, in a process of its own
        measure(old_source, args.cases, args.runs, args.rounds, args.one == "new-first",
                args.reading)
        return
    for case in args.cases.split(","):
        results = {}
        for order in ("old-first", "new-first"):
            out = subprocess.run([sys.executable, __file__, args.rev, "--cases", case,
                                  "--runs", str(args.runs), "--rounds", str(args.rounds),
                                  "--reading", args.reading, "--one", order],
                                 check=True, capture_output=True, text=True)
            same, ratio = out.stdout.split()
            results[order] = (int(same), float(ratio))
        same = min(s for s, _ in results.values())
        speedup = math.sqrt(results["old-first"][1] * results["new-first"][1])
        print(f"{case:16s} identical {same}/{args.runs}  speed-up {speedup:.3f} (paired "
              f"medians: old compiled first {results['old-first'][1]:.3f}, new first "
              f"{results['new-first'][1]:.3f})", flush=True)


if __name__ == "__main__":
    main()
