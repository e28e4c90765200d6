"""The readings of the paper: each rule variant on a hand-placed case that only it passes, and
the presets (docs/model.md, Readings).

Drones are placed by hand around a BS at the centre (2000, 2000) and fly 5 m per 1 s step; the
take-off counts as a direction change at t = 0, so the first periodic update is at step 2 and
a recorded heading at step k + 1 is the one decided at step k.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from phase_inputs import padded, params
from sarlink import ConfigError, Mission, Scenario, load, prepare, simulate
from sarlink.cli import app
from sarlink.config import DEFAULT_READING, READINGS, Experiment, Readings
from sarlink.engine import Prepared, Steering
from sarlink.engine.codes import SHADOWING_CODES, Mode
from sarlink.engine.radios import lognormal
from sarlink.engine.scenario import draw_scenario
from sarlink.engine.streams import plan_seed, run_streams
from sarlink.paper import ReproductionResult, reproduce
from sarlink.paper.experiments import EXPERIMENTS
from sarlink.paper.variants import SYMBOL, reaches, variants
from sarlink.planners import get_planner
from sarlink.planners.rules.conb import CONB

FAR_TARGET = (100.0, 3900.0)  # never sensed in these few steps


def _headings(planner: str, positions: list[tuple[float, float]], angles: list[float],
              steps: int = 6, **choices: object) -> np.ndarray:
    """The recorded headings of a hand-placed team as unit vectors ``(step, drone, 2)``:
    unless ``choices`` say otherwise, every commanded turn flown exactly and a vanishing
    Eq. 9 turning to θ_ij, so that a heading is one number the test can work out."""
    mission = Mission.build(planner=planner, drones=len(positions), horizon=float(steps),
                            **{"turns": "exact", "conb_fallback": "contact", **choices})
    scenario = Scenario(target=FAR_TARGET, positions=np.array(positions),
                        headings=np.array(angles))
    trajectory = simulate(mission, scenario=scenario, trajectory=True).trajectory
    assert trajectory is not None
    return np.stack([np.cos(trajectory.headings), np.sin(trajectory.headings)], axis=-1)


def test_the_continuous_check_turns_a_drone_about_to_leave_at_once() -> None:
    """A lone ConB drone 996 m east of the BS flies east: one increment on, it is 1001 m away,
    out of r_c = 1000 m. Checked at every increment, it turns at step 0 towards its only
    contact, the BS (Eq. 9's two unit terms cancel: it turns to θ_ij, due west); checked only
    when t_s has elapsed, at step 2 it has no neighbour left and flies on east."""
    args = ("conb", [(2996.0, 2000.0)], [0.0])
    continuous = _headings(*args, rc=1000.0, conb_check="continuous")
    period = _headings(*args, rc=1000.0, conb_check="period")
    assert continuous[1, 0] == pytest.approx((-1.0, 0.0))
    assert period[1:, 0] == pytest.approx(np.tile((1.0, 0.0), (len(period) - 1, 1)))


def test_contacts_all_follows_the_longest_contact_even_without_a_route() -> None:
    """Drone 0 (at 3885 m, flying east) will lose its only routed neighbour, drone 1 (flying
    west, 975 m away, towards the BS). Drone 2, 600 m north of drone 0, flies with it (equal
    velocities: the contact never ends) but has no route to the BS. Among routed neighbours
    (``routed``) drone 0 turns back towards drone 1 (the terms cancel: due west); among all
    (``all``) it keeps on with drone 2, nearly east."""
    positions = [(3885.0, 2000.0), (2910.0, 2000.0), (3885.0, 2600.0)]
    angles = [0.0, math.pi, 0.0]
    routed = _headings("conb", positions, angles, rc=1000.0, conb_check="period",
                       contacts="routed")
    every = _headings("conb", positions, angles, rc=1000.0, conb_check="period", contacts="all")
    assert routed[3, 0] == pytest.approx((-1.0, 0.0))
    # towards where drone 2 will be at T_max, from drone 0's next position, plus the heading
    cx, cy = 3895.0 + 5.0 * 4000.0, 2600.0
    dx, dy = cx - 3900.0, cy - 2000.0
    ux, uy = dx / math.hypot(dx, dy), dy / math.hypot(dx, dy)
    rx, ry = 1.0 + ux, uy
    assert every[3, 0] == pytest.approx((rx / math.hypot(rx, ry), ry / math.hypot(rx, ry)))


def test_an_isolated_drone_keeps_its_heading_or_turns_home() -> None:
    """A lone ConB drone 1500 m east of the BS (r_c = 500 m) flies north with no neighbour:
    at its update (step 2) it keeps its heading, or turns to the BS with ``isolated = home``."""
    args = ("conb", [(3500.0, 2000.0)], [math.pi / 2])
    keep = _headings(*args, rc=500.0, conb_check="period", isolated="keep")
    home = _headings(*args, rc=500.0, conb_check="period", isolated="home")
    assert keep[3, 0] == pytest.approx((0.0, 1.0))
    x, y = 3500.0, 2000.0 + 2 * 5.0  # where it is at step 2
    d = math.hypot(2000.0 - x, 2000.0 - y)
    assert home[3, 0] == pytest.approx(((2000.0 - x) / d, (2000.0 - y) / d))
    assert home[1:3, 0] == pytest.approx(np.array([(0.0, 1.0)] * 2))  # it flies on between updates


def test_a_vanishing_concov_resultant_keeps_the_heading_or_follows_connectivity() -> None:
    """A lone ConCov drone flies east, 995 m from the BS at its update (r_c = 1000 m) and out of
    range at t + t_s: CovB's term is its heading (no neighbour within r), ConB's points back to
    the BS, and with α = 0.5 Eq. 12 is exactly zero. It keeps its heading or, with
    ``concov_fallback = connectivity``, turns back with the connectivity term."""
    args = ("concov", [(2985.0, 2000.0)], [0.0])
    heading = _headings(*args, rc=1000.0, concov_fallback="heading")
    connectivity = _headings(*args, rc=1000.0, concov_fallback="connectivity")
    assert heading[3, 0] == pytest.approx((1.0, 0.0))
    assert connectivity[3, 0] == pytest.approx((-1.0, 0.0))


def test_a_connected_concov_drone_with_no_connectivity_term_follows_coverage() -> None:
    """Two ConCov drones near the BS (both routed), 200 m apart east-west, fly north. Drone 0's
    CovB resultant (Eq. 6) is its heading / r plus drone 1's push; with ``concov_connected =
    heading`` Eq. 12 adds its heading as R_con (Algorithm 2), with ``none`` nothing."""
    positions = [(2200.0, 2000.0), (2400.0, 2000.0)]
    angles = [math.pi / 2, math.pi / 2]
    with_heading = _headings("concov", positions, angles, concov_connected="heading")
    without = _headings("concov", positions, angles, concov_connected="none")
    y = 2000.0 + 2 * 5.0  # both at step 2
    fx, fy = 0.0 + (2200.0 - 2400.0) / 200.0**2, 1.0 / 500.0 + (y - y) / 200.0**2
    cx, cy = fx / math.hypot(fx, fy), fy / math.hypot(fx, fy)
    bx, by = 0.5 * cx, 0.5 * cy + 0.5
    assert without[3, 0] == pytest.approx((cx, cy))
    assert with_heading[3, 0] == pytest.approx((bx / math.hypot(bx, by),
                                                by / math.hypot(bx, by)))


def test_the_default_reading_is_what_a_mission_gives() -> None:
    assert Mission().readings.model_dump() == READINGS[DEFAULT_READING].choices
    for reading in READINGS.values():
        assert set(reading.choices) == set(Readings.model_fields)


def test_a_reading_preset_sets_the_choices_and_explicit_values_win() -> None:
    literal = Mission.build(reading="literal")
    assert literal.readings.model_dump() == READINGS["literal"].choices
    assert Mission.build(reading="literal", contacts="routed").readings.contacts == "routed"
    with pytest.raises(ConfigError, match="unknown reading 'nope'; known: literal, sarlink-1"):
        Mission.build(reading="nope")


def test_readings_reach_only_the_planners_whose_rules_they_change() -> None:
    """CovB and mTSP runs are the same under the presets that differ only in ConB's and
    ConCov's choices (``literal``, ``sarlink-1``, ``sarlink-2``), and the sensitivity
    analysis says those choices do not reach them."""
    older = ("literal", "sarlink-1", "sarlink-2")
    for planner in ("covb", "mtsp"):
        experiment = Experiment(seed=0, runs=1, mission=Mission.build(planner=planner))
        assert {c for c in reaches(get_planner(planner), experiment)
                if len({READINGS[r].choices[c] for r in older}) > 1} == set()
        runs = {name: simulate(Mission.build(reading=name, planner=planner, drones=4,
                                             rc=500.0, horizon=1500.0), seed=5, run=1)
                for name in older}
        first, *rest = runs.values()
        assert all(r.t_notify == first.t_notify and r.t_detect == first.t_detect and
                   np.array_equal(r.reach_cum, first.reach_cum) for r in rest)


# -- the readings in a reproduction -----------------------------------------------------------


def test_the_variants_change_one_choice_to_each_other_value() -> None:
    names = [v.name for v in variants(READINGS["sarlink-1"])]
    assert names == ["conb_check=continuous", "contacts=all", "isolated=home",
                     "concov_fallback=connectivity", "concov_connected=none", "takeoff=random",
                     "takeoff=jitter", "conb_fallback=heading", "conb_fallback=limit",
                     "turns=jitter", "covb_direction=printed", "shadowing=run",
                     "shadowing=correlated", "shadow_calibration=mean-area", "parked=base",
                     "reachability=multihop", "mtsp_plan=per-run", "mtsp_prediction=paths",
                     "td_fig3=1000", "td_fig3=4000"]
    assert [v.name for v in variants(READINGS["literal"])][:2] == ["conb_check=period",
                                                                   "contacts=routed"]


@pytest.fixture(scope="module")
def study(tmp_path_factory: pytest.TempPathFactory) -> ReproductionResult:
    """Fig. 7 (its sweeps stop early: seconds) with the sensitivity analysis, 3 runs a point."""
    return reproduce(tmp_path_factory.mktemp("sensitivity"), runs=3, figures=[7],
                     progress=False, workers=1, reading="sarlink-1", sensitivity_analysis=True)


def test_a_change_reruns_only_the_planners_it_reaches(study: ReproductionResult) -> None:
    folders = {p.name: sorted(f.name for f in p.iterdir())
               for p in (study.out / "runs" / "miss").iterdir()}
    experiment = EXPERIMENTS["miss"].build(3)

    def presets(planner: str) -> set[str]:  # the report tallies the claims under each preset
        reach = reaches(get_planner(planner), experiment)
        return {"-".join(r.choices[c] for c in reach) for r in READINGS.values()}

    # CovB: the take-off, Eq. 8's direction, reachability, the turns, parked drones
    assert folders["covb"] == sorted({
        "even-push-direct-exact-relay", "random-push-direct-exact-relay",
        "jitter-push-direct-exact-relay", "even-printed-direct-exact-relay",
        "even-push-multihop-exact-relay", "even-push-direct-jitter-relay",
        "even-push-direct-exact-base"} | presets("covb"))
    # mTSP: reachability, the plan, parked drones
    assert folders["mtsp"] == sorted({"direct-shared-relay", "multihop-shared-relay",
                                      "direct-per-run-relay", "direct-shared-base"}
                                     | presets("mtsp"))
    assert folders["conb"] == sorted({
        "period-routed-keep-even-contact-direct-exact-relay",
        "continuous-routed-keep-even-contact-direct-exact-relay",
        "period-all-keep-even-contact-direct-exact-relay",
        "period-routed-home-even-contact-direct-exact-relay",
        "period-routed-keep-random-contact-direct-exact-relay",
        "period-routed-keep-jitter-contact-direct-exact-relay",
        "period-routed-keep-even-heading-direct-exact-relay",
        "period-routed-keep-even-limit-direct-exact-relay",
        "period-routed-keep-even-contact-multihop-exact-relay",
        "period-routed-keep-even-contact-direct-jitter-relay",
        "period-routed-keep-even-contact-direct-exact-base"} | presets("conb"))
    base = READINGS["sarlink-1"].choices
    for planner, singles in (("mtsp-conb", 13), ("concov", 14)):  # the reading and its changes
        reach = reaches(get_planner(planner), experiment)
        changed = {"-".join({**base, v.choice: v.value}[c] for c in reach)
                   for v in study.variants if v.choice in reach}
        assert len(changed | {"-".join(base[c] for c in reach)}) == singles
        assert folders[planner] == sorted(changed | {"-".join(base[c] for c in reach)}
                                          | presets(planner))


def test_a_changed_reading_s_runs_are_those_of_its_missions(study: ReproductionResult) -> None:
    """The stored runs of ConB under the continuous check are those simulated directly."""
    runs = load(study.out / "runs" / "miss" / "conb" /
                "continuous-routed-keep-even-contact-direct-exact-relay")
    for row in runs.itertuples():
        mission = Mission.build(reading="sarlink-1", conb_check="continuous", planner="conb",
                                drones=10, rc=500.0, horizon=1000.0, stop="detected",
                                p_miss=row.p_miss)
        direct = simulate(mission, seed=row.seed, run=row.run)
        assert (direct.t_detect or math.nan) == pytest.approx(row.t_detect, nan_ok=True)


def test_the_report_holds_the_matrix_and_every_flip(study: ReproductionResult) -> None:
    matrix = pd.read_csv(study.out / "tables" / "sensitivity.csv")
    changes = [v.name for v in study.variants]
    assert list(matrix.columns) == ["figure", "claim", "default", *changes]
    assert list(matrix["default"]) == [SYMBOL[f.outcome] for f in study.findings]
    flipped = int((matrix[changes].to_numpy() != matrix[["default"]].to_numpy()).sum())
    md = study.report_md.read_text()
    section = md[md.index("## What each finding depends on"):].split("\n## ")[0]
    assert f"Flipped outcomes ({flipped})" in section
    assert section.count("\n- ") == max(flipped, 1)


def test_reproduce_names_an_unknown_reading(tmp_path: Path) -> None:
    out = CliRunner().invoke(app, ["reproduce", "--reading", "nope", "--out", str(tmp_path)])
    assert out.exit_code == 2
    assert "unknown reading 'nope'; known: literal, sarlink-1" in out.output


# -- the choices named by issue 23 --------------------------------------------------------------


def _takeoff(takeoff: str, seed: int = 4, run: int = 3, drones: int = 6) -> np.ndarray:
    """The recorded take-off headings (step 0) of a CovB team under ``takeoff``."""
    mission = Mission.build(planner="covb", drones=drones, horizon=2.0, takeoff=takeoff)
    trajectory = simulate(mission, seed=seed, run=run, trajectory=True).trajectory
    assert trajectory is not None
    return np.asarray(trajectory.headings[0])


def test_the_take_off_is_even_random_or_jittered_from_the_run_s_streams() -> None:
    """``even``: exactly 2πk/N plus the run's offset; ``random``: 2π u with u the take-off
    stream's numbers, one per drone; ``jitter``: even, each off by (2u - 1) · 5°. Each reading
    matches only its own formula."""
    n = 6
    offset = draw_scenario(Mission(), run_streams(4, 3).scenario).heading_offset
    u = run_streams(4, 3).takeoff.random(n)
    even = 2 * math.pi * np.arange(n) / n + offset
    formulas = {"even": even, "random": 2 * math.pi * u,
                "jitter": even + math.radians(5.0) * (2 * u - 1)}

    def same(a: np.ndarray, b: np.ndarray) -> bool:
        return bool(np.allclose(np.cos(a), np.cos(b), atol=1e-12)
                    and np.allclose(np.sin(a), np.sin(b), atol=1e-12))

    for takeoff in formulas:
        got = _takeoff(takeoff)
        assert [name for name, want in formulas.items() if same(got, want)] == [takeoff]
    jitter = _takeoff("jitter")
    assert np.abs(np.angle(np.exp(1j * (jitter - even)))).max() <= math.radians(5.0)


def test_conb_s_vanishing_resultant_turns_to_the_contact_or_keeps_the_heading() -> None:
    """A lone ConB drone 996 m east of the BS flies straight away from it: checked at every
    increment, it decides at once and Eq. 9's unit terms cancel exactly (θ_ij points back to
    the BS). ``contact`` turns it to θ_ij, due west; ``heading`` keeps it flying east."""
    args = ("conb", [(2996.0, 2000.0)], [0.0])
    contact = _headings(*args, rc=1000.0, conb_check="continuous", conb_fallback="contact")
    heading = _headings(*args, rc=1000.0, conb_check="continuous", conb_fallback="heading")
    assert contact[1, 0] == pytest.approx((-1.0, 0.0))
    assert heading[1:, 0] == pytest.approx(np.tile((1.0, 0.0), (len(heading) - 1, 1)))


def test_conb_s_vanishing_resultant_in_the_limit_turns_a_right_angle_to_a_drawn_side() -> None:
    """The same drone under ``limit``: Eq. 9's resultant for a heading α off due east has
    length 2|sin(α/2)| and points 90° - α/2 from the heading, so as α vanishes it turns a
    right angle, north or south, by the first draw of the run's rule stream (below 1/2:
    north); over runs both sides come."""
    sides = set()
    for run in range(8):
        got = _single_turn(run, conb_fallback="limit")
        north = run_streams(0, run).rule.random() < 0.5
        assert got == pytest.approx((0.0, 1.0 if north else -1.0))
        sides.add(north)
    assert sides == {True, False}
    alpha = 1e-3  # the equation itself, a little off the limit: 90° - α/2 from the heading
    rx, ry = math.cos(alpha) + math.cos(math.pi), math.sin(alpha) + math.sin(math.pi)
    assert math.hypot(rx, ry) == pytest.approx(2 * math.sin(alpha / 2))
    assert math.atan2(ry, rx) - alpha == pytest.approx(math.pi / 2 - alpha / 2)


def _single_turn(run: int, **choices: object) -> tuple[float, float]:
    """The heading flown after the first decision of a lone ConB drone 996 m east of the BS
    flying east (the decision comes at once: checked at every increment, its route is lost)."""
    mission = Mission.build(planner="conb", drones=1, horizon=3.0, rc=1000.0,
                            conb_check="continuous", **{"turns": "exact", **choices})
    scenario = Scenario(target=FAR_TARGET, positions=np.array([(2996.0, 2000.0)]),
                        headings=np.array([0.0]))
    trajectory = simulate(mission, scenario=scenario, seed=0, run=run,
                          trajectory=True).trajectory
    assert trajectory is not None
    return (math.cos(trajectory.headings[1, 0]), math.sin(trajectory.headings[1, 0]))


def test_a_commanded_turn_is_flown_exactly_or_off_by_the_run_s_heading_error() -> None:
    """The lone ConB drone turns back to the BS (``contact``): with ``turns = exact`` it flies
    due west; with ``jitter`` due west rotated by (2u - 1) · 5°, u the first number of the
    run's heading stream; a drone that keeps its heading (a CovB drone alone) draws nothing."""
    for run in range(4):
        assert _single_turn(run, conb_fallback="contact") == pytest.approx((-1.0, 0.0))
        e = math.radians(5.0) * (2 * run_streams(0, run).heading.random() - 1)
        got = _single_turn(run, conb_fallback="contact", turns="jitter")
        assert got == pytest.approx((math.cos(math.pi + e), math.sin(math.pi + e)), abs=1e-12)
    alone = _headings("covb", [(2200.0, 2000.0)], [math.pi / 2], turns="jitter")
    assert alone[1:, 0] == pytest.approx(np.tile((0.0, 1.0), (len(alone) - 1, 1)))


def test_eq_8_pushes_as_the_text_says_or_pulls_as_printed() -> None:
    """Two CovB drones 200 m apart east-west fly north (r = 500 m). At the update (step 2)
    drone 0's Eq. 6 is its heading / r plus (1/d) θ̂: θ from drone 1 to drone 0 (``push``,
    westwards) or from drone 0 to drone 1 as Eq. 8 is printed (``printed``, eastwards)."""
    positions = [(2200.0, 2000.0), (2400.0, 2000.0)]
    angles = [math.pi / 2, math.pi / 2]
    push = _headings("covb", positions, angles, covb_direction="push")
    pull = _headings("covb", positions, angles, covb_direction="printed")
    for got, sign in ((push, -1.0), (pull, 1.0)):
        fx, fy = sign / 200.0, 1.0 / 500.0
        assert got[3, 0] == pytest.approx((fx / math.hypot(fx, fy), fy / math.hypot(fx, fy)))


def _reach(reachability: str, positions: list[tuple[float, float]]) -> float:
    """Seconds the target at (2600, 2000), 600 m from the BS, was reachable in 10 s."""
    mission = Mission.build(planner="covb", drones=len(positions), horizon=10.0,
                            checkpoint=10.0, reachability=reachability)
    scenario = Scenario(target=(2600.0, 2000.0), positions=np.array(positions),
                        headings=np.full(len(positions), math.pi / 2))
    return float(simulate(mission, scenario=scenario).reach_cum[-1])


def test_reachability_counts_a_direct_target_bs_link_or_only_routes_over_drones() -> None:
    """The target 600 m from the BS (r_c = 1000 m), the only drone far away in a corner: a
    direct link makes it reachable all 10 s (``direct``), never over the drones
    (``multihop``). With a drone between them both count it."""
    far = [(200.0, 200.0)]
    assert _reach("direct", far) == 10.0
    assert _reach("multihop", far) == 0.0
    between = [(2300.0, 1500.0)]  # 580 m from the BS, 583 m from the target, flying north
    assert _reach("direct", between) == _reach("multihop", between) == 10.0


def _parked(parked: str, reachability: str = "multihop") -> tuple[float, float]:
    """Seconds of 10 the target at (2600, 2000), 600 m from the BS, was reachable, and the
    mean share of drones connected, for one CovB drone 10 m north of the BS whose 3 s of
    flight send it home at once: it is parked at the BS from step 2 on."""
    mission = Mission.build(planner="covb", drones=1, horizon=10.0, checkpoint=10.0,
                            flight_time=3.0, reachability=reachability, parked=parked)
    scenario = Scenario(target=(2600.0, 2000.0), positions=np.array([(2000.0, 2010.0)]),
                        headings=np.array([math.pi / 2]))
    result = simulate(mission, scenario=scenario, trajectory=True)
    assert result.trajectory is not None
    assert list(result.trajectory.mode[:4, 0]) == [Mode.SEARCHING, Mode.RETURNING, Mode.LANDED,
                                                   Mode.LANDED]
    return float(result.reach_cum[-1]), result.connected_fraction()


def test_a_parked_drone_relays_like_any_other_or_is_part_of_the_bs() -> None:
    """Landed at step 2, the drone is 600 m from the target (r_c = 1000 m). ``relay``: it
    keeps the target reachable over the drones and counts as connected all 10 s. ``base``:
    it is the BS, so only its 2 s in the air count for multihop reachability and for the
    connected share, while a direct target-BS link counts all 10 s as it would anyway."""
    assert _parked("relay") == (10.0, 1.0)
    assert _parked("base") == (2.0, 0.2)
    assert _parked("base", "direct") == (10.0, 0.2)


def test_shadowing_per_period_per_run_or_correlated_with_the_distance_flown() -> None:
    """The fades of a 3-drone team (5 nodes) at r_c = 1000 m, sigma = 3 dB, step by step:
    ``period`` redraws every coherence time (2 steps), ``run`` never after step 0,
    ``correlated`` keeps exp(-k V dt / d_c) of each link's normal state per step, k its
    drone ends (the BS-target link, k = 0, never changes), from the same normal numbers."""
    m, n, steps, seed = 5, 3, 6, 9
    upper = np.triu_indices(m, 1)

    def fades(shadowing: str) -> list[np.ndarray]:
        p = params(rc=1000.0, sigma=3.0, shadowing=int(SHADOWING_CODES[shadowing]))
        thr2 = lognormal.init(p, np.zeros(0), m, padded(m))
        rng, out = np.random.default_rng(seed), []
        for k in range(steps):
            lognormal.update(thr2, p, np.zeros(0), k, rng)
            out.append(-5.0 * p.pathloss_exponent * np.log10(thr2[:m, :m][upper] / 1e6) / 3.0)
        return out

    normals = np.random.default_rng(seed).standard_normal((steps, len(upper[0])))
    period, run, correlated = fades("period"), fades("run"), fades("correlated")
    for k in range(steps):
        np.testing.assert_allclose(period[k], normals[k // 2], atol=1e-9)
        np.testing.assert_allclose(run[k], normals[0], atol=1e-9)
    ends = np.array([int(a < n) + int(b < n) for a, b in zip(*upper, strict=True)])
    rho = np.exp(-ends * 5.0 * 1.0 / 50.0)
    z = normals[0]
    np.testing.assert_allclose(correlated[0], z, atol=1e-9)
    for k in range(1, steps):
        z = rho * z + np.sqrt(1 - rho**2) * normals[k]
        np.testing.assert_allclose(correlated[k], z, atol=1e-9)
    assert correlated[-1][ends == 0] == pytest.approx(normals[0][ends == 0])


def test_r_c_is_the_median_link_range_or_the_one_of_the_mean_link_area() -> None:
    """Eq. 13's squared link range is r_c² exp(-S ln10 / 5n), log-normal: its mean is
    exp(s²/2) r_c² with s = sigma ln10 / 5n (1.37 at sigma = 3 dB, n = 1.75) when r_c is the
    median range; ``mean-area`` makes the mean link area the disc's, pi r_c²."""
    m = 200
    s = 3.0 * math.log(10) / (5 * 1.75)
    for calibration, mean in (("median", math.exp(s * s / 2)), ("mean-area", 1.0)):
        p = params(rc=1000.0, sigma=3.0, shadowing=int(SHADOWING_CODES["run"]),
                   fade_bias=lognormal.fade_bias(3.0, 1.75, calibration))
        thr2 = lognormal.init(p, np.zeros(0), m, padded(m))
        lognormal.update(thr2, p, np.zeros(0), 0, np.random.default_rng(5))
        area = thr2[:m, :m][np.triu_indices(m, 1)] / 1e6
        assert area.mean() == pytest.approx(mean, abs=4 * area.std() / math.sqrt(area.size))
        assert np.median(area) == pytest.approx(math.exp(-s * s / 2) ** (calibration != "median"),
                                                rel=0.03)


def test_correlated_fades_are_stationary_normal_and_the_same_at_every_range() -> None:
    """After many steps a link's correlated fade is still N(0, 1) in z (Gauss-Markov keeps
    the variance), with the lag-one correlation exp(-2 V dt / d_c) of a drone-drone link; the
    fades do not depend on r_c (issue 22's coupling across ranges relies on it)."""
    m, steps = 4, 4000

    def zs(rc: float) -> np.ndarray:
        p = params(rc=rc, sigma=3.0, shadowing=int(SHADOWING_CODES["correlated"]))
        thr2 = lognormal.init(p, np.zeros(0), m, padded(m))
        rng, out = np.random.default_rng(1), []
        for k in range(steps):
            lognormal.update(thr2, p, np.zeros(0), k, rng)
            out.append(np.log(thr2[0, 1] / rc**2))
        return np.array(out)

    a, b = zs(500.0), zs(2000.0)
    np.testing.assert_allclose(a, b, rtol=1e-9, atol=1e-12)
    z = a / (-math.log(10) / (5 * 1.75) * 3.0)
    rho = math.exp(-2 * 5.0 / 50.0)
    assert np.corrcoef(z[:-1], z[1:])[0, 1] == pytest.approx(rho, abs=0.03)
    # z's variance over 4000 steps of an AR(1) with rho = 0.82: ~400 effective samples
    assert z.var() == pytest.approx(1.0, abs=0.25)


def test_a_run_s_own_mtsp_plan_is_the_plan_seeded_from_seed_and_run() -> None:
    """``per-run``: run k flies the plan of ``plan_seed(seed, k)``, different from run to run;
    ``shared``: every run flies the mission's one plan."""
    small = {"planner": "mtsp", "drones": 3, "iterations": 200, "horizon": 1500.0}
    own = Mission.build(mtsp_plan="per-run", **small)
    shared = Mission.build(mtsp_plan="shared", **small)
    for run in (0, 1):
        direct = Mission.build(mtsp_plan="shared", plan_seed=plan_seed(7, run), **small)
        a, b = simulate(own, seed=7, run=run), simulate(direct, seed=7, run=run)
        assert (a.t_detect, a.t_notify) == (b.t_detect, b.t_notify)
        np.testing.assert_array_equal(a.reach_cum, b.reach_cum)
    routes = [prepare(own).steering.per_run(7, run) for run in (0, 1)]  # type: ignore[misc]
    assert any(not np.array_equal(x, y) for x, y in zip(*routes, strict=True))
    assert prepare(shared).steering.per_run is None


def test_mtsp_conb_predicts_the_mtsp_drones_by_heading_or_along_their_paths() -> None:
    """Drone 0 flies a route: 5 m west to (2895, 2000), then east. ConB drone 1, 990 m east
    of it, flies north (r_c = 1000 m, the BS at the centre). Extrapolating drone 0's heading
    (west), drone 1 is out of range of it two increments on (1000.05 m) and turns at once
    towards their contact's end (Eq. 9); along drone 0's path (back east) it stays within
    990.05 m and keeps flying north."""
    route = np.array([[2895.0, 2000.0], [3500.0, 2000.0], [2000.0, 2000.0]])
    scenario = Scenario(target=FAR_TARGET, positions=np.array([[2900.0, 2000.0],
                                                               [3890.0, 2000.0]]),
                        headings=np.array([math.pi, math.pi / 2]))

    def heading_of_drone_1(prediction: str) -> tuple[float, float]:
        mission = Mission.build(planner="mtsp-conb", drones=2, rc=1000.0, horizon=3.0,
                                conb_check="continuous", mtsp_prediction=prediction,
                                turns="exact")
        prepared = Prepared.build(mission, Steering(rule=CONB, routes=(route,)))
        trajectory = prepared.run(0, 0, scenario=scenario, trajectory=True).trajectory
        assert trajectory is not None
        angle = trajectory.headings[1, 1]
        return math.cos(angle), math.sin(angle)

    assert heading_of_drone_1("paths") == pytest.approx((0.0, 1.0))
    # Eq. 9 by hand: drone 0 at (2900, 2000) with velocity (-5, 0), drone 1 at (3890, 2000)
    # with (0, 5); the contact ends at tau with |p + w tau| = r_c
    px, py, wx, wy = -990.0, 0.0, -5.0, -5.0
    a, b, c = wx * wx + wy * wy, 2 * (px * wx + py * wy), px * px + py * py - 1000.0**2
    tau = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    cx, cy = 2900.0 - 5.0 * tau, 2000.0
    ux, uy = cx - 3890.0, cy - 2005.0
    ux, uy = ux / math.hypot(ux, uy), uy / math.hypot(ux, uy)
    rx, ry = ux, 1.0 + uy
    assert heading_of_drone_1("heading") == pytest.approx((rx / math.hypot(rx, ry),
                                                           ry / math.hypot(rx, ry)))
