"""Metrics: hand-computed values on a made-up table, Wilson references, the engine's records."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sarlink import Mission, simulate
from sarlink.metrics import run_values, success_curve, summarize, varying_params, wilson


def made_up() -> pd.DataFrame:
    """Two groups. conb comes first: groups keep their order of appearance.

    covb: horizon 100 s, records at 0, 50 and 100 s.

    ====  ========  ========  ============  =============
    run   t_detect  t_notify  reach_cum     connected_cum
    ====  ========  ========  ============  =============
    0     10        10        0, 20, 70     0, 50, 100
    1     20        40        0, 0, 30      0, 25, 75
    2     never     never     0, 0, 0       0, 0, 0
    3     60        90        0, 10, 10     0, 50, 50
    4     30        never     0, 50, 100    0, 50, 100
    ====  ========  ========  ============  =============
    """
    nan = math.nan
    rows = [("conb", 5.0, 5.0, [0, 50, 100], [0, 50, 100]),
            ("conb", nan, nan, [0, 0, 0], [0, 50, 100]),
            ("covb", 10.0, 10.0, [0, 20, 70], [0, 50, 100]),
            ("covb", 20.0, 40.0, [0, 0, 30], [0, 25, 75]),
            ("covb", nan, nan, [0, 0, 0], [0, 0, 0]),
            ("covb", 60.0, 90.0, [0, 10, 10], [0, 50, 50]),
            ("covb", 30.0, nan, [0, 50, 100], [0, 50, 100])]
    df = pd.DataFrame(rows, columns=["planner", "t_detect", "t_notify", "reach_cum",
                                     "connected_cum"])
    for column in ("reach_cum", "connected_cum"):
        df[column] = [np.asarray(v, dtype=float) for v in df[column]]
    df["checkpoints"] = [np.array([0.0, 50.0, 100.0])] * len(df)
    df["immediate"] = df.t_notify == df.t_detect
    return df.assign(horizon=100.0, checkpoint=50.0)


def test_hand_computed_measures() -> None:
    out = summarize(made_up(), td=[50, 75, 100])
    assert list(zip(out.planner, out.td, strict=True)) == [
        ("conb", 50), ("conb", 75), ("conb", 100), ("covb", 50), ("covb", 75), ("covb", 100)]
    covb = out[out.planner == "covb"].set_index("td")
    expected = {
        # td=50: detected 0, 1, 4; notified 0, 1; immediate 0 of the 3 detected
        50: dict(runs=5, detected=3, notified=2, P_d=0.6, P_s=0.4, immediate=1 / 3,
                 mission_time=25.0, mission_time_se=15.0,  # sd of (10, 40) is sqrt(450)
                 # (10 + 20) / (10 + 40); delta method: s_x² = 50, s_y² = 450, s_xy = 150:
                 # (50 - 2 * 0.6 * 150 + 0.36 * 450) / (2 * 25²) = 0.0256
                 search_share=0.6, search_share_se=0.16,
                 # reach at 50 s: 20, 0, 0, 10, 50 -> /50; connected: 50, 25, 0, 50, 50 -> /50
                 reachability=0.32, reachability_se=math.sqrt(0.688 / 4 / 5),
                 connected=0.7, connected_se=0.2),
        # td=75: run 3 detected, not yet notified; records halfway between 50 and 100 s
        75: dict(detected=4, notified=2, P_d=0.8, P_s=0.4, immediate=0.25, mission_time=25.0,
                 search_share=0.6, reachability=(45 + 15 + 0 + 10 + 75) / 75 / 5,
                 connected=(75 + 50 + 0 + 50 + 75) / 75 / 5),
        # td=100: notified 0, 1, 3
        100: dict(P_s=0.6, mission_time=140 / 3, mission_time_se=math.sqrt(4900 / 3 / 3),
                  search_share=30 / (140 / 3), reachability=0.42, connected=3.25 / 5),
    }
    for td, values in expected.items():
        for name, value in values.items():
            assert covb.loc[td, name] == pytest.approx(value), (td, name)
    lo, hi = map(float, wilson(3, 5))
    assert (covb.loc[50, "P_d_lo"], covb.loc[50, "P_d_hi"]) == pytest.approx((lo, hi))
    lo, hi = map(float, wilson(1, 4))
    assert (covb.loc[75, "immediate_lo"], covb.loc[75, "immediate_hi"]) == pytest.approx((lo, hi))
    conb = out[out.planner == "conb"].iloc[0]  # one notified run: no spread to estimate
    assert conb.mission_time == 5.0 and math.isnan(conb.mission_time_se)
    assert conb.search_share == 1.0 and math.isnan(conb.search_share_se)


def test_defaults_group_by_varying_parameters_at_the_horizon() -> None:
    df = made_up()
    assert varying_params(df) == ["planner"]
    out = summarize(df)
    assert out.td.tolist() == [100.0, 100.0] and out.runs.tolist() == [2, 5]
    whole = summarize(df, td=50, by=[])
    assert whole.runs.tolist() == [7] and whole.P_s.tolist() == [3 / 7]


def test_no_runs_notified_gives_nan_means_not_errors() -> None:
    out = summarize(made_up(), td=4, by=[])
    assert out.P_s.tolist() == [0.0] and math.isnan(out.mission_time.iloc[0])
    assert out.P_s_lo.tolist() == [0.0] and math.isnan(out.immediate.iloc[0])


@pytest.mark.parametrize(("td", "message"), [(101, "beyond the horizon"), (0, "positive"),
                                             (-5, "positive")])
def test_invalid_durations(td: float, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        summarize(made_up(), td=td)
    with pytest.raises(ValueError, match=message):
        success_curve(made_up(), [50, td])


def test_success_curve_is_the_summary_at_every_td() -> None:
    df = made_up()
    tds = [1, 5, 10, 39.5, 40, 89, 90, 100]
    curve = success_curve(df, tds)
    summary = summarize(df, td=tds)
    pd.testing.assert_frame_equal(curve, summary[curve.columns])
    covb = curve[curve.planner == "covb"]
    assert covb.P_s.tolist() == [0, 0, 0.2, 0.2, 0.4, 0.4, 0.6, 0.6]


def test_reachability_and_connectivity_agree_with_the_engine() -> None:
    """Same interpolation as RunResult, also when the horizon is not a multiple of the spacing."""
    mission = Mission.build(drones=5, rc=1000.0, horizon=420.0)
    results = [simulate(mission, seed=3, run=k) for k in range(6)]
    df = pd.DataFrame([r.row() for r in results]).assign(horizon=420.0, checkpoint=50.0)
    for column in ("reach_cum", "connected_cum"):
        df[column] = df[column].map(np.asarray)
    tds = [1.0, 37.0, 50.0, 401.0, 420.0]
    out = summarize(df, td=tds, by=["run"])
    for r in results:
        rows = out[out.run == r.run].set_index("td")
        for td in tds:
            assert rows.loc[td, "reachability"] == pytest.approx(r.t_reachable(td) / td)
            taken = np.searchsorted(r.checkpoints, td, side="right") - 1  # not interpolated
            assert rows.loc[td, "depth"] == r.depth[taken]
            assert rows.loc[td, "farthest"] == r.farthest[taken]
            assert rows.loc[td, "connected"] == pytest.approx(r.connected_fraction(td))
            assert rows.loc[td, "P_s"] == r.notified(td) and rows.loc[td, "P_d"] == r.detected(td)
    assert any(r.t_reachable() > 0 for r in results)


# -- Wilson intervals --------------------------------------------------------------------------


@pytest.mark.parametrize(("k", "n", "lo", "hi"), [
    (7, 10, 0.3968, 0.8922),    # e.g. Wikipedia, "Binomial proportion confidence interval"
    (81, 263, 0.2553, 0.3662),  # Newcombe (1998), Stat. Med. 17:857, Table I, method 3
    (15, 148, 0.0624, 0.1605),
    (0, 20, 0.0, 0.1611),
    (1, 29, 0.0061, 0.1718),
])
def test_wilson_matches_published_values(k: int, n: int, lo: float, hi: float) -> None:
    assert wilson(k, n) == pytest.approx((lo, hi), abs=5e-5)


@pytest.mark.parametrize("n", [1, 7, 2000])
def test_wilson_edges(n: int) -> None:
    none_lo, none_hi = wilson(0, n)
    all_lo, all_hi = wilson(n, n)
    assert none_lo == 0.0 and all_hi == 1.0
    assert all_lo == pytest.approx(1 - none_hi) and 0 < none_hi < 1
    assert all(math.isnan(v) for v in wilson(0, 0))


# -- invariants --------------------------------------------------------------------------------

times = st.one_of(st.just(math.nan), st.floats(0, 1000, allow_nan=False))


@given(notify=st.lists(times, min_size=1, max_size=40),
       tds=st.lists(st.floats(0.5, 1000), min_size=1, max_size=12))
def test_success_never_decreases_in_td(notify: list[float], tds: list[float]) -> None:
    df = pd.DataFrame({"t_notify": notify, "horizon": 1000.0})
    curve = success_curve(df, sorted(tds), by=[])
    assert np.all(np.diff(curve.P_s) >= 0)
    assert np.all(np.diff(curve.P_s_lo) >= 0) and np.all(np.diff(curve.P_s_hi) >= 0)
    assert np.all((curve.P_s_lo <= curve.P_s) & (curve.P_s <= curve.P_s_hi))
    expected = [np.sum(np.asarray(notify) <= td) / len(notify) for td in sorted(tds)]
    assert curve.P_s.tolist() == pytest.approx(expected)


def test_the_bs_network_is_its_snapshot_at_td_averaged_over_the_runs() -> None:
    """A snapshot is read at the last checkpoint at or before t_d, never interpolated: at
    t_d = 75 s the one taken at 50 s. CovB's five runs have depths 3, 0, 1, 2, 4 at 50 s (mean
    2, standard error sqrt(2.5 / 5)) and 2, 0, 1, 1, 4 at 100 s; a table stored before the
    snapshots has none (NaN), and neither has a run stopped before t_d."""
    df = made_up()
    depths = [[1, 2, 3], [1, 1, 1], [1, 3, 2], [1, 0, 0], [1, 1, 1], [1, 2, 1], [1, 4, 4]]
    df["depth"] = [np.array(d, dtype=float) for d in depths]
    df["farthest"] = [100.0 * np.array(d, dtype=float) for d in depths]
    covb = summarize(df, td=[50, 75, 100]).query("planner == 'covb'").set_index("td")
    assert covb.depth.tolist() == [2.0, 2.0, 1.6]
    assert covb.depth_se.loc[50] == pytest.approx(math.sqrt(2.5 / 5))
    assert covb.farthest.tolist() == pytest.approx([200.0, 200.0, 160.0])
    values = run_values(df.assign(run=range(len(df))), [75.0], ["planner"])
    assert values["depth@75"].tolist() == [2.0, 1.0, 3.0, 0.0, 1.0, 2.0, 4.0]
    assert summarize(made_up(), td=50).depth.isna().all()
    df["depth"] = [np.array([1.0, math.nan, math.nan]), *df["depth"][1:]]
    assert math.isnan(summarize(df, td=50).depth.iloc[0])


def test_run_values_are_each_runs_own_as_the_engine_reports_them() -> None:
    """The per-run table of the paired statistics: event times, immediate notification and
    the reachability and connectivity read at each t_d as RunResult reads them."""
    mission = Mission.build(drones=5, rc=1000.0, horizon=420.0)
    results = [simulate(mission, seed=3, run=k) for k in range(6)]
    df = pd.DataFrame([r.row() for r in results]).assign(horizon=420.0, checkpoint=50.0,
                                                         planner="covb")
    for column in ("reach_cum", "connected_cum"):
        df[column] = df[column].map(np.asarray)
    out = run_values(df, [37.0, 420.0], ["planner"]).set_index("run")
    for r in results:
        row = out.loc[r.run]
        assert row["t_detect"] == pytest.approx(r.t_detect if r.t_detect is not None
                                                else math.nan, nan_ok=True)
        assert bool(row["immediate"]) == r.immediate
        for td in (37.0, 420.0):
            assert row[f"reach@{td:g}"] == pytest.approx(r.t_reachable(td) / td)
            assert row[f"connected@{td:g}"] == pytest.approx(r.connected_fraction(td))


def test_runs_stopped_at_notification_keep_the_event_measures_and_lose_reachability() -> None:
    """An early stop changes no event time; records it no longer has read as NaN, not as 0."""
    full = Mission.build(drones=5, rc=1000.0, horizon=1500.0)

    def table(mission: Mission) -> pd.DataFrame:
        df = pd.DataFrame([simulate(mission, seed=4, run=k).row() for k in range(12)])
        for column in ("reach_cum", "connected_cum"):
            df[column] = df[column].map(np.asarray)
        return df.assign(horizon=1500.0, checkpoint=50.0)

    tds = [500.0, 1500.0]
    both = summarize(table(full), td=tds), summarize(table(full.replace(stop="notified")), td=tds)
    for column in ("P_d", "P_s", "immediate", "mission_time", "search_share"):
        np.testing.assert_array_equal(both[0][column], both[1][column])
    assert 0 < both[1]["P_s"].iloc[-1] < 1  # some runs were cut short, some ran to the end
    assert both[0]["reachability"].notna().all() and both[1]["reachability"].isna().all()
