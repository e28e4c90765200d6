"""Batteries in the simulation (docs/model.md, Endurance): what a 25-minute battery does to the
paper's 2-drone mTSP team, with swaps at the BS and without, and what a run on batteries
costs.

A model measurement on the paper's setting (the 4 km square, the BS at its centre, r = 500 m,
V_m = 5 m/s, r_c = 500 m), flown to 8000 s with the flight budget T_max raised to match (the
paper's 4000 s would end the tours before the batteries matter), common random numbers
(seed 2024, runs 0 .. RUNS-1 in every row). The battery holds 25 minutes of hover under
Zeng's model (its capacity is the hover power times 1500 s, as docs/missions.md's "25-minute
battery"), with the default reserve (0.2)
and swap time (120 s); "no swap" has no spare at the BS. Then the time per run of CovB's
N_m = 10 with and without that battery (the same runs, each kernel compiled and warmed
first). Writes ``benchmarks/results/endurance.md``.

    .venv/bin/python benchmarks/endurance.py [RUNS]
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

import results_file
from sarlink import Mission, prepare
from sarlink.engine.energy import get_energy_model

SEED = 2024
HORIZON = 8000.0
TDS = (2000.0, 4000.0, 6000.0, 8000.0)
MODEL = "zeng2019"
MINUTES = 25.0


def battery_wh() -> float:
    """The capacity that hovers ``MINUTES`` under :data:`MODEL`, Wh."""
    return get_energy_model(MODEL).power(0.0) * MINUTES * 60.0 / 3600.0


TEAMS: dict[str, dict[str, Any]] = {
    "no battery (the paper)": {},
    "battery, swaps": {"battery_wh": battery_wh(), "energy_model": MODEL},
    "battery, no swap": {"battery_wh": battery_wh(), "energy_model": MODEL, "spares": 0},
}


def _row(name: str, runs: int) -> str:
    mission = Mission.build(planner="mtsp", drones=2, rc=500.0, horizon=HORIZON,
                            flight_time=HORIZON, **TEAMS[name])
    prepared = prepare(mission)
    notify, sorties, ground = [], [], []
    for k in range(runs):
        r = prepared.run(SEED, k)
        notify.append(math.inf if r.t_notify is None else r.t_notify)
        if r.sorties is not None and r.ground_time is not None:
            sorties.append(float(r.sorties.mean()))
            ground.append(float(r.ground_time.mean()))
    times = np.array(notify)
    cells = []
    for td in TDS:
        ps = float(np.mean(times <= td))
        se = math.sqrt(max(ps * (1 - ps), 1 / runs) / runs)
        cells.append(f"{ps:.3f} ± {se:.3f}")
    flown = (f"{statistics.fmean(sorties):.2f} | {statistics.fmean(ground):.0f}"
             if sorties else "1 | 0")
    return f"| {name} | " + " | ".join(cells) + f" | {flown} |"


def _per_run(battery: bool, runs: int) -> float:
    """Median seconds per CovB N_m = 10 run over ``runs`` runs, its kernel warmed first."""
    extra = TEAMS["battery, swaps"] if battery else {}
    prepared = prepare(Mission.build(planner="covb", drones=10, rc=500.0, **extra))
    prepared.run(SEED, 0)
    spent = []
    for k in range(runs):
        t0 = time.perf_counter()
        prepared.run(SEED, k)
        spent.append(time.perf_counter() - t0)
    return statistics.median(spent)


def main(runs: int) -> str:
    wh = battery_wh()
    lines = [f"{runs} runs per row, seed {SEED}: the paper's 2-drone mTSP team at r_c = 500 m "
             f"on the default square, flown to {HORIZON:g} s (T_max = {HORIZON:g} s). Battery: "
             f"{wh:.1f} Wh, {MINUTES:g} minutes of hover under {MODEL} "
             f"({get_energy_model(MODEL).power(0.0):.1f} W; "
             f"{get_energy_model(MODEL).power(5.0):.1f} W at 5 m/s), reserve 0.2, swap 120 s. "
             "P_s(t_d) = share of runs notified by t_d (± one binomial standard error); sorties "
             "and ground time: per drone, mean over the runs.", "",
             "| team | " + " | ".join(f"P_s({td:g} s)" for td in TDS)
             + " | sorties per drone | swap time per drone, s |",
             "|---|" + "---|" * (len(TDS) + 2)]
    t0 = time.perf_counter()
    for name in TEAMS:
        row = _row(name, runs)
        lines.append(row)
        print(row, flush=True)
    plain, battery = _per_run(False, runs), _per_run(True, runs)
    lines += ["", f"Per run, CovB N_m = 10, r_c = 500 m, the default horizon ({runs} runs, "
              f"median): {plain * 1e3:.2f} ms without a battery, {battery * 1e3:.2f} ms with "
              f"the battery above ({battery / plain:.2f}×).", "",
              f"({time.perf_counter() - t0:.0f} s on this machine, one process)", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    text = main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
    results_file.write(Path(__file__).parent / "results" / "endurance.md",
                       "Batteries: the paper's 2-drone mTSP team, with and without swaps", text)
