"""Shared fixtures and the hypothesis profile (examples kept few: each runs the engine)."""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, settings

settings.register_profile(
    "sarlink", max_examples=25, deadline=None,
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
