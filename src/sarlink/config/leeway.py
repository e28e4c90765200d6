"""What drifts and what drives it: the Leeway model's object classes and the forcing tables
(docs/model.md, Target motion, ``drift``).

The Leeway model (Allen and Plourde 1999, *Review of Leeway: Field Experiments and
Implementation*, USCG R&D Center report CG-D-08-99; Allen 2005, *Leeway Divergence*, CG-D-05-05)
fits an object's leeway, its motion through the water under the wind, by two components linear
in the 10 m wind speed ``W``: downwind ``L_d = a_d W + b_d`` and crosswind ``L_c = a_c W + b_c``,
with separate crosswind fits for an object right (``CWR``) and left (``CWL``) of downwind, and
the standard error of each fit. The coefficients below are those of OpenDrift's table
``opendrift/models/OBJECTPROP.DAT`` (commit 130bc999, "updated 2011-08-25 by Oyvind Breivik
based on the SAROPS list received from Art Allen"), for sixteen common classes: slopes in %
(cm/s per m/s of wind), offsets and standard errors in cm/s. The table lives here, with the
configuration, so that a mission's ``drift_object`` is checked against it when the mission is
made; the engine's ``drift`` motion reads the same table.

Wind and current are each a table of rows ``(t, east, north)`` (s, m/s, m/s) with increasing
times, read by linear interpolation and held at the ends: a constant is the one row
``(0, east, north)``, and a pair ``(east, north)`` is taken as that row.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from itertools import pairwise
from typing import Any

from sarlink.config.base import ConfigError

__all__ = ["LEEWAY_CLASSES", "Forcing", "LeewayClass", "forcing_table", "leeway_class"]

Forcing = tuple[tuple[float, float, float], ...]
"""A wind or current table: rows ``(t, east, north)``, times increasing (s, m/s, m/s)."""


@dataclass(frozen=True)
class LeewayClass:
    """One object class's leeway fits: downwind (``dw``), crosswind right (``cwr``) and left
    (``cwl``) of downwind, each a slope (%), an offset (cm/s) and the fit's standard error
    (cm/s), as in OBJECTPROP.DAT's nine columns."""

    name: str
    description: str
    dw: tuple[float, float, float]
    cwr: tuple[float, float, float]
    cwl: tuple[float, float, float]

    @property
    def coefficients(self) -> tuple[float, ...]:
        """The nine numbers in OBJECTPROP.DAT's order."""
        return (*self.dw, *self.cwr, *self.cwl)


def _row(name: str, description: str, *c: float) -> LeewayClass:
    return LeewayClass(name, description, (c[0], c[1], c[2]), (c[3], c[4], c[5]),
                       (c[6], c[7], c[8]))


LEEWAY_CLASSES: dict[str, LeewayClass] = {c.name: c for c in (
    _row("PIW-1", "person in water, unknown state (mean values)",
         0.96, 0.00, 12.00, 0.54, 0.00, 9.40, -0.54, 0.00, 9.40),
    _row("PIW-2", "person in water, vertical, PFD type III, conscious",
         0.48, 0.00, 8.30, 0.15, 0.00, 6.70, -0.15, 0.00, 6.70),
    _row("PIW-3", "person in water, sitting, PFD type I or II",
         1.60, -3.98, 2.42, 0.13, 0.33, 2.11, -0.13, -0.33, 2.11),
    _row("PIW-4", "person in water, survival suit (face up)",
         1.71, 1.12, 3.93, 1.36, -3.30, 1.71, -0.13, -2.65, 1.62),
    _row("PIW-5", "person in water, scuba suit (face up)",
         0.63, 0.00, 5.30, 0.31, 0.00, 4.50, -0.31, 0.00, 4.50),
    _row("PIW-6", "person in water, deceased (face down)",
         1.117, 10.2, 3.04, 0.04, 3.90, 4.05, -0.04, -3.90, 4.05),
    _row("LIFE-RAFT-DB-10", "life raft, deep ballast, general (mean values)",
         3.52, -2.50, 6.10, 0.62, -3.00, 3.50, -0.45, -0.20, 3.60),
    _row("LIFE-RAFT-SB-6", "life raft, shallow ballast and canopy, general (mean values)",
         2.68, 0.00, 12.00, 1.10, 0.00, 9.40, -1.10, 0.00, 9.40),
    _row("LIFE-RAFT-NB-1", "life raft, no ballast, general (mean values)",
         3.70, 0.00, 12.00, 1.98, 0.00, 9.40, -1.98, 0.00, 9.40),
    _row("PERSON-POWERED-VESSEL-1", "sea kayak with person on aft deck",
         1.16, 11.12, 4.12, 0.41, 0.00, 4.39, -0.41, 0.00, 4.39),
    _row("PERSON-POWERED-VESSEL-2", "surf board with person",
         1.93, 0.00, 8.30, 0.51, 0.00, 6.70, -0.51, 0.00, 6.70),
    _row("SKIFF-1", "skiff, modified-v cathedral hull, runabout outboard powerboat",
         3.15, 0.00, 2.20, 1.29, 0.00, 2.20, -1.29, 0.00, 2.20),
    _row("SKIFF-2", "skiff, v-hull",
         2.87, 3.98, 3.33, 0.32, -2.93, 2.53, -0.62, 1.03, 3.05),
    _row("FISHING-VESSEL-1", "fishing vessel, general (mean values)",
         2.47, 0.00, 12.00, 2.76, 0.00, 9.40, -2.76, 0.00, 9.40),
    _row("SAILBOAT-1", "sailboat, mono-hull (average)",
         4.5, 0.0, 19.4, 4.95, 0.0, 18.42, -2.82, 0.0, 24.95),
    _row("SLDMB", "self-locating datum marker buoy, no windage (moves with the current)",
         0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00),
)}
"""The supported object classes by OBJECTPROP.DAT's key."""


def leeway_class(name: str) -> LeewayClass:
    """The class named ``name``; a :class:`ConfigError` naming it and the known ones else."""
    if name not in LEEWAY_CLASSES:
        raise ConfigError(f"unknown Leeway object class {name!r}; known: "
                          f"{', '.join(LEEWAY_CLASSES)}")
    return LEEWAY_CLASSES[name]


ALLOWED = ("a pair east,north (m/s) or a table of rows t,east,north (s, m/s, m/s) with "
           "increasing times, as an array or as text with rows separated by ';'")
"""What a forcing table may be, for messages."""


def _floats(row: list[Any]) -> list[float] | None:
    """The finite numbers of ``row`` (numbers or their text), or None if one is not."""
    out = []
    for value in row:
        if isinstance(value, bool) or not isinstance(value, int | float | str):
            return None
        try:
            number = float(value)
        except ValueError:
            return None
        if not math.isfinite(number):
            return None
        out.append(number)
    return out


def _rows(value: Any) -> list[list[Any]] | None:
    """The rows of ``value``: text ``"e,n"`` or ``"t,e,n; t,e,n"``, a pair, or rows."""
    if isinstance(value, str):
        return [row.split(",") for row in value.split(";")] if value.strip() else None
    if not isinstance(value, Sequence) or len(value) == 0:
        return None
    if all(not isinstance(v, Sequence) for v in value):
        return [list(value)]
    if any(isinstance(row, str) or not isinstance(row, Sequence) for row in value):
        return None
    return [list(row) for row in value]


def forcing_table(value: Any) -> Forcing:
    """``value`` as a forcing table: a pair ``(east, north)`` is the constant ``((0, east,
    north),)``; rows ``(t, east, north)`` must have increasing times; text gives the same
    with commas between numbers and ``;`` between rows. Anything else is a
    :class:`ConfigError` saying what is allowed."""
    numbers = [_floats(row) for row in _rows(value) or []]
    rows = [row for row in numbers if row is not None]
    if not rows or len(rows) < len(numbers):
        raise ConfigError(f"expected {ALLOWED}")
    if len(rows) == 1 and len(rows[0]) == 2:
        return ((0.0, rows[0][0], rows[0][1]),)
    if any(len(row) != 3 for row in rows):
        raise ConfigError(f"expected {ALLOWED}")
    table = tuple((t, e, n) for t, e, n in rows)
    for before, after in pairwise(table):
        if after[0] <= before[0]:
            raise ConfigError(f"times out of order ({after[0]:g} s after {before[0]:g} s); "
                              f"expected {ALLOWED}")
    return table
