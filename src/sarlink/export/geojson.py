"""The team's mission on the map as one GeoJSON (RFC 7946): area, no-fly zones, BS, prior
zones, and each drone's route (or simulated track) with its task (searcher or relay), length
and flight time."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from shapely.geometry import Polygon
from shapely.geometry.polygon import orient

from sarlink.config import Mission
from sarlink.config.geo import Frame
from sarlink.config.region import area_polygon, zone_polygon

__all__ = ["team_geojson"]


def _lonlat(frame: Frame, xy: np.ndarray) -> list[list[float]]:
    lon, lat = frame.to_lonlat(xy[:, 0], xy[:, 1])
    return [[round(float(a), 8), round(float(b), 8)] for a, b in zip(lon, lat, strict=True)]


def _polygon(frame: Frame, poly: Polygon) -> dict[str, Any]:
    """A polygon in longitude/latitude, outer ring counter-clockwise (RFC 7946's right-hand
    rule), holes clockwise."""
    poly = orient(poly, sign=1.0)
    rings = [poly.exterior, *poly.interiors]
    return {"type": "Polygon",
            "coordinates": [_lonlat(frame, np.asarray(r.coords)) for r in rings]}


def _feature(geometry: dict[str, Any], **props: Any) -> dict[str, Any]:
    return {"type": "Feature", "properties": props, "geometry": geometry}


def team_geojson(mission: Mission, frame: Frame, paths: dict[int, tuple[str, np.ndarray]],
                 speed: float,
                 sorties: Sequence[tuple[int, int, np.ndarray, dict[str, float]]] = ()
                 ) -> dict[str, Any]:
    """The FeatureCollection of a team's mission; ``paths[i]`` is drone ``i``'s kind and its
    points in the mission's frame (from the BS). A drone's ``task`` is ``relay`` for the
    team's last ``team.relays`` drones, else ``searcher``. ``sorties`` are the battery-sized
    flights of route drones: drone, number, points (from the BS to the BS) and properties
    (length, duration, energy), each a feature of role ``sortie``."""
    region = mission.region
    area = area_polygon(region, mission.area.size)
    features = [_feature(_polygon(frame, Polygon(area.exterior)), role="area",
                         name=region.name if region is not None else "")]
    features += [_feature(_polygon(frame, Polygon(h)), role="no-fly zone", hole=k)
                 for k, h in enumerate(area.interiors)]
    if region is not None:
        total = sum(z.weight for z in region.zones) or 1.0
        features += [_feature(_polygon(frame, zone_polygon(z)), role="prior zone",
                              probability=z.weight / total)
                     for z in region.zones]
    features.append(_feature({"type": "Point", "coordinates": [
        round(frame.anchor[0], 8), round(frame.anchor[1], 8)]}, role="BS"))
    searchers = mission.team.drones - mission.team.relays
    for drone, (kind, points) in sorted(paths.items()):
        length = float(np.hypot(*np.diff(points, axis=0).T).sum()) if len(points) > 1 else 0.0
        features.append(_feature({"type": "LineString", "coordinates": _lonlat(frame, points)},
                                 role=kind, drone=drone,
                                 task="relay" if drone >= searchers else "searcher",
                                 length_m=round(length, 1),
                                 flight_time_s=round(length / speed, 1)))
    features += [_feature({"type": "LineString", "coordinates": _lonlat(frame, points)},
                          role="sortie", drone=drone, sortie=number, **props)
                 for drone, number, points, props in sorties]
    return {"type": "FeatureCollection", "name": f"sarlink: {mission.team.planner}, "
            f"{mission.team.drones} drones", "features": features}
