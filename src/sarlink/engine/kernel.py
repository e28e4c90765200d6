"""The mission model as one Numba kernel: a run from arrays and scalars (docs/model.md).

This module is the loop; the model's parts live in the modules named after them (sensing,
radio, graph, rules, motion, records), and together they are the only copy of the model. It
never validates: :mod:`sarlink.engine.run` builds its inputs from a checked mission.

Each step at ``t = k dt`` observes (sense, links, flooding, records), decides (who turns home
or updates, the team's rule, the boundary rule) and moves. Node indices: drones ``0 .. N-1``,
the BS ``N``, the (first) target ``N + 1``. Headings are unit vectors ``(hx, hy)``.

This file is a template: :mod:`sarlink.engine.build` compiles it once per distributed rule,
radio model and relay strategy (:mod:`sarlink.engine.hooks`), and with the chain to a found
target or without (``CHAIN``, ``on_detect = relay``), replacing the block of plug-in imports
below, into a module of its own in the cache folder, named after the digest of every source it
depends on (so an edit anywhere recompiles, and every process shares the compiled code).
The same text also gives the kernel's stepping form (``build.kernel_for(..., stepping=True)``,
:mod:`sarlink.env`): a generator that yields at the marked line of the decide phase.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine import (
    area,
    critical_ranges,
    endurance,
    graph,
    many,
    motion,
    records,
    sensing,
)
from sarlink.engine.geometry import FAR, PAD, unit
from sarlink.engine.observation import Observation
from sarlink.engine.params import (
    REPORT,
    SEARCHING,
    STOP_DETECTED,
    STOP_NOTIFIED,
    Params,
)
from sarlink.engine.records import NEVER, RunRecord
from sarlink.engine.relays import chain as relay_chain
from sarlink.engine.relays import flight as relay_flight

# isort: off
# ---- plug-ins: this block is replaced per rule, radio model and relay strategy (build) ----
from sarlink.engine.radios.lognormal import init as radio_init
from sarlink.engine.radios.lognormal import nominal as radio_nominal
from sarlink.engine.radios.lognormal import static as radio_static
from sarlink.engine.radios.lognormal import update as radio_update
from sarlink.engine.rules.none import decide as rule_decide
from sarlink.engine.rules.none import due as rule_due
from sarlink.engine.relays.none import place as relay_place
from sarlink.engine.relays.none import prepare as relay_prepare
from sarlink.engine.rules.none import prepare as rule_prepare
from sarlink.engine.target_motion.still import move as target_move
from sarlink.engine.target_motion.still import start as target_start

RELAYS = False
CHAIN = False
ENERGY = False
RULE_DUE = False
RULE_NEAR = False
SCANS_RANGES = True
TARGET_MOVES = False
TARGET_STATE = 0
MANY_TARGETS = False
# ---- end of plug-ins ----
# isort: on


@njit(cache=True, error_model="numpy", nogil=True)
def simulate_kernel(p: Params, rp: np.ndarray, target_x: float, target_y: float,
                    pos0: np.ndarray, heading0: np.ndarray, wp: np.ndarray, wp_start: np.ndarray,
                    cp_steps: np.ndarray, rng_turn: np.random.Generator,
                    rng_shadow: np.random.Generator, rng_look: np.random.Generator,
                    rng_rule: np.random.Generator, rng_heading: np.random.Generator,
                    edges: np.ndarray, nav: np.ndarray, far: float, r2s: np.ndarray,
                    tp: np.ndarray, rng_target: np.random.Generator, tt: np.ndarray,
                    rng_others: np.random.Generator) -> RunRecord:
    """Simulate one run; ``rp`` are the radio model's parameters.

    ``wp[wp_start[i]:wp_start[i+1]]`` is drone ``i``'s route (empty: distributed drone).
    ``edges`` are the segments of a polygon area's rings (:mod:`sarlink.engine.area`), ``nav``
    its corners (x, y, distance home, distances to the corners they see) and ``far`` the
    longest flight home; ``edges`` empty for the paper's square ``[0, p.size]²``.
    ``(target_x, target_y)`` is where the target was last seen; a moving target
    (``TARGET_MOVES``) moves from there by the target-motion model's hooks with parameters
    ``tp`` and draws from ``rng_target`` (:mod:`sarlink.engine.target_motion`), first for
    ``p.target_delay`` steps before take-off, then on; it moves every ``p.target_every``
    steps, at the end of the move phase of the step that ends its own (a clock from the
    sighting: its ``g``-th step since then ends a move of ``target_every`` steps when
    ``g + 1`` is a multiple of it), and stands where it went in between.
    ``tt`` are every target's last-seen positions, ``(K, 2)``, the first
    ``(target_x, target_y)``; with several (``MANY_TARGETS``, :mod:`sarlink.engine.many`) the
    others move, after the first, with draws from ``rng_others``.
    ``cp_steps`` are the steps at which the cumulative records are taken. A run stopped early
    (``p.stop``) has NaN records after its last step and a trajectory that ends there. The
    kernel releases the GIL, so that threads (a threaded Dask worker) can simulate at once.
    """
    n = pos0.shape[0]
    m = n + 2
    mp = (m + PAD - 1) // PAD * PAD  # padded with far-away nodes, linked to nothing
    px, py, pz = np.full(mp, FAR), np.full(mp, FAR), np.zeros(mp)
    px[:n] = pos0[:, 0]
    py[:n] = pos0[:, 1]
    pz[:n] = p.altitude
    px[n], py[n], px[n + 1], py[n + 1] = p.bs_x, p.bs_y, target_x, target_y
    if TARGET_MOVES:  # compiled only for a moving target (build): its walk before take-off
        txy, tstate = np.array([target_x, target_y]), np.zeros(TARGET_STATE)
        target_start(txy, tstate, tp, rng_target)
        every = p.target_every  # the steps before take-off at which a move of its own ends
        for j in range(every - 1, p.target_delay, every):
            target_move(txy, tstate, (j + 1 - every) * p.dt, every * p.dt, tp, edges, p.size,
                        rng_target)
        px[n + 1], py[n + 1] = txy[0], txy[1]
    n_tg = tt.shape[0]
    t_det_each, t_not_each = np.full(n_tg, NEVER), np.full(n_tg, NEVER)
    det_each = np.full(n_tg, -1, dtype=np.int64)
    if MANY_TARGETS:  # compiled only for several targets (build): each its own rows
        oxy = tt[1:].copy()  # the targets after the first
        ostate = np.zeros((n_tg - 1, TARGET_STATE))
        if TARGET_MOVES:  # after the first's walk before take-off, each other's in order
            for o in range(n_tg - 1):
                target_start(oxy[o], ostate[o], tp, rng_others)
            every = p.target_every
            for j in range(every - 1, p.target_delay, every):
                for o in range(n_tg - 1):
                    target_move(oxy[o], ostate[o], (j + 1 - every) * p.dt, every * p.dt, tp,
                                edges, p.size, rng_others)
        ex, ey = np.empty(n_tg), np.empty(n_tg)  # every target's position this step
        in_each = np.zeros((n_tg, n), dtype=np.bool_)
        pass_each = np.zeros((n_tg, n), dtype=np.int64)
        known = np.zeros((n_tg, n), dtype=np.bool_)  # who knows where each target is
    hx, hy = np.empty(n), np.empty(n)
    for i in range(n):
        hx[i], hy[i] = math.cos(heading0[i]), math.sin(heading0[i])
    mode = np.full(n, SEARCHING, dtype=np.int8)
    if RELAYS:  # compiled only for a team with relays (build)
        relay_flight.start(p, mode)
    wp_next, wp_end = wp_start[:n].copy(), wp_start[1:].copy()
    on_route = wp_end > wp_next
    for i in range(n):
        if on_route[i]:
            k = wp_start[i]
            hx[i], hy[i] = unit(wp[k, 0] - px[i], wp[k, 1] - py[i], hx[i], hy[i])
    last_change, pass_start = np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.int64)
    knows, in_range = np.zeros(n, dtype=np.bool_), np.zeros(n, dtype=np.bool_)
    thr2 = radio_init(p, rp, m, mp)
    nw = (m + 63) // 64
    adj, near = np.zeros((m, nw), dtype=np.uint64), np.zeros((m, nw), dtype=np.uint64)
    routed = np.zeros(nw, dtype=np.uint64)  # nodes with a route to the BS
    spread = np.zeros(nw, dtype=np.uint64)  # nodes that know the target's location
    stack = np.empty(m, dtype=np.int64)
    if MANY_TARGETS:  # the components a location floods over (many.flood)
        comp, reached = np.empty(n + 1, dtype=np.int64), np.zeros(n + 1, dtype=np.bool_)
        unseen = np.zeros(nw, dtype=np.uint64)
    nhx, nhy = np.zeros(n), np.zeros(n)  # new headings
    deciding = np.zeros(n, dtype=np.bool_)
    leave_x, leave_y = np.zeros(n), np.zeros(n)  # where a reporting route drone left its tour
    rejoin = np.zeros(n, dtype=np.bool_)  # flying back to that point
    goal_x, goal_y = np.full(n, np.nan), np.full(n, np.nan)  # that point, on a polygon area
    aim_x, aim_y = px[:n].copy(), py[:n].copy()  # the point a relay flies to and holds
    obs = Observation(px, py, pz, hx, hy, mode, on_route, last_change, knows, adj, near, routed,
                      spread, radio_nominal(p, rp), wp, wp_next, wp_end, rng_rule,
                      np.zeros(1, dtype=np.int64))
    ws = rule_prepare(p, obs)
    if RELAYS:
        rws = relay_prepare(p, obs)
        relay_gx, relay_gy = aim_x.copy(), aim_y.copy()  # the strategy's points
    if CHAIN:  # compiled only for on_detect = relay (build)
        chain_x, chain_y = np.empty(0), np.empty(0)  # the chain's points, once found
        heard = np.zeros(nw, dtype=np.uint64)
        slot = np.full(n, -1, dtype=np.int64)  # the point each drone of the chain holds
    if ENERGY:  # compiled only for a team with a battery (build)
        battery = endurance.start(p, n)
        energy, resume, was_route, ground_until, sorties, ground_s, used = battery
        spares = np.full(1, p.spares, dtype=np.int64)
        bx, by, airborne = np.empty(n), np.empty(n), np.zeros(n, dtype=np.bool_)
    track = records.new_track(p.n_steps + 1 if p.record else 0, n, nw,
                              p.n_steps + 1 if p.trace else 0)
    traj_pos, traj_head, traj_knows, traj_route, traj_mode, traj_links = track
    traj_target = np.empty((p.n_steps + 1 if TARGET_MOVES and p.record else 0, 1, 2))
    if MANY_TARGETS:
        traj_target = np.empty((p.n_steps + 1 if TARGET_MOVES and p.record else 0, n_tg, 2))
    reach_cum, conn_cum = np.empty(cp_steps.shape[0]), np.empty(cp_steps.shape[0])
    depth, farthest = np.full(cp_steps.shape[0], np.nan), np.full(cp_steps.shape[0], np.nan)
    acc_reach = acc_conn = 0.0
    # not literals (nor is push, below): a phase called with a variable first typed as the
    # literal 0 (-1, False) and then int64 (bool) compiles twice, the literal's copy unused
    ci = int(np.int64(0))
    t_det = t_not = NEVER
    detector = int(np.int64(-1))
    routes = wp.shape[0] > 0
    # a recorded run keeps every step; a moving target may walk into a settled drone's range
    may_settle = radio_static(p, rp) and not p.record and not TARGET_MOVES
    if MANY_TARGETS:
        may_settle_many = may_settle  # and every target's drones settled too (below)
    polygon = edges.shape[0] > 0
    home_max = far if polygon else motion.farthest_home(p)
    scanning = SCANS_RANGES and r2s.shape[0] > 0
    if SCANS_RANGES:
        sc = critical_ranges.new_scan(r2s, n, mp, cp_steps.shape[0])

    for k in range(p.n_steps + 1):
        t = k * p.dt
        due = ci  # the first checkpoint at or after this step
        ci = records.take_checkpoints(k, cp_steps, ci, reach_cum, conn_cum, acc_reach, acc_conn)
        if ENERGY:  # swaps on the ground; a drone that takes off observes this step airborne
            endurance.ground(k, (p.flight_time - t) - home_max / p.speed < 2.0 * p.dt, p, mode,
                             on_route, last_change, energy, resume, was_route, ground_until,
                             sorties, ground_s, used, spares)
        # ---- observe: sense, link, flood, notify, account ----
        radio_update(thr2, p, rp, k, rng_shadow)
        if MANY_TARGETS:  # each target in order, then the mission's detection (success)
            ex[0], ey[0] = px[n + 1], py[n + 1]
            for o in range(n_tg - 1):
                ex[o + 1], ey[o + 1] = oxy[o, 0], oxy[o, 1]
            many.sense(ex, ey, px, py, k, t, p, in_each, pass_each, known, t_det_each,
                       det_each, rng_look)
            jd = many.event(t_det_each, p.success)
            if t_det < 0.0 and jd >= 0:
                t_det, detector = t_det_each[jd], det_each[jd]
        else:
            first = sensing.sense(px, py, k, p, in_range, pass_start, knows, rng_look)
            if t_det < 0.0 and first >= 0:
                t_det, detector = t, first
        if RULE_NEAR:  # the pairs within r, on the steps at which a drone may decide
            push = bool(np.bool_(RULE_DUE))  # a due hook may make a drone decide at any step
            for i in range(n):
                push |= (not on_route[i] and mode[i] == SEARCHING
                         and k - last_change[i] >= p.ts_steps)
        else:  # the literal: the link passes compiled without the pairs within r
            push = False
        if not scanning:  # a range scan has a link pass of its own, at every range
            graph.links(px, py, pz, thr2, adj, p.r * p.r, near, push)
        reachable, connected = False, 0
        if SCANS_RANGES and scanning:  # compiled only where the team may be range-free (build)
            critical_ranges.scan_step(k, due, p, cp_steps, px, py, pz, thr2, t_det >= 0.0,
                                      knows, mode, spread, stack, sc, near, push)
        if not (scanning or p.trace):  # a traced flight is scanned afterwards (critical_ranges)
            graph.bs_component(adj, n, routed, stack)
            if MANY_TARGETS:
                many.flood(adj, known, t_det_each, t_not_each, t, knows, spread, comp,
                           reached, unseen, stack)
                jn = many.event(t_not_each, p.success)
                if t_not < 0.0 and jn >= 0:
                    t_not = t_not_each[jn]
            elif t_det >= 0.0 and graph.flood(adj, routed, knows, spread, stack) and \
                    t_not < 0.0:
                t_not = t
            reachable, connected = graph.reachability(adj, routed, mode, p.reachability,
                                                      p.parked)
            for c in range(due, ci):  # this step's checkpoints (mostly none): the BS's network
                depth[c], farthest[c] = records.network(adj, mode, p.parked, px, py, p.bs_x, p.bs_y)
        if p.record:
            records.record_step(k, px, py, hx, hy, routed, knows, mode, adj, traj_pos, traj_head,
                                traj_knows, traj_route, traj_mode, traj_links)
            if TARGET_MOVES:
                traj_target[k, 0, 0], traj_target[k, 0, 1] = px[n + 1], py[n + 1]
                if MANY_TARGETS:
                    traj_target[k, 1:] = oxy
        elif p.trace:
            records.record_positions(k, px, py, mode, traj_pos, traj_mode)
        if k == p.n_steps or (p.stop == STOP_DETECTED and t_det >= 0.0) or (
                p.stop == STOP_NOTIFIED and t_not >= 0.0) or (
                SCANS_RANGES and scanning and not sc.going.any()):
            break
        acc_reach += p.dt if reachable else 0.0
        acc_conn += p.dt * connected / n
        homing = (p.flight_time - t) - home_max / p.speed < 2.0 * p.dt
        if MANY_TARGETS:  # settled only if no drone still looks for a target it lacks
            may_settle = may_settle_many and (routes or homing) and many.settled(
                mode, in_each, known, p.look)
        # a drone lands at the end of its route or, homing, at the BS
        if may_settle and (routes or homing) and records.settled(mode, in_range, knows, p.look
                                                                ) and not (
                ENERGY and endurance.pending(resume)):
            # a settled team observes this step again and again (the graph, the knowers and
            # the links to the target are fixed): carry the sums to the horizon
            records.carry_records(k + 1, p.n_steps, cp_steps, ci, reach_cum, conn_cum,
                                  acc_reach, acc_conn, p.dt if reachable else 0.0,
                                  p.dt * connected / n)
            if SCANS_RANGES and scanning:
                critical_ranges.carry_scan(k + 1, p, cp_steps, ci, sc, mode, px, py)
            elif not p.trace:  # the graph is fixed too: the BS's network repeats
                d, f = records.network(adj, mode, p.parked, px, py, p.bs_x, p.bs_y)
                depth[ci:] = d
                farthest[ci:] = f
            ci = cp_steps.shape[0]
            break

        # ---- decide: every drone from the state before anyone turns ----
        if p.on_detect == REPORT and t_det >= 0.0:
            motion.report(k, p, t_not >= 0.0, detector, knows, mode, on_route, px, py, leave_x,
                          leave_y, rejoin, last_change)
        if CHAIN and t_det >= 0.0:  # the detector holds, the knowers share out the chain
            if t_det == t:
                chain_x, chain_y = relay_chain.start(p, obs.rc, detector, mode, on_route, px,
                                                     py, aim_x, aim_y, edges)
            relay_chain.join(detector, knows, mode, on_route, px, py, adj, chain_x, chain_y,
                             slot, aim_x, aim_y, heard, stack)
        if ENERGY:  # who turns home to swap
            endurance.turn_home(p, px, py, hx, hy, mode, on_route, energy, resume, was_route,
                                leave_x, leave_y, rejoin, edges, nav)
        any_deciding = motion.schedule(k, homing, p, px, py, hx, hy, mode, on_route,
                                       last_change, deciding, nhx, nhy)
        if RULE_DUE:
            any_deciding = rule_due(k, p, obs, ws, deciding)
        if any_deciding:
            # ---- stepping form: the decisions come from outside here (sarlink.env) ----
            rule_decide(k, p, obs, ws, deciding, nhx, nhy)
            if p.turn_error > 0.0:  # the heading a drone flies is not the one commanded
                motion.turn_errors(p, deciding, hx, hy, nhx, nhy, rng_heading)
        if RELAYS:  # the BS's points for its relays, and the relays' flight to theirs
            relay_place(k, p, obs, rws, edges, relay_gx, relay_gy)
            relay_flight.steer(k, homing, p, px, py, hx, hy, mode, routed, relay_gx, relay_gy,
                               aim_x, aim_y, nhx, nhy, edges, nav)
        if CHAIN:
            relay_chain.steer(k, homing, p, px, py, hx, hy, mode, aim_x, aim_y, nhx, nhy,
                              edges, nav)
        if polygon:  # the boundary rule on the polygon, and the ways round its holes
            area.polygon_rules(k, homing, p, px, py, nhx, nhy, mode, on_route, last_change,
                               edges, nav, rejoin, leave_x, leave_y, goal_x, goal_y, rng_turn)
        else:
            motion.boundary(k, p, px, py, mode, on_route, last_change, nhx, nhy, rng_turn)
        hx[:] = nhx
        hy[:] = nhy
        # ---- move ----
        if ENERGY:
            endurance.keep(px, py, mode, bx, by, airborne)
        motion.move(p, px, py, hx, hy, mode, on_route, wp, wp_next, wp_end, leave_x, leave_y,
                    rejoin, aim_x, aim_y)
        if ENERGY:
            endurance.drain(p, px, py, mode, bx, by, airborne, energy, used)
        # the target moves last, at the end of its own step: the next step senses it there
        if TARGET_MOVES and (p.target_delay + k + 1) % p.target_every == 0:
            since = (p.target_delay + k + 1 - p.target_every) * p.dt  # its step's start
            target_move(txy, tstate, since, p.target_every * p.dt, tp, edges, p.size,
                        rng_target)
            px[n + 1], py[n + 1] = txy[0], txy[1]
            if MANY_TARGETS:
                for o in range(n_tg - 1):
                    target_move(oxy[o], ostate[o], since, p.target_every * p.dt, tp, edges,
                                p.size, rng_others)

    if not MANY_TARGETS:  # one target: its events are the mission's
        t_det_each[0], t_not_each[0], det_each[0] = t_det, t_not, detector
    if ENERGY:  # noqa: SIM108 (a statement Numba prunes: without ENERGY, sorties is unbound)
        flown = records.Sorties(sorties, ground_s, used)
    else:
        flown = records.one_sortie(n)
    reach_cum[ci:] = np.nan  # checkpoints after an early stop
    conn_cum[ci:] = np.nan
    kk = min(traj_pos.shape[0], k + 1)  # a run stopped early records fewer steps
    at_ranges = critical_ranges.scan_records(sc) if SCANS_RANGES else records.no_ranges(cp_steps)
    return RunRecord(t_det, t_not, detector, t_not >= 0.0 and t_not == t_det,
                     cp_steps * p.dt, reach_cum, conn_cum,
                     records.Track(traj_pos[:kk], traj_head[:kk], traj_knows[:kk],
                                   traj_route[:kk], traj_mode[:kk], traj_links[:kk]),
                     at_ranges, depth, farthest, obs.work[0], flown, traj_target[:kk],
                     t_det_each, t_not_each, det_each)
