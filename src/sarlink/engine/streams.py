"""Random streams of one run, derived from ``(seed, run)`` only.

Each purpose has its own stream, so switching a feature off (``sigma = 0``, ``p_miss = 0``)
leaves every other draw of the run unchanged, and a run's result never depends on which
process ran it or in which order. A stream added later is spawned after the others, so the
draws of the earlier ones stay what they were.
"""

from __future__ import annotations

from typing import Any

import numpy as np


class Streams:
    """The independent generators of run ``run`` of an experiment seeded with ``seed``.

    Stream ``i`` is ``SeedSequence(seed, spawn_key=(run,)).spawn(...)[i]``, made directly as
    ``SeedSequence(seed, spawn_key=(run, i))`` (what ``spawn`` makes) when first asked for: a
    run makes only the streams it draws from.
    """

    __slots__ = ("_made", "run", "seed")

    def __init__(self, seed: int, run: int) -> None:
        self.seed, self.run = seed, run
        self._made: dict[int, np.random.Generator] = {}

    def _stream(self, i: int) -> np.random.Generator:
        if i not in self._made:
            sequence = np.random.SeedSequence(self.seed, spawn_key=(self.run, i))
            self._made[i] = np.random.Generator(np.random.PCG64(sequence))
        return self._made[i]

    @property
    def scenario(self) -> np.random.Generator:
        """The target's position and the take-off heading offset."""
        return self._stream(0)

    @property
    def turn(self) -> np.random.Generator:
        """Boundary turns."""
        return self._stream(1)

    @property
    def shadow(self) -> np.random.Generator:
        """The channel: shadow fading per link (a radio model's ``update``)."""
        return self._stream(2)

    @property
    def look(self) -> np.random.Generator:
        """Imperfect-sensing looks."""
        return self._stream(3)

    @property
    def takeoff(self) -> np.random.Generator:
        """Take-off headings (``readings.takeoff`` random, jitter)."""
        return self._stream(4)

    @property
    def plan(self) -> np.random.Generator:
        """The seed of a run's own mTSP plan (``readings.mtsp_plan = per-run``)."""
        return self._stream(5)

    @property
    def rule(self) -> np.random.Generator:
        """A distributed rule's own draws (``Observation.rng``)."""
        return self._stream(6)

    @property
    def heading(self) -> np.random.Generator:
        """The errors of commanded changes of heading (``readings.turns = jitter``)."""
        return self._stream(7)

    @property
    def target(self) -> np.random.Generator:
        """A moving target's draws (a target-motion model's hooks,
        :mod:`sarlink.engine.target_motion`)."""
        return self._stream(8)

    @property
    def targets(self) -> np.random.Generator:
        """Where the targets after the first were last seen (``target.count > 1``): the
        first is drawn from :attr:`scenario` as it always was."""
        return self._stream(9)


def run_streams(seed: int, run: int) -> Streams:
    """The independent generators of run ``run`` of an experiment seeded with ``seed``."""
    if seed < 0 or run < 0:
        raise ValueError(f"seed and run must be >= 0, got seed={seed}, run={run}")
    return Streams(seed, run)


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
