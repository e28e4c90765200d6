"""Where the reproduction's time goes: CPU per experiment, planner and figure.

Every sweep of ``sarlink reproduce`` (the experiments of :mod:`sarlink.paper.experiments`,
split by planner as the reproduction splits them, under the default reading or ``--reading``)
is swept with the sweep's own code at a reduced number of runs per grid point, its jobs run in
this process (CPU time of the work: flights, critical ranges, tables, files; no worker
start-up). A sweep of one run beforehand, not counted, compiles or loads every kernel the
sweep uses (the flight's and its readings') and solves run 0's plans; the plans of the other
runs, which the default reading solves per run, are solved in the timing, in a plan cache of
its own so that plans of an earlier call are not reused. The CPU is scaled linearly to the
paper's 2000 runs per point. Figures are drawn from the tables and timed too. Run with

    python benchmarks/bench_reproduce.py --runs 20 --out benchmarks/results/reproduce.md

The full 2000-run reproduction is not run: the machine is shared. The scaled numbers assume
that a run's cost does not depend on its index (runs 0 .. R-1 stand for all 2000).
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from collections import defaultdict
from pathlib import Path

import pandas as pd

import results_file
from inprocess import InProcess
from sarlink import Experiment, execution
from sarlink.cachedir import cache_root
from sarlink.config import DEFAULT_READING, get_reading
from sarlink.execution import sweep_all
from sarlink.paper.experiments import EXPERIMENTS, RUNS
from sarlink.paper.figures import FIGURES
from sarlink.paper.variants import _planner_sweeps
from sarlink.planners import get_planner
from sarlink.simulation import plugins_in_code


def _timed(sweeps: list[tuple[Experiment, Path]]) -> tuple[list[pd.DataFrame], float]:
    """The sweeps' runs, swept in one call in this process, and the CPU seconds it took."""
    start = time.process_time()
    frames = sweep_all(sweeps, progress=False, pool=InProcess())
    return frames, time.process_time() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=20, help="runs per grid point")
    parser.add_argument("--reading", default=DEFAULT_READING,
                        help=f"the reading swept (default {DEFAULT_READING})")
    parser.add_argument("--out", type=Path, default=Path("benchmarks/results/reproduce.md"))
    args = parser.parse_args()
    assert not any(plugins_in_code().values())
    choices = get_reading(args.reading).choices
    rows = []  # experiment, planner, points, CPU s
    together: dict[str, float] = {}  # planner: CPU s of its main and report swept at once
    tables: dict[str, list] = defaultdict(list)
    kernels = cache_root() / "kernels"  # the compiled kernels, but no plan of a run
    kernels.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp, execution._environment(
            {"SARLINK_CACHE_DIR": str(Path(tmp) / "cache")}):
        (Path(tmp) / "cache").mkdir()
        (Path(tmp) / "cache" / "kernels").symlink_to(kernels)
        for exp in EXPERIMENTS.values():
            warm = dict(_planner_sweeps(exp, 1, choices))
            for folder, experiment in _planner_sweeps(exp, args.runs, choices):
                # kernels (the flight's and its readings'), run 0's plans: outside the timing
                sweep_all([(warm[folder], Path(tmp) / "warm" / folder)], progress=False,
                          pool=InProcess())
                (frame,), cpu = _timed([(experiment, Path(tmp) / folder)])
                planner = experiment.mission.team.planner
                rows.append((exp.name, planner, len(experiment.points()), cpu))
                tables[exp.name].append(frame)
                print(f"{exp.name:10s} {planner:18s} {len(experiment.points()):4d} "
                      f"points {cpu:7.2f} s", flush=True)
        # as the reproduction sweeps them: each planner's main and report in one call, whose
        # reporting runs are taken from main's runs where no drone reports (engine.sharing)
        # (in a plan cache of their own: the plans of each run are solved again)
        pairs = [dict(_planner_sweeps(EXPERIMENTS[name], args.runs, choices))
                 for name in ("main", "report")]
        warm = [dict(_planner_sweeps(EXPERIMENTS[name], 1, choices)) for name in ("main", "report")]
        again = Path(tmp) / "together"
        (again / "cache").mkdir(parents=True)
        (again / "cache" / "kernels").symlink_to(kernels)
        os.environ["SARLINK_CACHE_DIR"] = str(again / "cache")
        for main_folder, report_folder in zip(*pairs, strict=True):
            sweep_all([(warm[0][main_folder], again / "warm" / main_folder),
                       (warm[1][report_folder], again / "warm" / report_folder)],
                      progress=False, pool=InProcess())
            _, cpu = _timed([(pairs[0][main_folder], again / main_folder),
                             (pairs[1][report_folder], again / report_folder)])
            together[pairs[0][main_folder].mission.team.planner] = cpu
            print(f"main+report {pairs[0][main_folder].mission.team.planner:18s} {cpu:7.2f} s",
                  flush=True)
    summaries = {}
    for exp in EXPERIMENTS.values():
        summaries.update(exp.tables(pd.concat(tables[exp.name], ignore_index=True)))
    drawing = {}
    for number, spec in FIGURES.items():
        if all(t in summaries for t in spec.tables):
            start = time.process_time()
            spec.draw(*(summaries[t] for t in spec.tables))
            drawing[number] = time.process_time() - start
    scale = RUNS / args.runs
    total = sum(r[3] for r in rows) * scale
    lines = [
        "Every sweep "
        f"of `sarlink reproduce` under the reading {args.reading} at **{args.runs} runs per grid "
        f"point** (not the paper's {RUNS}: the machine is shared), its jobs in this process "
        "(CPU of flights, critical ranges, tables and files, and the mTSP plans of each run "
        "that the reading solves per run; no worker start-up; kernels and run 0's plans made "
        f"beforehand by a one-run sweep), scaled ×{scale:g} to {RUNS} runs per point.",
        "",
        "| experiment | figures | planner | points | CPU s measured | ms per run | "
        f"CPU min at {RUNS} runs | share |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for name, planner, points, cpu in sorted(rows, key=lambda r: -r[3]):
        figures = ", ".join(map(str, EXPERIMENTS[name].figures))
        lines.append(f"| {name} | {figures} | {get_planner(planner).label} | {points} | "
                     f"{cpu:.2f} | {1e3 * cpu / (points * args.runs):.2f} | "
                     f"{cpu * scale / 60:.1f} | {cpu * scale / total:.1%} |")
    lines += ["", "By experiment (and the figures it feeds):", "",
              f"| experiment | figures | CPU min at {RUNS} runs | share |", "|---|---|---|---|"]
    for exp in EXPERIMENTS.values():
        cpu = sum(r[3] for r in rows if r[0] == exp.name) * scale
        lines.append(f"| {exp.name} | {', '.join(map(str, exp.figures))} | "
                     f"{cpu / 60:.1f} | {cpu / total:.1%} |")
    by_planner: dict[str, float] = defaultdict(float)
    for _, planner, _, cpu in rows:
        by_planner[planner] += cpu * scale
    lines += ["", "By planner, over every experiment:", "",
              f"| planner | CPU min at {RUNS} runs | share |", "|---|---|---|"]
    for planner, cpu in sorted(by_planner.items(), key=lambda kv: -kv[1]):
        lines.append(f"| {get_planner(planner).label} | {cpu / 60:.1f} | {cpu / total:.1%} |")
    alone = sum(r[3] for r in rows if r[0] in ("main", "report")) * scale
    shared = total - alone + sum(together.values()) * scale
    lines += ["", f"Total: **{total / 60:.1f} CPU-minutes** of sweeps at {RUNS} runs per point, "
              f"each swept alone (about {total / 120:.1f} min of wall time on 2 idle cores); "
              f"**{shared / 60:.1f}** as the reproduction sweeps them, each planner's `main` "
              f"and `report` in one call, which takes a reporting run from `main`'s run where "
              f"no drone reports ({alone / 60:.1f} CPU-minutes for the two swept apart, "
              f"{sum(together.values()) * scale / 60:.1f} together: "
              + ", ".join(f"{get_planner(p).label} {cpu * scale / 60:.1f}"
                          for p, cpu in together.items()) + ").", "",
              "Drawing each figure from its tables (independent of the runs), CPU s: " +
              ", ".join(f"Fig. {n} {s:.2f}" for n, s in sorted(drawing.items())) + ".", ""]
    lines += ["The reporting runs of `report` and their prefix. A reporting run where no drone "
              "ever reports (nothing detected, or the BS told in the step of the first "
              "detection) is `main`'s run with the same seed and index, ended where it stops: "
              "swept with `main` it is taken, not flown. Every other one flies as `main`'s run "
              "until the first detection, a prefix that is still flown twice (its share of "
              "the run's flown time: until the notification, where the run stops, or the "
              "horizon).", "",
              "| planner | runs | detected | taken from `main` | flight before the first "
              "detection |", "|---|---|---|---|---|"]
    for planner, frame in pd.concat(tables["report"]).groupby("planner", sort=False):
        flown = frame["t_notify"].fillna(frame["horizon"])
        before = frame["t_detect"].fillna(frame["horizon"]).clip(upper=flown)
        taken = frame["t_detect"].isna() | frame["immediate"]
        lines.append(f"| {get_planner(str(planner)).label} | {len(frame)} | "
                     f"{frame['t_detect'].notna().mean():.1%} | {taken.mean():.1%} | "
                     f"{before.sum() / flown.sum():.1%} |")
    lines.append("")
    print("\n".join(lines))
    results_file.write(args.out, "Where the reproduction's time goes", "\n".join(lines))


if __name__ == "__main__":
    main()
