"""Where a mission happens on the map: a polygon area with no-fly holes, and the target prior.

The paper's world is the square ``[0, size]²`` with a uniform target; :class:`Region` replaces
either part. Coordinates are local metres (x east, y north); ``anchor`` puts that frame on the
Earth (:mod:`sarlink.config.mapfile` reads GeoJSON in longitude/latitude into it). The models
only check their shape; :func:`check_region` checks the geometry against the mission (a valid
polygon, the BS inside, a prior with mass inside), with one sentence per problem.
"""

from __future__ import annotations

import math
import re
from typing import Self

import shapely
from pydantic import Field, model_validator
from shapely.geometry import Point, Polygon, box

from sarlink.config.base import Checked

__all__ = ["Region", "Ring", "Zone", "area_label", "area_polygon", "check_region",
           "zone_polygon"]

BS_CLEARANCE = 1.0
"""How far (m) the BS must lie from a polygon area's edges: drones fly home to it, and a
flight along an edge is no flight inside."""

XY = tuple[float, float]
Ring = tuple[XY, ...]
"""A closed ring of ``(x, y)`` points, m; the closing point may be repeated or left out."""


def _ring_problem(ring: Ring) -> str | None:
    distinct = {tuple(p) for p in ring}
    return None if len(distinct) >= 3 else f"needs at least 3 distinct points, got {len(distinct)}"


class Zone(Checked):
    """One part of a target prior: a polygon and the probability mass (or weight) in it.

    The target lies in the zone with probability proportional to ``weight`` times the part of
    the zone inside the search area, uniformly there (the probability of area of SAR
    planning, POA).
    """

    outline: Ring = Field(description="the zone's outer ring, local metres")
    holes: tuple[Ring, ...] = Field((), description="rings cut out of the zone")
    weight: float = Field(gt=0, description="probability mass, or a relative weight")

    @model_validator(mode="after")
    def _rings(self) -> Self:
        for what, ring in (("outline", self.outline),
                           *((f"hole {k}", h) for k, h in enumerate(self.holes))):
            problem = _ring_problem(ring)
            if problem:
                raise ValueError(f"zone {what} {problem}")
        return self


class Region(Checked):
    """A mission's place on the map: the area's polygon and holes, the prior, the anchor.

    ``outline`` None is the paper's square ``[0, area.size]²`` (holes may still be cut out of
    it); ``zones`` empty is the paper's uniform target. ``anchor`` is the BS's longitude and
    latitude (WGS84): the local frame is the azimuthal equidistant projection centred on the
    BS, shifted so that the BS sits at ``area.bs``; without it the mission has no place on
    the map (and no export to an autopilot).
    """

    name: str = Field("", description="what the area is called, for titles and exports")
    anchor: XY | None = Field(None, description="(longitude, latitude) of the BS, degrees")
    outline: Ring | None = Field(None, description="the area's outer ring, local metres; "
                                                   "None: the square [0, size]²")
    holes: tuple[Ring, ...] = Field((), description="no-fly zones cut out of the area")
    zones: tuple[Zone, ...] = Field((), description="the target prior; empty: uniform")

    @model_validator(mode="after")
    def _shape(self) -> Self:
        rings = [] if self.outline is None else [("outline", self.outline)]
        rings += [(f"hole {k}", h) for k, h in enumerate(self.holes)]
        for what, ring in rings:
            problem = _ring_problem(ring)
            if problem:
                raise ValueError(f"{what} {problem}")
        if self.anchor is not None:
            lon, lat = self.anchor
            if not (-180 <= lon <= 180 and -90 <= lat <= 90):
                raise ValueError(f"anchor must be (longitude, latitude) in degrees, longitude "
                                 f"in [-180, 180] and latitude in [-90, 90], got ({lon}, {lat})")
        return self


EDGE = 1e-6
"""How far outside the area's edge (m) a given position or waypoint may lie, for rounding."""


def is_polygon(region: Region | None) -> bool:
    """Whether ``region`` makes the area a polygon or gives it holes (else it is the paper's
    square)."""
    return region is not None and (region.outline is not None or bool(region.holes))


def area_polygon(region: Region | None, size: float) -> Polygon:
    """The search area: ``region``'s outline (or the square of side ``size``) minus its holes."""
    shell = box(0.0, 0.0, size, size) if region is None or region.outline is None else \
        Polygon(region.outline)
    holes = () if region is None else region.holes
    return Polygon(shell.exterior.coords, [h for h in holes])


def area_label(region: Region | None, size: float) -> str:
    """The area in a few words, for titles: ``4000 m square`` or ``valley, 10.1 km², 1
    no-fly zone``."""
    if region is None or (region.outline is None and not region.holes):
        text = f"{size:g} m square"
    else:
        holes = len(region.holes)
        text = (f"{region.name or 'polygon'}, {area_polygon(region, size).area / 1e6:.1f} km², "
                f"{holes} no-fly zone{'s' if holes != 1 else ''}")
    if region is not None and region.zones:
        text += f", prior of {len(region.zones)} zone{'s' if len(region.zones) != 1 else ''}"
    return text


def zone_polygon(zone: Zone) -> Polygon:
    """A prior zone as a polygon."""
    return Polygon(zone.outline, list(zone.holes))


def _where(reason: str) -> str:
    """GEOS's reason ``Self-intersection[x y]`` as ``self-intersection at (x, y) m``."""
    match = re.search(r"\[([-\d.e+]+) ([-\d.e+]+)\]", reason)
    text = reason.split("[")[0].strip().lower()
    return f"{text} at ({float(match[1]):.1f}, {float(match[2]):.1f}) m" if match else text


def _polygon_problem(what: str, ring: Ring) -> str | None:
    poly = Polygon(ring)
    if poly.is_valid and poly.area > 0:
        return None
    if poly.area <= 0 and poly.is_valid:
        return f"{what} encloses no area"
    return f"{what} is not a simple polygon: {_where(shapely.is_valid_reason(poly))}"


def check_region(region: Region | None, size: float, bs: XY,
                 bs_name: str | None = None) -> str | None:
    """What is wrong with the geometry of ``region`` in a mission, or None; ``bs_name`` says
    where the BS is in the user's words (default: its position in metres).

    Checked: each ring is a simple polygon; each hole lies inside the outline and leaves the
    area in one piece; the BS is inside the area and not in a hole; the prior has mass inside
    the area.
    """
    if region is None:
        return None
    shell = box(0.0, 0.0, size, size) if region.outline is None else Polygon(region.outline)
    if region.outline is not None:
        problem = _polygon_problem("the outline", region.outline)
        if problem:
            return problem
    for k, ring in enumerate(region.holes):
        problem = _polygon_problem(f"hole {k}", ring)
        if problem:
            return problem
        hole = Polygon(ring)
        rest = shell.difference(hole)
        if rest.geom_type != "Polygon":
            return (f"hole {k} cuts the area in {len(getattr(rest, 'geoms', ()))} pieces; a "
                    "search area is one piece (search the pieces as separate missions)")
        if not shell.contains(hole):
            return f"hole {k} crosses the area's outline; a hole must lie inside the area"
    area = area_polygon(region, size)
    if not area.is_valid:
        reason = shapely.is_valid_reason(area)
        if reason.startswith("Interior is disconnected"):
            return ("the holes cut the area in pieces; a search area is one piece (search the "
                    "pieces as separate missions)")
        return f"the holes overlap or touch each other: {_where(reason)}"
    at = bs_name or f"({bs[0]:.1f}, {bs[1]:.1f}) m"
    if not area.covers(Point(bs)):
        where = "in a hole (a no-fly zone)" if shell.covers(Point(bs)) else "outside the area"
        return f"the BS at {at} is {where}"
    polygon = region.outline is not None or bool(region.holes)
    if polygon and area.boundary.distance(Point(bs)) < BS_CLEARANCE:
        return (f"the BS at {at} is on the edge of the area or of a hole; put it at least "
                f"{BS_CLEARANCE:g} m inside")
    if region.zones:
        mass = 0.0
        for k, zone in enumerate(region.zones):
            poly = zone_polygon(zone)
            if not poly.is_valid:
                return f"prior zone {k} is not a simple polygon: " \
                       f"{_where(shapely.is_valid_reason(poly))}"
            inside = poly.intersection(area).area
            mass += zone.weight * inside / poly.area if poly.area > 0 else 0.0
        if not mass > 0 or not math.isfinite(mass):
            return "the target prior has no mass inside the area (no zone overlaps it)"
    return None
