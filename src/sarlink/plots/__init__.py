"""Figures. Functions take ``ax: plt.Axes | None`` and return the axes they drew on; the
design figure has several panels and returns its figure (import it from
``sarlink.plots.design``: it needs pandas, which the others do not)."""

from sarlink.plots.plan import plot_plan
from sarlink.plots.run import plot_network, plot_run

__all__ = ["plot_network", "plot_plan", "plot_run"]
