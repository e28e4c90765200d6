"""The experiments behind the paper's figures (the paper's Table 3; docs/reproduce.md).

Figures 2–6 read one main sweep (planner × team size × communication range, simulated to
``t_d = 4000 s``): every ``t_d`` they show comes from the same runs' event times, so one sweep
serves them all and their numbers agree with each other. Its rows carry the notification
staircase of the teams that fly the same at every range (mTSP, CovB, mTSP-ConB up to N_r),
whose flights it shares between its three ranges anyway: Fig. :data:`RANGE_FIG` reads P_s at
every range from 100 m to 3000 m from them. Fig. 7a (imperfect sensing) and Fig. 7b
(shadowing) change the mission itself and need sweeps of their own; they plot only detection
(7a) or notification (7b), so their runs stop at that event, which makes them several times
faster. So do the sweeps beyond the paper (Figs. :data:`BEYOND`, :data:`OTHERS`,
:data:`RELAY_FIG` and :data:`MOVING_FIG`: drones that report, the other planners, searchers
and relays, targets that move), which show
P_s, mission time and search share, all settled at notification: their runs stop there, and
their tables have no reachability or connected fraction past a run's stop (NaN). Fig. 1
times the planners rather than simulating missions. Every experiment uses the one seed
:data:`SEED`. The paper's figures fly the paper's five planners (:data:`PAPER_PLANNERS`);
every other registered planner (:func:`sarlink.planner_names`: the IAMSAR search patterns,
and any planner registered since) is flown over the main grid, with and without drones that
report, by the ``beyond`` experiment, read when it is built, so that a newly registered
planner is compared with the paper's without edits here; Fig. :data:`RELAY_FIG` flies CovB
searchers with relays (:data:`RELAY_PLANNER`, :data:`RELAY_COUNTS`); Fig. :data:`MOVING_FIG`
flies the paper's planners and the others against a still, a walking and a drifting target
(:data:`MOTIONS`) at one team size and range (:data:`MOVING_DRONES`, :data:`MOVING_RC`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from sarlink.at_range import range_curve
from sarlink.config import Experiment, Mission
from sarlink.engine.streams import plan_seed
from sarlink.metrics import run_values, success_curve, summarize
from sarlink.mtsp import plan_for
from sarlink.planners import PAPER_PLANNERS, get_planner, planner_names

__all__ = [
    "BEYOND",
    "CURVE_TDS",
    "DRONES",
    "EXPERIMENTS",
    "FIG2_DRONES",
    "FIG5_RANGES",
    "MOTIONS",
    "MOVING_CURRENT",
    "MOVING_DELAYS",
    "MOVING_DRONES",
    "MOVING_FIG",
    "MOVING_RC",
    "MOVING_TDS",
    "MOVING_WIND",
    "OTHERS",
    "PAPER_PLANNERS",
    "PLAN_TIME_PLANNERS",
    "P_MISS",
    "QUICK_RUNS",
    "RANGES",
    "RANGE_CURVE",
    "RANGE_DRONES",
    "RANGE_FIG",
    "RANGE_TDS",
    "RELAY_COUNTS",
    "RELAY_DRONES",
    "RELAY_FIG",
    "RELAY_PLANNER",
    "RELAY_TDS",
    "RUNS",
    "SEED",
    "SIGMA",
    "TD_FIG3",
    "TD_LONG",
    "TD_SHORT",
    "PaperExperiment",
    "moving_planners",
    "mtsp_plans",
    "other_planners",
    "plan_time_missions",
    "relay_label",
]

SEED = 2024
"""The one seed of every run of every experiment."""
RUNS = 2000
"""Monte Carlo runs per grid point, as in the paper."""
QUICK_RUNS = 100
"""Runs per grid point of ``--quick``: the trends, with intervals about 4.5 times wider."""

DRONES = tuple(range(2, 23, 2))
"""Team sizes N_m."""
RANGES = (500.0, 1000.0, 2000.0)
"""Communication ranges r_c, m."""
FIG2_DRONES = (10, 22)
"""The team sizes of Fig. 2's rows."""
FIG5_RANGES = (500.0, 1000.0)
"""The ranges of Fig. 5's panels: the paper leaves out 2000 m, where every planner is near 1."""

TD_SHORT = 1000.0
"""A short target duration, s: where the paper says a large r_c still gives P_s near 1."""
TD_FIG3 = 2000.0
"""The fixed t_d of Fig. 3, s. The paper does not state it (4000 s, the t_d of Figs. 4-6, is
the other candidate); the figure and, by default, the claims of Figs. 2-3 use this one."""
TD_LONG = 4000.0
"""t_d of Figs. 4–6 and 7b, s: the flight budget, which gives the drones a chance to spread."""
CURVE_TDS = np.arange(100.0, TD_LONG + 1, 100.0)
"""The t_d at which Fig. 2 reads P_s from the empirical CDF of notification times, s."""

RANGE_CURVE = np.arange(100.0, 3000.0 + 1, 25.0)
"""The continuous communication ranges of Fig. :data:`RANGE_FIG`, m."""
RANGE_DRONES = (4, 10, 22)
"""Its team sizes."""
RANGE_TDS = (TD_SHORT, TD_FIG3)
"""Its target durations, s."""

P_MISS = tuple(round(0.1 * k, 1) for k in range(10))
"""Miss probabilities of Fig. 7a."""
SIGMA = 3.0
"""Shadowing standard deviation of Fig. 7b, dB (the paper's, after Yang et al.)."""
"""The paper's planners, in the order of its legends: the planners of its figures and claims."""
PLAN_TIME_PLANNERS = ("mtsp", "covb", "conb", "mtsp-conb", "concov")
"""The planners whose plan computation time Fig. 1 shows: the paper's natives, and the hybrids,
whose times Section 4.2 predicts without showing them."""

_BY = ["planner", "drones", "rc"]


@dataclass(frozen=True)
class PaperExperiment:
    """A sweep behind some figures, and how its runs become the figures' summary tables."""

    name: str
    """Folder name under ``out/runs/``."""
    figures: tuple[int, ...]
    build: Callable[[int], Experiment]
    """The experiment with the given runs per grid point."""
    tables: Callable[[pd.DataFrame], dict[str, pd.DataFrame]]
    """Summary tables, by name, from the experiment's runs."""
    quick_share: float = 1.0
    """The share of the reproduction's runs per grid point it flies under ``--quick``: below 1
    for a sweep whose runs cost many times the others', so that the quick reproduction stays
    quick; every full reproduction flies them all."""

    def runs(self, runs: int, quick: bool) -> int:
        """Its runs per grid point in a reproduction of ``runs`` per point: runs ``0 ..
        n-1``, the first of every other sweep's (the same targets), at least one."""
        return max(1, math.ceil(runs * self.quick_share)) if quick else runs


def _main(runs: int) -> Experiment:
    return Experiment(
        name="Figs. 2-6", seed=SEED, runs=runs,
        mission=Mission.build(horizon=TD_LONG),
        grid={"planner": list(PAPER_PLANNERS), "drones": list(DRONES), "rc": list(RANGES)},
        staircase=True,
    )


def _range_table(runs: pd.DataFrame) -> pd.DataFrame:
    """P_s against the range at :data:`RANGE_TDS` for :data:`RANGE_DRONES`, from the
    staircases of the runs flown once for every range (one range's rows: each has them)."""
    rows = runs[(runs["rc"] == RANGES[0]) & runs["drones"].isin(RANGE_DRONES)]
    return pd.concat([range_curve(rows, RANGE_CURVE, td, ["planner", "drones"])
                      for td in RANGE_TDS], ignore_index=True)


def _main_tables(runs: pd.DataFrame) -> dict[str, pd.DataFrame]:
    return {"main": summarize(runs, td=[TD_SHORT, TD_FIG3, TD_LONG], by=_BY),
            "curve": success_curve(runs, CURVE_TDS, by=_BY),
            "range_curve": _range_table(runs),
            "main_runs": run_values(runs, [TD_SHORT, TD_FIG3, TD_LONG], _BY),
            "mtsp_plans": mtsp_plans(runs)}


PLAN_SAMPLE = 100
"""Under per-run plans, the runs whose plans :func:`mtsp_plans` describes: the first ones,
which every sweep has (their plans are in the cache; elsewhere they are solved again)."""


def mtsp_plans(runs: pd.DataFrame) -> pd.DataFrame:
    """The mTSP plans the main sweep's mTSP runs fly at each team size (cached): the cells that
    every one of them visits, and the flight time of their longest tour beside the flight
    budget (Section 4.1's claims).

    With one plan per team size (``mtsp_plan = shared``) that plan; with a plan per run, those
    of the first :data:`PLAN_SAMPLE` runs: the longest tour's mean, least and largest."""
    rows = []
    mtsp = runs[runs["planner"] == "mtsp"]
    for n in DRONES:
        mission = Mission.build(planner="mtsp", drones=n, horizon=TD_LONG)
        mine = mtsp[mtsp["drones"] == n]
        if not mine.empty and mine["mtsp_plan"].iloc[0] == "per-run":
            seed = int(mine["seed"].iloc[0])
            plans = [plan_for(mission.replace(mtsp_plan="per-run",
                                              plan_seed=plan_seed(seed, int(run))),
                              n, compact=True)
                     for run in sorted(set(mine["run"]))[:PLAN_SAMPLE]]
        else:
            plans = [plan_for(mission.replace(mtsp_plan="shared"), n)]
        longest = np.array([plan.longest for plan in plans]) / mission.team.speed
        rows.append({"drones": n, "plans": len(plans),
                     "cells": min(len({c for tour in plan.tours for c in tour})
                                  for plan in plans),
                     "longest_s": longest.mean(), "longest_min_s": longest.min(),
                     "longest_max_s": longest.max(), "flight_time": mission.team.flight_time})
    return pd.DataFrame(rows)


def _miss(runs: int) -> Experiment:
    return Experiment(
        name="Fig. 7a", seed=SEED, runs=runs,
        mission=Mission.build(drones=10, rc=500.0, horizon=TD_SHORT, stop="detected"),
        grid={"planner": list(PAPER_PLANNERS), "p_miss": list(P_MISS)},
    )


def _miss_tables(runs: pd.DataFrame) -> dict[str, pd.DataFrame]:
    return {"miss": summarize(runs, td=TD_SHORT, by=["planner", "drones", "rc", "p_miss"]),
            "miss_runs": run_values(runs, [TD_SHORT], ["planner", "p_miss"])}


def _shadowing(runs: int) -> Experiment:
    return Experiment(
        name="Fig. 7b", seed=SEED, runs=runs,
        mission=Mission.build(rc=1000.0, sigma=SIGMA, horizon=TD_LONG, stop="notified"),
        grid={"planner": list(PAPER_PLANNERS), "drones": list(DRONES)},
    )


def _shadowing_tables(runs: pd.DataFrame) -> dict[str, pd.DataFrame]:
    return {"shadowing": summarize(runs, td=TD_LONG, by=[*_BY, "sigma"]),
            "shadowing_runs": run_values(runs, [TD_LONG], _BY)}


def _report(runs: int) -> Experiment:
    """Beyond the paper: the main grid with drones that fly to tell the BS (``on_detect``)."""
    return Experiment(
        name="Beyond: on_detect = report", seed=SEED, runs=runs,
        mission=Mission.build(horizon=TD_LONG, on_detect="report", stop="notified"),
        grid={"planner": list(PAPER_PLANNERS), "drones": list(DRONES), "rc": list(RANGES)},
    )


def _report_tables(runs: pd.DataFrame) -> dict[str, pd.DataFrame]:
    return {"report": summarize(runs, td=[TD_SHORT, TD_FIG3, TD_LONG], by=_BY),
            "report_curve": success_curve(runs, CURVE_TDS, by=_BY)}


def other_planners() -> list[str]:
    """Every registered planner that is not the paper's, in registration order."""
    return [p for p in planner_names() if p not in PAPER_PLANNERS]


def _others(runs: int) -> Experiment:
    """Beyond the paper: every other planner over the main grid, with and without drones
    that report, beside the paper's planners (the main and report sweeps)."""
    return Experiment(
        name="Beyond: other planners", seed=SEED, runs=runs,
        mission=Mission.build(horizon=TD_LONG, stop="notified"),
        grid={"planner": other_planners(), "drones": list(DRONES), "rc": list(RANGES),
              "on_detect": ["continue", "report"]},
    )


def _others_tables(runs: pd.DataFrame) -> dict[str, pd.DataFrame]:
    return {"others": summarize(runs, td=[TD_SHORT, TD_FIG3, TD_LONG], by=[*_BY, "on_detect"])}


RELAY_PLANNER = "covb"
"""The searchers' planner of Fig. :data:`RELAY_FIG`: CovB, the paper's coverage planner. It
searches nearly as well as mTSP, plans nothing ahead (mTSP would need a GA plan for every
searcher count), and its drones make no effort to stay linked, so what the relays add is not
mixed with a planner's own effort for the link."""
RELAY_COUNTS = (1, 2, 3)
"""The relay counts of Fig. :data:`RELAY_FIG`, each a sweep of its own."""
RELAY_DRONES = tuple(n for n in DRONES if n > max(RELAY_COUNTS))
"""Its team sizes: the paper's that leave a searcher beside every relay count."""
RELAY_TDS = (TD_SHORT, TD_FIG3)
"""Its target durations, s: those of Figs. 8 and 9, where success is not yet certain."""


def relay_label(relays: int) -> str:
    """A team of searchers and relays as figures and the report name it: "CovB + 2 relays"."""
    return f"{get_planner(RELAY_PLANNER).label} + {relays} relay{'' if relays == 1 else 's'}"


def _relays(runs: int) -> Experiment:
    """Beyond the paper: searchers and relays, the same team sizes and ranges as the paper's
    planners fly in ``main``. Their runs stop at notification or at the last t_d read: a
    relay run re-plans the relays every t_s and costs many plain runs."""
    return Experiment(
        name="Beyond: searchers and relays", seed=SEED, runs=runs,
        mission=Mission.build(horizon=max(RELAY_TDS), stop="notified"),
        grid={"planner": [RELAY_PLANNER], "drones": list(RELAY_DRONES), "rc": list(RANGES),
              "relays": list(RELAY_COUNTS)},
    )


def _relays_tables(runs: pd.DataFrame) -> dict[str, pd.DataFrame]:
    by = [*_BY, "relays"]
    return {"relays": summarize(runs, td=list(RELAY_TDS), by=by),
            "relays_runs": run_values(runs, list(RELAY_TDS), by)}


MOVING_DRONES = 10
"""The team size of Fig. :data:`MOVING_FIG`: that of the first row of Fig. 2 and of Figs. 7a
and 8a, the paper's middle team, which neither finds every target at once nor misses most."""
MOVING_RC = 500.0
"""Its communication range, m: the paper's shortest, that of Fig. 7a, where P_s is far from
1 at the t_d read, so a target's motion can show in it (at 2000 m nearly every planner
notifies nearly every run by 2000 s)."""
MOTIONS = ("still", "walk", "drift")
"""The target motions of Fig. :data:`MOVING_FIG` (docs/model.md, Target motion), each with
its defaults: a walker at 0.5 m/s who stops after a log-normal time of median 4 h; a person
in the water (PIW-1) under :data:`MOVING_WIND` and :data:`MOVING_CURRENT`."""
MOVING_WIND = (5.0, 0.0)
"""The drifting target's 10 m wind, m/s (east, north): a gentle breeze (Beaufort 3) towards
the east, constant. PIW-1's leeway is some 1 % of it downwind, 5 cm/s."""
MOVING_CURRENT = (0.0, 0.2)
"""Its surface current, m/s (east, north): 0.2 m/s (0.4 kn) towards the north, constant, a
moderate coastal current; with the leeway the target moves some 0.21 m/s, 740 m an hour,
and may leave the square (then no drone inside it can find it: docs/model.md, drift)."""
MOVING_DELAYS = (0.0, 1800.0)
"""The times from the last sighting to take-off, s: none, the paper's case, and half an hour,
during which a walker or a drifter moves before the drones fly (a still target ignores it)."""
MOVING_TDS = (TD_SHORT, TD_FIG3, TD_LONG)
"""The target durations its tables and sentences read, s; the figure draws P_s against t_d
up to :data:`TD_LONG`."""


def moving_planners() -> list[str]:
    """The planners of Fig. :data:`MOVING_FIG`: the paper's five, then every other registered
    one (the IAMSAR search patterns), as the ``others`` sweep reads them."""
    return [*PAPER_PLANNERS, *other_planners()]


def _moving(runs: int) -> Experiment:
    """Beyond the paper: every planner against a still, a walking and a drifting target, at
    N_m = 10 and r_c = 500 m, with and without a delay before take-off. Their runs stop at
    notification: the figure and the tables read P_s alone."""
    return Experiment(
        name="Beyond: targets that move", seed=SEED, runs=runs,
        mission=Mission.build(drones=MOVING_DRONES, rc=MOVING_RC, horizon=TD_LONG,
                              stop="notified", drift_wind=[MOVING_WIND],
                              drift_current=[MOVING_CURRENT]),
        grid={"planner": moving_planners(), "motion": list(MOTIONS),
              "delay": list(MOVING_DELAYS)},
    )


_MOVING_BY = ["planner", "drones", "rc", "motion", "delay"]


def _moving_tables(runs: pd.DataFrame) -> dict[str, pd.DataFrame]:
    return {"moving": summarize(runs, td=list(MOVING_TDS), by=_MOVING_BY),
            "moving_curve": success_curve(runs, CURVE_TDS, by=_MOVING_BY),
            "moving_runs": run_values(runs, list(MOVING_TDS), _MOVING_BY)}


BEYOND = 8
"""The number of the figure beyond the paper's seven: its planners with drones that report."""
OTHERS = 9
"""The number of the figure of the other planners (the search patterns) beside the paper's."""
RANGE_FIG = 10
"""The number of the figure of P_s against a continuous communication range."""
RELAY_FIG = 11
"""The number of the figure of searchers and relays against the paper's planners."""
MOVING_FIG = 12
"""The number of the figure of the planners against a walking and a drifting target."""

EXPERIMENTS = {e.name: e for e in (
    PaperExperiment("main", (2, 3, 4, 5, 6, BEYOND, OTHERS, RANGE_FIG, RELAY_FIG), _main,
                    _main_tables),
    PaperExperiment("miss", (7,), _miss, _miss_tables),
    PaperExperiment("shadowing", (7,), _shadowing, _shadowing_tables),
    PaperExperiment("report", (BEYOND, OTHERS), _report, _report_tables),
    PaperExperiment("others", (OTHERS,), _others, _others_tables),
    PaperExperiment("relays", (RELAY_FIG,), _relays, _relays_tables, quick_share=0.25),
    PaperExperiment("moving", (MOVING_FIG,), _moving, _moving_tables, quick_share=0.25),
)}
"""The sweeps, by folder name; ``main`` gives the tables ``main`` (``summarize`` at
:data:`TD_SHORT`, :data:`TD_FIG3` and :data:`TD_LONG`), ``curve`` (``success_curve`` at
:data:`CURVE_TDS`), ``range_curve`` (:func:`sarlink.at_range.range_curve`) and ``main_runs``
(every run's values, ``run_values``, for the paired statistics of the claims; ``miss`` and
``shadowing`` give theirs too); ``others`` the table ``others``, by ``on_detect`` too;
``relays`` the tables ``relays`` (by the relay count too) and ``relays_runs``, paired with
``main_runs`` run by run; under ``--quick`` it flies a quarter of the runs (25 of 100), since
a relay run costs some ten plain ones at r_c = 500 m; ``moving`` the tables ``moving``
(``summarize`` at :data:`MOVING_TDS` by target motion and delay too), ``moving_curve``
(``success_curve`` at :data:`CURVE_TDS`) and ``moving_runs``, paired run by run between the
motions; under ``--quick`` it too flies a quarter of the runs, so that its 48 points add
little to the quick reproduction."""


def plan_time_missions(iterations: int | None = None) -> list[Mission]:
    """The missions whose plans Fig. 1 times: the native planners at r_c = 500 m, every N_m.

    ``iterations`` overrides the GA's (the paper's 5000) for quick tests only.
    """
    extra: dict[str, Any] = {} if iterations is None else {"iterations": iterations}
    return [Mission.build(planner=p, drones=n, rc=500.0, **extra)
            for p in PLAN_TIME_PLANNERS for n in DRONES]
