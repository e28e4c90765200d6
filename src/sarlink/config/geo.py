"""Missions on the map: the local metric frame, and area and prior files read into a Region.

The frame is the azimuthal equidistant projection (PROJ ``aeqd``, WGS84 ellipsoid) centred on
the BS, shifted so that the BS sits at the mission's ``area.bs``: distances and bearings from
the BS are exact, and over a search area of 10 km the scale error elsewhere stays below 1 ppm
(a millimetre per kilometre), far below the drones' 5 m steps.

Files (``[region]`` keys of a mission file, or ``--area``, ``--prior``, ``--bs``):

- ``area``: GeoJSON in longitude/latitude (RFC 7946), one Polygon (its holes are no-fly
  zones), optionally with a Point feature for the BS;
- ``prior``: GeoJSON polygons with a ``probability`` (or ``weight``) property, or a raster
  (GeoTIFF, through the optional ``rasterio``) of relative probabilities per pixel;
- ``bs``: the BS's ``[longitude, latitude]``.
"""

from __future__ import annotations

import json
import math
import warnings
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np
from pyproj import CRS, Transformer
from shapely.geometry import Polygon

from sarlink.config.base import ConfigError
from sarlink.config.region import Region, Zone, check_region

__all__ = ["FILE_KEYS", "MAX_PIXELS", "Frame", "parse_lonlat", "resolve_files"]

FILE_KEYS = ("area", "prior", "bs")
"""The ``[region]`` keys read from files (or typed as longitude/latitude) when a mission is
loaded; the mission keeps what they hold, not the paths."""
MAX_PIXELS = 20_000
"""Most raster pixels with a positive probability: each becomes a zone of the mission."""
WGS84 = CRS.from_epsg(4326)


@dataclass(frozen=True)
class Frame:
    """The local frame of a mission on the map: x east, y north, metres."""

    anchor: tuple[float, float]
    """(longitude, latitude) of the BS, degrees."""
    bs: tuple[float, float]
    """Where the BS sits in the local frame, m."""

    @property
    def crs(self) -> CRS:
        lon, lat = self.anchor
        return CRS.from_proj4(f"+proj=aeqd +lat_0={lat!r} +lon_0={lon!r} +x_0={self.bs[0]!r} "
                              f"+y_0={self.bs[1]!r} +datum=WGS84 +units=m +no_defs")

    def to_local(self, lon: Any, lat: Any) -> tuple[np.ndarray, np.ndarray]:
        """Longitude/latitude (degrees) to local metres."""
        x, y = _transformer(WGS84.to_wkt(), self.crs.to_wkt()).transform(lon, lat)
        return np.asarray(x, dtype=float), np.asarray(y, dtype=float)

    def to_lonlat(self, x: Any, y: Any) -> tuple[np.ndarray, np.ndarray]:
        """Local metres to longitude/latitude (degrees)."""
        lon, lat = _transformer(self.crs.to_wkt(), WGS84.to_wkt()).transform(x, y)
        return np.asarray(lon, dtype=float), np.asarray(lat, dtype=float)

    def ring(self, positions: Sequence[Sequence[float]]) -> tuple[tuple[float, float], ...]:
        """A ring of [longitude, latitude] positions in local metres, rounded to the
        millimetre: the mission (and so its hash, the name of its results folder) does not
        change with the last bits of another PROJ version."""
        lon, lat = np.asarray(positions, dtype=float)[:, :2].T
        x, y = self.to_local(lon, lat)
        return tuple((round(float(a), 3), round(float(b), 3)) for a, b in zip(x, y, strict=True))


@lru_cache(maxsize=32)
def _transformer(source: str, target: str) -> Transformer:
    return Transformer.from_crs(CRS.from_wkt(source), CRS.from_wkt(target), always_xy=True)


def parse_lonlat(text: str, what: str = "--bs") -> tuple[float, float]:
    """``"lon,lat"`` as two floats in range, or a :class:`ConfigError` naming ``what``."""
    parts = text.split(",")
    try:
        lon, lat = (float(p) for p in parts)
    except ValueError:
        raise ConfigError(f"{what} {text!r}: expected longitude,latitude in degrees, e.g. "
                          "6.8652,45.9237") from None
    _check_lonlat(lon, lat, what)
    return lon, lat


def _check_lonlat(lon: float, lat: float, what: str) -> None:
    if not (math.isfinite(lon) and math.isfinite(lat) and -180 <= lon <= 180
            and -90 <= lat <= 90):
        raise ConfigError(f"{what}: ({lon:g}, {lat:g}) is not a longitude/latitude in degrees "
                          "(WGS84: longitude in [-180, 180], latitude in [-90, 90]; GeoJSON "
                          "writes [longitude, latitude]); an area in metres is given as "
                          "region.outline in a mission file")


def _read_json(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ConfigError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise ConfigError(f"{path} is a folder; a GeoJSON file is expected") from None
    except (ValueError, UnicodeDecodeError) as exc:
        raise ConfigError(f"{path}: not valid GeoJSON (JSON text): {exc}") from None
    except OSError as exc:
        raise ConfigError(f"{path}: cannot be read ({exc.strerror})") from None


def _features(path: Path, data: Any) -> Iterator[tuple[dict[str, Any], dict[str, Any]]]:
    """(geometry, properties) of every feature of a GeoJSON object."""
    if not isinstance(data, dict) or "type" not in data:
        raise ConfigError(f"{path}: not a GeoJSON object (no \"type\")")
    crs = data.get("crs")
    if crs is not None:  # the 2008 spec's member: only WGS84 longitude/latitude is read
        name = str((crs.get("properties") or {}).get("name", "")) if isinstance(crs, dict) \
            else ""
        if not name.upper().endswith(("CRS84", "4326")):
            raise ConfigError(f"{path}: coordinates in {name or 'another system'}; sarlink "
                              "reads GeoJSON in longitude/latitude (WGS84, RFC 7946)")
    kind = data["type"]
    if kind == "FeatureCollection":
        for feature in data.get("features") or []:
            yield from _features(path, feature)
    elif kind == "Feature":
        if isinstance(data.get("geometry"), dict):
            yield data["geometry"], dict(data.get("properties") or {})
    else:
        yield data, {}


def _positions(path: Path, rings: Any) -> list[list[list[float]]]:
    """A Polygon's rings, every position checked to be a longitude/latitude."""
    if not isinstance(rings, list) or not rings:
        raise ConfigError(f"{path}: a Polygon without coordinates")
    for ring in rings:
        if not isinstance(ring, list) or len(ring) < 4:
            raise ConfigError(f"{path}: a Polygon's ring needs at least 4 positions (the first "
                              "repeated at the end)")
        for pos in ring:
            if not (isinstance(pos, list) and 2 <= len(pos) <= 3
                    and all(isinstance(v, int | float) for v in pos)):
                raise ConfigError(f"{path}: {pos!r} is not a GeoJSON position "
                                  "[longitude, latitude]")
            _check_lonlat(float(pos[0]), float(pos[1]), str(path))
    return rings


def _polygons(path: Path, geometry: dict[str, Any]) -> list[list[list[list[float]]]]:
    kind = geometry.get("type")
    coords = geometry.get("coordinates")
    if kind == "Polygon":
        return [_positions(path, coords)]
    if kind == "MultiPolygon" and isinstance(coords, list):
        return [_positions(path, c) for c in coords]
    return []


def _read_area(path: Path) -> tuple[list[list[list[float]]], tuple[float, float] | None, str]:
    """The area's rings, the BS's position if the file has a Point, and its name."""
    polygons, points, name = [], [], ""
    for geometry, props in _features(path, _read_json(path)):
        if geometry.get("type") == "Point":
            pos = geometry.get("coordinates")
            if not (isinstance(pos, list) and len(pos) >= 2):
                raise ConfigError(f"{path}: a Point without a position")
            _check_lonlat(float(pos[0]), float(pos[1]), str(path))
            points.append((float(pos[0]), float(pos[1])))
        else:
            found = _polygons(path, geometry)
            polygons += found
            if found and not name:
                name = str(props.get("name", ""))
    if len(polygons) != 1:
        raise ConfigError(f"{path}: the area must be one Polygon (its holes are no-fly "
                          f"zones), found {len(polygons)}")
    if len(points) > 1:
        raise ConfigError(f"{path}: at most one Point (the BS) may be given, found "
                          f"{len(points)}")
    return polygons[0], points[0] if points else None, name or path.stem


def _weight(path: Path, k: int, props: dict[str, Any]) -> float:
    for key in ("probability", "weight"):
        if key in props:
            value = props[key]
            if isinstance(value, int | float) and math.isfinite(value) and value >= 0:
                return float(value)
            raise ConfigError(f"{path}: feature {k}'s {key} must be a number >= 0, got "
                              f"{value!r}")
    raise ConfigError(f"{path}: feature {k} has no \"probability\" (or \"weight\") property")


def _read_zones(path: Path, frame: Frame) -> tuple[Zone, ...]:
    """Prior zones from GeoJSON polygons weighted by their ``probability`` property.

    A MultiPolygon's mass is shared among its parts in proportion to their areas.
    """
    zones: list[Zone] = []
    for k, (geometry, props) in enumerate(_features(path, _read_json(path))):
        polygons = _polygons(path, geometry)
        if not polygons:
            raise ConfigError(f"{path}: feature {k} is a {geometry.get('type')}; a prior's "
                              "features are Polygons or MultiPolygons")
        weight = _weight(path, k, props)
        parts = [[frame.ring(r) for r in rings] for rings in polygons]
        areas = [Polygon(rings[0], rings[1:]).area for rings in parts]
        for rings, area in zip(parts, areas, strict=True):
            share = weight * area / sum(areas) if sum(areas) > 0 else 0.0
            if share > 0:
                zones.append(Zone(outline=rings[0], holes=tuple(rings[1:]), weight=share))
    if not zones:
        raise ConfigError(f"{path}: the prior has no zone with a positive probability")
    return tuple(zones)


def _read_raster(path: Path, frame: Frame) -> tuple[Zone, ...]:
    """Prior zones from a raster: each pixel with a positive value is a zone of that weight."""
    try:
        import rasterio
    except ImportError:
        raise ConfigError(f"{path}: a raster prior needs rasterio "
                          "(pip install 'sarlink[raster]')") from None
    try:
        with warnings.catch_warnings():  # a raster without a CRS is refused below
            warnings.simplefilter("ignore", rasterio.errors.NotGeoreferencedWarning)
            with rasterio.open(path) as src:
                values = src.read(1, masked=True).filled(0.0).astype(float)
                crs, transform = src.crs, src.transform
    except rasterio.errors.RasterioIOError as exc:
        raise ConfigError(f"{path}: not a raster sarlink can read: {exc}") from None
    if crs is None:
        raise ConfigError(f"{path}: the raster has no coordinate reference system")
    if not np.isfinite(values).all() or (values < 0).any():
        raise ConfigError(f"{path}: pixel values must be finite numbers >= 0 (relative "
                          "probabilities)")
    rows, cols = np.nonzero(values > 0)
    if rows.size > MAX_PIXELS:
        raise ConfigError(f"{path}: {rows.size:,} pixels have a positive probability; at most "
                          f"{MAX_PIXELS:,} are read (resample the raster coarser)")
    corners = np.array([(0, 0), (1, 0), (1, 1), (0, 1)], dtype=float)
    cc = cols[:, None] + corners[None, :, 0]
    rr = rows[:, None] + corners[None, :, 1]
    t = transform  # pixel (column, row) corners to the raster's coordinates (affine)
    fx, fy = t.a * cc + t.b * rr + t.c, t.d * cc + t.e * rr + t.f
    lon, lat = _transformer(CRS.from_user_input(crs).to_wkt(), WGS84.to_wkt()).transform(fx, fy)
    x, y = frame.to_local(lon, lat)
    return tuple(Zone(outline=tuple(zip(x[k].tolist(), y[k].tolist(), strict=True)),
                      weight=float(values[rows[k], cols[k]])) for k in range(rows.size))


def _file(value: Any, folder: Path, key: str) -> Path:
    if not isinstance(value, str | Path):
        raise ConfigError(f"region.{key} must be a file name, got {value!r}")
    path = Path(value)
    return path if path.is_absolute() else folder / path


def resolve_files(data: dict[str, Any], folder: Path, size: float) -> dict[str, Any]:
    """Mission data whose ``region`` names files (``area``, ``prior``) or the BS's
    ``bs = [longitude, latitude]``, with what they hold in their place.

    An area file replaces ``region.outline`` and ``holes`` and puts the BS at ``(0, 0)``;
    without one, the BS's longitude and latitude anchor the square (or the polygon in local
    metres) at the mission's BS. ``size`` is the square's side when the data does not set it.
    Errors name the file and what is wrong with it.
    """
    region = dict(data["region"])
    area_file = _file(region.pop("area"), folder, "area") if "area" in region else None
    prior_file = _file(region.pop("prior"), folder, "prior") if "prior" in region else None
    bs_lonlat = region.pop("bs", None)
    if bs_lonlat is not None:
        if isinstance(bs_lonlat, str):
            bs_lonlat = parse_lonlat(bs_lonlat, "region.bs")
        if not (isinstance(bs_lonlat, list | tuple) and len(bs_lonlat) == 2):
            raise ConfigError(f"region.bs must be [longitude, latitude], got {bs_lonlat!r}")
        _check_lonlat(float(bs_lonlat[0]), float(bs_lonlat[1]), "region.bs")
        bs_lonlat = (float(bs_lonlat[0]), float(bs_lonlat[1]))
    area = {"size": size, **(data.get("area") or {})}
    if area_file is not None:
        rings, file_bs, name = _read_area(area_file)
        anchor = bs_lonlat or file_bs
        if anchor is None:
            raise ConfigError(f"{area_file}: no BS: add a Point feature for it, or give its "
                              "longitude,latitude (--bs, or region.bs)")
        area["bs"] = (0.0, 0.0)
        frame = Frame(anchor, (0.0, 0.0))
        region.update(outline=frame.ring(rings[0]), holes=tuple(frame.ring(h) for h in rings[1:]),
                      anchor=anchor)
        region.setdefault("name", name)
    else:
        anchor = bs_lonlat or region.get("anchor")
        if anchor is None:
            if prior_file is not None:
                raise ConfigError(f"{prior_file}: a prior on the map needs the mission on the "
                                  "map: give the area as GeoJSON (--area) or the BS's "
                                  "longitude,latitude (--bs)")
        else:
            region["anchor"] = anchor
    if prior_file is not None:
        frame = Frame(tuple(region["anchor"]), _bs_of(area))
        suffix = prior_file.suffix.lower()
        region["zones"] = (_read_zones(prior_file, frame) if suffix in (".json", ".geojson")
                           else _read_raster(prior_file, frame))
    try:
        checked = Region.from_dict(region)
    except ConfigError as exc:
        raise ConfigError(f"{area_file or prior_file or 'region'}: {exc}") from None
    lonlat = checked.anchor
    problem = check_region(checked, float(area["size"]), _bs_of(area),
                           None if lonlat is None else f"longitude {lonlat[0]:g}, latitude "
                                                       f"{lonlat[1]:g}")
    if problem:
        blamed = prior_file if "prior" in problem and prior_file is not None else area_file
        raise ConfigError(f"{blamed or 'region'}: {problem}")
    return {**data, "area": area, "region": checked.model_dump()}


def _bs_of(area: dict[str, Any]) -> tuple[float, float]:
    bs = area.get("bs")
    if bs is None:
        size = float(area["size"])
        return size / 2, size / 2
    return float(bs[0]), float(bs[1])
