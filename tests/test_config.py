"""Configuration: the paper's defaults, clear errors naming the field, flat views, files."""

from __future__ import annotations

import pytest

from sarlink import ConfigError, Mission


def test_defaults_are_the_papers_table_3() -> None:
    m = Mission()
    assert (m.area.size, m.team.speed, m.sensing.r, m.timing.ts, m.team.flight_time) == (
        4000, 5, 500, 2, 4000)
    assert m.area.bs_xy == (2000, 2000)  # centre: every drone one hop away at r_c ~ 2800 m
    assert (m.team.alpha, m.team.nr, m.channel.pathloss_exponent) == (0.5, 6, 1.75)
    assert (m.mtsp.population, m.mtsp.iterations) == (80, 5000)


@pytest.mark.parametrize(
    ("params", "field", "allowed"),
    [
        ({"drones": 0}, "team.drones", "greater than or equal to 1"),
        ({"rc": -5.0}, "channel.rc", "greater than 0"),
        ({"r": 0.0}, "sensing.r", "greater than 0"),
        ({"alpha": 1.5}, "team.alpha", "less than or equal to 1"),
        ({"p_miss": -0.1}, "sensing.p_miss", "greater than or equal to 0"),
        ({"bs": (5000.0, 10.0)}, "area", "inside the area"),
        ({"dt": 3.0}, "timing.dt", "at most timing.ts"),
        ({"horizon": 10.5}, "timing.horizon", "multiple of timing.dt"),
        ({"look": "sometimes"}, "sensing.look", "per-pass"),
        ({"speed": float("nan")}, "team.speed", "finite"),
        ({"sigma": 50.0}, "channel.sigma", "less than or equal to 30"),
        ({"stop": "never"}, "timing.stop", "horizon"),
    ],
)
def test_bad_values_name_the_field_and_the_range(params: dict, field: str, allowed: str) -> None:
    with pytest.raises(ConfigError) as info:
        Mission.build(**params)
    assert field in str(info.value)
    assert allowed in str(info.value)


def test_unknown_parameter_lists_the_known_ones() -> None:
    with pytest.raises(ConfigError, match=r"unknown mission parameter 'drone'.*drones"):
        Mission.build(drone=3)


def test_flat_view_round_trips_and_missions_hash_by_value() -> None:
    m = Mission.build(drones=22, rc=500.0, planner="conb", p_miss=0.2)
    assert Mission.build(**m.params()) == m
    assert hash(Mission.build(drones=22, rc=500.0, planner="conb", p_miss=0.2)) == hash(m)
    assert m.replace(drones=10) != m
    with pytest.raises(ValueError, match="frozen"):
        m.team.drones = 3  # type: ignore[misc]


def test_toml_file_is_checked(tmp_path) -> None:
    good = tmp_path / "m.toml"
    good.write_text('[team]\nplanner = "concov"\ndrones = 22\n[channel]\nrc = 500\n')
    m = Mission.from_toml(good)
    assert (m.team.planner, m.team.drones, m.channel.rc) == ("concov", 22, 500)
    bad = tmp_path / "bad.toml"
    bad.write_text("[team]\ndrones = 22\nspeeed = 4\n")
    with pytest.raises(ConfigError, match=r"team\.speeed: Extra inputs are not permitted"):
        Mission.from_toml(bad)


def test_toml_syntax_errors_name_the_file(tmp_path) -> None:
    broken = tmp_path / "broken.toml"
    broken.write_text("[team\ndrones = 3\n")
    with pytest.raises(ConfigError, match=r"broken\.toml"):
        Mission.from_toml(broken)
