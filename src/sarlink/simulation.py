"""One run of a mission: the planner registry's steering handed to the engine.

The engine knows rules and routes, not planners; this layer resolves the mission's planner
(:mod:`sarlink.planners`) and hands its steering to the engine.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from sarlink.config import Mission
from sarlink.engine import (
    Prepared,
    Scenario,
    Steering,
    get_radio,
    get_relay_strategy,
    get_target_motion,
)
from sarlink.engine.energy import get_energy_model
from sarlink.planners import get_planner
from sarlink.registry import Plugins, adopt_plugins, plugins_in_code
from sarlink.result import RunResult

__all__ = ["Plugins", "adopt_plugins", "check_mission", "plugins_in_code", "prepare", "simulate",
           "warm_up"]


def check_mission(mission: Mission) -> None:
    """Raise a :class:`~sarlink.ConfigError` unless the mission's planner, radio model, relay
    strategy, energy model and target-motion model are known: what cannot be checked before
    plug-ins are loaded, checked where work starts."""
    get_planner(mission.team.planner)
    get_radio(mission.radio)
    get_relay_strategy(mission.team.relay_strategy)
    get_energy_model(mission.energy_model)
    get_target_motion(mission.target.motion)


def warm_up(planner: str, radio: str, *, ranges: bool = False,
            relays: str | None = None, chain: bool = False, energy: bool = False,
            target: str | None = None, many: bool = False) -> None:
    """Compile (or load from the disk cache) the kernel of ``planner``'s rule, the radio
    model ``radio``, the relay strategy ``relays`` (None: a team without relays), the chain to
    a found target if ``chain`` (``on_detect = relay``), batteries if ``energy``, the target
    motion model ``target`` (None: a still target) and several targets if ``many``, by flying
    one tiny run that needs no plan; with ``ranges``, also the scan of one flight's staircase
    after it (:meth:`~sarlink.engine.Prepared.run_ranges`), from a drone on a route, which
    flies the same at every range under any rule's kernel."""
    rule = get_planner(planner).rule
    team = {"drones": 2, "relays": 1, "relay_strategy": relays} if relays else {"drones": 1}
    seams: dict[str, Any] = {**({"battery_wh": 100.0} if energy else {}),
             **({"motion": target} if target else {}), **({"count": 2} if many else {})}
    mission = Mission.build(planner=planner, horizon=10.0, radio=radio,
                            sigma=0.0 if radio == "disc" else 1.0,
                            on_detect="relay" if chain else "continue", **team, **seams)
    route = (np.array([mission.area.bs_xy]),)
    if ranges:
        steering = Steering(rule=rule, routes=route)
        Prepared.build(mission, steering).run_ranges(0, 0, (1.0, 2.0), staircase=True)
        return
    routes = () if rule is not None else route
    Prepared.build(mission, Steering(rule=rule, routes=routes)).run(0, 0)


def prepare(mission: Mission) -> Prepared:
    """Kernel inputs for ``mission``, steered by its planner, to run many times."""
    return Prepared.build(mission, get_planner(mission.team.planner).steering(mission.searching()))


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
