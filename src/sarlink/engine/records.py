"""What a run records: event times, cumulative records at checkpoints, the trajectory.

The kernel returns one :class:`RunRecord`. "Never happened" is encoded once in this layer:
an event time of ``-1.0`` and a detector of ``-1``; the Python layer turns them into ``None``
(:class:`sarlink.RunResult`) and the result tables into NaN / null.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from sarlink.engine.graph import add, has, lowest, part_of_bs
from sarlink.engine.params import LANDED, PER_PERIOD

NEVER = -1.0
"""The kernel's event time of an event that did not happen within the run."""


class Track(NamedTuple):
    """The state at every recorded step (arrays indexed ``[step, drone]``)."""

    positions: np.ndarray  # (steps, N, 2) m
    headings: np.ndarray  # (steps, N) rad
    knows: np.ndarray  # (steps, N) bool
    bs_route: np.ndarray  # (steps, N) bool
    mode: np.ndarray  # (steps, N) int8 Mode
    links: np.ndarray  # (steps, N + 2, words) uint64 adjacency bitsets


class AtRanges(NamedTuple):
    """A range-free flight's records at each range it was scanned at as it flew
    (:mod:`sarlink.engine.critical_ranges`), in the order of the ranges given; empty otherwise."""

    notified: np.ndarray
    """Per range: the step of the notification (``-1``: never)."""
    reach_cum: np.ndarray
    """``(ranges, checkpoints)``: ``reach_cum`` at each range."""
    conn_cum: np.ndarray
    """``(ranges, checkpoints)``: ``conn_cum`` at each range."""
    depth: np.ndarray
    """``(ranges, checkpoints)``: the BS's network's depth at each range (:func:`network`)."""
    farthest: np.ndarray
    """``(ranges, checkpoints)``: its farthest drone at each range."""


class Sorties(NamedTuple):
    """Each drone's sorties, time on the ground for battery swaps (s) and energy drawn (J,
    NaN for a team without a battery, which flies one sortie: :mod:`sarlink.engine.endurance`)."""

    number: np.ndarray
    ground: np.ndarray
    energy: np.ndarray


@njit(cache=True, error_model="numpy")
def one_sortie(n: int) -> Sorties:
    """The sorties of a team without a battery: one each, no swap, energy not counted."""
    return Sorties(np.ones(n, dtype=np.int64), np.zeros(n), np.full(n, np.nan))


class RunRecord(NamedTuple):
    """One run as the kernel returns it (times in seconds; ``-1``: never). With several
    targets (:mod:`sarlink.engine.many`) the events are the mission's, by
    ``target.success``, and the records of reachability follow the first target."""

    t_detect: float
    t_notify: float
    detector: int
    immediate: bool
    checkpoints: np.ndarray
    """Times of the cumulative records, s: every ``checkpoint`` and the horizon."""
    reach_cum: np.ndarray
    """Time the target was reachable during ``[0, checkpoints[c])``; NaN after a stop."""
    conn_cum: np.ndarray
    """Time integral of the fraction of drones with a route to the BS over the same."""
    track: Track
    """The trajectory, empty (zero steps) unless the run was recorded; a traced run
    (``Params.trace``) has only the positions."""
    at_ranges: AtRanges
    """The records at each range of a flight scanned at several ranges (then the run's own
    notification, immediacy and records above are not kept)."""
    depth: np.ndarray
    """The BS's network at each checkpoint (:func:`network`): the most hops from the BS to an
    airborne drone with a route; NaN after a stop, and throughout a range scan or a traced
    flight, which build no graph of their own."""
    farthest: np.ndarray
    """The distance from the BS of the farthest airborne drone with a route at each
    checkpoint, m (0: none); NaN where ``depth`` is."""
    work: int
    """The work the rule counted in ``obs.work`` (ConB: the nodes its route predictions
    expanded); 0 for a rule that counts none."""
    sorties: Sorties
    target_track: np.ndarray
    """``(steps, K, 2)``: every target's position at every recorded step, m; empty unless the
    run was recorded and its targets move (:mod:`sarlink.engine.target_motion`)."""
    t_detect_each: np.ndarray
    """``(K,)``: each target's first detection, s (``-1``: never); with one target,
    ``t_detect``. The mission's ``t_detect`` is one of these, by ``target.success``."""
    t_notify_each: np.ndarray
    """``(K,)``: the first step's time at which the BS knew where each target is."""
    detector_each: np.ndarray
    """``(K,)``: each target's first detector (``-1``: none)."""


@njit(cache=True, error_model="numpy")
def no_ranges(cp_steps: np.ndarray) -> AtRanges:
    """The records at no range: a run not scanned at several ranges."""
    empty = np.empty((0, cp_steps.shape[0]))
    return AtRanges(np.full(0, -1, dtype=np.int64), empty, empty, empty, empty)


@njit(cache=True, error_model="numpy")
def new_track(steps: int, n: int, nw: int, position_steps: int = 0) -> Track:
    """Room for ``steps`` recorded steps of ``n`` drones (``nw`` bitset words per row), and
    for the positions and modes of ``position_steps`` steps if more (a traced run)."""
    traced = max(steps, position_steps)
    return Track(np.empty((traced, n, 2)), np.empty((steps, n)),
                 np.empty((steps, n), dtype=np.bool_), np.empty((steps, n), dtype=np.bool_),
                 np.empty((traced, n), dtype=np.int8),
                 np.empty((steps, n + 2, nw), dtype=np.uint64))


@njit(cache=True, error_model="numpy")
def record_step(k: int, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
                routed: np.ndarray, knows: np.ndarray, mode: np.ndarray, adj: np.ndarray,
                positions: np.ndarray, headings: np.ndarray, track_knows: np.ndarray,
                bs_route: np.ndarray, track_mode: np.ndarray, links: np.ndarray) -> None:
    """Store the observed state of step ``k`` in the arrays of a :class:`Track`.

    The kernel hands the track's arrays one by one, not the tuple: a tuple of arrays passed
    in the step loop costs a reference count of each of its arrays at every step.
    """
    for i in range(knows.shape[0]):
        positions[k, i, 0] = px[i]
        positions[k, i, 1] = py[i]
        headings[k, i] = math.atan2(hy[i], hx[i])
        bs_route[k, i] = has(routed, i)
    track_knows[k] = knows
    track_mode[k] = mode
    links[k] = adj


@njit(cache=True, error_model="numpy")
def record_positions(k: int, px: np.ndarray, py: np.ndarray, mode: np.ndarray,
                     positions: np.ndarray, track_mode: np.ndarray) -> None:
    """Store the drones' positions and modes of step ``k`` (a traced run, see
    ``Params.trace``: the modes say which drones are parked at the BS)."""
    for i in range(positions.shape[1]):
        positions[k, i, 0] = px[i]
        positions[k, i, 1] = py[i]
        track_mode[k, i] = mode[i]


@njit(cache=True, error_model="numpy")
def take_checkpoints(k: int, cp_steps: np.ndarray, ci: int, reach_cum: np.ndarray,
                     conn_cum: np.ndarray, acc_reach: float, acc_conn: float) -> int:
    """Record the sums so far at every checkpoint of step ``k``; return the next checkpoint."""
    while ci < cp_steps.shape[0] and cp_steps[ci] == k:
        reach_cum[ci] = acc_reach
        conn_cum[ci] = acc_conn
        ci += 1
    return ci


@njit(cache=True, error_model="numpy")
def network(adj: np.ndarray, mode: np.ndarray, parked: int, px: np.ndarray, py: np.ndarray,
            bs_x: float, bs_y: float) -> tuple[int, float]:
    """The BS's network of this step: its depth, the largest hop count from the BS to a drone
    with a route that is not part of the BS, and the distance from the BS of the farthest such
    drone (0 and 0.0 when there is none).

    Drones that are part of the BS (:func:`~sarlink.engine.graph.part_of_bs`: parked, under
    ``readings.parked = base``) are hop 0, so a drone linked to one is one hop out; under
    ``relay`` a parked drone is a relay like any other. A search level by level over the
    bitsets, from the BS and the drones part of it, never through the target (node ``N + 1``).
    The kernel calls it at its checkpoints only.
    """
    n = mode.shape[0]
    nw = adj.shape[1]
    reached = np.zeros(nw, dtype=np.uint64)
    level = np.zeros(nw, dtype=np.uint64)
    add(reached, n)
    add(level, n)
    for i in range(n):
        if part_of_bs(parked, mode[i]):
            add(reached, i)
            add(level, i)
    add(reached, n + 1)  # the target relays nothing
    nxt = np.zeros(nw, dtype=np.uint64)
    depth = 0
    far = 0.0
    while True:
        for w in range(nw):
            nxt[w] = 0
        for w in range(nw):
            bits = level[w]
            while bits:
                a = w * 64 + lowest(bits)
                bits &= bits - np.uint64(1)
                for v in range(nw):
                    nxt[v] |= adj[a, v] & ~reached[v]
        found = False
        for w in range(nw):
            found |= nxt[w] != 0
            reached[w] |= nxt[w]
            level[w] = nxt[w]
        if not found:
            return depth, far
        depth += 1
        for w in range(nw):  # every new node is an airborne drone
            bits = nxt[w]
            while bits:
                a = w * 64 + lowest(bits)
                bits &= bits - np.uint64(1)
                far = max(far, math.hypot(px[a] - bs_x, py[a] - bs_y))


@njit(cache=True, error_model="numpy")
def carry_records(start: int, n_steps: int, cp_steps: np.ndarray, ci: int, reach_cum: np.ndarray,
                  conn_cum: np.ndarray, acc_reach: float, acc_conn: float, d_reach: float,
                  d_conn: float) -> None:
    """Fill the checkpoints from step ``start`` on, as if every step added ``d_reach`` and
    ``d_conn``: summed step by step, like the full loop, so that the sums are the same."""
    for k in range(start, n_steps + 1):
        ci = take_checkpoints(k, cp_steps, ci, reach_cum, conn_cum, acc_reach, acc_conn)
        acc_reach += d_reach
        acc_conn += d_conn


@njit(cache=True, error_model="numpy")
def settled(mode: np.ndarray, in_range: np.ndarray, knows: np.ndarray, look: int) -> bool:
    """Whether no later step can differ from this one: every drone has landed, and none in
    sensing range still looks for the target (only per-period looks repeat in place)."""
    for i in range(mode.shape[0]):
        if mode[i] != LANDED or (look == PER_PERIOD and in_range[i] and not knows[i]):
            return False
    return True
