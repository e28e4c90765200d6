"""The rules phase (sarlink.planners.rules) called directly: CovB's force against Eq. 6 written in
angles, ConB's prediction against a breadth-first search on extrapolated positions, ConB's
direction against Eqs. 9-11 (contact times from the quadratic's roots), ConCov's blend
against Eq. 12, each also on hand-computed cases (docs/model.md, Planners and Readings).

Node indices: drones ``0 .. n-1``, the BS ``n``, the target ``n + 1``; headings are angles
here and unit vectors ``(hx, hy)`` in the engine.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from phase_inputs import BS, component, members, node_arrays, pack, padded, params, words
from sarlink.engine.codes import ConbFallback, Prediction
from sarlink.engine.geometry import FAR
from sarlink.engine.graph import bs_component, links
from sarlink.engine.observation import Observation
from sarlink.engine.params import LANDED, RETURNING, SEARCHING, Params
from sarlink.planners.rules import conb, concov, covb
from sarlink.planners.rules.conb import check_continuously, conb_headings, predict_routes
from sarlink.planners.rules.concov import blend
from sarlink.planners.rules.covb import covb_force, flying_drones

ANGLE = st.floats(-math.pi, math.pi)
P = params()  # V = 5 m/s, dt = 1 s, r = 500 m, T_max = 4000 s, BS at (2000, 2000)


@st.composite
def teams(draw: st.DrawFn, most: int = 8, spread: float = 1500.0) -> tuple[
        list[tuple[float, float]], list[float], list[int]]:
    """Drone positions around the BS, headings and modes; the BS and a target appended."""
    n = draw(st.integers(1, most))
    coordinate = st.floats(-spread, spread)
    xy = [(BS[0] + draw(coordinate), BS[1] + draw(coordinate)) for _ in range(n)]
    angles = [draw(ANGLE) for _ in range(n)]
    modes = [draw(st.sampled_from([SEARCHING, SEARCHING, RETURNING, LANDED])) for _ in range(n)]
    target = (BS[0] + draw(coordinate), BS[1] + draw(coordinate))
    return [*xy, BS, target], angles, modes


def _headings(angles: list[float]) -> tuple[np.ndarray, np.ndarray]:
    return np.cos(angles), np.sin(angles)


def _same_direction(got: tuple[float, float], want: tuple[float, float]) -> bool:
    return got == pytest.approx(want, abs=1e-9)


# -- CovB (Eqs. 6-8) --------------------------------------------------------------------------


def _eq6(i: int, xy: list[tuple[float, float]], angle: float, pushers: list[int],
         r: float) -> tuple[float, float]:
    """Eq. 6 in angles: ``θ̂_c / r`` plus ``(1/d) û`` from each pusher closer than r but at
    least 1 m away, ``û`` pointing from the pusher to drone ``i``."""
    rx, ry = math.cos(angle) / r, math.sin(angle) / r
    for j in pushers:
        d = math.dist(xy[i], xy[j])
        if d >= 1.0:
            phi = math.atan2(xy[i][1] - xy[j][1], xy[i][0] - xy[j][0])
            rx, ry = rx + math.cos(phi) / d, ry + math.sin(phi) / d
    return rx, ry


@given(team=teams(spread=400.0), who=st.integers(0, 7))
def test_covb_force_is_eq_6(team: tuple[list[tuple[float, float]], list[float], list[int]],
                            who: int) -> None:
    """The direction of Eq. 6's resultant over the flying drones within r (landed drones are
    in range but push nothing); no pusher in range: exactly the heading."""
    xy, angles, modes = team
    n = len(angles)
    i = who % n
    r = P.r
    near_sets = [{j for j in range(n + 2) if j != a and math.dist(xy[a], xy[j]) ** 2 <= r * r}
                 for a in range(n + 2)]  # the BS and the target are in range too
    near = pack(near_sets, words(n + 2))
    flying = np.zeros(words(n + 2), dtype=np.uint64)
    flying_drones(np.array(modes, dtype=np.int8), flying)
    assert members(flying) == {j for j in range(n) if modes[j] != LANDED}
    px, py, _ = node_arrays(xy, n)
    hx, hy = _headings(angles)
    got = covb_force(i, px, py, hx, hy, near, flying, r, False)
    pushers = sorted(j for j in near_sets[i] if j < n and modes[j] != LANDED)
    if not pushers:
        assert got == (hx[i], hy[i])
        return
    rx, ry = _eq6(i, xy, angles[i], pushers, r)
    size = math.hypot(rx, ry)
    assume(not 1e-12 < size < 1e-7)  # a nearly vanishing resultant has no stable direction
    want = (hx[i], hy[i]) if size <= 1e-12 else (rx / size, ry / size)
    assert _same_direction(got, want)


def test_covb_force_on_hand_computed_cases() -> None:
    """Drone 0 flies north with drone 1 100 m east of it: R = (0, 1/500) + (-1/100, 0).
    Drone 2 flies east with drone 3 exactly r ahead: 1/r - 1/r = 0, it keeps its heading;
    drone 4 has drone 5 half a metre away (no force) and a landed drone 6 (no push)."""
    xy = [(1000.0, 1000.0), (1100.0, 1000.0), (3000.0, 1000.0), (3500.0, 1000.0),
          (1000.0, 3000.0), (1000.5, 3000.0), (1200.0, 3000.0), BS, BS]
    n = 7
    angles = [math.pi / 2, 0.0, 0.0, 0.0, 0.3, 0.0, 0.0]
    px, py, _ = node_arrays(xy, n)
    hx, hy = _headings(angles)
    near = pack([{1}, {0}, {3}, {2}, {5, 6}, {4, 6}, {4, 5}, set(), set()], 1)
    flying = np.zeros(1, dtype=np.uint64)
    flying_drones(np.array([SEARCHING] * 6 + [LANDED], dtype=np.int8), flying)
    size = math.hypot(-0.01, 0.002)
    assert _same_direction(covb_force(0, px, py, hx, hy, near, flying, 500.0, False),
                           (-0.01 / size, 0.002 / size))
    assert covb_force(2, px, py, hx, hy, near, flying, 500.0, False) == (1.0, 0.0)
    assert _same_direction(covb_force(4, px, py, hx, hy, near, flying, 500.0, False),
                           (math.cos(0.3), math.sin(0.3)))


# -- ConB's prediction (Algorithm 1) ----------------------------------------------------------


def _predicted(xy: list[tuple[float, float]], hx: np.ndarray, hy: np.ndarray,
               modes: list[int], p: Params, steps: int, altitude: float) -> set[int]:
    """Who reaches the BS ``steps`` increments ahead: flying drones extrapolated along their
    headings, links within r_c (slant for drone-ground pairs), searched breadth first."""
    n = len(modes)
    ahead = p.speed * steps * p.dt
    q = [(x + ahead * hx[j], y + ahead * hy[j]) if j < n and modes[j] != LANDED else (x, y)
         for j, (x, y) in enumerate(xy)]
    h = [altitude if j < n else 0.0 for j in range(n + 2)]
    neighbours = [{b for b in range(n + 2) if b != a and (q[a][0] - q[b][0]) ** 2
                   + (q[a][1] - q[b][1]) ** 2 + (h[a] - h[b]) ** 2 <= p.rc * p.rc}
                  for a in range(n + 2)]
    return component({n}, neighbours, blocked=n + 1)


def _no_routes(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Waypoints, next and end indices of a team without routes."""
    return np.empty((0, 2)), np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.int64)


def _conb_arrays(n: int, rc: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray,
                                             np.ndarray]:
    """ConB's workspace: predicted positions, nominal ranges, a bitset and the bitset of
    expanded nodes."""
    m, mp = n + 2, padded(n + 2)
    disc2 = np.zeros((m, mp))
    disc2[:, :m] = rc * rc
    return (np.full(mp, FAR), np.full(mp, FAR), disc2, np.zeros(words(m), dtype=np.uint64),
            np.zeros(words(m), dtype=np.uint64))


def _seen(px: np.ndarray, py: np.ndarray, pz: np.ndarray, hx: np.ndarray, hy: np.ndarray,
          mode: np.ndarray, on_route: np.ndarray, last_change: np.ndarray,
          rc: float) -> Observation:
    """What ConB's check reads of a team without routes (links, pairs and bitsets unread)."""
    n, m = hx.shape[0], hx.shape[0] + 2
    bits = np.zeros((m, words(m)), dtype=np.uint64)
    return Observation(px, py, pz, hx, hy, mode, on_route, last_change,
                       np.zeros(n, dtype=np.bool_), bits, bits, bits[0], bits[0], rc,
                       *_no_routes(n), np.random.default_rng(0), np.zeros(1, dtype=np.int64))


@given(team=teams(), steps=st.integers(1, 40), rc=st.floats(200.0, 1500.0),
       altitude=st.sampled_from([0.0, 120.0]))
def test_predict_routes_is_a_search_on_extrapolated_positions(
        team: tuple[list[tuple[float, float]], list[float], list[int]], steps: int, rc: float,
        altitude: float) -> None:
    xy, angles, modes = team
    n = len(angles)
    p = params(rc=rc)
    px, py, pz = node_arrays(xy, n, altitude)
    hx, hy = _headings(angles)
    qx, qy, disc2, out, expanded = _conb_arrays(n, rc)
    count = predict_routes(px, py, hx, hy, np.array(modes, dtype=np.int8), pz, p, steps, qx,
                           qy, disc2, out, expanded, np.zeros(n, np.bool_), *_no_routes(n),
                           pack([range(n + 2)], words(n + 2))[0])
    routed = _predicted(xy, hx, hy, modes, p, steps, altitude)
    assert members(out) == routed
    # the work counted (Fig. 1) is the nodes expanded: every routed node when some node is
    # cut off (the search cannot stop early), at most every routed node otherwise
    assert count == len(members(expanded) - {n + 1})
    assert count == len(routed) if len(routed) < n + 1 else 1 <= count <= len(routed)


def test_the_search_counts_the_nodes_it_expands_by_hand() -> None:
    """Three parked drones (predicted where they are) east of the BS, r_c = 500 m: 0 at 400 m,
    1 at 800 m, 2 at 1200 m. The search from the BS expands the BS, 0 and 1 and then holds
    every node: 3 expansions, 2's links never computed. With 2 out of reach at 2000 m it
    expands the same three and runs out of nodes: 3 again. A goal the BS alone already
    covers needs none."""
    n, bs = 3, (2000.0, 2000.0)
    modes = np.full(n, LANDED, dtype=np.int8)
    p = params(rc=500.0)
    hx, hy = _headings([0.0] * n)
    for far, routed in ((1200.0, {0, 1, 2, n}), (2000.0, {0, 1, n})):
        xy = [(bs[0] + 400.0, bs[1]), (bs[0] + 800.0, bs[1]), (bs[0] + far, bs[1]), bs,
              (100.0, 100.0)]
        px, py, pz = node_arrays(xy, n)
        for goal, count in ((range(n + 2), 3), ({n}, 0)):
            qx, qy, disc2, out, expanded = _conb_arrays(n, p.rc)
            assert predict_routes(px, py, hx, hy, modes, pz, p, 2, qx, qy, disc2, out,
                                  expanded, np.zeros(n, np.bool_), *_no_routes(n),
                                  pack([goal], words(n + 2))[0]) == count
            if count:
                assert members(out) == routed


@given(team=teams(most=70), steps=st.integers(1, 40), rc=st.floats(200.0, 1500.0),
       goal=st.sets(st.integers(0, 71)))
def test_a_search_towards_a_goal_finds_the_goal_s_routed_nodes(
        team: tuple[list[tuple[float, float]], list[float], list[int]], steps: int, rc: float,
        goal: set[int]) -> None:
    """Stopping once every node of the goal is reached: the goal's routed nodes are exactly
    those of the whole search, and every node found is routed (teams of up to 70 drones:
    the search crosses the bitsets' word boundary)."""
    xy, angles, modes = team
    n = len(angles)
    goal = {a for a in goal if a < n + 2}
    p = params(rc=rc)
    px, py, pz = node_arrays(xy, n)
    hx, hy = _headings(angles)
    qx, qy, disc2, out, expanded = _conb_arrays(n, rc)
    predict_routes(px, py, hx, hy, np.array(modes, dtype=np.int8), pz, p, steps, qx, qy, disc2,
                   out, expanded, np.zeros(n, np.bool_), *_no_routes(n),
                   pack([goal], words(n + 2))[0])
    routed = _predicted(xy, hx, hy, modes, p, steps, 0.0)
    assert members(out) & goal == routed & goal
    assert members(out) <= routed


@given(team=teams(), ts=st.integers(1, 30), rc=st.floats(200.0, 1500.0),
       on_route=st.lists(st.booleans(), min_size=8, max_size=8),
       deciding=st.lists(st.booleans(), min_size=8, max_size=8))
def test_the_continuous_check_decides_for_a_loss_at_any_increment(
        team: tuple[list[tuple[float, float]], list[float], list[int]], ts: int, rc: float,
        on_route: list[bool], deciding: list[bool]) -> None:
    """Section 3.2's check: a searching distributed drone not routed at every increment up to
    t + t_s decides now (its clock restarts); the others keep their state. Every node is
    predicted by its heading (``mtsp_prediction = heading``: the drones marked as on a route
    have none here)."""
    xy, angles, modes = team
    n = len(angles)
    p = params(rc=rc, ts_steps=ts, mtsp_prediction=int(Prediction.HEADING))
    px, py, pz = node_arrays(xy, n)
    hx, hy = _headings(angles)
    qx, qy, disc2, routed_next, expanded = _conb_arrays(n, rc)
    routed_step = routed_next.copy()
    decide = np.array(deciding[:n])
    last_change = np.full(n, 3, dtype=np.int64)
    k = 7
    any_deciding = check_continuously(
        k, p, _seen(px, py, pz, hx, hy, np.array(modes, dtype=np.int8), np.array(on_route[:n]),
                    last_change, rc),
        conb.Workspace(qx, qy, disc2, routed_next, routed_step, expanded), decide, True)
    always = set.intersection(*(_predicted(xy, hx, hy, modes, p, s, 0.0)
                                for s in range(1, ts + 1)))
    assert members(routed_next) == always
    turned = {i for i in range(n) if not deciding[i] and not on_route[i]
              and modes[i] == SEARCHING and i not in always}
    assert set(np.flatnonzero(decide).tolist()) == turned | {i for i in range(n) if deciding[i]}
    assert last_change.tolist() == [k if i in turned else 3 for i in range(n)]
    assert any_deciding == bool(decide.any())


def test_the_continuous_check_sees_a_loss_at_the_last_increment() -> None:
    """Drone 0 flies east 981 m east of the BS, drone 1 north 975 m north of it (r_c =
    1000 m, t_s = 4 steps of 5 m): drone 0 is out of range only at the fourth increment
    (1001 m) and decides now; drone 1 is still in range there (995 m) and does not."""
    xy = [(2981.0, 2000.0), (2000.0, 2975.0), BS, (100.0, 100.0)]
    p = params(rc=1000.0, ts_steps=4)
    px, py, pz = node_arrays(xy, 2)
    qx, qy, disc2, routed_next, expanded = _conb_arrays(2, 1000.0)
    deciding, last_change = np.zeros(2, dtype=np.bool_), np.zeros(2, dtype=np.int64)
    obs = _seen(px, py, pz, np.array([1.0, 0.0]), np.array([0.0, 1.0]),
                np.array([SEARCHING] * 2, dtype=np.int8), np.zeros(2, np.bool_), last_change,
                1000.0)
    ws = conb.Workspace(qx, qy, disc2, routed_next, routed_next.copy(), expanded)
    assert check_continuously(9, p, obs, ws, deciding, True)
    assert deciding.tolist() == [True, False]
    assert last_change.tolist() == [9, 0]
    assert members(routed_next) == {1, 2}



@given(team=teams(), deciding=st.lists(st.booleans(), min_size=8, max_size=8))
def test_the_check_when_off_adds_no_drone(
        team: tuple[list[tuple[float, float]], list[float], list[int]],
        deciding: list[bool]) -> None:
    """Off (a periodic check, or ConCov at α = 1) there are no increments: every node counts
    as routed, no drone is added, no clock restarts, and the answer is whether any drone was
    already deciding."""
    xy, angles, modes = team
    n = len(angles)
    px, py, pz = node_arrays(xy, n)
    hx, hy = _headings(angles)
    qx, qy, disc2, routed_next, expanded = _conb_arrays(n, 1000.0)
    decide, last_change = np.array(deciding[:n]), np.full(n, 3, dtype=np.int64)
    obs = _seen(px, py, pz, hx, hy, np.array(modes, dtype=np.int8), np.zeros(n, np.bool_),
                last_change, 1000.0)
    ws = conb.Workspace(qx, qy, disc2, routed_next, routed_next.copy(), expanded)
    assert check_continuously(7, P, obs, ws, decide, False) == any(deciding[:n])
    assert decide.tolist() == deciding[:n]
    assert last_change.tolist() == [3] * n
    assert members(routed_next) == set(range(n + 2))

# -- ConB's direction (Eqs. 9-11) -------------------------------------------------------------


def _contact_time(rel: tuple[float, float], w: tuple[float, float], rc: float) -> float:
    """When ``|rel + w τ|`` reaches r_c, from the roots of the quadratic (``inf``: equal
    velocities, the contact never ends)."""
    a = w[0] ** 2 + w[1] ** 2
    if a < 1e-12:
        return math.inf
    roots = np.roots([a, 2.0 * (rel[0] * w[0] + rel[1] * w[1]),
                      rel[0] ** 2 + rel[1] ** 2 - rc * rc])
    real = roots[np.abs(roots.imag) <= 1e-9 * np.abs(roots).max()].real
    return max(0.0, float(real.max())) if real.size else 0.0


def _eq9(i: int, j: int, tau: float, xy: list[tuple[float, float]], angles: list[float],
         velocity: list[tuple[float, float]], p: Params) -> tuple[float, float] | None:
    """Eq. 9: ``θ̂_c + θ̂_ij``, θ_ij from ``i``'s next position to where ``j`` is when the
    contact ends (at T_max if never); its angle, or θ_ij if the two cancel (``None``: they
    nearly cancel, and the angle of what is left is rounding)."""
    end = p.flight_time if math.isinf(tau) else tau
    cx, cy = xy[j][0] + velocity[j][0] * end, xy[j][1] + velocity[j][1] * end
    step = p.speed * p.dt
    nx, ny = xy[i][0] + step * math.cos(angles[i]), xy[i][1] + step * math.sin(angles[i])
    theta_ij = math.atan2(cy - ny, cx - nx)
    rx, ry = math.cos(angles[i]) + math.cos(theta_ij), math.sin(angles[i]) + math.sin(theta_ij)
    if math.hypot(rx, ry) < 1e-10:
        return math.cos(theta_ij), math.sin(theta_ij)
    if math.hypot(rx, ry) < 1e-6:
        return None
    theta = math.atan2(ry, rx)
    return math.cos(theta), math.sin(theta)


def _conb_directions(xy: list[tuple[float, float]], angles: list[float], modes: list[int],
                     neighbours: list[set[int]], routed_next: set[int], p: Params,
                     no_term: bool) -> list[list[tuple[float, float] | None]]:
    """Every drone's acceptable directions under Eqs. 9-11: one, or one per neighbour whose
    contact is as long as the longest to within rounding (the engine may pick either)."""
    n = len(angles)
    velocity = [(p.speed * math.cos(a), p.speed * math.sin(a)) if modes[j] != LANDED
                else (0.0, 0.0) for j, a in enumerate(angles)] + [(0.0, 0.0)]  # the BS
    out = []
    for i in range(n):
        heading = (math.cos(angles[i]), math.sin(angles[i]))
        if i in routed_next:
            out.append([(0.0, 0.0) if no_term else heading])
            continue
        around = sorted(j for j in neighbours[i] if j <= n)  # the target is not a contact
        if not around:
            d = math.dist(xy[i], BS)
            home = ((BS[0] - xy[i][0]) / d, (BS[1] - xy[i][1]) / d)
            out.append([home if p.isolated else heading])
            continue
        candidates = [j for j in around if j in routed_next] if p.contacts == 0 else []
        candidates = candidates or around
        vi = (p.speed * heading[0], p.speed * heading[1])  # a deciding drone flies
        taus = {j: _contact_time((xy[j][0] - xy[i][0], xy[j][1] - xy[i][1]),
                                 (velocity[j][0] - vi[0], velocity[j][1] - vi[1]), p.rc)
                for j in candidates}
        longest = max(taus.values())
        if math.isinf(longest):  # never-ending contacts: the nearest
            ends = [j for j in candidates if math.isinf(taus[j])]
            nearest = min(math.dist(xy[i], xy[j]) for j in ends)
            best = [j for j in ends if math.dist(xy[i], xy[j]) <= nearest + 1e-9]
        else:
            best = [j for j in candidates if taus[j] >= longest - 1e-6 * max(1.0, longest)]
        out.append([_eq9(i, j, taus[j], xy, angles, velocity, p) for j in best])
    return out


@given(team=teams(most=6, spread=1200.0), routed=st.lists(st.booleans(), min_size=7,
                                                           max_size=7),
       contacts=st.integers(0, 1), isolated=st.integers(0, 1), no_term=st.booleans(),
       rc=st.floats(300.0, 1500.0))
def test_conb_headings_are_eqs_9_to_11(
        team: tuple[list[tuple[float, float]], list[float], list[int]], routed: list[bool],
        contacts: int, isolated: int, no_term: bool, rc: float) -> None:
    """Every deciding drone: its heading if predicted to stay routed (none with ``no_term``);
    else towards the end of its longest contact among its neighbours (routed ones first with
    ``contacts = routed``), the BS and landed drones standing still; with no neighbour, its
    heading or (``isolated = home``) the BS."""
    xy, angles, modes = team
    n = len(angles)
    # a vanishing Eq. 9 turns to θ_ij (conb_fallback = contact): one direction to check
    p = params(rc=rc, contacts=contacts, isolated=isolated,
               conb_fallback=int(ConbFallback.CONTACT))
    neighbours = [{b for b in range(n + 2) if b != a and math.dist(xy[a], xy[b]) <= rc}
                  for a in range(n + 2)]
    routed_next = {j for j in range(n + 1) if routed[j]}
    want = _conb_directions(xy, angles, modes, neighbours, routed_next, p, no_term)
    px, py, _ = node_arrays(xy, n)
    hx, hy = _headings(angles)
    vx, vy = np.full(n, 9.0), np.full(n, 9.0)
    deciding = np.ones(n, dtype=np.bool_)
    conb_headings(deciding, px, py, hx, hy, np.array(modes, dtype=np.int8),
                  pack(neighbours, words(n + 2)), pack([routed_next], words(n + 2))[0], p, rc,
                  no_term, vx, vy, np.random.default_rng(0))
    for i in range(n):
        if None not in want[i]:
            assert any(_same_direction((vx[i], vy[i]), w) for w in want[i]), (i, want[i])


def _one_decision(xy: list[tuple[float, float]], angles: list[float], modes: list[int],
                  routed_next: set[int], p: Params, no_term: bool = False,
                  deciding: tuple[bool, ...] | None = None) -> list[tuple[float, float]]:
    """``conb_headings`` for hand-placed drones, with links within r_c, a vanishing Eq. 9
    turning to θ_ij (``conb_fallback = contact``: one direction, worked out by hand)."""
    p = p._replace(conb_fallback=int(ConbFallback.CONTACT))
    n = len(angles)
    neighbours = [{b for b in range(n + 2) if b != a and math.dist(xy[a], xy[b]) <= p.rc}
                  for a in range(n + 2)]
    px, py, _ = node_arrays(xy, n)
    hx, hy = _headings(angles)
    vx, vy = np.full(n, 9.0), np.full(n, 9.0)
    who = np.array(deciding if deciding is not None else [True] * n)
    conb_headings(who, px, py, hx, hy, np.array(modes, dtype=np.int8),
                  pack(neighbours, words(n + 2)), pack([routed_next], words(n + 2))[0], p,
                  p.rc, no_term, vx, vy, np.random.default_rng(0))
    return list(zip(vx.tolist(), vy.tolist(), strict=True))


FAR_TARGET = (100.0, 100.0)


def test_conb_follows_the_longest_contact_computed_by_hand() -> None:
    """Drone 0, 500 m east of the BS, flies east (r_c = 1000 m). The BS (standing) stays in
    contact while |-500 - 5τ| <= 1000: τ = 100 s. Drone 1, at (+100, +300) from drone 0 and
    flying north, has relative velocity (-5, 5): 50τ² + 2000τ - 900000 = 0, τ = 115.65 s, the
    longer: drone 0 steers between its heading and where drone 1 will be then. Among routed
    contacts only (the BS), the BS's end point lies straight behind its next position: the
    terms cancel and it turns to θ_ij, due west."""
    p = params(rc=1000.0, contacts=0)
    xy = [(2500.0, 2000.0), (2600.0, 2300.0), BS, FAR_TARGET]
    angles, modes = [0.0, math.pi / 2], [SEARCHING, SEARCHING]
    tau = (-40.0 + math.sqrt(40.0**2 + 4 * 18000.0)) / 2.0
    cx, cy = 2600.0, 2300.0 + 5.0 * tau
    ux, uy = cx - 2505.0, cy - 2000.0
    ux, uy = ux / math.hypot(ux, uy), uy / math.hypot(ux, uy)
    rx, ry = 1.0 + ux, uy
    towards_1 = (rx / math.hypot(rx, ry), ry / math.hypot(rx, ry))
    got = _one_decision(xy, angles, modes, {1, 2}, p, deciding=(True, False))
    assert _same_direction(got[0], towards_1)
    assert got[1] == (9.0, 9.0)  # not deciding: untouched
    assert _same_direction(_one_decision(xy, angles, modes, {2}, p)[0], (-1.0, 0.0))
    # landed, drone 1 stands still: |(100 - 5τ, 300)| = 1000 gives τ = 210.8 s, still the
    # longest, and the contact ends where drone 1 sits
    ux, uy = 2600.0 - 2505.0, 2300.0 - 2000.0
    ux, uy = ux / math.hypot(ux, uy), uy / math.hypot(ux, uy)
    rx, ry = 1.0 + ux, uy
    got = _one_decision(xy, angles, [SEARCHING, LANDED], {1, 2}, p)
    assert _same_direction(got[0], (rx / math.hypot(rx, ry), ry / math.hypot(rx, ry)))


def test_conb_never_ending_contacts_rank_first_and_the_nearer_wins() -> None:
    """Drones 1 and 2 fly with drone 0 (equal velocities, 300 and 600 m north of it): their
    contacts never end, outrank the BS's, and the nearer, drone 1, is followed to where it
    is at T_max."""
    p = params(rc=1000.0, contacts=1)
    xy = [(2500.0, 2000.0), (2500.0, 2300.0), (2500.0, 2600.0), BS, FAR_TARGET]
    angles = [0.0, 0.0, 0.0]
    got = _one_decision(xy, angles, [SEARCHING] * 3, set(), p, deciding=(True, False, False))
    ux, uy = 2500.0 + 5.0 * 4000.0 - 2505.0, 300.0
    ux, uy = ux / math.hypot(ux, uy), uy / math.hypot(ux, uy)
    rx, ry = 1.0 + ux, uy
    assert _same_direction(got[0], (rx / math.hypot(rx, ry), ry / math.hypot(rx, ry)))


def test_conb_keeps_a_routed_heading_and_an_isolated_drone_keeps_or_goes_home() -> None:
    xy = [(2100.0, 2000.0), (3500.0, 3000.0), BS, FAR_TARGET]
    angles, modes = [1.0, 2.0], [SEARCHING, SEARCHING]
    keep = _one_decision(xy, angles, modes, {0, 2}, params(rc=500.0, isolated=0))
    assert _same_direction(keep[0], (math.cos(1.0), math.sin(1.0)))
    assert _same_direction(keep[1], (math.cos(2.0), math.sin(2.0)))
    home = _one_decision(xy, angles, modes, {0, 2}, params(rc=500.0, isolated=1), no_term=True)
    d = math.hypot(1500.0, 1000.0)
    assert home[0] == (0.0, 0.0)
    assert _same_direction(home[1], (-1500.0 / d, -1000.0 / d))


# -- ConCov (Eq. 12) --------------------------------------------------------------------------


@given(alpha=st.floats(0.0, 1.0, exclude_min=True, exclude_max=True), c=ANGLE, v=ANGLE,
       h=ANGLE, fallback=st.integers(0, 1))
def test_blend_is_eq_12(alpha: float, c: float, v: float, h: float, fallback: int) -> None:
    """``α R_cov/|R_cov| + (1 - α) R_con/|R_con|`` to length 1, from the two unit terms; where
    they cancel, the heading or (``concov_fallback = connectivity``) ConB's term."""
    p = params(alpha=alpha, concov_fallback=fallback)
    terms = (math.cos(c), math.sin(c), math.cos(v), math.sin(v), math.cos(h), math.sin(h))
    rx = alpha * terms[0] + (1.0 - alpha) * terms[2]
    ry = alpha * terms[1] + (1.0 - alpha) * terms[3]
    size = math.hypot(rx, ry)
    assume(not 1e-12 < size < 1e-6)  # nearly cancelling: the direction is rounding
    want = (rx / size, ry / size) if size > 1e-12 else (terms[2:4] if fallback else terms[4:])
    assert _same_direction(blend(p, *terms), want)


@given(c=st.tuples(st.floats(-2, 2), st.floats(-2, 2)), v=st.tuples(st.floats(-2, 2),
                                                                     st.floats(-2, 2)))
def test_blend_at_the_ends_of_alpha_is_exactly_the_pure_term(
        c: tuple[float, float], v: tuple[float, float]) -> None:
    assert blend(params(alpha=1.0), *c, *v, 0.0, 1.0) == c
    assert blend(params(alpha=0.0), *c, *v, 0.0, 1.0) == v


@pytest.mark.parametrize(("fallback", "want"), [(0, (0.0, 1.0)), (1, (-1.0, 0.0))])
def test_blend_of_cancelling_terms_keeps_the_heading_or_follows_conb(
        fallback: int, want: tuple[float, float]) -> None:
    """CovB's term east, ConB's west, α = 0.5: Eq. 12 is exactly zero."""
    assert blend(params(alpha=0.5, concov_fallback=fallback), 1.0, 0.0, -1.0, 0.0,
                 0.0, 1.0) == want


# -- the hooks, composed ----------------------------------------------------------------------


def _observation(seed: int, n: int, p: Params) -> Observation:
    """A random team around the BS observed as the kernel observes it (links within r_c,
    pairs within r, the BS's component)."""
    rng = np.random.default_rng(seed)
    xy = [(float(x), float(y)) for x, y in BS + rng.uniform(-900.0, 900.0, (n + 1, 2))]
    xy.insert(n, BS)
    px, py, pz = node_arrays(xy, n)
    angles = rng.uniform(-math.pi, math.pi, n)
    m, mp = n + 2, padded(n + 2)
    thr2 = np.zeros((m, mp))
    thr2[:, :m] = p.rc * p.rc
    adj = np.zeros((m, words(m)), dtype=np.uint64)
    near = adj.copy()
    links(px, py, pz, thr2, adj, p.r * p.r, near, True)
    routed, spread = np.zeros(words(m), dtype=np.uint64), np.zeros(words(m), dtype=np.uint64)
    bs_component(adj, n, routed, np.empty(m, dtype=np.int64))
    mode = np.where(rng.random(n) < 0.2, LANDED, SEARCHING).astype(np.int8)
    return Observation(px, py, pz, np.cos(angles), np.sin(angles), mode,
                       np.zeros(n, dtype=np.bool_), np.zeros(n, dtype=np.int64),
                       np.zeros(n, dtype=np.bool_), adj, near, routed, spread, p.rc,
                       *_no_routes(n), np.random.default_rng(0), np.zeros(1, dtype=np.int64))


@pytest.mark.parametrize("seed", range(4))
def test_concov_at_the_ends_of_alpha_decides_as_covb_or_conb(seed: int) -> None:
    """Eq. 12 at α = 1 (0) is CovB's (ConB's) direction, bit for bit, and only the deciding
    drones get one (ConB predicting a sensing period ahead)."""
    n = 12
    for alpha, pure in ((1.0, covb), (0.0, conb)):
        p = params(alpha=alpha, rc=450.0, conb_check=0)
        obs = _observation(seed, n, p)
        deciding = obs.mode == SEARCHING
        deciding[::3] = False
        got, want = (np.full(n, 7.0), np.full(n, 7.0)), (np.full(n, 7.0), np.full(n, 7.0))
        concov.decide(5, p, obs, concov.prepare(p, obs), deciding, *got)
        pure.decide(5, p, obs, pure.prepare(p, obs), deciding, *want)
        np.testing.assert_array_equal(got, want)
        assert (got[0][~deciding] == 7.0).all()
        assert (np.hypot(*got)[deciding] == pytest.approx(1.0))
        assert (np.abs(got[0] - obs.hx)[deciding] > 1e-9).any()  # some drone did turn
