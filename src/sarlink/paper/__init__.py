"""Reproduce the paper's evaluation: its experiments, figures, findings and a report.

``reproduce(out)`` reruns what Figs. 1–7 need, draws them, checks the paper's findings against
the results and writes ``out/report.md`` and ``out/report.html``; ``sarlink reproduce`` is its
command.
"""

from sarlink.paper.findings import Finding, check_all
from sarlink.paper.reproduce import ReproductionResult, reproduce

__all__ = ["Finding", "ReproductionResult", "check_all", "reproduce"]
