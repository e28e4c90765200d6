"""ConB's lock and what breaks it: the relaying planners under ``sarlink-3``, under each of
``sarlink-4``'s new choices alone, and under ``sarlink-4`` (docs/model.md, "ConB's lock").

Under ``sarlink-3`` a ConB team leaves the BS together, every drone reaches r_c at the same
step with the BS as its only routed neighbour, Eq. 9's two unit terms cancel and the drone
reverses: a star that never leaves the disc of radius r_c, whose P_d is the share of the
square within r_c + r of the BS (the ``disc`` column, from shapely). The rows show whether
the team leaves that disc (P_d above it, rising with t_d) and what it costs the connected
share and immediate notification.

Not a speed measurement: a model measurement at a modest run count, common random numbers
(seed 2024, runs 0 .. RUNS-1 at every row). Writes ``benchmarks/results/conb-lock.md``.

    .venv/bin/python benchmarks/conb_lock.py [RUNS]
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np
from shapely.geometry import Point, box

import results_file
from sarlink import Mission, prepare

SEED = 2024
TDS = (1000.0, 2000.0, 4000.0)

POINTS: list[dict[str, object]] = [
    {"planner": "conb", "drones": 4, "rc": 1000.0},
    {"planner": "conb", "drones": 6, "rc": 1000.0},
    {"planner": "conb", "drones": 8, "rc": 1000.0},
    {"planner": "conb", "drones": 10, "rc": 1000.0},
    {"planner": "conb", "drones": 22, "rc": 500.0},
    {"planner": "concov", "drones": 10, "rc": 1000.0},
    {"planner": "mtsp-conb", "drones": 10, "rc": 1000.0},
    {"planner": "mtsp-conb", "drones": 22, "rc": 500.0},
]

VARIANTS: list[tuple[str, str, dict[str, str]]] = [
    ("sarlink-3", "sarlink-3", {}),
    ("sarlink-3, turns = jitter", "sarlink-3", {"turns": "jitter"}),
    ("sarlink-3, conb_fallback = limit", "sarlink-3", {"conb_fallback": "limit"}),
    ("sarlink-3, parked = base", "sarlink-3", {"parked": "base"}),
    ("sarlink-4", "sarlink-4", {}),
]


def disc_share(mission: Mission) -> float:
    """The share of the area within r_c + r of the BS: a star's P_d at any t_d."""
    a = mission.area.size
    reach = Point(*mission.area.bs_xy).buffer(mission.channel.rc + mission.sensing.r, 256)
    return float(reach.intersection(box(0.0, 0.0, a, a)).area / (a * a))


def _row(label: str, reading: str, choices: dict[str, str], point: dict[str, object],
         runs: int) -> str:
    mission = Mission.build(reading=reading, horizon=4000.0, **{**point, **choices})
    prepared = prepare(mission)
    results = [prepared.run(SEED, k) for k in range(runs)]
    detect = np.array([math.inf if r.t_detect is None else r.t_detect for r in results])
    notify = np.array([math.inf if r.t_notify is None else r.t_notify for r in results])
    pd_ = " / ".join(f"{float(np.mean(detect <= td)):.2f}" for td in TDS)
    ps = " / ".join(f"{float(np.mean(notify <= td)):.2f}" for td in TDS)
    connected = float(np.mean([r.connected_fraction(4000.0) for r in results]))
    immediate = float(np.mean([r.immediate for r in results]))
    reach = float(np.mean([r.t_reachable(4000.0) for r in results])) / 40.0
    where = f"{point['planner']}, N_m = {point['drones']}, r_c = {point['rc']:g} m"
    return (f"| {where} | {label} | {pd_} | {disc_share(mission):.3f} | {ps} | "
            f"{connected:.2f} | {immediate:.2f} | {reach:.1f} |")


def main(runs: int) -> str:
    se = math.sqrt(0.25 / runs)
    lines = [f"{runs} runs per row, seed {SEED} (a share's binomial standard error is at most "
             f"{se:.3f}). P_d and P_s at t_d = {' / '.join(f'{t:g}' for t in TDS)} s; disc = "
             "the share of the square within r_c + r of the BS, a star's P_d; connected = mean "
             "share of the drones with a route to the BS over 4000 s; immediate = share "
             "notified at the step of detection; reachability = mean % of the 4000 s the "
             "target had a route to the BS.", "",
             "| point | reading | P_d | disc | P_s | connected | immediate | reachability, % |",
             "|---|---|---|---|---|---|---|---|"]
    t0 = time.perf_counter()
    for point in POINTS:
        for label, reading, choices in VARIANTS:
            row = _row(label, reading, choices, point, runs)
            lines.append(row)
            print(row, flush=True)
    lines += ["", f"({time.perf_counter() - t0:.0f} s on this machine, one process)", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    text = main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
    results_file.write(Path(__file__).parent / "results" / "conb-lock.md",
                       "ConB's lock and what breaks it", text)
