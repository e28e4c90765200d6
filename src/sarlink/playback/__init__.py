"""Replays: watch runs in a browser, from one self-contained HTML file (no server, no network).

``replay(result, mission)`` shows one run; ``compare(mission, planners, seed, run)`` flies the
same target and seed with several planners, in synchronised panels under one time control.
The format and the choice of a hand-written canvas layer are described in ``docs/replay.md``.
"""

from __future__ import annotations

import html
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from sarlink.config import ConfigError, Mission
from sarlink.planners import get_planner, planner_names
from sarlink.playback.page import render
from sarlink.playback.scene import describe, modes, scene, setting
from sarlink.result import RunResult
from sarlink.simulation import simulate

__all__ = ["PAGE_BUDGET", "Panel", "Replay", "compare", "replay"]

PAGE_BUDGET = 3.3e6
"""Bytes of frames per page before base64 (which adds a third): a page stays under 5 MB.
A 4000 s run of 22 drones takes 0.7 MB, so only much longer runs or many panels are thinned."""


@dataclass(frozen=True)
class Panel:
    """One run on the page, with the mission it flew and an optional title."""

    result: RunResult
    mission: Mission
    title: str | None = None


@dataclass(frozen=True)
class Replay:
    """A replay page of one or more runs; ``write`` saves it, Jupyter displays it inline."""

    panels: tuple[Panel, ...]
    title: str

    def html(self) -> str:
        """The page, as one self-contained HTML document."""
        budget = PAGE_BUDGET / len(self.panels)
        return render(self.title, {
            "modes": modes(),
            "panels": [scene(p.result, p.mission, p.title, budget) for p in self.panels],
        })

    def write(self, path: str | Path) -> Path:
        """Write the page to ``path`` (open it in any browser, also offline)."""
        path = Path(path)
        path.write_text(self.html(), encoding="utf-8")
        return path

    def _repr_html_(self) -> str:
        """Jupyter: the page in an isolated frame, so its script and style stay its own."""
        height = 760 if len(self.panels) == 1 else 1100
        return (f'<iframe srcdoc="{html.escape(self.html(), quote=True)}" '
                f'style="width: 100%; height: {height}px; border: 1px solid #ccc"></iframe>')


def replay(result: RunResult, mission: Mission, title: str | None = None) -> Replay:
    """A replay of one run simulated with ``trajectory=True``."""
    if result.trajectory is None:
        raise ValueError("a replay needs a result simulated with trajectory=True")
    return Replay((Panel(result, mission, title),), title or describe(mission, result))


def compare(mission: Mission, planners: Sequence[str], seed: int, run: int) -> Replay:
    """Fly run ``run`` of ``seed`` (same target, same take-off) with each planner in turn."""
    unknown = [p for p in planners if p not in planner_names()]
    if unknown or not planners:
        got = ", ".join(repr(p) for p in unknown) if unknown else "none"
        raise ConfigError(f"planners must be among {', '.join(planner_names())}; got {got}")
    panels = []
    for name in planners:
        flown = mission.replace(planner=name)
        panels.append(Panel(simulate(flown, seed=seed, run=run, trajectory=True), flown,
                            get_planner(name).label))
    labels = ", ".join(get_planner(p).label for p in planners)
    return Replay(tuple(panels), f"{labels}: {setting(mission)} (seed {seed}, run {run})")
