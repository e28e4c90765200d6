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
    """Keep the tests' mTSP plans out of the user's cache (shared by the whole session)."""
    os.environ["SARLINK_CACHE_DIR"] = str(tmp_path_factory.mktemp("cache"))
