"""Batteries in the kernel: energy drawn, the turn home, the swap at the BS and the take-off
that resumes (docs/model.md, Endurance). Compiled only into the kernels of teams with a
battery (``ENERGY``, :mod:`sarlink.engine.build`): a team without one flies today's kernel.

A drone flies at ``V_m`` or holds where it is, so its power is the energy model's at those two
speeds (``p.fly_w``, ``p.hover_w``), evaluated once in Python (:mod:`sarlink.engine.energy`): a step
in which a drone came ``d`` metres from where it was costs ``fly_w d / V_m`` for the flight and
``hover_w`` for the rest of the step. A take-off
costs the climb to the mission's altitude (``p.climb_j``), a landing the descent
(``p.descent_j``). A drone turns home at the first step at which what it has above the reserve
no longer pays for the flight home (round the holes on a polygon area) three steps more, at the
larger of the two powers, and the descent: it lands with the reserve intact whether it flew or
held in the step before it turned (the margin the bound needs: the step in which it decides, the
step of arrival, and one step's draw it may have made since the last check). Landed with a swap
due, it waits ``p.swap_steps`` steps on the ground (a spare from the BS's stock, ``p.spares``;
``-1``: unlimited; none left: it stays parked) and takes off again with a full battery, in the
role it left: a route drone flies back to where it left its route, a distributed drone decides
under its rule at once, a relay takes its place again.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.area import home_heading
from sarlink.engine.geometry import unit
from sarlink.engine.params import LANDED, RELAYING, RETURNING, SEARCHING, Params

NO_SWAP = -1
"""``resume[i]`` of a drone that is not coming back for a swap."""


@njit(cache=True, error_model="numpy")
def start(p: Params, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray,
                                      np.ndarray, np.ndarray, np.ndarray]:
    """Every drone's battery at take-off, full less the climb, and its state: ``energy`` J
    left, ``resume`` the mode it takes off in after a swap (:data:`NO_SWAP`: none due),
    ``was_route`` whether it left its route, ``ground_until`` the step its swap ends (``-1``:
    not begun), ``sorties``, ``ground`` seconds on the ground for swaps, ``used`` J drawn."""
    energy = np.full(n, p.battery_j - p.climb_j)
    resume = np.full(n, NO_SWAP, dtype=np.int8)
    was_route = np.zeros(n, dtype=np.bool_)
    ground_until = np.full(n, -1, dtype=np.int64)
    sorties = np.ones(n, dtype=np.int64)
    ground = np.zeros(n)
    used = np.full(n, p.climb_j)
    return energy, resume, was_route, ground_until, sorties, ground, used


@njit(cache=True, error_model="numpy")
def turn_home(p: Params, px: np.ndarray, py: np.ndarray, hx: np.ndarray, hy: np.ndarray,
              mode: np.ndarray, on_route: np.ndarray, energy: np.ndarray, resume: np.ndarray,
              was_route: np.ndarray, leave_x: np.ndarray, leave_y: np.ndarray,
              rejoin: np.ndarray, edges: np.ndarray, nav: np.ndarray) -> None:
    """Every airborne drone whose energy above the reserve no longer pays for the flight home
    (three steps more at the larger power, and the descent) turns home to swap its battery,
    remembering its role;
    a route drone remembers where it left its route (unless it left it already to report)."""
    step = p.speed * p.dt
    polygon = edges.shape[0] > 0
    power = max(p.fly_w, p.hover_w)
    for i in range(mode.shape[0]):
        if mode[i] == LANDED or mode[i] == RETURNING:
            continue
        if polygon:
            ux, uy, home = home_heading(px[i], py[i], p.bs_x, p.bs_y, step, edges, nav,
                                        hx[i], hy[i])
        else:
            dx, dy = p.bs_x - px[i], p.bs_y - py[i]
            home = math.sqrt(dx * dx + dy * dy)
            ux, uy = unit(dx, dy, hx[i], hy[i])
        need = power * (home / p.speed + 3.0 * p.dt) + p.descent_j
        if energy[i] - p.reserve_j > need:
            continue
        # a relay comes back a relay; a drone of the chain, a free knower
        resume[i] = RELAYING if mode[i] == RELAYING else SEARCHING
        if on_route[i]:
            was_route[i] = True
            on_route[i] = False
            if not rejoin[i]:
                leave_x[i], leave_y[i] = px[i], py[i]
                rejoin[i] = True
        mode[i] = RETURNING
        hx[i], hy[i] = ux, uy


@njit(cache=True, error_model="numpy")
def ground(k: int, homing: bool, p: Params, mode: np.ndarray, on_route: np.ndarray,
           last_change: np.ndarray, energy: np.ndarray, resume: np.ndarray,
           was_route: np.ndarray, ground_until: np.ndarray, sorties: np.ndarray,
           ground_s: np.ndarray, used: np.ndarray, spares: np.ndarray) -> None:
    """Every drone landed for a swap, at the start of step ``k`` (so that a drone taking off
    observes the step in the air and its rule decides on what it observes): a swap begins on
    landing if the BS has a spare (``spares[0]``, ``-1``: unlimited; else the drone stays
    parked), counts its time on the ground, and ends with a take-off in the role the drone
    left, unless the team's flight budget is due (``homing``: it would only turn home again)."""
    for i in range(mode.shape[0]):
        if mode[i] != LANDED or resume[i] == NO_SWAP:
            continue
        if ground_until[i] < 0:
            if spares[0] == 0:
                resume[i] = NO_SWAP
                continue
            if spares[0] > 0:
                spares[0] -= 1
            ground_until[i] = k + p.swap_steps
        if k < ground_until[i]:
            ground_s[i] += p.dt
            continue
        if homing:
            resume[i] = NO_SWAP
            continue
        mode[i] = resume[i]
        resume[i] = NO_SWAP
        ground_until[i] = -1
        energy[i] = p.battery_j - p.climb_j
        used[i] += p.climb_j
        sorties[i] += 1
        if was_route[i]:
            on_route[i] = True
            was_route[i] = False
        else:
            last_change[i] = k - p.ts_steps  # due for a direction update now


@njit(cache=True, error_model="numpy")
def keep(px: np.ndarray, py: np.ndarray, mode: np.ndarray, bx: np.ndarray, by: np.ndarray,
         airborne: np.ndarray) -> None:
    """Where every drone is before the move, and whether it is in the air."""
    for i in range(mode.shape[0]):
        bx[i], by[i] = px[i], py[i]
        airborne[i] = mode[i] != LANDED


@njit(cache=True, error_model="numpy")
def drain(p: Params, px: np.ndarray, py: np.ndarray, mode: np.ndarray, bx: np.ndarray,
          by: np.ndarray, airborne: np.ndarray, energy: np.ndarray, used: np.ndarray) -> None:
    """The step's energy for every drone in the air: ``d / V_m`` of it flying, ``d`` the way
    from where it was (straight: a route's corner within a step counts the chord), the rest
    holding (a relay at its point, a reporter over the BS), and the descent for one that
    landed."""
    for i in range(energy.shape[0]):
        if not airborne[i]:
            continue
        flying = min(math.hypot(px[i] - bx[i], py[i] - by[i]) / p.speed, p.dt)
        drawn = p.fly_w * flying + p.hover_w * (p.dt - flying)
        if mode[i] == LANDED:
            drawn += p.descent_j
        energy[i] -= drawn
        used[i] += drawn


@njit(cache=True, error_model="numpy")
def pending(resume: np.ndarray) -> bool:
    """Whether a landed drone may still take off again (its swap is due or under way)."""
    return bool((resume != NO_SWAP).any())
