"""What each named choice of a reading changes: the default reading with that one choice set to
each of its values, at a point of the paper's grid where the choice acts (docs/model.md,
Readings).

Not a speed measurement: a model measurement at a modest run count, common random numbers
(seed 2024, runs 0 .. RUNS-1 at every row). Writes ``benchmarks/results/readings-effects.md``.

    .venv/bin/python benchmarks/readings_effects.py [RUNS]
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path
from typing import get_args

import numpy as np

import results_file
from sarlink import Mission, prepare
from sarlink.config import DEFAULT_READING, READINGS, Readings

SEED = 2024
TD = 1000.0

CASES: list[tuple[str, dict[str, object]]] = [
    ("takeoff", {"planner": "conb", "drones": 6, "rc": 1000.0}),
    ("takeoff", {"planner": "conb", "drones": 2, "rc": 1000.0}),
    ("takeoff", {"planner": "concov", "drones": 6, "rc": 1000.0}),
    ("conb_fallback", {"planner": "conb", "drones": 10, "rc": 1000.0}),
    ("turns", {"planner": "conb", "drones": 10, "rc": 1000.0}),
    ("turns", {"planner": "covb", "drones": 10, "rc": 1000.0}),
    ("covb_direction", {"planner": "covb", "drones": 10, "rc": 1000.0}),
    ("shadowing", {"planner": "conb", "drones": 10, "rc": 1000.0, "sigma": 3.0}),
    ("shadowing", {"planner": "mtsp", "drones": 10, "rc": 1000.0, "sigma": 3.0}),
    ("shadow_calibration", {"planner": "conb", "drones": 10, "rc": 1000.0, "sigma": 3.0}),
    ("reachability", {"planner": "covb", "drones": 10, "rc": 500.0}),
    ("parked", {"planner": "mtsp", "drones": 10, "rc": 500.0}),
    ("parked", {"planner": "mtsp", "drones": 22, "rc": 500.0}),
    ("reachability", {"planner": "covb", "drones": 10, "rc": 2000.0}),
    ("mtsp_plan", {"planner": "mtsp", "drones": 20, "rc": 1000.0}),
    ("mtsp_plan", {"planner": "mtsp", "drones": 22, "rc": 1000.0}),
    ("mtsp_prediction", {"planner": "mtsp-conb", "drones": 10, "rc": 1000.0}),
]


def _row(choice: str, value: str, point: dict[str, object], runs: int) -> str:
    mission = Mission.build(reading=DEFAULT_READING, horizon=4000.0, **{**point, choice: value})
    prepared = prepare(mission)
    results = [prepared.run(SEED, k) for k in range(runs)]
    notify = np.array([math.inf if r.t_notify is None else r.t_notify for r in results])
    detect = np.array([math.inf if r.t_detect is None else r.t_detect for r in results])
    ps = float(np.mean(notify <= TD))
    se = math.sqrt(max(ps * (1 - ps), 1 / runs) / runs)
    done = np.isfinite(notify)
    mission_time = float(notify[done].mean()) if done.any() else math.nan
    immediate = float(np.mean([r.immediate for r in results]))
    reach = float(np.mean([r.t_reachable(4000.0) for r in results])) / 40.0
    connected = float(np.mean([r.connected_fraction(4000.0) for r in results]))
    where = ", ".join(f"{k}={v:g}" if isinstance(v, float) else f"{k}={v}"
                      for k, v in point.items())
    return (f"| `{choice}` | {where} | {value} | {float(np.mean(detect <= TD)):.3f} | "
            f"{ps:.3f} ± {se:.3f} | {mission_time:.0f} | {immediate:.3f} | {reach:.1f} | "
            f"{connected:.2f} |")


def main(runs: int) -> str:
    values = {c: get_args(Readings.model_fields[c].annotation) for c, _ in CASES}
    lines = [f"{runs} runs per row, seed {SEED}. The default reading (`{DEFAULT_READING}`) "
             "with one choice set to each value; "
             f"the default's value is in bold. P_d and P_s at t_d = {TD:g} s (± one binomial "
             "standard error), mission time = mean notification time of the runs notified "
             "within 4000 s, immediate = share notified at the step of detection, reachability "
             "= mean % of the 4000 s the target had a route to the BS, connected = mean share "
             "of the drones with a route to the BS over the 4000 s.", "",
             "| choice | point | value | P_d | P_s | mission time, s | immediate | "
             "reachability, % | connected |", "|---|---|---|---|---|---|---|---|---|"]
    default = READINGS[DEFAULT_READING].choices
    t0 = time.perf_counter()
    for choice, point in CASES:
        for value in values[choice]:
            row = _row(choice, value, point, runs)
            if value == default[choice]:
                row = row.replace(f"| {value} |", f"| **{value}** |", 1)
            lines.append(row)
            print(row, flush=True)
    lines += ["", f"({time.perf_counter() - t0:.0f} s on this machine, one process)", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    text = main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
    results_file.write(Path(__file__).parent / "results" / "readings-effects.md",
                       "What each named choice changes", text)
