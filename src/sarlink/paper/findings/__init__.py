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
difference is judged run by run. A level of one point keeps its Wilson interval. Conventions
where the paper is loose:

- A comparison the sentence states without a team size is decided on the average over the
  team sizes N_m = 2, ..., 22 (one paired statistic), and its part shows the per-team-size
  picture beside it: ``+`` holds, ``−`` contradicted, ``?`` undecided, ``=`` not testable
  (equal in every run). Statements about the level of every scheme ("all low") hold at every
  team size.
- mTSP-ConB flies exactly mTSP's mission up to N_r = 6 drones, so the two are compared only
  above N_r.
- "Near 1" is above :data:`~.helpers.NEAR_ONE`; "about x" is x ± :data:`~.helpers.ABOUT`,
  but never more than half of x (so "about 10 %" excludes 0); a "small" or "slight" change of
  a probability, and "no help", is less than :data:`~.helpers.SMALL`; "mostly" is more than
  half; "highly likely" above :data:`~.helpers.HIGHLY_LIKELY`.
- A trend ("as r_c becomes larger ... approaches 1") is tested as a change between settings,
  a limit ("for high r_c ... converges to 1") at the setting closest to it.
- "Somewhere" (an existence claim) is tested at every candidate point with Bonferroni's
  correction: 95% jointly.
- Fig. 3's t_d, which the paper does not state, is :attr:`Settings.td_fig3`; statements the
  paper ties to short target durations or to delayed notification are read at
  :data:`~sarlink.paper.experiments.TD_SHORT` (1000 s, the paper's own short t_d of Fig. 7a).
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
