"""Figure of a mission design: ``P_s`` against team size per planner, and the tuned settings."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from sarlink.design import CandidateEstimate, DesignAnswer


def _errorbar(ax: plt.Axes, x: Sequence[float], estimates: Sequence[CandidateEstimate],
              **style: Any) -> None:
    p = np.array([e.p for e in estimates])
    lo = np.array([e.lo for e in estimates])
    hi = np.array([e.hi for e in estimates])
    ax.errorbar(x, p, yerr=[p - lo, hi - p], capsize=3, marker="o", ms=4, **style)


def plot_design(answer: DesignAnswer) -> Figure:
    """One panel of ``P_s(t_d)`` against team size (each planner at its best setting per size,
    95 % Wilson intervals, the requirement as a line, the recommendation starred), and one
    panel per tuned planner: ``P_s`` against its setting at its smallest team."""
    tuned = [p for p in answer.planners if p.tuning is not None]
    fig, axes = plt.subplots(1, 1 + len(tuned), figsize=(7 + 4.5 * len(tuned), 5),
                             layout="constrained", squeeze=False)
    ax = axes[0, 0]
    request = answer.request
    for planner in answer.planners:
        sizes = planner.team_sizes
        if sizes:
            _errorbar(ax, [s.drones for s in sizes], [s.best for s in sizes],
                      label=planner.label, alpha=0.85)
    ax.axhline(request.ps, color="black", ls="--", lw=1, label=f"required P_s = {request.ps:g}")
    chosen = answer.recommendation
    if chosen is not None and chosen.chosen is not None:
        ax.plot(chosen.chosen.drones, chosen.chosen.p, marker="*", ms=18, color="gold",
                mec="black", ls="none", zorder=5,
                label=f"recommended: {chosen.label}, {chosen.chosen.drones} drones")
    ax.set(xlabel="team size N_m", ylabel=f"P_s(t_d = {request.td:g} s)", ylim=(-0.02, 1.02),
           title="smallest team meeting the requirement")
    ax.legend(fontsize=8, loc="lower right")
    for ax, planner in zip(axes[0, 1:], tuned, strict=True):
        tuning = planner.tuning
        assert tuning is not None and planner.smallest is not None
        _errorbar(ax, [float(e.value or 0) for e in tuning.curve], tuning.curve,
                  color="tab:gray", label="95 % Wilson interval")
        ax.plot(float(tuning.best.value or 0), tuning.best.p, marker="*", ms=16, color="gold",
                mec="black", ls="none", zorder=5, label=f"best {tuning.setting}")
        ax.axhline(request.ps, color="black", ls="--", lw=1)
        if not isinstance(tuning.best.value, float):
            ax.xaxis.set_major_locator(MaxNLocator(integer=True))
        ax.set(xlabel=tuning.setting, ylabel="P_s", ylim=(-0.02, 1.02),
               title=f"{planner.label}, {planner.smallest} drones")
        ax.legend(fontsize=8, loc="lower right")
    return fig
