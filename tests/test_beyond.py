"""The text beyond the paper: gains from reporting, and who beats the paper everywhere."""

from __future__ import annotations

import itertools

import pandas as pd

from sarlink.metrics import wilson
from sarlink.paper.beyond import TDS, beyond_text, gains, others_text
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


def _others(p_s: dict[tuple[str, str], float]) -> pd.DataFrame:
    """A made-up ``others`` table: P_s by (planner, on_detect) at every grid point."""
    return pd.concat([_table({planner: value}).assign(on_detect=mode)
                      for (planner, mode), value in p_s.items()], ignore_index=True)


def test_a_pattern_is_compared_with_the_paper_flown_the_same_way() -> None:
    paper = _table({"covb": 0.6, "conb": 0.5})
    report = _table({"covb": 0.8, "conb": 0.55})
    # parallel track beats the paper's 0.6 as in the paper, but not the paper's 0.8 reporting
    others = _others({("parallel", "continue"): 0.7, ("parallel", "report"): 0.75})
    lines = others_text(paper, report, others)
    points = len(DRONES) * len(RANGES) * len(TDS)
    assert lines[0].startswith(f"Parallel track as in the paper: beats every planner of the "
                               f"paper flown the same way at {points} of {points} grid points "
                               "and is beaten by one at 0; its lowest P_s is 0.700")
    assert lines[1].startswith(f"Parallel track with reporting: beats every planner of the "
                               f"paper flown the same way at 0 of {points} grid points and is "
                               f"beaten by one at {points}")
    assert lines[2] == (f"Parallel track: reporting raises P_s significantly at {points} of "
                        f"{points} grid points and lowers it at 0.")
    assert lines[-1] == ("So Parallel track as in the paper beats every planner of the paper "
                         "flown the same way at every grid point.")


def test_no_pattern_beats_the_paper_where_all_are_equal() -> None:
    paper = _table({"covb": 0.9})
    others = _others({("sector", "continue"): 0.9, ("sector", "report"): 0.9})
    lines = others_text(paper, paper, others)
    assert "at 0 of" in lines[0] and lines[0].endswith(
        "is beaten by one at 0; its lowest P_s is 0.900 [0.886, 0.912] at N_m = 2, "
        "r_c = 500 m, t_d = 1000 s.")
    assert lines[-1].startswith("So no planner beyond the paper's beats every planner")
    assert others_text(paper, paper, others.iloc[:0]) == []
