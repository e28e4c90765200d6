"""Critical ranges (sarlink.engine.critical_ranges) against direct flights at the same ranges.

A range-free team flies the same at every range, so one flight scanned at any range must give
exactly what the engine gives when it flies at that range: the same event times, immediate
flag and cumulative records, bit for bit, at hypothesis-drawn ranges and on knife edges.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import given
from hypothesis import strategies as st

from naive import component
from sarlink import ConfigError, Experiment, Mission, execution, register_radio, storage
from sarlink.at_range import at_range
from sarlink.compile_times import Part
from sarlink.engine import RadioModel, sharing
from sarlink.engine.radios import lognormal
from sarlink.engine.streams import copied, run_streams
from sarlink.execution import sweep
from sarlink.metrics import summarize
from sarlink.result import RunResult
from sarlink.simulation import prepare

# every eligible planner: routes (mTSP, a search pattern, mTSP-ConB with N <= N_r), CovB
ELIGIBLE = [
    dict(planner="covb", drones=8),
    dict(planner="mtsp", drones=4),
    dict(planner="parallel", drones=5),
    dict(planner="mtsp-conb", drones=4, nr=6),
]
TDS = (500.0, 1000.0, 2000.0, 4000.0)


def same_outcome(a: RunResult, b: RunResult) -> None:
    """Everything a row holds of a run, compared exactly (and the measures at several t_d)."""
    assert (a.t_detect, a.t_notify, a.detector, a.immediate) == (
        b.t_detect, b.t_notify, b.detector, b.immediate)
    np.testing.assert_array_equal(a.checkpoints, b.checkpoints)
    np.testing.assert_array_equal(a.reach_cum, b.reach_cum)
    np.testing.assert_array_equal(a.connected_cum, b.connected_cum)
    np.testing.assert_array_equal(a.depth, b.depth)
    np.testing.assert_array_equal(a.farthest, b.farthest)
    for td in (t for t in TDS if t <= b.horizon):
        assert a.notified(td) == b.notified(td)
        if not math.isnan(b.t_reachable(td)):
            assert a.t_reachable(td) == b.t_reachable(td)
            assert a.connected_fraction(td) == b.connected_fraction(td)


def check(mission: Mission, run: int, rcs: list[float]) -> list[RunResult]:
    """Read with and without the staircase (which follows the knowledge further)."""
    via = prepare(mission).run_ranges(3, run, rcs, staircase=True)
    bare = prepare(mission).run_ranges(3, run, rcs)
    for rc, got, plain in zip(rcs, via, bare, strict=True):
        direct = prepare(mission.replace(rc=rc)).run(3, run)
        same_outcome(got, direct)
        same_outcome(plain, direct)
        assert plain.notify_times is None
        np.testing.assert_array_equal(np.isnan(direct.depth), np.isnan(direct.reach_cum))
    return via


@pytest.mark.parametrize("sigma", [0.0, 4.0])
@pytest.mark.parametrize("team", ELIGIBLE, ids=lambda t: t["planner"])
@given(rcs=st.lists(st.floats(60.0, 3500.0), min_size=1, max_size=3), run=st.integers(0, 50))
def test_one_flight_equals_a_flight_at_each_range(team: dict, sigma: float, rcs: list[float],
                                                  run: int) -> None:
    mission = Mission.build(**team, rc=1000.0, sigma=sigma, horizon=2000.0)
    assert prepare(mission).range_free
    check(mission, run, rcs)


def test_a_copied_stream_draws_what_the_stream_draws() -> None:
    """The scan redraws the flight's looks and fades from copies taken before it."""
    stream = run_streams(5, 9).look
    stream.random(3)
    copy = copied(stream)
    ahead = copy.standard_normal(50)
    np.testing.assert_array_equal(stream.standard_normal(50), ahead)
    assert stream.random() == copy.random()  # each goes on by itself


@pytest.mark.parametrize("sigma", [0.0, 4.0])
def test_knife_edges_of_the_staircase(sigma: float) -> None:
    """At the float ranges just below, at and above every critical range of the staircase
    (where a link's distance equals the range to the last bit) the flights agree."""
    mission = Mission.build(planner="covb", drones=6, rc=1000.0, sigma=sigma, horizon=1500.0)
    edges = 0
    for run in range(4):
        (first,) = prepare(mission).run_ranges(3, run, [1000.0], staircase=True)
        assert first.notify_rc2 is not None
        for key in first.notify_rc2[::max(1, len(first.notify_rc2) // 4)][:4]:
            rc = math.sqrt(key)
            around = [math.nextafter(rc, 0.0), rc, math.nextafter(rc, math.inf)]
            around = [r for r in around if r > 0]
            # the BS is notified at that step from the critical range on and not below it
            assert any(r * r < key for r in around) and any(r * r >= key for r in around)
            check(mission, run, around)
            edges += 1
    assert edges >= 4


def test_take_off_knife_edge() -> None:
    """At t = r_c / V every drone sits at exactly r_c from the BS (docs/model.md)."""
    for rc in (500.0, 1000.0, 2000.0):
        mission = Mission.build(planner="covb", drones=10, rc=rc, horizon=1000.0)
        for run in range(3):
            check(mission, run, [rc, rc - 5.0, rc + 5.0])


@pytest.mark.parametrize("stop", ["detected", "notified"])
def test_runs_stopped_early(stop: str) -> None:
    mission = Mission.build(planner="mtsp", drones=4, rc=700.0, stop=stop, p_miss=0.3)
    for run in range(4):
        check(mission, run, [300.0, 700.0, 1200.0])


@pytest.mark.parametrize("shadowing", ["period", "run", "correlated"])
@pytest.mark.parametrize("planner", ["covb", "mtsp"])
def test_every_way_of_drawing_the_fades(shadowing: str, planner: str) -> None:
    """The fades redrawn each coherence time, once per run (a landed mTSP team then settles
    under shadowing) or drifting with the distance flown: scanned at every range as drawn."""
    mission = Mission.build(planner=planner, drones=5, rc=700.0, sigma=6.0,
                            shadowing=shadowing, horizon=3000.0)
    for run in range(3):
        check(mission, run, [200.0, 700.0, 1300.0, 2500.0])


def test_per_period_looks_of_a_settled_team() -> None:
    """mTSP drones land and settle; with per-period looks a landed drone may still sense the
    target later, and at some ranges knows it already: the flight's end is not every
    range's."""
    mission = Mission.build(planner="mtsp", drones=6, rc=500.0, p_miss=0.6, look="per-period",
                            bs=(2000.0, 2000.0))
    for run in range(6):
        check(mission, run, [150.0, 500.0, 900.0])


def test_staircase_gives_the_notification_at_any_range() -> None:
    mission = Mission.build(planner="covb", drones=6, rc=800.0, horizon=3000.0)
    for run in range(3):
        (res,) = prepare(mission).run_ranges(5, run, [800.0], staircase=True)
        assert res.notify_times is not None and res.notify_rc2 is not None
        assert np.all(np.diff(res.notify_rc2) < 0) and np.all(np.diff(res.notify_times) > 0)
        for rc in (120.0, 450.0, 800.0, 1700.0):
            direct = prepare(mission.replace(rc=rc)).run(5, run)
            hit = np.flatnonzero(res.notify_rc2 <= rc * rc)
            assert direct.t_notify == (res.notify_times[hit[0]] if hit.size else None)


@pytest.mark.parametrize("team", [dict(planner="conb", drones=6),
                                  dict(planner="mtsp-conb", drones=6, nr=2),
                                  dict(planner="concov", drones=6, alpha=1.0),
                                  dict(planner="covb", drones=6, on_detect="report")])
def test_teams_whose_paths_follow_the_links_are_not_range_free(team: dict) -> None:
    prepared = prepare(Mission.build(**team))
    assert not prepared.range_free
    with pytest.raises(ValueError, match="each range"):
        prepared.run_ranges(0, 0, [500.0, 1000.0])


# -- sweeps: a grid over rc of a range-free team flies once per run ----------------------------


def _experiment(planner: str, rcs: list[float], staircase: bool = False,
                **extra: object) -> Experiment:
    return Experiment.from_dict({
        "name": "ranges", "seed": 11, "runs": 6, "chunk": 4, "staircase": staircase,
        "mission": {"team": {"planner": planner, "drones": 5},
                    "timing": {"horizon": 1500.0}, **extra},
        "grid": {"rc": rcs}})


def _rows(df: pd.DataFrame) -> pd.DataFrame:
    return df.drop(columns="point").sort_values(["rc", "run"]).reset_index(drop=True)


@pytest.mark.parametrize(("planner", "staircase"), [("covb", False), ("covb", True),
                                                    ("conb", True)])
def test_a_sweep_over_rc_equals_a_sweep_per_range(planner: str, staircase: bool,
                                                  tmp_path: Path) -> None:
    """The same columns and values as one sweep per range; a range-free team's jobs fly
    each run once (conb is flown per range as before)."""
    rcs = [400.0, 900.0, 1600.0]
    together = sweep(_experiment(planner, rcs, staircase), tmp_path / "all", workers=1,
                     progress=False)
    apart = pd.concat([sweep(_experiment(planner, [rc], staircase), tmp_path / f"{rc}",
                             workers=1, progress=False) for rc in rcs])
    a, b = _rows(together), _rows(apart)
    assert list(a.columns) == list(b.columns)
    assert ("notify_times" in a.columns) == (planner == "covb" and staircase)
    pd.testing.assert_frame_equal(a, b)
    varied = a.groupby("run")[["t_reachable", "connected_fraction"]].nunique()
    assert (varied.max(axis=1) > 1).all()  # each run's outcome depends on the range


def _tasks(folder: Path, planners: list[str], staircase: bool = False,
           on_detect: str = "continue") -> list:
    """The tasks of 8 runs, in chunks of 4, of 4 drones of each planner at two ranges."""
    experiment = Experiment.from_dict({
        "name": "tasks", "seed": 1, "runs": 8, "chunk": 4, "staircase": staircase,
        "mission": {"team": {"drones": 4, "on_detect": on_detect}},
        "grid": {"planner": planners, "rc": [500.0, 1000.0]}})
    with storage.open_store(folder, experiment) as store:
        return execution._plan(store, experiment.runs, experiment.chunk, staircase)


def test_sweep_jobs_group_only_range_free_points(tmp_path: Path) -> None:
    tasks = _tasks(tmp_path, ["covb", "conb", "mtsp"])
    jobs = execution._jobs(tasks)
    sizes = sorted((job[0].point.params["planner"], len(job)) for job in jobs)
    assert sizes == [("conb", 1)] * 4 + [("covb", 2)] * 2 + [("mtsp", 2)] * 2

    def ids(ts: list) -> list:
        return sorted((t.point.hash, t.runs.start) for t in ts)

    assert ids([t for job in jobs for t in job]) == ids(tasks)
    for job in jobs:  # together: the same runs of one team at several ranges
        assert len({(t.runs, t.point.params["planner"]) for t in job}) == 1
        assert len({t.point.params["rc"] for t in job}) == len(job)


def test_the_parts_to_compile_spread_the_scan_and_the_ga_over_the_workers(
        tmp_path: Path) -> None:
    """The kernels scan several ranges themselves; the staircase is a part of its own,
    compiled only where a team may be scanned by it: not a team forming a chain to a found
    target (``on_detect = relay``), whose kernel is a part of its own."""
    parts = [Part("kernel", "conb"), Part("mtsp"), Part("kernel", "mtsp"), Part("kernel", "covb")]
    tasks = _tasks(tmp_path / "plain", ["conb", "mtsp", "covb"])
    assert execution._parts(execution._jobs(tasks)) == parts
    stairs = _tasks(tmp_path / "stairs", ["conb", "mtsp", "covb"], staircase=True)
    assert execution._parts(execution._jobs(stairs)) == [*parts, Part("ranges", "mtsp")]
    conb = _tasks(tmp_path / "conb", ["conb"], staircase=True)
    assert execution._parts(execution._jobs(conb)) == [Part("kernel", "conb")]
    chain = _tasks(tmp_path / "chain", ["covb"], staircase=True, on_detect="relay")
    assert execution._parts(execution._jobs(chain)) == [Part("kernel", "covb", chain=True)]


def test_warming_up_the_scan_compiles_it() -> None:
    """In a process of its own: this one has scanned flights at several ranges already."""
    code = ("from sarlink.engine import critical_ranges\n"
            "from sarlink.simulation import warm_up\n"
            "assert not critical_ranges.critical.signatures\n"
            "warm_up('mtsp', 'disc', ranges=True)\n"
            "assert critical_ranges.critical.signatures\n")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_a_one_range_job_flies_as_before_unless_asked_for_the_staircase(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """The critical ranges cost most of a flight: a job of one range never finds them,
    unless its rows must carry the staircase; a job of several ranges always does."""
    from sarlink.engine import Prepared
    from sarlink.simulation import plugins_in_code

    scans = []
    original = Prepared.run_ranges

    def counted(self: Prepared, *args: object, **kwargs: object) -> object:
        scans.append(1)
        return original(self, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(Prepared, "run_ranges", counted)
    one = Mission.build(planner="covb", drones=4, rc=700.0, horizon=800.0)
    text = one.model_dump_json()
    (plain,) = execution._run_chunk([text], [False], 2, 0, 3, plugins_in_code())
    assert scans == [] and "notify_times" not in plain.column_names
    (stairs,) = execution._run_chunk([text], [True], 2, 0, 3, plugins_in_code())
    assert len(scans) == 3 and "notify_times" in stairs.column_names
    pd.testing.assert_frame_equal(
        stairs.drop_columns(["notify_times", "notify_rc2"]).to_pandas(), plain.to_pandas())
    scans.clear()
    two = [text, one.replace(rc=1400.0).model_dump_json()]
    first, _ = execution._run_chunk(two, [False, False], 2, 0, 3, plugins_in_code())
    assert len(scans) == 3
    pd.testing.assert_frame_equal(first.to_pandas(), plain.to_pandas())


def test_routes_that_read_the_range_are_flown_per_range() -> None:
    """A route function may read r_c: the worker then flies each range (the same rows)."""
    from sarlink.engine import Prepared
    from sarlink.engine.steering import Steering

    missions = [Mission.build(planner="mtsp", drones=2, rc=rc) for rc in (300.0, 900.0)]

    def routed(m: Mission) -> Prepared:  # a route that goes as far as the range
        route = np.array([[2000.0 + m.channel.rc, 2000.0], [2000.0, 2000.0]])
        return Prepared.build(m, Steering(rule=None, routes=(route, route)))

    assert all(p.range_free for p in map(routed, missions))
    flat = [False, False]
    assert sharing._range_groups([routed(m) for m in missions], flat) == [[0], [1]]
    assert sharing._range_groups([prepare(m) for m in missions], flat) == [[0, 1]]


def halved_init(p: object, rp: np.ndarray, m: int, mp: int) -> np.ndarray:
    """A plug-in radio's ``init``: links at half the range."""
    return lognormal.init(p, rp, m, mp) / 4.0


@pytest.mark.usefixtures("fresh_registries")
def test_only_the_built_in_radio_may_be_range_free() -> None:
    assert register_radio(RadioModel("again", lognormal.init, lognormal.update,
                                     lognormal.nominal, range_free=True)).range_free
    assert not RadioModel("other", halved_init, lognormal.update, lognormal.nominal).range_free
    with pytest.raises(ConfigError, match="range_free is only for the built-in"):
        register_radio(RadioModel("other", halved_init, lognormal.update, lognormal.nominal,
                                  range_free=True))


def test_at_range_evaluates_unflown_ranges_as_flights_would(tmp_path: Path) -> None:
    flown = sweep(_experiment("covb", [300.0, 1200.0], True), tmp_path / "grid", workers=1,
                  progress=False)
    direct = sweep(_experiment("covb", [750.0]), tmp_path / "one", workers=1, progress=False)
    evaluated = at_range(flown, 750.0)
    assert len(evaluated) == len(direct)
    for column in ("rc", "t_detect", "t_notify", "immediate", "detector"):
        np.testing.assert_array_equal(evaluated[column].to_numpy(), direct[column].to_numpy())
    assert evaluated["t_reachable"].isna().all()  # not kept: NaN, never a wrong number
    kept = at_range(flown, 1200.0)
    pd.testing.assert_frame_equal(kept, flown[flown["rc"] == 1200.0].reset_index(drop=True))
    s = summarize(evaluated, td=[1000.0])
    assert s["P_s"].iloc[0] == summarize(direct, td=[1000.0])["P_s"].iloc[0]


@pytest.mark.parametrize(("planner", "staircase"), [("conb", True), ("covb", False)])
def test_at_range_needs_a_staircase(planner: str, staircase: bool, tmp_path: Path) -> None:
    flown = sweep(_experiment(planner, [300.0, 1200.0], staircase), tmp_path / "grid",
                  workers=1, progress=False)
    with pytest.raises(ConfigError, match="no run can be evaluated"):
        at_range(flown, 750.0)
    with pytest.raises(ConfigError, match="rc must be"):
        at_range(flown, -1.0)


def test_summarize_at_an_unflown_range_on_the_command_line(tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from sarlink.cli import app

    sweep(_experiment("mtsp", [300.0, 1200.0], True), tmp_path / "grid", workers=1,
          progress=False)
    direct = sweep(_experiment("mtsp", [750.0]), tmp_path / "one", workers=1, progress=False)
    out = CliRunner().invoke(app, ["summarize", str(tmp_path / "grid"), "--rc", "750",
                                   "--td", "1000", "--json"])
    assert out.exit_code == 0, out.output
    (row,) = json.loads(out.output)
    assert row["rc"] == 750.0
    expected = summarize(direct, td=[1000.0]).iloc[0]
    assert (row["notified"], row["detected"]) == (expected["notified"], expected["detected"])
    bad = CliRunner().invoke(app, ["summarize", str(tmp_path / "grid"), "--rc", "0"])
    assert bad.exit_code == 2 and "rc must be" in bad.output


@given(n=st.integers(1, 7), steps=st.integers(1, 60), seed=st.integers(0, 2**32 - 1),
       rcs=st.lists(st.floats(20.0, 400.0), min_size=1, max_size=5), shadowed=st.booleans(),
       move=st.sampled_from([5.0, 40.0]))
def test_the_scan_keeps_every_range_s_graph_and_component(n: int, steps: int, seed: int,
                                                            rcs: list[float], shadowed: bool,
                                                            move: float) -> None:
    """After each step's pass over the links (``ranges._band_links``), the graph at every range
    is the links within it, and a range not marked as moved still holds the BS component of
    that graph and the reachability found when it last moved: the marks may skip a search only
    where neither can have changed."""
    from sarlink.engine import critical_ranges, graph
    from sarlink.engine.geometry import FAR, PAD

    rng = np.random.default_rng(seed)
    m = n + 2
    mp = (m + PAD - 1) // PAD * PAD
    sc = critical_ranges.new_scan(np.array(rcs) ** 2, n, mp, 1)
    px, py, pz = np.full(mp, FAR), np.full(mp, FAR), np.zeros(mp)
    px[n:m], py[n:m] = (0.0, 150.0), (0.0, 150.0)  # the BS, the target
    fade = rng.lognormal(0.0, 0.5, (m, m)) if shadowed else np.ones((0, 0))
    near = np.zeros((m, sc.adj.shape[2]), dtype=np.uint64)
    stack = np.empty(m, dtype=np.int64)
    found = [(False, 0)] * len(rcs)  # reachability and connected drones, as last found
    pos = rng.uniform(0.0, 300.0, (n, 2))
    for _ in range(steps):  # moves that change a link or two, or several ranges at once
        pos += rng.normal(0.0, move, pos.shape)
        px[:n], py[:n] = pos[:, 0], pos[:, 1]
        critical_ranges._band_links(px, py, pz, fade, shadowed, sc, near, 0.0, False)
        for j, r2 in enumerate(sc.thr):
            links = {(a, b) for a in range(m) for b in range(a + 1, m)
                     if (px[a] - px[b]) ** 2 + (py[a] - py[b]) ** 2
                     <= (r2 * fade[a, b] if shadowed else r2)}
            bits = {(a, b) for a in range(m) for b in range(a + 1, m)
                    if graph.linked(sc.adj[j], a, b)}
            assert bits == links
            around: dict[int, set[int]] = {a: set() for a in range(m)}
            for a, b in links:
                around[a].add(b)
                around[b].add(a)
            routed = component({n}, around, blocked=n + 1)  # the target never relays
            now = (any((a, n + 1) in links for a in routed), len(routed) - 1)
            if not sc.moved[j]:
                assert {a for a in range(m) if graph.has(sc.routed[j], a)} == routed
                assert now == found[j]
            graph.bs_component(sc.adj[j], n, sc.routed[j], stack)
            found[j] = now
            sc.moved[j] = sc.changed[j] = False
