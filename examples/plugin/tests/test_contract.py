"""The plug-in's planners keep sarlink's contract (run after installing the package): the
planner contract for both, and the rule contract (its declarations hold in flight) for
``tether``."""

import pytest

from sarlink import planner_names
from sarlink.testing import check_planner, check_rule


@pytest.mark.parametrize("name", ["rays", "tether"])
def test_the_planner_is_installed_and_keeps_the_contract(name: str) -> None:
    assert name in planner_names()
    check_planner(name, rc=500.0)


def test_the_rule_keeps_its_declarations() -> None:
    check_rule("tether", rc=500.0)
