"""Plug-ins end to end: rules, radio models and planners defined outside sarlink
(tests/plugins/), registered in code or found through entry points, at the engine's full
behaviour; and bad plug-ins, each reported in one line naming the plug-in."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from sarlink import (
    ConfigError,
    DistributedRule,
    Experiment,
    Mission,
    RoutePlanner,
    RulePlanner,
    get_planner,
    load,
    planner_names,
    register_planner,
    register_radio,
    simulate,
    sweep,
)
from sarlink.engine import radios
from sarlink.engine.streams import run_streams
from sarlink.planners import registry

PLUGINS = Path(__file__).parent / "plugins"
sys.path.insert(0, str(PLUGINS))
import bad  # noqa: E402
from covb_again import PLANNER  # noqa: E402
from radios_outside import CUT, FULL, HALF  # noqa: E402
from random_walk import RANDOM_WALK  # noqa: E402


@pytest.fixture(autouse=True)
def fresh_registries(monkeypatch: pytest.MonkeyPatch) -> None:
    """What a test registers does not outlive it."""
    monkeypatch.setattr(registry, "_ENTRIES", dict(registry._ENTRIES))
    monkeypatch.setattr(registry, "_BROKEN", dict(registry._BROKEN))
    monkeypatch.setattr(radios._REGISTRY, "models", dict(radios._REGISTRY.models))
    monkeypatch.setattr(radios._REGISTRY, "origins", dict(radios._REGISTRY.origins))


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
    mission = Mission.build(planner="random-walk", drones=4, horizon=300.0)
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
        "[sarlink.radios]\ncut = radios_outside:CUT\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setattr(registry, "_LOADED", False)
    monkeypatch.setattr(radios._REGISTRY, "loaded", False)
    assert "covb-again" in planner_names()
    origin = registry.planner_entries()["covb-again"].origin
    assert origin == "sarlink-testplug 1.2 (entry point covb-again)"
    assert "cut-bs" in radios.radio_names()
    with pytest.raises(ConfigError, match="plug-in broken failed to load: sarlink-testplug 1.2 "
                       r"\(entry point broken\): ModuleNotFoundError"):
        get_planner("nope")
    assert simulate(Mission.build(planner="covb-again", radio="cut-bs")).t_notify is None
    from sarlink.cli.planners import listing

    assert [b["entry_point"] for b in listing()["broken"]] == ["broken"]


# -- bad plug-ins: one line naming the plug-in and what is wrong ------------------------------


def test_a_hook_with_the_wrong_signature_is_refused_when_the_rule_is_made() -> None:
    with pytest.raises(ConfigError, match=r"rule 'few': decide\(k, p, obs, ws, deciding, vx\) "
                       "must take exactly 7 positional parameters"):
        DistributedRule("few", bad.decide_too_few)

    def local(k, p, obs, ws, deciding, vx, vy):  # type: ignore[no-untyped-def]
        pass

    with pytest.raises(ConfigError, match="rule 'local': decide must be defined at the top "
                       "level of a module"):
        DistributedRule("local", local)


def test_a_hook_that_does_not_compile_is_one_line_naming_the_rule() -> None:
    register_planner(RulePlanner("untyped", "Untyped", DistributedRule("untyped",
                                                                       bad.decide_untyped)))
    with pytest.raises(ConfigError, match="the kernel for rule 'untyped' and radio model 'disc' "
                       "does not compile") as info:
        simulate(Mission.build(planner="untyped", drones=2, horizon=100.0))
    assert "no_such_field" in str(info.value)


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
