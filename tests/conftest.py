"""Shared fixtures and the hypothesis profile (examples kept few: each runs the engine)."""

from __future__ import annotations

import os
import time

import pytest
from hypothesis import HealthCheck, settings
from numba.core.event import Event, Listener

settings.register_profile(  # derandomized: a commit's CI run draws the examples it drew here
    "sarlink", max_examples=25, deadline=None, derandomize=True,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile(
    "thorough", max_examples=300, deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "sarlink"))


@pytest.fixture(autouse=True, scope="session")
def _private_plan_cache(tmp_path_factory: pytest.TempPathFactory) -> None:
    """Keep the tests' mTSP plans and kernels out of the user's cache. Under pytest-xdist the
    workers share one (their base temp folders' parent): plans and kernel sources are written
    once under file locks, so a plan is solved and a kernel written once per test session."""
    base = tmp_path_factory.getbasetemp()
    root = base.parent if "PYTEST_XDIST_WORKER" in os.environ else base
    (root / "sarlink-cache").mkdir(exist_ok=True)
    os.environ["SARLINK_CACHE_DIR"] = str(root / "sarlink-cache")


@pytest.fixture
def fresh_registries(monkeypatch: pytest.MonkeyPatch) -> None:
    """What a test registers, or loads from entry points, does not outlive it (every kind)."""
    from sarlink.registry import KINDS

    for registry in KINDS.values():
        monkeypatch.setattr(registry, "_entries", dict(registry._entries))
        monkeypatch.setattr(registry, "_broken", dict(registry._broken))
        monkeypatch.setattr(registry, "_loaded", registry._loaded)


KERNELS = [
    [("mtsp", True, None, False), ("covb", False, "tree", False),
     ("conb", False, "tree", False), ("mtsp", False, "tree", False)],
    [("covb", False, None, False), ("covb", False, None, True), ("mtsp", False, None, True),
     ("conb", False, None, False), ("concov", False, None, False),
     ("covb", False, "tree", True)],
]
"""The engine's kernels most test files fly (planner, with the range scan, relay strategy,
with the chain to a found target), in two lists compiled side by side, each in turn. A
kernel's first compile also compiles the engine's plain functions it calls (minutes from
empty caches: those of every kernel, then those of the relay strategy, of the chain) and
the next kernels load them from the cache; two kernels compiled at once that need the same
uncompiled functions both compile them. So the relays' functions are compiled by one list
(its second kernel), the chain's by the other (its second), and the one kernel with both,
last."""


def _compile_in_turn(kernels: list[tuple[str, bool, str | None, bool]]) -> None:
    from sarlink.simulation import warm_up

    for planner, ranges, relays, chain in kernels:
        warm_up(planner, "disc", ranges=ranges, relays=relays, chain=chain)


def pytest_sessionstart(session: pytest.Session) -> None:
    """Before pytest-xdist starts its workers on the whole suite, compile the kernels most
    test files fly into the cache the workers share, one list per core: otherwise every
    worker compiles each of them (minutes each) when its first test needs it, mostly at once."""
    config = session.config
    workers = (config.getoption("numprocesses", None)
               if config.pluginmanager.has_plugin("xdist") else None)
    if not workers or hasattr(config, "workerinput") or config.option.file_or_dir:
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    root = config._tmp_path_factory.getbasetemp()  # the workers' basetemps are inside it
    (root / "sarlink-cache").mkdir(exist_ok=True)
    os.environ["SARLINK_CACHE_DIR"] = str(root / "sarlink-cache")
    with ProcessPoolExecutor(min(int(workers), len(KERNELS)),
                             mp_context=multiprocessing.get_context("spawn")) as pool:
        for done in [pool.submit(_compile_in_turn, kernels) for kernels in KERNELS]:
            done.result()


class _CompileLog(Listener):
    """``SARLINK_COMPILE_LOG=path``: append a line per top-level Numba compile to ``path``
    (worker, test, module and function, seconds), to see where a test run's compile time goes."""

    def __init__(self, path: str) -> None:
        super().__init__()
        self.path, self.started = path, list[float]()

    def on_start(self, event: Event) -> None:
        self.started.append(time.perf_counter())

    def on_end(self, event: Event) -> None:
        seconds = time.perf_counter() - self.started.pop()
        if self.started:  # a compile inside another's: counted in the outer one
            return
        fn = event.data["dispatcher"].py_func  # a kernel's module names its seams
        name = f"{getattr(fn, '__module__', '?')}.{getattr(fn, '__qualname__', '?')}"
        test = os.environ.get("PYTEST_CURRENT_TEST", "session start").split(" ")[0]
        with open(self.path, "a") as log:
            log.write(f"{os.environ.get('PYTEST_XDIST_WORKER', 'main')}\t{test}\t{name}\t"
                      f"{seconds:.1f}\n")


if os.environ.get("SARLINK_COMPILE_LOG"):
    from numba.core import event as _numba_event

    _numba_event.register("numba:compile", _CompileLog(os.environ["SARLINK_COMPILE_LOG"]))
