"""The range as a design variable: the smallest communication range each team size needs.

``sarlink design`` without ``--rc`` asks, for each planner whose team flies the same at every
range (:attr:`sarlink.engine.run.Prepared.range_free`) and each team size: *which range
``r_c`` makes ``P_s(t_d) >= ps``?* One flight per run answers it at every range: a run's
notification staircase (:mod:`sarlink.engine.critical_ranges`) gives the smallest range at which its
BS is notified by ``t_d``, its *needed range* ``ρ_k`` (infinite if the target is not found by
then). A run notified at some range is notified at every larger one, so
``P_s(t_d, r_c) = Pr{ρ ≤ r_c}`` and the range asked for is the ``ps``-quantile of ``ρ``.

The guarantee is that of ``sarlink design`` with ``--rc`` at each team size (each misjudged
with probability at most the one-sided error ``δ``, 2.5 % at 95 %): the reported range is the
``s``-th smallest needed range, with ``s`` the fewest successes whose exact (Clopper–Pearson)
lower bound at ``δ`` reaches ``ps``. Then ``P_s(t_d, range) < ps`` happens with probability at
most ``δ``: it needs ``s`` of the ``n`` runs below the true quantile, where each falls with
probability below ``ps`` (the classical distribution-free bound on a quantile). Symmetrically
``below`` is the largest range shown to fail (upper bound below ``ps``). One look, a fixed
number of runs (``range_runs``): the bound is exact at any ``n``, and more runs only narrow
the gap between ``below`` and ``range``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from sarlink.at_range import needed_ranges
from sarlink.config import Experiment, Mission
from sarlink.design.request import DesignRequest
from sarlink.design.sequential import lower_bound, upper_bound
from sarlink.engine.radios import get_radio
from sarlink.execution import Workers, sweep_all
from sarlink.planners import get_planner
from sarlink.simulation import prepare

__all__ = ["PlannerRanges", "RangeNeed", "range_design", "smallest_range"]

TRACED_AT = 1000.0
"""The range the runs are traced at: any; their staircase gives every other range."""


@dataclass(frozen=True)
class RangeNeed:
    """The range one team size of one planner needs."""

    drones: int
    runs: int
    range: float | None
    """The smallest range shown to reach ``ps`` (m, rounded up to the metre); None if no
    range does (the target is not found by ``t_d`` often enough)."""
    estimate: float | None
    """The ``ps``-quantile of the needed ranges, m (None: beyond every range)."""
    below: float | None
    """Ranges below this one are shown to fail, m (None: none is, or no range reaches)."""
    found: float
    """The share of runs notified by ``t_d`` at some range: ``P_s`` at an unlimited range."""
    front: bool = False
    """On the planner's Pareto front of drones against range: no smaller team of it needs a
    range as small."""


@dataclass(frozen=True)
class PlannerRanges:
    """One planner's needs, team size by team size; ``reason`` if it cannot be asked."""

    planner: str
    label: str
    needs: tuple[RangeNeed, ...]
    reason: str | None = None


def _ceil_metre(key_root: float) -> float:
    """The range in whole metres at which a needed range ``key_root`` is surely reached (the
    engine tests ``key <= fl(r_c²)``; an integer's square is exact)."""
    return float(math.ceil(key_root))


def _first(n: int, holds: Callable[[int], bool]) -> int:
    """The smallest ``s`` in ``0 .. n`` with ``holds(s)`` (``n + 1`` if none), for ``holds``
    false then true as ``s`` grows: a bisection, since each bound costs a beta quantile."""
    lo, hi = 0, n + 1
    while lo < hi:
        mid = (lo + hi) // 2
        if holds(mid):
            hi = mid
        else:
            lo = mid + 1
    return lo


def smallest_range(needed: np.ndarray, ps: float, error: float) -> tuple[
        float | None, float | None, float | None]:
    """``(range, estimate, below)`` of :class:`RangeNeed` from the needed ranges of ``n``
    runs, judged at the one-sided ``error``."""
    n = len(needed)
    ordered = np.sort(needed)
    meets = max(1, _first(n, lambda s: lower_bound(s, n, error) >= ps))
    reached = None
    if meets <= n and math.isfinite(ordered[meets - 1]):
        reached = _ceil_metre(float(ordered[meets - 1]))
    at = max(1, math.ceil(ps * n))
    estimate = float(ordered[at - 1]) if math.isfinite(ordered[at - 1]) else None
    # ranges below the (f+1)-th needed range hold at most f successes, f the largest count
    # whose upper bound stays below ps
    f = _first(n, lambda s: upper_bound(s, n, error) >= ps) - 1
    below = None
    if 0 <= f < n and 0.0 < ordered[f] < math.inf:
        below = float(math.floor(np.nextafter(ordered[f], 0.0)))
    return reached, estimate, below


def _front(needs: list[RangeNeed]) -> tuple[RangeNeed, ...]:
    """Mark the sizes on the Pareto front: each needs less range than every smaller team."""
    out, best = [], math.inf
    for need in sorted(needs, key=lambda x: x.drones):
        on = need.range is not None and need.range < best
        if on:
            best = need.range  # type: ignore[assignment]
        out.append(RangeNeed(**{**asdict(need), "front": on}))
    return tuple(out)


def _mission(request: DesignRequest, planner: str, drones: int) -> Mission:
    """The traced mission of one team size: to ``t_d``, not stopped early (the staircase must
    reach every range), drones that do not report."""
    return request.mission.replace(planner=planner, drones=drones, horizon=request.td,
                                   stop="horizon", rc=TRACED_AT, on_detect="continue")


def _range_free(request: DesignRequest, planner: str, drones: int) -> bool:
    """Whether the team flies the same at every range; asked of the steering (an mTSP plan)
    only where the planner's kind leaves it open (a hybrid whose rule reads the links)."""
    mission = _mission(request, planner, drones)
    if mission.target.count > 1:  # several targets: flown at each range (Prepared.range_free)
        return False
    rule = get_planner(planner).rule
    if rule is None or rule.range_free:
        return bool(get_radio(mission.radio).range_free)
    return prepare(mission).range_free


def range_design(request: DesignRequest, out: str | Path, sizes: tuple[int, ...], runs: int,
                 *, pool: Workers | None = None) -> list[PlannerRanges]:
    """For each planner of ``request`` and each team size of ``sizes``, the smallest range
    reaching ``request.ps`` at ``request.td``, from ``runs`` runs per size kept under
    ``<out>/ranges-seed-<seed>/<planner>/`` (reused by a later design)."""
    answers = []
    for name in request.planners:
        planner = get_planner(name)
        eligible = [n for n in sizes if _range_free(request, name, n)]
        if not eligible:
            answers.append(PlannerRanges(name, planner.label, (), reason=(
                "its drones fly differently at each range: give --rc")))
            continue
        experiment = Experiment(
            name=f"design ranges {name}", seed=request.seed, runs=runs, staircase=True,
            mission=_mission(request, name, eligible[0]), grid={"drones": eligible})
        folder = Path(out) / f"ranges-seed-{request.seed}" / name
        (frame,) = sweep_all([(experiment, folder)], progress=False, pool=pool)
        needs = []
        for drones in eligible:
            needed = needed_ranges(frame[frame["drones"] == drones], request.td)
            reached, estimate, below = smallest_range(needed, request.ps, request.error)
            needs.append(RangeNeed(drones, len(needed), reached, estimate, below,
                                   float(np.isfinite(needed).mean())))
        skipped = [n for n in sizes if n not in eligible]
        answers.append(PlannerRanges(
            name, planner.label, _front(needs),
            reason=None if not skipped else
            f"sizes {', '.join(map(str, skipped))} fly differently at each range"))
    return answers


def to_json(answers: list[PlannerRanges]) -> list[dict[str, Any]]:
    """The answers as JSON-ready records."""
    return [asdict(a) for a in answers]
