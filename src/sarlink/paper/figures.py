"""The paper's figures, drawn from summary tables, and the values each one plots.

Every function takes the summary tables of :mod:`sarlink.paper.experiments` (and optionally an
empty figure to draw into) and returns the figure, laid out like the paper's: one panel per
communication range where the paper splits them, Fig. 2 with a row per team size. Every
probability is drawn with its 95% Wilson interval as a band, every mean with a band of ± one
standard error. Every planner of the tables is drawn, in the registry's order (the paper's
legend order, then the others) with the colour, marker and label it is registered with, so a
new planner needs no edits here. :data:`FIGURES` lists them with their captions, the tables they
need and the table of values they plot, which the report prints beside each figure.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.ticker import PercentFormatter

from sarlink.metrics import MEASURES, Measure
from sarlink.paper.experiments import (
    BEYOND,
    DRONES,
    FIG2_DRONES,
    FIG5_RANGES,
    MOTIONS,
    MOVING_CURRENT,
    MOVING_DELAYS,
    MOVING_DRONES,
    MOVING_FIG,
    MOVING_RC,
    MOVING_TDS,
    MOVING_WIND,
    OTHERS,
    RANGE_DRONES,
    RANGE_FIG,
    RANGE_TDS,
    RANGES,
    RELAY_COUNTS,
    RELAY_FIG,
    RELAY_PLANNER,
    RELAY_TDS,
    SIGMA,
    TD_FIG3,
    TD_LONG,
    TD_SHORT,
    relay_label,
)
from sarlink.planners import PAPER_PLANNERS, get_planner, planner_names

__all__ = ["FIGURES", "RELAYING", "FigureSpec", "fig1", "fig2", "fig3", "fig4", "fig5", "fig6",
           "fig7", "fig8", "fig9", "fig10", "fig11", "fig12", "network_values", "save"]

_BAND = 0.15
"""Opacity of the interval bands: light enough for five to overlap legibly."""

P_S, P_D, IMMEDIATE, MISSION_TIME, SEARCH_SHARE, REACHABILITY, DEPTH, FARTHEST = (
    MEASURES[c] for c in ("P_s", "P_d", "immediate", "mission_time", "search_share",
                          "reachability", "depth", "farthest"))
RELAYING = ("conb", "mtsp-conb", "concov")
"""The planners whose drones keep links to pass the news on: ConB and the hybrids."""


def _band(measure: Measure, rows: pd.DataFrame) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Value, lower and upper edge of the band: the 95% interval or ± one standard error."""
    value = rows[measure.column].to_numpy(dtype=float)
    if measure.probability:
        return (value, rows[f"{measure.column}_lo"].to_numpy(dtype=float),
                rows[f"{measure.column}_hi"].to_numpy(dtype=float))
    se = rows[f"{measure.column}_se"].to_numpy(dtype=float)
    return value, value - se, value + se


def _axis(measure: Measure) -> str:
    """The axis label: name, the paper's symbol in TeX, unit."""
    symbol = f" ${measure.symbol}$" if measure.symbol else ""
    unit = (" (% of $t_d$)" if measure.share_of_td
            else f" ({measure.unit})" if measure.unit else "")
    return measure.label + symbol + unit


def _header(measure: Measure) -> str:
    """The column header of the plotted values."""
    symbol = f" {measure.symbol}" if measure.symbol else ""
    unit = (" (fraction of t_d)" if measure.share_of_td
            else f" ({measure.unit})" if measure.unit else "")
    return (measure.label + symbol + unit
            + (" [95% interval]" if measure.probability else " ± SE"))


_KEYS = {"rc": "r_c (m)", "drones": "N_m", "td": "t_d (s)", "p_miss": "p_miss",
         "planner": "planner", "on_detect": "on detection", "relays": "relays",
         "motion": "target", "delay": "delay (s)"}


def _label(planner: str) -> str:
    return get_planner(planner).label


def _legend_order(column: pd.Series) -> pd.Series:
    """A sort key that puts planners in the registry's order (the paper's legend order)."""
    if column.name != "planner":
        return column
    return column.map({p: i for i, p in enumerate(planner_names())})


def _planners(*tables: pd.DataFrame) -> list[str]:
    """The planners found in ``tables``, in the registry's order."""
    found = set().union(*(t["planner"].unique() for t in tables))
    return [p for p in planner_names() if p in found]


@contextmanager
def _style() -> Iterator[None]:
    with plt.rc_context({
        "font.size": 9, "axes.titlesize": 9, "axes.labelsize": 9, "legend.fontsize": 9,
        "xtick.labelsize": 8, "ytick.labelsize": 8, "axes.grid": True, "grid.alpha": 0.3,
        "lines.linewidth": 1.3, "lines.markersize": 4,
        "svg.hashsalt": "sarlink",  # the same SVG for the same data
    }):
        yield


def _axes(fig: Figure | None, rows: int, cols: int, *,
          sharey: bool | Literal["row"] = True) -> tuple[Figure, np.ndarray]:
    """A grid of panels in ``fig`` (a new figure sized for the grid if None)."""
    if fig is None:
        fig = plt.figure(figsize=(3.3 * cols + 0.4, 2.7 * rows + 0.5), layout="constrained")
    return fig, fig.subplots(rows, cols, squeeze=False, sharey=sharey)


def _legend(fig: Figure, planners: Sequence[str], faint: Sequence[str] = (),
            teams: Sequence[int] = ()) -> None:
    """One legend for the whole figure, planners in the registry's order; the ``faint`` ones
    (references drawn dashed, see :func:`_lines`) after them; before them all, the ``teams``
    of searchers and relays by their relay count (:func:`_relay_lines`)."""
    handles = [Line2D([], [], color=c, marker=m) for c, m in map(_relay_style, teams)]
    handles += [Line2D([], [], color=get_planner(p).colour, marker=get_planner(p).marker)
                for p in planners]
    handles += [Line2D([], [], color=get_planner(p).colour, ls="--", lw=0.9) for p in faint]
    labels = [relay_label(k) for k in teams] + [_label(p) for p in (*planners, *faint)]
    fig.legend(handles, labels, loc="outside upper center", ncols=min(len(labels), 5),
               frameon=False)


def _lines(ax: Axes, rows: pd.DataFrame, x: str, measure: Measure, planners: Sequence[str], *,
           dodge: float = 0.0, markevery: int = 1, faint: bool = False) -> None:
    """One line per planner of ``measure`` against column ``x``, with its band.

    Planners often coincide (all at P = 1; mTSP-ConB on mTSP up to N_r drones). So that none
    hides another, ``dodge`` shifts each planner's points sideways by that much per place in
    ``planners`` (the figure's legend), and with ``markevery`` > 1 each planner marks a
    different subset of points. ``faint`` lines are dashed, unmarked and without bands: a
    reference drawn beside the main lines.
    """
    middle = (len(planners) - 1) / 2
    for i, planner in enumerate(planners):
        sub = rows[rows["planner"] == planner].sort_values(x)
        if sub.empty:
            continue
        style = get_planner(planner)
        xs = sub[x].to_numpy(dtype=float) + dodge * (i - middle)
        value, lo, hi = _band(measure, sub)
        if faint:
            ax.plot(xs, value, color=style.colour, ls="--", lw=0.9, alpha=0.7)
            continue
        ax.plot(xs, value, color=style.colour, marker=style.marker,
                markevery=(i % markevery, markevery), label=style.label)
        ax.fill_between(xs, lo, hi, color=style.colour, alpha=_BAND, lw=0)
    if measure.probability or measure.share_of_td:
        ax.set_ylim(-0.02, 1.02)
    if measure.share_of_td:
        ax.yaxis.set_major_formatter(PercentFormatter(xmax=1.0, decimals=0))
    ax.set_ylabel(_axis(measure))


def _versus_drones(axes: Sequence[Axes], rows: pd.DataFrame, measure: Measure,
                   ranges: Sequence[float], planners: Sequence[str]) -> None:
    """The measure against N_m, one panel per communication range: Figs. 3–6 and 7b."""
    for ax, rc in zip(axes, ranges, strict=True):
        _lines(ax, rows[rows["rc"] == rc], "drones", measure, planners, dodge=0.2)
        ax.set_title(f"$r_c$ = {rc:g} m")
        ax.set_xlabel("number of drones $N_m$")
        ax.set_xticks(DRONES[::2])
    for ax in axes[1:]:
        ax.set_ylabel("")


def _at(table: pd.DataFrame, td: float) -> pd.DataFrame:
    return table[table["td"] == td]


@_style()
def fig1(plan_times: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Fig. 1: plan computation time against N_m at r_c = 500 m; the median of the repeats,
    the band spanning their minimum to maximum, a log time axis."""
    fig, axes = _axes(fig, 1, 1)
    ax = axes[0, 0]
    stats = _plan_time_stats(plan_times)
    planners = _planners(plan_times)
    for planner in planners:
        sub = stats[stats["planner"] == planner]
        style = get_planner(planner)
        ax.plot(sub["drones"], sub["median"], color=style.colour, marker=style.marker)
        ax.fill_between(sub["drones"], sub["min"], sub["max"], color=style.colour, alpha=_BAND,
                        lw=0)
    ax.set(yscale="log", xlabel="number of drones $N_m$", ylabel="plan computation time (CPU s)",
           title="$r_c$ = 500 m", xticks=DRONES[::2])
    _legend(fig, planners)
    return fig


def _plan_time_stats(plan_times: pd.DataFrame) -> pd.DataFrame:
    """Median, minimum and maximum seconds and the number of repeats per planner and N_m."""
    stats = (plan_times.groupby(["planner", "drones"], sort=False)["seconds"]
             .agg(["median", "min", "max", "count"]).reset_index())
    return stats.sort_values(["planner", "drones"], key=_legend_order)


@_style()
def fig2(curve: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Fig. 2: P_s against t_d from the empirical CDF of notification times; a row per team
    size (10, 22), a panel per r_c."""
    fig, axes = _axes(fig, len(FIG2_DRONES), len(RANGES))
    planners = _planners(curve)
    for row, n in zip(axes, FIG2_DRONES, strict=True):
        for ax, rc in zip(row, RANGES, strict=True):
            sub = curve[(curve["drones"] == n) & (curve["rc"] == rc)]
            _lines(ax, sub, "td", P_S, planners, markevery=5)
            ax.set_title(f"$N_m$ = {n}, $r_c$ = {rc:g} m")
            ax.set_xlabel("target duration $t_d$ (s)")
        for ax in row[1:]:
            ax.set_ylabel("")
    for ax in axes.flat:
        ax.set_xlim(0, TD_LONG)
        ax.set_xticks(np.arange(0, TD_LONG + 1, 1000))
    _legend(fig, planners)
    return fig


def _one_row(fig: Figure | None, main: pd.DataFrame, td: float, measure: Measure,
             ranges: Sequence[float]) -> Figure:
    """One measure at one ``td`` against N_m, a panel per communication range."""
    fig, axes = _axes(fig, 1, len(ranges))
    planners = _planners(main)
    _versus_drones(axes[0], _at(main, td), measure, ranges, planners)
    _legend(fig, planners)
    return fig


@_style()
def fig3(main: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Fig. 3: P_s against N_m at t_d = 2000 s, a panel per r_c."""
    return _one_row(fig, main, TD_FIG3, P_S, RANGES)


@_style()
def fig4(main: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Fig. 4: (a) mission time and (b) search share against N_m at t_d = 4000 s, a column per
    r_c."""
    fig, axes = _axes(fig, 2, len(RANGES), sharey="row")
    rows = _at(main, TD_LONG)
    planners = _planners(main)
    for panel, measure, tag in zip(axes, (MISSION_TIME, SEARCH_SHARE), "ab", strict=True):
        _versus_drones(panel, rows, measure, RANGES, planners)
        panel[0].set_ylabel(f"({tag}) {panel[0].get_ylabel()}")
    for ax in axes[1]:
        ax.set_ylim(0, 1.02)
    _legend(fig, planners)
    return fig


@_style()
def fig5(main: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Fig. 5: immediate notification against N_m at t_d = 4000 s, for r_c = 500 and 1000 m
    (the paper leaves out 2000 m, where every planner is near 1; the tables have it)."""
    return _one_row(fig, main, TD_LONG, IMMEDIATE, FIG5_RANGES)


@_style()
def fig6(main: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Fig. 6: target reachability (share of t_d with a multihop route from the target to the
    BS) against N_m at t_d = 4000 s, a panel per r_c."""
    return _one_row(fig, main, TD_LONG, REACHABILITY, RANGES)


@_style()
def fig7(miss: pd.DataFrame, shadowing: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Fig. 7: (a) P_d against the miss probability, N_m = 10, r_c = 500 m, t_d = 1000 s;
    (b) immediate notification against N_m with log-normal shadowing (σ = 3 dB),
    r_c = 1000 m, t_d = 4000 s."""
    fig, axes = _axes(fig, 1, 2, sharey=False)
    a, b = axes[0]
    planners = _planners(miss, shadowing)
    _lines(a, miss, "p_miss", P_D, planners, dodge=0.01)
    a.set(xlabel="miss probability $p_{miss}$",
          title=f"(a) imperfect sensing\n$N_m$ = 10, $r_c$ = 500 m, $t_d$ = {TD_SHORT:g} s")
    rc = float(shadowing["rc"].iloc[0])
    _versus_drones([b], _at(shadowing, TD_LONG), IMMEDIATE, [rc], planners)
    b.set_title(f"(b) log-normal shadowing, σ = {SIGMA:g} dB\n"
                f"$r_c$ = {rc:g} m, $t_d$ = {TD_LONG:g} s")
    _legend(fig, planners)
    return fig


@_style()
def fig8(curve: pd.DataFrame, main: pd.DataFrame, report_curve: pd.DataFrame,
         report: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Beyond the paper: the planners with drones that fly to tell the BS (solid, with bands)
    beside the paper's behaviour (dashed), for r_c = 500 and 1000 m: (a) P_s against t_d for
    N_m = 10 (as Fig. 2), (b) P_s against N_m at t_d = 2000 s (as Fig. 3), (c) mission time
    and (d) search share against N_m at t_d = 4000 s (as Fig. 4)."""
    ranges = FIG5_RANGES
    fig, axes = _axes(fig, 4, len(ranges), sharey="row")
    planners = _planners(report)
    for ax, rc in zip(axes[0], ranges, strict=True):
        for table, faint in ((curve, True), (report_curve, False)):
            sub = table[(table["drones"] == 10) & (table["rc"] == rc)]
            _lines(ax, sub, "td", P_S, planners, markevery=5, faint=faint)
        ax.set(title=f"$N_m$ = 10, $r_c$ = {rc:g} m", xlabel="target duration $t_d$ (s)",
               xlim=(0, TD_LONG), xticks=np.arange(0, TD_LONG + 1, 1000))
    for row, measure, td in ((axes[1], P_S, TD_FIG3), (axes[2], MISSION_TIME, TD_LONG),
                             (axes[3], SEARCH_SHARE, TD_LONG)):
        for ax, rc in zip(row, ranges, strict=True):
            for table, faint in ((main, True), (report, False)):
                sub = _at(table, td)
                _lines(ax, sub[sub["rc"] == rc], "drones", measure, planners, dodge=0.2,
                       faint=faint)
            ax.set(title=f"$r_c$ = {rc:g} m, $t_d$ = {td:g} s",
                   xlabel="number of drones $N_m$", xticks=DRONES[::2])
    for tag, row in zip("abcd", axes, strict=True):
        row[0].set_ylabel(f"({tag}) {row[0].get_ylabel()}")
        for ax in row[1:]:
            ax.set_ylabel("")
    _legend(fig, planners)
    return fig


_MODES = (("continue", "the paper's drones"), ("report", "drones that report"))


@_style()
def fig9(main: pd.DataFrame, report: pd.DataFrame, others: pd.DataFrame,
         fig: Figure | None = None) -> Figure:
    """Beyond the paper: the other planners (the IAMSAR search patterns; solid, with bands)
    beside the paper's planners (dashed): P_s against N_m at t_d = 2000 s, a column per r_c,
    (a) as in the paper and (b) with drones that report, each against the paper's planners
    flown the same way."""
    fig, axes = _axes(fig, len(_MODES), len(RANGES))
    planners, paper = _planners(others), _planners(main, report)
    for row, (mode, about), table, tag in zip(axes, _MODES, (main, report), "ab", strict=True):
        mine = _at(others[others["on_detect"] == mode], TD_FIG3)
        for ax, rc in zip(row, RANGES, strict=True):
            theirs = _at(table, TD_FIG3)
            _lines(ax, theirs[theirs["rc"] == rc], "drones", P_S, paper, dodge=0.2, faint=True)
            _lines(ax, mine[mine["rc"] == rc], "drones", P_S, planners, dodge=0.2)
            ax.set(title=f"({tag}) {about}, $r_c$ = {rc:g} m", xlabel="number of drones $N_m$",
                   xticks=DRONES[::2])
        for ax in row[1:]:
            ax.set_ylabel("")
    _legend(fig, planners, paper)
    return fig


@_style()
def fig10(range_curve: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Beyond the paper: how much range a team needs. P_s(t_d) against a continuous r_c for
    the planners that fly the same at every range, a row per t_d and a column per team size,
    the paper's three ranges marked."""
    fig, axes = _axes(fig, len(RANGE_TDS), len(RANGE_DRONES))
    planners = _planners(range_curve)
    for row, td in zip(axes, RANGE_TDS, strict=True):
        for ax, drones in zip(row, RANGE_DRONES, strict=True):
            rows = range_curve[(range_curve["td"] == td) & (range_curve["drones"] == drones)]
            _lines(ax, rows, "rc", P_S, planners, markevery=12)
            for rc in RANGES:
                ax.axvline(rc, color="0.6", lw=0.8, ls=":")
            ax.set(title=f"$N_m$ = {drones}, $t_d$ = {td:g} s",
                   xlabel="communication range $r_c$ (m)")
        for ax in row[1:]:
            ax.set_ylabel("")
    _legend(fig, planners)
    return fig


RELAY_STYLES = (("#8c8c8c", "v"), ("#4d4d4d", "D"), ("#000000", "X"))
"""Colour and marker of the teams of searchers and relays, by relay count in increasing
order (darker with more relays): greys, which no registered planner wears."""


def _relay_style(relays: int) -> tuple[str, str]:
    """The colour and marker of a team with ``relays`` relays: the count's place among the
    experiment's counts picks the style (the first one for a count it does not fly)."""
    place = RELAY_COUNTS.index(relays) if relays in RELAY_COUNTS else 0
    return RELAY_STYLES[place % len(RELAY_STYLES)]


def _relay_lines(ax: Axes, rows: pd.DataFrame, counts: Sequence[int]) -> None:
    """P_s against N_m of the searchers and relays, one line per relay count with its
    band, shifted sideways like :func:`_lines`' planners."""
    middle = (len(counts) - 1) / 2
    for i, k in enumerate(counts):
        sub = rows[rows["relays"] == k].sort_values("drones")
        colour, marker = _relay_style(k)
        xs = sub["drones"].to_numpy(dtype=float) + 0.2 * (i - middle)
        value, lo, hi = _band(P_S, sub)
        ax.plot(xs, value, color=colour, marker=marker, label=relay_label(k))
        ax.fill_between(xs, lo, hi, color=colour, alpha=_BAND, lw=0)


@_style()
def fig11(main: pd.DataFrame, relays: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Beyond the paper: searchers and relays (solid, with bands, one line per relay count)
    against the paper's planners (dashed) at equal team size: P_s against N_m, a row per
    t_d (1000 and 2000 s) and a column per r_c."""
    fig, axes = _axes(fig, len(RELAY_TDS), len(RANGES))
    counts = sorted(int(k) for k in relays["relays"].unique())
    paper = [p for p in _planners(main) if p in PAPER_PLANNERS]
    theirs = main[main["drones"].isin(relays["drones"].unique())]
    for row, td in zip(axes, RELAY_TDS, strict=True):
        for ax, rc in zip(row, RANGES, strict=True):
            ours = _at(relays, td)
            others = _at(theirs, td)
            _lines(ax, others[others["rc"] == rc], "drones", P_S, paper, faint=True)
            _relay_lines(ax, ours[ours["rc"] == rc], counts)
            ax.set(title=f"$r_c$ = {rc:g} m, $t_d$ = {td:g} s",
                   xlabel="number of drones $N_m$ (searchers + relays)", xticks=DRONES[::2])
        for ax in row[1:]:
            ax.set_ylabel("")
    _legend(fig, [], paper, counts)
    return fig


MOTION_TITLES = {"still": "a still target (the paper's)", "walk": "a walking target",
                 "drift": "a drifting target"}
"""How Fig. :data:`MOVING_FIG` titles its panels, by target motion."""


@_style()
def fig12(moving_curve: pd.DataFrame, fig: Figure | None = None) -> Figure:
    """Beyond the paper: P_s against t_d of the paper's planners and the IAMSAR patterns for
    a still, a walking and a drifting target (a column each), N_m = 10, r_c = 500 m, a row per
    delay from the last sighting to take-off."""
    delays = [d for d in MOVING_DELAYS if d in set(moving_curve["delay"])]
    fig, axes = _axes(fig, len(delays), len(MOTIONS))
    planners = _planners(moving_curve)
    for row, delay in zip(axes, delays, strict=True):
        for ax, motion in zip(row, MOTIONS, strict=True):
            rows = moving_curve[(moving_curve["motion"] == motion)
                                & (moving_curve["delay"] == delay)]
            _lines(ax, rows, "td", P_S, planners, markevery=5)
            ax.set(title=f"{MOTION_TITLES[motion]}, delay {delay:g} s",
                   xlabel="target duration $t_d$ (s)", xlim=(0, TD_LONG),
                   xticks=np.arange(0, TD_LONG + 1, 1000))
        for ax in row[1:]:
            ax.set_ylabel("")
    _legend(fig, planners)
    return fig


def save(fig: Figure, folder: Path, name: str) -> list[Path]:
    """Write ``name.png`` (200 dpi) and ``name.svg`` into ``folder`` and close the figure."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = [folder / f"{name}.png", folder / f"{name}.svg"]
    fig.savefig(paths[0], dpi=200, metadata={"Software": None})
    fig.savefig(paths[1], metadata={"Date": None})
    plt.close(fig)
    return paths


# -- the plotted values, as text tables ---------------------------------------------------------


def _values(rows: pd.DataFrame, keys: Sequence[str], measures: Sequence[Measure]
            ) -> pd.DataFrame:
    """The plotted rows as text: the keys, then each measure with its interval."""
    rows = rows.sort_values(keys, key=_legend_order)
    out = pd.DataFrame({_KEYS[k]: rows[k].map(_label if k == "planner" else str
                                              if k in ("on_detect", "motion") else "{:g}".format)
                        for k in keys})
    for measure in measures:
        out[_header(measure)] = [measure.text(r) for _, r in rows.iterrows()]
    return out.reset_index(drop=True)


_VERSUS_KEYS = ["rc", "planner", "drones"]


def _count(value: float) -> str:
    """A work count as printed: ``–`` for none (a planner without that part)."""
    return f"{value:,.0f}" if value > 0 else "–"


def _fig1_values(plan_times: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    stats = _plan_time_stats(plan_times)
    # the counts are the same in every repeat (the same plan and run): their median
    counts = (plan_times.groupby(["planner", "drones"], sort=False)[["expansions", "evaluations"]]
              .median().reindex(pd.MultiIndex.from_frame(stats[["planner", "drones"]])))
    return [("", pd.DataFrame({
        "planner": stats["planner"].map(_label), "N_m": stats["drones"],
        "median (s)": stats["median"].map("{:.4g}".format),
        "min (s)": stats["min"].map("{:.4g}".format),
        "max (s)": stats["max"].map("{:.4g}".format), "repeats": stats["count"],
        "search expansions": [_count(v) for v in counts["expansions"]],
        "GA evaluations": [_count(v) for v in counts["evaluations"]],
    }).reset_index(drop=True))]


def network_values(main: pd.DataFrame, drones: Sequence[int]) -> pd.DataFrame:
    """The BS's network of the relaying planners (:data:`RELAYING`) with ``drones`` drones at
    every t_d of the main table, as text: the mean depth in hops and the mean distance of the
    farthest connected drone, the numbers by which a reader judges whether chains form."""
    rows = main[main["planner"].isin(RELAYING) & main["drones"].isin(drones)]
    return _values(rows, ["rc", "planner", "drones", "td"], [DEPTH, FARTHEST])


def _fig2_values(curve: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    rows = curve[curve["drones"].isin(FIG2_DRONES)]
    return [("", _values(rows, ["drones", "rc", "planner", "td"], [P_S]))]


def _main_values(td: float, measures: Sequence[Measure], ranges: Sequence[float] = RANGES
                 ) -> Callable[[pd.DataFrame], list[tuple[str, pd.DataFrame]]]:
    def values(main: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
        rows = _at(main, td)
        return [("", _values(rows[rows["rc"].isin(ranges)], _VERSUS_KEYS, measures))]
    return values


def _fig7_values(miss: pd.DataFrame, shadowing: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    return [("(a) imperfect sensing", _values(miss, ["planner", "p_miss"], [P_D])),
            ("(b) shadowing", _values(_at(shadowing, TD_LONG), _VERSUS_KEYS, [IMMEDIATE]))]


def _fig8_values(curve: pd.DataFrame, main: pd.DataFrame, report_curve: pd.DataFrame,
                 report: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    both = pd.concat([main.assign(on_detect="continue"), report.assign(on_detect="report")])
    rows = both[both["rc"].isin(FIG5_RANGES) & both["td"].isin([TD_SHORT, TD_FIG3])]
    return [("P_s with and without reporting", _values(
        rows, ["rc", "td", "planner", "drones", "on_detect"], [P_S]))]


def _fig9_values(main: pd.DataFrame, report: pd.DataFrame, others: pd.DataFrame
                 ) -> list[tuple[str, pd.DataFrame]]:
    paper = pd.concat([main.assign(on_detect="continue"), report.assign(on_detect="report")])
    rows = pd.concat([paper, others])
    rows = rows[rows["td"].isin([TD_SHORT, TD_FIG3])]
    return [("P_s of every planner, with and without reporting", _values(
        rows, ["on_detect", "rc", "td", "planner", "drones"], [P_S]))]


def _fig10_values(range_curve: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    rows = range_curve[range_curve["rc"] % 250.0 == 0.0]
    return [("every 250 m", _values(rows, ["td", "drones", "planner", "rc"], [P_S]))]


def _fig11_values(main: pd.DataFrame, relays: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    paper = main[main["planner"].isin(PAPER_PLANNERS) & main["drones"].isin(relays["drones"])]
    rows = pd.concat([paper.assign(relays=0), relays])
    rows = rows[rows["td"].isin(RELAY_TDS)]
    return [("P_s with and without relays", _values(
        rows, ["rc", "td", "drones", "relays", "planner"], [P_S]))]


def _fig12_values(moving_curve: pd.DataFrame) -> list[tuple[str, pd.DataFrame]]:
    rows = moving_curve[moving_curve["td"].isin(MOVING_TDS)]
    return [("P_s by target motion", _values(
        rows, ["delay", "td", "motion", "planner"], [P_S]))]


@dataclass(frozen=True)
class FigureSpec:
    """A paper figure: what it shows, the summary tables it needs, how to draw it and the
    values it plots (titled tables, one per panel group)."""

    number: int
    caption: str
    tables: tuple[str, ...]
    draw: Callable[..., Figure]
    values: Callable[..., list[tuple[str, pd.DataFrame]]]


FIGURES = {f.number: f for f in (
    FigureSpec(1, "Plan computation time against the number of drones, r_c = 500 m "
               "(median of the repeats; band: their range). Its values list the work counted "
               "beside the time, which does not depend on the machine: the nodes the "
               "connectivity checks' searches expanded over the whole plan, and the GA's "
               "evaluations.", ("plan_times",), fig1, _fig1_values),
    FigureSpec(2, "Probability that the target information reaches the BS within t_d against "
               "t_d, for N_m = 10 and 22.", ("curve",), fig2, _fig2_values),
    FigureSpec(3, f"Probability that the target information reaches the BS within t_d against "
               f"the number of drones, t_d = {TD_FIG3:g} s.", ("main",), fig3,
               _main_values(TD_FIG3, [P_S])),
    FigureSpec(4, f"Mission time (a) and the share of it spent searching (b) against the number "
               f"of drones, t_d = {TD_LONG:g} s (bands: ± one standard error).", ("main",), fig4,
               _main_values(TD_LONG, [MISSION_TIME, SEARCH_SHARE])),
    FigureSpec(5, f"Probability of immediate notification (detection and BS notification at "
               f"once) against the number of drones, t_d = {TD_LONG:g} s.", ("main",), fig5,
               _main_values(TD_LONG, [IMMEDIATE], FIG5_RANGES)),
    FigureSpec(6, f"Share of t_d during which the target has a multihop route to the BS "
               f"against the number of drones, t_d = {TD_LONG:g} s (bands: ± one standard "
               f"error).", ("main",), fig6, _main_values(TD_LONG, [REACHABILITY])),
    FigureSpec(7, f"(a) Detection probability against the miss probability, N_m = 10, "
               f"r_c = 500 m, t_d = {TD_SHORT:g} s; (b) immediate notification against the "
               f"number of drones under log-normal shadowing (σ = {SIGMA:g} dB), r_c = 1000 m, "
               f"t_d = {TD_LONG:g} s.", ("miss", "shadowing"), fig7, _fig7_values),
    FigureSpec(BEYOND, "Beyond the paper: drones that fly to tell the BS once they know where "
               "the target is (on_detect = report; solid, with 95% bands) beside the paper's "
               "behaviour (dashed): (a) P_s against t_d, N_m = 10; (b) P_s against N_m, "
               f"t_d = {TD_FIG3:g} s; (c) mission time and (d) search share against N_m, "
               f"t_d = {TD_LONG:g} s.", ("curve", "main", "report_curve", "report"), fig8,
               _fig8_values),
    FigureSpec(OTHERS, "Beyond the paper: the other planners, the IAMSAR search patterns "
               "(solid, with 95% bands), beside the paper's planners (dashed): P_s against the "
               f"number of drones, t_d = {TD_FIG3:g} s, (a) as in the paper and (b) with drones "
               "that fly to tell the BS (on_detect = report), each against the paper's "
               "planners flown the same way.", ("main", "report", "others"), fig9,
               _fig9_values),
    FigureSpec(RANGE_FIG, "Beyond the paper: how much range a team needs. P_s(t_d) against a "
               "continuous communication range, 100-3000 m, for the planners whose drones fly "
               "the same at every range (mTSP, CovB; mTSP-ConB where all its drones fly the "
               "plan), evaluated from the runs of Figs. 2-6 (one flight per run, its notification "
               "staircase); dotted: the paper's three ranges.", ("range_curve",), fig10,
               _fig10_values),
    FigureSpec(RELAY_FIG, "Beyond the paper: searchers and relays against the paper's planners "
               "at equal team size. P_s against the number of drones N_m, searchers and relays "
               f"together: {get_planner(RELAY_PLANNER).label} searchers with "
               f"{', '.join(map(str, RELAY_COUNTS[:-1]))} or {RELAY_COUNTS[-1]} of the team's "
               "drones as relays that keep them linked to the BS, one line per relay count "
               "(solid, with 95% bands), beside the paper's five planners with every drone "
               "searching (dashed), on the same runs (run k of every line searches for the "
               f"same target); t_d = {RELAY_TDS[0]:g} and {RELAY_TDS[1]:g} s.",
               ("main", "relays"), fig11, _fig11_values),
    FigureSpec(MOVING_FIG, "Beyond the paper: targets that move. P_s against t_d of the "
               "paper's planners and the IAMSAR search patterns (solid, with 95% bands) for a "
               "still target (the paper's), a walking one (0.5 m/s, a correlated random "
               "heading, stopping after a log-normal time of median 4 h) and a person in the "
               "water drifting under a constant wind of "
               f"({MOVING_WIND[0]:g}, {MOVING_WIND[1]:g}) m/s and current of "
               f"({MOVING_CURRENT[0]:g}, {MOVING_CURRENT[1]:g}) m/s (east, north; Leeway "
               f"PIW-1; a drifter that leaves the square is not found), N_m = {MOVING_DRONES}, "
               f"r_c = {MOVING_RC:g} m, the same runs (run k of every panel starts from the same "
               "last-seen point); a row per delay from the last sighting to take-off "
               f"({', '.join(f'{d:g}' for d in MOVING_DELAYS)} s; a still target ignores it, so "
               "its panels agree). Its values: P_s at t_d = "
               f"{', '.join(f'{td:g}' for td in MOVING_TDS)} s.", ("moving_curve",), fig12,
               _fig12_values),
)}
"""Every figure by its number in the paper, and :data:`BEYOND`, :data:`OTHERS`,
:data:`RANGE_FIG`, :data:`RELAY_FIG` and :data:`MOVING_FIG` after them."""
