"""Figure of an mTSP plan: the cells, the BS and every drone's tour with its length."""

from __future__ import annotations

from collections.abc import Sequence
from itertools import pairwise

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Rectangle

from sarlink.mtsp import MtspPlan


def plot_plan(
    plan: MtspPlan, ax: plt.Axes | None = None, *, size: float | None = None,
    r: float | None = None, routes: Sequence[np.ndarray] | None = None,
) -> plt.Axes:
    """Draw ``plan`` on ``ax`` (a new figure if None).

    Each tour has its own colour, arrows on its legs give the flying order, and the legend
    gives its number of cells and length. With ``r``, every point is drawn as a cell of side
    ``r``; with ``size``, the area ``[0, size]²`` is outlined and framed. ``routes`` are
    the tours as flown when they differ from the plan's straight legs (bent round holes).
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 7), layout="constrained")
    if size is not None:
        ax.add_patch(Rectangle((0, 0), size, size, fill=False, lw=1.2, color="black"))
    if r is not None:
        for x, y in plan.points:
            ax.add_patch(Rectangle((x - r / 2, y - r / 2), r, r, fill=False, lw=0.5,
                                   color="0.75"))
    n = len(plan.tours)
    cmap = plt.get_cmap("tab10" if n <= 10 else "tab20" if n <= 20 else "hsv")
    colors = cmap(np.linspace(0, 1, n, endpoint=False)) if n > 20 else cmap(np.arange(n))
    flown = plan.routes() if routes is None else routes
    for i, (route, color) in enumerate(zip(flown, colors, strict=True)):
        path = np.vstack([plan.depot, route])
        cells = len(plan.tours[i])
        ax.plot(path[:, 0], path[:, 1], lw=1.4, color=color, marker="o", ms=3,
                label=f"drone {i}: {cells} cells, {plan.lengths[i] / 1000:.2f} km")
        for a, b in pairwise(path):
            mid, half = (a + b) / 2, (b - a) * 0.02
            ax.annotate("", xy=mid + half, xytext=mid - half,
                        arrowprops={"arrowstyle": "-|>", "color": color, "mutation_scale": 12})
    ax.plot(*plan.depot, marker="^", ms=12, color="black", ls="none", label="base station")
    if size is not None:
        ax.set(xlim=(-0.03 * size, 1.03 * size), ylim=(-0.03 * size, 1.03 * size))
    ax.set(aspect="equal", xlabel="x (m)", ylabel="y (m)",
           title=f"mTSP ({plan.solver}, {plan.objective}): {n} drones, total "
                 f"{plan.total / 1000:.2f} km, longest {plan.longest / 1000:.2f} km")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8, framealpha=0.9)
    return ax
