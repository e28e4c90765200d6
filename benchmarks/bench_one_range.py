"""CPU of a one-range CovB sweep (N = 10, 300 runs), its jobs in this process: run it in two
checkouts to compare them (a one-range sweep must cost what it cost before the range scan
existed). Usage, from each checkout's root with its own environment:

    .venv/bin/python benchmarks/bench_one_range.py LABEL

It only uses each checkout's own ``execution._calls`` and ``_run_chunk``, whatever their
signatures.
"""

import sys
import tempfile
import time
from pathlib import Path

from inprocess import InProcess
from sarlink import Experiment
from sarlink.execution import sweep_all


def exp(runs: int) -> Experiment:
    return Experiment.from_dict({"name": "one", "seed": 7, "runs": runs, "chunk": 100,
        "mission": {"team": {"planner": "covb", "drones": 10}}, "grid": {"rc": [1000.0]}})
with tempfile.TemporaryDirectory() as tmp:
    sweep_all([(exp(2), Path(tmp) / "w")], progress=False, pool=InProcess())
    best = []
    for i in range(3):
        s = time.process_time()
        sweep_all([(exp(300), Path(tmp) / f"r{i}")], progress=False, pool=InProcess())
        best.append(time.process_time() - s)
print(sys.argv[1], "one-range CovB N=10 sweep, 300 runs, CPU s (3 repeats):",
      " ".join(f"{b:.2f}" for b in best))
