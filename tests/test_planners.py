"""The planner registry matches the modules on disk, and every planner flies.

Nothing here lists the registered planners: adding one is no edit of these tests.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import sarlink.planners as planners_pkg
from sarlink import Mission, get_planner, planner_names, simulate
from sarlink.paper.experiments import PAPER_PLANNERS
from sarlink.planners import PLANNERS
from sarlink.planners.patterns import PATTERNS


def test_registry_matches_the_planner_modules_on_disk() -> None:
    """One module per planner; the search patterns one module each in ``patterns/``, beside
    what they share."""
    folder = Path(planners_pkg.__file__).parent
    modules = {p.stem.replace("_", "-") for p in folder.glob("*.py")} - {"--init--", "base"}
    patterns = {p.stem for p in (folder / "patterns").glob("*.py")} - {
        "__init__", "base", "geometry"}
    assert {p.routes.__module__.rsplit(".", 1)[-1] for p in PATTERNS} == patterns
    assert set(planner_names()) == modules | {p.name for p in PATTERNS}


def test_unknown_planner_is_a_clear_error() -> None:
    with pytest.raises(KeyError, match="unknown planner 'nope'; known: mtsp, covb, conb"):
        get_planner("nope")


def test_the_paper_planners_come_first_in_its_legend_order_and_styles_are_distinct() -> None:
    assert planner_names()[:len(PAPER_PLANNERS)] == list(PAPER_PLANNERS)
    styles = [(p.colour, p.marker) for p in PLANNERS.values()]
    assert len({c for c, _ in styles}) == len({m for _, m in styles}) == len(styles)


@pytest.mark.parametrize("name", list(PLANNERS))
def test_every_planner_flies_a_mission(name: str) -> None:
    mission = Mission.build(planner=name, drones=8, horizon=600.0)
    steering = get_planner(name).steering(mission)
    assert len(steering.routes) <= mission.team.drones
    result = simulate(mission, seed=0, trajectory=True)
    assert result.trajectory is not None
    assert np.isfinite(result.trajectory.positions).all()
    moved = np.linalg.norm(result.trajectory.positions[-1] - result.trajectory.positions[0], axis=1)
    assert (moved > 0).any()
