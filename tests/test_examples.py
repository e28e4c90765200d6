"""The shipped example experiments load, and the Fig. 7 ones are what the reproduction runs."""

from __future__ import annotations

from pathlib import Path

import pytest

from sarlink import Experiment
from sarlink.paper.experiments import EXPERIMENTS

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.name)
def test_every_example_is_a_valid_experiment(path: Path) -> None:
    assert Experiment.from_toml(path).points()


@pytest.mark.parametrize(("example", "paper"), [("fig7a", "miss"), ("fig7b", "shadowing")])
def test_fig7_examples_match_the_reproduction(example: str, paper: str) -> None:
    mine = Experiment.from_toml(EXAMPLES / f"{example}.toml")
    theirs = EXPERIMENTS[paper].build(2000)
    assert (mine.seed, mine.runs, mine.mission) == (theirs.seed, theirs.runs, theirs.mission)
    assert mine.grid == theirs.grid
