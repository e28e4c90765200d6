"""Missions on the map from the command line: --area, --bs, --prior in simulate, replay,
export and sweep files; bad map input is one line naming the file or flag."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from shapely.geometry import Point
from typer.testing import CliRunner

from sarlink import Experiment, Mission
from sarlink.cli import app
from sarlink.cli.common import console
from sarlink.config.region import area_polygon
from sarlink.export import mission_frame

runner = CliRunner()
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
AREA = str(EXAMPLES / "valley.geojson")
PRIOR = str(EXAMPLES / "valley-prior.geojson")


def test_simulate_flies_the_example_valley(tmp_path: Path) -> None:
    out = runner.invoke(app, ["simulate", "--area", AREA, "--prior", PRIOR, "--planner", "covb",
                              "--drones", "4", "--td", "600", "--seed", "2", "--json",
                              "--plot", str(tmp_path / "run.png")])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout[:out.stdout.rindex("}") + 1])
    mission = Mission.from_dict({"region": {"area": AREA, "prior": PRIOR}})
    assert area_polygon(mission.region, 4000).contains(Point(data["target"]))
    x, y = mission_frame(mission).to_local(*data["target_lonlat"])
    assert math.dist((x, y), data["target"]) < 0.05
    assert (tmp_path / "run.png").stat().st_size > 10_000


def test_replay_draws_the_polygon_holes_and_prior(tmp_path: Path) -> None:
    page = tmp_path / "r.html"
    out = runner.invoke(app, ["replay", "--area", AREA, "--prior", PRIOR, "--planners",
                              "mtsp,covb", "--drones", "3", "--td", "300", "--out", str(page)])
    assert out.exit_code == 0, out.output
    html = page.read_text()
    assert '"holes"' in html and '"zones"' in html and '"origin"' in html


def test_export_writes_the_upload_files(tmp_path: Path) -> None:
    out = runner.invoke(app, ["export", "--area", AREA, "--planner", "mtsp", "--drones", "2",
                              "--firmware", "ardupilot", "--altitude", "80", "--out",
                              str(tmp_path / "plans")])
    assert out.exit_code == 0, out.output
    names = sorted(p.name for p in (tmp_path / "plans").iterdir())
    assert names == ["drone-00.plan", "drone-00.waypoints", "drone-01.plan",
                     "drone-01.waypoints", "fence.waypoints", "team.geojson"]
    plan = json.loads((tmp_path / "plans" / "drone-01.plan").read_text())
    assert plan["mission"]["firmwareType"] == 3
    assert [p["inclusion"] for p in plan["geoFence"]["polygons"]] == [True, False]
    assert "fence for ArduPilot" in out.stdout


def test_distributed_planners_export_their_tracks_and_say_why_no_upload(tmp_path: Path) -> None:
    out = runner.invoke(app, ["export", "--area", AREA, "--planner", "covb", "--drones", "3",
                              "--out", str(tmp_path / "plans")])
    assert out.exit_code == 0, out.output
    assert sorted(p.name for p in (tmp_path / "plans").iterdir()) == ["fence.waypoints",
                                                                      "team.geojson"]
    assert "no file can hold their flight in advance" in " ".join(out.stdout.split())
    data = json.loads((tmp_path / "plans" / "team.geojson").read_text())
    tracks = [f for f in data["features"] if f["properties"]["role"] == "simulated track"]
    assert [f["properties"]["drone"] for f in tracks] == [0, 1, 2]


def test_sweep_files_read_the_area_beside_them(tmp_path: Path) -> None:
    (tmp_path / "valley.toml").write_text(
        f'seed = 1\nruns = 3\n[mission.region]\narea = "{AREA}"\nprior = "{PRIOR}"\n'
        "[mission.timing]\nhorizon = 100\n[grid]\nplanner = ['covb', 'conb']\n")
    experiment = Experiment.from_toml(tmp_path / "valley.toml")
    assert experiment.mission.region is not None and experiment.mission.region.zones
    out = runner.invoke(app, ["sweep", str(tmp_path / "valley.toml"), "--out",
                              str(tmp_path / "res"), "--workers", "1"])
    assert out.exit_code == 0, out.output


@pytest.mark.parametrize(("args", "words"), [
    (["simulate", "--bs", "200,46"], ["--bs", "not a longitude/latitude"]),
    (["simulate", "--bs", "east"], ["--bs 'east'", "longitude,latitude"]),
    (["simulate", "--area", "{d}/missing.geojson"], ["missing.geojson: no such file"]),
    (["simulate", "--area", "{d}/utm.geojson"], ["utm.geojson", "not a longitude/latitude"]),
    (["simulate", "--area", "{d}/bowtie.geojson"], ["bowtie.geojson", "self-intersection"]),
    (["simulate", "--area", "{d}/cut.geojson"], ["cut.geojson", "cuts the area in 2 pieces"]),
    (["simulate", "--area", AREA, "--bs", "7.0,45.0"], ["valley.geojson", "outside the area"]),
    (["simulate", "--area", AREA, "--prior", "{d}/far.geojson"],
     ["far.geojson", "no mass inside the area"]),
    (["simulate", "--prior", PRIOR], ["needs the mission on the map"]),
    (["export", "--planner", "mtsp", "--drones", "2", "--out", "{d}/p"],
     ["no place on the map", "--area"]),
    (["export", "--area", AREA, "--firmware", "dji", "--out", "{d}/p"], ["--firmware 'dji'"]),
    (["export", "--area", AREA, "--altitude", "-5", "--out", "{d}/p"], ["--altitude", "> 0"]),
    (["export", "--area", AREA, "--altitude", "100000", "--out", "{d}/p"],
     ["--altitude", "at most 1000 m", "got 100000"]),
    (["export", "--area", AREA, "--battery-wh", "-1", "--out", "{d}/p"],
     ["--battery-wh (battery.battery_wh)", "greater than 0"]),
    (["export", "--area", AREA, "--battery-wh", "inf", "--out", "{d}/p"],
     ["--battery-wh (battery.battery_wh)", "finite number"]),
    (["export", "--area", AREA, "--battery-wh", "nan", "--out", "{d}/p"],
     ["--battery-wh (battery.battery_wh)", "finite number"]),
    (["export", "--area", AREA, "--battery-wh", "90", "--reserve", "1", "--out", "{d}/p"],
     ["--reserve (battery.reserve)", "less than 1"]),
    (["export", "--area", AREA, "--reserve", "-0.2", "--out", "{d}/p"],
     ["--reserve (battery.reserve)", "greater than or equal to 0"]),
    (["export", "--area", AREA, "--swap-time", "0", "--out", "{d}/p"],
     ["--swap-time (battery.swap_time)", "greater than 0"]),
    (["export", "--area", AREA, "--speed", "0", "--out", "{d}/p"],
     ["--speed (team.speed)", "greater than 0"]),
    (["export", "--area", AREA, "--energy-model", "lipo", "--out", "{d}/p"],
     ["--energy-model (battery.energy_model)", "unknown energy model 'lipo'",
      "none, zeng2019, rodrigues2021"]),
    (["export", "--area", AREA, "--energy-model", "none", "--battery-wh", "50", "--out",
      "{d}/p"], ["--energy-model (battery.energy_model) 'none' draws no power"]),
    (["export", "--area", AREA, "--planner", "mtsp", "--drones", "2", "--battery-wh", "20",
      "--out", "{d}/p"], ["--battery-wh 20: drone 0's route cannot be flown in sorties"]),
])
def test_bad_map_input_is_one_line(tmp_path: Path, args: list[str], words: list[str]) -> None:
    ring = [[6.99, 45.87], [7.03, 45.86], [7.06, 45.90], [7.00, 45.91], [6.99, 45.87]]
    bs = {"type": "Feature", "properties": {},
          "geometry": {"type": "Point", "coordinates": [7.02, 45.885]}}

    def area(rings: list) -> str:
        return json.dumps({"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {},
             "geometry": {"type": "Polygon", "coordinates": rings}}, bs]})

    (tmp_path / "utm.geojson").write_text(area([[[350000, 5090000], [351000, 5090000],
                                                 [351000, 5091000], [350000, 5090000]]]))
    (tmp_path / "bowtie.geojson").write_text(area([[[6.99, 45.87], [7.03, 45.86],
                                                    [6.99, 45.91], [7.03, 45.91],
                                                    [6.99, 45.87]]]))
    band = [[7.025, 45.80], [7.028, 45.80], [7.028, 45.95], [7.025, 45.95], [7.025, 45.80]]
    (tmp_path / "cut.geojson").write_text(area([ring, band]))
    (tmp_path / "far.geojson").write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"probability": 1.0}, "geometry": {
            "type": "Polygon", "coordinates": [[[8, 46], [8.01, 46], [8.01, 46.01], [8, 46]]]}}]}))
    out = runner.invoke(app, [a.replace("{d}", str(tmp_path)) for a in args])
    assert out.exit_code == 2, out.output
    lines = [line for line in out.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), out.output
    for word in words:
        assert word in " ".join(lines[0].split())
    assert not (tmp_path / "p").exists()  # nothing written, not even the folder


def test_export_flies_a_battery_in_sorties_and_tables_them(tmp_path: Path,
                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    """The docs' example: each sortie's files, length, duration and energy in the table, the
    battery's rule and each drone's time with swaps below it, a note above 120 m."""
    # a terminal 200 wide: the console takes its width once, from COLUMNS when it is made
    # (pytest-xdist's workers set it to 80), so the table's cells are not wrapped
    monkeypatch.setattr(console, "width", 200)
    out = runner.invoke(app, ["export", "--area", AREA, "--planner", "mtsp", "--drones", "2",
                              "--speed", "8", "--battery-wh", "70", "--energy-model",
                              "zeng2019", "--altitude", "150", "--out", str(tmp_path / "p")])
    assert out.exit_code == 0, out.output
    names = sorted(p.name for p in (tmp_path / "p").iterdir())
    assert names == [f"drone-0{i}-sortie-{k}.{ext}" for i in (0, 1) for k in (1, 2, 3)
                     for ext in ("plan", "waypoints")] + ["fence.waypoints", "team.geojson"]
    text = " ".join(out.stdout.split())
    assert "drone-01-sortie-3.plan, .waypoints" in text and " 56.0 Wh " in text
    assert "a sortie uses at most 56.0 Wh (80%)" in text and "drone 1 is done after" in text
    assert "--altitude 150 m is above the 120 m" in text
