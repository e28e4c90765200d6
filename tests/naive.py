"""A slow, obvious reference of the mission model (docs/model.md), in plain Python.

Written from the model's text, not from the kernel: angles instead of unit vectors, sets and
a breadth-first search instead of bitsets, one function per rule. It draws its random numbers
from the same per-purpose streams in the same order as the engine, so the two can be compared
run by run as well as statistically. The square area only (no polygons); the distributed
planners (CovB, ConB, ConCov), or routes given to it (a route planner's, as the engine plans
them: the reference flies them, the planning is checked in tests/test_mtsp*.py).

Relays (``team.relays``, docs/model.md, Relays) are flown here from the model's text: the
BS's hearing, its dead reckoning, the re-plan's terminals, delivery, homing and the flight.
The re-plan itself (the tree, the priority and the bottleneck assignment) is the engine's own
placement, run as plain Python (``plan.py_func``): :func:`relay_plan` below has no branch
points, no assignment and no points, so it is no plan the engine would make;
tests/test_relay_placement.py checks the placement on its own (against :func:`relay_plan`,
brute force, OR-Tools and exact bounds).

The chain to a found target (``on_detect = relay``, docs/model.md, Search, then relay) is
flown from the model's text too: the detector's hold, the chain's points on the segment from
the BS to it, the share-out in each component of the links, the points nearest the BS first,
the flight and homing. The share-out itself is the engine's bottleneck assignment, run as
plain Python (``assign.py_func``), checked on its own in tests/test_relay_placement.py.

Batteries (``mission.battery``, docs/model.md, Endurance) are flown from the model's text: the
energy of each step (flying or holding), the turn home when the energy above the reserve pays
for the flight home and no more, the swap from the BS's spares, and the take-off in the role
left (a route drone back to where it left its route). The powers are the energy model's own
(``EnergyModel.power``), checked against its equations in tests/test_energy.py.

A walking target (``target.motion = walk``, docs/model.md, Target motion) walks here from the
model's text: the heading's normal turn each step, the log-normal time it stops, the uniform
headings drawn again until a step stays in the square, and its walk during ``target.delay``
before take-off; it moves after the drones, once every ``target.motion_step`` seconds by the
walk of that time, so each step senses it where it is then. A
drifting target (``drift``) drifts here from the same text: its Leeway fit drawn once, the
wind and current read from their tables at the step's start, the jibe after the step.

Several targets (``target.count = K``, docs/model.md, Several targets): the first drawn as
one target is, the others from the run's targets stream (in order), each sensed, flooded and
notified on its own, each moving after the first by draws from the targets stream; the
mission's events are the first or the last of theirs, by ``target.success``.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass
from itertools import pairwise

import numpy as np

from sarlink.config import Mission
from sarlink.config.leeway import LEEWAY_CLASSES
from sarlink.engine.codes import PRIORITY_CODES
from sarlink.engine.energy import CLIMB_RATE, DESCENT_RATE, get_energy_model
from sarlink.engine.relays.placement import assign, plan
from sarlink.engine.streams import run_streams


@dataclass
class NaiveResult:
    t_detect: float | None
    t_notify: float | None
    immediate: bool
    t_reachable: float
    connected_time: float
    positions: list[list[tuple[float, float]]]
    depth: list[int]
    """At every checkpoint: the most hops from the BS to an airborne drone with a route."""
    farthest: list[float]
    """At every checkpoint: the distance from the BS of the farthest such drone, m (0: none)."""
    sorties: list[int] | None = None
    """On batteries: each drone's sorties, its time on the ground for swaps (s) and the
    energy it drew (J)."""
    ground_time: list[float] | None = None
    energy: list[float] | None = None
    target_track: list[tuple[float, float]] | None = None
    """A walking target's position at every recorded step."""
    detector: int = -1
    t_detect_each: list[float | None] | None = None
    """Several targets: each one's first detection, notification and detector."""
    t_notify_each: list[float | None] | None = None
    detector_each: list[int] | None = None
    targets: list[tuple[float, float]] | None = None
    """Several targets: where each was last seen."""
    tracks: list[list[tuple[float, float]]] | None = None
    """Several moving targets: every target's position at every recorded step."""


def mission_event(times: list[float | None], success: str) -> int | None:
    """The target whose time is the mission's: the earliest (``first``), or the latest once
    all have one (``all``); the lowest index among ties; None if there is none yet."""
    happened = [j for j, x in enumerate(times) if x is not None]
    if not happened or (success == "all" and len(happened) < len(times)):
        return None
    best = (min if success == "first" else max)(times[j] for j in happened)  # type: ignore
    return next(j for j in happened if times[j] == best)


def _dist(p: tuple[float, float], q: tuple[float, float]) -> float:
    return math.hypot(p[0] - q[0], p[1] - q[1])


def _within(p: tuple[float, float], q: tuple[float, float], limit: float, h: float = 0.0) -> bool:
    """``|p - q| <= limit``, compared squared: drones often sit at exactly ``r`` or ``r_c``
    (they take off radially at a whole number of metres per step), and the squared form is
    the one the engine uses."""
    return (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 + h * h <= limit * limit


def _inside(p: tuple[float, float], a: float) -> bool:
    return 0 <= p[0] <= a and 0 <= p[1] <= a


class Walker:
    """A lost person walking in the square ``[0, a]²`` (docs/model.md, Target motion), drawing
    from the run's target stream: a first heading and a stop time, then per step a turn."""

    def __init__(self, mission: Mission, rng: np.random.Generator) -> None:
        t = mission.target
        self.speed, self.turn, self.a, self.rng = t.walk_speed, t.walk_turn, mission.area.size, rng
        self.heading = rng.random() * 2 * math.pi
        self.stop = t.walk_mobile * math.exp(t.walk_spread * rng.standard_normal())

    def move(self, at: tuple[float, float], t: float, dt: float) -> tuple[float, float]:
        """Where the person walks from ``at`` between ``t`` and ``t + dt``."""
        if t >= self.stop:
            return at
        step = self.speed * min(dt, self.stop - t)
        self.heading += self.turn * math.sqrt(dt / 60) * self.rng.standard_normal()
        for _ in range(256):
            to = (at[0] + step * math.cos(self.heading), at[1] + step * math.sin(self.heading))
            if _inside(to, self.a):
                return to
            self.heading = self.rng.random() * 2 * math.pi
        to = (at[0] + step * math.cos(self.heading), at[1] + step * math.sin(self.heading))
        return to if _inside(to, self.a) else at


def _forcing(table: Sequence[tuple[float, float, float]], t: float) -> tuple[float, float]:
    """A wind or current table's (east, north) at ``t``: linear between rows, held at the ends."""
    if t <= table[0][0]:
        return table[0][1], table[0][2]
    for (t0, e0, n0), (t1, e1, n1) in pairwise(table):
        if t <= t1:
            f = (t - t0) / (t1 - t0)
            return e0 + f * (e1 - e0), n0 + f * (n1 - n0)
    return table[-1][1], table[-1][2]


class Drifter:
    """A person or an object at sea (docs/model.md, Target motion, ``drift``): the Leeway of
    its class plus the current, drawing from the run's target stream its side (right with
    probability 1/2), then the downwind fit error (again while the perturbed slope is
    negative) and the crosswind one, then per step whether it jibes (0.04 per hour)."""

    def __init__(self, mission: Mission, rng: np.random.Generator) -> None:
        t = mission.target
        fits = LEEWAY_CLASSES[t.drift_object]
        self.down, self.sides = fits.dw, {1: fits.cwr, -1: fits.cwl}
        self.wind, self.current, self.rng = t.drift_wind, t.drift_current, rng
        self.side = 1 if rng.random() < 0.5 else -1
        self.rd = rng.standard_normal()
        while self.down[0] + self.rd * self.down[2] / 20 < 0:
            self.rd = rng.standard_normal()
        self.rc = rng.standard_normal()

    def move(self, at: tuple[float, float], t: float, dt: float) -> tuple[float, float]:
        """Where the target drifts from ``at`` between ``t`` and ``t + dt``."""
        (wx, wy), (cx, cy) = _forcing(self.wind, t), _forcing(self.current, t)
        w = math.hypot(wx, wy)
        if w > 0:  # the error eps = r sigma: eps / 20 on the slope, eps / 2 on the offset
            a, b, sigma = self.down
            down = (a * w + b + self.rd * sigma * (w / 20 + 0.5)) / 100
            a, b, sigma = self.sides[self.side]
            cross = (a * w + b + self.rc * sigma * (w / 20 + 0.5)) / 100  # right of downwind
            cx += down * wx / w + cross * wy / w
            cy += down * wy / w - cross * wx / w
        if self.rng.random() < 1 - (1 - 0.04) ** (dt / 3600):
            self.side = -self.side
        return at[0] + cx * dt, at[1] + cy * dt


MOVERS = {"walk": Walker, "drift": Drifter}
"""The moving targets the reference knows, by ``target.motion``."""


def component(start: set[int], links: dict[int, set[int]], blocked: int) -> set[int]:
    """All nodes linked to ``start``, never passing through ``blocked``."""
    seen = set(start)
    queue = deque(start)
    while queue:
        a = queue.popleft()
        for b in links[a]:
            if b not in seen and b != blocked:
                seen.add(b)
                queue.append(b)
    return seen


def network(linked: list[list[bool]], base: list[bool], where: list[tuple[float, float]],
            bs: tuple[float, float]) -> tuple[int, float]:
    """The BS's network: the most hops from the BS to a drone with a route that is not part of
    the BS, and the distance from the BS of the farthest such drone (0 and 0.0 if none).
    ``linked`` is the adjacency matrix of the drones, the BS (``N``) and the target (``N + 1``,
    which relays nothing); a drone in ``base`` is part of the BS, hop 0. A plain breadth-first
    search."""
    n = len(base)
    hops = {n: 0, **{i: 0 for i in range(n) if base[i]}}
    queue = deque(hops)
    while queue:
        a = queue.popleft()
        for b in range(n):  # drones only: never the target
            if linked[a][b] and b not in hops:
                hops[b] = hops[a] + 1
                queue.append(b)
    out = [i for i in hops if i < n and not base[i]]
    return (max((hops[i] for i in out), default=0),
            max((_dist(where[i], bs) for i in out), default=0.0))


def simulate_naive(mission: Mission, seed: int, run: int, record: bool = False,
                   routes: Sequence[np.ndarray] = ()) -> NaiveResult:
    """Run ``run`` of ``mission`` (seeded with ``seed``); ``routes``: each searcher's waypoints
    (``(k, 2)``, ending at the BS) for a route planner, none for CovB, ConB and ConCov."""
    a = mission.area.size
    bs = mission.area.bs_xy
    n = mission.team.drones
    v = mission.team.speed
    dt = mission.timing.dt
    ts = mission.timing.ts
    r, rc = mission.sensing.r, mission.channel.rc
    planner = mission.team.planner
    alpha = {"covb": 1.0, "conb": 0.0}.get(planner, mission.team.alpha)
    readings = mission.readings
    searchers = n - mission.team.relays  # the relays are the team's last drones
    rule = planner in ("covb", "conb", "concov")
    route = [[(float(x), float(y)) for x, y in routes[i]] if i < len(routes) else []
             for i in range(n)]
    if rule == any(route):
        raise ValueError(f"the reference flies CovB, ConB and ConCov without routes, and any "
                         f"other planner with its routes given; got {planner!r} with "
                         f"{sum(map(bool, route))} routes")
    streams = run_streams(seed, run)
    target = (streams.scenario.random() * a, streams.scenario.random() * a)
    offset = streams.scenario.random() * 2 * math.pi
    count = mission.target.count
    others = [(streams.targets.random() * a, streams.targets.random() * a)
              for _ in range(count - 1)]
    seen = [target, *others]
    BS, TG = n, n + 1
    motion = MOVERS.get(mission.target.motion)
    mover = motion(mission, streams.target) if motion else None
    delay = round(mission.target.delay / dt) if mover else 0
    # a moving target's own time step: it moves at the end of each step g since the sighting
    # at which every·dt has passed since its last move, for that time, and stands in between
    every = max(1, round(mission.target.motion_step / dt))

    def ends_a_move(g: int) -> bool:
        return (g + 1) % every == 0

    for j in range(delay):
        if ends_a_move(j):
            assert mover is not None
            target = mover.move(target, (j + 1 - every) * dt, every * dt)
    movers = [motion(mission, streams.targets) for _ in others] if motion else []
    for j in range(delay):
        if ends_a_move(j):
            others = [m.move(o, (j + 1 - every) * dt, every * dt)
                      for m, o in zip(movers, others, strict=True)]
    track = []
    tracks = []

    pos = [bs] * n
    free = [i for i in range(searchers) if not route[i]]  # the drones the rule steers
    heading = [0.0] * n  # route drones and relays: east, until they turn
    for k, i in enumerate(free):
        heading[i] = 2 * math.pi * k / len(free) + offset
    if readings.takeoff != "even" and free:  # one uniform number per drone, take-off stream
        u = [streams.takeoff.random() for _ in range(n)]
        for i in free:
            if readings.takeoff == "random":
                heading[i] = 2 * math.pi * u[i]
            else:  # each off by at most 5 degrees (docs/model.md)
                heading[i] += math.radians(5.0) * (2 * u[i] - 1)
    wp_next = [0] * n  # each route drone's next waypoint
    for i in range(searchers):
        if route[i] and route[i][0] != bs:  # towards the first waypoint
            heading[i] = math.atan2(route[i][0][1] - bs[1], route[i][0][0] - bs[0])
    last_change = [0.0] * n
    mode = ["search"] * searchers + ["relaying"] * (n - searchers)
    aim = list(pos)  # the point each relay flies to and holds
    points = list(pos)  # the point the BS last planned for each relay
    # x, y, heading, step, next waypoint and mode of each drone when the BS last heard it
    heard: list[tuple[float, float, float, int, int, str]] = []
    knows_each = [[False] * n for _ in range(count)]  # who knows where each target is
    knows = knows_each[0]  # one target: the same list
    in_range = [[False] * n for _ in range(count)]
    pass_start = [[0.0] * n for _ in range(count)]
    t_det_each: list[float | None] = [None] * count
    t_not_each: list[float | None] = [None] * count
    det_each = [-1] * count
    shadow: dict[tuple[int, int], float] = {}
    z: dict[tuple[int, int], float] = {}  # correlated shadowing's normal state per link
    t_det: float | None = None
    t_not: float | None = None
    detector = -1
    chain: list[tuple[float, float]] = []  # on_detect = relay: the chain's points from the BS
    slot: dict[int, int] = {}  # the point each drone of the chain holds
    reach_time = conn_time = 0.0
    steps = round(mission.timing.horizon / dt)
    coherence = round(mission.coherence / dt)
    positions = []
    checkpoints = set(mission.checkpoint_steps())
    depth: list[int] = []
    farthest: list[float] = []

    battery = mission.battery.battery_wh is not None
    if battery:
        model = get_energy_model(mission.energy_model)
        capacity = mission.battery.battery_wh * 3600.0
        reserve = mission.battery.reserve * capacity
        fly_w, hover_w = model.power(v), model.power(0.0)
        h = mission.channel.altitude
        climb = model.vertical_power(CLIMB_RATE) * h / CLIMB_RATE
        descent = model.vertical_power(-DESCENT_RATE) * h / DESCENT_RATE
        spares = -1 if mission.battery.spares is None else mission.battery.spares
        swap = round(mission.battery.swap_time / dt)
    energy = [capacity - climb if battery else 0.0] * n
    used = [climb if battery else 0.0] * n
    sorties, ground_time = [1] * n, [0.0] * n
    back_as: list[str | None] = [None] * n  # the role a drone takes off in after its swap
    swap_ends: list[int | None] = [None] * n
    rejoin: list[tuple[float, float] | None] = [None] * n  # where it left its route
    home_max = 1.0 + max(_dist(bs, (cx, cy)) for cx in (0.0, a) for cy in (0.0, a))

    # mean-area: a loss margin of sigma² ln10 / 10n dB, so that E[area] = pi rc²
    n_exp, sigma = mission.channel.pathloss_exponent, mission.channel.sigma
    margin = (sigma**2 * math.log(10) / (10 * n_exp)
              if readings.shadow_calibration == "mean-area" else 0.0)

    def node(j: int, where: list[tuple[float, float]]) -> tuple[float, float]:
        return where[j] if j < n else (bs if j == BS else target)

    def link_graph(where: list[tuple[float, float]], faded: bool) -> dict[int, set[int]]:
        links: dict[int, set[int]] = {j: set() for j in range(n + 2)}
        for i in range(n + 2):
            for j in range(i + 1, n + 2):
                p, q = node(i, where), node(j, where)
                h = mission.channel.altitude if (i < n) != (j < n) else 0.0
                if faded and mission.channel.sigma > 0:
                    d = math.hypot(_dist(p, q), h)
                    ok = d == 0 or 10 * mission.channel.pathloss_exponent * math.log10(
                        d / rc) + shadow[(i, j)] + margin <= 0
                else:
                    ok = _within(p, q, rc, h)
                if ok:
                    links[i].add(j)
                    links[j].add(i)
        return links

    def covb(i: int) -> float:
        fx, fy = math.cos(heading[i]) / r, math.sin(heading[i]) / r
        near = [j for j in range(n) if j != i and mode[j] != "landed"
                and _within(pos[i], pos[j], r)]
        if not near:
            return heading[i]
        for j in near:
            d = _dist(pos[i], pos[j])
            if d >= 1:  # pairs closer than 1 m exert no force
                push = -1.0 if readings.covb_direction == "printed" else 1.0  # theta_ij: i to j
                fx += push * (pos[i][0] - pos[j][0]) / d / d
                fy += push * (pos[i][1] - pos[j][1]) / d / d
        return math.atan2(fy, fx)

    def velocity(j: int) -> tuple[float, float]:
        if j >= n or mode[j] == "landed":
            return 0.0, 0.0
        return v * math.cos(heading[j]), v * math.sin(heading[j])

    def conb(i: int, links: dict[int, set[int]], routed_next: set[int]) -> float | None:
        """ConB's direction; None for no term (ConCov, connected, concov_connected = none)."""
        if i in routed_next:
            none = planner == "concov" and readings.concov_connected == "none" and alpha > 0
            return None if none else heading[i]
        neighbours = sorted(j for j in links[i] if j != TG)
        if not neighbours:
            if readings.isolated == "home":
                return math.atan2(bs[1] - pos[i][1], bs[0] - pos[i][0])
            return heading[i]
        candidates = neighbours
        if readings.contacts == "routed":
            candidates = [j for j in neighbours if j in routed_next] or neighbours
        vi = velocity(i)

        def contact(j: int) -> tuple[float, float, float]:
            """(rank, -distance, time the contact ends)."""
            pj = node(j, pos)
            vj = velocity(j)
            px, py = pj[0] - pos[i][0], pj[1] - pos[i][1]
            wx, wy = vj[0] - vi[0], vj[1] - vi[1]
            aa = wx * wx + wy * wy
            if aa < 1e-12:
                return math.inf, -math.hypot(px, py), mission.team.flight_time
            b = 2 * (px * wx + py * wy)
            c = px * px + py * py - rc * rc
            disc = b * b - 4 * aa * c
            tau = 0.0 if disc < 0 else max(0.0, (-b + math.sqrt(disc)) / (2 * aa))
            return tau, -math.hypot(px, py), tau

        j = max(candidates, key=lambda c: contact(c)[:2])
        tau = contact(j)[2]
        pj, vj = node(j, pos), velocity(j)
        cx, cy = pj[0] + vj[0] * tau, pj[1] + vj[1] * tau
        nx, ny = pos[i][0] + v * dt * math.cos(heading[i]), pos[i][1] + v * dt * math.sin(
            heading[i])
        theta_ij = heading[i] if math.hypot(cx - nx, cy - ny) < 1e-12 else math.atan2(cy - ny,
                                                                                      cx - nx)
        rx = math.cos(heading[i]) + math.cos(theta_ij)
        ry = math.sin(heading[i]) + math.sin(theta_ij)
        if math.hypot(rx, ry) < 1e-9:
            if readings.conb_fallback == "limit":  # a right angle, to a side drawn
                return heading[i] + (1 if streams.rule.random() < 0.5 else -1) * math.pi / 2
            return theta_ij if readings.conb_fallback == "contact" else heading[i]
        return math.atan2(ry, rx)

    def predicted(seconds: float) -> set[int]:
        """Who has a route to the BS ``seconds`` ahead if every drone keeps its heading."""
        ahead = [p if mode[j] == "landed" else
                 (p[0] + v * seconds * math.cos(heading[j]),
                  p[1] + v * seconds * math.sin(heading[j])) for j, p in enumerate(pos)]
        return component({BS}, link_graph(ahead, faded=False), blocked=TG)

    def inward(i: int, h: float) -> float:
        """Boundary rule: a uniform heading in the half (quarter) circle facing into the area."""
        walls: set[str] = set()
        while True:
            nxt = (pos[i][0] + v * dt * math.cos(h), pos[i][1] + v * dt * math.sin(h))
            if _inside(nxt, a):
                return h
            walls |= {w for w, out in (("W", nxt[0] < 0), ("E", nxt[0] > a), ("S", nxt[1] < 0),
                                       ("N", nxt[1] > a)) if out}
            arcs = {"W": (-math.pi / 2, math.pi / 2), "E": (math.pi / 2, 3 * math.pi / 2),
                    "S": (0.0, math.pi), "N": (math.pi, 2 * math.pi)}
            corners = {frozenset("WS"): (0.0, math.pi / 2), frozenset("WN"): (-math.pi / 2, 0.0),
                       frozenset("ES"): (math.pi / 2, math.pi),
                       frozenset("EN"): (math.pi, 3 * math.pi / 2)}
            lo, hi = corners[frozenset(walls)] if len(walls) == 2 else arcs[next(iter(walls))]
            h = lo + streams.turn.random() * (hi - lo)

    def length(x: float, y: float) -> float:
        """The length of ``(x, y)``, in the engine's arithmetic (its distances' last bits)."""
        return math.sqrt(x * x + y * y)

    def clamp(p: tuple[float, float]) -> tuple[float, float]:
        """The nearest point of the square area."""
        return min(max(p[0], 0.0), a), min(max(p[1], 0.0), a)

    def reckoned(i: int, k: int) -> tuple[float, float]:
        """Where the BS believes drone ``i`` at step ``k``, by dead reckoning from when it
        last heard it, by what it was doing then: on along its route at V_m if it flew one,
        straight home if it was flying home, where it was heard if it held a point of the
        chain to a found target, else on along the heading it was heard with (into the
        area)."""
        x, y, h, when, w, was = heard[i]
        travel = v * dt * (k - when)
        if travel <= 0 or was == "chaining":  # it holds its point of the chain
            return x, y
        if route[i] and was != "returning":
            for wx, wy in route[i][w:]:
                d = length(wx - x, wy - y)
                if d > travel:
                    return x + travel * (wx - x) / d, y + travel * (wy - y) / d
                x, y, travel = wx, wy, travel - d
            return x, y
        if was == "returning":
            d = length(bs[0] - x, bs[1] - y)
            if d <= travel:
                return bs
            return x + travel * (bs[0] - x) / d, y + travel * (bs[1] - y) / d
        return clamp((x + travel * math.cos(h), y + travel * math.sin(h)))

    def fly_to_aim(i: int, t: float, new: list[float]) -> None:
        """A drone holding a point (a relay, a drone of the chain): home if its budget is
        due, else straight for its aim."""
        home = _dist(pos[i], bs)
        if (mission.team.flight_time - t) - home / v < 2 * dt:
            mode[i] = "returning"
            new[i] = math.atan2(bs[1] - pos[i][1], bs[0] - pos[i][0])
        elif aim[i] != pos[i]:
            new[i] = math.atan2(aim[i][1] - pos[i][1], aim[i][0] - pos[i][0])

    def form_the_chain(t: float, links: dict[int, set[int]]) -> None:
        """``on_detect = relay``: at the detection the detector (searching or relaying) holds
        where it is, leaving its route, and the chain's points are set: the fewest that cut
        the segment from the BS to it into hops of at most r_c, evenly spaced, into the
        area. Every step, in each component of the links, its free drones (they know, are
        not the detector, and search, relay or hold a point of the chain), in index order:
        a chain drone keeps its point unless one before it in the component holds it
        nearer (or as near); the others take the points none of them holds, those nearest
        the BS, as many as there are of them, by the bottleneck assignment; one given a
        point flies to it and stays in the chain, a chain drone given none holds where it
        is, a searcher given none searches on."""
        if t_det == t:
            d = pos[detector]
            if mode[detector] in ("search", "relaying"):
                mode[detector] = "chaining"
                route[detector] = []
                aim[detector] = d
            gap = length(d[0] - bs[0], d[1] - bs[1])
            count = max(0, math.ceil((gap - 1e-9) / rc) - 1)
            chain[:] = [clamp((bs[0] + j / (count + 1) * (d[0] - bs[0]),
                               bs[1] + j / (count + 1) * (d[1] - bs[1])))
                        for j in range(1, count + 1)]

        def free(j: int) -> bool:
            return knows[j] and j != detector and mode[j] in ("search", "relaying", "chaining")

        def xy(where: list[tuple[float, float]]) -> tuple[np.ndarray, np.ndarray]:
            return np.array([w[0] for w in where]), np.array([w[1] for w in where])

        done: set[int] = set()
        for i in range(n):
            if i in done or not free(i):
                continue
            members = sorted(j for j in component({i}, links, blocked=TG) if j < n and free(j))
            done |= set(members)
            holder: dict[int, int] = {}
            waiting = []
            for j in members:
                b = slot.get(j) if mode[j] == "chaining" else None
                if b is None:
                    waiting.append(j)
                elif b not in holder:
                    holder[b] = j
                else:  # two hold one point: the nearer keeps it, the other waits
                    if _dist(pos[j], chain[b]) < _dist(pos[holder[b]], chain[b]):
                        holder[b], j = j, holder[b]
                    del slot[j]
                    waiting.append(j)
            unheld = [b for b in range(len(chain)) if b not in holder][:len(waiting)]
            goal, _ = assign.py_func(*xy([pos[j] for j in waiting]),
                                     *xy([chain[b] for b in unheld]))
            for j, g in zip(waiting, goal.tolist(), strict=True):
                if g >= 0:
                    mode[j] = "chaining"
                    route[j] = []
                    slot[j] = unheld[g]
                    aim[j] = chain[unheld[g]]
                elif mode[j] == "chaining":
                    aim[j] = pos[j]

    def hold_the_link(k: int, t: float, routed: set[int], new: list[float]) -> None:
        """The relays' part of step ``k``'s decisions: the BS hears every drone with a route
        to it (everyone at take-off); every t_s it plans a point for each relay, the tree over
        itself and the searchers (the first N - K drones) not heard landed (those flying home
        too) where it believes them (``team.relay_estimate``: where last heard, or reckoned)
        from where it last heard its relays; a relay it reaches takes its point (into the
        area), one it does not heads back to the BS; a relay whose budget is due turns home,
        the others head straight for their aim."""
        for i in range(n):
            if k == 0 or i in routed:
                heard[i] = (pos[i][0], pos[i][1], heading[i], k, wp_next[i], mode[i])
        if k % round(ts / dt) == 0:
            airborne = [i for i in range(searchers) if heard[i][5] != "landed"]
            holding = [i for i in range(n) if mode[i] == "relaying"]
            where = [bs, *(heard[i][:2] if mission.team.relay_estimate == "heard"
                           else reckoned(i, k) for i in airborne)]
            gx, gy, *_ = plan.py_func(
                np.array([w[0] for w in where]), np.array([w[1] for w in where]), 0, rc,
                np.array([heard[i][0] for i in holding]),
                np.array([heard[i][1] for i in holding]),
                int(PRIORITY_CODES[mission.team.relay_priority]), a, np.empty((0, 4)))
            for j, i in enumerate(holding):
                points[i] = (float(gx[j]), float(gy[j]))
        for i in range(n):
            if mode[i] != "relaying":
                continue
            aim[i] = clamp(points[i]) if i in routed else bs
            fly_to_aim(i, t, new)

    def swaps(k: int, t: float) -> None:
        """Batteries at the start of step ``k``: a drone landed for a swap takes a spare (none
        left: it stays), waits the swap time on the ground and takes off in the role it left
        (unless the flight budget is due: it would only turn home), and so observes the step
        in the air."""
        nonlocal spares
        homing = (mission.team.flight_time - t) - home_max / v < 2 * dt
        for i in range(n):
            if mode[i] != "landed" or back_as[i] is None:
                continue
            if swap_ends[i] is None:
                if spares == 0:
                    back_as[i] = None
                    continue
                spares -= 1 if spares > 0 else 0
                swap_ends[i] = k + swap
            if k < swap_ends[i]:
                ground_time[i] += dt
                continue
            if homing:
                back_as[i] = None
                continue
            mode[i], back_as[i], swap_ends[i] = back_as[i], None, None
            energy[i] = capacity - climb
            used[i] += climb
            sorties[i] += 1
            last_change[i] = t - ts  # a distributed drone decides at once

    def turns(new: list[float]) -> None:
        """Every airborne drone whose energy above the reserve no longer pays for the flight
        home and three steps more, at the larger of its flying and holding power, and the
        descent, turns home, a route drone remembering where it left its route."""
        for i in range(n):
            if mode[i] in ("landed", "returning"):
                continue
            home = _dist(pos[i], bs)
            if energy[i] - reserve > max(fly_w, hover_w) * (home / v + 3 * dt) + descent:
                continue
            back_as[i] = "relaying" if mode[i] == "relaying" else "search"
            if route[i] and rejoin[i] is None:
                rejoin[i] = pos[i]
            mode[i] = "returning"
            if home > 0:
                new[i] = heading[i] = math.atan2(bs[1] - pos[i][1], bs[0] - pos[i][0])

    heard = [(bs[0], bs[1], heading[i], 0, 0, mode[i]) for i in range(n)]
    for k in range(steps + 1):
        t = k * dt
        if battery:
            swaps(k, t)
        # observe
        if mission.channel.sigma > 0 and readings.shadowing == "correlated":
            # Gudmundson: each drone end flies v dt per step; exp(-x / d_c) over x flown
            for i in range(n + 2):
                for j in range(i + 1, n + 2):
                    e = streams.shadow.standard_normal()
                    flown = v * dt * ((i < n) + (j < n))
                    rho = math.exp(-flown / mission.channel.decorrelation)
                    z[(i, j)] = e if k == 0 else rho * z[(i, j)] + math.sqrt(1 - rho**2) * e
                    shadow[(i, j)] = mission.channel.sigma * z[(i, j)]
        elif mission.channel.sigma > 0 and (k == 0 or (readings.shadowing == "period"
                                                       and k % coherence == 0)):
            for i in range(n + 2):
                for j in range(i + 1, n + 2):
                    shadow[(i, j)] = mission.channel.sigma * streams.shadow.standard_normal()
        for j, where in enumerate([target, *others]):  # target by target, drone by drone
            for i in range(n):
                now_in = _within(pos[i], where, r)
                if now_in:
                    look = not in_range[j][i]
                    if look:
                        pass_start[j][i] = t
                    elif mission.sensing.look == "per-period" and \
                            round((t - pass_start[j][i]) / dt) % round(ts / dt) == 0:
                        look = True
                    if look and streams.look.random() >= mission.sensing.p_miss:
                        knows_each[j][i] = True
                        if t_det_each[j] is None:
                            t_det_each[j], det_each[j] = t, i
                in_range[j][i] = now_in
        jd = mission_event(t_det_each, mission.target.success)
        if t_det is None and jd is not None:
            t_det, detector = t_det_each[jd], det_each[jd]
        links = link_graph(pos, faded=True)
        routed = component({BS}, links, blocked=TG)
        for j in range(count):
            informed = component({i for i in range(n) if knows_each[j][i]}, links, blocked=TG)
            for i in informed - {BS}:
                knows_each[j][i] = True
            if t_not_each[j] is None and BS in informed:
                t_not_each[j] = t
        jn = mission_event(t_not_each, mission.target.success)
        if t_not is None and jn is not None:
            t_not = t_not_each[jn]
        if count > 1:  # what the drones know: any target's location
            knows = [any(row[i] for row in knows_each) for i in range(n)]
        if record:
            positions.append(list(pos))
            track.append(target)
            tracks.append([target, *others])
        if k in checkpoints:
            matrix = [[j in links[i] for j in range(n + 2)] for i in range(n + 2)]
            base = [readings.parked == "base" and mo == "landed" for mo in mode]
            hops, far = network(matrix, base, pos, bs)
            depth.append(hops)
            farthest.append(far)
        if k == steps:
            break
        over = {BS} if readings.reachability == "direct" else set()  # else drones only
        flying = {i for i in range(n) if readings.parked == "relay" or mode[i] != "landed"}
        if readings.parked == "base" and readings.reachability == "direct":
            over |= set(range(n))  # a parked drone's link is the BS's own
        if any(j in routed and (j in flying or j in over) for j in links[TG]):
            reach_time += dt
        conn_time += dt * sum(1 for i in flying if i in routed) / n

        # decide
        new = list(heading)
        if mission.team.on_detect == "relay" and t_det is not None:
            form_the_chain(t, links)

        if battery:
            turns(new)

        routed_next: set[int] | None = None
        continuous = rule and alpha < 1 and readings.conb_check == "continuous"
        if continuous:  # routed at every increment up to t + t_s
            routed_next = set.intersection(*(predicted(s * dt) for s in
                                             range(1, round(ts / dt) + 1)))
        for i in range(n):
            if mode[i] != "search" or route[i]:
                continue
            home = _dist(pos[i], bs)
            if (mission.team.flight_time - t) - home / v < 2 * dt:
                mode[i] = "returning"
                if home > 0:
                    new[i] = math.atan2(bs[1] - pos[i][1], bs[0] - pos[i][0])
                continue
            h = heading[i]
            losing = continuous and routed_next is not None and i not in routed_next
            if t - last_change[i] >= ts - 1e-9 or losing:
                last_change[i] = t
                cov = covb(i) if alpha > 0 else h
                con: float | None = h
                if alpha < 1:
                    if routed_next is None:
                        routed_next = predicted(ts)
                    con = conb(i, links, routed_next)
                if alpha == 1:
                    h = cov
                elif alpha == 0:
                    h = h if con is None else con
                elif con is None:
                    h = cov
                else:
                    rx = alpha * math.cos(cov) + (1 - alpha) * math.cos(con)
                    ry = alpha * math.sin(cov) + (1 - alpha) * math.sin(con)
                    if math.hypot(rx, ry) >= 1e-12:
                        h = math.atan2(ry, rx)
                    elif readings.concov_fallback == "connectivity":
                        h = con
                turn = math.remainder(h - heading[i], 2 * math.pi)
                if readings.turns == "jitter" and abs(turn) > 1e-9:  # flown off by <= 5 degrees
                    h += math.radians(5.0) * (2 * streams.heading.random() - 1)
            h2 = inward(i, h)
            if h2 != h:
                last_change[i] = t
            new[i] = h2
        if searchers < n:
            hold_the_link(k, t, routed, new)
        for i in range(n):
            if mode[i] == "chaining":
                fly_to_aim(i, t, new)
        heading = new

        # move
        before = [None if mode[i] == "landed" else pos[i] for i in range(n)]
        for i in range(n):
            if mode[i] == "landed":
                continue
            if mode[i] == "returning":
                if _dist(pos[i], bs) <= v * dt:
                    pos[i] = bs
                    mode[i] = "landed"
                else:
                    pos[i] = (pos[i][0] + v * dt * math.cos(heading[i]),
                              pos[i][1] + v * dt * math.sin(heading[i]))
                continue
            if mode[i] in ("relaying", "chaining"):
                dx, dy = aim[i][0] - pos[i][0], aim[i][1] - pos[i][1]
                step = v * dt
                pos[i] = aim[i] if dx * dx + dy * dy <= step * step else (
                    pos[i][0] + step * (dx / length(dx, dy)),
                    pos[i][1] + step * (dy / length(dx, dy)))
                continue
            if route[i]:  # on along the waypoints, landing after the last
                travel = v * dt
                if rejoin[i] is not None:  # back to where it left them first
                    w = rejoin[i]
                    d = length(w[0] - pos[i][0], w[1] - pos[i][1])
                    if d > travel:
                        pos[i] = (pos[i][0] + travel * (w[0] - pos[i][0]) / d,
                                  pos[i][1] + travel * (w[1] - pos[i][1]) / d)
                        continue
                    pos[i], travel, rejoin[i] = w, travel - d, None
                while travel > 0 and mode[i] != "landed":
                    w = route[i][wp_next[i]]
                    d = length(w[0] - pos[i][0], w[1] - pos[i][1])
                    heading[i] = math.atan2(w[1] - pos[i][1], w[0] - pos[i][0])
                    if d > travel:
                        pos[i] = (pos[i][0] + travel * (w[0] - pos[i][0]) / d,
                                  pos[i][1] + travel * (w[1] - pos[i][1]) / d)
                        break
                    pos[i], travel = w, travel - d
                    wp_next[i] += 1
                    if wp_next[i] == len(route[i]):
                        mode[i] = "landed"
                continue
            pos[i] = (pos[i][0] + v * dt * math.cos(heading[i]),
                      pos[i][1] + v * dt * math.sin(heading[i]))
        if battery:  # the step's energy: flying, or holding where it was
            for i in range(n):
                if before[i] is not None:
                    flying = min(_dist(pos[i], before[i]) / v, dt)  # the rest of the step held
                    drawn = fly_w * flying + hover_w * (dt - flying)
                    drawn += descent if mode[i] == "landed" else 0.0
                    energy[i] -= drawn
                    used[i] += drawn
        if mover is not None and ends_a_move(delay + k):  # it moves last, the others after it
            since = (delay + k + 1 - every) * dt
            target = mover.move(target, since, every * dt)
            others = [m.move(o, since, every * dt) for m, o in zip(movers, others, strict=True)]

    immediate = t_not is not None and t_not == t_det
    several = count > 1
    return NaiveResult(t_det, t_not, immediate, reach_time, conn_time, positions, depth,
                       farthest, *((sorties, ground_time, used) if battery else (None,) * 3),
                       target_track=track if mover else None, detector=detector,
                       t_detect_each=t_det_each if several else None,
                       t_notify_each=t_not_each if several else None,
                       detector_each=det_each if several else None,
                       targets=seen if several else None,
                       tracks=tracks if mover and several else None)


@dataclass
class NaiveRelayPlan:
    needs: dict[int, int]
    """The relays each tree edge needs, by the edge's far terminal (from the root)."""
    connected: set[int]
    """The terminals the plan holds to the root (the root too)."""
    spent: int
    """Relays the plan stands on tree edges."""
    longest_hop: float
    """The longest hop on the tree with the plan's relays on it."""


def relay_plan(terminals: list[tuple[float, float]], rc: float, relays: int,
               priority: str) -> NaiveRelayPlan:
    """Where relays go (docs/model.md, Relays), plainly: Kruskal's minimum spanning tree over
    the terminals (the root first), hung from the root by a breadth-first search; each edge
    needs the fewest relays that cut it into hops of at most ``rc`` (1e-9 m of slack); with
    fewer relays than all edges need, "nearest-first" walks the searchers by the relays on
    their path (then distance to the root, then index) and builds each whole path that still
    fits, "most-connected" tries every set of searchers to build paths to and keeps the one
    that holds the most terminals for the fewest relays, "k-bottleneck" finds the shortest
    longest hop the relays can give the tree by trying each hop length the edges can have."""
    n = len(terminals)
    pairs = sorted((_dist(terminals[a], terminals[b]), a, b)
                   for a in range(n) for b in range(a + 1, n))
    group = list(range(n))

    def find(a: int) -> int:
        while group[a] != a:
            a = group[a]
        return a

    near: dict[int, set[int]] = {a: set() for a in range(n)}
    for _, a, b in pairs:
        if find(a) != find(b):
            group[find(a)] = find(b)
            near[a].add(b)
            near[b].add(a)
    parent = {0: -1}
    queue = deque([0])
    while queue:
        a = queue.popleft()
        for b in near[a]:
            if b not in parent:
                parent[b] = a
                queue.append(b)
    length = {v: _dist(terminals[v], terminals[parent[v]]) for v in range(1, n)}

    def hops_within(v: int, limit: float) -> int:
        """The fewest relays on edge v for hops of at most ``limit``."""
        k = 0
        while length[v] / (k + 1) > limit:
            k += 1
        return k

    needs = {v: hops_within(v, rc + 1e-9) for v in range(1, n)}

    def path(v: int) -> list[int]:
        out = []
        while v != 0:
            out.append(v)
            v = parent[v]
        return out

    def held(built: set[int]) -> set[int]:
        return {v for v in range(n) if all(e in built or needs[e] == 0 for e in path(v))}

    def cost(built: set[int]) -> int:
        return sum(needs[e] for e in built)

    if relays >= sum(needs.values()):
        built = set(needs)
    elif priority == "nearest-first":
        built = set()
        order = sorted(range(1, n), key=lambda v: (sum(needs[e] for e in path(v)),
                                                   _dist(terminals[v], terminals[0]), v))
        for v in order:
            more = set(path(v)) - built
            if cost(built) + cost(more) <= relays:
                built |= more
    elif priority == "most-connected":
        built = set()
        for mask in range(1 << (n - 1)):
            trial = {e for v in range(1, n) if mask >> (v - 1) & 1 for e in path(v)}
            if cost(trial) <= relays and (len(held(trial)), -cost(trial)) > (
                    len(held(built)), -cost(built)):
                built = trial
    else:  # k-bottleneck: report the best longest hop; the edges hold what their relays allow
        limits = sorted({length[v] / (k + 1) for v in length for k in range(relays + 1)})
        best = next(t for t in limits if sum(hops_within(v, t) for v in length) <= relays)
        alloc = {v: hops_within(v, best) for v in length}
        return NaiveRelayPlan(needs, {v for v in range(n) if all(
            alloc[e] >= needs[e] for e in path(v))}, sum(alloc.values()),
            max((length[v] / (alloc[v] + 1) for v in length), default=0.0))
    return NaiveRelayPlan(needs, held(built), cost(built), max(
        (length[v] / ((needs[v] if v in built else 0) + 1) for v in length), default=0.0))
