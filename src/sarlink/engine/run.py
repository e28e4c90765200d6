"""The engine's Python side: turn a checked mission into kernel inputs and results into objects."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sarlink.config import Mission
from sarlink.engine.codes import LOOK_CODES, STOP_CODES
from sarlink.engine.kernel import Params, simulate_kernel
from sarlink.engine.scenario import Scenario, draw_scenario, takeoff_headings
from sarlink.engine.streams import run_streams
from sarlink.planners import get_planner
from sarlink.result import RunResult, Trajectory


@dataclass(frozen=True)
class Prepared:
    """A mission turned into kernel inputs once, to run many times."""

    mission: Mission
    params: Params
    distributed: np.ndarray
    waypoints: np.ndarray
    wp_start: np.ndarray
    cp_steps: np.ndarray

    def run(self, seed: int = 0, run: int = 0, *, scenario: Scenario | None = None,
            trajectory: bool = False) -> RunResult:
        """Simulate run ``run`` of an experiment seeded with ``seed``."""
        streams = run_streams(seed, run)
        drawn = draw_scenario(self.mission, streams.scenario)
        scenario = drawn if scenario is None else scenario
        scenario.check(self.mission)
        n = self.mission.team.drones
        if scenario.positions is None:
            pos0 = np.tile(np.asarray(self.mission.area.bs_xy, dtype=float), (n, 1))
        else:
            pos0 = np.asarray(scenario.positions, dtype=float)
        params = self.params._replace(record=trajectory)
        out = simulate_kernel(
            params, float(scenario.target[0]), float(scenario.target[1]), pos0,
            takeoff_headings(scenario, self.distributed), self.waypoints, self.wp_start,
            self.cp_steps, streams.turn, streams.shadow, streams.look,
        )
        events, reach_cum, conn_cum, pos, head, knows, route, mode, links = out
        dt = self.mission.timing.dt
        traj = None
        if trajectory:
            traj = Trajectory(t=np.arange(pos.shape[0]) * dt, positions=pos, headings=head,
                              knows=knows, bs_route=route, mode=mode, links=unpack_links(links))
        t_det, t_not, detector, immediate = events
        return RunResult(
            seed=seed, run=run, target=(float(scenario.target[0]), float(scenario.target[1])),
            t_detect=None if t_det < 0 else float(t_det),
            t_notify=None if t_not < 0 else float(t_not),
            immediate=bool(immediate), detector=None if detector < 0 else int(detector),
            checkpoints=self.cp_steps * dt, reach_cum=reach_cum, connected_cum=conn_cum,
            trajectory=traj,
        )


def unpack_links(bits: np.ndarray) -> np.ndarray:
    """``(steps, m, words)`` adjacency bitsets as a ``(steps, m, m)`` boolean array."""
    m = bits.shape[1]
    flat = np.unpackbits(bits.astype("<u8").view(np.uint8), axis=-1, bitorder="little")
    return flat[..., :m].astype(bool)


def prepare(mission: Mission) -> Prepared:
    """Kernel inputs for ``mission``: its planner's steering, scalars and checkpoint steps."""
    n = mission.team.drones
    steering = get_planner(mission.team.planner).steering(mission)
    routes = list(steering.routes) + [np.empty((0, 2))] * (n - len(steering.routes))
    wp_start = np.zeros(n + 1, dtype=np.int64)
    wp_start[1:] = np.cumsum([len(r) for r in routes])
    waypoints = np.concatenate([np.asarray(r, dtype=float).reshape(-1, 2) for r in routes])
    bs_x, bs_y = mission.area.bs_xy
    t = mission.timing
    cp = mission.steps(t.checkpoint)
    cp_steps = np.arange(0, mission.n_steps + 1, cp, dtype=np.int64)
    if cp_steps[-1] != mission.n_steps:
        cp_steps = np.append(cp_steps, mission.n_steps)
    params = Params(
        size=mission.area.size, bs_x=bs_x, bs_y=bs_y, speed=mission.team.speed,
        rule=int(steering.rule), alpha=float(steering.alpha),
        flight_time=mission.team.flight_time, r=mission.sensing.r,
        p_miss=mission.sensing.p_miss, look=int(LOOK_CODES[mission.sensing.look]),
        rc=mission.channel.rc, sigma=mission.channel.sigma,
        pathloss_exponent=mission.channel.pathloss_exponent, altitude=mission.channel.altitude,
        dt=t.dt, ts_steps=mission.steps(t.ts), coherence_steps=mission.steps(mission.coherence),
        n_steps=mission.n_steps, stop=int(STOP_CODES[t.stop]), record=False,
    )
    return Prepared(mission=mission, params=params, distributed=steering.distributed(n),
                    waypoints=waypoints, wp_start=wp_start, cp_steps=cp_steps)


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
