"""The engine's Python side: a checked mission and its steering into kernel inputs, and the
kernel's record into a :class:`~sarlink.RunResult`."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numba.core.errors import NumbaError

from sarlink.config import ConfigError, Mission
from sarlink.config.region import area_polygon, is_polygon
from sarlink.engine.area import edge_array
from sarlink.engine.build import kernel_for
from sarlink.engine.codes import (
    CHECK_CODES,
    CONB_FALLBACK_CODES,
    CONNECTED_CODES,
    CONTACTS_CODES,
    COVB_DIRECTION_CODES,
    ESTIMATE_CODES,
    FALLBACK_CODES,
    ISOLATED_CODES,
    LOOK_CODES,
    ON_DETECT_CODES,
    PARKED_CODES,
    PREDICTION_CODES,
    PRIORITY_CODES,
    REACHABILITY_CODES,
    REPORTERS_CODES,
    SHADOWING_CODES,
    STOP_CODES,
    SUCCESS_CODES,
)
from sarlink.engine.critical_ranges import Critical, critical
from sarlink.engine.energy import get_energy_model
from sarlink.engine.hooks import RelayStrategy
from sarlink.engine.params import CONTINUE, RELAY, STOP_DETECTED, STOP_NOTIFIED, Params
from sarlink.engine.paths import Navigation
from sarlink.engine.radios import get_radio
from sarlink.engine.radios.lognormal import fade_bias
from sarlink.engine.records import AtRanges, RunRecord
from sarlink.engine.relays import get_relay_strategy
from sarlink.engine.scenario import HEADING_ERROR, Scenario, draw_scenario, takeoff_headings
from sarlink.engine.steering import Steering
from sarlink.engine.streams import Streams, copied, run_streams
from sarlink.engine.target_motion import TargetMotion, get_target_motion
from sarlink.result import RunResult, Trajectory


@dataclass(frozen=True)
class Prepared:
    """A mission and its steering turned into kernel inputs once, to run many times."""

    mission: Mission
    steering: Steering
    params: Params
    radio_params: np.ndarray
    distributed: np.ndarray
    waypoints: np.ndarray
    wp_start: np.ndarray
    cp_steps: np.ndarray
    edges: np.ndarray
    """A polygon area's edges (:mod:`sarlink.engine.area`); empty for the square, whose walls
    the square's boundary rule (``params.size``) keeps."""
    nav: np.ndarray
    """A polygon area's corners, their distances home and to each other."""
    far: float
    """A polygon area's longest flight home, m (an upper bound)."""
    target_params: np.ndarray
    """The target-motion model's parameter array (empty for a still target)."""

    @classmethod
    def build(cls, mission: Mission, steering: Steering) -> Prepared:
        """Kernel inputs for ``mission`` flown with ``steering`` (its searchers' steering,
        :meth:`~sarlink.config.Mission.searching`): scalars, routes, checkpoints."""
        n = mission.team.drones
        distributed = np.zeros(n, dtype=bool)  # the relays, last, run no rule
        distributed[:n - mission.team.relays] = steering.distributed(n - mission.team.relays)
        if steering.rule is None and distributed.any():
            raise ConfigError(f"team.planner {mission.team.planner!r} gave no route to drone "
                              f"{int(np.argmax(distributed))} and has no distributed rule")
        radio = get_radio(mission.radio)
        routes = list(steering.routes) + [np.empty((0, 2))] * (n - len(steering.routes))
        wp_start = np.zeros(n + 1, dtype=np.int64)
        wp_start[1:] = np.cumsum([len(r) for r in routes])
        waypoints = np.concatenate([np.asarray(r, dtype=float).reshape(-1, 2) for r in routes])
        bs_x, bs_y = mission.area.bs_xy
        edges, nav, far = np.empty((0, 4)), np.empty((0, 3)), 0.0
        if is_polygon(mission.region):
            polygon = area_polygon(mission.region, mission.area.size)
            rings = [polygon.exterior.coords, *(h.coords for h in polygon.interiors)]
            edges = edge_array([np.asarray(ring) for ring in rings])
            nav, far = Navigation(polygon).home((bs_x, bs_y))
        t, r = mission.timing, mission.readings
        cp_steps = np.array(mission.checkpoint_steps(), dtype=np.int64)
        motion = get_target_motion(mission.target.motion)
        params = Params(
            size=mission.area.size, bs_x=bs_x, bs_y=bs_y, speed=mission.team.speed,
            alpha=mission.team.alpha,
            flight_time=mission.team.flight_time, r=mission.sensing.r,
            p_miss=mission.sensing.p_miss, look=int(LOOK_CODES[mission.sensing.look]),
            rc=mission.channel.rc, sigma=mission.channel.sigma,
            pathloss_exponent=mission.channel.pathloss_exponent,
            altitude=mission.channel.altitude, decorrelation=mission.channel.decorrelation,
            dt=t.dt, ts_steps=mission.steps(t.ts),
            coherence_steps=mission.steps(mission.coherence), n_steps=mission.n_steps,
            stop=int(STOP_CODES[t.stop]), record=False, trace=False,
            on_detect=int(ON_DETECT_CODES[mission.team.on_detect]),
            reporters=int(REPORTERS_CODES[mission.team.reporters]),
            conb_check=int(CHECK_CODES[r.conb_check]), contacts=int(CONTACTS_CODES[r.contacts]),
            isolated=int(ISOLATED_CODES[r.isolated]),
            concov_fallback=int(FALLBACK_CODES[r.concov_fallback]),
            concov_connected=int(CONNECTED_CODES[r.concov_connected]),
            conb_fallback=int(CONB_FALLBACK_CODES[r.conb_fallback]),
            covb_direction=int(COVB_DIRECTION_CODES[r.covb_direction]),
            shadowing=int(SHADOWING_CODES[r.shadowing]),
            reachability=int(REACHABILITY_CODES[r.reachability]),
            mtsp_prediction=int(PREDICTION_CODES[r.mtsp_prediction]),
            parked=int(PARKED_CODES[r.parked]),
            turn_error=HEADING_ERROR if r.turns == "jitter" else 0.0,
            fade_bias=fade_bias(mission.channel.sigma, mission.channel.pathloss_exponent,
                                r.shadow_calibration),
            relays=mission.team.relays,
            relay_priority=int(PRIORITY_CODES[mission.team.relay_priority]),
            relay_estimate=int(ESTIMATE_CODES[mission.team.relay_estimate]),
            **battery_params(mission),
            target_delay=round(mission.target.delay / t.dt) if motion.moves else 0,
            target_every=max(1, round(mission.target.motion_step / t.dt)) if motion.moves else 1,
            success=int(SUCCESS_CODES[mission.target.success]),
        )
        rp = np.asarray(radio.params(mission) if radio.params else (), dtype=float)
        return cls(mission=mission, steering=steering, params=params, radio_params=rp,
                   distributed=distributed, waypoints=waypoints, wp_start=wp_start,
                   cp_steps=cp_steps, edges=edges, nav=nav, far=far,
                   target_params=motion.array(mission) if motion.moves else np.empty(0))

    @property
    def relays(self) -> RelayStrategy | None:
        """The team's relay strategy, or None for a team without relays."""
        team = self.mission.team
        return get_relay_strategy(team.relay_strategy) if team.relays else None

    @property
    def target_motion(self) -> TargetMotion:
        """How the mission's target moves (``target.motion``)."""
        return get_target_motion(self.mission.target.motion)

    @property
    def kernel(self) -> Any:
        """The kernel compiled for this team's rule, the mission's radio model, the team's
        relay strategy (if it has relays), its chain to a found target (if
        ``on_detect = relay``), its batteries, the target's motion (if it moves) and several
        targets (if ``target.count > 1``)."""
        return self._kernel(stepping=False)

    @property
    def stepping_kernel(self) -> Any:
        """The stepping form of :attr:`kernel` (``sarlink.env``), with the same seams: a
        generator of the kernel's state at every step at which a drone decides."""
        return self._kernel(stepping=True)

    def _kernel(self, *, stepping: bool) -> Any:
        return kernel_for(self.steering.rule, get_radio(self.mission.radio), self.relays,
                          stepping=stepping, chain=self.params.on_detect == RELAY,
                          energy=self.energy, target=self.target_motion,
                          many=self.mission.target.count > 1)

    @property
    def energy(self) -> bool:
        """Whether the team flies on batteries (``mission.battery``; the kernel with
        :mod:`sarlink.engine.endurance`)."""
        return math.isfinite(self.params.battery_j)

    def arguments(self, streams: Streams, scenario: Scenario, *, trajectory: bool = False,
                  traced_at: float | None = None, scan_at: Sequence[float] = ()
                  ) -> tuple[object, ...]:
        """The kernel's arguments for one run from its random streams and initial conditions;
        ``traced_at``: a traced flight (``Params.trace``) at that range instead; ``scan_at``:
        a flight scanned at each of those ranges as it flies (its radio at ``r_c = 1``)."""
        n = self.mission.team.drones
        if scenario.positions is None:
            pos0 = np.tile(np.asarray(self.mission.area.bs_xy, dtype=float), (n, 1))
        else:
            pos0 = np.asarray(scenario.positions, dtype=float)
        p = self.params._replace(record=trajectory)
        if traced_at is not None:
            p = p._replace(rc=traced_at, trace=True)
        if scan_at:
            p = p._replace(rc=1.0)
        return (p, self.radio_params,
                float(scenario.target[0]), float(scenario.target[1]), pos0,
                takeoff_headings(scenario, self.distributed, self.mission.readings.takeoff,
                                 streams.takeoff), self.waypoints, self.wp_start,
                self.cp_steps, streams.turn, streams.shadow, streams.look, streams.rule,
                streams.heading,
                self.edges, self.nav, self.far, np.array([rc * rc for rc in scan_at]),
                # a still target's kernel draws nothing from its stream: none is made
                self.target_params,
                streams.target if self.target_motion.moves else streams.turn,
                scenario.targets,
                # the other targets move with draws after their positions' (draw_scenario)
                streams.targets if self.mission.target.count > 1 else streams.turn)

    def record(self, streams: Streams, scenario: Scenario, *, trajectory: bool = False,
               traced_at: float | None = None, scan_at: Sequence[float] = ()) -> RunRecord:
        """The kernel's record of one run from its random streams and initial conditions.

        A team with no distributed drone (mTSP-ConB with ``N_m <= N_r``) is scanned at several
        ranges by the kernel of routes: its rule never acts (:attr:`range_free`), and only
        the kernels of range-free teams carry the range scan (``SCANS_RANGES``, engine.build).
        """
        kernel = self.kernel
        if scan_at and not self.distributed.any():
            kernel = kernel_for(None, get_radio(self.mission.radio))  # range-free: still
        args = self.arguments(streams, scenario, trajectory=trajectory, traced_at=traced_at,
                              scan_at=scan_at)
        if kernel.signatures:  # compiled: no checks in the way of a sweep's runs
            return kernel(*args)
        try:
            return kernel(*args)
        except NumbaError as exc:
            rule = self.steering.rule.name if self.steering.rule else "(routes only)"
            relays = (f", relay strategy {self.mission.team.relay_strategy!r}"
                      if self.mission.team.relays else "")
            detail = next((line.strip() for line in str(exc).splitlines() if line.strip()
                           and not line.startswith(("Failed in", "During:", "-"))), str(exc))
            raise ConfigError(f"the kernel for rule {rule!r}, radio model "
                              f"{self.mission.radio!r}{relays} does not compile (a plug-in's hook "
                              f"does not fit the engine's types, docs/plugins.md): "
                              f"{detail}") from exc

    def _start(self, seed: int, run: int, scenario: Scenario | None
               ) -> tuple[Streams, Scenario]:
        streams = run_streams(seed, run)
        if scenario is None:
            scenario = draw_scenario(self.mission, streams.scenario, streams.targets
                                     if self.mission.target.count > 1 else None)
        scenario.check(self.mission)
        return streams, scenario

    def run(self, seed: int = 0, run: int = 0, *, scenario: Scenario | None = None,
            trajectory: bool = False) -> RunResult:
        """Simulate run ``run`` of an experiment seeded with ``seed`` (with that run's own
        routes if the steering makes them per run)."""
        if self.steering.per_run is not None:
            return self._own(seed, run).run(seed, run, scenario=scenario, trajectory=trajectory)
        streams, scenario = self._start(seed, run, scenario)
        rec = self.record(streams, scenario, trajectory=trajectory)
        traj = None
        if trajectory:
            tr = rec.track
            traj = Trajectory(t=np.arange(tr.mode.shape[0]) * self.params.dt,
                              positions=tr.positions, headings=tr.headings, knows=tr.knows,
                              bs_route=tr.bs_route, mode=tr.mode, links=unpack_links(tr.links),
                              target=rec.target_track if rec.target_track.shape[0] else None)
        return run_result(rec, seed, run, (float(scenario.target[0]), float(scenario.target[1])),
                          traj, batteries=self.energy,
                          targets=scenario.targets if scenario.others else None)

    def run_record(self, seed: int = 0, run: int = 0) -> RunRecord:
        """The kernel's own record of run ``run`` (with that run's own routes if the steering
        makes them per run): what :meth:`run` returns and what it leaves out, such as the work
        the rule counted (``RunRecord.work``, Fig. 1)."""
        if self.steering.per_run is not None:
            return self._own(seed, run).run_record(seed, run)
        streams, scenario = self._start(seed, run, None)
        return self.record(streams, scenario)

    @property
    def range_free(self) -> bool:
        """Whether the team flies the same at every communication range, as the seams declare
        it: the radio model's fades do not depend on ``r_c`` (the built-in log-normal model),
        no drone reports or forms a chain to a found target (``on_detect = continue``: the
        chain's points depend on ``r_c``), there is one target and it stands still (the scan
        reads one target position), and every distributed drone (if any) runs a rule
        declared ``range_free`` (CovB). Such a run can be flown once for all ranges
        (:meth:`run_ranges`)."""
        rule = self.steering.rule
        return (get_radio(self.mission.radio).range_free and self.params.on_detect == CONTINUE
                and self.params.relays == 0 and not self.energy
                and not self.target_motion.moves and self.mission.target.count == 1
                and (not self.distributed.any() or (rule is not None and rule.range_free)))

    def _own(self, seed: int, run: int) -> Prepared:
        """This mission with run ``run``'s own plan, if its steering plans per run."""
        if self.steering.per_run is None:
            return self
        own = replace(self.steering, routes=self.steering.per_run(seed, run), per_run=None)
        return Prepared.build(self.mission, own)

    def critical(self, seed: int, run: int, rcs: Sequence[float], *,
                 scenario: Scenario | None = None) -> tuple[Scenario, RunRecord, Critical]:
        """One traced flight of a range-free mission (``Params.trace``: positions only, flown
        to the horizon or the detection if it stops there), its critical ranges (the
        notification staircase) and its records at each range of ``rcs``; with the run's
        initial conditions and the flight's own record."""
        if self.steering.per_run is not None:
            return self._own(seed, run).critical(seed, run, rcs, scenario=scenario)
        self._check_range_free()
        streams, scenario = self._start(seed, run, scenario)
        # the looks and fades, drawn again as the flight draws them
        shadow, look = copied(streams.shadow), copied(streams.look)
        p = self.params
        rec = self.record(streams, scenario, traced_at=min(rcs))
        stopped = p.stop == STOP_DETECTED and rec.t_detect >= 0.0
        positions = rec.track.positions
        crit = critical(p, p._replace(rc=1.0), float(scenario.target[0]),
                        float(scenario.target[1]), positions, rec.track.mode,
                        positions.shape[0] - 1 if stopped else p.n_steps, shadow, look,
                        self.cp_steps, np.array([rc * rc for rc in rcs]))
        return scenario, rec, crit

    def _check_range_free(self) -> None:
        if not self.range_free:
            raise ValueError(f"{self.mission.team.planner} with these settings flies "
                             "differently at each range: fly each range")

    def run_ranges(self, seed: int, run: int, rcs: Sequence[float], *, staircase: bool = False,
                   scenario: Scenario | None = None) -> list[RunResult]:
        """Run ``run`` at every range of ``rcs`` from one flight (a range-free mission only):
        the same results, bit for bit, as :meth:`run` with the mission at each range; with
        ``staircase``, each also with its notification staircase
        (:attr:`sarlink.RunResult.notify_times`), found after the flight from its positions
        (:meth:`critical`); without it, the flight is scanned at each range as it flies."""
        p = self.params
        if staircase:
            scenario, rec, crit = self.critical(seed, run, rcs, scenario=scenario)
            at = AtRanges(crit.notified, crit.reach_cum, crit.conn_cum, crit.depth,
                          crit.farthest)
        else:
            own = self._own(seed, run)
            own._check_range_free()
            streams, scenario = own._start(seed, run, scenario)
            rec = own.record(streams, scenario, scan_at=rcs)
            at = rec.at_ranges
        target = (float(scenario.target[0]), float(scenario.target[1]))
        out = []
        for j, k in enumerate(at.notified.tolist()):
            t_notify = None if k < 0 else float(k * p.dt)
            stairs: dict[str, Any] = {}
            if staircase:  # a run stopped at its notification knows its staircase up to there
                keep = crit.notify_steps <= (k if p.stop == STOP_NOTIFIED and k >= 0
                                             else p.n_steps)
                stairs = {"notify_times": crit.notify_steps[keep] * p.dt,
                          "notify_rc2": crit.notify_keys[keep]}
            out.append(RunResult(
                seed=seed, run=run, target=target,
                t_detect=None if rec.t_detect < 0 else rec.t_detect, t_notify=t_notify,
                immediate=t_notify is not None and t_notify == rec.t_detect,
                detector=None if rec.detector < 0 else rec.detector,
                checkpoints=rec.checkpoints, reach_cum=at.reach_cum[j],
                connected_cum=at.conn_cum[j], depth=at.depth[j], farthest=at.farthest[j],
                **stairs))
        return out

def run_result(rec: RunRecord, seed: int, run: int, target: tuple[float, float],
               trajectory: Trajectory | None = None, *, batteries: bool = False,
               targets: np.ndarray | None = None) -> RunResult:
    """The kernel's record of run ``run`` (seed ``seed``) as a :class:`~sarlink.RunResult`;
    ``batteries``: with the sorties of a team on batteries; ``targets``: several targets'
    positions, ``(K, 2)``, with each one's events."""
    flown = rec.sorties
    each: dict[str, Any] = {}
    if targets is not None:
        each = {"targets": np.asarray(targets, dtype=float),
                "t_detect_each": np.where(rec.t_detect_each < 0, np.nan, rec.t_detect_each),
                "t_notify_each": np.where(rec.t_notify_each < 0, np.nan, rec.t_notify_each),
                "detector_each": rec.detector_each.copy()}
    return RunResult(
        seed=seed, run=run, target=target,
        t_detect=None if rec.t_detect < 0 else rec.t_detect,
        t_notify=None if rec.t_notify < 0 else rec.t_notify,
        immediate=rec.immediate, detector=None if rec.detector < 0 else rec.detector,
        checkpoints=rec.checkpoints, reach_cum=rec.reach_cum, connected_cum=rec.conn_cum,
        depth=rec.depth, farthest=rec.farthest, trajectory=trajectory,
        **({"sorties": flown.number, "ground_time": flown.ground, "energy": flown.energy}
           if batteries else {}),
        **each,
    )


def battery_params(mission: Mission) -> dict[str, Any]:
    """The kernel's battery scalars (:class:`~sarlink.engine.params.Params`) for ``mission``:
    the energy model's power at ``V_m`` and hovering, a take-off's climb and a landing's descent
    to and from the mission's altitude (at :data:`~sarlink.engine.energy.CLIMB_RATE` and
    :data:`~sarlink.engine.energy.DESCENT_RATE`, as export predicts), the capacity and reserve
    in joules; ``battery_j = inf`` without a battery."""
    b = mission.battery
    if b.battery_wh is None:
        return {"battery_j": math.inf, "reserve_j": 0.0, "fly_w": 0.0, "hover_w": 0.0,
                "climb_j": 0.0, "descent_j": 0.0, "swap_steps": 0, "spares": -1}
    model = get_energy_model(mission.energy_model)
    altitude = mission.channel.altitude
    climb, descent = model.climb(altitude), model.descent(altitude)
    capacity = b.battery_wh * 3600.0
    fly, hover = model.power(mission.team.speed), model.power(0.0)
    least = climb + descent + 3.0 * mission.timing.dt * max(fly, hover)
    if capacity * (1.0 - b.reserve) <= least:
        raise ConfigError(
            f"battery.battery_wh = {b.battery_wh:g} with battery.reserve = {b.reserve:g} leaves "
            f"{capacity * (1.0 - b.reserve) / 3600.0:.3g} Wh a sortie, and the climb to "
            f"{altitude:g} m, the landing and three steps in the air take {least / 3600.0:.3g} "
            f"Wh under {mission.energy_model}: allowed, more than "
            f"{least / 3600.0 / (1.0 - b.reserve):.3g} Wh")
    return {"battery_j": capacity, "reserve_j": b.reserve * capacity,
            "fly_w": fly, "hover_w": hover,
            "climb_j": climb, "descent_j": descent, "swap_steps": mission.steps(b.swap_time),
            "spares": -1 if b.spares is None else b.spares}


def unpack_links(bits: np.ndarray) -> np.ndarray:
    """``(steps, m, words)`` adjacency bitsets as a ``(steps, m, m)`` boolean array."""
    m = bits.shape[1]
    flat = np.unpackbits(bits.astype("<u8").view(np.uint8), axis=-1, bitorder="little")
    return flat[..., :m].astype(bool)
