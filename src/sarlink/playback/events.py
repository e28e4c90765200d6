"""What happened in a run, in time order: the marks on the replay's timeline."""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from sarlink.engine.codes import Mode
from sarlink.result import RunResult

__all__ = ["Event", "events"]


@dataclass(frozen=True)
class Event:
    """One mark on the timeline."""

    t: float
    """s from take-off"""
    kind: str
    """``detect``, ``notify``, or the lower-case name of the :class:`Mode` a drone entered"""
    text: str
    drone: int | None = None

    def json(self) -> dict[str, object]:
        return asdict(self)


def events(result: RunResult) -> list[Event]:
    """Detection, the BS's notification and every change of a drone's mode, read at full
    resolution from the run simulated with ``trajectory=True``."""
    traj = result.trajectory
    if traj is None:
        raise ValueError("a replay needs a result simulated with trajectory=True")
    found: list[Event] = []
    if result.t_detect is not None:
        found.append(Event(result.t_detect, "detect",
                           f"target detected by drone {result.detector}", result.detector))
    if result.t_notify is not None:
        delay = (" at once" if result.immediate or result.t_detect is None
                 else f", {result.t_notify - result.t_detect:g} s after detection")
        found.append(Event(result.t_notify, "notify", f"BS notified{delay}"))
    steps, drones = np.nonzero(traj.mode[1:] != traj.mode[:-1])
    for k, i in zip(steps + 1, drones, strict=True):
        name = Mode(int(traj.mode[k, i])).name.lower()
        found.append(Event(float(traj.t[k]), name, f"drone {i} {name}", int(i)))
    return sorted(found, key=lambda e: e.t)
