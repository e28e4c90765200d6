"""The paper's measures, read from run event times for any target duration ``t_d``.

A run records when things happened (detection, notification, cumulative reachability), not
whether they happened by one ``t_d``, so every ``t_d`` up to the horizon is read from the same
runs (docs/model.md, "Records and metrics"). Probabilities come with 95% Wilson score
intervals, means with standard errors. Everything is computed on whole columns: group ids from
pandas, sums per group with ``np.bincount``. :data:`MEASURES` says how each measure is named
and printed, for the command line, the figures and the report alike.

The input is a table of runs as :func:`sarlink.load` returns it. The columns used are
``t_detect``, ``t_notify`` (NaN when the event did not happen) and ``immediate``, and for
reachability and connectivity ``reach_cum``, ``connected_cum`` and the ``checkpoints`` they
were recorded at, as the engine stored them (``horizon`` and ``checkpoint`` group the runs),
and for the BS's network its snapshots ``depth`` and ``farthest`` at the same checkpoints
(NaN where a table of runs stored before them lacks them).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from sarlink.config import param_groups

__all__ = ["MEASURES", "Z95", "Measure", "format_interval", "format_mean", "run_values",
           "success_curve", "summarize", "varying_params", "wilson"]

Z95 = 1.959963984540054
"""The standard normal quantile of 0.975: two-sided 95% intervals."""


def wilson(successes: np.ndarray | float, trials: np.ndarray | float,
           z: float = Z95) -> tuple[np.ndarray, np.ndarray]:
    """The Wilson score interval of a binomial proportion (NaN where ``trials`` is 0).

    Chosen over the normal (Wald) interval because it stays inside [0, 1] and keeps close to
    its nominal coverage near 0 and 1, where success probabilities often lie; it is a few lines,
    so no statistics package is needed. ``0`` successes give a lower bound of exactly 0 and
    ``trials`` successes an upper bound of exactly 1.
    """
    k = np.asarray(successes, dtype=float)
    n = np.asarray(trials, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        p = k / n
        scale = 1 + z**2 / n
        centre = (p + z**2 / (2 * n)) / scale
        half = z * np.sqrt(p * (1 - p) / n + z**2 / (4 * n**2)) / scale
    lo = np.where(k == 0, 0.0, centre - half)
    hi = np.where(k == n, 1.0, centre + half)
    return np.where(n > 0, lo, np.nan), np.where(n > 0, hi, np.nan)


def format_interval(value: float, lo: float, hi: float, digits: int = 3) -> str:
    """``0.532 [0.501, 0.563]``: an estimate with its interval; ``–`` when there is none."""
    if np.isnan(value):
        return "–"
    return f"{value:.{digits}f} [{lo:.{digits}f}, {hi:.{digits}f}]"


def format_mean(value: float, se: float, digits: int = 3) -> str:
    """``1234 ± 12``: a mean with its standard error (just the mean when the error is NaN)."""
    if np.isnan(value):
        return "–"
    return f"{value:.{digits}f}" + ("" if np.isnan(se) else f" ± {se:.{digits}f}")


@dataclass(frozen=True)
class Measure:
    """One of :func:`summarize`'s measures: its column, name, kind and how it is printed.

    The one definition the command line, the figures and the report format values with, so
    that a number reads the same everywhere.
    """

    column: str
    label: str
    probability: bool
    """A probability has ``_lo``/``_hi`` Wilson bounds; a mean has ``_se``."""
    unit: str = ""
    symbol: str = ""
    """The paper's symbol, as TeX without the dollars (``P_s``)."""
    share_of_td: bool = False
    """A fraction of t_d (drawn as a percentage)."""
    digits: int = 3

    def interval(self, row: Mapping[str, Any]) -> tuple[float, float, float]:
        """Value and 95% interval: Wilson for a probability, ± 1.96 standard errors for a mean."""
        value = float(row[self.column])
        if self.probability:
            return value, float(row[f"{self.column}_lo"]), float(row[f"{self.column}_hi"])
        half = Z95 * float(row[f"{self.column}_se"])
        return value, value - half, value + half

    def text(self, row: Mapping[str, Any]) -> str:
        """The value as printed: with its 95% interval (probability) or standard error (mean)."""
        if self.probability:
            return format_interval(*self.interval(row), self.digits)
        return format_mean(float(row[self.column]), float(row[f"{self.column}_se"]),
                           self.digits)


MEASURES = {m.column: m for m in (
    Measure("P_s", "mission success", True, symbol="P_s"),
    Measure("P_d", "detection probability", True, symbol="P_d"),
    Measure("immediate", "immediate notification", True),
    Measure("mission_time", "mission time", False, "s", digits=0),
    Measure("search_share", "search share of mission time", False),
    Measure("reachability", "target reachability", False, share_of_td=True),
    Measure("connected", "drones connected", False),
    Measure("depth", "depth of the BS's network", False, "hops", digits=2),
    Measure("farthest", "farthest connected drone", False, "m", digits=0),
    Measure("found", "targets found", False, digits=2),
    Measure("told", "targets the BS was told of", False, digits=2),
    Measure("sorties", "sorties per drone", False, digits=2),
    Measure("energy", "energy per drone", False, "Wh", digits=1),
)}
"""The measures of :func:`summarize`, by column."""


def varying_params(df: pd.DataFrame) -> list[str]:
    """The mission parameters that take more than one value in ``df``: a sweep's grid."""
    return [p for p in param_groups() if p in df.columns and df[p].nunique(dropna=False) > 1]


def _groups(df: pd.DataFrame, by: Sequence[str] | None) -> tuple[np.ndarray, pd.DataFrame]:
    """A group id per row (groups numbered in order of appearance) and each group's keys."""
    if df.empty:
        raise ValueError("no runs to summarise")
    by = varying_params(df) if by is None else list(by)
    if not by:
        return np.zeros(len(df), dtype=np.int64), pd.DataFrame(index=range(1))
    gid = df.groupby(by, sort=False, dropna=False).ngroup().to_numpy()
    _, first = np.unique(gid, return_index=True)
    return gid, df[by].iloc[first].reset_index(drop=True)


def _cum_at(df: pd.DataFrame, column: str, td: np.ndarray) -> np.ndarray:
    """A cumulative record (``reach_cum``, ``connected_cum``) of every run read at its ``td``.

    Records are read at the ``checkpoints`` the engine stored with them and interpolated
    linearly in between, as :meth:`sarlink.RunResult.t_reachable` does. Runs of one horizon
    and checkpoint spacing share their checkpoints, so each such group is read in one pass.
    """
    out = np.empty(len(df))
    spacing = df[["horizon", "checkpoint"]].to_numpy(dtype=float)
    combos, which = np.unique(spacing, axis=0, return_inverse=True)
    for c in range(len(combos)):  # one pass per sampling, not per run
        rows = np.flatnonzero(which.ravel() == c)
        values = np.stack(df[column].to_numpy()[rows])
        times = np.asarray(df["checkpoints"].iloc[rows[0]], dtype=float)
        if times.shape != values.shape[1:]:
            raise ValueError(f"{column} has {values.shape[1]} values for "
                             f"{times.size} checkpoints")
        j = np.clip(np.searchsorted(times, td[rows], side="right") - 1, 0, len(times) - 2)
        frac = (td[rows] - times[j]) / (times[j + 1] - times[j])
        picked = values[np.arange(len(rows)), j]
        out[rows] = picked + frac * (values[np.arange(len(rows)), j + 1] - picked)
    return out


def _snapshot_at(df: pd.DataFrame, column: str, td: np.ndarray) -> np.ndarray:
    """A snapshot record (``depth``, ``farthest``) of every run at its ``td``: the one taken at
    the last checkpoint at or before ``td`` (a snapshot is not interpolated). NaN for runs
    stored without it (files written before the engine kept it)."""
    out = np.full(len(df), np.nan)
    if column not in df:
        return out
    cells = df[column].to_numpy()
    stored = np.array([np.ndim(v) == 1 for v in cells], dtype=bool)
    spacing = df[["horizon", "checkpoint"]].to_numpy(dtype=float)
    combos, which = np.unique(spacing, axis=0, return_inverse=True)
    for c in range(len(combos)):  # one pass per sampling, as in _cum_at
        rows = np.flatnonzero((which.ravel() == c) & stored)
        if not rows.size:
            continue
        values = np.stack(cells[rows]).astype(float)
        times = np.asarray(df["checkpoints"].iloc[rows[0]], dtype=float)
        j = np.clip(np.searchsorted(times, td[rows], side="right") - 1, 0, len(times) - 1)
        out[rows] = values[np.arange(len(rows)), j]
    return out


def _td_per_run(df: pd.DataFrame, gid: np.ndarray, td: float | None) -> np.ndarray:
    """``td`` for every run, checked against its horizon; None: its group's shortest horizon."""
    horizon = df["horizon"].to_numpy(dtype=float)
    if td is None:
        shortest = np.full(gid.max() + 1, np.inf)
        np.minimum.at(shortest, gid, horizon)
        return shortest[gid]
    if not td > 0:
        raise ValueError(f"td must be positive, got {td}")
    if td > horizon.min():
        raise ValueError(f"td = {td:g} s is beyond the horizon ({horizon.min():g} s) of some "
                         "runs: their events after it were not simulated")
    return np.full(len(df), float(td))


class _Sums:
    """Per-group sums over the rows of a table."""

    def __init__(self, gid: np.ndarray) -> None:
        self.gid = gid
        self.groups = int(gid.max()) + 1

    def __call__(self, values: np.ndarray) -> np.ndarray:
        return np.bincount(self.gid, weights=values.astype(float), minlength=self.groups)

    def mean(self, values: np.ndarray, mask: np.ndarray) -> tuple[np.ndarray, np.ndarray,
                                                                  np.ndarray]:
        """The mean of ``values`` over the masked rows of each group, the rows' deviations from
        it (0 elsewhere) and the count."""
        count = self(mask)
        with np.errstate(divide="ignore", invalid="ignore"):
            mean = self(np.where(mask, values, 0.0)) / count
        return mean, np.where(mask, values - mean[self.gid], 0.0), count

    def covariance(self, dx: np.ndarray, dy: np.ndarray, count: np.ndarray) -> np.ndarray:
        """Sample covariance from deviations (NaN for fewer than two rows)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(count > 1, self(dx * dy) / (count - 1), np.nan)


def _measures(df: pd.DataFrame, gid: np.ndarray, td: np.ndarray) -> dict[str, np.ndarray]:
    """Every measure of every group at the per-run target durations ``td``."""
    sums = _Sums(gid)
    t_det = df["t_detect"].to_numpy(dtype=float)
    t_not = df["t_notify"].to_numpy(dtype=float)
    detected, notified = t_det <= td, t_not <= td
    immediate = detected & df["immediate"].to_numpy(dtype=bool)
    n, k_d, k_s, k_i = sums(np.ones(len(df))), sums(detected), sums(notified), sums(immediate)
    out: dict[str, np.ndarray] = {"td": np.bincount(gid, weights=td) / n, "runs": n.astype(int),
                                  "detected": k_d.astype(int), "notified": k_s.astype(int)}
    for name, k, trials in (("P_d", k_d, n), ("P_s", k_s, n), ("immediate", k_i, k_d)):
        with np.errstate(divide="ignore", invalid="ignore"):
            out[name] = k / trials
        out[f"{name}_lo"], out[f"{name}_hi"] = wilson(k, trials)

    # mission time and search share over the runs notified within td; the share is a ratio of
    # means, its standard error by the delta method:
    # Var(x̄/ȳ) ≈ (s_x² - 2 R s_xy + R² s_y²) / (k ȳ²)
    mean_det, dx, k = sums.mean(t_det, notified)
    mean_not, dy, _ = sums.mean(t_not, notified)
    var_det, var_not = sums.covariance(dx, dx, k), sums.covariance(dy, dy, k)
    cov = sums.covariance(dx, dy, k)
    with np.errstate(divide="ignore", invalid="ignore"):
        share = mean_det / mean_not
        out["mission_time"], out["mission_time_se"] = mean_not, np.sqrt(var_not / k)
        out["search_share"] = share
        out["search_share_se"] = np.sqrt(
            np.maximum(var_det - 2 * share * cov + share**2 * var_not, 0.0) / k) / mean_not

    everyone = np.ones(len(df), dtype=bool)
    for name, column in (("reachability", "reach_cum"), ("connected", "connected_cum")):
        fraction = _cum_at(df, column, td) / td
        mean, dev, _ = sums.mean(fraction, everyone)
        out[name], out[f"{name}_se"] = mean, np.sqrt(sums.covariance(dev, dev, n) / n)
    for name in ("depth", "farthest"):
        mean, dev, _ = sums.mean(_snapshot_at(df, name, td), everyone)
        out[name], out[f"{name}_se"] = mean, np.sqrt(sums.covariance(dev, dev, n) / n)
    if "t_detect_each" in df:  # several targets in some runs: how many were found and told
        for name, each, one in (("found", "t_detect_each", t_det),
                                ("told", "t_notify_each", t_not)):
            mean, dev, _ = sums.mean(_per_target_count(df[each], one, td), everyone)
            out[name], out[f"{name}_se"] = mean, np.sqrt(sums.covariance(dev, dev, n) / n)
    if "sorties" in df:  # teams on batteries in some runs: over each whole run, whatever td
        for name, unit in (("sorties", 1.0), ("energy", 3600.0)):
            values = _per_drone_mean(df[name]) / unit
            mean, dev, count = sums.mean(values, ~np.isnan(values))
            with np.errstate(divide="ignore", invalid="ignore"):
                out[name] = mean
                out[f"{name}_se"] = np.sqrt(sums.covariance(dev, dev, count) / count)
    return out


def _listed(each: pd.Series) -> Iterator[tuple[int, np.ndarray]]:
    """The rows of a list column that hold a list (a run without one holds None or NaN), as
    ``(row, values)``."""
    for k, values in enumerate(each.to_list()):
        if values is not None and not (np.isscalar(values) and pd.isna(values)):
            yield k, np.asarray(values, dtype=float)


def _per_drone_mean(each: pd.Series) -> np.ndarray:
    """The mean over the drones of a per-drone record (a list per run), NaN in a run without
    it (a team without batteries)."""
    out = np.full(len(each), np.nan)
    for k, values in _listed(each):
        out[k] = np.mean(values)
    return out


def _per_target_count(each: pd.Series, one: np.ndarray, td: np.ndarray) -> np.ndarray:
    """How many targets' times of ``each`` (a list per run; None in a run of one target,
    whose time is ``one``) are at most each run's ``td``."""
    out = (one <= td).astype(float)
    for k, times in _listed(each):
        out[k] = np.count_nonzero(times <= td[k])
    return out


def summarize(df: pd.DataFrame, td: float | Sequence[float] | None = None,
              by: Sequence[str] | None = None) -> pd.DataFrame:
    """The paper's measures per group of runs and target duration ``t_d``.

    Parameters
    ----------
    df
        Runs, as :func:`sarlink.load` returns them.
    td
        Target durations, s; default: each group's horizon.
    by
        Columns that define a group; default: the mission parameters that vary in ``df``.

    Returns
    -------
    One row per group and ``td``, groups in order of appearance: the group's keys, ``td``,
    ``runs``, ``detected``, ``notified`` (counts within ``td``), then

    - ``P_d``, ``P_s``: detection and mission success probabilities, ``Pr{t ≤ t_d}``;
    - ``immediate``: ``Pr{t_notify = t_detect | t_detect ≤ t_d}``;
    - ``mission_time``: mean ``t_notify`` of the runs notified within ``t_d``;
    - ``search_share``: their mean ``t_detect`` over their mean ``t_notify``;
    - ``reachability``: mean fraction of ``[0, t_d]`` in which the target had a route to the BS;
    - ``connected``: mean fraction of drones with a route to the BS over ``[0, t_d]``;
    - ``found``, ``told`` (only if some runs have several targets): the mean number of targets
        detected, and of those the BS was told of, within ``t_d``;
    - ``depth``, ``farthest``: the BS's network at ``t_d`` (the last checkpoint at or before
        it), averaged over the runs: the most hops from the BS to an airborne drone with a
        route, and the distance from the BS of the farthest such drone, m;
    - ``sorties``, ``energy`` (only if some runs' teams fly on batteries): a drone's sorties
        and the energy it drew, Wh, averaged over the drones and over those runs, each over
        its whole run (to the horizon, or to the event the run stopped at), whatever ``t_d``;

    with ``*_lo``/``*_hi`` (95% Wilson) beside probabilities and ``*_se`` beside means.
    """
    gid, keys = _groups(df, by)
    tds: list[float | None] = [None] if td is None else list(np.atleast_1d(td).astype(float))
    frames = []
    for t in tds:
        frame = pd.concat([keys, pd.DataFrame(_measures(df, gid, _td_per_run(df, gid, t)))],
                          axis=1)
        frame.insert(0, "_group", np.arange(len(keys)))
        frames.append(frame)
    out = pd.concat(frames, ignore_index=True).sort_values("_group", kind="stable")
    return out.drop(columns="_group").reset_index(drop=True)


def success_curve(df: pd.DataFrame, tds: Sequence[float] | np.ndarray,
                  by: Sequence[str] | None = None) -> pd.DataFrame:
    """Mission success ``P_s(t_d)`` over many ``t_d``, from the empirical CDF of ``t_notify``.

    One set of runs gives the whole curve; it never decreases in ``t_d``. Columns: the group's
    keys (``by`` as in :func:`summarize`), ``td``, ``runs``, ``P_s``, ``P_s_lo``, ``P_s_hi``.
    """
    gid, keys = _groups(df, by)
    tds = np.asarray(tds, dtype=float)
    if tds.ndim != 1 or not len(tds):
        raise ValueError("tds must be a non-empty list of durations")
    for t in (tds.min(), tds.max()):
        _td_per_run(df, gid, float(t))
    t_not = df["t_notify"].to_numpy(dtype=float)
    order = np.lexsort((t_not, gid))  # by group, then time; NaN (never notified) last
    n = np.bincount(gid)
    starts = np.concatenate([[0], np.cumsum(n)[:-1]])
    sorted_t = t_not[order]
    # runs notified by td: position of td among the group's sorted times
    k = np.stack([np.searchsorted(sorted_t[s:s + m], tds, side="right")
                  for s, m in zip(starts, n, strict=True)])
    lo, hi = wilson(k, n[:, None])
    curve = pd.DataFrame({
        "td": np.tile(tds, len(n)), "runs": np.repeat(n, len(tds)),
        "P_s": (k / n[:, None]).ravel(), "P_s_lo": lo.ravel(), "P_s_hi": hi.ravel(),
    })
    return pd.concat([keys.loc[keys.index.repeat(len(tds))].reset_index(drop=True), curve],
                     axis=1)


def run_values(df: pd.DataFrame, tds: Sequence[float], by: Sequence[str]) -> pd.DataFrame:
    """Every run's own values, for statistics that pair runs across grid points.

    Runs of one seed share their target by ``run`` (common random numbers), so a comparison of
    two grid points is sharper run by run than from two summaries. One row per run: the
    columns ``by``, ``run``, ``t_detect``, ``t_notify`` (NaN if it did not happen),
    ``immediate``, and for each ``td`` the fraction of ``[0, t_d]`` the target was reachable
    (``reach@<td>``), the mean fraction of drones connected (``connected@<td>``) and the BS's
    network at ``t_d`` (``depth@<td>``, ``farthest@<td>``), read as :func:`summarize` reads
    them. Runs without those records (stopped at an event) get NaN.
    """
    out = df[[*by, "run"]].reset_index(drop=True)
    for column in ("t_detect", "t_notify"):
        out[column] = df[column].to_numpy(dtype=float)
    out["immediate"] = df["immediate"].to_numpy(dtype=bool)
    horizon = df["horizon"].to_numpy(dtype=float)
    for td in tds:
        for name, column in (("reach", "reach_cum"), ("connected", "connected_cum")):
            if column in df and df[column].notna().all() and td <= horizon.min():
                values = _cum_at(df, column, np.full(len(df), float(td))) / td
            else:
                values = np.full(len(df), np.nan)
            out[f"{name}@{td:g}"] = values
        for name in ("depth", "farthest"):
            out[f"{name}@{td:g}"] = (_snapshot_at(df, name, np.full(len(df), float(td)))
                                     if td <= horizon.min() else np.full(len(df), np.nan))
    return out
