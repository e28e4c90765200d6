"""Paired timing of the kernel against the kernel of another git revision, on the same runs.

The host's speed drifts by tens of percent within an hour, so timings of two kernel versions
taken minutes apart cannot show a 10 % change. This script compiles both kernels side by side
(the working tree's and ``git show REV:src/sarlink/engine/kernel.py``, both without the disk
cache, so that neither is favoured), runs every run with both back to back in alternating
order, and reports the median of the paired time ratios. It also counts the runs whose results
are identical, bit for bit. Run with

    python benchmarks/bench_paired.py fff07f0 --cases covb:22,conb:22 --runs 10 --rounds 6

Both kernels must take the same inputs (the ``Params`` fields and the kernel's arguments).
"""

from __future__ import annotations

import argparse
import importlib.util
import subprocess
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


def run_once(kernel: ModuleType, mission: Mission, seed: int, run: int) -> tuple[float, tuple]:
    """Wall seconds of one kernel call and its result, from fresh random streams."""
    prepared = prepare(mission)
    streams = run_streams(seed, run)
    scenario = draw_scenario(mission, streams.scenario)
    pos0 = np.tile(np.asarray(mission.area.bs_xy, dtype=float), (mission.team.drones, 1))
    args = (kernel.Params(*prepared.params), float(scenario.target[0]),
            float(scenario.target[1]), pos0, takeoff_headings(scenario, prepared.distributed),
            prepared.waypoints, prepared.wp_start, prepared.cp_steps, streams.turn,
            streams.shadow, streams.look)
    start = time.perf_counter()
    out = kernel.simulate_kernel(*args)
    return time.perf_counter() - start, out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rev", help="git revision of the kernel to compare with")
    parser.add_argument("--cases", default="covb:22,conb:22",
                        help="planner:drones[:rc[:sigma]] items, comma-separated")
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=6)
    args = parser.parse_args()
    old_source = subprocess.run(["git", "show", f"{args.rev}:{KERNEL}"], cwd=ROOT, check=True,
                                capture_output=True, text=True).stdout
    with tempfile.TemporaryDirectory() as tmp:
        old = load_kernel(old_source, "kernel_old", Path(tmp))
        new = load_kernel((ROOT / KERNEL).read_text(), "kernel_new", Path(tmp))
        for case in args.cases.split(","):
            planner, drones, *rest = case.split(":")
            mission = Mission.build(planner=planner, drones=int(drones),
                                    rc=float(rest[0]) if rest else 1000.0,
                                    sigma=float(rest[1]) if len(rest) > 1 else 0.0)
            same = sum(all(np.array_equal(a, b, equal_nan=a.dtype.kind == "f") for a, b in
                           zip(run_once(old, mission, 1, r)[1], run_once(new, mission, 1, r)[1],
                               strict=True))
                       for r in range(args.runs))
            ratios, times = [], {"old": [], "new": []}
            for rnd in range(args.rounds):
                for r in range(args.runs):
                    order = [("old", old), ("new", new)][:: 1 if (rnd + r) % 2 == 0 else -1]
                    pair = {tag: run_once(kernel, mission, 1, r)[0] for tag, kernel in order}
                    ratios.append(pair["old"] / pair["new"])
                    for tag in pair:
                        times[tag].append(pair[tag])
            q1, median, q3 = np.percentile(ratios, [25, 50, 75])
            print(f"{case:14s} identical {same}/{args.runs}  old "
                  f"{np.median(times['old']) * 1e3:6.2f} ms  new "
                  f"{np.median(times['new']) * 1e3:6.2f} ms  speed-up (paired median) "
                  f"{median:.3f}, IQR {q1:.3f}-{q3:.3f}", flush=True)


if __name__ == "__main__":
    main()
