"""The planner registry, and the contracts every registered planner, rule, radio model and
relay strategy keeps (sarlink.testing).

Nothing here lists them: a planner, rule, radio model or relay strategy added to sarlink or
installed as a plug-in is checked by the same tests, the way VMAS tests every scenario.
"""

from __future__ import annotations

import numpy as np
import pytest

from sarlink import ConfigError, Mission, RoutePlanner, get_planner, planner_names, simulate
from sarlink.engine.radios import radio_names
from sarlink.engine.relays import relay_strategy_names
from sarlink.planners import PAPER_PLANNERS, registry
from sarlink.testing import (
    check_planner,
    check_radio,
    check_relay_strategy,
    check_rule,
    check_run,
)


def test_the_paper_planners_come_first_in_the_order_of_its_legends() -> None:
    assert PAPER_PLANNERS == ("mtsp", "covb", "conb", "mtsp-conb", "concov")
    assert tuple(planner_names()[:5]) == PAPER_PLANNERS


def test_every_planner_has_its_own_style_and_a_kind() -> None:
    planners = [get_planner(n) for n in planner_names()]
    styles = [(p.colour, p.marker) for p in planners]
    assert len(set(styles)) == len(styles)
    for p in planners:
        assert p.kind in ("route", "rule", "hybrid")
        assert (p.rule is None) == (p.kind == "route")


def test_an_unknown_planner_is_one_clear_error_naming_the_known_ones() -> None:
    with pytest.raises(ConfigError, match=r"team.planner: unknown planner 'nope'; known: mtsp, "):
        get_planner("nope")
    with pytest.raises(ConfigError, match="unknown planner 'nope'"):
        simulate(Mission.build(planner="nope"))


def _diagonal(mission: Mission) -> list[np.ndarray]:
    a = mission.area.size
    return [np.array([[a * (i + 1) / (mission.team.drones + 1)] * 2])
            for i in range(mission.team.drones)]


@pytest.mark.usefixtures("fresh_registries")
def test_a_planner_registered_in_code_flies_by_name() -> None:
    planner = RoutePlanner("diagonal", "Diagonal", _diagonal, colour="#000000", marker="x")
    assert registry.register_planner(planner) is planner
    assert planner_names()[-1] == "diagonal"
    origin = registry.planner_entries()["diagonal"].origin
    assert origin.startswith("code (") and origin.endswith("test_planners)")
    result = simulate(Mission.build(planner="diagonal", drones=3), trajectory=True)
    assert result.trajectory is not None
    # each drone flies to its point on the diagonal and lands at the BS (appended)
    bs = np.asarray(Mission().area.bs_xy)
    np.testing.assert_allclose(result.trajectory.positions[-1], np.tile(bs, (3, 1)))
    with pytest.raises(ConfigError, match="planner name 'diagonal' is taken"):
        registry.register_planner(RoutePlanner("diagonal", "Other", _diagonal))
    registry.register_planner(RoutePlanner("diagonal", "Other", _diagonal), replace=True)
    assert get_planner("diagonal").label == "Other"


@pytest.mark.parametrize("name", planner_names())
def test_every_registered_planner_keeps_the_contract(name: str) -> None:
    check_planner(name, drones=(1, 6), runs=2, horizon=1200.0, rc=500.0)


RULES = {get_planner(n).rule.name: n for n in planner_names()  # type: ignore[union-attr]
         if get_planner(n).rule is not None}
"""Every rule a registered planner flies, with one planner that flies it."""


@pytest.mark.parametrize("planner", RULES.values(), ids=RULES.keys())
def test_every_registered_rule_keeps_its_declarations(planner: str) -> None:
    check_rule(planner, runs=1, horizon=900.0)


def _channel_of(name: str, channel: dict) -> bool:
    """Whether the radio model ``name`` takes these channel settings (the disc has no fades)."""
    try:
        Mission.build(radio=name, **channel)
    except ConfigError:
        return False
    return True


CHANNELS = [{"sigma": 0.0}, *({"sigma": 4.0, "shadowing": how}
                              for how in ("correlated", "period", "run"))]
RADIOS = [(name, channel) for name in radio_names() for channel in CHANNELS
          if _channel_of(name, channel)]
"""Every registered radio model with every channel setting it takes."""


@pytest.mark.parametrize(("name", "channel"), RADIOS)
def test_every_registered_radio_model_keeps_the_contract(name: str, channel: dict) -> None:
    check_radio(name, **channel)


@pytest.mark.parametrize("name", relay_strategy_names())
def test_every_registered_relay_strategy_keeps_the_contract(name: str) -> None:
    check_relay_strategy(name, runs=1, horizon=900.0, rc=500.0)


@pytest.mark.usefixtures("fresh_registries")
def test_the_contract_catches_a_planner_that_leaves_the_area() -> None:
    """The contract can fail: a run whose drone is outside the area is caught (the route
    check already refuses waypoints outside, so the run is altered after the flight)."""
    registry.register_planner(RoutePlanner("ok", "OK", _diagonal))
    check_planner("ok", drones=(2,), runs=1, horizon=600.0)
    result = simulate(Mission.build(planner="ok", drones=2, horizon=600.0), trajectory=True)
    assert result.trajectory is not None
    result.trajectory.positions[10, 1] = (-5.0, 10.0)
    with pytest.raises(AssertionError, match="drone 1 leaves the area"):
        check_run(result, Mission.build(planner="ok", drones=2, horizon=600.0))
