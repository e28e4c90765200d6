"""The plug-in's planners keep sarlink's planner contract (run after installing the package)."""

import pytest

from sarlink import planner_names
from sarlink.testing import check_planner


@pytest.mark.parametrize("name", ["rays", "tether"])
def test_the_planner_is_installed_and_keeps_the_contract(name: str) -> None:
    assert name in planner_names()
    check_planner(name, rc=500.0)
