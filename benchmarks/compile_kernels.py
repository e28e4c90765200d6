"""What compiling the engine's kernels costs from an empty cache: this tree against git
revision ``REV``, kernel by kernel, in the order a test session or a sweep meets them.

Each side runs in a process of its own with empty sarlink and Numba caches (the old side from
``git archive REV src/sarlink``), compiles the kernels of :data:`KERNELS` one after the other
with :func:`sarlink.simulation.warm_up`, and reports the CPU seconds each took. A kernel's
first compile also compiles what later kernels load from the disk cache (the engine's plain
functions), so the order is part of the measurement and the same on both sides. The sides
run one after the other; CPU time, not wall time, so a busy machine changes the numbers less.
Writes ``benchmarks/results/compile-kernels.md`` with ``--out``::

    python benchmarks/compile_kernels.py b2fc27b --out benchmarks/results/compile-kernels.md
"""

from __future__ import annotations

import argparse
import io
import json
import os
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

import results_file

ROOT = Path(__file__).resolve().parents[1]
KERNELS = [("covb", False, None, False), ("conb", False, None, False),
           ("concov", False, None, False), ("mtsp", False, None, False),
           ("covb", False, "tree", False), ("covb", False, None, True),
           ("conb", False, "tree", False), ("mtsp", False, "tree", False)]
"""(planner, with the staircase scan, relay strategy, with the chain): the first kernels of the
test session's warm-up (``tests/conftest.py``), each a seam the kernel compiles in."""

_SIDE = """
import json, sys, time
from sarlink.simulation import warm_up
for planner, ranges, relays, chain in json.loads(sys.argv[1]):
    start = time.process_time()
    warm_up(planner, "disc", ranges=ranges, relays=relays, chain=chain)
    print(time.process_time() - start, flush=True)
"""


def side(src: Path, work: Path) -> list[float]:
    """CPU seconds per kernel of :data:`KERNELS`, compiled by the package in ``src`` from
    empty caches under ``work``."""
    env = {**os.environ, "PYTHONPATH": str(src), "SARLINK_CACHE_DIR": str(work / "sarlink"),
           "NUMBA_CACHE_DIR": str(work / "numba"), "PYTHONWARNINGS": "ignore"}
    out = subprocess.run([sys.executable, "-c", _SIDE, json.dumps(KERNELS)], env=env,
                         cwd=work, check=True, capture_output=True, text=True).stdout
    return [float(line) for line in out.split()]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rev", help="the git revision to compare with")
    parser.add_argument("--out", type=Path, help="write the results here (markdown)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        old = Path(tmp) / "old"
        tar = subprocess.run(["git", "archive", args.rev, "src/sarlink"], cwd=ROOT,
                             check=True, capture_output=True).stdout
        with tarfile.open(fileobj=io.BytesIO(tar)) as archive:
            archive.extractall(old, filter="data")
        (Path(tmp) / "new").mkdir()
        seconds = {"old": side(old / "src", old), "new": side(ROOT / "src", Path(tmp) / "new")}
    lines = ["| kernel (planner, relays, chain) | " + args.rev + ", CPU s | this tree, CPU s |",
             "|---|---|---|"]
    for (planner, _, relays, chain), a, b in zip(KERNELS, seconds["old"], seconds["new"],
                                                 strict=True):
        name = planner + (f", relays {relays}" if relays else "") + (", chain" if chain else "")
        lines.append(f"| {name} | {a:.1f} | {b:.1f} |")
    total = {k: sum(v) for k, v in seconds.items()}
    lines.append(f"| **all {len(KERNELS)}** | **{total['old']:.0f}** | **{total['new']:.0f}** |")
    body = "\n".join([
        "Each side compiles the kernels in this order in one process, from empty sarlink and "
        "Numba caches (`sarlink.simulation.warm_up`, the disc radio); CPU seconds per kernel.",
        "", *lines, "", f"All kernels: {total['old'] / total['new']:.2f}x less CPU time."])
    print(body)
    if args.out:
        results_file.write(args.out, f"Compiling the kernels: this tree against {args.rev}",
                           body)


if __name__ == "__main__":
    main()
