"""A route cut into sorties that each fit a battery, every sortie resuming where the last one
turned home.

A sortie takes off at the BS, climbs to the flight height, flies the shortest way inside the
area (round the no-fly zones) to where the last sortie turned home, searches on along the
route from a little before it (:data:`RESUME_OVERLAP`), turns home when the energy of the
flight so far, of the way home and of the landing reaches what a sortie may use, and lands at
the BS. What a sortie may use is the battery less its reserve (``battery.reserve``, 20 % by
default). Each sortie is cut as late as it can be: the energy of a sortie that turns home
``s`` metres along the route grows with ``s`` (the way home shortens by at most what the
route lengthens), so the last point that fits is found by bisection on its leg.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sarlink.config import ConfigError, Mission
from sarlink.config.region import area_polygon
from sarlink.engine.energy import EnergyModel, Flight, get_energy_model
from sarlink.engine.paths import Navigation

__all__ = ["RESUME_OVERLAP", "Sortie", "battery_budget", "split_route"]

RESUME_OVERLAP = 20.0
"""Metres of the route each sortie flies again before where the last one turned home: what
a GPS error of a few metres and the turn onto the route could otherwise leave unsearched."""
TOLERANCE = 1e-3
"""How close to the best cut (m along the route) the bisection stops."""


@dataclass(frozen=True)
class Sortie:
    """One flight of a drone's route, from take-off at the BS to landing there."""

    waypoints: np.ndarray
    """The points after take-off, in the mission's frame (m), the last one the BS."""
    start: float
    """Where along the route (m from the BS) its search begins."""
    end: float
    """Where along the route it turns home."""
    flight: Flight
    """Its level length, speed and height."""
    energy: float
    """Joules it takes under the mission's energy model (0 under ``none``)."""


def battery_budget(mission: Mission) -> float | None:
    """Joules a sortie may use (the capacity less the reserve), or None without a battery."""
    b = mission.battery
    return None if b.battery_wh is None else b.battery_wh * 3600.0 * (1.0 - b.reserve)


class _Route:
    """A route from the BS as a polyline measured from its start, with the ways home."""

    def __init__(self, bs: np.ndarray, route: np.ndarray, nav: Navigation) -> None:
        self.bs, self.nav = bs, nav
        self.path = np.vstack([bs, route])
        self.cum = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(self.path, axis=0).T))])
        self.length = float(self.cum[-1])

    def at(self, s: float) -> np.ndarray:
        """The point ``s`` metres along the route."""
        return np.array([np.interp(s, self.cum, self.path[:, 0]),
                         np.interp(s, self.cum, self.path[:, 1])])

    def between(self, a: float, b: float) -> np.ndarray:
        """The route's points from ``a`` to ``b`` metres along it, both ends included."""
        inner = self.path[(self.cum > a) & (self.cum < b)]
        return np.vstack([self.at(a), inner, self.at(b)])

    def way(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """The shortest flight from ``a`` to ``b`` inside the area, its points after ``a``."""
        return self.nav.path((float(a[0]), float(a[1])), (float(b[0]), float(b[1])))

    def home(self, s: float) -> float:
        """Metres of the shortest flight home from ``s`` metres along the route."""
        here = self.at(s)
        return _length(np.vstack([here, self.way(here, self.bs)]))


def _length(points: np.ndarray) -> float:
    return float(np.hypot(*np.diff(points, axis=0).T).sum()) if len(points) > 1 else 0.0


def _joined(points: list[np.ndarray], bs: np.ndarray) -> np.ndarray:
    """Waypoints after take-off at ``bs``: the pieces in order, a point within a nanometre
    of the one before it (or of the BS, first) dropped, the last one the BS itself."""
    path = np.vstack([bs[None, :], *points])
    keep = np.ones(len(path), dtype=bool)
    keep[1:] = (np.abs(np.diff(path, axis=0)) > 1e-9).any(axis=1)
    out = path[keep][1:]
    out[-1] = bs
    return out


def split_route(mission: Mission, drone: int, route: np.ndarray, altitude: float
                ) -> list[Sortie]:
    """``route`` (waypoints after take-off at the BS, ending there, in the mission's frame)
    as the sorties that fly it under the mission's battery: one sortie, the whole route,
    without a battery. A route of which some stretch cannot be reached, searched and left
    within one battery is refused with a :class:`ConfigError` that says so (``drone`` names
    it)."""
    model = get_energy_model(mission.energy_model)
    speed = mission.team.speed
    bs = np.asarray(mission.area.bs_xy, dtype=float)
    budget = battery_budget(mission)
    line = _Route(bs, np.asarray(route, dtype=float), Navigation(area_polygon(
        mission.region, mission.area.size)))
    if budget is None:
        flight = Flight(line.length, speed, altitude)
        return [Sortie(line.path[1:], 0.0, line.length, flight, flight.energy(model))]
    per_metre = model.per_metre(speed)
    level = (budget - Flight(0.0, speed, altitude).energy(model)) / per_metre
    sorties: list[Sortie] = []
    start, out = 0.0, 0.0
    while True:
        # the sortie from `start` may fly `level` metres: out, along the route to s, home
        reach = level - out + start  # the largest s + home(s) that fits
        end = _last_fit(line, start, reach)
        if end < line.length and end - start <= RESUME_OVERLAP:
            raise _too_small(mission, model, drone, line, start, out, altitude, budget)
        here = line.at(start)
        pieces = [line.way(bs, here)] if start > 0 else []
        pieces += [line.between(start, end)]
        if end < line.length:
            pieces.append(line.way(line.at(end), bs))
        waypoints = _joined(pieces, bs)
        flight = Flight(_length(np.vstack([bs, waypoints])), speed, altitude)
        sorties.append(Sortie(waypoints, start, end, flight, flight.energy(model)))
        if end >= line.length:
            return sorties
        start = end - RESUME_OVERLAP
        out = line.home(start)


def _last_fit(line: _Route, start: float, reach: float) -> float:
    """The largest ``s`` in ``[start, length]`` with ``s + home(s) <= reach`` (``start`` if
    none: the caller refuses the route then)."""
    def fits(s: float) -> bool:
        return s + line.home(s) <= reach

    if fits(line.length):
        return line.length
    lo, hi = start, line.length
    for s in line.cum[line.cum > start]:  # the first vertex past the reach
        if not fits(float(s)):
            hi = float(s)
            break
        lo = float(s)
    while hi - lo > TOLERANCE:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if fits(mid) else (lo, mid)
    return lo


def _too_small(mission: Mission, model: EnergyModel, drone: int, line: _Route, start: float,
               out: float, altitude: float, budget: float) -> ConfigError:
    """The one line that refuses a route: the round trip it could not fit, to the route's
    farthest waypoint (the way the drone flies) if that one does not fit, else to where the
    sortie could not search on past the overlap."""
    b, speed = mission.battery, mission.team.speed
    far = max(line.home(float(s)) for s in line.cum)
    need = Flight(2 * far, speed, altitude).energy(model)
    where = f"its farthest waypoint, {far / 1000:.2f} km from the BS,"
    if need <= budget:
        step = min(start + RESUME_OVERLAP, line.length)
        need = Flight(out + (step - start) + line.home(step), speed, altitude).energy(model)
        where = f"searching on at {out / 1000:.2f} km from the BS"
    best = model.range_speed()
    faster = f", a --speed nearer {best:.1f} m/s (the longest range)" if speed < best else ""
    return ConfigError(
        f"--battery-wh {b.battery_wh:g}: drone {drone}'s route cannot be flown in sorties of "
        f"this battery: {where} takes {need / 3600:.1f} Wh out and back ({model.name} at "
        f"{speed:g} m/s, with the climb to {altitude:g} m and the landing), and a sortie may "
        f"use {budget / 3600:.1f} Wh ({1 - b.reserve:.0%} of {b.battery_wh:g} Wh); a larger "
        f"battery{faster}, a lower --altitude or a smaller --reserve")
