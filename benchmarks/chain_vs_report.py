"""Search, then relay against reporting (docs/model.md, Search, then relay): once a drone has
found the target, ``on_detect = report`` sends the drones that know to the BS, ``relay`` holds
the detector over the target and forms a chain of links from the BS to it.

Not a speed measurement: a model measurement on the paper's setting (the default mission: the
4 km square, the BS at its centre, r = 500 m, V_m = 5 m/s, T_max = 4000 s) for CovB and mTSP
at r_c = 500 m and N_m = 8, common random numbers (seed 2024, runs 0 .. RUNS-1 for each row,
so the two behaviours are paired run by run). Writes ``benchmarks/results/chain-vs-report.md``.

    .venv/bin/python benchmarks/chain_vs_report.py [RUNS]
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

import results_file
from sarlink import Mission, prepare

SEED = 2024
HORIZON = 4000.0
TDS = (1000.0, 2000.0, 4000.0)
PLANNERS = ("covb", "mtsp")
MODES = ("report", "relay")


def _notify_times(planner: str, mode: str, runs: int) -> tuple[np.ndarray, np.ndarray]:
    """Each run's notification time (inf: none within the horizon) and the share of the
    horizon after its notification at which the target had a route to the BS."""
    mission = Mission.build(planner=planner, drones=8, rc=500.0, horizon=HORIZON,
                            on_detect=mode)
    prepared = prepare(mission)
    notify, after = [], []
    for k in range(runs):
        r = prepared.run(SEED, k)
        t = math.inf if r.t_notify is None else r.t_notify
        notify.append(t)
        if math.isfinite(t) and t < HORIZON:
            held = r.t_reachable(HORIZON) - (r.t_reachable(t) if t > 0 else 0.0)
            after.append(held / (HORIZON - t))
    return np.array(notify), np.array(after)


def main(runs: int) -> str:
    lines = [f"{runs} runs per row, seed {SEED}, N_m = 8, r_c = 500 m, the default mission "
             f"(the paper's setting), flown to {HORIZON:g} s. P_s(t_d) = share of runs whose "
             "BS was notified by t_d (± one binomial standard error); mean notification time "
             "of the runs notified within the horizon; link kept = mean share of the time "
             "from the notification to the horizon at which the target had a route to the BS "
             "(over the notified runs); earlier / later = runs (of the same seed and index) "
             "notified earlier / later with relay than with report.", "",
             "| planner | on_detect | " + " | ".join(f"P_s({td:g} s)" for td in TDS)
             + " | mean notification time, s | link kept | earlier | later |",
             "|---|---|" + "---|" * (len(TDS) + 4)]
    t0 = time.perf_counter()
    for planner in PLANNERS:
        flown = {mode: _notify_times(planner, mode, runs) for mode in MODES}
        report, relay = flown["report"][0], flown["relay"][0]
        for mode in MODES:
            notify, after = flown[mode]
            cells = []
            for td in TDS:
                ps = float(np.mean(notify <= td))
                se = math.sqrt(max(ps * (1 - ps), 1 / runs) / runs)
                cells.append(f"{ps:.3f} ± {se:.3f}")
            done = np.isfinite(notify)
            mean = float(notify[done].mean()) if done.any() else math.nan
            kept = float(after.mean()) if after.size else math.nan
            paired = (f"{int(np.sum(relay < report))} | {int(np.sum(relay > report))}"
                      if mode == "relay" else "— | —")
            row = (f"| {planner} | {mode} | " + " | ".join(cells)
                   + f" | {mean:.0f} | {kept:.2f} | {paired} |")
            lines.append(row)
            print(row, flush=True)
    lines += ["", f"({time.perf_counter() - t0:.0f} s on this machine, one process, compiled "
              "kernels loaded from the cache)", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    text = main(int(sys.argv[1]) if len(sys.argv) > 1 else 100)
    results_file.write(Path(__file__).parent / "results" / "chain-vs-report.md",
                       "Search, then relay against reporting", text)
