"""The text beyond the paper: gains from reporting, and who beats the paper everywhere."""

from __future__ import annotations

import itertools

import pandas as pd

from sarlink.metrics import wilson
from sarlink.paper.beyond import TDS, beyond_text, gains
from sarlink.paper.experiments import DRONES, RANGES

RUNS = 2000


def _table(p_s: dict[str, float]) -> pd.DataFrame:
    """A made-up summary table: each planner's P_s at every grid point, with Wilson bounds."""
    rows = []
    for (planner, value), n, rc, td in itertools.product(p_s.items(), DRONES, RANGES, TDS):
        lo, hi = wilson(round(value * RUNS), RUNS)
        rows.append({"planner": planner, "drones": n, "rc": rc, "td": td, "runs": RUNS,
                     "P_s": value, "P_s_lo": float(lo), "P_s_hi": float(hi)})
    return pd.DataFrame(rows)


def test_a_planner_whose_reporting_beats_the_paper_everywhere_is_named() -> None:
    paper = _table({"covb": 0.6, "conb": 0.5})
    report = _table({"covb": 0.8, "conb": 0.55})
    text = " ".join(beyond_text(paper, report))
    points = len(DRONES) * len(RANGES) * len(TDS)
    assert f"CovB with reporting beats every planner of the paper at {points} of {points}" in text
    assert text.endswith("So CovB with reporting beats every planner of the paper at every "
                         "grid point.")
    assert "Reporting helps most CovB: 0.200" in text
    # ConB with reporting (0.55) is beaten by CovB without (0.6) everywhere
    assert (f"ConB with reporting beats every planner of the paper at 0 of {points} grid points "
            f"and is beaten by one at {points}") in text


def test_no_planner_beats_the_paper_where_all_are_equal() -> None:
    paper = _table({"covb": 0.9, "mtsp": 0.9})
    report = _table({"covb": 0.9, "mtsp": 0.9})
    lines = beyond_text(paper, report)
    assert lines[-1].startswith("So no planner with reporting beats every planner")
    assert all(abs(g.gain.value) < 1e-12 and g.gain.lo < 0 < g.gain.hi
               for g in gains(paper, report))
