"""The contract every plug-in keeps, for sarlink's tests and a plug-in author's own: each
helper flies or calls a registered plug-in and raises an ``AssertionError`` naming what broke.

- :func:`check_planner`: drones stay in the area, the BS is not notified before the target is
  detected, the same ``(seed, run)`` flies the same, and the runs replay in the browser page;
- :func:`check_rule`: every declaration of a :class:`~sarlink.DistributedRule` holds in
  flight (``readings`` are fields of :class:`~sarlink.config.Readings`; a ``range_free`` rule
  flies the same at two ranges; an ``ignores_reporting`` one flies the same with and without
  reporting until a drone reports): a false one makes sarlink's shortcuts give wrong rows;
- :func:`check_radio`: a :class:`~sarlink.RadioModel`'s thresholds are finite, symmetric and
  zero towards the padding, its nominal range positive, a ``static`` model's never change
  after step 0, and a ``range_free`` one's scale with r_c²;
- :func:`check_relay_strategy`: teams with relays fly with a
  :class:`~sarlink.RelayStrategy` (every drone in the area, the BS not notified before the
  detection), the same ``(seed, run)`` flies the same, and the points its ``place`` hook
  writes for the relays are finite (the kernel ignores others, so such a relay would stand
  still unnoticed);
- :func:`check_energy_model`: an :class:`~sarlink.EnergyModel`'s hooks compile with Numba
  (the kernel calls them compiled) and give there what they give in Python; its powers are
  finite and never negative, the same hovering in level flight and straight up or down at
  speed 0, and a model that draws power draws it at every speed;
- :func:`check_target_motion`: a :class:`~sarlink.TargetMotion`'s hooks compile with Numba
  and move targets there as in Python, ``start`` does not move a target, positions stay
  finite, the same draws give the same tracks, and a model declared ``on_land`` keeps every
  target inside the square and inside an area with a hole, out of the hole.

In a plug-in's test suite::

    from sarlink.testing import check_planner, check_rule

    def test_my_planner_keeps_the_contract():
        check_planner("my-planner")
        check_rule("my-planner")  # the rule it flies
"""

from __future__ import annotations

import math
import tempfile
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

import numpy as np
from numba import njit

from sarlink.config import Mission, Readings
from sarlink.engine import Observation, Prepared, RadioModel, Steering, get_radio
from sarlink.engine.area import contains as area_contains
from sarlink.engine.area import edge_array
from sarlink.engine.codes import Mode
from sarlink.engine.energy import get_energy_model
from sarlink.engine.geometry import FAR, PAD
from sarlink.engine.hooks import DistributedRule
from sarlink.engine.relays import get_relay_strategy
from sarlink.engine.relays import none as no_relays
from sarlink.engine.target_motion import get_target_motion
from sarlink.planners import get_planner
from sarlink.playback import replay
from sarlink.result import RunResult
from sarlink.simulation import prepare, simulate

__all__ = ["check_energy_model", "check_planner", "check_radio", "check_relay_strategy",
           "check_rule", "check_run", "check_target_motion"]

SPEEDS = np.linspace(0.0, 40.0, 81)
"""Ground speeds (m/s) an energy model's level hook is called at: hover to beyond any
multirotor's top speed."""
CLIMBS = np.linspace(-10.0, 10.0, 41)
"""Vertical speeds (m/s) its vertical hook is called at."""


def check_run(result: RunResult, mission: Mission) -> None:
    """The invariants of one run flown with its trajectory."""
    name = mission.team.planner
    traj = result.trajectory
    assert traj is not None, "check_run needs a run simulated with trajectory=True"
    size = mission.area.size
    pos = traj.positions
    assert np.isfinite(pos).all(), f"{name}: a drone position is not finite"
    outside = (pos < -1e-9) | (pos > size + 1e-9)
    if outside.any():
        step, drone, _ = np.argwhere(outside)[0]
        raise AssertionError(f"{name}: drone {drone} leaves the area [0, {size:g}]² at "
                             f"t = {traj.t[step]:g} s: {tuple(pos[step, drone])}")
    if result.t_notify is not None:
        assert result.t_detect is not None and result.t_notify >= result.t_detect, (
            f"{name}: the BS is notified at {result.t_notify} s, before any detection "
            f"({result.t_detect})")


def _same(a: RunResult, b: RunResult) -> bool:
    ra, rb = a.row(), b.row()
    rows = ra.keys() == rb.keys() and all(
        np.array_equal(np.asarray(ra[k]), np.asarray(rb[k]), equal_nan=True) for k in ra)
    assert a.trajectory is not None and b.trajectory is not None
    return rows and np.array_equal(a.trajectory.positions, b.trajectory.positions)


def check_planner(name: str, *, drones: Sequence[int] = (1, 4, 10), runs: int = 2,
                  horizon: float = 1500.0, seed: int = 7, **params: Any) -> None:
    """Fly the registered planner ``name`` and check the contract (module docstring).

    ``params`` are further flat mission parameters (``rc=500.0``, ``on_detect="report"``).
    """
    planner = get_planner(name)
    for n in drones:
        mission = Mission.build(planner=name, drones=n, horizon=horizon, **params)
        steering = planner.steering(mission)
        assert len(steering.routes) <= n, f"{name}: {len(steering.routes)} routes for {n} drones"
        for run in range(runs):
            result = simulate(mission, seed=seed, run=run, trajectory=True)
            check_run(result, mission)
            again = simulate(mission, seed=seed, run=run, trajectory=True)
            assert _same(result, again), (f"{name}: run {run} of seed {seed} with {n} drones "
                                          "differs when flown again")
    with tempfile.TemporaryDirectory() as tmp:
        page = replay(result, mission).write(Path(tmp) / "replay.html").read_text()
    assert planner.label in page, f"{name}: the replay page does not name {planner.label!r}"


def _rule(rule: DistributedRule | str) -> DistributedRule:
    if isinstance(rule, DistributedRule):
        return rule
    found = get_planner(rule).rule
    assert found is not None, f"planner {rule!r} flies routes only: it has no rule to check"
    return found


def _fly(rule: DistributedRule, seed: int, run: int, **params: Any) -> RunResult:
    """One run of a team whose every drone runs ``rule``."""
    mission = Mission.build(planner=rule.name, **params)
    return Prepared.build(mission, Steering(rule=rule)).run(seed, run, trajectory=True)


def _parting(a: RunResult, b: RunResult, steps: int | None = None) -> int | None:
    """The first of the first ``steps`` steps (all by default) at which the two flights
    differ in position or heading; ``None`` if they do not."""
    ta, tb = a.trajectory, b.trajectory
    assert ta is not None and tb is not None
    k = min(len(ta.t), len(tb.t), len(ta.t) if steps is None else steps)
    differs = ((ta.positions[:k] != tb.positions[:k]).any(axis=(1, 2))
               | (ta.headings[:k] != tb.headings[:k]).any(axis=1))
    return int(np.argmax(differs)) if differs.any() else None


def check_rule(rule: DistributedRule | str, *, drones: Sequence[int] = (4,), runs: int = 2,
               horizon: float = 1200.0, seed: int = 7,
               ranges: tuple[float, float] = (300.0, 1500.0), **params: Any) -> None:
    """Check every declaration of ``rule`` (a :class:`~sarlink.DistributedRule`, or the name
    of a registered planner whose rule it is) against flights of a team that runs it.

    ``ranges`` are the two ranges a ``range_free`` rule is flown at; ``ignores_reporting`` is
    checked at the first, or at ``rc`` if given. ``params`` are further flat mission
    parameters.
    """
    rule = _rule(rule)
    unknown = set(rule.readings) - set(Readings.model_fields)
    assert not unknown, (f"rule {rule.name!r}: readings {sorted(unknown)} are not fields of "
                         f"sarlink.config.Readings ({', '.join(Readings.model_fields)})")
    for n in drones:
        for run in range(runs):
            fly = {"drones": n, "horizon": horizon, "rc": ranges[0], **params}
            where = f"run {run} of seed {seed} with {n} drones"
            if rule.range_free:
                near, far = (_fly(rule, seed, run, **{**fly, "rc": rc, "on_detect": "continue"})
                             for rc in ranges)
                k = _parting(near, far)
                assert k is None and (near.t_detect, near.detector) == (
                    far.t_detect, far.detector), (
                    f"rule {rule.name!r} declares range_free but flies differently at r_c = "
                    f"{ranges[0]:g} m and {ranges[1]:g} m ({where}, from step {k})")
            if rule.ignores_reporting:
                silent, loud = (_fly(rule, seed, run, **{**fly, "on_detect": mode})
                                for mode in ("continue", "report"))
                assert loud.trajectory is not None
                reporting = (loud.trajectory.mode == Mode.REPORTING).any(axis=1)
                first = int(np.argmax(reporting)) if reporting.any() else None
                k = _parting(silent, loud, first)
                assert k is None, (
                    f"rule {rule.name!r} declares ignores_reporting but flies differently with "
                    f"on_detect = report before any drone reports ({where}, from step {k})")


def check_radio(name: str, *, drones: Sequence[int] = (1, 6), steps: int = 60, seed: int = 7,
                ranges: tuple[float, float] = (300.0, 1500.0), **params: Any) -> None:
    """Call the hooks of the registered radio model ``name`` for a few teams, at two ranges,
    for ``steps`` steps, and check what they return (module docstring). ``params`` are
    further flat mission parameters (``sigma=4.0``, ``shadowing="correlated"``)."""
    model = get_radio(name)
    for n in drones:
        m = n + 2
        flown = {rc: _thresholds(model, n, steps, seed, rc=rc, **params) for rc in ranges}
        for rc, (nominal, static, later) in flown.items():
            where = f"radio model {name!r} with {n} drones at r_c = {rc:g} m"
            assert np.isfinite(nominal) and nominal > 0, (
                f"{where}: nominal range {nominal!r} is not positive")
            for k, thr2 in enumerate(later):
                assert thr2.shape[0] >= m and thr2.shape[1] == m + 2, (
                    f"{where}: thresholds of shape {thr2.shape} for {m} nodes and 2 padding")
                links = thr2[:m, :m]
                assert np.isfinite(links).all(), f"{where}: a threshold is not finite at step {k}"
                assert np.array_equal(links, links.T), (
                    f"{where}: thresholds are not symmetric at step {k}")
                assert not thr2[:m, m:].any(), (
                    f"{where}: a threshold towards a padding node is not zero at step {k}")
                assert not static or np.array_equal(links, later[0][:m, :m]), (
                    f"{where}: declared static, but its thresholds change at step {k}")
        if model.range_free:
            (a, (_, _, near)), (b, (_, _, far)) = flown.items()
            scaled = all(np.allclose(x[:m, :m] / a**2, y[:m, :m] / b**2, rtol=1e-12, atol=0.0)
                         for x, y in zip(near, far, strict=True))
            assert scaled, (f"radio model {name!r} declares range_free but its thresholds at "
                            f"r_c = {a:g} m and {b:g} m are not r_c² times the same fades "
                            f"({n} drones)")


def _thresholds(model: RadioModel, n: int, steps: int, seed: int,
                **params: Any) -> tuple[float, bool, list[np.ndarray]]:
    """The model's nominal range, whether it says it is static, and its thresholds after the
    update of each step (drawn from one random stream of ``seed``), for ``n`` drones and two
    padding nodes."""
    mission = Mission.build(radio=model.name, drones=n, **params)
    home = (np.array([mission.area.bs_xy]),) * n  # no rule: the thresholds need only Params
    prepared = Prepared.build(mission, Steering(rule=None, routes=home))
    p, rp = prepared.params, prepared.radio_params
    thr2 = model.init(p, rp, n + 2, n + 4)
    rng = np.random.default_rng(seed)
    later = []
    for k in range(steps):
        model.update(thr2, p, rp, k, rng)
        later.append(thr2.copy())
    static = model.static if isinstance(model.static, bool) else bool(model.static(p, rp))
    return float(model.nominal(p, rp)), static, later


def check_relay_strategy(name: str, *, planner: str = "covb", drones: int = 6,
                         relays: Sequence[int] = (1, 3), runs: int = 2, horizon: float = 1200.0,
                         seed: int = 7, **params: Any) -> None:
    """Fly teams of ``drones`` drones, ``relays`` of them relays placed by the registered relay
    strategy ``name`` and the others searching with ``planner``, and check the contract
    (module docstring). ``params`` are further flat mission parameters (``rc=500.0``).

    The points are checked by calling the strategy's hooks on the states each run recorded,
    in step order, as the kernel calls them (:func:`_recorded_states`).
    """
    strategy = get_relay_strategy(name)
    for k in relays:
        mission = Mission.build(planner=planner, drones=drones, relays=k, relay_strategy=name,
                                horizon=horizon, **params)
        prepared = prepare(mission)
        for run in range(runs):
            where = (f"relay strategy {name!r}, run {run} of seed {seed} with {k} of {drones} "
                     "drones relays")
            result = prepared.run(seed, run, trajectory=True)
            try:
                check_run(result, mission)
            except AssertionError as exc:
                raise AssertionError(f"{where}: {exc}") from None
            assert _same(result, prepared.run(seed, run, trajectory=True)), (
                f"{where}: the run differs when flown again")
            assert result.trajectory is not None
            gx, gy = result.trajectory.positions[0].T.copy()  # the kernel's first points
            ws = None
            for step, obs in _recorded_states(prepared, result, seed):
                if step == 0:
                    ws = (strategy.prepare or no_relays.prepare)(prepared.params, obs)
                strategy.place(step, prepared.params, obs, ws, prepared.edges, gx, gy)
                bad = (obs.mode == Mode.RELAYING) & ~(np.isfinite(gx) & np.isfinite(gy))
                if bad.any():
                    i = int(np.argmax(bad))
                    raise AssertionError(f"{where}: place wrote the point ({gx[i]}, {gy[i]}) "
                                         f"for relay {i} at step {step}; a point must be "
                                         "finite (the kernel ignores it and the relay stays)")


def _recorded_states(prepared: Prepared, result: RunResult, seed: int
                     ) -> Iterator[tuple[int, Observation]]:
    """The states a run recorded (``trajectory=True``), step by step, as the hooks see them:
    one :class:`Observation` whose arrays change in place as the kernel's do. What the
    trajectory does not record stays as at take-off: the decision clocks, the progress
    along the routes and the pairs within sensing range."""
    traj = result.trajectory
    assert traj is not None
    p = prepared.params
    n = prepared.mission.team.drones
    m = n + 2
    mp = -(-m // PAD) * PAD
    px, py, pz = np.full(mp, FAR), np.full(mp, FAR), np.zeros(mp)
    pz[:n] = p.altitude
    px[n], py[n] = p.bs_x, p.bs_y
    px[n + 1], py[n + 1] = result.target
    hx, hy = np.empty(n), np.empty(n)
    mode, knows = np.empty(n, dtype=np.int8), np.empty(n, dtype=np.bool_)
    adj = _bits(np.zeros((m, m), dtype=bool))
    routed, spread = _bits(np.zeros(m, dtype=bool)), _bits(np.zeros(m, dtype=bool))
    start = prepared.wp_start
    nominal = float(get_radio(prepared.mission.radio).nominal(p, prepared.radio_params))
    obs = Observation(px, py, pz, hx, hy, mode, start[1:] > start[:-1],
                      np.zeros(n, dtype=np.int64), knows, adj, np.zeros_like(adj), routed, spread,
                      nominal, prepared.waypoints, start[:-1].copy(), start[1:].copy(),
                      np.random.default_rng(seed), np.zeros(1, dtype=np.int64))
    notified = math.inf if result.t_notify is None else result.t_notify
    for k in range(len(traj.t)):
        px[:n], py[:n] = traj.positions[k, :, 0], traj.positions[k, :, 1]
        hx[:], hy[:] = np.cos(traj.headings[k]), np.sin(traj.headings[k])
        mode[:], knows[:] = traj.mode[k], traj.knows[k]
        adj[:] = _bits(traj.links[k])
        routed[:] = _bits(np.append(traj.bs_route[k], [True, False]))  # the BS is node n
        spread[:] = _bits(np.append(traj.knows[k], [traj.t[k] >= notified, False]))
        yield k, obs


def _bits(flags: np.ndarray) -> np.ndarray:
    """Flags over the nodes (the last axis) as the kernel's bitsets: 64-bit words, node ``b``
    at bit ``b % 64`` of word ``b // 64`` (the inverse of the trajectory's unpacking)."""
    m = flags.shape[-1]
    padded = np.zeros((*flags.shape[:-1], -(-m // 64) * 64), dtype=bool)
    padded[..., :m] = flags
    return np.packbits(padded, axis=-1, bitorder="little").view("<u8").astype(np.uint64)


def check_energy_model(name: str) -> None:
    """Call the hooks of the registered energy model ``name`` at :data:`SPEEDS` and
    :data:`CLIMBS`, compiled and in Python, and check what they return (module docstring)."""
    model = get_energy_model(name)
    ep = model.array
    for hook, speeds in (("level", SPEEDS), ("vertical", CLIMBS)):
        fn = getattr(model, hook)
        compiled = fn if hasattr(fn, "py_func") else njit(fn)
        python = compiled.py_func
        for v in speeds:
            where = f"energy model {name!r}: {hook}({v:g}, params)"
            got = compiled(float(v), ep)
            assert np.isfinite(got) and got >= 0, f"{where} = {got!r}, not a power >= 0 W"
            again = python(float(v), ep)
            assert np.isclose(got, again, rtol=1e-12, atol=0.0), (
                f"{where} is {got!r} compiled but {again!r} in Python")
            assert model.draws_power == (got > 0), (
                f"{where} = {got!r}, but level(0, params) = {model.power(0.0)!r}: a model "
                "draws power at every speed or at none")
    hover = model.power(0.0)
    for vz in (0.0, -0.0):
        assert np.isclose(model.vertical_power(vz), hover, rtol=1e-12, atol=0.0), (
            f"energy model {name!r}: vertical({vz}) = {model.vertical_power(vz)!r} is not "
            f"level(0) = {hover!r}, the hover power")


def _walls(size: float) -> dict[str, np.ndarray]:
    """The areas a target-motion model is checked in, as the kernel has them: the square
    (no edges) and the square with a square hole in its middle third."""
    a, b = size / 3.0, 2.0 * size / 3.0
    outline = np.array([[0.0, 0.0], [size, 0.0], [size, size], [0.0, size], [0.0, 0.0]])
    hole = np.array([[a, a], [a, b], [b, b], [b, a], [a, a]])
    return {"the square": np.empty((0, 4)), "the square with a hole": edge_array([outline, hole])}


def _inside(x: float, y: float, edges: np.ndarray, size: float) -> bool:
    if edges.shape[0] == 0:
        return 0.0 <= x <= size and 0.0 <= y <= size
    return bool(area_contains.py_func(x, y, edges))


def check_target_motion(name: str, *, targets: int = 12, steps: int = 300, seed: int = 7,
                        **params: Any) -> None:
    """Move ``targets`` targets of the registered target-motion model ``name`` for ``steps``
    steps from points of the mission's area, compiled and in Python, and check the contract
    (module docstring). ``params`` are further flat mission parameters (``delay=600.0``)."""
    model = get_target_motion(name)
    if not model.moves:
        return
    mission = Mission.build(motion=name, **params)
    tp, dt, size = model.array(mission), mission.timing.dt, mission.area.size
    assert model.start is not None and model.move is not None
    compiled = [f if hasattr(f, "py_func") else njit(f) for f in (model.start, model.move)]
    starts = np.random.default_rng(seed).uniform(0.05, 0.3, size=(targets, 2)) * size
    for where, edges in _walls(size).items():
        for j, first in enumerate(starts):
            tracks = []
            for start, move in (compiled, [f.py_func for f in compiled]):
                rng = np.random.default_rng([seed, j])
                xy, state = first.copy(), np.zeros(model.state)
                start(xy, state, tp, rng)
                assert np.array_equal(xy, first), (
                    f"target motion {name!r}: start moved the target from {tuple(first)} to "
                    f"{tuple(xy)}")
                track = [xy.copy()]
                for k in range(steps):
                    move(xy, state, k * dt, dt, tp, edges, size, rng)
                    track.append(xy.copy())
                tracks.append(np.array(track))
            fast, slow = tracks
            assert np.isfinite(fast).all(), f"target motion {name!r}: a position is not finite"
            assert np.allclose(fast, slow, rtol=1e-9, atol=1e-6), (
                f"target motion {name!r} moves target {j} in {where} to "
                f"{tuple(fast[-1])} compiled but to {tuple(slow[-1])} in Python")
            if model.on_land:
                for k, (x, y) in enumerate(fast):
                    assert _inside(x, y, edges, size), (
                        f"target motion {name!r} is declared on_land but target {j} is at "
                        f"({x:.1f}, {y:.1f}), outside {where}, after {k} steps")
