"""One run of a mission: the planner registry's steering handed to the engine.

The engine knows rules and routes, not planners; this layer resolves the mission's planner
(:mod:`sarlink.planners`) and hands its steering to the engine.
"""

from __future__ import annotations

from sarlink.config import Mission
from sarlink.engine import Prepared, Scenario
from sarlink.planners import get_planner
from sarlink.result import RunResult

__all__ = ["prepare", "simulate"]


def prepare(mission: Mission) -> Prepared:
    """Kernel inputs for ``mission``, steered by its planner, to run many times."""
    return Prepared.build(mission, get_planner(mission.team.planner).steering(mission))


def simulate(mission: Mission, seed: int = 0, run: int = 0, *, scenario: Scenario | None = None,
             trajectory: bool = False) -> RunResult:
    """Simulate one run of ``mission``; randomness comes only from ``(seed, run)``.

    Parameters
    ----------
    scenario
        Initial conditions to use instead of the ones drawn from ``(seed, run)``.
    trajectory
        Also return the full state at every step (for plots and analysis).
    """
    return prepare(mission).run(seed, run, scenario=scenario, trajectory=trajectory)
