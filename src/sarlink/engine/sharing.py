"""Missions that share their flights: the runs of several missions with the same seed, each
the same, bit for bit, as flying it alone.

Two kinds of sharing, both exact:

- **One team at several ranges.** A range-free team (:attr:`Prepared.range_free`) flies the
  same at every ``r_c``: each run is flown once and scanned at every range
  (:meth:`Prepared.run_ranges`).
- **A run whose drones report, from the same run without reporting.** ``on_detect = report``
  changes what a drone does only once it knows where the target is while the BS does not
  (:func:`sarlink.engine.motion.report`). If nothing is detected, or the BS is told in the
  step of the first detection (immediate notification), no drone ever reports: the run is the
  same flight as with ``on_detect = continue``, and its record is that run's, ended where its
  own ``stop`` ends it. Only the other runs are flown. A distributed rule takes part only if it
  declares that its hooks never read what differs (``ignores_reporting``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from sarlink.engine.codes import ON_DETECT_CODES, STOP_CODES
from sarlink.engine.params import REPORT
from sarlink.engine.run import Prepared
from sarlink.result import RunResult

HORIZON = int(STOP_CODES["horizon"])
CONTINUE = int(ON_DETECT_CODES["continue"])


def fly(prepared: Sequence[Prepared], staircase: Sequence[bool], seed: int,
        runs: range) -> list[list[RunResult]]:
    """Runs ``runs`` of each mission of ``prepared``, sharing the flights they share;
    ``staircase[i]``: mission ``i``'s rows carry the notification staircase (a range-free
    team's, :meth:`Prepared.run_ranges`)."""
    out: dict[int, list[RunResult]] = {}
    same: dict[tuple[str, bool], int] = {}  # the same mission twice (two folders): flown once
    copies = {i: same.setdefault((p.mission.model_dump_json(), staircase[i]), i)
              for i, p in enumerate(prepared)}
    kept = [i for i in copies if copies[i] == i]
    bases = {i: _base_of(prepared, i, kept) for i in kept}
    flown = [i for i, b in bases.items() if b is None]
    for group in _range_groups([prepared[i] for i in flown], [staircase[i] for i in flown]):
        idx = [flown[g] for g in group]
        first = prepared[idx[0]]
        if first.range_free and (len(idx) > 1 or staircase[idx[0]]):
            rcs = [prepared[i].mission.channel.rc for i in idx]
            each = zip(*(first.run_ranges(seed, k, rcs, staircase=staircase[idx[0]])
                         for k in runs), strict=True)
            out.update((i, list(rows)) for i, rows in zip(idx, each, strict=True))
        else:
            out[idx[0]] = [first.run(seed, k) for k in runs]
    for i, b in bases.items():
        if b is not None:
            twin = prepared[i]
            out[i] = [reporting_twin(row, prepared[b], twin) or twin.run(seed, k)
                      for k, row in zip(runs, out[b], strict=True)]
    return [out[copies[i]] for i in range(len(prepared))]


def _range_groups(prepared: Sequence[Prepared], staircase: Sequence[bool]) -> list[list[int]]:
    """Indices of ``prepared`` in groups flown as one: the missions of one range-free team
    that differ only in ``r_c``, with the same routes (a route function may read ``r_c``) and
    rows alike (``staircase``); every other mission alone."""
    groups: list[list[int]] = []
    for i, p in enumerate(prepared):
        for group in groups:
            first = prepared[group[0]]
            if (p.range_free and first.range_free and staircase[i] == staircase[group[0]]
                    and p.mission.replace(rc=first.mission.channel.rc) == first.mission
                    and np.array_equal(p.waypoints, first.waypoints)
                    and np.array_equal(p.wp_start, first.wp_start)
                    and np.array_equal(p.radio_params, first.radio_params)):
                group.append(i)
                break
        else:
            groups.append([i])
    return groups


def _base_of(prepared: Sequence[Prepared], i: int, among: Sequence[int]) -> int | None:
    """The mission of ``prepared`` (one of ``among``) whose runs mission ``i``'s reporting
    runs may be taken from: the same mission with ``on_detect = continue``, ending no earlier
    (``stop``)."""
    twin = prepared[i]
    if twin.params.on_detect != REPORT or not _ignores_reporting(twin):
        return None
    for j in among:
        base = prepared[j]
        m = base.mission
        if (base.params.on_detect == CONTINUE
                and (twin.params.stop != HORIZON or base.params.stop == HORIZON)
                and twin.mission.replace(on_detect=m.team.on_detect, reporters=m.team.reporters,
                                         stop=m.timing.stop) == m
                and np.array_equal(twin.waypoints, base.waypoints)
                and np.array_equal(twin.wp_start, base.wp_start)):
            return j
    return None


def _ignores_reporting(prepared: Prepared) -> bool:
    rule = prepared.steering.rule
    return not prepared.distributed.any() or (rule is not None and rule.ignores_reporting)


def reporting_twin(base: RunResult, base_mission: Prepared, twin: Prepared) -> RunResult | None:
    """The run of ``twin`` (``on_detect = report``) with ``base``'s seed and index, from
    ``base``, the run of the same mission with ``on_detect = continue`` (:func:`_base_of`),
    if no drone of it ever reports; None if it must be flown.

    The twin stops at a detection (``stop`` ``detected`` or ``notified``, the same step for an
    immediate notification) or at the horizon; its cumulative records end there (NaN after)."""
    if base.t_detect is not None and not base.immediate:
        return None  # a drone knew, the BS did not: it reports
    if base.t_detect is not None and base_mission.params.stop != HORIZON and (
            twin.params.stop == HORIZON):
        return None  # the base ended at the detection, the twin flies on
    records: tuple[np.ndarray, ...] = (base.reach_cum, base.connected_cum, base.depth,
                                       base.farthest)
    if base.t_detect is not None and twin.params.stop != HORIZON:
        after = base.checkpoints > base.t_detect
        records = tuple(np.where(after, np.nan, values) for values in records)
    reach, conn, depth, farthest = records
    return replace(base, reach_cum=reach, connected_cum=conn, depth=depth, farthest=farthest,
                   notify_times=None, notify_rc2=None)
