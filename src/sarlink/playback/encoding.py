"""A trajectory packed for the replay page: typed arrays, base64, a few bits per link.

A full 4000 s run of 22 drones is 4001 steps; kept whole it costs about 0.7 MB (0.9 MB as
base64), because every quantity is stored at the width it needs:

- positions: ``uint16`` per coordinate on a grid spanning the positions' bounding box, so the
  error is at most half a grid step (3 cm across a 4 km area), plus the rounding of the
  float64 arithmetic that encodes and decodes it (:func:`position_error_bound`);
- headings: ``uint8`` turns of 2π/256 (1.4°), only used to point the drone markers;
- modes: ``uint8`` per drone and step (:class:`sarlink.engine.codes.Mode` values);
- knows, route to the BS: one bit per drone and step;
- links: one bit per node pair ``i < j`` (upper triangle of the ``(N + 2)²`` matrix, drones,
  BS, target) and step;
- a moving target's position: ``float32`` per coordinate and step (absent for a still one),
  and those of the other targets of several (``others``, frame by frame, target by target).

Runs longer than the byte budget keep every ``stride``-th step (and the last); the page then
shows each kept step until the next. Nothing is compressed, so the page decodes synchronously
with ``atob`` and typed arrays, in any browser. Integers are little-endian.
"""

from __future__ import annotations

import base64
import math
from dataclasses import asdict, dataclass

import numpy as np

from sarlink.result import Trajectory

__all__ = ["EncodedTrajectory", "decode", "encode", "frame_bytes", "link_pairs",
           "position_error_bound"]

POSITION_LEVELS = 65535
HEADING_LEVELS = 256


@dataclass(frozen=True)
class EncodedTrajectory:
    """One run's frames, as the page reads them (see the module docstring for the layout)."""

    frames: int
    drones: int
    stride: int
    """Every ``stride``-th step of the trajectory was kept (and its last step)."""
    origin: tuple[float, float]
    """Position of grid point (0, 0), m."""
    quantum: tuple[float, float]
    """Grid step along x and y, m: the position error is at most half of it."""
    t: str
    """float64 frame times, s"""
    positions: str
    """uint16 (frames, drones, 2)"""
    headings: str
    """uint8 (frames, drones)"""
    mode: str
    """uint8 (frames, drones)"""
    knows: str
    """bits (frames, drones), least significant bit first"""
    route: str
    """bits (frames, drones)"""
    links: str
    """bits (frames, pairs) over :func:`link_pairs` (drones + 2)"""
    target: str = ""
    """float32 (frames, 2): a moving target's position; empty for a still target"""
    others: str = ""
    """float32 (frames, K - 1, 2): the other moving targets' positions (``target.count = K``);
    empty for one target or still ones"""

    def json(self) -> dict[str, object]:
        """The fields by name, as the page's data block holds them."""
        return asdict(self)


def link_pairs(nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """Node pairs ``i < j`` in row-major order: the order of the link bits."""
    return np.triu_indices(nodes, 1)


def frame_bytes(drones: int) -> float:
    """Bytes one frame of ``drones`` drones takes before base64."""
    pairs = (drones + 2) * (drones + 1) // 2
    return 8 + drones * (2 * 2 + 1 + 1) + (2 * drones + pairs) / 8


def position_error_bound(enc: EncodedTrajectory, largest: float) -> np.ndarray:
    """The most a decoded coordinate can differ from the original, m, per axis.

    Half a grid step, plus what float64 rounding adds (``largest`` is the largest magnitude of
    an original coordinate). The encoder rounds ``p - origin`` and its quotient by the quantum
    (each within a unit roundoff ``u = 2⁻⁵³`` relative, so ``rint`` may pick the grid point
    ``2u·span`` past the nearest), and the decoder rounds ``grid × quantum`` and the sum with
    the origin (``u·span`` and ``u·largest``): ``3u·span + u·largest`` in all, bounded here by
    ``4u·(span + largest)``. Near 32 km with a span of 1 mm the rounding is about 10⁻³ of the
    half step, so the half step alone is not a bound.
    """
    quantum = np.array(enc.quantum)
    span = quantum * POSITION_LEVELS
    unit_roundoff = np.finfo(float).eps / 2
    return quantum / 2 + 4 * unit_roundoff * (span + largest)


def _b64(array: np.ndarray) -> str:
    return base64.b64encode(np.ascontiguousarray(array).tobytes()).decode("ascii")


def _bits(array: np.ndarray) -> str:
    return _b64(np.packbits(array.astype(bool).reshape(-1), bitorder="little"))


def encode(traj: Trajectory, budget: float = math.inf) -> EncodedTrajectory:
    """Pack ``traj``, keeping every step unless that takes more than ``budget`` bytes."""
    steps, drones = traj.positions.shape[:2]
    stride = max(1, math.ceil(steps * frame_bytes(drones) / budget))
    keep = np.arange(0, steps, stride)
    if keep[-1] != steps - 1:
        keep = np.append(keep, steps - 1)
    pos = traj.positions[keep]
    low = pos.min(axis=(0, 1))
    span = pos.max(axis=(0, 1)) - low
    quantum = np.where(span > 0, span / POSITION_LEVELS, 1.0)
    grid = np.rint((pos - low) / quantum).astype("<u2")
    turns = np.mod(traj.headings[keep], 2 * np.pi) / (2 * np.pi) * HEADING_LEVELS
    headings = np.rint(turns).astype(np.int64) % HEADING_LEVELS
    i, j = link_pairs(drones + 2)
    return EncodedTrajectory(
        frames=len(keep), drones=drones, stride=stride,
        origin=(float(low[0]), float(low[1])), quantum=(float(quantum[0]), float(quantum[1])),
        t=_b64(traj.t[keep].astype("<f8")),
        positions=_b64(grid),
        headings=_b64(headings.astype(np.uint8)),
        mode=_b64(traj.mode[keep].astype(np.uint8)),
        knows=_bits(traj.knows[keep]),
        route=_bits(traj.bs_route[keep]),
        links=_bits(traj.links[keep][:, i, j]),
        target="" if traj.target is None else _b64(traj.target[keep, 0].astype("<f4")),
        others="" if traj.target is None or traj.target.shape[1] == 1 else
        _b64(traj.target[keep, 1:].astype("<f4")),
    )


def _unb64(text: str, dtype: str) -> np.ndarray:
    return np.frombuffer(base64.b64decode(text), dtype=dtype)


def _unbits(text: str, shape: tuple[int, int]) -> np.ndarray:
    bits = np.unpackbits(_unb64(text, "u1"), bitorder="little", count=shape[0] * shape[1])
    return bits.astype(bool).reshape(shape)


def decode(enc: EncodedTrajectory) -> Trajectory:
    """The frames of ``enc`` back as a :class:`Trajectory` (positions within
    :func:`position_error_bound`, about half a quantum, headings within half a turn step,
    everything else exact)."""
    f, n = enc.frames, enc.drones
    grid = _unb64(enc.positions, "<u2").reshape(f, n, 2)
    links = np.zeros((f, n + 2, n + 2), dtype=bool)
    i, j = link_pairs(n + 2)
    links[:, i, j] = _unbits(enc.links, (f, len(i)))
    links |= links.transpose(0, 2, 1)
    return Trajectory(
        t=_unb64(enc.t, "<f8"),
        positions=grid * np.array(enc.quantum) + np.array(enc.origin),
        headings=_unb64(enc.headings, "u1").reshape(f, n) * (2 * np.pi / HEADING_LEVELS),
        knows=_unbits(enc.knows, (f, n)),
        bs_route=_unbits(enc.route, (f, n)),
        mode=_unb64(enc.mode, "u1").reshape(f, n),
        links=links,
        target=None if not enc.target else np.concatenate(
            [_unb64(enc.target, "<f4").astype(float).reshape(f, 1, 2),
             _unb64(enc.others, "<f4").astype(float).reshape(f, -1, 2)], axis=1),
    )
