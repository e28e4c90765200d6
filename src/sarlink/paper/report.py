"""The reproduction report, as Markdown and as one self-contained HTML file.

Both are rendered from one list of blocks (headings, paragraphs, lists, tables, figures), so
they say the same thing; Markdown links the PNG files beside it, HTML embeds them (base64), so
``report.html`` can be mailed on its own. Tables are rendered here in a few lines, without a
dependency.
"""

from __future__ import annotations

import base64
import html
import os
import platform
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from importlib.metadata import version
from pathlib import Path

import pandas as pd

from sarlink.config import DEFAULT_READING, READINGS, Mission, Reading, get_reading
from sarlink.paper.beyond import beyond_text, others_text
from sarlink.paper.causes import Contradiction, contradictions, first_line
from sarlink.paper.evidence import Outcome
from sarlink.paper.experiments import (
    BEYOND,
    CURVE_TDS,
    DRONES,
    MOVING_CURRENT,
    MOVING_DELAYS,
    MOVING_DRONES,
    MOVING_FIG,
    MOVING_RC,
    MOVING_WIND,
    OTHERS,
    P_MISS,
    RANGES,
    RELAY_COUNTS,
    RELAY_DRONES,
    RELAY_FIG,
    RELAY_PLANNER,
    RELAY_TDS,
    SEED,
    SIGMA,
    TD_FIG3,
    TD_LONG,
    TD_SHORT,
)
from sarlink.paper.figures import FIGURES, RELAYING, network_values
from sarlink.paper.findings import CLAIMS, Finding, tally
from sarlink.paper.moving import best_text, moving_points, moving_table, moving_text
from sarlink.paper.relays import relay_points, relays_summary, relays_table, relays_text
from sarlink.planners import PAPER_PLANNERS, get_planner

__all__ = ["ReplayLink", "Stage", "machine", "write_report"]


@dataclass(frozen=True)
class Stage:
    """A timed part of the reproduction."""

    name: str
    detail: str
    seconds: float


@dataclass(frozen=True)
class ReplayLink:
    """A replay page beside the report, and what it shows."""

    page: Path
    about: str


@dataclass(frozen=True)
class _Heading:
    text: str
    level: int
    css: str | None = None
    """HTML class: how a claim came out."""


@dataclass(frozen=True)
class _Para:
    text: str


@dataclass(frozen=True)
class _List:
    items: list[str]


@dataclass(frozen=True)
class _Table:
    frame: pd.DataFrame
    collapsed: str | None = None
    """Summary line of a collapsible table, or None to show it open."""


@dataclass(frozen=True)
class _Image:
    png: Path
    caption: str


@dataclass(frozen=True)
class _Link:
    text: str
    href: str


_Block = _Heading | _Para | _List | _Table | _Image | _Link


def machine() -> dict[str, str]:
    """The CPU model, cores, Python and platform: what the timings were measured on."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as fh:
            cpu = next((line.split(":", 1)[1].strip() for line in fh
                        if line.startswith("model name")), cpu)
    except OSError:
        pass
    return {"CPU": cpu, "cores": str(os.cpu_count()), "Python": platform.python_version(),
            "platform": platform.platform(), "sarlink": version("sarlink"),
            "numba": version("numba"), "numpy": version("numpy")}


def _duration(seconds: float) -> str:
    minutes, rest = divmod(seconds, 60)
    return f"{int(minutes)} min {rest:.0f} s" if minutes else f"{rest:.1f} s"


def _pairs(rows: Sequence[tuple[str, str]], header: tuple[str, str]) -> pd.DataFrame:
    return pd.DataFrame(list(rows), columns=list(header))


def _setting(runs: int, quick: bool, reading: Reading) -> list[_Block]:
    m = Mission.build(reading=reading.name)
    labels = ", ".join(get_planner(p).label for p in PAPER_PLANNERS)
    rows = [
        ("area a × a", f"{m.area.size:g} m × {m.area.size:g} m, BS at the centre"),
        ("drone speed V_m", f"{m.team.speed:g} m/s"),
        ("sensing range r", f"{m.sensing.r:g} m"),
        ("time step, sensing period t_s", f"{m.timing.dt:g} s, {m.timing.ts:g} s"),
        ("flight budget T_max", f"{m.team.flight_time:g} s"),
        ("communication range r_c", ", ".join(f"{rc:g}" for rc in RANGES) + " m"),
        ("team sizes N_m", f"{DRONES[0]} to {DRONES[-1]} in steps of {DRONES[1] - DRONES[0]}"),
        ("planners", labels),
        ("ConCov weight α; mTSP-ConB's mTSP drones N_r", f"{m.team.alpha:g}; {m.team.nr}"),
        ("mTSP GA", f"population {m.mtsp.population}, {m.mtsp.iterations} iterations, "
                    f"total distance"),
        ("target durations t_d", f"Fig. 2: {CURVE_TDS[0]:g} to {CURVE_TDS[-1]:g} s; Fig. 3: "
                                 f"{TD_FIG3:g} s; Figs. 4–6, 7b: {TD_LONG:g} s; "
                                 f"Fig. 7a: {TD_SHORT:g} s"),
        ("reading of what the paper leaves open", f"{reading.name}: {reading.about}"),
        *((f"reading: {name}", value) for name, value in reading.choices.items()),
        ("Fig. 7a miss probabilities (one look per pass)", ", ".join(f"{p:g}" for p in P_MISS)),
        ("Fig. 7b shadowing", f"σ = {SIGMA:g} dB, n = {m.channel.pathloss_exponent:g}"),
        ("runs per grid point", f"{runs}" + (" (quick; the paper's is 2000)" if quick else "")),
        ("seed", f"{SEED} (common random numbers: run k of every point has the same target)"),
        ("sarlink", version("sarlink")),
    ]
    return [_Heading("Setting", 2), _Table(_pairs(rows, ("parameter", "value")))]


def _timing(seconds: float, stages: Sequence[Stage], workers: str) -> list[_Block]:
    rows = [(s.name, s.detail, _duration(s.seconds)) for s in stages]
    about = [(k, v) for k, v in machine().items()] + [("workers", workers)]
    return [
        _Heading("Time and machine", 2),
        _Para(f"This reproduction took {_duration(seconds)} of wall time (simulation, plan "
              "timing, tables and figures). Stored runs of an earlier call in the same output "
              "folder are reused, not redone, so a resumed call takes less."),
        _Table(pd.DataFrame(rows, columns=["stage", "what", "wall time"])),
        _Table(_pairs(about, ("machine", ""))),
    ]


@dataclass(frozen=True)
class Sensitivity:
    """What each claim depends on: outcomes under single changes of the reading."""

    matrix: pd.DataFrame
    """Claim × change (columns ``figure``, ``claim``, ``default``, then one per change)."""
    flips: list[str]
    """Each claim a single change flips, with the number that decides it."""
    findings: Mapping[str, Sequence[Finding]] = field(default_factory=dict)
    """The claims decided under each single change, by its name (for the tally by cause)."""


def _sensitivity(study: Sensitivity | None) -> list[_Block]:
    if study is None:
        return []
    changes = [c for c in study.matrix.columns if c not in ("figure", "claim", "default")]
    return [
        _Heading("What each finding depends on", 2),
        _Para(f"Every claim decided again under each single change of the reading "
              f"({len(changes)} changes: {', '.join(changes)}), on runs of their own for the "
              "planners a change reaches (the others' runs are shared). Flipped outcomes "
              f"({len(study.flips)}), with the number that decides each:"),
        _List(study.flips or ["none: no single change flips a claim"]),
        _Table(study.matrix, "The whole matrix: claim × change"),
    ]


_CSS_CLASS = {Outcome.HOLDS: "holds", Outcome.CONTRADICTED: "fails",
              Outcome.UNDECIDED: "undecided", Outcome.NOT_TESTABLE: "untestable"}


def _presets(findings: Sequence[Finding], reading: Reading,
             presets: dict[str, list[Finding]] | None) -> list[_Block]:
    """The tally under every preset reading: its range, not one chosen number."""
    by_name = presets or {reading.name: list(findings)}
    if list(by_name) == [reading.name]:
        return [_Para("The claims were tallied under this reading only: the tally under every "
                      "other preset reading reruns the experiments with its choices "
                      "(`sarlink reproduce --presets`; done by default without `--quick`).")]
    rows = [(name + (" (this report)" if name == reading.name else ""),
             READINGS[name].about if name in READINGS else "", tally(found))
            for name, found in by_name.items()]
    return [_Para(f"The tally under every preset reading ({len(rows)}; each runs every "
                  "experiment with its own choices; docs/model.md, Readings):"),
            _Table(pd.DataFrame(rows, columns=["reading", "what it follows", "claims"]))]


def _other_readings(reading: Reading, presets: Mapping[str, Sequence[Finding]] | None,
                    sensitivity: Sensitivity | None) -> dict[str, Sequence[Finding]]:
    """The claims under every other reading decided: the other presets, the single changes."""
    out = {name: found for name, found in (presets or {}).items()
           if name != reading.name and found}
    return out | dict(sensitivity.findings if sensitivity else {})


def _causes(found: Sequence[Contradiction]) -> list[_Block]:
    """The first table: each contradicted claim and why."""
    if not found:
        return []
    rows = [(c.finding.figure, c.finding.claim, c.cause.value, c.why) for c in found]
    return [_Para("Each contradicted claim by cause: it hinges on one reading when it holds "
                  "under another preset or a single change of this one (named); it is decided "
                  "by a level the paper does not state when at the most lenient value a "
                  "reader could defend of each threshold its criterion chose no part is "
                  "contradicted; otherwise it is a model-level disagreement, whose mechanism is "
                  "written beside the claim (docs/reproduce.md, The tally by cause)."),
            _Table(pd.DataFrame(rows, columns=["about", "claim", "cause",
                                               "which reading, which level, or the mechanism"]))]


def _claims(findings: Sequence[Finding], tables: dict[str, pd.DataFrame],
            reading: Reading, presets: dict[str, list[Finding]] | None = None,
            found: Sequence[Contradiction] = ()) -> list[_Block]:
    """The paper's claims grouped by figure, each with its sentence, outcome, criterion and
    numbers, after the contradicted ones by cause."""
    unchecked = [c for c in CLAIMS if not c.checkable(tables)]
    blocks: list[_Block] = [_Heading("The paper's claims", 2)]
    if not findings:
        return [*blocks, _Para("The claims are checked on the runs of the figures they are "
                               "about, none of which this reproduction included.")]
    blocks += [
        *_causes(found),
        _Para(f"{len(findings)} of the paper's claims checked: {tally(findings)}."
              + (f" Not checked, for want of the runs of their figures: "
                 f"{len(unchecked)} ({', '.join(sorted({c.figure for c in unchecked}))})."
                 if unchecked else "")),
        *_presets(findings, reading, presets),
        _Para("Each claim quotes the paper's sentence and is decided from the runs by the "
              "criterion quoted with it. All intervals are 95%. Comparisons are paired: run k "
              "of every grid point searches for the same target, so a difference is judged "
              "run by run (McNemar's exact test on the discordant runs for two success "
              "indicators, Student's t on per-run pseudo-values otherwise); a measure over the "
              "runs notified (mission time, its phases, the delay) is compared over the runs "
              "both notify, the same targets; a level has its "
              "Wilson interval; plan times have Welch and least-squares t intervals. A part "
              "holds where its interval supports it, is contradicted where the interval "
              "excludes it, is undecided at this sample size otherwise (more runs can settle "
              "it), and is not testable at this setting where the two compared are equal in "
              "every run (both always succeed, say). A claim is contradicted if a part is, "
              "undecided if a part is, holds if a part holds and none is contradicted or "
              "undecided; parts not testable decide nothing. Where the sentence names no team "
              "size, a comparison is decided on its average over N_m and shows the picture "
              "per N_m beside it (+ holds, − contradicted, ? undecided, = not testable). "
              f"Fig. 3's t_d, which the paper does not state, is taken as "
              f"{reading.td_fig3:g} s (reading {reading.name!r})."),
        _Table(pd.DataFrame([(f.figure, f.claim, f.outcome.value) for f in findings],
                            columns=["about", "claim", "outcome"])),
    ]
    for figure in dict.fromkeys(f.figure for f in findings):
        blocks.append(_Heading(figure, 3))
        for f in (f for f in findings if f.figure == figure):
            blocks += [
                _Heading(f"{f.claim} — {f.outcome.value}", 4, _CSS_CLASS[f.outcome]),
                _Para(f"The paper, {f.section}: “{f.sentence}”"),
                _Para("Criterion: " + f.criterion),
                _List([f"{p.text} — {p.outcome.value}"
                       + (f" (at the lenient level: {p.lenient.value})"
                          if p.lenient is not None and p.lenient is not p.outcome else "")
                       for p in f.parts]),
            ]
            if f.notes:
                blocks += [_Para("For context:"), _List(list(f.notes))]
    return blocks


def _figures(out: Path, figures: dict[int, Path], tables: dict[str, pd.DataFrame]
             ) -> list[_Block]:
    blocks: list[_Block] = [_Heading("Figures", 2), _Para(
        "Bands: 95% Wilson intervals around probabilities, ± one standard error around means. "
        f"Up to N_r = {Mission().team.nr} drones mTSP-ConB flies the mTSP plan with all of its "
        "drones, so there its line lies on mTSP's. So that coinciding lines stay visible, each "
        "planner's points are shifted slightly sideways against N_m and p_miss, and in Fig. 2 "
        "each planner marks different t_d.")]
    for number, png in sorted(figures.items()):
        spec = FIGURES[number]
        blocks += [_Heading(f"Figure {number}", 3),
                   _Image(png.relative_to(out), f"Figure {number}. {spec.caption}")]
        for title, frame in spec.values(*(tables[t] for t in spec.tables)):
            name = f"Figure {number}{' ' + title if title else ''}"
            blocks.append(_Table(frame, f"{name}: the {len(frame)} plotted values"))
    blocks.append(_Para("The summary tables behind every figure, with all measures, are in "
                        "tables/ (CSV and Parquet); the runs themselves in runs/."))
    return blocks


NETWORK_DRONES = (6, 10, 22)
"""The team sizes of the report's open table of the BS's network (the others are folded)."""


def _network(tables: dict[str, pd.DataFrame]) -> list[_Block]:
    """Whether the relaying planners form chains: the BS's network at each t_d."""
    if "main" not in tables:
        return []
    labels = ", ".join(get_planner(p).label for p in RELAYING)
    main = tables["main"]
    return [_Heading("The BS's network: do chains form?", 2), _Para(
        f"The paper's case for {labels} is multihop connectivity: drones that pass the news to "
        "the BS through each other. At each t_d, over the runs of Figs. 2–6: the depth of the "
        "BS's connected component (the most hops from the BS to an airborne drone with a "
        "route; drones parked at the BS are part of it) and the distance from the BS of the "
        "farthest airborne drone with a route. A team that never relays is a single-hop star: "
        "depth at most 1, its farthest connected drone within r_c. Up to N_r = "
        f"{Mission().team.nr} drones mTSP-ConB flies mTSP's plan, whose flights are scanned at "
        "every range without a graph of their own (–)."),
        _Table(network_values(main, NETWORK_DRONES)),
        _Table(network_values(main, DRONES), "Every team size")]


def _beyond(tables: dict[str, pd.DataFrame]) -> list[_Block]:
    if "report" not in tables or "main" not in tables:
        return []
    return [_Heading("Beyond the paper: drones that go and tell", 2), _Para(
        "The paper's drones do not react to the target: a detection reaches the BS only over a "
        "multihop path that happens to exist, or when the drone flies home. With on_detect = "
        "report (docs/model.md) a drone that learns where the target is flies straight to the "
        f"BS until it is notified, then resumes its plan. Figure {BEYOND} compares it with the "
        "paper's behaviour on the same runs (common random numbers); P_s differences carry "
        "Newcombe's 95% interval, over N_m = 2-22, r_c = 500, 1000, 2000 m and t_d = 1000 and "
        "2000 s."), _List(beyond_text(tables["main"], tables["report"]))]


def _others(tables: dict[str, pd.DataFrame]) -> list[_Block]:
    if not {"main", "report", "others"} <= set(tables):
        return []
    others = tables["others"]
    labels = ", ".join(get_planner(p).label for p in dict.fromkeys(others["planner"]))
    return [_Heading("Beyond the paper: the search patterns SAR teams fly", 2), _Para(
        "A SAR reviewer expects the patterns of the IAMSAR Manual beside the paper's planners: "
        "parallel track (the area split among the drones), expanding square and sector "
        "search, each from the BS (docs/model.md, Search patterns), and every other registered "
        f"planner. Here: {labels}. They fly the grid of Figs. 2-6 as in the paper and with "
        "drones that report (on_detect = report), on the same runs (common random numbers); "
        f"Figure {OTHERS} draws them beside the paper's planners flown the same way. P_s "
        "comparisons carry Newcombe's 95% interval, over N_m = 2-22, r_c = 500, 1000, 2000 m "
        "and t_d = 1000 and 2000 s."),
        _List(others_text(tables["main"], tables["report"], others))]


def _relays(tables: dict[str, pd.DataFrame]) -> list[_Block]:
    if not {"main_runs", "relays_runs"} <= set(tables):
        return []
    points = relay_points(tables["main_runs"], tables["relays_runs"])
    runs = tables["relays_runs"]["run"].nunique()
    searcher = get_planner(RELAY_PLANNER).label
    counts = f"{', '.join(map(str, RELAY_COUNTS[:-1]))} or {RELAY_COUNTS[-1]}"
    return [_Heading("Beyond the paper: how many drones should hold the link?", 2), _Para(
        "The paper ends on it: \"our future work will focus on determining the optimum "
        "allocation of resources to different tasks of the mission\". Here a team of N_m "
        f"drones is {searcher} searchers and {counts} relays (team.relays; docs/model.md, "
        "Relays): drones that only keep the searchers linked to the BS, standing on a tree of "
        "hops of at most r_c over the BS and where it believes the searchers are. Figure "
        f"{RELAY_FIG} sets them against the paper's five planners with every drone searching, "
        f"at equal team size (N_m = {RELAY_DRONES[0]}-{RELAY_DRONES[-1]}), r_c = "
        f"{', '.join(f'{rc:g}' for rc in RANGES)} m and t_d = "
        f"{' and '.join(f'{td:g}' for td in RELAY_TDS)} s, over {runs} runs per point, paired "
        "run by run (run k of every team searches for the same target): each point against "
        "the best of the paper's five there (the highest P_s on these runs, which favours "
        f"the paper) and against {searcher} with every drone searching. Differences of P_s "
        "carry the paired 95% interval of their discordant runs."),
        _List(relays_text(points)),
        _Table(relays_summary(points)),
        _Table(relays_table(points), f"Every point: the {len(points)} paired comparisons")]


def _moving(tables: dict[str, pd.DataFrame]) -> list[_Block]:
    if "moving_runs" not in tables:
        return []
    runs = tables["moving_runs"]
    points = moving_points(runs)
    labels = ", ".join(get_planner(p).label for p in dict.fromkeys(runs["planner"]))
    wind, current = MOVING_WIND, MOVING_CURRENT
    return [_Heading("Beyond the paper: targets that move", 2), _Para(
        "The paper's target stays where it is drawn; the people SAR teams look for do not. "
        f"Here {labels} search with N_m = {MOVING_DRONES} drones and r_c = {MOVING_RC:g} m "
        "for a still target, a walking one (target.motion = walk with its defaults: 0.5 m/s, a "
        "correlated random heading, stopping after a log-normal time of median 4 h) and a "
        "person in the water (drift, Leeway class PIW-1) under a constant wind of "
        f"({wind[0]:g}, {wind[1]:g}) m/s and current of ({current[0]:g}, {current[1]:g}) m/s "
        "(east, north; docs/model.md, Target motion), which starts where it was last seen, "
        "inside the square, and may drift out of it: then no drone finds it. The drones take "
        "off when the target was last seen or "
        f"{' or '.join(f'{d:g}' for d in MOVING_DELAYS[1:])} s later (target.delay), during "
        f"which a moving target moves. Figure {MOVING_FIG} draws P_s against t_d; over "
        f"{runs['run'].nunique()} runs per point, paired run by run (run k of every target "
        "starts from the same last-seen point). Differences of P_s carry the paired 95% "
        "interval of their discordant runs."),
        _List([*moving_text(points), *best_text(runs)]),
        _Table(moving_table(points),
               f"Every point: the {len(points)} paired comparisons with a still target")]


def _replay(out: Path, link: ReplayLink | None) -> list[_Block]:
    if link is None:
        return []
    name = link.page.relative_to(out).as_posix()
    return [_Heading("Watch a mission", 2), _Para(link.about),
            _Link(f"Open {name} (beside this report; any browser, no network needed)", name)]


def _document(out: Path, *, runs: int, quick: bool, figures: dict[int, Path],
              tables: dict[str, pd.DataFrame], findings: Sequence[Finding],
              reading: Reading, stages: Sequence[Stage], seconds: float, workers: str,
              replay: ReplayLink | None, sensitivity: Sensitivity | None,
              presets: dict[str, list[Finding]] | None) -> list[_Block]:
    found = contradictions(findings, _other_readings(reading, presets, sensitivity))
    intro = (f"sarlink {version('sarlink')} reran the evaluation of Yanmaz et al., "
             "\"Connectivity considerations for mission planning of a search and rescue drone "
             f"team\" (Figs. {', '.join(str(n) for n in sorted(figures))}) with "
             f"{runs} runs per grid point, under the reading {reading.name!r} of what the paper "
             "leaves open (docs/model.md, Readings).")
    first = [_Para(first_line(findings, found))] if findings else []
    return [_Heading("Reproduction of the paper's evaluation", 1), *first, _Para(intro),
            *_claims(findings, tables, reading, presets, found), *_sensitivity(sensitivity),
            *_network(tables),
            *_setting(runs, quick, reading),
            *_timing(seconds, stages, workers),
            *_beyond(tables), *_others(tables), *_relays(tables), *_moving(tables),
            *_figures(out, figures, tables),
            *_replay(out, replay)]


# -- rendering ----------------------------------------------------------------------------------


def _md_table(frame: pd.DataFrame) -> str:
    def row(cells: Sequence[object]) -> str:
        return "| " + " | ".join(str(c).replace("|", "\\|") for c in cells) + " |"
    lines = [row(frame.columns), "|" + "---|" * len(frame.columns)]
    lines += [row(r) for r in frame.itertuples(index=False)]
    return "\n".join(lines)


def _markdown(blocks: Sequence[_Block]) -> str:
    parts = []
    for b in blocks:
        match b:
            case _Heading(text, level, _):
                parts.append("#" * level + " " + text)
            case _Para(text):
                parts.append(text)
            case _List(items):
                parts.append("\n".join(f"- {item}" for item in items))
            case _Table(frame, None):
                parts.append(_md_table(frame))
            case _Table(frame, summary):
                parts.append(f"<details><summary>{html.escape(str(summary))}</summary>\n\n"
                             f"{_md_table(frame)}\n\n</details>")
            case _Image(png, caption):
                parts.append(f"![{caption}]({png.as_posix()})\n\n*{caption}*")
            case _Link(text, href):
                parts.append(f"[{text}]({href})")
    return "\n\n".join(parts) + "\n"


_CSS = """
body { font-family: system-ui, sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em;
       color: #222; line-height: 1.45; }
h1, h2, h3 { line-height: 1.2; } h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; }
table { border-collapse: collapse; margin: .5em 0 1em; font-size: .9em; }
th, td { border: 1px solid #ccc; padding: .2em .6em; text-align: left; }
th { background: #f3f3f3; } tr:nth-child(even) td { background: #fafafa; }
img { max-width: 100%; } figcaption { font-style: italic; margin-bottom: 1em; }
details { margin: .5em 0 1.2em; } summary { cursor: pointer; color: #245; }
.holds { color: #176617; } .fails { color: #a32020; } .undecided { color: #7a5a00; }
.untestable { color: #555; }
"""


def _html_table(frame: pd.DataFrame) -> str:
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in frame.columns)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in r) + "</tr>"
                   for r in frame.itertuples(index=False))
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _html(blocks: Sequence[_Block], out: Path) -> str:
    parts = []
    for b in blocks:
        match b:
            case _Heading(text, level, css):
                attribute = f' class="{css}"' if css else ""
                parts.append(f"<h{level}{attribute}>{html.escape(text)}</h{level}>")
            case _Para(text):
                parts.append(f"<p>{html.escape(text)}</p>")
            case _List(items):
                parts.append("<ul>" + "".join(f"<li>{html.escape(i)}</li>" for i in items)
                             + "</ul>")
            case _Table(frame, None):
                parts.append(_html_table(frame))
            case _Table(frame, summary):
                parts.append(f"<details><summary>{html.escape(str(summary))}</summary>"
                             f"{_html_table(frame)}</details>")
            case _Image(png, caption):
                data = base64.b64encode((out / png).read_bytes()).decode()
                parts.append(f'<figure><img src="data:image/png;base64,{data}" '
                             f'alt="{html.escape(caption)}"><figcaption>{html.escape(caption)}'
                             "</figcaption></figure>")
            case _Link(text, href):
                parts.append(f'<p><a href="{html.escape(href)}">{html.escape(text)}</a></p>')
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<title>sarlink: reproduction of the paper</title>"
            f"<style>{_CSS}</style></head><body>\n" + "\n".join(parts) + "\n</body></html>\n")


def write_report(out: Path, *, runs: int, quick: bool, figures: dict[int, Path],
                 tables: dict[str, pd.DataFrame], findings: Sequence[Finding],
                 stages: Sequence[Stage], seconds: float, workers: str,
                 reading: Reading | None = None, replay: ReplayLink | None = None,
                 sensitivity: Sensitivity | None = None,
                 presets: dict[str, list[Finding]] | None = None) -> tuple[Path, Path]:
    """Write ``out/report.md`` and ``out/report.html``; return their paths.

    ``figures`` maps figure numbers to their PNG files inside ``out``; ``tables`` holds the
    summary tables the figures were drawn from and ``findings`` the claims checked on them,
    under ``reading`` (default: the default reading); ``workers`` says what ran the
    simulations; ``replay`` is a replay page inside ``out`` to link; ``sensitivity`` what the
    claims depend on; ``presets`` the claims under every preset reading, by name.
    """
    blocks = _document(out, runs=runs, quick=quick, figures=figures, tables=tables,
                       findings=findings, reading=reading or get_reading(DEFAULT_READING),
                       stages=stages, seconds=seconds, workers=workers, replay=replay,
                       sensitivity=sensitivity, presets=presets)
    md, page = out / "report.md", out / "report.html"
    md.write_text(_markdown(blocks), encoding="utf-8")
    page.write_text(_html(blocks, out), encoding="utf-8")
    return md, page
