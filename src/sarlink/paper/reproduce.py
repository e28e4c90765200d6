"""Rerun the paper's evaluation: sweeps, plan timing, summary tables, figures, claims, report.

Layout of the output folder::

    runs/<experiment>/<planner>/<choices>/
                           the sweeps, one per planner and the reading's choices that reach
                           it (sarlink.sweep folders: resumable, loadable with load; shared
                           by readings and by the sensitivity analysis)
    plan_times.json        Fig. 1's measured plan times and work counts, with their
                           setting and machine
    tables/<name>.csv      summary tables (also .parquet): main, curve, miss, shadowing,
                           plan_times, mtsp_plans, report, report_curve, others (the
                           planners beyond the paper), relays (searchers and relays),
                           moving, moving_curve (targets that move), and sensitivity
                           (claim × single change of the reading); main_runs, miss_runs,
                           shadowing_runs, relays_runs, moving_runs (Parquet only): every
                           run's values, for the paired statistics
    figures/figN.png|svg   one figure per paper figure
    report.md, report.html the report (HTML self-contained)
    replay-rc500.html      one run flown by each of the paper's planners, side by side (linked)
"""

from __future__ import annotations

import json
import os
import time
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from sarlink.config import DEFAULT_READING, ConfigError, Mission, get_reading
from sarlink.paper.experiments import (
    EXPERIMENTS,
    QUICK_RUNS,
    RUNS,
    SEED,
    plan_time_missions,
)
from sarlink.paper.figures import FIGURES, save
from sarlink.paper.findings import Finding, Settings, check_all
from sarlink.paper.report import ReplayLink, Sensitivity, Stage, machine, write_report
from sarlink.paper.variants import (
    Variant,
    flips,
    matrix,
    preset_findings,
    reading_tables,
    sensitivity,
)
from sarlink.planners import PAPER_PLANNERS, get_planner
from sarlink.plantime import plan_cost
from sarlink.playback import compare
from sarlink.progress import progress as progress_bars
from sarlink.simulation import simulate

__all__ = ["ReproductionResult", "reproduce"]

PLAN_REPEATS = 3
"""Timings per planner and team size in Fig. 1; the figure shows their median."""


@dataclass(frozen=True)
class ReproductionResult:
    """What :func:`reproduce` made, and where."""

    out: Path
    runs: int
    """Runs per grid point."""
    figures: dict[int, list[Path]]
    """Each figure's files (PNG, SVG) by its number."""
    tables: dict[str, pd.DataFrame]
    """Summary tables by name, as written to ``out/tables``."""
    findings: list[Finding]
    """The paper's claims checked: those whose figures were reproduced."""
    report_md: Path
    report_html: Path
    seconds: float
    """Wall time of the call, report writing aside."""
    stages: list[Stage]
    replay: Path
    """The side-by-side replay of one run at r_c = 500 m that the report links."""
    reading: str
    """The name of the reading the runs were made under."""
    variants: list[Variant]
    """With ``sensitivity``: the claims under each single change of the reading."""
    presets: dict[str, list[Finding]]
    """The claims under every preset reading, by name (``reading``'s are ``findings``); only
    ``reading``'s when the other presets were not run (``presets=False``)."""


def _figure_numbers(figures: Iterable[int] | None) -> list[int]:
    if figures is None:
        return sorted(FIGURES)
    numbers = sorted(set(figures))
    unknown = [n for n in numbers if n not in FIGURES]
    if unknown or not numbers:
        raise ConfigError(f"figures must be among {', '.join(map(str, FIGURES))}, "
                          f"got {', '.join(map(str, numbers)) or 'none'}")
    return numbers


def _plan_times(path: Path, missions: list[Mission], repeats: int, progress: bool
                ) -> pd.DataFrame:
    """Fig. 1's plan times and work counts (:class:`sarlink.plantime.PlanCost`): read from
    ``path`` if measured there for the same missions and repeats, otherwise measured now (one
    mission at a time, nothing else running) and stored."""
    # CPU time (plantime) and the work counts; timings of another clock, or without the
    # counts, are redone
    setting = {"missions": [m.model_dump(mode="json") for m in missions], "repeats": repeats,
               "clock": "process", "counts": ["expansions", "evaluations"]}
    if path.exists():
        stored = json.loads(path.read_text())
        if stored.get("setting") == setting:
            return pd.DataFrame(stored["rows"])
    rows = []
    with progress_bars(progress, "plans", rate=False) as bars:
        shown = bars.add_task("timing the plans of Fig. 1", total=len(missions) * repeats)
        for m in missions:
            for k in range(repeats):
                cost = plan_cost(m)
                rows.append({"planner": m.team.planner, "drones": m.team.drones,
                             "rc": m.channel.rc, "repeat": k, "seconds": cost.seconds,
                             "expansions": cost.expansions, "evaluations": cost.evaluations})
                bars.advance(shown, 1)
    temporary = path.with_suffix(".tmp")
    temporary.write_text(json.dumps({"setting": setting, "machine": machine(), "rows": rows},
                                    indent=1))
    os.replace(temporary, path)
    return pd.DataFrame(rows)


def _write_tables(folder: Path, tables: dict[str, pd.DataFrame]) -> None:
    """Every table as Parquet, and as CSV but for the per-run tables (``*_runs``), which are
    large and read by programs only."""
    folder.mkdir(parents=True, exist_ok=True)
    for name, table in tables.items():
        if not name.endswith("_runs"):
            table.to_csv(folder / f"{name}.csv", index=False)
        table.to_parquet(folder / f"{name}.parquet", index=False)


def _replay(out: Path, reading: str) -> ReplayLink:
    """Every planner of the paper flying one run at r_c = 500 m, side by side
    (``replay-rc500.html``): the first run of the paper's seed that every one notifies, so
    that each panel shows a detection and the multihop path that carried it to the BS."""
    mission = Mission.build(reading=reading, drones=10, rc=500.0)
    planners = list(PAPER_PLANNERS)
    run = next((k for k in range(100) if all(
        simulate(mission.replace(planner=p), seed=SEED, run=k).t_notify is not None
        for p in planners)), 0)
    page = compare(mission, planners, SEED, run)
    times = ", ".join(f"{get_planner(p.mission.team.planner).label} {p.result.t_notify:g} s"
                      for p in page.panels if p.result.t_notify is not None)
    about = (f"Run {run} of seed {SEED} at N = 10, r_c = 500 m, t_d = "
             f"{mission.timing.horizon:g} s, flown by each of the paper's planners (same "
             "target, same take-off) and replayed side by side under one time control: the "
             "first run of the seed that every one notifies, so that each panel shows a "
             f"detection and how the news travelled to the BS. The BS was notified at: {times}.")
    return ReplayLink(page.write(out / "replay-rc500.html"), about)


def reproduce(out: str | Path, *, runs: int | None = None, quick: bool = False,
              figures: Iterable[int] | None = None, workers: int | None = None,
              scheduler: str | None = None, progress: bool = True,
              plan_iterations: int | None = None, reading: str = DEFAULT_READING,
              sensitivity_analysis: bool = False, presets: bool | None = None,
              ) -> ReproductionResult:
    """Rerun the experiments behind the paper's figures into ``out`` and report on them.

    Only the sweeps the requested figures need are run; runs already stored in ``out`` (by an
    earlier, perhaps interrupted, call) are reused, and so are Fig. 1's plan times when they
    were measured for the same setting.

    Parameters
    ----------
    runs
        Runs per grid point; default 2000 (the paper's), or 100 with ``quick``.
    quick
        Few runs: the trends in minutes, with wide intervals. The report says so. The sweep
        of searchers and relays (Fig. 11), whose runs cost many plain ones, and that of
        targets that move (Fig. 12) fly a quarter of them
        (:attr:`~sarlink.paper.experiments.PaperExperiment.quick_share`).
    figures
        Figure numbers to reproduce (the paper's 1–7, 8 to 12 beyond it); default all.
    workers, scheduler
        As for :func:`sarlink.sweep`: local worker processes, or a Dask scheduler's address.
    progress
        Show the sweeps' progress bars.
    plan_iterations
        GA iterations for Fig. 1's mTSP timing instead of the paper's 5000 (for tests only:
        the time depends on it).
    reading
        The named reading of what the paper leaves open (:data:`sarlink.config.READINGS`):
        the rules' choices for every run, and Fig. 3's t_d for the claims.
    sensitivity_analysis
        Also decide every claim under each single change of the reading, rerunning only the
        experiments of Figs. 2-7 and only the planners a change reaches; the report gets the
        matrix claim × change.
    presets
        Also decide every claim under each other preset reading, rerunning the planners its
        choices reach (the report's tally under every preset); default: not with ``quick``,
        whose few runs leave most claims undecided anyway and which would run four times the
        sweeps.
    """
    start = time.perf_counter()
    out = Path(out)
    numbers = _figure_numbers(figures)
    runs = runs if runs is not None else QUICK_RUNS if quick else RUNS
    if runs < 1:
        raise ConfigError(f"runs must be at least 1, got {runs}")
    chosen = get_reading(reading)
    settings = Settings(td_fig3=chosen.td_fig3, reading=chosen.name)
    needed = [e for e in EXPERIMENTS.values() if set(e.figures) & set(numbers)]
    tables, stages = reading_tables(out / "runs", needed, runs, chosen.choices,
                                    workers=workers, scheduler=scheduler, progress=progress,
                                    quick=quick)
    if 1 in numbers:
        t0 = time.perf_counter()
        missions = plan_time_missions(plan_iterations)
        tables["plan_times"] = _plan_times(out / "plan_times.json", missions, PLAN_REPEATS,
                                           progress)
        stages.append(Stage("plan times", f"Fig. 1: {len(missions)} plans × {PLAN_REPEATS} "
                            "repeats", time.perf_counter() - t0))

    t0 = time.perf_counter()
    _write_tables(out / "tables", tables)
    findings = check_all(tables, settings)
    drawn = {}
    for n in numbers:
        spec = FIGURES[n]
        drawn[n] = save(spec.draw(*(tables[t] for t in spec.tables)), out / "figures", f"fig{n}")
    stages.append(Stage("figures and tables", f"{len(drawn)} figures, {len(tables)} tables",
                        time.perf_counter() - t0))
    checked = [e for e in needed if set(e.figures) & set(range(1, 8))]
    by_preset = {chosen.name: findings}
    if (not quick) if presets is None else presets:
        by_preset, timed = preset_findings(chosen, tables, out / "runs", checked, runs,
                                           workers=workers, scheduler=scheduler,
                                           progress=progress)
        stages += timed
    done: list[Variant] = []
    study = None
    if sensitivity_analysis:
        done, timed = sensitivity(chosen, tables, out / "runs", checked, runs, workers=workers,
                                  scheduler=scheduler, progress=progress)
        stages += timed
        study = Sensitivity(matrix(findings, done), flips(findings, done),
                            {v.name: list(v.findings) for v in done})
        _write_tables(out / "tables", {"sensitivity": study.matrix})
    t0 = time.perf_counter()
    replay = _replay(out, reading)
    stages.append(Stage("replay", f"{replay.page.name}: one run by each paper planner",
                        time.perf_counter() - t0))
    seconds = time.perf_counter() - start
    where = (f"Dask scheduler {scheduler}" if scheduler is not None
             else f"{workers or os.cpu_count()} local processes")
    md, page = write_report(out, runs=runs, quick=quick,
                            figures={n: paths[0] for n, paths in drawn.items()}, tables=tables,
                            findings=findings, stages=stages, seconds=seconds, workers=where,
                            reading=chosen, replay=replay, sensitivity=study,
                            presets=by_preset)
    return ReproductionResult(out, runs, drawn, tables, findings, md, page, seconds, stages,
                              replay.page, reading, done, by_preset)
