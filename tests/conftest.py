"""Shared fixtures and the hypothesis profile (examples kept few: each runs the engine)."""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, settings

from sarlink import Mission

settings.register_profile(
    "sarlink", max_examples=25, deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile(
    "thorough", max_examples=300, deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "sarlink"))


@pytest.fixture(scope="session")
def short_mission() -> Mission:
    """The paper's setting, 8 drones, cut to 600 s so that a run takes a millisecond."""
    return Mission.build(drones=8, horizon=600.0)
