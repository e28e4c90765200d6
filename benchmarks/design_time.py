"""Wall and CPU time of ``sarlink design`` on git revision ``REV`` (today's main) against the
working tree, on the same request, on this machine.

Each side runs ``sarlink design ... --json`` in a process of its own (with this script's
``nice``): the old one from a temporary git worktree of ``REV`` with that worktree's ``src``
first on ``PYTHONPATH``, the new one from this repository's ``src``. Each starts from empty
folders (runs, mTSP plans, Numba's compiled kernels), so both pay their compiles and solve
their plans. CPU time is that of the process and every worker it started (the rusage of
reaped children), the fairer number on a shared host; the load average is sampled every 30 s
while each side runs. Then the recommendation of each side is checked with 1000 independent
runs (another seed) of the mission it recommends, by the working tree's code. Run with

    nice -n 10 python benchmarks/design_time.py main --out benchmarks/results/design-time.md

The old design takes tens of minutes: ``--side old`` or ``--side new`` measures one side and
keeps it in ``--state`` (JSON), so the two can be measured in two calls; the results file is
written once the state holds both (``--side none``: from the state alone). After the new
side, it is asked again with its caches kept (a machine that has run sarlink before), and the
compile of every planner's kernel from an empty cache is timed apart (``--side
compiles``: that alone), the fixed part of a first design on a machine.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

import results_file

REQUEST = ["--rc", "500", "--td", "1800", "--ps", "0.9"]
"""The coordinator's question of issue 45: 500 m radios, found and reported within 30 minutes
with probability 0.9."""

CHECK_RUNS = 1000
CHECK_SEED = 7777
"""The seed of the independent check, not the design's (2024)."""


def _load_sampler(samples: list[float], stop: threading.Event) -> threading.Thread:
    def sample() -> None:
        while not stop.wait(30):
            samples.append(os.getloadavg()[0])
    thread = threading.Thread(target=sample, daemon=True)
    thread.start()
    return thread


WARM = ("from sarlink.planners import planner_names\n"
        "from sarlink.simulation import warm_up\n"
        "for planner in planner_names():\n"
        "    warm_up(planner, 'disc')\n")
"""Compile the kernel of every planner the design tries (patterns share one), one process."""


def _env(src: Path, workdir: Path) -> dict[str, str]:
    """The environment of a side: its ``src`` first, its caches in ``workdir``."""
    return {**os.environ, "PYTHONPATH": str(src), "SARLINK_CACHE_DIR": str(workdir / "cache"),
            "NUMBA_CACHE_DIR": str(workdir / "numba")}


def run_side(label: str, src: Path, workdir: Path, workers: int | None,
             runs: str = "runs", warm: bool = False) -> dict[str, Any]:
    """Run the design from ``src`` with the caches in ``workdir`` (empty on a first call,
    unless ``warm``: every planner's kernel compiled first, untimed) and an empty runs folder
    ``runs``; its wall and CPU seconds and answer."""
    env = _env(src, workdir)
    if warm:
        subprocess.run([sys.executable, "-c", WARM], env=env, check=True)
    extra = [] if workers is None else ["--workers", str(workers)]
    cmd = [sys.executable, "-c", "from sarlink.cli import app; app()", "design", *REQUEST,
           "--json", "--quiet", "--out", str(workdir / runs), *extra]
    samples = [os.getloadavg()[0]]
    stop = threading.Event()
    sampler = _load_sampler(samples, stop)
    before = _children_cpu()
    start = time.perf_counter()
    done = subprocess.run(cmd, env=env, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    cpu = _children_cpu() - before
    stop.set()
    sampler.join()
    if done.returncode != 0:
        raise SystemExit(f"{label}: design failed ({done.returncode}):\n{done.stderr[-3000:]}")
    return {"label": label, "wall": wall, "cpu": cpu, "load": samples, "warm": warm,
            "started": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime(time.time() - wall)),
            "answer": json.loads(done.stdout),
            "breakdown": breakdown(workdir / runs, workdir / "cache")}


def compiles(src: Path, workdir: Path) -> float:
    """CPU seconds that compiling the kernels of every planner takes from an empty cache: the
    fixed part of a design's time on a machine that has never run one."""
    before = _children_cpu()
    subprocess.run([sys.executable, "-c", WARM], env=_env(src, workdir), check=True)
    return _children_cpu() - before


def _children_cpu() -> float:
    """CPU seconds of this process's reaped children and theirs: a design's process grows it
    by its own and its workers' (it reaps them when it closes its pool)."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def breakdown(runs: Path, cache: Path) -> dict[str, Any]:
    """Where a side's work went, from what it left: runs and drone-seconds flown per planner
    and option (each run stops at notification or ``t_d``), and the mTSP plans solved (the
    plan files in its cache), with the team size each was solved for."""
    import pandas as pd

    from sarlink import load

    frames = [load(folder) for folder in sorted((runs / "seed-2024").iterdir())]
    df = pd.concat(frames, ignore_index=True)
    flown = df["t_notify"].fillna(df["horizon"]).clip(upper=df["horizon"]) * df["drones"]
    df = df.assign(flown=flown)
    rows = []
    for (planner, on_detect), group in df.groupby(["planner", "on_detect"], sort=True):
        rows.append({"planner": planner, "on_detect": on_detect,
                     "candidates": len(group[["drones", "alpha", "nr"]].drop_duplicates()),
                     "runs": len(group), "drone_hours": float(group["flown"].sum() / 3600)})
    plans = [json.loads(f.read_text()) for f in (cache / "plans").glob("*.json")]
    salesmen = [int(plan["params"]["salesmen"]) for plan in plans]
    return {"variants": rows, "plans": len(plans),
            "plan_seconds": float(sum(plan.get("seconds", 0.0) for plan in plans)),
            "plan_sizes": {str(n): salesmen.count(n) for n in sorted(set(salesmen))}}


def check(answer: dict[str, Any], folder: Path) -> dict[str, Any] | None:
    """The recommended mission of ``answer`` flown ``CHECK_RUNS`` times with another seed, by
    the working tree's code (so with its one shared plan): the runs that meet ``t_d``."""
    from sarlink import Experiment, sweep
    from sarlink.design import Candidate, DesignRequest, PlannerVariant

    rec = answer["recommendation"]
    if rec is None:
        return None
    request = DesignRequest.model_validate(answer["request"])
    variant = PlannerVariant(rec["planner"], tuple(rec["fixed"].items()), request.split)
    mission = Candidate(variant, rec["chosen"]["drones"], rec["chosen"]["value"]
                        ).mission(request.base())
    runs = sweep(Experiment(name="design check", seed=CHECK_SEED, runs=CHECK_RUNS,
                            mission=mission), folder, progress=False)
    met = int((runs["t_notify"] <= request.td).sum())
    return {"label": rec["label"], "drones": rec["chosen"]["drones"], "met": met,
            "runs": CHECK_RUNS, "ps": request.ps}


def unfinished(pid: int, label: str) -> dict[str, Any]:
    """A side still running as process ``pid``: its wall and CPU seconds so far (those of the
    process and its workers, from ``/proc``), lower bounds on what it will take."""
    tick = os.sysconf("SC_CLK_TCK")

    def stat(p: int) -> list[str]:
        text = Path(f"/proc/{p}/stat").read_text()
        return text[text.rindex(")") + 2:].split()  # fields from the state on

    tree = [pid] + [int(d.name) for d in Path("/proc").iterdir() if d.name.isdigit()
                    and _alive(d) and int(stat(int(d.name))[1]) == pid]
    cpu = sum(int(stat(p)[11]) + int(stat(p)[12]) for p in tree) / tick
    uptime = float(Path("/proc/uptime").read_text().split()[0])
    wall = uptime - int(stat(pid)[19]) / tick
    return {"label": label, "unfinished": True, "wall": wall, "cpu": cpu,
            "load": [os.getloadavg()[0]], "answer": None, "breakdown": None,
            "started": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime(time.time() - wall))}


def _alive(folder: Path) -> bool:
    try:
        (folder / "stat").read_text()
    except OSError:
        return False
    return True


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rev", help="the git revision to compare with (today's main)")
    parser.add_argument("--side", choices=("old", "new", "both", "compiles", "none"),
                        default="both", help="the side to measure; compiles: only the "
                        "compile time; none: only check and write from --state")
    parser.add_argument("--state", type=Path, default=Path("benchmarks/results/design-time.json"))
    parser.add_argument("--workers", type=int, default=None)
    parser.add_argument("--warm", action="store_true",
                        help="compile each side's kernels before timing it (a machine that "
                             "has run sarlink before)")
    parser.add_argument("--no-check", action="store_true",
                        help="skip the 1000-run check of each recommendation")
    parser.add_argument("--unfinished", type=int, default=None, metavar="PID",
                        help="the old side still runs as process PID: write its time so far "
                             "as a lower bound")
    parser.add_argument("--out", type=Path, default=Path("benchmarks/results/design-time.md"))
    args = parser.parse_args()
    state: dict[str, Any] = json.loads(args.state.read_text()) if args.state.exists() else {}
    with tempfile.TemporaryDirectory(prefix="design-time-") as tmp:
        root = Path(tmp)
        if args.side in ("old", "both"):
            tree = root / "old-tree"
            subprocess.run(["git", "worktree", "add", "--detach", str(tree), args.rev],
                           cwd=results_file.ROOT, check=True, capture_output=True)
            try:
                rev = subprocess.run(["git", "rev-parse", "--short", args.rev],
                                     cwd=results_file.ROOT, check=True, capture_output=True,
                                     text=True).stdout.strip()
                state["old"] = run_side(f"{args.rev} ({rev})", tree / "src", root / "old",
                                        args.workers, warm=args.warm)
            finally:
                subprocess.run(["git", "worktree", "remove", "--force", str(tree)],
                               cwd=results_file.ROOT, check=False, capture_output=True)
            args.state.write_text(json.dumps(state, indent=1))
        if args.side in ("new", "both"):
            state["new"] = run_side(f"working tree ({results_file.COMMIT})",
                                    results_file.ROOT / "src", root / "new", args.workers,
                                    warm=args.warm)
            warm = run_side("again", results_file.ROOT / "src", root / "new", args.workers,
                            runs="runs-again")
            state["new"]["again"] = {"wall": warm["wall"], "cpu": warm["cpu"]}
            args.state.write_text(json.dumps(state, indent=1))
        if args.side in ("new", "both", "compiles") and "new" in state:
            state["new"]["compiles"] = compiles(results_file.ROOT / "src", root / "compiles")
            args.state.write_text(json.dumps(state, indent=1))
    if args.unfinished is not None:
        state["old"] = unfinished(args.unfinished, f"{args.rev} (still running)")
    if "old" in state and "new" in state:
        with tempfile.TemporaryDirectory(prefix="design-check-") as tmp:
            for side in ("old", "new"):
                if state[side]["answer"] is not None and not args.no_check:
                    state[side]["check"] = check(state[side]["answer"], Path(tmp) / side)
        args.state.write_text(json.dumps(state, indent=1))
        write(state, args.out)


def write(state: dict[str, Any], out: Path) -> None:
    """The results file from both sides."""
    old, new = state["old"], state["new"]
    lines = [results_file.header("`sarlink design` on the coordinator's question: main against "
                                 "the working tree"),
             f"Request: `sarlink design {' '.join(REQUEST)}` (every planner, with and without "
             "reporting drones, up to 22 drones, seed 2024), each side from empty folders "
             + ("(runs, mTSP plans) but with every planner's kernel compiled first, untimed "
                "(`--warm`: a machine that has run sarlink before), on this "
                if old.get("warm") and new.get("warm") else
                "(runs, mTSP plans, Numba's compiled kernels: compiles are included), on this ")
             + "machine, under `nice -n 10`, default workers (one per core); sides measured in "
             "separate calls (`--side old`, `--side new`) may overlap, and then competed for "
             "the cores (see their start times and wall times). The load average, sampled "
             f"every 30 s, is below ({os.cpu_count()} cores): wall times depend on it, CPU "
             "seconds (the design's process and its workers) much less.",
             "",
             "| side | started | wall, s | CPU, s | load average (min / mean / max) | runs used "
             "| mTSP plans solved | their solve time, s (wall, summed) | recommendation "
             "| check: runs meeting t_d of 1000 |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for side in (old, new):
        load = side["load"]
        if side.get("unfinished"):
            lines.append(f"| {side['label']} | {side['started']} | more than {side['wall']:.0f} "
                         f"| more than {side['cpu']:.0f} | {load[0]:.1f} when written | – | – "
                         "| – | not finished when this file was written | – |")
            continue
        rec = side["answer"]["recommendation"]
        chosen = "none" if rec is None else (
            f"{rec['label']}, {rec['chosen']['drones']} drones, P_s = {rec['chosen']['p']:.3f} "
            f"[{rec['chosen']['lo']:.3f}, {rec['chosen']['hi']:.3f}] from "
            f"{rec['chosen']['runs']:,} runs")
        checked = side.get("check")
        verdict = "–" if checked is None else f"{checked['met']}"
        b = side["breakdown"]
        lines.append(f"| {side['label']} | {side['started']} | {side['wall']:.0f} "
                     f"| {side['cpu']:.0f} | {min(load):.1f} / {sum(load) / len(load):.1f} / "
                     f"{max(load):.1f} | {side['answer']['runs']['used']:,} | {b['plans']:,} "
                     f"| {b['plan_seconds']:.0f} | {chosen} | {verdict} |")
    least = "at least " if old.get("unfinished") else ""
    checked = any(side.get("check") for side in (old, new))
    lines += ["",
              f"Speed-up: {least}{old['wall'] / new['wall']:.1f}x in wall time, "
              f"{least}{old['cpu'] / new['cpu']:.1f}x in CPU time.",
              "",
              "" if "again" not in new else
              "Asked again with its compiled kernels and mTSP plans kept (the runs folder "
              f"empty), as on a machine that has run sarlink before, the working tree answers "
              f"in {new['again']['wall']:.0f} s of wall time ({new['again']['cpu']:.0f} CPU "
              "seconds).",
              "",
              "" if "compiles" not in new else
              "Of each side's CPU time, compiling the engine's kernels is a fixed part: every "
              f"planner's kernel from an empty cache takes {new['compiles']:.0f} CPU seconds "
              "(the working tree's, measured apart in one process); a machine that has run "
              "sarlink before loads them from its cache.",
              "",
              "" if checked else "The 1000-run check was not run for this file (`--no-check`).",
              "",
              "The check flies the recommended mission (with the working tree's code, so with "
              f"its one shared mTSP plan) {CHECK_RUNS} times with seed {CHECK_SEED}, not the "
              "design's: the requirement is met if about "
              f"{new['answer']['request']['ps']:g} of them or more meet t_d.",
              "",
              "## Where the runs went",
              "",
              "Per planner and option: the candidates (team size and setting) that got runs, "
              "the runs, and the drone-hours flown (each run ends at the notification or at "
              "t_d); a run's cost grows with its drones and its length. On main, each run of "
              "an mTSP or mTSP-ConB candidate also solved a GA plan of its own (the plans "
              "solved above).",
              ""]
    for side in (old, new):
        if side["breakdown"] is None:
            continue
        lines += [f"### {side['label']}", "",
                  "| planner | on_detect | candidates | runs | drone-hours |",
                  "|---|---|---|---|---|"]
        for row in side["breakdown"]["variants"]:
            lines.append(f"| {row['planner']} | {row['on_detect']} | {row['candidates']} "
                         f"| {row['runs']:,} | {row['drone_hours']:,.0f} |")
        sizes = ", ".join(f"{n}: {k:,}" for n, k in side["breakdown"]["plan_sizes"].items())
        lines += ["", f"mTSP plans solved, by team size: {sizes or 'none'}.", ""]
    out.write_text("\n".join(lines))


if __name__ == "__main__":
    main()
