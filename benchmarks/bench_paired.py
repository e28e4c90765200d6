"""Paired timing of the engine against the engine of another git revision, on the same runs.

The host's speed drifts by tens of percent within an hour, so timings of two engine versions
taken minutes apart cannot show a 10 % change. This script loads the git revision's whole
package beside the working tree's (``git archive REV src/sarlink``, renamed ``sarlink_rev``,
compiled without the disk cache), runs every run with both kernels back to back in
alternating order, and reports the median of the paired time ratios. It also counts the runs
whose results are identical, bit for bit.

The kernel compiled first in a process runs faster, by 10-40 % for identical code (where the
machine code lands in memory matters), so each case is measured in two processes, one per
compile order, and the speed-up is the geometric mean of their two medians. Run with

    python benchmarks/bench_paired.py 5c5ff3d --cases covb:22,conb:22 --runs 10 --rounds 6

``--plugin covb`` flies the working tree's CovB both ways instead: as the built-in rule and
as the same rule written outside sarlink (``tests/plugins/covb_again.py``), the plug-in path.
``--ranges 250,500,...`` times range-free flights scanned at those ranges as they fly (a sweep
over ``rc``, :mod:`sarlink.engine.critical_ranges`) instead of recorded flights, and compares every
range's records. Both revisions must have ``Prepared.record(streams, scenario,
trajectory=..., scan_at=...)`` (``read_at`` before the range scan was named so).
"""

from __future__ import annotations

import argparse
import importlib
import io
import math
import re
import subprocess
import sys
import tarfile
import tempfile
import time
from inspect import signature
from pathlib import Path
from types import ModuleType
from typing import Any, get_args

import numpy as np

import results_file
from sarlink import Mission, prepare
from sarlink.config.experiment import ADDED_LATER
from sarlink.engine.build import kernel_for
from sarlink.engine.radios import get_radio
from sarlink.engine.streams import run_streams

ROOT = Path(__file__).resolve().parents[1]
_NAME = re.compile(r"\bsarlink\b(?=[.\s,)])")
REGION: dict[str, str] = {}
"""``--region``: the cases' area (and prior), as the mission's ``region`` table."""


def load_revision(rev: str, folder: Path) -> ModuleType:
    """The package ``sarlink`` of git revision ``rev`` as ``sarlink_rev``, without disk cache."""
    tar = subprocess.run(["git", "archive", rev, "src/sarlink"], cwd=ROOT, check=True,
                         capture_output=True).stdout
    with tarfile.open(fileobj=io.BytesIO(tar)) as archive:
        archive.extractall(folder, filter="data")
    package = folder / "src" / "sarlink"
    for path in package.rglob("*.py"):
        text = _NAME.sub("sarlink_rev", path.read_text()).replace("cache=True", "cache=False")
        # the registries know sarlink's own modules by the package's name (registry.SARLINK)
        path.write_text(text.replace('SARLINK = "sarlink"', 'SARLINK = "sarlink_rev"'))
    package.rename(folder / "sarlink_rev")
    sys.path.insert(0, str(folder))
    return importlib.import_module("sarlink_rev")


class Side:
    """One engine to time: flies run ``r`` of a case and returns (seconds, record).

    ``kernel_of`` picks the kernel for a prepared mission; ``None`` calls the revision's own
    ``record()``, whose kernel is compiled without disk cache.
    """

    def __init__(self, mission_of: Any, prepare_of: Any, kernel_of: Any = None) -> None:
        self.mission_of, self.prepare_of, self.kernel_of = mission_of, prepare_of, kernel_of

    def run_once(self, case: str, reading: str, seed: int, run: int,
                 scan_at: tuple[float, ...] = ()) -> tuple[float, Any]:
        """Fly run ``run``: recorded, or scanned at the ranges ``scan_at`` if any."""
        prepared = self.prepare_of(self.mission_of(case, reading))
        # the keyword as the side's revision names it
        keyword = "scan_at" if "scan_at" in signature(prepared.record).parameters else "read_at"
        how: dict[str, Any] = {keyword: scan_at} if scan_at else {"trajectory": True}
        streams = run_streams(seed, run)
        # each side draws with its own revision's draw_scenario, which its run module imports
        draw = sys.modules[type(prepared).__module__].draw_scenario
        scenario = draw(prepared.mission, streams.scenario)
        if self.kernel_of is None:
            start = time.perf_counter()
            out = prepared.record(streams, scenario, **how)
        else:
            kernel = self.kernel_of(prepared)
            args = prepared.arguments(streams, scenario, **how)
            start = time.perf_counter()
            out = kernel(*args)
        return time.perf_counter() - start, out


def outcome(out: Any) -> list[np.ndarray]:
    """A run record as a list of arrays: events, records, trajectory, records at each range."""
    events = np.array([out.t_detect, out.t_notify, float(out.detector),
                       1.0 if out.immediate else 0.0])
    tr, at = out.track, out.at_ranges
    return [events, out.reach_cum, out.conn_cum, tr.positions, tr.headings, tr.knows,
            tr.bs_route, tr.mode, at.notified, at.reach_cum, at.conn_cum]


def case_mission(case: str, reading: str) -> Mission:
    """The mission of a ``planner:drones[:rc[:sigma]]`` case under a named reading, over the
    area of ``--region`` (:data:`REGION`) if one is given."""
    planner, drones, *rest = case.split(":")
    mission = Mission.build(reading=reading, planner=planner, drones=int(drones),
                            rc=float(rest[0]) if rest else 1000.0,
                            sigma=float(rest[1]) if len(rest) > 1 else 0.0)
    if not REGION:
        return mission
    return Mission.from_dict({**mission.model_dump(exclude={"channel": {"radio"}}),
                              "region": REGION})


def uncached(rule: Any) -> Any:
    """A kernel picker: ``rule`` (or the mission's own), compiled without disk cache."""
    def kernel_of(prepared: Any) -> Any:
        chosen = prepared.steering.rule if rule is None else rule
        return kernel_for(chosen, get_radio(prepared.mission.radio), cache=False)
    return kernel_of


def sides(rev: str, folder: Path) -> dict[str, Side]:
    """The two engines: ``old`` (revision ``rev``; with ``rev = plugin`` the built-in CovB)
    and ``new`` (the working tree; with ``plugin`` CovB written as a plug-in)."""
    if rev == "plugin":
        sys.path.insert(0, str(ROOT / "tests" / "plugins"))
        from covb_again import COVB_AGAIN  # type: ignore[import-not-found]

        return {"old": Side(case_mission, prepare, uncached(None)),
                "new": Side(case_mission, prepare, uncached(COVB_AGAIN))}
    old = load_revision(rev, folder)

    def old_mission(case: str, reading: str) -> Any:
        """The case as the old revision's mission: choices named since are left out where
        they hold the behaviour of before (else the revision cannot fly the case)."""
        data = case_mission(case, reading).model_dump(exclude={"channel": {"radio"}})
        for group, fields in data.items():
            if not isinstance(fields, dict):
                continue
            annotation = old.config.mission.Mission.model_fields[group].annotation
            known = next(a for a in get_args(annotation) or (annotation,)  # a table or None
                         if hasattr(a, "model_fields")).model_fields
            for name, value in list(fields.items()):
                if name not in known:
                    if ADDED_LATER.get(group, {}).get(name, ...) != value:
                        raise SystemExit(f"{rev} cannot fly {group}.{name} = {value!r}")
                    del fields[name]
        return old.Mission(**data)

    return {"old": Side(old_mission, old.prepare), "new": Side(case_mission, prepare,
                                                               uncached(None))}


def measure(rev: str, case: str, runs: int, rounds: int, new_first: bool, reading: str,
            scan_at: tuple[float, ...]) -> None:
    """Print ``identical speed-up`` for one case, with the kernels compiled in one order."""
    with tempfile.TemporaryDirectory() as tmp:
        both = sides(rev, Path(tmp))
        order = ("new", "old") if new_first else ("old", "new")
        for tag in order:  # compile in that order
            both[tag].run_once(case, reading, 1, 0, scan_at)
        same = sum(all(np.array_equal(a, b, equal_nan=a.dtype.kind == "f") for a, b in
                       zip(outcome(both["old"].run_once(case, reading, 1, r, scan_at)[1]),
                           outcome(both["new"].run_once(case, reading, 1, r, scan_at)[1]),
                           strict=True))
                   for r in range(runs))
        ratios = []
        for rnd in range(rounds):
            for r in range(runs):
                pair_order = ["old", "new"][:: 1 if (rnd + r) % 2 == 0 else -1]
                pair = {tag: both[tag].run_once(case, reading, 1, r, scan_at)[0]
                        for tag in pair_order}
                ratios.append(pair["old"] / pair["new"])
    print(same, np.median(ratios))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rev", help="git revision of the engine to compare with, or 'plugin' "
                                    "(built-in CovB against CovB as a plug-in)")
    parser.add_argument("--cases", default="covb:22,conb:22",
                        help="planner:drones[:rc[:sigma]] items, comma-separated")
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=6)
    parser.add_argument("--reading", default="sarlink-1",
                        help="the reading of the paper to fly (default: sarlink-1, the rules "
                             "of kernels before readings were selectable)")
    parser.add_argument("--ranges", default="",
                        help="comma-separated ranges (m): fly each case scanned at them (a "
                             "range-free team) instead of recorded")
    parser.add_argument("--region", default="",
                        help="AREA[,PRIOR]: GeoJSON files of a polygon area (and its prior) "
                             "to fly every case over instead of the paper's square")
    parser.add_argument("--out", type=Path, help="write the results here (markdown)")
    parser.add_argument("--one", choices=["old-first", "new-first"], help=argparse.SUPPRESS)
    args = parser.parse_args()
    scan_at = tuple(float(rc) for rc in args.ranges.split(",") if rc)
    if args.region:
        area, *prior = args.region.split(",")
        REGION.update({"area": str(Path(area).resolve()),
                       **({"prior": str(Path(prior[0]).resolve())} if prior else {})})
    if args.one:  # one compile order, in a process of its own
        measure(args.rev, args.cases, args.runs, args.rounds, args.one == "new-first",
                args.reading, scan_at)
        return
    lines = []
    for case in args.cases.split(","):
        results = {}
        for order in ("old-first", "new-first"):
            out = subprocess.run([sys.executable, __file__, args.rev, "--cases", case,
                                  "--runs", str(args.runs), "--rounds", str(args.rounds),
                                  "--reading", args.reading, "--ranges", args.ranges,
                                  "--region", args.region, "--one", order],
                                 check=True, capture_output=True, text=True)
            same, ratio = out.stdout.split()
            results[order] = (int(same), float(ratio))
        same = min(s for s, _ in results.values())
        speedup = math.sqrt(results["old-first"][1] * results["new-first"][1])
        lines.append(f"{case:16s} identical {same}/{args.runs}  speed-up {speedup:.3f} "
                     f"(paired medians: old compiled first {results['old-first'][1]:.3f}, "
                     f"new first {results['new-first'][1]:.3f})")
        print(lines[-1], flush=True)
    if args.out:
        results_file.write(args.out, f"Paired timing: this tree against {args.rev}", "\n".join([
            f"Reading {args.reading}, seed 1, runs 0-{args.runs - 1}, {args.rounds} rounds"
            + (f", range-free flights scanned at {args.ranges} m" if scan_at else "")
            + (f", over the area {args.region}" if args.region else "")
            + ". Speed-up = old time / new time, the geometric mean of the medians of the "
            "paired ratios in the two compile orders; identical = runs whose every output is "
            "bit for bit the same.", "", "```", *lines, "```"]))


if __name__ == "__main__":
    main()
