"""Hand-made inputs for the engine's phase functions (tests/test_phase_*.py), and bitsets read
back in plain Python, so that the tests call the Numba functions directly."""

from __future__ import annotations

import functools
from collections import deque
from collections.abc import Iterable, Sequence

import numpy as np

from sarlink import Mission
from sarlink.engine.geometry import FAR, PAD
from sarlink.engine.params import Params
from sarlink.simulation import prepare

BS = (2000.0, 2000.0)
"""The default mission's BS, at the centre of the 4000 m square."""


@functools.cache
def _base() -> Params:
    return prepare(Mission.build(drones=2, planner="covb")).params


def params(**changes: object) -> Params:
    """The default mission's scalars with ``changes``, each cast to the field's own type (a
    float given as an int would make Numba compile the function again)."""
    base = _base()
    return base._replace(**{k: type(getattr(base, k))(v) for k, v in changes.items()})


def words(m: int) -> int:
    """Bitset words per row for ``m`` nodes."""
    return (m + 63) // 64


def padded(m: int) -> int:
    """Length of the kernel's padded position arrays for ``m`` nodes."""
    return (m + PAD - 1) // PAD * PAD


def node_arrays(xy: Sequence[tuple[float, float]], n: int,
                altitude: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``px, py, pz`` of the nodes ``xy`` (``n`` drones, the BS, the target) padded as the
    kernel pads them: far away, on the ground."""
    mp = padded(len(xy))
    px, py, pz = np.full(mp, FAR), np.full(mp, FAR), np.zeros(mp)
    for j, (x, y) in enumerate(xy):
        px[j], py[j] = x, y
    pz[:n] = altitude
    return px, py, pz


def pack(rows: Sequence[Iterable[int]], nw: int) -> np.ndarray:
    """Bitset rows (``uint64``, ``nw`` words) holding the node sets ``rows``."""
    out = np.zeros((len(rows), nw), dtype=np.uint64)
    for a, row in enumerate(rows):
        for b in row:
            out[a, b // 64] = int(out[a, b // 64]) | (1 << (b % 64))
    return out


def members(bits: np.ndarray) -> set[int]:
    """The node set of one bitset row, read bit by bit."""
    return {w * 64 + b for w, word in enumerate(bits.tolist()) for b in range(64)
            if (int(word) >> b) & 1}


def component(seeds: Iterable[int], neighbours: Sequence[set[int]], blocked: int) -> set[int]:
    """Every node linked to ``seeds`` by a breadth-first search that never expands
    ``blocked`` (the target: it may be reached, never relays) and leaves it out."""
    seen = set(seeds)
    queue = deque(seen)
    while queue:
        a = queue.popleft()
        if a == blocked:
            continue
        for b in neighbours[a]:
            if b not in seen:
                seen.add(b)
                queue.append(b)
    seen.discard(blocked)
    return seen
