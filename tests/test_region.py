"""Missions on the map: polygon areas, holes, the BS, priors, GeoJSON and GeoTIFF files."""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from pyproj import Geod
from scipy import stats
from shapely.geometry import Point, Polygon

from polygons import areas
from sarlink import ConfigError, Mission
from sarlink.config import mission_hash
from sarlink.config.geo import Frame
from sarlink.config.region import area_polygon, zone_polygon
from sarlink.engine.scenario import draw_scenario
from sarlink.engine.streams import run_streams
from sarlink.engine.targets import target_prior

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SQUARE = [(0.0, 0.0), (3000.0, 0.0), (3000.0, 3000.0), (0.0, 3000.0)]


def polygon_mission(**region: object) -> Mission:
    return Mission.from_dict({"area": {"bs": (100.0, 100.0)},
                              "region": {"outline": SQUARE, **region}})


def test_the_papers_missions_keep_their_hashes() -> None:
    """Result folders are named by the mission hash: the square's must not change
    (values computed before regions existed, under the default reading then, sarlink-2: the
    readings named since keep their hash at the values of the older presets)."""
    assert mission_hash(Mission.build(reading="sarlink-2")) == "762e7f26a6c24ee4"
    assert mission_hash(Mission()) != "762e7f26a6c24ee4"  # sarlink-3 flies other runs
    m = Mission.build(reading="sarlink-2", planner="mtsp", drones=6, rc=500.0,
                      bs=(100.0, 200.0))
    assert mission_hash(m) == "6eb251ab8ccc731c"
    assert "region" not in Mission().model_dump_json()


def test_the_square_draws_its_targets_as_before() -> None:
    """The paper's uniform target: two uniform numbers times the side, then the offset; a
    region that only anchors the square on the map changes nothing."""
    anchored = Mission.from_dict({"region": {"anchor": (7.0, 46.0)}})
    for run in range(20):
        rng = run_streams(3, run).scenario
        x, y, offset = rng.random() * 4000, rng.random() * 4000, rng.random() * 2 * math.pi
        for mission in (Mission(), anchored):
            s = draw_scenario(mission, run_streams(3, run).scenario)
            assert s.target == (x, y) and s.heading_offset == offset


@pytest.mark.parametrize(("region", "bs", "message"), [
    ({"outline": [(0, 0), (100, 0), (0, 100), (100, 100)]}, (10, 10),
     "the outline is not a simple polygon: self-intersection at (50.0, 50.0) m"),
    ({"outline": SQUARE, "holes": [[(1000, -10), (1200, -10), (1200, 3100), (1000, 3100)]]},
     (10, 10), "hole 0 cuts the area in 2 pieces"),
    ({"outline": SQUARE, "holes": [[(1000, -10), (1200, -10), (1200, 500)]]}, (10, 10),
     "hole 0 crosses the area's outline"),
    ({"outline": SQUARE}, (-5, 10), "the BS at (-5.0, 10.0) m is outside the area"),
    ({"outline": SQUARE, "holes": [[(0, 500), (500, 500), (500, 1000)]]}, (400, 550),
     "is in a hole (a no-fly zone)"),
    ({"outline": SQUARE, "holes": [[(500, 500), (900, 500), (900, 900), (500, 900)],
                                   [(800, 800), (1000, 800), (1000, 1000)]]}, (10, 10),
     "the holes overlap or touch each other"),
    ({"outline": SQUARE, "zones": [{"outline": [(5000, 0), (6000, 0), (6000, 900)],
                                    "weight": 1.0}]}, (10, 10),
     "the target prior has no mass inside the area"),
    ({"outline": [(0, 0), (10, 0)]}, (0, 0), "needs at least 3 distinct points"),
    ({"anchor": (200.0, 46.0)}, None, "anchor must be (longitude, latitude)"),
])
def test_bad_regions_are_one_clear_sentence(region: dict, bs: tuple | None,
                                            message: str) -> None:
    with pytest.raises(ConfigError) as info:
        Mission.from_dict({"area": {"bs": bs}, "region": region})
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_a_polygon_needs_its_bs() -> None:
    with pytest.raises(ConfigError, match="needs the BS's position"):
        Mission.from_dict({"region": {"outline": SQUARE}})


def test_holes_may_be_cut_out_of_the_square() -> None:
    m = Mission.from_dict({"region": {"holes": [[(100, 100), (300, 100), (300, 300)]]}})
    assert area_polygon(m.region, m.area.size).area == pytest.approx(4000**2 - 200 * 200 / 2)


def _write(path: Path, data: object) -> Path:
    path.write_text(json.dumps(data))
    return path


def _polygon(rings: list[list[list[float]]], **props: object) -> dict:
    return {"type": "Feature", "properties": props,
            "geometry": {"type": "Polygon", "coordinates": rings}}


def _closed(ring: list[list[float]]) -> list[list[float]]:
    return [*ring, ring[0]]


def test_geojson_area_is_projected_about_the_bs(tmp_path: Path) -> None:
    """In the local frame the BS is the origin and every distance and bearing from it is
    the geodesic one on the WGS84 ellipsoid (pyproj's Geod, independent of the projection)."""
    ring = _closed([[6.99, 45.87], [7.03, 45.86], [7.06, 45.90], [7.00, 45.91]])
    bs = [7.02, 45.885]
    area = _write(tmp_path / "valley.geojson", {"type": "FeatureCollection", "features": [
        _polygon([ring], name="the valley"),
        {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": bs}}]})
    m = Mission.from_dict({"region": {"area": str(area)}})
    assert m.area.bs == (0.0, 0.0) and m.region.anchor == tuple(bs)
    assert m.region.name == "the valley"
    geod = Geod(ellps="WGS84")
    for (lon, lat), (x, y) in zip(ring, m.region.outline, strict=False):
        azimuth, _, dist = geod.inv(bs[0], bs[1], lon, lat)
        assert math.hypot(x, y) == pytest.approx(dist, abs=1e-3)  # kept to the millimetre
        assert math.degrees(math.atan2(x, y)) == pytest.approx(azimuth, abs=1e-4)


def test_frame_round_trips_to_a_millimetre() -> None:
    frame = Frame((-122.4, 37.7), (120.0, -40.0))
    x, y = np.array([-3000.0, 0.0, 2500.0]), np.array([1500.0, -2000.0, 4000.0])
    back = frame.to_local(*frame.to_lonlat(x, y))
    assert np.allclose(back, (x, y), atol=1e-3)


def test_bs_flag_overrides_the_files_point_and_anchors_a_square(tmp_path: Path) -> None:
    ring = _closed([[6.99, 45.87], [7.03, 45.86], [7.06, 45.90], [7.00, 45.91]])
    area = _write(tmp_path / "a.geojson", _polygon([ring]))
    m = Mission.from_dict({"region": {"area": str(area), "bs": [7.03, 45.89]}})
    assert m.region.anchor == (7.03, 45.89)
    square = Mission.from_dict({"region": {"bs": "7.03,45.89"}})
    assert square.region.outline is None and square.region.anchor == (7.03, 45.89)
    assert square.area.bs_xy == (2000.0, 2000.0)


@pytest.mark.parametrize(("content", "message"), [
    (_polygon([_closed([[350000.0, 5090000.0], [351000.0, 5090000.0], [351000.0, 5091000.0]])]),
     "is not a longitude/latitude in degrees"),
    ({"type": "FeatureCollection", "features": []}, "the area must be one Polygon"),
    (_polygon([_closed([[6.99, 45.87], [7.03, 45.86], [7.06, 45.90]])]), "no BS"),
    ({"type": "FeatureCollection", "features": [
        _polygon([_closed([[6.99, 45.87], [7.03, 45.86], [6.99, 45.91], [7.03, 45.91]])]),
        {"type": "Feature", "properties": {},
         "geometry": {"type": "Point", "coordinates": [7.0, 45.88]}}]},
     "the outline is not a simple polygon: self-intersection"),
    ("{not json", "not valid GeoJSON"),
    ({"type": "Polygon", "crs": {"type": "name", "properties": {"name": "EPSG:32632"}},
      "coordinates": []}, "coordinates in EPSG:32632"),
])
def test_bad_area_files_name_the_file(tmp_path: Path, content: object, message: str) -> None:
    path = tmp_path / "area.geojson"
    path.write_text(content if isinstance(content, str) else json.dumps(content))
    with pytest.raises(ConfigError) as info:
        Mission.from_dict({"region": {"area": str(path)}})
    text = str(info.value)
    assert str(path) in text and message in text and "\n" not in text


def test_a_prior_outside_the_area_names_the_prior_file(tmp_path: Path) -> None:
    ring = _closed([[6.99, 45.87], [7.03, 45.86], [7.06, 45.90], [7.00, 45.91]])
    area = _write(tmp_path / "a.geojson", _polygon([ring]))
    far = _closed([[8.0, 46.0], [8.01, 46.0], [8.01, 46.01]])
    prior = _write(tmp_path / "p.geojson", {"type": "FeatureCollection",
                                            "features": [_polygon([far], probability=1)]})
    with pytest.raises(ConfigError, match=rf"{prior}: the target prior has no mass inside"):
        Mission.from_dict({"region": {"area": str(area), "prior": str(prior),
                                      "bs": [7.02, 45.885]}})


def test_mission_files_read_region_files_beside_them(tmp_path: Path) -> None:
    (tmp_path / "m.toml").write_text('[region]\narea = "area.geojson"\nbs = [7.02, 45.885]\n')
    ring = _closed([[6.99, 45.87], [7.03, 45.86], [7.06, 45.90], [7.00, 45.91]])
    _write(tmp_path / "area.geojson", _polygon([ring]))
    m = Mission.from_toml(tmp_path / "m.toml")
    assert m.region.outline is not None and len(m.region.outline) == 5
    again = Mission.model_validate_json(m.model_dump_json())  # what workers receive
    assert again == m and mission_hash(again) == mission_hash(m)


# -- the target prior ----------------------------------------------------------------------


def _targets(mission: Mission, runs: int) -> np.ndarray:
    return np.array([draw_scenario(mission, run_streams(11, r).scenario).target
                     for r in range(runs)])


@given(areas())
def test_targets_fall_inside_the_area_and_out_of_its_holes(mission: Mission) -> None:
    area = area_polygon(mission.region, mission.area.size)
    prior = target_prior(mission)
    assert prior is not None
    rng = np.random.default_rng(0)
    for _ in range(200):
        x, y = prior.draw(rng)
        assert area.distance(Point(x, y)) < 1e-6


def test_targets_follow_a_prior_of_three_zones() -> None:
    """Chi-square goodness of fit of 6000 targets to the zones' masses inside the area:
    three zones, one sticking out of the area, one holding a hole, and the rest."""
    hole = [(1800, 1800), (2400, 1800), (2400, 2400), (1800, 2400)]
    zones = [
        {"outline": [(0, 0), (1000, 0), (1000, 1000), (0, 1000)], "weight": 0.5},
        {"outline": [(2000, -1000), (4000, -1000), (4000, 1000), (2000, 1000)], "weight": 0.3},
        {"outline": [(1500, 1500), (3000, 1500), (3000, 3000), (1500, 3000)], "weight": 0.2},
    ]
    m = polygon_mission(holes=[hole], zones=zones)
    area = area_polygon(m.region, m.area.size)
    polys = [zone_polygon(z) for z in m.region.zones]
    mass = np.array([z.weight * p.intersection(area).area / p.area
                     for z, p in zip(m.region.zones, polys, strict=True)])
    targets = _targets(m, 6000)
    counts = np.array([sum(p.covers(Point(t)) for t in targets) for p in polys])
    assert counts.sum() == len(targets)  # the zones do not overlap: every target in one
    expected = mass / mass.sum() * len(targets)
    assert stats.chisquare(counts, expected).pvalue > 1e-3
    assert not any(Polygon(hole).contains(Point(t)) for t in targets)


def test_uniform_polygon_targets_are_uniform() -> None:
    """Uniform over an L-shaped area: the counts in four quadrant pieces follow their areas."""
    outline = [(0, 0), (3000, 0), (3000, 1000), (1000, 1000), (1000, 3000), (0, 3000)]
    m = Mission.from_dict({"area": {"bs": (500.0, 500.0)}, "region": {"outline": outline}})
    area = area_polygon(m.region, m.area.size)
    cells = [Polygon([(x, y), (x + 1000, y), (x + 1000, y + 1000), (x, y + 1000)])
             for x, y in ((0, 0), (1000, 0), (2000, 0), (0, 1000), (0, 2000))]
    targets = _targets(m, 5000)
    counts = np.array([sum(c.covers(Point(t)) for t in targets) for c in cells])
    assert counts.sum() == len(targets)
    expected = np.array([c.intersection(area).area for c in cells]) / area.area * len(targets)
    assert stats.chisquare(counts, expected).pvalue > 1e-3


def test_the_example_prior_reads_its_probabilities() -> None:
    m = Mission.from_dict({"region": {"area": str(EXAMPLES / "valley.geojson"),
                                      "prior": str(EXAMPLES / "valley-prior.geojson")}})
    assert [round(z.weight, 6) for z in m.region.zones] == [0.5, 0.3, 0.2]
    assert len(m.region.holes) == 1


def test_a_geotiff_prior_weights_each_pixel(tmp_path: Path) -> None:
    """A 4 x 4 raster in longitude/latitude over the valley: each positive pixel becomes a
    zone of its value; the targets fall in the pixels in proportion to value times the part
    of the pixel inside the area (chi-square)."""
    import rasterio
    from affine import Affine

    values = np.array([[0, 1, 2, 0], [1, 4, 4, 1], [0, 2, 8, 2], [0, 0, 1, 3]], dtype="float32")
    path = tmp_path / "prior.tif"
    transform = Affine(0.01, 0.0, 7.025, 0.0, -0.01, 45.91)  # 0.01° pixels from 7.025 E, 45.91 N
    with rasterio.open(path, "w", driver="GTiff", height=4, width=4, count=1,
                       dtype="float32", crs="EPSG:4326", transform=transform) as dst:
        dst.write(values, 1)
    m = Mission.from_dict({"region": {"area": str(EXAMPLES / "valley.geojson"),
                                      "prior": str(path)}})
    assert sorted(z.weight for z in m.region.zones) == sorted(values[values > 0].tolist())
    area = area_polygon(m.region, m.area.size)
    polys = [zone_polygon(z) for z in m.region.zones]
    mass = np.array([z.weight * p.intersection(area).area / p.area
                     for z, p in zip(m.region.zones, polys, strict=True)])
    keep = mass > 0
    targets = _targets(m, 4000)
    counts = np.array([sum(p.covers(Point(t)) for t in targets) for p in polys])
    assert counts[~keep].sum() == 0
    expected = mass[keep] / mass.sum() * len(targets)
    assert stats.chisquare(counts[keep], expected).pvalue > 1e-3


def test_a_raster_without_a_crs_is_refused(tmp_path: Path) -> None:
    import rasterio

    path = tmp_path / "bare.tif"
    with warnings.catch_warnings():  # rasterio warns that it writes no georeference: the point
        warnings.simplefilter("ignore", rasterio.errors.NotGeoreferencedWarning)
        with rasterio.open(path, "w", driver="GTiff", height=2, width=2, count=1,
                           dtype="float32") as dst:
            dst.write(np.ones((2, 2), dtype="float32"), 1)
    with pytest.raises(ConfigError, match=r"bare\.tif: the raster has no coordinate"):
        Mission.from_dict({"region": {"area": str(EXAMPLES / "valley.geojson"),
                                      "prior": str(path)}})
