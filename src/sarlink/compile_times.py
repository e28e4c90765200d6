"""How long compiling the engine takes: the estimate said before it starts, from this
machine's record of its last compiles.

A part is one Numba compilation a sweep needs (:func:`sarlink.execution._parts`): the kernel
of a distributed rule (or of routes only) with a radio model, the scan of a flight's
notification staircase, or the mTSP GA. Each is compiled once per machine and loaded from
Numba's disk cache after; an edit to the engine compiles it again, and it is then that the
record (``<cache>/compile-seconds.json``, :func:`sarlink.cachedir.cache_root`) gives the
estimate. Before any record, :data:`TYPICAL` does.
"""

from __future__ import annotations

import contextlib
import json
from collections.abc import Sequence
from pathlib import Path

from sarlink.cachedir import cache_root
from sarlink.planners import get_planner

__all__ = ["CHAIN_PART", "TYPICAL", "compile_estimate", "describe_parts", "part_relays",
           "record_compile"]

CHAIN_PART = "chain"
"""The item that ends the part of a kernel whose team forms a chain to a found target
(``on_detect = relay``)."""


def part_relays(part: tuple[str, ...]) -> str | None:
    """The relay strategy a kernel part names (its fourth item unless that is
    :data:`CHAIN_PART`), None for a team without."""
    rest = [item for item in part[3:] if item != CHAIN_PART]
    return rest[0] if rest else None

TYPICAL = {"kernel": 30.0, "staircase": 15.0, "GA": 15.0}
"""Rough CPU seconds of one part on a 2-core x86-64 machine, by kind, used until this
machine has compiled a part of that name (the kernels range from about 10 s for routes only
to about 50 s for ConCov)."""


def _name(part: tuple[str, ...]) -> str:
    if part[0] == "mtsp":
        return "GA"
    if part[0] == "ranges":
        return "staircase"
    rule = get_planner(part[1]).rule
    relays = f" with relays ({part_relays(part)})" if part_relays(part) else ""
    chain = " forming a chain" if CHAIN_PART in part[3:] else ""
    return f"kernel {rule.name if rule is not None else 'routes'}{relays}{chain}"


def _file() -> Path:
    return cache_root() / "compile-seconds.json"


def _record() -> dict[str, float]:
    with contextlib.suppress(OSError, ValueError):
        data = json.loads(_file().read_text())
        if isinstance(data, dict):
            return {str(k): float(v) for k, v in data.items()}
    return {}


def describe_parts(parts: Sequence[tuple[str, ...]]) -> str:
    """``"kernels of routes, covb and conb, the GA"``: what is about to compile."""
    names = [_name(p) for p in parts]
    rules = [n.removeprefix("kernel ") for n in names if n.startswith("kernel ")]
    kernels = [] if not rules else [
        f"kernel{'s' if len(rules) > 1 else ''} of "
        + (rules[0] if len(rules) == 1 else f"{', '.join(rules[:-1])} and {rules[-1]}")]
    others = [f"the {n}" for n in names if not n.startswith("kernel ")]
    return ", ".join(kernels + others)


def compile_estimate(parts: Sequence[tuple[str, ...]], workers: int) -> float:
    """Wall seconds to compile ``parts`` on ``workers`` processes: this machine's last time
    for each part where it has one, :data:`TYPICAL` else; the parts spread over the workers,
    so no less than the longest."""
    record = _record()
    seconds = [record.get(n, TYPICAL[n.split()[0]]) for n in map(_name, parts)]
    return max(max(seconds, default=0.0), sum(seconds) / max(workers, 1))


def record_compile(part: tuple[str, ...], seconds: float) -> None:
    """Keep ``seconds`` as this machine's time for ``part`` (best effort: a cache folder that
    cannot be written loses only the estimate)."""
    record = _record()
    record[_name(part)] = round(seconds, 1)
    with contextlib.suppress(OSError):
        _file().parent.mkdir(parents=True, exist_ok=True)
        _file().write_text(json.dumps(record, indent=1, sort_keys=True))
