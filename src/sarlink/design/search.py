"""The adaptive search: which candidates get runs, and when the answer is known.

Two phases, both spending runs in rounds (one pool of workers per round; every candidate of a
round grows to its next look of the :class:`~sarlink.design.sequential.Schedule`).

1. **Smallest team.** For each planner variant, team sizes are probed on a doubling ladder
   from the smallest considered (1, 2, 4, ..., the largest; a variant with ``k`` fixed relays
   starts at ``k + 1``, one searcher beside them), climbed one rung at a time: a probe gets
   runs once every smaller probe is decided (for the recommendation alone, every smaller
   probe of every variant). Once a size meets the requirement, or the ladder is decided,
   every smaller size is opened. A size meets when one of its settings does; it fails when
   all do. Sizes above the smallest that meets are never run again. The ladder only orders
   the work: the answer does not assume that ``P_s`` grows with the team. For the
   recommendation alone, an open candidate at the smallest team that meets for any variant
   gets no more runs once its exact upper bound on ``P_s`` (at ``δ/K`` per look) is below
   the estimate of the best candidate that meets there: it is *outranked*, since only the
   most successful of that size can be recommended.
   For the recommendation alone (``every_planner`` off), sizes above the smallest that meets
   for *any* variant are never run again either: the recommendation is the smallest team
   overall, so no larger one can be it (that size itself stays open to every variant, whose
   ``P_s`` there breaks ties).
2. **Best setting.** At the smallest team of a tunable variant (for the recommendation alone:
   only at the smallest team overall), its settings race: all grow
   together, a setting shown worse than the current best (exact McNemar test on the common
   runs) drops out, and the race ends when one is left or the rest are shown within ``margin``
   of the best. A continuous setting is then refined: the two midpoints beside the best join
   the race, halving the spacing down to ``alpha_tol``.

Error control (Bonferroni, each a union bound): with ``K`` looks and ``G`` settings that can
ever be tried at a team size (ConCov's alpha grid and its refinements; ``N_r`` values for
mTSP-ConB, one per searcher; ``N`` relay counts 0..N-1 for a team of ``N`` whose split is
tuned), "meets" is judged at error ``δ/(K·G)`` per setting and look,
"fails" at ``δ/K``, and eliminations at ``δ/(K·(G−1))``, where ``δ`` is the one-sided error of
the requested confidence (0.025 at 95 %). So each team size of each planner is misjudged with
probability at most ``δ``, and at the tuned size the best setting is dropped with probability
at most ``δ``. Leaving sizes unrun makes no decision that is made less sure.

A time budget (``max_seconds``) is looked at only between rounds: it decides after which
round the search stops, never which runs a round flies, so the answer after a given round is
the same on any machine and with any number of workers.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from sarlink.config import Mission
from sarlink.design.answer import CandidateEstimate, DesignAnswer, PlannerAnswer, TeamSize, Tuning
from sarlink.design.candidates import Candidate, PlannerVariant, refinements
from sarlink.design.request import DesignRequest
from sarlink.design.runs import Runs, Tally
from sarlink.design.sequential import (
    Decision,
    Schedule,
    decide,
    not_worse_by,
    upper_bound,
    worse,
)

__all__ = ["Errors", "Snapshot", "errors", "search"]


@dataclass(frozen=True)
class Snapshot:
    """Where a search stands after a round: what a live view shows."""

    decided: int
    """Candidates decided (meets, fails or borderline)."""
    opened: int
    """Candidates opened so far."""
    used: int
    """Runs the decisions rest on."""
    label: str | None
    """The planner variant of the best candidate so far, or None before any run."""
    best: CandidateEstimate | None
    """The best candidate so far: the smallest team that meets (the highest ``P_s`` among
    them), or while none does, the candidate with the highest lower bound."""


Progress = Callable[[Snapshot], None]
"""Called after each round with where the search stands."""


@dataclass
class _Arm:
    """One candidate in the search: its mission and what its runs say so far."""

    candidate: Candidate
    mission: Mission
    verdict: Decision = Decision.OPEN


@dataclass(frozen=True)
class Errors:
    """The errors the decisions at one team size of one variant are judged at, per look."""

    settings: int
    """``G``: the settings that can ever be tried at this size."""
    meets: float
    """``δ/(K·G)``: a setting judged to meet the requirement."""
    fails: float
    """``δ/K``: a setting judged to fail it."""
    drops: float
    """``δ/(K·(G−1))``: a setting dropped from the race as worse than the best."""


def errors(request: DesignRequest, variant: PlannerVariant, drones: int) -> Errors:
    """The Bonferroni shares of the module docstring at team size ``drones``: ``G`` is 1
    without a setting, ConCov's alpha grid with its refinements, mTSP-ConB's ``N_r`` values
    (one per searcher), or the team's ``N`` relay counts when the split is tuned."""
    setting = variant.setting
    count = 1 if setting is None else setting.size(
        variant.span(drones, request.mission), request.alpha_step, request.alpha_tol)
    per_look = request.error / len(request.schedule().looks)
    return Errors(count, per_look / count, per_look, per_look / max(count - 1, 1))


@dataclass
class _Cell:
    """One team size of one variant: its settings' arms and the errors they are judged at."""

    drones: int
    arms: list[_Arm]
    errors: Errors

    @property
    def verdict(self) -> Decision:
        verdicts = {arm.verdict for arm in self.arms}
        if Decision.MEETS in verdicts:
            return Decision.MEETS
        if verdicts == {Decision.FAILS}:
            return Decision.FAILS
        for verdict in (Decision.OPEN, Decision.BORDERLINE):
            if verdict in verdicts:
                return verdict
        return Decision.OUTRANKED  # outranked, or failed


def _value(arm: _Arm) -> float | int:
    """The setting value of an arm of a tunable variant."""
    value = arm.candidate.value
    assert value is not None
    return value


def _ladder(sizes: range) -> list[int]:
    """The probes of ``sizes``: its first, doubling, and its last."""
    probes = [sizes[0]]
    while probes[-1] * 2 < sizes[-1]:
        probes.append(probes[-1] * 2)
    return sorted({*probes, sizes[-1]})


@dataclass
class _Search:
    request: DesignRequest
    runs: Runs
    progress: Progress | None
    schedule: Schedule = field(init=False)
    base: Mission = field(init=False)
    max_seconds: float | None = None
    cells: dict[PlannerVariant, dict[int, _Cell]] = field(default_factory=dict)
    budget_hit: bool = False
    out_of_time: bool = False
    started: float = field(default_factory=time.monotonic)

    def __post_init__(self) -> None:
        self.schedule = self.request.schedule()
        self.base = self.request.base()
        self.cells = {variant: {} for variant in self.request.variants()}

    # -- bookkeeping --------------------------------------------------------------------------

    def tally(self, arm: _Arm) -> Tally:
        return self.runs.tally(arm.mission)

    def arms(self) -> list[_Arm]:
        return [arm for cells in self.cells.values() for cell in cells.values()
                for arm in cell.arms]

    def used(self) -> int:
        return sum(self.tally(arm).runs for arm in self.arms())

    def cell(self, variant: PlannerVariant, drones: int) -> _Cell:
        cells = self.cells[variant]
        if drones not in cells:
            setting = variant.setting
            span = variant.span(drones, self.base)
            values: Sequence[float | int | None] = (
                [None] if setting is None else setting.grid(span, self.request.alpha_step))
            arms = [self.arm(Candidate(variant, drones, v)) for v in values]
            cells[drones] = _Cell(drones, arms, errors(self.request, variant, drones))
        return cells[drones]

    def arm(self, candidate: Candidate) -> _Arm:
        return _Arm(candidate, candidate.mission(self.base))

    def spend(self, wanted: Sequence[tuple[_Arm, int]]) -> bool:
        """Grow arms to the run counts wanted, in order, while the budget lasts; False when
        the budget stopped any (then nothing after it in the order runs either), or when the
        time is up after this round (then no later round runs)."""
        if self.out_of_time:
            return False
        left = self.request.max_runs - self.used()
        allowed = []
        for arm, runs in wanted:
            extra = runs - self.tally(arm).runs
            if extra > left:
                self.budget_hit = True
                break
            allowed.append((arm.mission, runs))
            left -= extra
        self.runs.grow(allowed)
        if self.max_seconds is not None and \
                time.monotonic() - self.started >= self.max_seconds:
            self.out_of_time = True
        return len(allowed) == len(wanted) and not self.out_of_time

    @property
    def ended_by(self) -> str:
        """What stopped the search early (``time``, ``budget``), else ``statistics``."""
        return "time" if self.out_of_time else "budget" if self.budget_hit else "statistics"

    def report(self) -> None:
        """Tell ``progress`` where the search stands."""
        if self.progress is None:
            return
        arms = self.arms()
        ran = [a for a in arms if self.tally(a).runs]
        best = None
        if ran:
            meets = [a for a in ran if a.verdict is Decision.MEETS]
            best = (min(meets, key=lambda a: (a.candidate.drones, -self.tally(a).p)) if meets
                    else max(ran, key=lambda a: self.tally(a).interval()[0]))
        self.progress(Snapshot(sum(a.verdict is not Decision.OPEN for a in arms), len(arms),
                               self.used(), None if best is None else best.candidate.variant.label,
                               None if best is None else self.estimate(best)))

    def judge(self, arm: _Arm, cell: _Cell) -> None:
        tally = self.tally(arm)
        arm.verdict = decide(tally.successes, tally.runs, self.request.ps,
                              meets_error=cell.errors.meets, fails_error=cell.errors.fails,
                              final=self.schedule.after(tally.runs) is None)

    # -- phase 1: the smallest team -----------------------------------------------------------

    def smallest(self, variant: PlannerVariant) -> int | None:
        meets = [n for n, c in self.cells[variant].items() if c.verdict is Decision.MEETS]
        return min(meets, default=None)

    def ceiling(self) -> int | None:
        """For the recommendation alone, the largest team worth runs: the smallest that meets
        for any variant (None: every size, or no size meets yet)."""
        if self.request.every_planner:
            return None
        return min(filter(None, map(self.smallest, self.cells)), default=None)

    def below(self, variant: PlannerVariant) -> range:
        """The sizes of ``variant`` that can still be the answer: below its smallest that
        meets, and for the recommendation alone up to the smallest that meets for any."""
        team = self.request.sizes(variant)
        smallest = self.smallest(variant)
        below = team if smallest is None else range(team.start, smallest)
        ceiling = self.ceiling()
        return below if ceiling is None else range(below.start, min(below.stop, ceiling + 1))

    def open_probes(self, variant: PlannerVariant) -> list[int]:
        """The ladder's probes of ``variant`` that can still be the answer and are open."""
        return [n for n in _ladder(self.request.sizes(variant)) if n in self.below(variant)
                and self.cell(variant, n).verdict is Decision.OPEN]

    def rung(self, variant: PlannerVariant) -> int | None:
        """The ladder's rung worth runs now: the smallest open probe (for the recommendation
        alone, of any variant; else of ``variant``), so that the ladder is climbed one rung
        at a time and no size above the first that meets is run (None: no probe open)."""
        scope = [variant] if self.request.every_planner else list(self.cells)
        return min((n for v in scope for n in self.open_probes(v)), default=None)

    def active(self, variant: PlannerVariant) -> list[_Cell]:
        """The open cells of ``variant`` worth runs now (see the module docstring)."""
        probes = self.open_probes(variant)
        if self.smallest(variant) is not None or not probes:  # fill in below
            sizes: Sequence[int] = self.below(variant)
        else:
            rung = self.rung(variant)
            sizes = [n for n in probes if rung is not None and n <= rung]
        return [c for n in sizes if (c := self.cell(variant, n)).verdict is Decision.OPEN]

    def find_smallest(self) -> None:
        order = {variant: i for i, variant in enumerate(self.cells)}
        while True:
            wanted = []
            for variant in self.cells:
                for cell in self.active(variant):
                    for arm in cell.arms:
                        nxt = self.schedule.after(self.tally(arm).runs)
                        if arm.verdict is Decision.OPEN and nxt is not None:
                            wanted.append((cell, arm, nxt))
            if not wanted:
                return
            wanted.sort(key=lambda w: (w[0].drones, order[w[1].candidate.variant]))
            complete = self.spend([(arm, n) for _, arm, n in wanted])
            for cell, arm, _ in wanted:
                self.judge(arm, cell)
            self.outrank()
            self.report()
            if not complete:
                return

    def outrank(self) -> None:
        """For the recommendation alone, set aside each open candidate at the smallest team
        that meets whose exact upper bound on ``P_s`` (at ``δ/K`` per look) is below the
        estimate of the best candidate that meets there: the recommendation is the most
        successful of that size, so it cannot be."""
        ceiling = self.ceiling()
        if ceiling is None:
            return
        cells = [cells[ceiling] for cells in self.cells.values() if ceiling in cells]
        best = max(self.tally(a).p for c in cells for a in c.arms
                   if a.verdict is Decision.MEETS)
        for cell in cells:
            if cell.verdict is not Decision.OPEN:  # a size that meets races its own settings
                continue
            for arm in cell.arms:
                tally = self.tally(arm)
                if arm.verdict is Decision.OPEN and tally.runs and upper_bound(
                        tally.successes, tally.runs, cell.errors.fails) < best:
                    arm.verdict = Decision.OUTRANKED

    # -- phase 2: the best setting ------------------------------------------------------------

    def tune(self, variant: PlannerVariant, cell: _Cell) -> Tuning:
        setting = variant.setting
        assert setting is not None
        error = cell.errors.drops
        step = self.request.alpha_step
        halvings = refinements(step, self.request.alpha_tol) if setting.continuous else 0
        # a setting judged to fail cannot be the best of a size that meets
        survivors = [a for a in cell.arms if a.verdict is not Decision.FAILS]
        while True:
            runs = max(self.tally(a).runs for a in survivors)
            lagging = [(a, runs) for a in survivors if self.tally(a).runs < runs]
            if lagging:
                if not self.spend(lagging):
                    ended_by = self.ended_by
                    break
                self.report()
                continue
            best = self.best(survivors)
            won = self.tally(best).success
            survivors = [a for a in survivors
                         if a is best or not worse(self.tally(a).success, won, error)]
            settled = all(a is best or not_worse_by(self.tally(a).success, won,
                                                    self.request.margin, error)
                          for a in survivors)
            if settled and halvings:
                halvings -= 1
                step /= 2
                survivors += self.refine(cell, best, step)
                continue
            if settled:
                ended_by = "statistics"
                break
            nxt = self.schedule.after(runs)
            if nxt is None:
                ended_by = "cap"
                break
            if not self.spend([(a, nxt) for a in survivors]):
                ended_by = self.ended_by
                break
            self.report()
        for arm in cell.arms:
            self.judge(arm, cell)
        best = self.best(survivors)
        return Tuning(setting.name, self.estimate(best),
                      tuple(sorted(map(_value, survivors))),
                      tuple(self.estimate(a) for a in sorted(cell.arms, key=_value)), ended_by)

    def best(self, arms: Sequence[_Arm]) -> _Arm:
        """The most successful arm on the runs all of them have (ties: shorter mission)."""
        common = min(self.tally(a).runs for a in arms)

        def key(arm: _Arm) -> tuple[float, float]:
            tally = self.tally(arm).first(common)
            return (tally.p, -tally.mission_time if tally.successes else float("-inf"))

        return max(arms, key=key)

    def refine(self, cell: _Cell, best: _Arm, step: float) -> list[_Arm]:
        """New arms halfway between the best value and its neighbours, within [0, 1]."""
        centre = _value(best)
        known = {_value(a) for a in cell.arms}
        new = [self.arm(Candidate(best.candidate.variant, cell.drones, round(v, 12)))
               for v in (centre - step, centre + step)
               if 0 <= v <= 1 and all(abs(v - k) > 1e-9 for k in known)]
        cell.arms += new
        return new

    # -- the answer ---------------------------------------------------------------------------

    def estimate(self, arm: _Arm) -> CandidateEstimate:
        return CandidateEstimate.of(arm.mission, arm.candidate.value, self.tally(arm),
                                    arm.verdict)

    def answer(self, variant: PlannerVariant, tuning: Tuning | None) -> PlannerAnswer:
        cells = self.cells[variant]
        smallest = self.smallest(variant)
        team_sizes = tuple(TeamSize(n, c.verdict, self.estimate(self.most_successful(c)),
                                    len(c.arms))
                           for n, c in sorted(cells.items())
                           if any(self.tally(a).runs for a in c.arms))
        sizes = self.request.sizes(variant)
        ceiling = self.ceiling()
        tried = sizes.stop if ceiling is None else min(sizes.stop, ceiling + 1)
        limit = tried if smallest is None else smallest
        # an outranked size cannot be the recommendation, but it may still be this planner's
        # smallest when a larger size of it meets
        settled = (Decision.FAILS,) if smallest is not None else (Decision.FAILS,
                                                                   Decision.OUTRANKED)
        undecided = tuple(n for n in range(sizes.start, limit)
                          if n not in cells or cells[n].verdict not in settled)
        chosen = None
        if smallest is not None:
            meets = [a for a in cells[smallest].arms if a.verdict is Decision.MEETS]
            chosen = (self.estimate(max(meets, key=lambda a: self.tally(a).p))
                      if tuning is None else tuning.best)
            status = "reached"
        else:
            outranked = ceiling in cells and cells[ceiling].verdict is Decision.OUTRANKED
            status = ("undecided" if undecided else "outranked" if outranked
                      else "not reachable" if tried == sizes.stop else "larger")
        held = variant.own if variant.split else None
        return PlannerAnswer(variant.planner, variant.label, dict(variant.fixed), status,
                             smallest, chosen, undecided, team_sizes, tuning,
                             {} if held is None else {held.name: self.base.params()[held.name]})

    def most_successful(self, cell: _Cell) -> _Arm:
        """The arm of ``cell`` with the highest ``P_s`` estimate, each on all its own runs."""
        return max((a for a in cell.arms if self.tally(a).runs),
                   key=lambda a: self.tally(a).p)


def _grid_points(request: DesignRequest) -> int:
    """Candidates of a full grid at the finest setting spacing the design can reach."""
    finest = request.alpha_step / 2 ** refinements(request.alpha_step, request.alpha_tol)
    total = 0
    for variant in request.variants():
        for drones in request.sizes(variant):
            setting = variant.setting
            span = variant.span(drones, request.mission)
            total += 1 if setting is None else len(setting.grid(span, finest))
    return total


def search(request: DesignRequest, runs: Runs, progress: Progress | None = None, *,
           max_seconds: float | None = None) -> DesignAnswer:
    """Answer ``request``, running what it needs through ``runs``; with ``max_seconds``, no
    round starts after that many seconds (the answer then says ``ended_by = "time"``)."""
    state = _Search(request, runs, progress, max_seconds=max_seconds)
    state.find_smallest()
    ceiling = state.ceiling()
    tunings = {v: state.tune(v, state.cells[v][n]) for v in state.cells
               if v.setting is not None and (n := state.smallest(v)) is not None
               and (ceiling is None or n == ceiling)}
    planners = tuple(state.answer(v, tunings.get(v)) for v in state.cells)
    reached = [i for i, p in enumerate(planners) if p.chosen is not None]

    def rank(i: int) -> tuple[int, float, float]:
        chosen = planners[i].chosen
        assert chosen is not None
        return (chosen.drones, -chosen.p, chosen.mission_time)

    return DesignAnswer(
        request, planners, min(reached, key=rank, default=None), state.used(),
        runs.simulated, _grid_points(request), state.ended_by)
