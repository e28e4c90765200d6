"""Time CovB's N_m = 10 at the paper's setting (r_c = 1000 m, 4000 s) under a few variants of
the target, on the same runs: each kernel compiled and warmed first, the variants flown in
alternating order so that the machine's drift in speed falls on each alike."""

from __future__ import annotations

import time
from typing import Any

from sarlink import Mission, RunResult, prepare


def fly_alternately(cases: dict[str, dict[str, Any]], seed: int, runs: int
                    ) -> tuple[dict[str, list[float]], dict[str, list[RunResult]]]:
    """Seconds per run and the runs of every case (``Mission.build`` keyword arguments)."""
    prepared = {name: prepare(Mission.build(planner="covb", drones=10, rc=1000.0, **params))
                for name, params in cases.items()}
    for p in prepared.values():  # compile and warm
        p.run(seed, 0)
    times: dict[str, list[float]] = {name: [] for name in cases}
    results: dict[str, list[RunResult]] = {name: [] for name in cases}
    for run in range(runs):
        for name in list(cases)[:: 1 if run % 2 == 0 else -1]:
            start = time.perf_counter()
            results[name].append(prepared[name].run(seed, run))
            times[name].append(time.perf_counter() - start)
    return times, results
