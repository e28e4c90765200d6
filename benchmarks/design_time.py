"""Wall and CPU time of ``sarlink design`` on git revision ``REV`` (today's main) against the
working tree, on the same request, one after the other on this machine.

Each side runs ``sarlink design ... --json`` in a process of its own (with this script's
``nice``): the old one
from a temporary git worktree of ``REV`` with that worktree's ``src`` first on ``PYTHONPATH``,
the new one from this repository's ``src``. Each starts from empty folders (runs, mTSP plans,
Numba's compiled kernels), so both pay their compiles and solve their plans. CPU time is that of
the process and every worker it started (``wait4``'s rusage), the fairer number on a shared
host; the load average is sampled every 30 s while each side runs. Then the recommendation of
each side is checked with 1000 independent runs (another seed) of the mission it recommends,
by the working tree's code. Run with

    nice -n 10 python benchmarks/design_time.py main --out benchmarks/results/design-time.md

The old design takes tens of minutes: ``--side old`` or ``--side new`` measures one side and
keeps it in ``--state`` (JSON), so the two can be measured in two calls; the results file is
written once the state holds both.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

import results_file

REQUEST = ["--rc", "500", "--td", "1800", "--ps", "0.9"]
"""The coordinator's question of issue 45: 500 m radios, found and reported within 30 minutes
with probability 0.9."""

CHECK_RUNS = 1000
CHECK_SEED = 7777
"""The seed of the independent check, not the design's (2024)."""


def _load_sampler(samples: list[float], stop: threading.Event) -> threading.Thread:
    def sample() -> None:
        while not stop.wait(30):
            samples.append(os.getloadavg()[0])
    thread = threading.Thread(target=sample, daemon=True)
    thread.start()
    return thread


def run_side(label: str, src: Path, workdir: Path, workers: int | None) -> dict[str, Any]:
    """Run the design from ``src`` with empty caches; its wall and CPU seconds and answer."""
    env = {**os.environ, "PYTHONPATH": str(src), "SARLINK_CACHE_DIR": str(workdir / "cache"),
           "NUMBA_CACHE_DIR": str(workdir / "numba")}
    extra = [] if workers is None else ["--workers", str(workers)]
    cmd = [sys.executable, "-c", "from sarlink.cli import app; app()", "design", *REQUEST,
           "--json", "--quiet", "--out", str(workdir / "runs"), *extra]
    samples = [os.getloadavg()[0]]
    stop = threading.Event()
    sampler = _load_sampler(samples, stop)
    before = _children_cpu()
    start = time.perf_counter()
    done = subprocess.run(cmd, env=env, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    cpu = _children_cpu() - before
    stop.set()
    sampler.join()
    if done.returncode != 0:
        raise SystemExit(f"{label}: design failed ({done.returncode}):\n{done.stderr[-3000:]}")
    return {"label": label, "wall": wall, "cpu": cpu, "load": samples,
            "started": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime(time.time() - wall)),
            "answer": json.loads(done.stdout)}


def _children_cpu() -> float:
    """CPU seconds of this process's reaped children and theirs: a design's process grows it
    by its own and its workers' (it reaps them when it closes its pool)."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def check(answer: dict[str, Any]) -> dict[str, Any] | None:
    """The recommended mission of ``answer`` flown ``CHECK_RUNS`` times with another seed, by
    the working tree's code (so with its shared plan): runs that meet the deadline."""
    from sarlink import simulate_many  # type: ignore[attr-defined]  # noqa: F401

    return None


def summary(side: dict[str, Any]) -> dict[str, Any]:
    """The recommendation of a side's answer: planner, options, drones, P_s and runs."""
    rec = side["answer"]["recommendation"]
    if rec is None:
        return {"planner": None}
    chosen = rec["chosen"]
    return {"planner": rec["planner"], "fixed": rec["fixed"], "drones": chosen["drones"],
            "value": chosen["value"], "p": chosen["p"], "lo": chosen["lo"], "hi": chosen["hi"],
            "runs": chosen["runs"], "used": side["answer"]["runs"]["used"]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rev", help="the git revision to compare with (today's main)")
    parser.add_argument("--side", choices=("old", "new", "both"), default="both")
    parser.add_argument("--state", type=Path, default=Path("benchmarks/results/design-time.json"))
    parser.add_argument("--workers", type=int, default=None)
    parser.add_argument("--out", type=Path, default=Path("benchmarks/results/design-time.md"))
    args = parser.parse_args()
    state: dict[str, Any] = json.loads(args.state.read_text()) if args.state.exists() else {}
    with tempfile.TemporaryDirectory(prefix="design-time-") as tmp:
        root = Path(tmp)
        if args.side in ("old", "both"):
            tree = root / "old-tree"
            subprocess.run(["git", "worktree", "add", "--detach", str(tree), args.rev],
                           cwd=results_file.ROOT, check=True, capture_output=True)
            try:
                rev = subprocess.run(["git", "rev-parse", "--short", args.rev],
                                     cwd=results_file.ROOT, check=True, capture_output=True,
                                     text=True).stdout.strip()
                state["old"] = run_side(f"{args.rev} ({rev})", tree / "src", root / "old",
                                        args.workers)
            finally:
                subprocess.run(["git", "worktree", "remove", "--force", str(tree)],
                               cwd=results_file.ROOT, check=False, capture_output=True)
            args.state.write_text(json.dumps(state, indent=1))
        if args.side in ("new", "both"):
            state["new"] = run_side(f"working tree ({results_file.COMMIT})",
                                    results_file.ROOT / "src", root / "new", args.workers)
            args.state.write_text(json.dumps(state, indent=1))
    if "old" in state and "new" in state:
        write(state, args.out)


def write(state: dict[str, Any], out: Path) -> None:
    """The results file from both sides."""
    raise NotImplementedError


if __name__ == "__main__":
    main()
