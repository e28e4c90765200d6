"""Shared by the claims' checks: the thresholds that give the paper's loose words a
meaning (the conventions of :mod:`sarlink.paper.findings`), and the statistics and
wording the checks have in common.

A threshold the paper states ("higher than 90%", "at least 50%", "around 0.2") is a number
here; one it does not state is a :class:`~sarlink.paper.evidence.Level` with the most lenient
value a reader could defend from the words alone, so that the report can tell a
contradiction the threshold decides from one no defensible threshold removes.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

from sarlink.config import Mission
from sarlink.metrics import MEASURES
from sarlink.paper.evidence import Estimate, Level, Outcome, Verdict, average, exists
from sarlink.paper.experiments import DRONES, RANGES
from sarlink.paper.paired import PairedTables, Stat, mean_of, on_common
from sarlink.planners import PAPER_PLANNERS, get_planner

NEAR_ONE = Level('"near 1", "converges to 1"', 0.9, 0.8, "a probability above {0}")
"""Where the paper states no number: 0.9, its own "higher than 90%" elsewhere; four in five
is the least a reader would still call near 1."""
ABOUT = Level('"about x", "around x"', 0.1, 0.15,
              "x ± {0}, at most ± x / 2 and at most half the gap to a value the sentence sets "
              "against x")
"""What "about x" admits for a probability or share. Never more than x / 2 (so "about 10 %"
excludes 0), nor half the distance to another value the same sentence contrasts with x
("30% compared to 45%": neither admits the other)."""
SMALL = Level('"small", "slight", "no help"', 0.1, 0.15, "a change of a probability under {0}")
"""Ten points of a probability; fifteen is the most a reader would still call slight."""
HIGHLY_LIKELY = Level('"highly likely"', 0.75, 0.6, "a probability above {0}")
"""Three times as likely as not; 0.6 is the least that is still more than "likely"."""
LOW = Level('"low" target reachability', 0.25, 0.35, "under {0} of t_d")
"""A quarter of t_d; a third (0.35 with rounding) is the most still read as low."""
FLAT = Level('"does not change significantly" (a plan time)', 2.0, 3.0,
             "a change by a factor within 1/{0} to {0} from 2 to 22 drones")
"""Fig. 1's log axis spans decades; an 11-fold team changing the time by less than 2 (3 at
most) leaves it flat on that axis."""
MUCH = Level('"much higher" (a plan time)', 2.0, 1.5, "more than {0} times")
"""Twice; one and a half times is the least a reader would call much higher."""
SMALL_MISS = Level('"not too high" (a miss probability)', 0.2, 0.1, "up to {0}")
"""The miss probabilities at which detection must barely change: up to 0.2, or only 0.1."""
VISIBLE = Level('a trend of a figure ("decreases monotonically", "decreases", "approaches")',
                0.02, 0.05, "broken only by a step against it of more than {0} of the axis "
                "(1 for a probability, t_d for a mission time)")
"""A trend read off a figure is broken by a step against it that the figure shows: a 4-pt
marker on a panel about 150 pt tall spans some 3 % of its axis, so a step under 2 % of the
axis (40 s of a 2000 s mission-time axis, 0.02 of a probability) is hidden by the marker; a
reader could argue for 5 %. Steps smaller than that are significant with 2000 paired runs but
invisible, and do not break "monotonically"."""
SMALL_TEAMS = (2, 4)
"""The "small N_m" / "lower number of drones": the two smallest teams."""
NR = Mission().team.nr
"""mTSP-ConB's mTSP drones: up to this team size it flies exactly the mTSP plan."""
V_M = Mission().team.speed
"""The drones' speed, m/s."""
HYBRID_SMALL_TEAMS = tuple(n for n in DRONES if n > NR)[:2]
"""mTSP-ConB's smallest teams that are not mTSP's."""
COVERAGE = ("mtsp", "covb")
"""The coverage-based schemes (Section 3.1)."""
CONNECTIVITY = ("conb", "concov")
"""The connectivity-aware distributed schemes."""
HYBRIDS = {"mtsp-conb": "mtsp", "concov": "covb"}
"""Each hybrid and its native coverage scheme (Section 3.3)."""

_MARK = {Outcome.HOLDS: "+", Outcome.CONTRADICTED: "−", Outcome.UNDECIDED: "?",
         Outcome.NOT_TESTABLE: "="}
_WHAT = {**{k: m.label for k, m in MEASURES.items()}, "detection_time": "mean detection time",
         "delay": "notification delay (t_notify − t_detect)"}


def _value(level: Level | float, lenient: bool) -> float:
    """A threshold's number: a stated one as it is, a level at sarlink's or its lenient value."""
    if isinstance(level, Level):
        return level.lenient if lenient else level.value
    return level


@dataclass(frozen=True)
class Decide:
    """How a part is decided from its estimate: ``rule(estimate, lenient)``, where ``lenient``
    puts each of ``levels`` (the unstated thresholds the rule uses) at its lenient value."""

    rule: Callable[[Estimate, bool], Outcome]
    levels: tuple[Level, ...] = ()

    def __call__(self, e: Estimate) -> Outcome:
        return self.rule(e, False)

    def lenient(self, e: Estimate) -> Outcome | None:
        return self.rule(e, True) if self.levels else None

    def test(self, v: Verdict, e: Estimate, text: str) -> None:
        """Record the part decided on ``e`` in ``v``."""
        v.test(self(e), text, self.levels, self.lenient(e))


def _levels(*xs: Level | float) -> tuple[Level, ...]:
    return tuple(x for x in xs if isinstance(x, Level))


def _label(planner: str) -> str:
    return get_planner(planner).label


def _rc(rc: float) -> str:
    return f"r_c = {rc:g} m"


def _others(planner: str) -> list[str]:
    return [p for p in PAPER_PLANNERS if p != planner]


def _above(x: Level | float = 0.0) -> Decide:
    return Decide(lambda e, lenient: e.above(_value(x, lenient)), _levels(x))


def _below(x: Level | float = 0.0) -> Decide:
    return Decide(lambda e, lenient: e.below(_value(x, lenient)), _levels(x))


def _within(lo: Level | float, hi: Level | float) -> Decide:
    return Decide(lambda e, lenient: e.within(_value(lo, lenient), _value(hi, lenient)),
                  _levels(lo, hi))


def _level(tests: int) -> float:
    """The confidence level of each of ``tests`` intervals that hold jointly at 95%."""
    return 1 - 0.05 / tests


def _own(planner: str) -> list[int]:
    """The team sizes at which ``planner`` is itself: mTSP-ConB only above N_r (up to N_r it
    flies exactly mTSP's mission, so there it is no hybrid)."""
    return [n for n in DRONES if planner != "mtsp-conb" or n > NR]


def _sizes(a: str, b: str) -> list[int]:
    """The team sizes at which ``a`` is compared with ``b``: where both are themselves."""
    return [n for n in _own(a) if n in _own(b)]


def _stat(t: PairedTables, measure: str, planner: str, drones: int, rc: float, td: float
          ) -> Stat:
    return t.runs.stat(measure, planner, drones, rc, td=td)


def _picture(per: Mapping[int, Estimate], decide: Decide) -> str:
    return "per N_m: " + " ".join(f"{n}{_MARK[decide(e)]}" for n, e in per.items())


def _grid_picture(per: Mapping[tuple[int, float], Stat], decide: Decide) -> str:
    """The picture of :func:`_picture` for statistics at grid points (N_m, r_c), by range."""
    ranges = dict.fromkeys(rc for _, rc in per)
    return "per N_m: " + "; ".join(
        f"{_rc(rc)}: " + " ".join(f"{n}{_MARK[decide(e.estimate())]}"
                                  for (n, r), e in per.items() if r == rc) for rc in ranges)


def _averaged(v: Verdict, per: Mapping[int, Stat], decide: Decide, what: str) -> Estimate:
    """Test ``decide`` on the average of ``per`` (a statistic per team size), showing each."""
    avg = mean_of(per.values()).estimate()
    decide.test(v, avg, f"{what}, averaged over N_m: {avg}; "
                        f"{_picture({n: s.estimate() for n, s in per.items()}, decide)}")
    return avg


def _gap(v: Verdict, t: PairedTables, measure: str, a: str, b: str, rc: float, td: float,
         decide: Decide) -> None:
    """Test ``decide`` on ``a − b`` in ``measure``, paired, averaged over team sizes."""
    per = {n: _stat(t, measure, a, n, rc, td) - _stat(t, measure, b, n, rc, td)
           for n in _sizes(a, b)}
    _averaged(v, per, decide, f"{_rc(rc)}, t_d = {td:g} s: {_label(a)} − {_label(b)} "
                              f"{_WHAT[measure]}")


def _gaps(v: Verdict, t: PairedTables, measure: str, firsts: Iterable[str],
          seconds: Iterable[str], ranges: Iterable[float], td: float, decide: Decide) -> None:
    seconds = list(seconds)
    for rc in ranges:
        for a in firsts:
            for b in seconds:
                if a != b:
                    _gap(v, t, measure, a, b, rc, td, decide)


def _change(t: PairedTables, measure: str, planner: str, start: tuple[int, float, float],
            end: tuple[int, float, float]) -> Stat:
    """``measure`` at ``end`` minus at ``start``, each (N_m, r_c, t_d), paired."""
    return _stat(t, measure, planner, *end) - _stat(t, measure, planner, *start)


def _spread(t: PairedTables, measure: str, drones: int, rc: float, td: float) -> Stat:
    """The largest minus the smallest planner's ``measure`` (the two picked by value; a
    measure over the runs notified over the runs every planner notifies)."""
    stats = on_common([_stat(t, measure, p, drones, rc, td) for p in PAPER_PLANNERS])
    if any(math.isnan(s.value) for s in stats):
        return Stat(math.nan, 0 * stats[0].influence, stats[0].digits, contrast=True)
    ordered = sorted(stats, key=lambda s: s.value)
    return ordered[-1] - ordered[0]


def _every_run(v: Verdict, t: PairedTables, event: str, planner: str, td: float) -> None:
    """Test that every run of ``planner`` at every point has ``event`` within ``td`` (one run
    without it contradicts at any sample size)."""
    for rc in RANGES:
        short = {n: _stat(t, event, planner, n, rc, td) for n in DRONES}
        missed = {n: s.counts[1] - s.counts[0] for n, s in short.items() if s.counts
                  and s.counts[0] < s.counts[1]}
        v.test(Outcome.CONTRADICTED if missed else Outcome.HOLDS,
               f"{_rc(rc)}, {_label(planner)}: {_WHAT[event]} within {td:g} s in every run "
               "at every N_m" if not missed else
               f"{_rc(rc)}, {_label(planner)}: runs without it: "
               + ", ".join(f"N_m = {n}: {k}" for n, k in missed.items()))


def _half(t: PairedTables, v: Verdict, fast: Sequence[str], slow: Sequence[str],
          rc: float, td: float, sizes: Mapping[str, Sequence[int]]) -> None:
    """Test at each team size of ``sizes[f]``: half of each ``slow`` planner's mission time
    minus ``f``'s, over the runs both notify, lies above 0 (mTSP-ConB only where it is
    itself)."""
    for f in fast:
        for n in sizes[f]:
            mine = _stat(t, "mission_time", f, n, rc, td)
            for p in slow:
                if n not in _sizes(f, p):
                    continue
                other, me = on_common([_stat(t, "mission_time", p, n, rc, td), mine])
                e = (other.scaled(0.5) - me).estimate()
                v.test(e.above(), f"{_rc(rc)}, N_m = {n}, t_d = {td:g} s, over the runs both "
                                  f"notify: half of {_label(p)}'s mission time "
                                  f"{other.estimate().scaled(0.5)} s minus {_label(f)}'s "
                                  f"{me.estimate()} s: {e} s")


def _plan_ratio(t: PairedTables, a: str, b: str) -> Estimate:
    """``a``'s plan time over ``b``'s, a geometric mean over the timed team sizes: per team
    size the difference of mean log times with Welch's interval, bounds averaged."""
    times = t.plan_times
    return average(times.log_ratio(a, b, n) for n in times.team_sizes()).mapped(math.exp, 2)


def _about_band(x: float, lenient: bool, versus: Iterable[float] = ()) -> tuple[float, float]:
    """What "about ``x``" admits (:data:`ABOUT`), apart from the values ``versus``."""
    half = min(_value(ABOUT, lenient), x / 2, *(abs(x - y) / 2 for y in versus))
    return x - half, x + half


def _about(x: float, versus: Iterable[float] = ()) -> Decide:
    """Is the estimate "about ``x``" (the sentence setting it against ``versus``)."""
    others = tuple(versus)
    return Decide(lambda e, lenient: e.within(*_about_band(x, lenient, others)), (ABOUT,))


def _against(points: Mapping[float, Stat], sign: int, scale: float, lenient: bool
             ) -> list[tuple[float, float]]:
    """The steps between neighbouring ``points`` (in order) that go against a trend of
    direction ``sign`` (+1 rising, −1 falling) by more than :data:`VISIBLE` × ``scale`` (the
    figure's axis): their interval lies beyond it."""
    tolerance = _value(VISIBLE, lenient) * scale
    steps = {(a, b): (points[b] - points[a]).estimate() for a, b in itertools.pairwise(points)}
    return [ab for ab, e in steps.items() if (e.lo if sign < 0 else -e.hi) > tolerance]


def _trend(v: Verdict, points: Mapping[float, Stat], sign: int, scale: float, text: str,
           axis: str, unit: str = "") -> None:
    """A trend of a figure's curve (``points`` in order along the axis ``axis``, a format for
    a key): contradicted if a step goes against it visibly (:func:`_against`); otherwise
    holds if the change from the first point to the last lies on the side of ``sign``,
    contradicted if on the other."""
    keys = list(points)
    first, last = on_common([points[keys[0]], points[keys[-1]]])
    overall = (last - first).estimate()
    decide = _above() if sign > 0 else _below()
    against = _against(points, sign, scale, lenient=False)
    lenient = (Outcome.CONTRADICTED if _against(points, sign, scale, lenient=True)
               else decide(overall))
    steps = ", ".join(f"{axis.format(a)} to {axis.format(b)}" for a, b in against)
    v.test(Outcome.CONTRADICTED if against else decide(overall),
           f"{text}: {first.estimate()}{unit} at {axis.format(keys[0])}, "
           f"{last.estimate()}{unit} at {axis.format(keys[-1])}"
           + (" (over the runs notified at both)" if first.over else "")
           + f", change {overall}{unit}"
           + (f"; {'rises' if sign < 0 else 'falls'} by more than {VISIBLE.value:g} of the "
              f"axis ({VISIBLE.value * scale:g}{unit}) from {steps}" if against else ""),
           (VISIBLE,), lenient)


def _exists_part(v: Verdict, outcomes: Mapping[str, Outcome], text: str) -> None:
    """An existence part ("at some ..."): :func:`~sarlink.paper.evidence.exists` over the
    candidates' ``outcomes`` (by name), with how many came out each way."""
    named = {o: [k for k, x in outcomes.items() if x is o] for o in Outcome}
    count = {o: len(k) for o, k in named.items()}
    v.test(exists(outcomes.values()),
           f"{text}: at {count[Outcome.HOLDS]} of {len(outcomes)}"
           + (f", e.g. {named[Outcome.HOLDS][0]}" if named[Outcome.HOLDS] else "")
           + f"; significantly not at {count[Outcome.CONTRADICTED]}, undecided at "
             f"{count[Outcome.UNDECIDED]}, equal in every run at {count[Outcome.NOT_TESTABLE]}")


def _jointly(outcomes: Iterable[Outcome]) -> Outcome:
    """One candidate of an existence claim that asks several comparisons at once ("above
    both"): contradicted if one is, not testable if one is equal in every run (it cannot show
    the candidate), holds if all hold, undecided otherwise."""
    found = set(outcomes)
    for o in (Outcome.CONTRADICTED, Outcome.NOT_TESTABLE, Outcome.UNDECIDED):
        if o in found:
            return o
    return Outcome.HOLDS
