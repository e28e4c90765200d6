"""Plug-ins end to end: rules, radio models, relay strategies and planners defined outside
sarlink (tests/plugins/), registered in code or found through entry points, at the engine's
full behaviour; one registry for every kind; the contract catching false declarations and
faulty relay strategies; and bad plug-ins, each reported in one line naming the plug-in."""

from __future__ import annotations

import importlib
import pkgutil
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from numba.core.errors import TypingError

from sarlink import (
    ConfigError,
    DistributedRule,
    Experiment,
    Mission,
    RelayStrategy,
    RoutePlanner,
    RulePlanner,
    get_planner,
    load,
    planner_names,
    register_energy_model,
    register_planner,
    register_radio,
    register_relay_strategy,
    register_target_motion,
    relay_strategy_names,
    simulate,
    sweep,
)
from sarlink.engine import RadioModel, energy, radios, relays
from sarlink.engine.radios import DISC, lognormal
from sarlink.engine.streams import run_streams
from sarlink.engine.target_motion import WALK
from sarlink.planners import registry, rules
from sarlink.registry import KINDS, adopt_plugins, plugins_in_code
from sarlink.simulation import prepare
from sarlink.testing import check_relay_strategy, check_rule

PLUGINS = Path(__file__).parent / "plugins"
sys.path.insert(0, str(PLUGINS))
import bad  # noqa: E402
from covb_again import PLANNER  # noqa: E402
from energy_outside import HEAVY  # noqa: E402
from homebound import HOMEBOUND  # noqa: E402
from liars import CLINGY  # noqa: E402
from radios_outside import CUT, FULL, HALF, IMPOSTOR  # noqa: E402
from random_walk import RANDOM_WALK  # noqa: E402
from relays_outside import FAULTY, MIDPOINT  # noqa: E402

pytestmark = pytest.mark.usefixtures("fresh_registries")  # what a test registers, it alone sees


def _same(a: Any, b: Any) -> bool:
    ra, rb = a.row(), b.row()
    return (all(np.array_equal(np.asarray(ra[k]), np.asarray(rb[k]), equal_nan=True)
                for k in ra if k not in ("planner", "radio"))
            and np.array_equal(a.trajectory.positions, b.trajectory.positions)
            and np.array_equal(a.trajectory.links, b.trajectory.links))


@pytest.mark.parametrize(("drones", "rc", "sigma"), [(10, 1000.0, 0.0), (22, 500.0, 0.0),
                                                    (4, 1000.0, 4.0)])
def test_covb_written_outside_flies_exactly_as_the_built_in(drones: int, rc: float,
                                                            sigma: float) -> None:
    register_planner(PLANNER)
    for run in range(3):
        mission = Mission.build(planner="covb", drones=drones, rc=rc, sigma=sigma)
        built_in = simulate(mission, seed=5, run=run, trajectory=True)
        plug_in = simulate(mission.replace(planner="covb-again"), seed=5, run=run,
                           trajectory=True)
        assert _same(built_in, plug_in)


def test_a_rule_draws_from_its_own_stream_of_seed_and_run() -> None:
    """A random walk's first headings are the first draws of the run's rule stream (numpy's
    own generator from ``(seed, run)``); the run is the same drawn again, another run not."""
    register_planner(RANDOM_WALK)
    mission = Mission.build(planner="random-walk", drones=4, horizon=300.0, turns="exact")
    first = simulate(mission, seed=5, run=2, trajectory=True)
    headings = first.trajectory.headings
    k = next(k for k in range(1, len(headings)) if not np.array_equal(headings[k],
                                                                     headings[k - 1]))
    np.testing.assert_allclose(np.mod(headings[k], 2 * np.pi),
                               2 * np.pi * run_streams(5, 2).rule.random(4), rtol=0, atol=1e-12)
    assert _same(first, simulate(mission, seed=5, run=2, trajectory=True))
    other = simulate(mission, seed=5, run=3, trajectory=True)
    assert not np.array_equal(first.trajectory.positions, other.trajectory.positions)


@pytest.mark.parametrize("planner", ["mtsp", "covb", "conb"])
def test_a_radio_model_from_outside_decides_every_link(planner: str) -> None:
    register_radio(CUT)
    result = simulate(Mission.build(planner=planner, drones=6, radio="cut-bs"), seed=3,
                      trajectory=True)
    assert result.t_detect is not None  # sensing does not depend on the radio
    assert result.t_notify is None and result.t_reachable(4000.0) == 0.0
    assert result.trajectory is not None
    assert not result.trajectory.links[:, :, 6].any()  # node 6 is the BS


def test_conb_predicts_with_the_radio_models_nominal_range() -> None:
    """The nominal range is what ConB predicts with: halving it changes ConB's flights but
    not CovB's; at r_c it is the disc model, run for run."""
    register_radio(HALF)
    register_radio(FULL)

    def fly(planner: str, radio: str | None) -> Any:
        return simulate(Mission.build(planner=planner, drones=6, rc=800.0, radio=radio),
                        seed=1, trajectory=True)

    assert not _same(fly("conb", "half-nominal"), fly("conb", "full-nominal"))
    assert _same(fly("covb", "half-nominal"), fly("covb", "full-nominal"))
    assert _same(fly("conb", None), fly("conb", "full-nominal"))


def test_plug_ins_of_an_installed_package_are_found_by_entry_points(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    info = tmp_path / "sarlink_testplug-1.2.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: sarlink-testplug\n"
                                   "Version: 1.2\n")
    (info / "entry_points.txt").write_text(
        "[sarlink.planners]\ncovb-again = covb_again:PLANNER\nbroken = no_such_module:X\n"
        "[sarlink.radios]\ncut = radios_outside:CUT\ndisc = radios_outside:IMPOSTOR\n"
        "not-a-radio = covb_again:PLANNER\n"
        "[sarlink.relays]\nmidpoint = relays_outside:MIDPOINT\n"
        "not-a-strategy = radios_outside:CUT\n"
        "[sarlink.energy_models]\nheavy = energy_outside:HEAVY\n"
        "not-a-model = covb_again:PLANNER\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    for kind in KINDS.values():
        monkeypatch.setattr(kind, "_loaded", False)
    assert "covb-again" in planner_names()
    origin = registry.planner_entries()["covb-again"].origin
    assert origin == "sarlink-testplug 1.2 (entry point covb-again)"
    assert "cut-bs" in radios.radio_names()
    assert relay_strategy_names() == ["tree", "midpoint"]
    assert relays.RELAY_STRATEGIES.entries()["midpoint"].origin == (
        "sarlink-testplug 1.2 (entry point midpoint)")
    with pytest.raises(ConfigError, match="plug-in broken failed to load: sarlink-testplug 1.2 "
                       r"\(entry point broken\): ModuleNotFoundError"):
        get_planner("nope")
    # each flies by name (on kernels the tests above compile: a kernel per rule and radio)
    assert simulate(Mission.build(planner="covb-again")).t_detect is not None
    assert simulate(Mission.build(planner="covb", radio="cut-bs")).t_notify is None
    from sarlink.cli.plugins import listing

    broken = {(b["kind"], b["entry_point"]): b["error"] for b in listing()["broken"]}
    assert broken.keys() == {("planner", "broken"), ("radio", "disc"), ("radio", "not-a-radio"),
                             ("relay", "not-a-strategy"), ("energy_model", "not-a-model")}
    assert "register_energy_model takes a sarlink EnergyModel" in broken[
        "energy_model", "not-a-model"]
    assert energy.ENERGY_MODELS.entries()["heavy"].origin == (
        "sarlink-testplug 1.2 (entry point heavy)")
    assert "register_relay_strategy takes a sarlink RelayStrategy" in broken[
        "relay", "not-a-strategy"]
    assert broken["radio", "disc"].endswith("radio model name 'disc' is taken (from sarlink)")
    assert "register_radio takes a sarlink RadioModel" in broken["radio", "not-a-radio"]
    assert radios.get_radio("disc") is DISC


# -- one registry for every kind ---------------------------------------------------------------


def test_a_taken_name_is_refused_without_replace_in_every_kind() -> None:
    with pytest.raises(ConfigError, match=r"radio model name 'disc' is taken \(from sarlink\); "
                       "pass replace=True"):
        register_radio(IMPOSTOR)
    with pytest.raises(ConfigError, match=r"planner name 'covb' is taken \(from sarlink\)"):
        register_planner(replace(PLANNER, name="covb"))
    with pytest.raises(ConfigError, match=r"relay strategy name 'tree' is taken \(from "
                       r"sarlink\); pass replace=True"):
        register_relay_strategy(replace(MIDPOINT, name="tree"))
    assert register_radio(DISC) is DISC and register_planner(PLANNER) is PLANNER
    assert register_planner(PLANNER) is PLANNER  # the same object again: nothing changes
    assert radios.RADIOS.entries()["disc"].origin == "sarlink"
    register_radio(IMPOSTOR, replace=True)
    assert radios.get_radio("disc") is IMPOSTOR
    assert radios.RADIOS.entries()["disc"].origin == "code (test_plugins)"


def test_only_sarlinks_own_radio_hooks_may_be_declared_range_free() -> None:
    """The range scan redraws the built-in log-normal fades whatever the model's hooks: a model
    from outside declaring range_free is refused unless its hooks are those very ones."""
    again = RadioModel("again", lognormal.init, lognormal.update, lognormal.nominal,
                       static=lognormal.static, range_free=True)
    assert register_radio(again).range_free
    with pytest.raises(ConfigError, match="radio model 'cut-bs': range_free is only for the "
                       "built-in log-normal hooks"):
        register_radio(replace(CUT, range_free=True))


def test_what_is_registered_in_code_is_adopted_by_workers_and_nothing_else() -> None:
    assert not any(plugins_in_code().values())  # the built-ins are sarlink's, not code's
    register_radio(CUT)
    register_planner(PLANNER)
    register_relay_strategy(MIDPOINT)
    register_energy_model(HEAVY)
    register_target_motion(replace(WALK, name="stroll"))
    found = plugins_in_code()
    assert {k: [e.obj.name for e in v] for k, v in found.items()} == {
        "radio": ["cut-bs"], "relay": ["midpoint"], "planner": ["covb-again"],
        "energy_model": ["heavy"], "target_motion": ["stroll"]}
    adopt_plugins(found)  # the same objects: nothing changes
    register_planner(replace(PLANNER, label="Other"), replace=True)
    with pytest.raises(ConfigError, match="planner name 'covb-again' means another planner in "
                       "the worker process than in the caller"):
        adopt_plugins(found)


def test_the_registries_hold_what_is_on_disk() -> None:
    """Every module of the built-in rules registers a planner flying its own rule, every
    built-in planner with a rule flies one of those, and the radio models sarlink registers
    are those its radio modules define."""
    modules = [importlib.import_module(f"{rules.__name__}.{m.name}")
               for m in pkgutil.iter_modules(rules.__path__)]
    assert modules and all(registry.planner_entries()[m.PLANNER.name].origin == "sarlink"
                           and m.PLANNER.rule.decide.__module__ == m.__name__ for m in modules)
    built_in = [e.obj for e in registry.planner_entries().values() if e.origin == "sarlink"]
    assert {p.rule.decide.__module__ for p in built_in if p.rule} == {m.__name__ for m in modules}
    defined = {obj.name for m in pkgutil.iter_modules(radios.__path__)
               for obj in vars(importlib.import_module(f"{radios.__name__}.{m.name}")).values()
               if isinstance(obj, RadioModel)}
    assert defined == {n for n, e in radios.RADIOS.entries().items() if e.origin == "sarlink"}
    strategies = {obj.name for m in pkgutil.iter_modules(relays.__path__)
                  for obj in vars(importlib.import_module(f"{relays.__name__}.{m.name}")).values()
                  if isinstance(obj, RelayStrategy)} | {
                      obj.name for obj in vars(relays).values() if isinstance(obj, RelayStrategy)}
    assert strategies == {n for n, e in relays.RELAY_STRATEGIES.entries().items()
                          if e.origin == "sarlink"} == {"tree"}


def test_the_contract_catches_a_rule_that_declares_range_free_but_reads_the_links() -> None:
    with pytest.raises(AssertionError, match="rule 'clingy' declares range_free but flies "
                       "differently at r_c = 300 m and 1500 m"):
        check_rule(CLINGY, runs=1, horizon=900.0)
    check_rule(replace(CLINGY, range_free=False), runs=1, horizon=900.0)  # the truth passes


def test_the_contract_catches_a_rule_that_declares_ignores_reporting_but_reads_it() -> None:
    rule = HOMEBOUND.rule
    assert rule is not None
    with pytest.raises(AssertionError, match="rule 'homebound' declares ignores_reporting but "
                       "flies differently with on_detect = report before any drone reports"):
        check_rule(replace(rule, ignores_reporting=True), runs=1, horizon=900.0)
    check_rule(rule, runs=1, horizon=900.0)


def test_the_contract_checks_that_readings_are_fields_of_readings() -> None:
    with pytest.raises(AssertionError, match=r"rule 'random-walk': readings \['conb_chek'\] "
                       "are not fields of sarlink.config.Readings"):
        check_rule(replace(RANDOM_WALK.rule, readings=("conb_chek",)), runs=1, horizon=600.0)
    check_rule(RANDOM_WALK.rule, runs=1, horizon=600.0)


def test_a_relay_strategy_from_outside_flies_by_name_and_keeps_the_contract() -> None:
    """The example of docs/plugins.md passes every check of the contract, and flies as it
    says: both relays, given one point at the same steps, fly as one, out from the BS."""
    register_relay_strategy(MIDPOINT)
    check_relay_strategy("midpoint", runs=1, horizon=900.0, rc=500.0)
    mission = Mission.build(drones=6, relays=2, relay_strategy="midpoint", rc=500.0,
                            horizon=900.0)
    traj = simulate(mission, seed=7, trajectory=True).trajectory
    assert traj is not None
    np.testing.assert_array_equal(traj.positions[:, 4], traj.positions[:, 5])
    bs = np.asarray(mission.area.bs_xy)
    assert np.hypot(*(traj.positions[:, 4] - bs).T).max() > mission.channel.rc / 2


@pytest.mark.parametrize(("alpha", "message"), [
    (0.25, r"relay strategy 'faulty', run 0 of seed 7 with 1 of 6 drones relays: place wrote "
           r"the point \(nan, [0-9.]+\) for relay 5 at step 0; a point must be finite"),
    (0.75, "relay strategy 'faulty', run 0 of seed 7 with 1 of 6 drones relays: the run "
           "differs when flown again"),
])
def test_the_contract_catches_a_faulty_relay_strategy(alpha: float, message: str) -> None:
    register_relay_strategy(FAULTY)
    with pytest.raises(AssertionError, match=message):
        check_relay_strategy("faulty", relays=(1,), runs=1, horizon=600.0, alpha=alpha)
    check_relay_strategy("faulty", relays=(1,), runs=1, horizon=600.0, alpha=0.5)  # no fault


# -- bad plug-ins: one line naming the plug-in and what is wrong ------------------------------


def test_a_hook_with_the_wrong_signature_is_refused_when_the_rule_is_made() -> None:
    with pytest.raises(ConfigError, match=r"rule 'few': decide\(k, p, obs, ws, deciding, vx\) "
                       "must take exactly 7 positional parameters"):
        DistributedRule("few", bad.decide_too_few)
    with pytest.raises(ConfigError, match=r"relay strategy 'few': place\(k, p, obs, ws, "
                       r"deciding, vx\) must take exactly 7 positional parameters"):
        RelayStrategy("few", bad.decide_too_few)

    def local(k, p, obs, ws, deciding, vx, vy):  # type: ignore[no-untyped-def]
        pass

    with pytest.raises(ConfigError, match="rule 'local': decide must be defined at the top "
                       "level of a module"):
        DistributedRule("local", local)


def test_a_hook_that_does_not_compile_is_one_line_naming_the_plug_ins() -> None:
    register_planner(RulePlanner("untyped", "Untyped", DistributedRule("untyped",
                                                                       bad.decide_untyped)))
    with pytest.raises(ConfigError, match="the kernel for rule 'untyped', radio model 'disc' "
                       "does not compile") as info:
        simulate(Mission.build(planner="untyped", drones=2, horizon=100.0))
    assert "no_such_field" in str(info.value)



def test_a_relay_kernel_that_does_not_compile_names_the_relay_strategy(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """The kernel's typing error, as Numba raises it (faked: typing the relay kernel for real
    takes minutes), becomes one line naming the rule, the radio model and the strategy."""
    register_relay_strategy(RelayStrategy("untyped", bad.decide_untyped))
    prepared = prepare(Mission.build(drones=2, relays=1, relay_strategy="untyped"))

    def kernel(*args: Any) -> None:
        raise TypingError("Unknown attribute 'no_such_field' of type Observation")

    kernel.signatures = []  # type: ignore[attr-defined]  # not compiled yet, as Numba's
    monkeypatch.setattr(type(prepared), "kernel", property(lambda self: kernel))
    with pytest.raises(ConfigError, match=r"the kernel for rule 'covb', radio model 'disc', "
                       r"relay strategy 'untyped' does not compile .*no_such_field"):
        prepared.run(0, 0)


@pytest.mark.parametrize(("routes", "message"), [
    (bad.routes_raise, "planner 'bad': its route function raised RuntimeError: the solver "
                       "licence expired"),
    (bad.routes_outside, r"planner 'bad': route of drone 0 leaves the area at waypoint "
                         r"\(4050, 10\); the area is \[0, 4000\]²"),
    (bad.routes_too_few, "planner 'bad': gave 1 routes for 3 drones; 3 expected"),
])
def test_bad_routes_are_one_line_naming_the_planner(routes: Any, message: str) -> None:
    register_planner(RoutePlanner("bad", "Bad", routes))
    with pytest.raises(ConfigError, match=message):
        simulate(Mission.build(planner="bad", drones=3))


def test_a_sweep_keeps_every_finished_run_when_a_plug_in_fails(tmp_path: Path) -> None:
    register_planner(RoutePlanner("bad", "Bad", bad.routes_raise))
    experiment = Experiment(name="plug", seed=1, runs=4, chunk=2,
                            mission=Mission.build(drones=2, horizon=300.0),
                            grid={"planner": ["covb", "bad"]})
    with pytest.raises(ConfigError, match="planner 'bad': its route function raised"):
        sweep(experiment, tmp_path / "out", workers=1)
    kept = load(tmp_path / "out")
    assert set(kept["planner"]) <= {"covb"} and len(kept) in (2, 4)  # whole chunks
    register_planner(RoutePlanner("bad", "Bad", bad.routes_diagonal), replace=True)
    done = sweep(experiment, tmp_path / "out", workers=1)  # fixed: the sweep resumes
    assert len(done) == 8
    again = done.set_index(["planner", "run"]).loc[kept.set_index(["planner", "run"]).index]
    np.testing.assert_array_equal(again["t_detect"], kept.set_index(["planner", "run"])["t_detect"])
