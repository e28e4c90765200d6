"""Figure of one run: area, BS, target, paths, and where detection and notification happened."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Circle

from sarlink.config import Mission
from sarlink.engine.codes import Mode
from sarlink.plots.area import draw_area
from sarlink.result import RunResult


def plot_run(result: RunResult, mission: Mission, ax: plt.Axes | None = None) -> plt.Axes:
    """Draw a run simulated with ``trajectory=True`` on ``ax`` (a new figure if None)."""
    traj = result.trajectory
    if traj is None:
        raise ValueError("plot_run needs a result simulated with trajectory=True")
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 7), layout="constrained")
    bx, by = mission.area.bs_xy
    tx, ty = result.target
    draw_area(ax, mission)
    ax.add_patch(Circle((bx, by), mission.channel.rc, fill=False, ls="--", lw=0.8, color="tab:blue",
                        label=f"BS range r_c = {mission.channel.rc:g} m"))
    ax.add_patch(Circle((tx, ty), mission.sensing.r, color="tab:red", alpha=0.12,
                        label=f"sensing range r = {mission.sensing.r:g} m"))
    colors = plt.get_cmap("tab20")(np.linspace(0, 1, traj.positions.shape[1], endpoint=False))
    for i, color in enumerate(colors):
        ax.plot(traj.positions[:, i, 0], traj.positions[:, i, 1], lw=0.7, color=color, alpha=0.8)
    reporting = traj.mode == Mode.REPORTING
    reporters = np.flatnonzero(reporting.any(axis=0))
    for k, drone in enumerate(reporters):  # on_detect = report: the legs to the BS
        legs = np.where(reporting[:, drone], traj.positions[:, drone].T, np.nan)
        ax.plot(legs[0], legs[1], lw=2.2, color="black", alpha=0.7,
                label="flying to tell the BS" if k == 0 else None)
    ax.plot(bx, by, marker="^", ms=12, color="tab:blue", ls="none", label="base station")
    ax.plot(tx, ty, marker="X", ms=11, color="tab:red", ls="none", label="target")
    if result.t_detect is not None and result.detector is not None:
        k = int(np.searchsorted(traj.t, result.t_detect))
        x, y = traj.positions[k, result.detector]
        ax.plot(x, y, marker="*", ms=16, color="gold", mec="black", ls="none",
                label=f"detected at t = {result.t_detect:g} s (drone {result.detector})")
    if result.t_notify is not None:
        k = int(np.searchsorted(traj.t, result.t_notify))
        relay = traj.knows[k] & traj.bs_route[k]
        ax.plot(traj.positions[k, relay, 0], traj.positions[k, relay, 1], marker="s", ms=8,
                mfc="none", mec="tab:green", mew=2, ls="none",
                label=f"BS notified at t = {result.t_notify:g} s")
    label = mission.team.planner
    ax.set(xlabel="x (m)", ylabel="y (m)",
           title=f"{label}, N = {mission.team.drones}, r_c = {mission.channel.rc:g} m, "
                 f"seed {result.seed}, run {result.run}")
    ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    return ax
