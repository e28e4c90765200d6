"""Reproduce the paper's evaluation: its experiments, figures, findings and a report.

``reproduce(out)`` reruns what Figs. 1–7 need, draws them, checks the paper's claims against
the results (:mod:`sarlink.paper.findings`) and writes ``out/report.md`` and
``out/report.html``; ``sarlink reproduce`` is its command. ``load_runs(out, "main")`` reads
an experiment's stored runs back as one table.
"""

from sarlink.paper.evidence import Outcome
from sarlink.paper.findings import CLAIMS, Finding, Settings, check_all, tally
from sarlink.paper.reproduce import ReproductionResult, reproduce
from sarlink.paper.variants import load_runs

__all__ = ["CLAIMS", "Finding", "Outcome", "ReproductionResult", "Settings", "check_all",
           "load_runs", "reproduce", "tally"]
