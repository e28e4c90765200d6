"""Why each contradicted claim is contradicted: the tally by cause.

A tally such as "30 hold, 23 contradicted" reads as "sarlink contradicts 40 % of the paper",
whatever made each contradiction. Each is put under the first of these that applies:

- it **hinges on one reading**: it holds under another preset reading, or under a single
  change of this one (the sensitivity analysis), named;
- it is **decided by a level the paper does not state**: at the most lenient value a reader
  could defend of each threshold its criterion had to choose (:class:`~sarlink.paper.evidence.
  Level`), no part of it is contradicted;
- it is a **model-level disagreement**: it holds under no reading decided and no defensible
  level removes it; the mechanism is one sentence written beside the claim
  (:attr:`~sarlink.paper.claim.Claim.mechanisms`).

The first two are computed from the runs (the claims decided under every preset and every
single change, and each part's outcome at the lenient levels); only the mechanism is written
by hand. Where no other reading was decided, a contradiction that no level decides is left
unclassified rather than called model-level.
"""

from __future__ import annotations

import enum
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from sarlink.paper.claim import Finding, tally
from sarlink.paper.evidence import Level, Outcome

__all__ = ["Cause", "Contradiction", "contradictions", "first_line"]


class Cause(enum.Enum):
    """Why a claim is contradicted."""

    READING = "hinges on one reading"
    LEVEL = "decided by a level the paper does not state"
    MODEL = "model-level disagreement"
    UNTRIED = "no other reading decided"


@dataclass(frozen=True)
class Contradiction:
    """A contradicted claim and its cause."""

    finding: Finding
    cause: Cause
    readings: tuple[str, ...] = ()
    """The readings under which the claim holds (:attr:`Cause.READING`)."""
    levels: tuple[Level, ...] = ()
    """The unstated levels that decide it (:attr:`Cause.LEVEL`)."""

    @property
    def why(self) -> str:
        """Which reading, which level, or the mechanism, in a few words."""
        match self.cause:
            case Cause.READING:
                return "holds under " + ", ".join(self.readings)
            case Cause.LEVEL:
                return ("not contradicted at the lenient value of: "
                        + "; ".join(str(level) for level in self.levels))
            case Cause.MODEL:
                return self.finding.mechanism or "mechanism not written yet"
        return "only this reading was decided (presets and --sensitivity decide the others)"


def _level_decided(f: Finding) -> tuple[Level, ...]:
    """The levels of the contradicted parts that no longer contradict at the lenient value,
    when the claim as a whole no longer does; otherwise none."""
    if f.lenient is Outcome.CONTRADICTED:
        return ()
    return tuple(dict.fromkeys(level for p in f.parts if p.outcome is Outcome.CONTRADICTED
                               for level in p.levels))


def contradictions(findings: Sequence[Finding],
                   readings: Mapping[str, Sequence[Finding]]) -> list[Contradiction]:
    """Every contradicted claim of ``findings`` with its cause, ``readings`` holding the same
    claims decided under each other reading (presets and single changes, by name)."""
    by_reading = {name: {f.name: f for f in found} for name, found in readings.items()}
    out = []
    for f in findings:
        if f.outcome is not Outcome.CONTRADICTED:
            continue
        holds = tuple(name for name, found in by_reading.items()
                      if f.name in found and found[f.name].outcome is Outcome.HOLDS)
        levels = _level_decided(f)
        if holds:
            out.append(Contradiction(f, Cause.READING, readings=holds))
        elif levels:
            out.append(Contradiction(f, Cause.LEVEL, levels=levels))
        else:
            out.append(Contradiction(f, Cause.MODEL if readings else Cause.UNTRIED))
    return out


def first_line(findings: Sequence[Finding], found: Sequence[Contradiction]) -> str:
    """The tally with the count of model-level disagreements beside it, and the other causes."""
    count = {c: sum(x.cause is c for x in found) for c in Cause}
    if count[Cause.UNTRIED]:
        causes = (f"no other reading was decided, so none of the {len(found)} contradictions "
                  f"is called model-level ({count[Cause.LEVEL]} decided by a level the paper "
                  "does not state)")
    else:
        causes = (f"{count[Cause.MODEL]} model-level disagreements (hold under no reading "
                  f"decided, and no defensible threshold removes them); of the other "
                  f"contradictions {count[Cause.READING]} hinge on one reading and "
                  f"{count[Cause.LEVEL]} on a level the paper does not state")
    return f"{len(findings)} of the paper's claims checked: {tally(findings)}; {causes}."
