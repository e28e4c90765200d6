"""Run tables evaluated at a communication range that was not flown.

A range-free run (:attr:`sarlink.engine.Prepared.range_free`) of an experiment with
``staircase = true`` is stored with its notification staircase (``notify_times``,
``notify_rc2``, :class:`sarlink.RunResult`): at a range ``r_c``
the BS is notified at ``notify_times[j]`` for the first ``j`` with
``notify_rc2[j] <= r_c * r_c``. That is all that detection and notification need, so
``P_d``, ``P_s`` at every ``t_d``, the mission time, the search share and immediate
notification follow at any range, exactly. Reachability, connectivity and the BS's network
(depth, farthest connected drone) need the geometry of every step, which the rows do not keep
(it would be some 40 times their size): they are NaN at a range that was not flown.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pandas as pd

from sarlink.config import ConfigError, param_groups
from sarlink.metrics import wilson

__all__ = ["at_range", "needed_ranges", "notify_time", "range_curve"]


def notify_time(times: np.ndarray, rc2: np.ndarray, rc: float) -> float:
    """When the BS is notified at range ``rc`` by a run's staircase, s (NaN: never)."""
    below = np.flatnonzero(np.asarray(rc2) <= rc * rc)
    return float(np.asarray(times)[below[0]]) if below.size else math.nan


def needed_ranges(runs: pd.DataFrame, td: float) -> np.ndarray:
    """Each run's needed range, m: the smallest at which its BS is notified by ``td`` (``inf``:
    at none, or a run without a staircase), from its staircase. A run notified at some range
    is notified at every larger one, so ``P_s(td, r_c)`` is the share of runs whose needed
    range is at most ``r_c``."""
    out = np.full(len(runs), math.inf)
    if "notify_times" not in runs:
        return out
    for i, (times, keys) in enumerate(zip(runs["notify_times"], runs["notify_rc2"],
                                          strict=True)):
        if times is None or (isinstance(times, float) and math.isnan(times)):
            continue
        times, keys = np.asarray(times, dtype=float), np.asarray(keys, dtype=float)
        by = keys[times <= td]
        if by.size:
            out[i] = math.sqrt(float(by.min()))
    return out


def range_curve(runs: pd.DataFrame, rcs: np.ndarray, td: float, by: list[str]) -> pd.DataFrame:
    """``P_s(td)`` against the communication range: for every group of ``by`` whose runs all
    carry a staircase, a row per range of ``rcs`` with ``P_s`` and its 95 % Wilson interval
    (columns ``*by, td, rc, runs, P_s, P_s_lo, P_s_hi``). Groups flown per range are left out."""
    has = (runs["notify_times"].notna() if "notify_times" in runs
           else pd.Series(False, index=runs.index))
    rows = []
    for key, group in runs.groupby(by, sort=False):
        if not has[group.index].all():
            continue
        needed = np.sort(needed_ranges(group, td))
        hits = np.searchsorted(needed, np.asarray(rcs, dtype=float), side="right")
        lo, hi = wilson(hits, len(needed))
        values = dict(zip(by, key if isinstance(key, tuple) else (key,), strict=True))
        rows.append(pd.DataFrame({**values, "td": td, "rc": rcs, "runs": len(needed),
                                  "P_s": hits / len(needed), "P_s_lo": lo, "P_s_hi": hi}))
    if not rows:
        return pd.DataFrame(columns=[*by, "td", "rc", "runs", "P_s", "P_s_lo", "P_s_hi"])
    return pd.concat(rows, ignore_index=True)


def at_range(runs: pd.DataFrame, rc: float) -> pd.DataFrame:
    """The runs of ``runs`` (as :func:`sarlink.load` returns them) at the range ``rc``, m.

    Runs flown at ``rc`` are kept as they are. Every other range-free run is evaluated from the
    row of the same run at the largest flown range below ``rc`` (the smallest flown range
    if there is none): its ``rc`` becomes ``rc``, ``t_notify`` and ``immediate`` are read
    from the staircase, and ``reach_cum``, ``connected_cum``, ``depth``, ``farthest``,
    ``t_reachable`` and ``connected_fraction`` are NaN. Runs of teams that fly differently at
    each range are left out, with a warning, unless they were flown at ``rc``; so are runs
    stored without a staircase (an experiment without ``staircase = true``).
    """
    if not (math.isfinite(rc) and rc > 0):
        raise ConfigError(f"rc must be a finite range > 0 m, got {rc:g}")
    if runs.empty:
        raise ConfigError("no runs to evaluate at a range")
    others = [p for p in param_groups() if p in runs.columns and p != "rc"]
    team = runs.groupby(others, sort=False, dropna=False).ngroup().to_numpy()
    run = runs["run"].to_numpy(dtype=np.int64)
    key = pd.Series(team * (int(run.max()) + 1) + run, index=runs.index)  # one per team's run
    flown = runs["rc"].to_numpy(dtype=float)
    staircase = (runs["notify_times"].notna().to_numpy() if "notify_times" in runs
                 else np.zeros(len(runs), dtype=bool))
    # per run: the row at rc, or else the staircase row at the largest flown range below
    # it, or else at the smallest flown range
    rank = np.where(flown == rc, 0, np.where(flown < rc, 1, 2))
    order = np.lexsort((np.where(rank == 1, -flown, flown), rank, key.to_numpy()))
    first = runs.iloc[order].assign(_key=key.to_numpy()[order], _rank=rank[order],
                                    _stairs=staircase[order])
    first = first[(first["_rank"] == 0) | first["_stairs"]]
    chosen = first.drop_duplicates("_key", keep="first")
    if chosen.empty:
        raise ConfigError(f"no run can be evaluated at r_c = {rc:g} m: it was not flown, and no "
                          "row carries a notification staircase (a team that flies the same "
                          "at every range, swept with staircase = true)")
    left_out = set(key) - set(chosen["_key"])
    if left_out:
        warnings.warn(f"{len(left_out)} runs left out at r_c = {rc:g} m: they were not flown "
                      "at it and carry no notification staircase", stacklevel=2)
    moved = chosen["_rank"].to_numpy() != 0
    if (moved & (chosen["stop"].to_numpy() == "notified")
            & (chosen["rc"].to_numpy(dtype=float) > rc)).any():
        raise ConfigError(f"runs stopped at their notification say nothing below the "
                          f"smallest flown range; r_c = {rc:g} m is below it")
    out = chosen.drop(columns=["_key", "_rank", "_stairs"]).copy()
    if moved.any():
        rows = np.flatnonzero(moved)
        t_notify = out["t_notify"].to_numpy(dtype=float).copy()
        for i in rows:
            t_notify[i] = notify_time(out["notify_times"].iat[i], out["notify_rc2"].iat[i], rc)
        t_detect = out["t_detect"].to_numpy(dtype=float)
        immediate = out["immediate"].to_numpy(dtype=bool).copy()
        immediate[rows] = t_notify[rows] == t_detect[rows]
        out["t_notify"], out["immediate"] = t_notify, immediate
        out["rc"] = np.where(moved, rc, out["rc"].to_numpy(dtype=float))
        for column in ("t_reachable", "connected_fraction"):
            out[column] = np.where(moved, np.nan, out[column].to_numpy(dtype=float))
        for column in ("reach_cum", "connected_cum", "depth", "farthest"):
            if column not in out:  # files written before the engine kept the BS's network
                continue
            values = out[column].to_list()
            for i in rows:
                values[i] = [math.nan] * len(values[i])
            out[column] = values
    return out.sort_values(["point", "run"], kind="stable").reset_index(drop=True)
