"""Headless Chromium for the replay's tests and benchmark.

Debian's ``chromium`` and ``chromium-driver`` (``.ci/run`` installs them): Selenium is pointed
at both binaries, so its driver manager never runs and nothing is downloaded. The network is
cut three ways: no proxy or DNS resolution reaches anything, and DevTools puts each loaded page
offline, so a page that needs the network fails its test. Chromium 150 drops DevTools' network
conditions at a navigation, so they are set again on every page ``open_page`` loads; the
load itself is covered by the proxy and DNS cut (and the tests count its resource requests).
"""

from __future__ import annotations

import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import WebDriverWait

CHROMIUM = Path("/usr/bin/chromium")
CHROMEDRIVER = Path("/usr/bin/chromedriver")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--proxy-server=127.0.0.1:9",
         "--host-resolver-rules=MAP * ~NOTFOUND", "--window-size=1280,1000")


@contextmanager
def chromium() -> Iterator[webdriver.Chrome]:
    """A headless Chromium with a fresh profile, offline, logging the console."""
    missing = [str(p) for p in (CHROMIUM, CHROMEDRIVER) if not p.exists()]
    if missing:
        raise RuntimeError(f"{', '.join(missing)} not found: install Debian's chromium and "
                           "chromium-driver (apt-get install -y chromium chromium-driver)")
    profile = tempfile.mkdtemp(prefix="sarlink-chromium-")
    options = Options()
    options.binary_location = str(CHROMIUM)
    for flag in (*FLAGS, f"--user-data-dir={profile}"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(options=options, service=Service(str(CHROMEDRIVER)))
    try:
        driver.execute_cdp_cmd("Network.enable", {})
        _offline(driver)
        yield driver
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)


def _offline(driver: webdriver.Chrome) -> None:
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})


def open_page(driver: webdriver.Chrome, page: Path) -> None:
    """Load ``page`` from disk, put it offline, and wait until its script has drawn the first
    frame."""
    driver.get(page.resolve().as_uri())
    _offline(driver)
    WebDriverWait(driver, 30).until(
        lambda d: d.execute_script("return document.body.dataset.ready === 'true'"))
