"""Figure of one run: area, BS, target, paths, and where detection and notification happened."""

from __future__ import annotations

from typing import Any

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Circle
from matplotlib.ticker import MaxNLocator

from sarlink.config import Mission
from sarlink.engine.codes import Mode
from sarlink.playback.scene import setting
from sarlink.plots.area import draw_area
from sarlink.result import RunResult, Trajectory


def plot_run(result: RunResult, mission: Mission, ax: plt.Axes | None = None) -> plt.Axes:
    """Draw a run simulated with ``trajectory=True`` on ``ax`` (a new figure if None)."""
    traj = result.trajectory
    if traj is None:
        raise ValueError("plot_run needs a result simulated with trajectory=True")
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 7), layout="constrained")
    bx, by = mission.area.bs_xy
    tx, ty = result.target
    walked = traj.target[:, 0, :] if traj.target is not None else None
    if walked is not None:  # a moving target: drawn where it was at detection, or at the end
        k = -1 if result.t_detect is None else int(np.searchsorted(traj.t, result.t_detect))
        tx, ty = walked[k]
    draw_area(ax, mission)
    ax.add_patch(Circle((bx, by), mission.channel.rc, fill=False, ls="--", lw=0.8, color="tab:blue",
                        label=f"BS range r_c = {mission.channel.rc:g} m"))
    ax.add_patch(Circle((tx, ty), mission.sensing.r, color="tab:red", alpha=0.12,
                        label=f"sensing range r = {mission.sensing.r:g} m"))
    colors = plt.get_cmap("tab20")(np.linspace(0, 1, traj.positions.shape[1], endpoint=False))
    for i, color in enumerate(colors):
        ax.plot(traj.positions[:, i, 0], traj.positions[:, i, 1], lw=0.7, color=color, alpha=0.8)
    _legs(ax, result, Mode.REPORTING, "flying to tell the BS", color="black", alpha=0.7)
    held = _legs(ax, result, Mode.RELAYING, "relays, holding the link", color="tab:olive",
                 ls=(0, (4, 1.5)), alpha=0.9)
    if held.size:  # where each relay stood last while relaying
        ax.plot(held[:, 0], held[:, 1], marker="D", ms=8, mfc="tab:olive", mec="black",
                ls="none")
    chain = _legs(ax, result, Mode.CHAINING, "the chain to the found target",
                  color="tab:red", ls=(0, (1, 1)), alpha=0.9)
    if chain.size:  # where each drone of the chain stood last in it
        ax.plot(chain[:, 0], chain[:, 1], marker="o", ms=7, mfc="tab:red", mec="black",
                ls="none")
    ax.plot(bx, by, marker="^", ms=12, color="tab:blue", ls="none", label="base station")
    if walked is not None:
        ax.plot(walked[:, 0], walked[:, 1], color="tab:red", lw=1.2, ls=(0, (2, 1)),
                label=f"the target's track ({mission.target.motion})")
        ax.plot(*result.target, marker="x", ms=9, color="tab:red", ls="none",
                label="target last seen")
    ax.plot(tx, ty, marker="X", ms=11, color="tab:red", ls="none", label="target")
    if result.targets is not None:  # several: the others, each where it was found or ended
        _other_targets(ax, result, traj)
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
    farthest = _farthest_drone(result, (bx, by))
    if farthest is not None:
        t, (x, y), distance = farthest
        ax.plot(x, y, marker="o", ms=10, mfc="none", mec="tab:purple", mew=2, ls="none",
                label=f"farthest connected drone: {distance:.0f} m at t = {t:g} s")
    ax.set(xlabel="x (m)", ylabel="y (m)",
           title=f"{mission.team.planner}, {setting(mission)}, seed {result.seed}, "
                 f"run {result.run}")
    ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    return ax


def _legs(ax: plt.Axes, result: RunResult, mode: Mode, label: str, **style: Any
          ) -> np.ndarray:
    """Draw, bold over the tracks, every drone's legs in ``mode`` (one legend entry); return
    where each such drone was last in it, ``(drones, 2)``."""
    traj = result.trajectory
    assert traj is not None
    within = traj.mode == mode
    drones = np.flatnonzero(within.any(axis=0))
    for k, drone in enumerate(drones):
        legs = np.where(within[:, drone], traj.positions[:, drone].T, np.nan)
        ax.plot(legs[0], legs[1], lw=2.2, label=label if k == 0 else None, **style)
    last = len(within) - 1 - np.argmax(within[::-1, drones], axis=0)
    return traj.positions[last, drones]


def _farthest_drone(result: RunResult, bs: tuple[float, float]
                    ) -> tuple[float, np.ndarray, float] | None:
    """When and where the run's farthest connected drone was, as its checkpoints recorded it
    (the first checkpoint at the largest ``farthest``), and how far from the BS at ``bs``;
    None if no airborne drone ever had a route at a checkpoint."""
    traj = result.trajectory
    if traj is None or not np.nanmax(result.farthest, initial=0.0) > 0:
        return None
    c = int(np.nanargmax(result.farthest))
    t = float(result.checkpoints[c])
    k = int(np.searchsorted(traj.t, t))
    routed = traj.bs_route[k] & (traj.mode[k] != Mode.LANDED)
    distance = np.where(routed, np.hypot(*(traj.positions[k] - np.asarray(bs)).T), -1.0)
    return t, traj.positions[k, int(np.argmax(distance))], float(result.farthest[c])


def plot_network(result: RunResult, mission: Mission, ax: plt.Axes | None = None) -> plt.Axes:
    """Draw the BS's network over a run at its checkpoints on ``ax`` (a new figure if None):
    the depth of the BS's component in hops (left axis) and the distance from the BS of the
    farthest connected drone, beside ``r_c`` (right axis). A team that relays nothing stays a
    single-hop star: one hop, its farthest connected drone within ``r_c``."""
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 2.5), layout="constrained")
    t = result.checkpoints
    # snapshots at the checkpoints: each drawn about its checkpoint, the last one too
    ax.step(t, result.depth, where="mid", color="tab:green", marker=".", ms=4,
            label="hops from the BS (depth)")
    ax.set(xlabel="t (s)", ylabel="hops", xlim=(0, t[-1]))
    ax.yaxis.set_major_locator(MaxNLocator(integer=True))
    far = ax.twinx()
    far.plot(t, result.farthest, color="tab:purple", lw=1.2, marker=".", ms=4,
             label="farthest connected drone")
    far.axhline(mission.channel.rc, color="tab:blue", ls="--", lw=0.8,
                label=f"r_c = {mission.channel.rc:g} m")
    far.set(ylabel="distance from the BS (m)", ylim=(0, None))
    lines = [*ax.get_lines(), *far.get_lines()]
    ax.legend(lines, [str(line.get_label()) for line in lines], loc="lower left",
              bbox_to_anchor=(0.0, 1.0), ncols=3, fontsize=8, frameon=False)  # above the data
    ax.set_ylim(0, max(float(np.nanmax(result.depth, initial=0.0)), 1.0) + 0.5)
    return ax


def _other_targets(ax: plt.Axes, result: RunResult, traj: Trajectory) -> None:
    """Targets 2..K of several: each one's track if they move, and its cross where it was
    found (ringed) or, if never, where it was last (or at the end)."""
    assert result.targets is not None and result.t_detect_each is not None
    ringed = False
    for j in range(1, result.targets.shape[0]):
        found = result.t_detect_each[j]
        at = result.targets[j]
        if traj.target is not None:
            ax.plot(traj.target[:, j, 0], traj.target[:, j, 1], color="tab:red", lw=0.9,
                    ls=(0, (2, 1)), alpha=0.7)
            at = traj.target[-1 if np.isnan(found) else
                             int(np.searchsorted(traj.t, found)), j]
        ax.plot(*at, marker="X", ms=9, color="tab:red", ls="none",
                label="the other targets" if j == 1 else None)
        if not np.isnan(found):
            ax.plot(*at, marker="o", ms=14, mfc="none", mec="tab:red", ls="none",
                    label=None if ringed else "found (ringed)")
            ringed = True
