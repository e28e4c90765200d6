"""How long compiling the engine takes: the estimate said before it starts, from this
machine's record of its last compiles.

A part (:class:`Part`) is one Numba compilation a sweep needs: the kernel of a distributed
rule (or of routes only) with a radio model and the seams its missions compile in, the scan
of a flight's notification staircase, or the mTSP GA. Each is compiled once per machine and
loaded from Numba's disk cache after; an edit to the engine compiles it again, and it is then
that the record (``<cache>/compile-seconds.json``, :func:`sarlink.cachedir.cache_root`) gives
the estimate. Before any record, :data:`TYPICAL` does.
"""

from __future__ import annotations

import contextlib
import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

from sarlink.cachedir import cache_root
from sarlink.config import Mission
from sarlink.engine.build import kernel_for
from sarlink.engine.radios import get_radio
from sarlink.engine.relays import get_relay_strategy
from sarlink.engine.target_motion import get_target_motion
from sarlink.planners import get_planner
from sarlink.simulation import warm_up

__all__ = ["TYPICAL", "Part", "compile_estimate", "describe_parts", "record_compile"]


@dataclass(frozen=True)
class Part:
    """One Numba compilation a sweep needs: the kernel of a planner's rule with a radio model
    and the seams its mission compiles in (``kind = "kernel"``), the scan of a flight's
    notification staircase (``"ranges"``), or the mTSP GA (``"mtsp"``)."""

    kind: Literal["kernel", "ranges", "mtsp"]
    planner: str = ""
    radio: str = "disc"
    relays: str | None = None
    """The relay strategy of a team with relays."""
    chain: bool = False
    """The chain to a found target (``on_detect = relay``)."""
    energy: bool = False
    """Batteries (``battery.battery_wh``)."""
    target: str | None = None
    """The motion model of a target that moves."""
    many: bool = False
    """Several targets (``target.count > 1``)."""

    @classmethod
    def kernel_of(cls, mission: Mission) -> Part:
        """The kernel ``mission`` flies (:attr:`sarlink.engine.Prepared.kernel`)."""
        team, motion = mission.team, get_target_motion(mission.target.motion)
        return cls("kernel", team.planner, mission.radio,
                   relays=team.relay_strategy if team.relays else None,
                   chain=team.on_detect == "relay",
                   energy=mission.battery.battery_wh is not None,
                   target=motion.name if motion.moves else None,
                   many=mission.target.count > 1)

    @property
    def name(self) -> str:
        """What compiles, as the notice and this machine's record name it."""
        if self.kind == "mtsp":
            return "GA"
        if self.kind == "ranges":
            return "staircase"
        rule = get_planner(self.planner).rule
        seams = [f"with relays ({self.relays})"] if self.relays else []
        seams += ["forming a chain"] * self.chain + ["on batteries"] * self.energy
        seams += [f"with a moving target ({self.target})"] if self.target else []
        seams += ["with several targets"] * self.many
        return " ".join(["kernel", rule.name if rule is not None else "routes", *seams])

    def kernel(self) -> Any:
        """The kernel of a kernel part, as :func:`sarlink.engine.build.kernel_for` memoizes it:
        the object a mission of this part flies (compiled on its first call)."""
        return kernel_for(get_planner(self.planner).rule, get_radio(self.radio),
                          get_relay_strategy(self.relays) if self.relays else None,
                          chain=self.chain, energy=self.energy,
                          target=get_target_motion(self.target) if self.target else None,
                          many=self.many)

    def compile(self) -> None:
        """Compile it in this process, or load it from Numba's disk cache."""
        if self.kind == "mtsp":
            from sarlink.mtsp import grid_cells, solve

            solve(grid_cells(1000.0, 500.0), (500.0, 500.0), 2, population=8, iterations=1)
            return
        warm_up(self.planner, self.radio, ranges=self.kind == "ranges", relays=self.relays,
                chain=self.chain, energy=self.energy, target=self.target, many=self.many)


TYPICAL = {"kernel": 30.0, "staircase": 15.0, "GA": 15.0}
"""Rough CPU seconds of one part on a 2-core x86-64 machine, by kind, used until this
machine has compiled a part of that name (the kernels range from about 10 s for routes only
to about 50 s for ConCov)."""


def _file() -> Path:
    return cache_root() / "compile-seconds.json"


def _record() -> dict[str, float]:
    with contextlib.suppress(OSError, ValueError):
        data = json.loads(_file().read_text())
        if isinstance(data, dict):
            return {str(k): float(v) for k, v in data.items()}
    return {}


def describe_parts(parts: Sequence[Part]) -> str:
    """``"kernels of routes, covb and conb, the GA"``: what is about to compile."""
    names = [p.name for p in parts]
    rules = [n.removeprefix("kernel ") for n in names if n.startswith("kernel ")]
    kernels = [] if not rules else [
        f"kernel{'s' if len(rules) > 1 else ''} of "
        + (rules[0] if len(rules) == 1 else f"{', '.join(rules[:-1])} and {rules[-1]}")]
    others = [f"the {n}" for n in names if not n.startswith("kernel ")]
    return ", ".join(kernels + others)


def compile_estimate(parts: Sequence[Part], workers: int) -> float:
    """Wall seconds to compile ``parts`` on ``workers`` processes: this machine's last time
    for each part where it has one, :data:`TYPICAL` else; the parts spread over the workers,
    so no less than the longest."""
    record = _record()
    seconds = [record.get(p.name, TYPICAL[p.name.split()[0]]) for p in parts]
    return max(max(seconds, default=0.0), sum(seconds) / max(workers, 1))


def record_compile(part: Part, seconds: float) -> None:
    """Keep ``seconds`` as this machine's time for ``part`` (best effort: a cache folder that
    cannot be written loses only the estimate)."""
    record = _record()
    record[part.name] = round(seconds, 1)
    with contextlib.suppress(OSError):
        _file().parent.mkdir(parents=True, exist_ok=True)
        _file().write_text(json.dumps(record, indent=1, sort_keys=True))
