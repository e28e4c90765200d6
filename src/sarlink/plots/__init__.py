"""Figures. Functions take ``ax: plt.Axes | None`` and return the axes they drew on."""

from sarlink.plots.plan import plot_plan
from sarlink.plots.run import plot_run

__all__ = ["plot_plan", "plot_run"]
