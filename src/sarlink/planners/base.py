"""What a planner is: a named maker of the engine's :class:`Steering` for a mission.

Two kinds cover every planner, built-in or plug-in (docs/plugins.md): a :class:`RoutePlanner`
plans each drone's waypoints before take-off (mTSP, the search patterns); a
:class:`RulePlanner` lets the drones decide in flight with a distributed rule
(:class:`~sarlink.engine.hooks.DistributedRule`), optionally with routes for some of them
(mTSP-ConB). A planner's functions are the plug-in's code: whatever they raise or return
wrongly is reported as one line naming the planner.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial
from typing import TYPE_CHECKING, Any, Literal, Protocol

import numpy as np
import shapely

from sarlink.config import ConfigError
from sarlink.config.region import EDGE, area_polygon, is_polygon
from sarlink.engine.hooks import DistributedRule
from sarlink.engine.steering import Steering
from sarlink.engine.streams import plan_seed

if TYPE_CHECKING:
    from sarlink.config import Mission

__all__ = ["Planner", "RoutePlanner", "Routes", "RulePlanner", "Steering"]

Routes = Callable[["Mission"], Sequence[Any]]
"""A route function: the mission -> one ``(k, 2)`` array of waypoints (x, y in m) per drone."""


class Planner(Protocol):
    """A path planner, registered by name (:func:`sarlink.register_planner`)."""

    @property
    def name(self) -> str:
        """Registry key used in configs and the CLI (``covb``)."""
        ...

    @property
    def label(self) -> str:
        """Name as people write it (``CovB``)."""
        ...

    @property
    def colour(self) -> str:
        """Its line colour in every figure (a Matplotlib colour)."""
        ...

    @property
    def marker(self) -> str:
        """Its marker in every figure (a Matplotlib marker)."""
        ...

    @property
    def kind(self) -> Literal["route", "rule", "hybrid"]:
        """``route``: waypoints only; ``rule``: a distributed rule; ``hybrid``: both."""
        ...

    @property
    def rule(self) -> DistributedRule | None:
        """The rule its distributed drones run (``None``: routes only)."""
        ...

    def steering(self, mission: Mission) -> Steering:
        """What the engine needs to fly ``mission`` with this planner."""
        ...


def _call(planner: str, fn: Routes, mission: Mission) -> Sequence[Any]:
    try:
        return fn(mission)
    except ConfigError:
        raise
    except Exception as exc:
        raise ConfigError(f"planner {planner!r}: its route function raised "
                          f"{type(exc).__name__}: {exc}") from exc


def checked_routes(planner: str, routes: Sequence[Any], mission: Mission, *,
                   every_drone: bool) -> tuple[np.ndarray, ...]:
    """``routes`` as float arrays, checked: at most one per drone (all of them if
    ``every_drone``), each ``(k, 2)``, finite and inside the area; the BS is appended where a
    route does not end there (drones land at the BS)."""
    n = mission.team.drones
    try:
        arrays = [np.asarray(r, dtype=float) for r in routes]
    except (TypeError, ValueError) as exc:
        raise ConfigError(f"planner {planner!r}: routes must be arrays of (x, y) waypoints: "
                          f"{exc}") from None
    if len(arrays) > n or (every_drone and len(arrays) != n):
        need = f"{n}" if every_drone else f"at most {n}"
        raise ConfigError(f"planner {planner!r}: gave {len(arrays)} routes for {n} drones; "
                          f"{need} expected")
    size, bs = mission.area.size, np.asarray(mission.area.bs_xy, dtype=float)
    area = area_polygon(mission.region, size) if is_polygon(mission.region) else None
    where = f"[0, {size:g}]²" if area is None else "its polygon, out of its holes"
    out = []
    for i, route in enumerate(arrays):
        if route.size == 0 and not every_drone:
            out.append(np.empty((0, 2)))
            continue
        if route.ndim != 2 or route.shape[1] != 2 or route.shape[0] == 0:
            raise ConfigError(f"planner {planner!r}: route of drone {i} has shape "
                              f"{route.shape}; (k, 2) waypoints with k >= 1 expected")
        if not np.isfinite(route).all():
            raise ConfigError(f"planner {planner!r}: route of drone {i} has a waypoint that "
                              "is not finite")
        if area is None:
            outside = ~((route >= 0) & (route <= size)).all(axis=1)
        else:
            outside = ~shapely.dwithin(area, shapely.points(route), EDGE)
        if outside.any():
            x, y = route[outside][0]
            raise ConfigError(f"planner {planner!r}: route of drone {i} leaves the area at "
                              f"waypoint ({x:g}, {y:g}); the area is {where}")
        if not np.array_equal(route[-1], bs):
            route = np.vstack([route, bs])
        out.append(route)
    return tuple(out)


def _own_routes(planner: RoutePlanner | RulePlanner, mission: Mission, seed: int,
                run: int) -> tuple[np.ndarray, ...]:
    """The routes of run ``run``: its own mTSP plan, seeded from ``(seed, run)``."""
    return planner.steering(mission.replace(plan_seed=plan_seed(seed, run))).routes


def _per_run(planner: RoutePlanner | RulePlanner, mission: Mission
             ) -> Callable[[int, int], tuple[np.ndarray, ...]] | None:
    """Each run's own routes, if the planner flies an mTSP plan and the mission plans per run
    (``readings.mtsp_plan``)."""
    if planner.mtsp and mission.readings.mtsp_plan == "per-run":
        return partial(_own_routes, planner, mission)
    return None


@dataclass(frozen=True)
class RoutePlanner:
    """A planner that gives every drone a route before take-off: ``routes(mission)`` returns
    one ``(k, 2)`` waypoint array per drone; the drones take off from the BS, fly to each
    waypoint in turn and land at the BS."""

    name: str
    label: str
    routes: Routes
    colour: str = "#7f7f7f"
    marker: str = "o"
    mtsp: bool = False
    """Whether its routes are an mTSP plan (``readings.mtsp_plan``: one per run or shared)."""

    @property
    def kind(self) -> Literal["route"]:
        """Always ``route``."""
        return "route"

    @property
    def rule(self) -> None:
        """None: no drone runs a distributed rule."""
        return None

    def steering(self, mission: Mission) -> Steering:
        """Every drone's checked route (:func:`checked_routes`)."""
        routes = _call(self.name, self.routes, mission)
        return Steering(rule=None, routes=checked_routes(self.name, routes, mission,
                                                        every_drone=True),
                        per_run=_per_run(self, mission))


@dataclass(frozen=True)
class RulePlanner:
    """A planner whose drones decide in flight with ``rule``; with ``routes``, the drones it
    gives a non-empty route fly it instead (a hybrid; at most one route per drone)."""

    name: str
    label: str
    rule: DistributedRule
    colour: str = "#7f7f7f"
    marker: str = "o"
    routes: Routes | None = None
    mtsp: bool = False
    """Whether its routes are an mTSP plan (``readings.mtsp_plan``: one per run or shared)."""

    @property
    def kind(self) -> Literal["rule", "hybrid"]:
        """``rule``, or ``hybrid`` when some drones fly routes."""
        return "rule" if self.routes is None else "hybrid"

    def steering(self, mission: Mission) -> Steering:
        """The rule, and the checked routes of a hybrid's route drones."""
        if self.routes is None:
            return Steering(rule=self.rule)
        routes = _call(self.name, self.routes, mission)
        return Steering(rule=self.rule, routes=checked_routes(self.name, routes, mission,
                                                             every_drone=False),
                        per_run=_per_run(self, mission))
