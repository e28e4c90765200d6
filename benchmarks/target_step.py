"""What a moving target's own time step (``target.motion_step``, docs/model.md, Target motion)
changes: the outcome and the cost of the runs when the target moves every time step (0),
every 10 s (the default) and every 60 s, for a walking and a drifting target.

CovB with N_m = 10 at r_c = 500 m over the paper's square and 4000 s, half an hour between the
sighting and take-off, the walk's defaults and the drift of Fig. 12 (PIW-1, wind (5, 0) m/s,
current (0, 0.2) m/s); seed 2024, runs 0 .. RUNS-1 of each (the same last-seen points; the
paths differ, since a coarser step draws less). Reports P_d at 1000, 2000 and 4000 s and P_s
at 4000 s with their 95 % Wilson intervals, the difference from every time step with its 95 %
interval (two independent proportions: conservative, the runs share their starts), and the
median time per run (the variants flown alternately). Writes
``benchmarks/results/target-step.md``::

    python benchmarks/target_step.py [RUNS]
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from pathlib import Path

import results_file
from sarlink import Mission, prepare
from sarlink.metrics import wilson

SEED = 2024
STEPS = (0.0, 10.0, 60.0)
MOTIONS = {"walk": {"motion": "walk"},
           "drift": {"motion": "drift", "drift_wind": "5,0", "drift_current": "0,0.2"}}
TDS = (1000.0, 2000.0, 4000.0)


def _share(hits: int, runs: int) -> str:
    lo, hi = wilson(hits, runs)
    return f"{hits / runs:.3f} [{lo:.3f}, {hi:.3f}]"


def _difference(a: int, b: int, runs: int) -> str:
    """b/runs − a/runs with a 95 % normal interval of two independent proportions."""
    pa, pb = a / runs, b / runs
    half = 1.96 * math.sqrt((pa * (1 - pa) + pb * (1 - pb)) / runs)
    return f"{pb - pa:+.3f} ± {half:.3f}"


def main() -> None:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    lines = ["| target | motion_step | P_d(1000 s) | P_d(2000 s) | P_d(4000 s) | P_s(4000 s) | "
             "P_s − every step | median ms per run |", "|---|---|---|---|---|---|---|---|"]
    for motion, params in MOTIONS.items():
        prepared = {step: prepare(Mission.build(planner="covb", drones=10, rc=500.0,
                                                delay=1800.0, motion_step=step, **params))
                    for step in STEPS}
        for p in prepared.values():  # compile and warm
            p.run(SEED, 0)
        seconds: dict[float, list[float]] = {step: [] for step in STEPS}
        detected = {step: [0] * len(TDS) for step in STEPS}
        notified = dict.fromkeys(STEPS, 0)
        for run in range(runs):
            for step in STEPS[:: 1 if run % 2 == 0 else -1]:
                start = time.perf_counter()
                got = prepared[step].run(SEED, run)
                seconds[step].append(time.perf_counter() - start)
                for i, td in enumerate(TDS):
                    detected[step][i] += got.t_detect is not None and got.t_detect <= td
                notified[step] += got.t_notify is not None
        for step in STEPS:
            lines.append(
                f"| {motion} | {step:g} s | "
                + " | ".join(_share(h, runs) for h in detected[step])
                + f" | {_share(notified[step], runs)} | "
                + ("" if step == 0.0 else _difference(notified[0.0], notified[step], runs))
                + f" | {1000 * statistics.median(seconds[step]):.2f} |")
    body = "\n".join([
        f"CovB, N_m = 10, r_c = 500 m, the paper's 4 km square and 4000 s (success: the BS "
        f"told within 4000 s); 1800 s from the sighting to take-off; seed {SEED}, runs 0-"
        f"{runs - 1}. The walk's defaults (0.5 m/s, 0.5 rad a minute, median 4 h mobile); the "
        "drift of Fig. 12 (PIW-1, wind (5, 0) m/s, current (0, 0.2) m/s). `motion_step` 0: the "
        "target moves at every time step (dt = 1 s).", "", *lines, "",
        "Intervals: 95 % Wilson for each share; for the difference, 95 % of two independent "
        "proportions (the variants share each run's last-seen point, so it is conservative)."])
    print(body)
    results_file.write(Path(__file__).parent / "results" / "target-step.md",
                       "A moving target's own time step: outcome and cost", body)


if __name__ == "__main__":
    main()
