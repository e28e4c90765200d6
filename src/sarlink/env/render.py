"""Pictures of the environment's state (PettingZoo's ``render``): the area, the BS, the target,
every drone and its links at the current step.

``rgb_array`` draws on a figure of its own (no pyplot, no window) and returns the image, the
frames a video recorder takes; ``human`` draws in a pyplot window and shows it for a frame's
time (``metadata["render_fps"]``).
"""

from __future__ import annotations

from typing import Literal

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from sarlink.config import Mission
from sarlink.engine.codes import Mode
from sarlink.engine.graph import has
from sarlink.engine.run import unpack_links
from sarlink.env.episode import EngineState
from sarlink.plots.area import draw_area

__all__ = ["FPS", "RENDER_MODES", "RenderMode", "Renderer"]

RenderMode = Literal["human", "rgb_array"]
RENDER_MODES: tuple[RenderMode, ...] = ("human", "rgb_array")
FPS = 10
"""Frames per second of the ``human`` window: one frame per step at which drones decide."""
_SIZE = 6.0
"""Figure side, inches (at 100 dpi: 600 × 600 pixels)."""


class Renderer:
    """Draws one mission's states, frame after frame, on one figure."""

    def __init__(self, mission: Mission, mode: RenderMode) -> None:
        self.mission, self.mode = mission, mode
        if mode == "human":
            self.figure: Figure = plt.figure(figsize=(_SIZE, _SIZE), layout="constrained")
        else:
            self.figure = Figure(figsize=(_SIZE, _SIZE), dpi=100, layout="constrained")
            FigureCanvasAgg(self.figure)
        self.ax = self.figure.add_subplot()

    def draw(self, state: EngineState, t: float) -> np.ndarray | None:
        """Draw ``state`` at time ``t``: the image (``rgb_array``), or ``None`` once shown."""
        ax, obs = self.ax, state.obs
        n = obs.hx.shape[0]
        ax.clear()
        draw_area(ax, self.mission)
        linked = unpack_links(obs.adj[None, : n + 1])[0]  # among the drones and the BS
        a, b = np.nonzero(np.triu(linked, 1))
        xy = np.column_stack([obs.px[: n + 1], obs.py[: n + 1]])
        ax.add_collection(LineCollection(list(np.stack([xy[a], xy[b]], axis=1)), colors="tab:blue",
                                         linewidths=0.6, alpha=0.5, label="link"))
        ax.plot(*xy[n], marker="^", ms=11, color="tab:blue", ls="none", label="base station")
        ax.plot(obs.px[n + 1], obs.py[n + 1], marker="X", ms=10, color="tab:red", ls="none",
                label="target")
        routed = np.array([has(obs.routed, i) for i in range(n)], dtype=bool)
        flying = obs.mode != Mode.LANDED
        for mask, colour, label in ((~obs.knows & ~routed, "0.45", "drone"),
                                    (~obs.knows & routed, "tab:blue", "drone, routed to the BS"),
                                    (obs.knows, "gold", "drone that knows the target")):
            shown = mask & flying
            if shown.any():
                ax.plot(xy[:n][shown, 0], xy[:n][shown, 1], marker="o", ms=6, color=colour,
                        mec="black", mew=0.5, ls="none", label=label)
        ax.set(xlabel="x (m)", ylabel="y (m)", title=f"t = {t:g} s")
        ax.legend(loc="upper left", fontsize=7, framealpha=0.9)
        if self.mode == "human":
            self.figure.canvas.draw_idle()
            plt.pause(1.0 / FPS)
            return None
        canvas = self.figure.canvas
        canvas.draw()
        return np.asarray(canvas.buffer_rgba())[..., :3].copy()  # type: ignore[attr-defined]

    def close(self) -> None:
        """Close the window (``human``); a figure of its own needs nothing."""
        if self.mode == "human":
            plt.close(self.figure)
