"""What a claim of the paper is, and what deciding it gives (:mod:`sarlink.paper.findings`
holds the claims themselves).

A claim quotes one sentence of the paper (with its section), says in a few words what is
tested, names the summary tables its check reads, and has a check whose docstring is the exact
criterion (the report quotes it). The check tests one or more parts, each *holds*,
*contradicted*, *undecided at this sample size* or *not testable at this setting*
(:class:`~sarlink.paper.evidence.Outcome`); the claim's outcome is that of its parts together
(:func:`~sarlink.paper.evidence.worst`). A claim the runs contradict under every reading
carries the mechanism of the disagreement, written beside it (:attr:`Claim.mechanisms`); the
report shows it where :mod:`sarlink.paper.causes` finds the contradiction model-level.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import pandas as pd

from sarlink.config import DEFAULT_READING
from sarlink.paper.evidence import Outcome, Part, Verdict, worst
from sarlink.paper.experiments import TD_FIG3
from sarlink.paper.paired import PairedTables

__all__ = ["CLAIMS", "DEFAULT_SETTINGS", "Check", "Claim", "Finding", "Settings", "claim",
           "tally"]


@dataclass(frozen=True)
class Settings:
    """Choices the paper leaves open that the claims' checks depend on (a model reading can
    set them; the defaults are sarlink's)."""

    td_fig3: float = TD_FIG3
    """Fig. 3's target duration, s, at which the claims about Fig. 3's P_s against N_m are
    read: the paper does not state it (:data:`sarlink.paper.experiments.TD_FIG3`, 2000 s;
    1000 and 4000 s are the other candidates the runs hold)."""
    reading: str = DEFAULT_READING
    """The reading whose runs are decided: a claim's mechanism is written for the runs of
    one reading (:attr:`Claim.mechanisms`)."""


DEFAULT_SETTINGS = Settings()
"""sarlink's choices."""


@dataclass(frozen=True)
class Finding:
    """One of the paper's claims decided on sarlink's results."""

    figure: str
    """What the claim is about (``Abstract``, ``Fig. 1``, ``Figs. 2–3``, ..., ``Conclusions``)."""
    claim: str
    outcome: Outcome
    parts: tuple[Part, ...]
    """Every tested part: the numbers that decide it, with their 95% intervals."""
    notes: tuple[str, ...]
    """Numbers shown for context, which decide nothing."""
    criterion: str
    """The exact rule applied (the check's docstring)."""
    section: str = ""
    """Where the sentence is in the paper."""
    sentence: str = ""
    """The paper's words."""
    name: str = ""
    """The claim's check's name, the same under every reading."""
    mechanism: str = ""
    """Why the model disagrees, where no reading makes it hold (:attr:`Claim.mechanisms`)."""

    @property
    def lenient(self) -> Outcome:
        """The outcome with every threshold the paper does not state at the most lenient value
        a reader could defend (:class:`~sarlink.paper.evidence.Level`)."""
        return worst(p.outcome if p.lenient is None else p.lenient for p in self.parts)

    @property
    def holds(self) -> bool:
        """Whether the claim holds (none of its parts contradicted or undecided)."""
        return self.outcome is Outcome.HOLDS

    @property
    def against(self) -> tuple[Part, ...]:
        """The parts that do not hold, the contradicted ones first."""
        order = [Outcome.CONTRADICTED, Outcome.UNDECIDED, Outcome.NOT_TESTABLE]
        return tuple(sorted((p for p in self.parts if p.outcome is not Outcome.HOLDS),
                            key=lambda p: order.index(p.outcome)))


Check = Callable[[PairedTables, Settings], Verdict]


@dataclass(frozen=True)
class Claim:
    """A claim of the paper: the sentence, the summary tables its check reads, and the check."""

    figure: str
    section: str
    sentence: str
    text: str
    """What is tested, in a few words."""
    tables: tuple[str, ...]
    check: Check
    mechanisms: Mapping[str, str] = field(default_factory=dict)
    """By reading: one sentence, what in that reading's runs makes the claim fail under every
    reading (none where none is known to: a mechanism read off one reading's runs need not
    hold for another's)."""

    @property
    def name(self) -> str:
        return self.check.__name__

    @property
    def criterion(self) -> str:
        return " ".join((self.check.__doc__ or "").split())

    def checkable(self, tables: Mapping[str, pd.DataFrame]) -> bool:
        return all(t in tables for t in self.tables)

    def __call__(self, tables: Mapping[str, pd.DataFrame] | PairedTables,
                 settings: Settings = DEFAULT_SETTINGS) -> Finding:
        """Decide the claim on ``tables`` (wrapped once for many claims by ``check_all``)."""
        wrapped = tables if isinstance(tables, PairedTables) else PairedTables(tables)
        verdict = self.check(wrapped, settings)
        return Finding(self.figure, self.text, worst(p.outcome for p in verdict.parts),
                       tuple(verdict.parts), tuple(verdict.notes), self.criterion,
                       self.section, self.sentence, self.name,
                       self.mechanisms.get(settings.reading, ""))


CLAIMS: list[Claim] = []
"""Every claim, in the paper's order."""


def claim(figure: str, section: str, sentence: str, text: str,
          tables: tuple[str, ...] = ("main_runs",), mechanism: Mapping[str, str] | None = None
          ) -> Callable[[Check], Claim]:
    """Register the decorated check as a claim about ``figure``, quoting ``sentence``, with
    the ``mechanism`` of its disagreement, by reading, where the model contradicts it under
    every reading."""
    def register(check: Check) -> Claim:
        made = Claim(figure, section, sentence, text, tables, check, dict(mechanism or {}))
        CLAIMS.append(made)
        return made
    return register


def tally(findings: Sequence[Finding]) -> str:
    """``"N hold, M contradicted, K undecided, L not testable"``."""
    count = {o: sum(f.outcome is o for f in findings) for o in Outcome}
    return (f"{count[Outcome.HOLDS]} hold, {count[Outcome.CONTRADICTED]} contradicted, "
            f"{count[Outcome.UNDECIDED]} undecided, {count[Outcome.NOT_TESTABLE]} not testable")
