"""Random streams of one run, derived from ``(seed, run)`` only.

Each purpose has its own stream, so switching a feature off (``sigma = 0``, ``p_miss = 0``)
leaves every other draw of the run unchanged, and a run's result never depends on which
process ran it or in which order. A stream added later is spawned after the others, so the
draws of the earlier ones stay what they were.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np


class Streams(NamedTuple):
    scenario: np.random.Generator  # target position, take-off heading offset
    turn: np.random.Generator  # boundary turns
    shadow: np.random.Generator  # shadow fading per link
    look: np.random.Generator  # imperfect-sensing looks
    takeoff: np.random.Generator  # take-off headings (readings.takeoff random, jitter)
    plan: np.random.Generator  # the seed of a run's own mTSP plan (readings.mtsp_plan per-run)
    rule: np.random.Generator  # a distributed rule's own draws (Observation.rng)


def run_streams(seed: int, run: int) -> Streams:
    """The independent generators of run ``run`` of an experiment seeded with ``seed``."""
    if seed < 0 or run < 0:
        raise ValueError(f"seed and run must be >= 0, got seed={seed}, run={run}")
    children = np.random.SeedSequence(seed, spawn_key=(run,)).spawn(len(Streams._fields))
    return Streams(*(np.random.Generator(np.random.PCG64(c)) for c in children))


def copied(stream: np.random.Generator) -> np.random.Generator:
    """A generator that draws what ``stream`` draws from now on (a third of the cost of the
    run's streams drawn again)."""
    state: Any = stream.bit_generator.state  # a PCG64's, as every stream here
    bits = np.random.PCG64(0)
    bits.state = state
    return np.random.Generator(bits)


def plan_seed(seed: int, run: int) -> int:
    """The seed of run ``run``'s own mTSP plan (``readings.mtsp_plan = per-run``)."""
    return int(run_streams(seed, run).plan.integers(2**63 - 1))
