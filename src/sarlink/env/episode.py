"""One run of a mission stepped from Python: the kernel's stepping form driven by a caller.

The stepping form (:func:`sarlink.engine.build.stepping_source`) is the engine's own kernel made
a generator: it runs the phases of every step (sense, links, flooding, notification, records,
the schedule of who decides, the rule's ``due`` hook) and stops where the rule's ``decide``
hook would run, handing over the kernel's state; the caller writes the new directions of the
drones that decide, and the kernel goes on with the boundary rule, the move and the next
steps. A run that gets the directions its rule would write flies bit for bit as ``simulate``.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from sarlink.config import ConfigError, Mission
from sarlink.engine.observation import Observation
from sarlink.engine.params import Params
from sarlink.engine.records import RunRecord
from sarlink.engine.run import Prepared, run_result
from sarlink.engine.scenario import draw_scenario
from sarlink.engine.streams import run_streams
from sarlink.planners import get_planner
from sarlink.result import RunResult


class EngineState(NamedTuple):
    """The kernel's own state at a step at which drones decide (its arrays, not copies).

    A policy may call a rule's hook on it, e.g. CovB's
    ``decide(state.k, state.params, state.obs, state.ws, state.deciding, vx, vy)``.
    """

    k: int
    """The step (``t = k * params.dt``)."""
    params: Params
    """The mission's scalars as the kernel reads them."""
    obs: Observation
    """What the drones observed this step."""
    ws: Any
    """The workspace of the planner's rule (its ``prepare`` hook's value; ConB's due hook has
    filled it this step)."""
    deciding: np.ndarray
    """Which drones decide now (bool, length N)."""


def stepping_mission(mission: Mission) -> Prepared:
    """``mission`` prepared for stepping: its planner must steer every drone by a distributed
    rule (the agents take its decisions and follow its schedule), and its runs stop at the
    BS's notification. Relays and the chain to a found target (``on_detect = relay``) are
    refused: the agents are the drones, and a drone holding a point takes no direction;
    batteries and several targets too, for now (the stepping kernel is compiled without
    them)."""
    if mission.team.relays:
        raise ConfigError(f"team.relays = {mission.team.relays}: sarlink.env steers every drone "
                          "as a searcher and cannot take relays yet; allowed: team.relays = 0")
    if mission.team.on_detect == "relay":
        raise ConfigError("team.on_detect = 'relay': sarlink.env steers every drone as a "
                          "searcher and cannot take the chain's drones; allowed: continue, "
                          "report")
    if mission.target.count > 1:
        raise ConfigError(f"target.count = {mission.target.count}: sarlink.env searches for "
                          "one target yet (its stepping kernel is compiled without several); "
                          "allowed: target.count = 1")
    planner = get_planner(mission.team.planner)
    steering = planner.steering(mission)
    if steering.rule is None or not steering.distributed(mission.team.drones).all():
        raise ConfigError(f"team.planner {mission.team.planner!r} flies routes; sarlink.env "
                          f"steers every drone and needs a distributed planner (covb, conb, "
                          f"concov or a rule plug-in) whose decision schedule the agents follow")
    return Prepared.build(mission.replace(stop="notified"), steering)


class Episode:
    """Run ``run`` of an experiment seeded with ``seed``, stepped decision by decision.

    The target and the take-off are those ``simulate(mission, seed, run)`` draws.
    """

    def __init__(self, prepared: Prepared, seed: int, run: int) -> None:
        self.prepared = prepared
        self.seed, self.run = seed, run
        streams = run_streams(seed, run)
        scenario = draw_scenario(prepared.mission, streams.scenario)
        self.target = (float(scenario.target[0]), float(scenario.target[1]))
        self._steps = prepared.stepping_kernel(*prepared.arguments(streams, scenario))
        self.record: RunRecord | None = None
        self._advance()

    def _advance(self) -> None:
        k, obs, ws, deciding, vx, vy, record = next(self._steps)
        if record is not None:
            deciding = np.zeros_like(deciding)
            self.record = record
        self.state = EngineState(int(k), self.prepared.params, obs, ws, deciding)
        self._vx, self._vy = vx, vy

    @property
    def done(self) -> bool:
        """Whether the run has ended (notification, or the horizon)."""
        return self.record is not None

    @property
    def t(self) -> float:
        """The time of the current step, s."""
        return self.state.k * self.prepared.params.dt

    def decide(self, vx: np.ndarray, vy: np.ndarray) -> None:
        """Give every deciding drone ``i`` its new unit direction ``(vx[i], vy[i])`` and run
        to the next step at which drones decide (or to the end)."""
        if self.done:
            raise RuntimeError("the run has ended")
        d = self.state.deciding
        self._vx[d] = vx[d]
        self._vy[d] = vy[d]
        self._advance()

    def result(self) -> RunResult:
        """The run's records, as :func:`sarlink.simulate` returns them (once it has ended)."""
        if self.record is None:
            raise RuntimeError("the run has not ended")
        return run_result(self.record, self.seed, self.run, self.target,
                          batteries=self.prepared.energy)
