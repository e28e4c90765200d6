"""The paper's checkable statements, each decided from the reproduction's tables.

Every sentence of the abstract, the introduction's summary of results, Sections 3–4 and the
conclusions that a number can decide is a claim here, quoted with its section
(:mod:`sarlink.paper.claim`), in the paper's order: one module per part of the paper
(:mod:`.introduction`, :mod:`.section3`, :mod:`.fig1` with Section 4.1, :mod:`.figs2_3`,
:mod:`.fig4` to :mod:`.fig7`, :mod:`.conclusions`), imported here in that order, and the
thresholds and statistics they share in :mod:`.helpers`. Each check's docstring is its exact
criterion; the criteria were written from the paper's words, not from the results.

Statistics: comparisons of planners, team sizes, ranges or target durations are *paired*
(:mod:`sarlink.paper.paired`): run ``k`` of every point searches for the same target, so a
difference is judged run by run; a measure over the runs notified (mission time, its phases,
the delay) is compared over the runs both points notify, the same targets. A level of one
point keeps its Wilson interval. Conventions where the paper is loose:

- A comparison the sentence states without a team size is decided on the average over the
  team sizes N_m = 2, ..., 22 (one paired statistic), and its part shows the per-team-size
  picture beside it: ``+`` holds, ``−`` contradicted, ``?`` undecided, ``=`` not testable
  (equal in every run). Statements about the level of every scheme ("all low") hold at every
  team size.
- mTSP-ConB flies exactly mTSP's mission up to N_r = 6 drones, so wherever it is compared
  it is compared above N_r only, where it is a hybrid.
- A threshold the paper does not state is a :class:`~sarlink.paper.evidence.Level` with the
  most lenient value a reader could defend, at which each part is decided again (the tally by
  cause, :mod:`sarlink.paper.causes`): "near 1" is above :data:`~.helpers.NEAR_ONE`;
  "about x" is x ± :data:`~.helpers.ABOUT`, but never more than half of x (so "about 10 %"
  excludes 0) nor half the gap to a value the sentence sets against x; a "small" or "slight"
  change of a probability, and "no help", is less than :data:`~.helpers.SMALL`; "highly
  likely" is above :data:`~.helpers.HIGHLY_LIKELY`. Words that fix their own number do not
  need one: "mostly" and "dominates" are more than half.
- A trend read off a figure ("decreases monotonically", "approaches 1") is broken only by a
  step against it that the figure would show, larger than :data:`~.helpers.VISIBLE` of the
  axis; an order a figure shows is one larger than that. A trend is tested as a change
  between settings, a limit ("for high r_c ... converges to 1") at the setting closest to it.
- "Somewhere" (an existence claim) is tested at every candidate point with Bonferroni's
  correction: 95% jointly; a candidate equal in every run to what it is compared with can
  show nothing and is dropped (:func:`~sarlink.paper.evidence.exists`).
- Fig. 3's t_d, which the paper does not state, is :attr:`Settings.td_fig3`, also for what
  the paper observes on Fig. 3 ("as N_m is increased ConCov significantly outperforms
  mTSP-Con"). "Short target durations" for P_s are
  :data:`~sarlink.paper.experiments.TD_SHORT` (1000 s, the paper's own short t_d of Fig. 7a);
  where the paper's reason for a short t_d is that a target "is detected only if it is closer
  to the BS", short is r_c / V_m, the time a drone takes to fly one communication range.
"""

from __future__ import annotations

from collections.abc import Mapping

import pandas as pd

from sarlink.paper.claim import CLAIMS, DEFAULT_SETTINGS, Claim, Finding, Settings, tally
from sarlink.paper.paired import PairedTables

# isort: off
# each part registers its claims as it is imported: in the paper's order
from sarlink.paper.findings import introduction
from sarlink.paper.findings import section3
from sarlink.paper.findings import fig1
from sarlink.paper.findings import figs2_3
from sarlink.paper.findings import fig4
from sarlink.paper.findings import fig5
from sarlink.paper.findings import fig6
from sarlink.paper.findings import fig7
from sarlink.paper.findings import conclusions
# isort: on

__all__ = [
    "CLAIMS",
    "DEFAULT_SETTINGS",
    "Claim",
    "Finding",
    "Settings",
    "check_all",
    "conclusions",
    "fig1",
    "fig4",
    "fig5",
    "fig6",
    "fig7",
    "figs2_3",
    "introduction",
    "section3",
    "tally",
]


def check_all(tables: Mapping[str, pd.DataFrame],
              settings: Settings = DEFAULT_SETTINGS) -> list[Finding]:
    """Every claim whose tables are in ``tables``, decided on them."""
    wrapped = PairedTables(tables)
    return [c(wrapped, settings) for c in CLAIMS if c.checkable(tables)]
