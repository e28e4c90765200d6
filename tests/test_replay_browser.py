"""The replay page in a real browser: headless Chromium, the file opened from disk, offline.

What the page drew (``sarlinkReplay.state()``) and its pixels are compared with the run's
trajectory, so a page that shows another state than the run's fails.
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
from selenium.webdriver.common.by import By

from browser import chromium, open_page
from sarlink import Mission, simulate
from sarlink.engine.codes import Mode
from sarlink.playback import Replay, compare, replay


@pytest.fixture(scope="module")
def browser():
    with chromium() as driver:
        yield driver


@pytest.fixture(scope="module")
def single(tmp_path_factory) -> tuple[Replay, Path]:
    """ConB with shadowing (reading sarlink-1): detected at 3337 s, notified at 3372 s, then
    the team returns."""
    mission = Mission.build(reading="sarlink-1", planner="conb", drones=10, rc=500.0, sigma=3.0)
    page = replay(simulate(mission, seed=3, run=2, trajectory=True), mission)
    return page, page.write(tmp_path_factory.mktemp("replay") / "mission.html")


@pytest.fixture(scope="module")
def side_by_side(tmp_path_factory) -> tuple[Replay, Path]:
    """Three planners flying one target, each run stopped at its notification."""
    mission = Mission.build(drones=8, rc=500.0, stop="notified")
    page = compare(mission, ["covb", "mtsp", "mtsp-conb"], seed=3, run=0)
    return page, page.write(tmp_path_factory.mktemp("replay") / "compare.html")


@pytest.fixture(scope="module")
def relayed(tmp_path_factory) -> tuple[Replay, Path]:
    """CovB's eight drones, the last three relays: at 300 s they hold a chain from the BS."""
    mission = Mission.build(planner="covb", drones=8, relays=3, rc=500.0, horizon=1200.0)
    page = replay(simulate(mission, seed=0, trajectory=True), mission)
    return page, page.write(tmp_path_factory.mktemp("replay") / "relays.html")


@pytest.fixture(scope="module")
def chained(tmp_path_factory) -> tuple[Replay, Path]:
    """CovB's eight drones searching, then relaying: detected at 280 s, notified at 811 s."""
    mission = Mission.build(planner="covb", drones=8, rc=500.0, on_detect="relay")
    page = replay(simulate(mission, seed=0, run=2, trajectory=True), mission)
    return page, page.write(tmp_path_factory.mktemp("replay") / "chain.html")


def _load(browser, path: Path) -> None:
    open_page(browser, path)
    browser.get_log("browser")  # start each test's console record afresh


def _seek(browser, t: float) -> list[dict]:
    return browser.execute_script("sarlinkReplay.seek(arguments[0]); "
                                  "return sarlinkReplay.state();", t)


def _check_state(drawn: dict, page: Replay, index: int, t: float) -> None:
    """What the page drew for panel ``index`` at ``t`` is the trajectory's step at ``t``."""
    panel = page.panels[index]
    traj = panel.result.trajectory
    k = int(np.searchsorted(traj.t, t, side="right")) - 1
    n = panel.mission.team.drones
    assert drawn["frameT"] == traj.t[k]
    xy = np.array([[d["x"], d["y"]] for d in drawn["drones"]])
    quantum = (traj.positions.max(axis=(0, 1)) - traj.positions.min(axis=(0, 1))) / 65535
    assert (np.abs(xy - traj.positions[k]) <= quantum / 2 * (1 + 1e-9)).all()
    view = drawn["view"]
    np.testing.assert_allclose([[d["px"], d["py"]] for d in drawn["drones"]],
                               view["margin"] + view["scale"] * np.column_stack(
                                   [xy[:, 0], view["size"] - xy[:, 1]]))
    assert [d["mode"] for d in drawn["drones"]] == [Mode(m).name.lower() for m in traj.mode[k]]
    assert drawn["knowers"] == np.flatnonzero(traj.knows[k]).tolist()
    assert [d["route"] for d in drawn["drones"]] == traj.bs_route[k].tolist()
    links = traj.links[k]
    assert drawn["links"] == int(np.triu(links[: n + 1, : n + 1], 1).sum())
    assert drawn["targetLinks"] == int(links[n + 1, : n + 1].sum())
    assert drawn["detected"] == (panel.result.t_detect is not None
                                 and traj.t[k] >= panel.result.t_detect)


def _console_errors(browser) -> list[dict]:
    return [e for e in browser.get_log("browser") if e["level"] == "SEVERE"]


def test_the_page_loads_offline_without_requests_or_errors(browser, single) -> None:
    _load(browser, single[1])
    assert browser.execute_script("return navigator.onLine") is False
    assert browser.execute_script("return performance.getEntriesByType('resource').length") == 0
    assert browser.find_element(By.CSS_SELECTOR, "canvas").size["width"] > 300
    assert _console_errors(browser) == []


def test_seeking_shows_the_trajectory_s_state(browser, single) -> None:
    page, path = single
    _load(browser, path)
    result = page.panels[0].result
    for t in (0.0, 137.5, result.t_detect, result.t_notify, 3700.0, 4000.0):
        (drawn,) = _seek(browser, t)
        _check_state(drawn, page, 0, t)
    assert "BS notified at 3372 s, 35 s after detection" in drawn["outcome"]
    assert _console_errors(browser) == []


def _coloured_by_mode(browser, drawn: dict) -> set[str]:
    """Check that every drone no other could cover is filled with its mode's colour, in the
    canvas's pixels; return the modes so checked."""
    colours = browser.execute_script("return sarlinkReplay.colours().modes")
    checked = set()
    xy = np.array([[d["px"], d["py"]] for d in drawn["drones"]])
    for i, d in enumerate(drawn["drones"]):
        if np.sort(np.hypot(*(xy - xy[i]).T))[1] < 20:
            continue  # another drone could cover this one
        rgba = browser.execute_script(
            "const c = document.querySelector('canvas'); const r = devicePixelRatio;"
            "return Array.from(c.getContext('2d').getImageData("
            "Math.round(arguments[0] * r), Math.round(arguments[1] * r), 1, 1).data);",
            d["px"], d["py"])
        want = colours[d["mode"]]
        assert rgba[:3] == [int(want[k:k + 2], 16) for k in (1, 3, 5)], (drawn["t"], i, d)
        checked.add(d["mode"])
    return checked


def test_drones_are_drawn_where_they_are_in_the_colour_of_their_mode(browser, single) -> None:
    _load(browser, single[1])
    checked = set()
    for t in (1000.0, 3800.0):  # everyone searching; some drones returning
        (drawn,) = _seek(browser, t)
        checked |= _coloured_by_mode(browser, drawn)
    assert checked == {"searching", "returning"}


def test_relays_are_drawn_relaying_in_their_own_colour_holding_the_chain(browser,
                                                                        relayed) -> None:
    page, path = relayed
    _load(browser, path)
    colours = browser.execute_script("return sarlinkReplay.colours().modes")
    assert colours.keys() == {m.name.lower() for m in Mode}
    assert len(set(colours.values())) == len(colours)  # relaying has a colour of its own
    assert "drone relaying" in browser.find_element(By.ID, "legend").text
    (drawn,) = _seek(browser, 300.0)
    _check_state(drawn, page, 0, 300.0)
    assert [d["mode"] for d in drawn["drones"]] == ["searching"] * 5 + ["relaying"] * 3
    assert "relaying" in _coloured_by_mode(browser, drawn)
    traj = page.panels[0].result.trajectory
    chain = _bs_component_links(traj, int(np.searchsorted(traj.t, 300.0)))
    assert chain[5:].any() or chain[:, 5:].any()  # a relay's link in the BS's component
    assert drawn["componentLinks"] == int(chain.sum())
    assert "N = 8 (3 relays)" in browser.find_element(By.TAG_NAME, "h1").text
    assert _console_errors(browser) == []


def _bs_component_links(traj, k: int) -> np.ndarray:
    """The links at step ``k`` between nodes the BS's component holds (the BS is the last)."""
    n = traj.positions.shape[1]
    routed = np.append(traj.bs_route[k], True)
    return np.triu(traj.links[k, :n + 1, :n + 1] & routed[:, None] & routed[None, :], 1)


def test_a_chain_to_a_found_target_is_drawn_chaining_in_its_own_colour(browser, chained
                                                                       ) -> None:
    page, path = chained
    result = page.panels[0].result
    _load(browser, path)
    assert "drone chaining" in browser.find_element(By.ID, "legend").text
    assert "on detect: relay" in browser.find_element(By.TAG_NAME, "h1").text
    (drawn,) = _seek(browser, result.t_notify)
    _check_state(drawn, page, 0, result.t_notify)
    assert "chaining" in _coloured_by_mode(browser, drawn)
    traj = result.trajectory
    k = int(np.searchsorted(traj.t, result.t_notify))
    chaining = np.append(traj.mode[k] == Mode.CHAINING, False)
    links = _bs_component_links(traj, k)
    assert links[chaining].any() or links[:, chaining].any()  # the chain the BS hears by
    assert drawn["componentLinks"] == int(links.sum())
    assert _console_errors(browser) == []


def test_the_timeline_holds_the_run_s_events_and_jumps_to_them(browser, single, tmp_path
                                                                ) -> None:
    page, path = single
    _load(browser, path)
    result = page.panels[0].result
    marks = {m.get_attribute("data-kind"): m
             for m in browser.find_elements(By.CSS_SELECTOR, ".lane .mark.detect, "
                                                             ".lane .mark.notify")}
    assert float(marks["detect"].get_attribute("data-t")) == result.t_detect
    assert float(marks["notify"].get_attribute("data-t")) == result.t_notify
    marks["detect"].click()
    assert browser.execute_script("return sarlinkReplay.time()") == result.t_detect
    (drawn,) = browser.execute_script("return sarlinkReplay.state()")
    _check_state(drawn, page, 0, result.t_detect)
    assert result.detector in drawn["knowers"] and not drawn["notified"]
    assert "found at 3337 s by drone" in browser.find_element(By.CSS_SELECTOR, ".outcome").text
    marks["notify"].click()
    (drawn,) = browser.execute_script("return sarlinkReplay.state()")
    _check_state(drawn, page, 0, result.t_notify)
    assert drawn["notified"] and drawn["componentLinks"] > 0
    shot = tmp_path / "replay.png"  # the README's screenshot: the news reaching the BS
    assert browser.save_screenshot(str(shot))
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert _console_errors(browser) == []


def test_play_advances_time_and_pause_stops_it(browser, single) -> None:
    _load(browser, single[1])
    browser.find_element(By.ID, "play").click()
    time.sleep(0.5)
    browser.find_element(By.ID, "play").click()
    stopped = browser.execute_script("return sarlinkReplay.time()")
    time.sleep(0.3)
    assert 0 < stopped == browser.execute_script("return sarlinkReplay.time()")
    assert browser.execute_script("return sarlinkReplay.playing()") is False


def test_side_by_side_panels_share_one_clock(browser, side_by_side, tmp_path) -> None:
    page, path = side_by_side
    _load(browser, path)
    lanes = browser.find_elements(By.CSS_SELECTOR, ".lane")
    assert [lane.get_attribute("data-planner") for lane in lanes] == ["covb", "mtsp",
                                                                       "mtsp-conb"]
    for lane, panel in zip(lanes, page.panels, strict=True):
        kinds = {m.get_attribute("data-kind"): float(m.get_attribute("data-t"))
                 for m in lane.find_elements(By.CSS_SELECTOR, ".mark")}
        assert (kinds["detect"], kinds["notify"]) == (panel.result.t_detect,
                                                      panel.result.t_notify)
    ends = [p.result.trajectory.t[-1] for p in page.panels]
    for t in (0.0, 300.0, min(ends), max(ends) + 100):
        drawn = _seek(browser, t)
        for index in range(len(page.panels)):
            _check_state(drawn[index], page, index, t)
            assert drawn[index]["t"] == t
    assert all("the run ended at" in d["outcome"] for d in drawn)
    browser.save_screenshot(str(tmp_path / "compare.png"))
    assert _console_errors(browser) == []
