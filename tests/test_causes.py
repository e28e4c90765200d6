"""The tally by cause: each contradicted claim hinges on one reading, is decided by a level
the paper does not state, or is a model-level disagreement; the report opens with it."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from sarlink.config import DEFAULT_READING
from sarlink.paper.causes import Cause, contradictions, first_line
from sarlink.paper.claim import Claim, Finding, Settings, tally
from sarlink.paper.evidence import Level, Outcome, Part, Verdict
from sarlink.paper.paired import PairedTables
from sarlink.paper.report import Sensitivity, write_report

HOLDS, CONTRADICTED, UNDECIDED, UNTESTABLE = (Outcome.HOLDS, Outcome.CONTRADICTED,
                                              Outcome.UNDECIDED, Outcome.NOT_TESTABLE)
LIKELY = Level('"highly likely"', 0.75, 0.6, "a probability above {0}")


def _found(name: str, outcome: Outcome, parts: tuple[Part, ...] = (),
           mechanism: str = "") -> Finding:
    return Finding("Fig. 5", f"claim {name}", outcome, parts or (Part(outcome, name),), (),
                   "a criterion", "4.2", "a sentence", name, mechanism)


def _levelled(*lenient: Outcome | None) -> tuple[Part, ...]:
    """Contradicted parts, each with ``LIKELY`` and this lenient outcome (None: no level)."""
    return tuple(Part(CONTRADICTED, f"part {k}", (LIKELY,) if o else (), o)
                 for k, o in enumerate(lenient))


DEFAULT = [
    _found("a", CONTRADICTED, _levelled(HOLDS)),  # holds under a reading: that comes first
    _found("b", CONTRADICTED, (*_levelled(HOLDS), Part(HOLDS, "b2"))),
    _found("c", CONTRADICTED, mechanism="ConB's drones never form a chain."),
    _found("d", CONTRADICTED, _levelled(HOLDS, None)),  # one part no level can remove
    _found("e", HOLDS),
    _found("f", CONTRADICTED),  # undecided elsewhere: it holds under no reading
    _found("g", CONTRADICTED, _levelled(UNDECIDED)),  # not contradicted at the lenient value
]
"""Claims under the default reading: a to g."""


def _under(outcomes: str) -> list[Finding]:
    """The same claims under another reading, one letter of ``outcomes`` each (h, c, u, n)."""
    code = {"h": HOLDS, "c": CONTRADICTED, "u": UNDECIDED, "n": UNTESTABLE}
    return [_found(f.name, code[x]) for f, x in zip(DEFAULT, outcomes, strict=True)]


READINGS = {"literal": _under("hccchuc"), "isolated=home": _under("hccchnc"),
            "takeoff=even": _under("ccccuuc")}


def test_each_contradiction_gets_the_first_cause_that_applies() -> None:
    found = {c.finding.name: c for c in contradictions(DEFAULT, READINGS)}
    assert list(found) == ["a", "b", "c", "d", "f", "g"]  # every contradicted claim, in order
    assert (found["a"].cause, found["a"].readings) == (Cause.READING,
                                                       ("literal", "isolated=home"))
    assert (found["b"].cause, found["b"].levels) == (Cause.LEVEL, (LIKELY,))
    assert (found["g"].cause, found["g"].levels) == (Cause.LEVEL, (LIKELY,))
    assert {n: found[n].cause for n in "cdf"} == dict.fromkeys("cdf", Cause.MODEL)
    assert found["c"].why == "ConB's drones never form a chain."
    assert found["f"].why == "mechanism not written yet"
    assert found["a"].why == "holds under literal, isolated=home"
    assert '"highly likely" taken as a probability above 0.75 (a reader could defend 0.6)' \
        in found["b"].why


def test_without_other_readings_no_contradiction_is_called_model_level() -> None:
    found = contradictions(DEFAULT, {})
    assert [c.cause for c in found] == [Cause.LEVEL, Cause.LEVEL, Cause.UNTRIED, Cause.UNTRIED,
                                        Cause.UNTRIED, Cause.LEVEL]
    line = first_line(DEFAULT, found)
    assert line.startswith(f"7 of the paper's claims checked: {tally(DEFAULT)}; ")
    assert "none of the 6 contradictions is called model-level" in line


def test_the_first_line_gives_the_model_level_count_beside_the_tally() -> None:
    line = first_line(DEFAULT, contradictions(DEFAULT, READINGS))
    assert line == ("7 of the paper's claims checked: 1 hold, 6 contradicted, 0 undecided, "
                    "0 not testable; 3 model-level disagreements (hold under no reading "
                    "decided, and no defensible threshold removes them); of the other "
                    "contradictions 1 hinge on one reading and 2 on a level the paper does "
                    "not state.")


def test_the_report_opens_with_the_tally_by_cause(tmp_path: Path) -> None:
    """The first line after the title is the tally with the model-level count; the first table
    lists each contradicted claim with its cause, from the presets and the single changes."""
    presets = {DEFAULT_READING: DEFAULT, "literal": READINGS["literal"]}
    study = Sensitivity(pd.DataFrame(), [], {k: v for k, v in READINGS.items()
                                             if k != "literal"})
    md, _ = write_report(tmp_path, runs=10, quick=True, figures={}, tables={},
                         findings=DEFAULT, stages=[], seconds=1.0, workers="none",
                         presets=presets, sensitivity=study)
    lines = md.read_text().splitlines()
    assert lines[0].startswith("# ") and lines[1] == ""
    assert lines[2] == first_line(DEFAULT, contradictions(DEFAULT, READINGS))
    table = lines[next(k for k, line in enumerate(lines) if line.startswith("|")):]
    assert table[0] == "| about | claim | cause | which reading, which level, or the mechanism |"
    rows = [r.split(" | ") for r in table[2:8]]
    assert [(r[1], r[2]) for r in rows] == [
        ("claim a", "hinges on one reading"),
        ("claim b", "decided by a level the paper does not state"),
        ("claim c", "model-level disagreement"), ("claim d", "model-level disagreement"),
        ("claim f", "model-level disagreement"),
        ("claim g", "decided by a level the paper does not state")]
    assert rows[0][3] == "holds under literal, isolated=home |"
    assert rows[2][3] == "ConB's drones never form a chain. |"


def test_a_mechanism_is_given_only_for_the_runs_of_the_reading_it_was_read_off() -> None:
    """A mechanism describes one reading's runs: decided under another reading, the claim
    carries none (the report then says it is not written yet)."""
    def check(tables: PairedTables, settings: Settings) -> Verdict:
        verdict = Verdict()
        verdict.test(CONTRADICTED, "a part")
        return verdict

    made = Claim("Fig. 5", "4.2", "a sentence", "a claim", (), check,
                 {"sarlink-3": "ConB's drones fly diameters through the BS."})
    found = {r: made({}, Settings(reading=r)).mechanism for r in ("sarlink-3", "sarlink-4")}
    assert found == {"sarlink-3": "ConB's drones fly diameters through the BS.", "sarlink-4": ""}
