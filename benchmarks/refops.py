"""Count the reference-count operations the kernel executes per step, under gdb.

Numba counts a reference (an atomic ``NRT_incref``/``NRT_decref`` pair) for arrays handed to
inlined helpers, and its pruner removes the pairs only where LLVM's optimisations left them in
a shape it recognises. Which pairs survive is hard to see in the source and cost the split
engine up to 8 % of a step; this script counts the ones executed in one run, by call site, so
that an edit can be checked to add none. Needs gdb (``apt-get install gdb``). Run with

    python benchmarks/refops.py covb:10 [--run 3]

A ``planner:drones[:rc[:sigma]]`` case as in ``bench_paired.py``. Prints the operations per step and
the call sites (offsets in the kernel's machine code) that run more than once per ten steps.
"""

from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

GDB_SCRIPT = """
import collections, gdb
hits = collections.Counter()
class Count(gdb.Breakpoint):
    def stop(self):
        ret = int(gdb.parse_and_eval("*(unsigned long *)$rsp"))
        hits[(self.location, ret)] += 1
        return False
inc, dec = Count("*{inc:#x}"), Count("*{dec:#x}")
gdb.execute("handle SIGSTOP nostop noprint pass")
gdb.execute("handle SIGCONT nostop noprint pass")
gdb.execute("signal SIGCONT")
while True:
    try:
        gdb.execute("continue")
    except gdb.error:
        break
for (loc, ret), c in hits.most_common():
    print("HIT", "incref" if loc == inc.location else "decref", ret - {base:#x}, c)
"""


def serve(case: str, run: int, reading: str) -> None:
    """Compile the kernel, print its addresses, stop until gdb attaches, then do one run."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from bench_paired import Side, case_mission, uncached
    from sarlink import prepare

    side = Side(case_mission, prepare, uncached(None))
    side.run_once(case, reading, 1, run)  # compile
    mission = case_mission(case, reading)
    kernel = uncached(None)(prepare(mission))
    sig = kernel.signatures[0]
    library = kernel.overloads[sig].library
    engine = library._codegen._engine
    name = kernel.overloads[sig].fndesc.mangled_name
    addresses = [engine.get_function_address(s) for s in ("NRT_incref", "NRT_decref")]
    print(*addresses, engine.get_function_address(name), prepare(mission).params.n_steps,
          flush=True)
    os.kill(os.getpid(), signal.SIGSTOP)  # gdb attaches here
    side.run_once(case, reading, 1, run)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", help="planner:drones[:rc[:sigma]]")
    parser.add_argument("--run", type=int, default=3, help="run index (seed 1)")
    parser.add_argument("--reading", default="sarlink-1", help="the reading of the paper to fly")
    parser.add_argument("--serve", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.serve:
        serve(args.case, args.run, args.reading)
        return
    child = subprocess.Popen([sys.executable, sys.argv[0], args.case, "--run", str(args.run),
                              "--reading", args.reading, "--serve"], stdout=subprocess.PIPE,
                             text=True)
    assert child.stdout is not None
    inc, dec, base, n_steps = (int(v) for v in child.stdout.readline().split())
    with tempfile.NamedTemporaryFile("w", suffix=".py") as script:
        script.write(GDB_SCRIPT.format(inc=inc, dec=dec, base=base))
        script.flush()
        out = subprocess.run(["gdb", "-q", "-batch", "-p", str(child.pid), "-ex",
                              f"source {script.name}"], capture_output=True, text=True).stdout
    child.wait()
    hits = [line.split()[1:] for line in out.splitlines() if line.startswith("HIT")]
    total = sum(int(c) for *_, c in hits)
    print(f"{args.case}: {total / (n_steps + 1):.2f} reference-count operations per step "
          f"({total} in {n_steps + 1} steps at most)")
    for kind, offset, count in hits:
        if int(count) * 10 > n_steps:
            print(f"  {kind} at kernel+{int(offset):#x}: {count}")


if __name__ == "__main__":
    main()
