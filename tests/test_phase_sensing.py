"""The sensing phase (sarlink.engine.sensing) called directly: detection within r (Eq. 2) and
imperfect looks (Section 4.3) against a reference built from the model's words: a pass is an
unbroken interval in range; one look at its start and, per period, every t_s in it; each look
misses with p_miss, on the look's own uniform draw (docs/model.md, Sensing)."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from phase_inputs import node_arrays, params
from sarlink.engine.params import PER_PERIOD
from sarlink.engine.sensing import sense

TARGET = (1000.0, 1000.0)
EDGE = (1300.0, 1400.0)  # exactly r = 500 m from the target (3-4-5)
OUTSIDE = (1300.0, 1400.0 + 1e-9)


def _state(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``in_range``, ``pass_start`` and ``knows`` of a run's start."""
    return np.zeros(n, dtype=np.bool_), np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.bool_)


@given(drones=st.lists(st.tuples(st.integers(0, 2000), st.integers(0, 2000)), min_size=1,
                       max_size=10),
       r=st.integers(0, 1000), k=st.integers(0, 100))
def test_perfect_sensing_detects_exactly_the_drones_within_r(
        drones: list[tuple[int, int]], r: int, k: int) -> None:
    """Whole metres make every squared distance exact, so ``<=`` is tested at the edge; the
    first detector is the lowest index; a detector's pass starts now."""
    n = len(drones)
    xy = [(float(x), float(y)) for x, y in drones]
    px, py, _ = node_arrays([*xy, (0.0, 0.0), TARGET], n)
    in_range, pass_start, knows = _state(n)
    within = [(x - TARGET[0]) ** 2 + (y - TARGET[1]) ** 2 <= r * r for x, y in xy]
    first = sense(px, py, k, params(r=r), in_range, pass_start, knows,
                  np.random.default_rng(0))
    assert knows.tolist() == in_range.tolist() == within
    assert first == (within.index(True) if any(within) else -1)
    assert pass_start.tolist() == [k if w else 0 for w in within]


def _expected(schedule: list[list[bool]], p_miss: float, per_period: bool, ts: int,
              draws: np.random.Generator) -> tuple[list[list[bool]], list[int]]:
    """What each drone knows after each step, and each step's first detector, for drones in
    range at the steps ``schedule[i]`` says: looks found from the passes, then taken in step
    order (drone order within a step), each on the next uniform draw."""
    n, steps = len(schedule), len(schedule[0])
    looks: set[tuple[int, int]] = set()
    for i, inside in enumerate(schedule):
        k = 0
        while k < steps:
            if not inside[k]:
                k += 1
                continue
            end = k
            while end < steps and inside[end]:
                end += 1
            looks.update((s, i) for s in range(k, end, ts if per_period else end - k))
            k = end
    knows = [False] * n
    known, firsts = [], []
    for step in range(steps):
        first = -1
        for i in range(n):
            if (step, i) in looks and draws.random() >= p_miss:
                knows[i] = True
                first = i if first < 0 else first
        known.append(list(knows))
        firsts.append(first)
    return known, firsts


@given(schedule=st.integers(1, 5).flatmap(lambda n: st.lists(
           st.lists(st.booleans(), min_size=n, max_size=n), min_size=1, max_size=30)),
       p_miss=st.floats(0.0, 1.0), per_period=st.booleans(), ts=st.integers(1, 4),
       seed=st.integers(0, 2**32 - 1))
def test_looks_miss_and_detect_as_the_model_says(schedule: list[list[bool]], p_miss: float,
                                                 per_period: bool, ts: int, seed: int) -> None:
    """Drones stand on the edge of the sensing range (in) or a nanometre beyond it (out),
    step by step; every step's detections, knowledge and first detector, and the number of
    random draws (one per look), are those of the reference."""
    by_drone = [list(row) for row in zip(*schedule, strict=True)]
    n, steps = len(by_drone), len(schedule)
    p = params(p_miss=p_miss, look=PER_PERIOD if per_period else 0, ts_steps=ts)
    rng, twin = np.random.default_rng(seed), np.random.default_rng(seed)
    known, firsts = _expected(by_drone, p_miss, per_period, ts, twin)
    in_range, pass_start, knows = _state(n)
    for k in range(steps):
        xy = [EDGE if by_drone[i][k] else OUTSIDE for i in range(n)]
        px, py, _ = node_arrays([*xy, (0.0, 0.0), TARGET], n)
        first = sense(px, py, k, p, in_range, pass_start, knows, rng)
        assert (knows.tolist(), first) == (known[k], firsts[k]), k
    assert rng.bit_generator.state == twin.bit_generator.state


def test_certain_misses_never_detect_however_often_a_drone_looks() -> None:
    p = params(p_miss=1.0, look=PER_PERIOD, ts_steps=1)
    px, py, _ = node_arrays([EDGE, (0.0, 0.0), TARGET], 1)
    in_range, pass_start, knows = _state(1)
    rng = np.random.default_rng(1)
    assert all(sense(px, py, k, p, in_range, pass_start, knows, rng) == -1 for k in range(200))
    assert not knows[0] and in_range[0]
