"""The paper's experiments under a reading, and what each claim depends on (``--sensitivity``).

A reading (:mod:`sarlink.config.readings`) sets the choices the paper leaves open. Most
choices reach only some planners (ConB's connectivity check changes nothing for CovB), so
every experiment is swept one planner at a time, in a folder named after the choices that
reach that planner: ``runs/<experiment>/<planner>/<values>``. Two readings that agree on what
reaches a planner share its runs, so the sensitivity analysis, which changes one choice at a
time, reruns only the planners that choice reaches (:func:`reaches`). A choice that reaches
no planner of a team is stored with its ``sarlink-1`` value, on which it has no effect.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from dataclasses import dataclass, replace
from pathlib import Path
from typing import get_args

import pandas as pd

from sarlink.config import DEFAULT_READING, READINGS, Experiment, Reading, Readings, get_reading
from sarlink.execution import start_workers, sweep_all
from sarlink.paper.evidence import Outcome
from sarlink.paper.experiments import EXPERIMENTS, PaperExperiment
from sarlink.paper.findings import Finding, Settings, check_all
from sarlink.paper.report import Stage
from sarlink.planners import Planner, get_planner
from sarlink.storage import load

__all__ = ["FIG3_TDS", "Variant", "load_runs", "preset_findings", "reaches", "reading_tables",
           "sensitivity",
           "variants"]

FIG3_TDS = (1000.0, 2000.0, 4000.0)
"""The candidates for Fig. 3's unstated t_d, s: those the main table holds."""

_NEUTRAL = READINGS["sarlink-1"].choices
"""The values stored for choices that cannot reach a planner."""


def reaches(planner: Planner, experiment: Experiment) -> list[str]:
    """The choices of :class:`~sarlink.config.mission.Readings` that can change ``planner``'s
    runs in ``experiment``: its rule's, the errors of commanded turns (a planner with a rule),
    target reachability and parked drones (every planner's), the mTSP plan's (a planner that
    flies one), the prediction of the mTSP drones (a hybrid that flies one) and, where a point
    has shadowing, how the fades change and which range r_c is."""
    rule = planner.rule.readings if planner.rule is not None else ()
    mtsp = bool(getattr(planner, "mtsp", False))
    sigmas = [experiment.mission.channel.sigma, *experiment.grid.get("sigma", [])]
    wanted = {*rule, "reachability", "parked",
              *(["turns"] if planner.rule is not None else []),
              *(["mtsp_plan"] if mtsp else []),
              *(["mtsp_prediction"] if mtsp and planner.rule is not None else []),
              *(["shadowing", "shadow_calibration"] if any(float(v) > 0 for v in sigmas)
                else [])}
    return [c for c in _NEUTRAL if c in wanted]


def _planner_sweeps(exp: PaperExperiment, runs: int, choices: dict[str, str]
                    ) -> Iterator[tuple[Path, Experiment]]:
    """``exp`` split by planner, each with the choices that reach it: (folder, experiment)."""
    experiment = exp.build(runs)
    grid = {k: v for k, v in experiment.grid.items() if k != "planner"}
    for name in experiment.grid["planner"]:
        planner = get_planner(name)
        reach = reaches(planner, experiment)
        mission = experiment.mission.replace(
            planner=name, **{c: choices[c] if c in reach else _NEUTRAL[c] for c in _NEUTRAL})
        values = "-".join(choices[c] for c in reach) or "any"
        yield (Path(exp.name) / name / values,
               Experiment(name=f"{experiment.name}, {planner.label}", seed=experiment.seed,
                          runs=runs, mission=mission, grid=grid,
                          staircase=experiment.staircase))


def load_runs(out: str | Path, experiment: str, reading: str = DEFAULT_READING
              ) -> pd.DataFrame:
    """The stored runs of one experiment of a reproduction in ``out`` (``main``, ``miss``,
    ``shadowing``, ``report``) under ``reading``: one row per run, every planner."""
    choices = get_reading(reading).choices
    return pd.concat([load(Path(out) / "runs" / folder) for folder, _ in
                      _planner_sweeps(EXPERIMENTS[experiment], 1, choices)], ignore_index=True)


def _sweep(runs_folder: Path, readings: list[dict[str, str]], experiments: list[PaperExperiment],
           runs: int, *, workers: int | None, scheduler: str | None, progress: bool,
           quick: bool = False) -> tuple[list[dict[str, pd.DataFrame]], Stage]:
    """The summary tables of ``experiments`` under each set of choices in ``readings``, from
    the sweeps of every planner's runs they need (``runs`` per point, or an experiment's
    share of them when ``quick``: :meth:`PaperExperiment.runs`), and how long it took.

    The readings are swept one after the other on one set of workers, each holding only its
    own runs in memory (a folder shared by readings is run once and read again): all of a
    sensitivity analysis's runs at once, some 150 sweeps of up to 66,000 runs, outgrew a
    23 GB machine at 2000 runs per point.
    """
    t0 = time.perf_counter()
    jobs: dict[Path, Experiment] = {}
    wanted: list[dict[str, list[Path]]] = []
    for choices in readings:
        wanted.append({})
        for exp in experiments:
            sweeps = dict(_planner_sweeps(exp, exp.runs(runs, quick), choices))
            wanted[-1][exp.name] = list(sweeps)
            jobs.update(sweeps)
    resumed = sum((runs_folder / folder / "experiment.json").exists() for folder in jobs)
    tables = []
    with start_workers(workers, scheduler=scheduler) as pool:
        for folders in wanted:
            mine_jobs = [f for exp in experiments for f in folders[exp.name]]
            frames = dict(zip(mine_jobs, sweep_all([(jobs[f], runs_folder / f)
                                                    for f in mine_jobs],
                                                   progress=progress, pool=pool), strict=True))
            mine: dict[str, pd.DataFrame] = {}
            for exp in experiments:
                mine.update(exp.tables(pd.concat([frames[f] for f in folders[exp.name]],
                                                 ignore_index=True)))
            tables.append(mine)
            del frames  # before the next reading's runs are read
    points = sum(len(e.points()) for e in jobs.values())
    stage = Stage(f"sweep {', '.join(e.name for e in experiments)}",
                  f"{len(jobs)} sweeps (a planner under the choices that reach it), {points} "
                  f"grid points × {runs} runs"
                  + "".join(f" ({e.name}: {e.runs(runs, quick)})" for e in experiments
                            if e.runs(runs, quick) != runs)
                  + (f"; {resumed} found stored and resumed or reused" if resumed else ""),
                  time.perf_counter() - t0)
    return tables, stage


def reading_tables(runs_folder: Path, experiments: list[PaperExperiment], runs: int,
                   choices: dict[str, str], *, workers: int | None = None,
                   scheduler: str | None = None, progress: bool = True, quick: bool = False,
                   ) -> tuple[dict[str, pd.DataFrame], list[Stage]]:
    """The summary tables of ``experiments`` under ``choices``, from runs stored (or resumed)
    under ``runs_folder``, and how long the sweep took; ``quick``: each experiment flies its
    share of ``runs`` (:meth:`PaperExperiment.runs`)."""
    if not experiments:
        return {}, []
    (tables,), stage = _sweep(runs_folder, [choices], experiments, runs, workers=workers,
                              scheduler=scheduler, progress=progress, quick=quick)
    return tables, [stage]


def preset_findings(reading: Reading, base: dict[str, pd.DataFrame], runs_folder: Path,
            experiments: list[PaperExperiment], runs: int, *, workers: int | None = None,
            scheduler: str | None = None, progress: bool = True,
            ) -> tuple[dict[str, list[Finding]], list[Stage]]:
    """The claims under every preset of :data:`~sarlink.config.READINGS`, by name: under
    ``reading`` from ``base`` (its tables), under each other from ``experiments`` rerun with
    its choices (one sweep, sharing the runs of the planners they do not reach) and the
    tables of ``base`` no choice reaches (Fig. 1's plan times, say)."""
    others = [r for r in READINGS.values() if r.name != reading.name]
    stages: list[Stage] = []
    changed: list[dict[str, pd.DataFrame]] = [{} for _ in others]
    if others and experiments:
        changed, stage = _sweep(runs_folder, [r.choices for r in others], experiments, runs,
                                workers=workers, scheduler=scheduler, progress=progress)
        stages.append(replace(stage, name=f"{stage.name} (the other presets)"))
    tables = {r.name: {**base, **mine} for r, mine in zip(others, changed, strict=True)}
    return {r.name: check_all(tables.get(r.name, base), Settings(td_fig3=r.td_fig3, reading=r.name))
            for r in READINGS.values()}, stages


@dataclass(frozen=True)
class Variant:
    """The default reading with one choice changed, and the claims decided under it."""

    choice: str
    """A field of :class:`~sarlink.config.mission.Readings`, or ``td_fig3``."""
    value: str
    findings: tuple[Finding, ...] = ()

    @property
    def name(self) -> str:
        return f"{self.choice}={self.value}"


def variants(reading: Reading) -> list[Variant]:
    """Every single choice changed from ``reading``: each other value of each choice."""
    out = [Variant(c, v) for c, field in Readings.model_fields.items()
           for v in get_args(field.annotation) if v != reading.choices[c]]
    return out + [Variant("td_fig3", f"{td:g}") for td in FIG3_TDS if td != reading.td_fig3]


def sensitivity(reading: Reading, base: dict[str, pd.DataFrame], runs_folder: Path,
                experiments: list[PaperExperiment], runs: int, *, workers: int | None = None,
                scheduler: str | None = None, progress: bool = True,
                ) -> tuple[list[Variant], list[Stage]]:
    """The claims under every single change of ``reading``: each mission choice reruns
    ``experiments`` (sharing the runs of the planners it does not reach), all in one sweep;
    Fig. 3's t_d only rereads ``base``, the tables under ``reading``."""
    todo = variants(reading)
    changes = [v for v in todo if v.choice != "td_fig3"]
    stages: list[Stage] = []
    changed: list[dict[str, pd.DataFrame]] = []
    if changes and experiments:
        changed, stage = _sweep(runs_folder, [{**reading.choices, v.choice: v.value}
                                              for v in changes], experiments, runs,
                                workers=workers, scheduler=scheduler, progress=progress)
        stages.append(replace(stage, name=f"{stage.name} (sensitivity)"))
    tables = dict(zip((v.name for v in changes), changed, strict=False))
    done = []
    for v in todo:
        td = float(v.value) if v.choice == "td_fig3" else reading.td_fig3
        mine = {**base, **tables.get(v.name, {})}
        done.append(replace(v, findings=tuple(check_all(mine, Settings(td_fig3=td)))))
    return done, stages


SYMBOL = {Outcome.HOLDS: "holds", Outcome.CONTRADICTED: "contradicted",
          Outcome.UNDECIDED: "undecided", Outcome.NOT_TESTABLE: "not testable"}


def matrix(findings: list[Finding], done: list[Variant]) -> pd.DataFrame:
    """Claim × reading: the outcome under the default and under each single change."""
    rows = []
    for k, f in enumerate(findings):
        row = {"figure": f.figure, "claim": f.claim, "default": SYMBOL[f.outcome]}
        for v in done:
            row[v.name] = SYMBOL[v.findings[k].outcome]
        rows.append(row)
    return pd.DataFrame(rows)


def flips(findings: list[Finding], done: list[Variant]) -> list[str]:
    """Each claim whose outcome a single change flips, with the number that decides it."""
    out = []
    for v in done:
        for before, after in zip(findings, v.findings, strict=True):
            if after.outcome is not before.outcome:
                moved = [a for a, b in zip(after.parts, before.parts, strict=False)
                         if a.outcome is not b.outcome]  # the parts that changed, if aligned
                part = (moved or after.against or after.parts)[0]
                out.append(f"{v.name}: {after.figure} \"{after.claim}\" {before.outcome.value}"
                           f" → {after.outcome.value} ({part.text})")
    return out
