"""``sarlink design``: the smallest team, planner and setting that meet a success requirement."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.table import Table

from sarlink.cli.common import console, print_json, user_errors
from sarlink.cli.flags import MissionFlags, mission_flags
from sarlink.config import ConfigError
from sarlink.config.region import area_label

if TYPE_CHECKING:
    from sarlink.design import CandidateEstimate, DesignAnswer, DesignRequest, PlannerAnswer
    from sarlink.design.needed_range import PlannerRanges

_OPTION_NAMES = {"planners": "--planner", "options": "--option"}


def _as_option(message: str) -> str:
    """A request error with its field written as the option the user typed (``--max-drones``)."""
    from sarlink.design import DesignRequest

    def rename(match: re.Match[str]) -> str:
        field = match[1]
        return _OPTION_NAMES.get(field, "--" + field.replace("_", "-")) + match[2]

    fields = "|".join(DesignRequest.model_fields)
    return re.sub(rf"(?:(?<=^)|(?<=; ))({fields})(:)", rename, message)


def _value(text: str) -> Any:
    """An option value as the mission expects it: an integer, a number, or the text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _options(specs: list[str]) -> dict[str, list[Any]]:
    options: dict[str, list[Any]] = {}
    for spec in specs:
        name, sep, values = spec.partition("=")
        if not sep or not name.strip():
            raise ConfigError(f"--option: expected NAME=VALUE[,VALUE...], got {spec!r}")
        options[name.strip()] = [_value(v.strip()) for v in values.split(",") if v.strip()]
    return options


def _probability(e: CandidateEstimate) -> str:
    return f"{e.p:.3f} [{e.lo:.3f}, {e.hi:.3f}]"


def _minutes(seconds: float) -> str:
    return "–" if math.isnan(seconds) else f"{seconds:.0f} s"


def _split(e: CandidateEstimate) -> str:
    """A team's split in words: its searchers and its relays."""
    return f"{e.searchers} searching, {e.relays} relay{'' if e.relays == 1 else 's'}"


def _setting(planner: PlannerAnswer) -> str:
    if planner.tuning is None or planner.chosen is None:
        return "–"
    tuning = planner.tuning
    others = [v for v in tuning.equivalent if v != planner.chosen.value]
    spread = f" (not told apart: {', '.join(f'{v:g}' for v in others)})" if others else ""
    return f"{tuning.setting} = {planner.chosen.value:g}{spread}"


def _print(answer: DesignAnswer) -> None:
    r = answer.request
    if r.every_planner:
        _print_planners(answer)
    best = answer.recommendation
    if best is not None and best.tuning is not None and not r.every_planner:
        _print_tuning(best)
    splits = r.split or (best is not None and best.chosen is not None
                         and best.chosen.relays > 0)
    if best is None or best.chosen is None:
        console.print(f"[bold]No planner reaches P_s >= {r.ps:g} within {r.max_drones} "
                      "drones.[/]")
    else:
        setting = "" if best.tuning is None or r.split else f", {_setting(best)}"
        split = f" ({_split(best.chosen)})" if splits else ""
        console.print(f"[bold]Recommendation: {best.label} with {best.chosen.drones} drones"
                      f"{split}{setting}[/]: "
                      f"P_s({r.td:g} s) = {_probability(best.chosen)} from "
                      f"{best.chosen.runs:,} runs, mean mission time "
                      f"{_minutes(best.chosen.mission_time)} (needed: {r.ps:g} at "
                      f"{r.confidence:.0%} confidence, r_c = {r.mission.channel.rc:g} m).",
                      highlight=False)
        if best.undecided:
            console.print(f"Team sizes {_sizes(best.undecided)} stayed too close to tell: "
                          "the true smallest may be one.", highlight=False)
    ended = ("the statistics" if answer.ended_by == "statistics"
             else f"the budget (--max-runs {r.max_runs:,}): more runs could change it"
             if answer.ended_by == "budget"
             else "the time (--max-seconds): more runs could change it")
    every = "" if r.every_planner else " (--every-planner: the smallest team of each planner)"
    console.print(f"Runs: {answer.runs_used:,} used ({answer.runs_simulated:,} simulated now, "
                  f"{answer.runs_used - answer.runs_simulated:,} reused); a full grid of "
                  f"{answer.grid_points:,} candidates at 2000 runs each: {answer.grid_runs:,}. "
                  f"The search was ended by {ended}.{every}", highlight=False)


def _print_planners(answer: DesignAnswer) -> None:
    """The per-planner table of ``--every-planner``, with each planner's tuning."""
    r = answer.request
    m = r.mission
    area = area_label(m.region, m.area.size)
    teams = (f"up to {r.max_drones}" if r.min_drones == 1 else f"{r.min_drones}"
             if r.min_drones == r.max_drones else f"{r.min_drones} to {r.max_drones}")
    table = Table(title=f"Smallest team with P_s({r.td:g} s) >= {r.ps:g} at {r.confidence:.0%} "
                        f"confidence (r_c = {m.channel.rc:g} m, {area}, {teams} drones)",
                  title_justify="left")
    # the split of each team, when the design tunes it or a team has relays
    splits = r.split or any(p.chosen is not None and p.chosen.relays for p in answer.planners)
    columns = ("planner", "smallest team", *("searchers + relays",) * splits,
               "P_s [95% Wilson]", "runs",
               "setting", "mission time")
    for name in columns:
        table.add_column(name, justify="left" if name in ("planner", "setting") else "right")
    for p in answer.planners:
        if p.chosen is None:
            why = ("not reachable within the largest team" if p.status == "not reachable"
                   else f"undecided: team sizes {_sizes(p.undecided)} too close to tell")
            table.add_row(p.label, f"[dim]{why}[/]", *[""] * (len(columns) - 2))
            continue
        note = f" ({_sizes(p.undecided)} undecided)" if p.undecided else ""
        split = f"{p.chosen.searchers} + {p.chosen.relays}"
        table.add_row(p.label, f"{p.smallest}{note}", *(split,) * splits,
                      _probability(p.chosen), f"{p.chosen.runs:,}", _setting(p),
                      _minutes(p.chosen.mission_time))
    console.print(table)
    for p in answer.planners:
        if p.tuning is not None:
            _print_tuning(p)
    held = [f"{p.label}: {k} = {v:g}" for p in answer.planners for k, v in p.held.items()]
    if held:
        console.print(f"Held at the mission's value while the split is tuned: "
                      f"{'; '.join(held)} (--option fixes another).", highlight=False)


def _sizes(sizes: tuple[int, ...]) -> str:
    return ", ".join(map(str, sizes))


def _print_tuning(planner: PlannerAnswer) -> None:
    tuning = planner.tuning
    assert tuning is not None
    table = Table(title=f"{planner.label} at {planner.smallest} drones: P_s against "
                        f"{tuning.setting} (search ended by {tuning.ended_by})",
                  title_justify="left")
    for name in (tuning.setting, "P_s [95% Wilson]", "runs", "verdict"):
        table.add_column(name, justify="right")
    for e in tuning.curve:
        mark = " *" if e.value == tuning.best.value else ""
        table.add_row(f"{e.value:g}{mark}", _probability(e), f"{e.runs:,}", e.verdict.value)
    console.print(table)


def _range_free_request(flags: MissionFlags) -> bool:
    """Whether the range is left to the design: no ``--rc``, and no ``rc`` in ``--config``."""
    from sarlink.config.base import read_toml

    if flags.value("--rc") is not None:
        return False
    config = flags.value("--config")
    if config is None:
        return True
    try:
        return "rc" not in read_toml(config).get("channel", {})
    except (ConfigError, OSError):  # the mission's own loading names the flag and the error
        return False


def _team_sizes(text: str | None, largest: int) -> tuple[int, ...]:
    if text is None:
        return tuple(range(1, largest + 1))
    try:
        sizes = tuple(sorted({int(v) for v in text.split(",") if v.strip()}))
    except ValueError:
        raise ConfigError(f"--sizes: expected team sizes like 4,10,22, got {text!r}") from None
    if not sizes or sizes[0] < 1 or sizes[-1] > largest:
        raise ConfigError(f"--sizes: team sizes must be between 1 and --max-drones "
                          f"({largest}), got {text!r}")
    return sizes


def _metres(value: float | None) -> str:
    return "–" if value is None else f"{value:,.0f} m"


def _print_ranges(request: DesignRequest, answers: list[PlannerRanges], runs: int) -> None:
    m = request.mission
    for a in answers:
        if not a.needs:
            console.print(f"[bold]{a.label}[/]: {a.reason}", highlight=False)
            continue
        table = Table(title=f"{a.label}: smallest r_c with P_s({request.td:g} s) >= "
                            f"{request.ps:g} at {request.confidence:.0%} confidence "
                            f"({area_label(m.region, m.area.size)}, {runs:,} runs per size)",
                      title_justify="left")
        for name in ("drones", "r_c needed", "estimate", "fails below",
                     "P_s at any range", "front"):
            table.add_column(name, justify="right")
        for need in a.needs:
            table.add_row(str(need.drones),
                          _metres(need.range) if need.range is not None else
                          "[dim]no range[/]", _metres(need.estimate), _metres(need.below),
                          f"{need.found:.3f}", "*" if need.front else "")
        console.print(table)
        if a.reason:
            console.print(f"  ({a.reason}: give --rc)", highlight=False)


@mission_flags("design")
def design(
    flags: MissionFlags,
    td: Annotated[float, typer.Option(help="target duration t_d, s")],
    ps: Annotated[float, typer.Option(help="required P_s(t_d), in (0, 1)")],
    planner: Annotated[list[str] | None, typer.Option(
        help="planner to consider; repeat for several; default: all")] = None,
    option: Annotated[list[str] | None, typer.Option(
        help="NAME=V1,V2: also try every planner with each value of a mission parameter; "
             "repeat for several; default: on_detect=continue,report")] = None,
    max_drones: Annotated[int, typer.Option(help="largest team considered")] = 22,
    min_drones: Annotated[int, typer.Option(
        help="smallest team considered; equal to --max-drones: that team alone")] = 1,
    split: Annotated[bool, typer.Option(
        "--split", help="tune the split: at every team size, every relay count from 0 to all "
                        "but one drone (each planner's own setting held)")] = False,
    confidence: Annotated[float, typer.Option(help="confidence of every decision")] = 0.95,
    max_runs: Annotated[int, typer.Option(help="budget: runs the whole design may use")
                        ] = 400_000,
    max_seconds: Annotated[float | None, typer.Option(
        help="no round of runs starts after this many seconds (the answer so far is given); "
             "changes when the design stops, never which runs it flies")] = None,
    every_planner: Annotated[bool, typer.Option(
        "--every-planner", help="the smallest team and setting of every planner, not only "
                                "the recommendation (more runs: larger teams too)")] = False,
    candidate_runs: Annotated[int, typer.Option(help="most runs of one candidate")] = 6400,
    first_runs: Annotated[int, typer.Option(help="runs of a candidate at its first look")] = 50,
    margin: Annotated[float, typer.Option(
        help="settings shown within this margin of the best P_s are as good")] = 0.01,
    alpha_step: Annotated[float, typer.Option(help="ConCov alpha grid spacing")] = 0.1,
    alpha_tol: Annotated[float, typer.Option(help="finest alpha spacing")] = 0.025,
    seed: Annotated[int, typer.Option(help="seed of every run")] = 2024,
    out: Annotated[Path, typer.Option("--out", "-o", help="runs folder, reused by reruns")
                   ] = Path("design-results"),
    workers: Annotated[int | None, typer.Option(
        help="worker processes (local pool or --dask-local); default: one per core")] = None,
    scheduler: Annotated[str | None, typer.Option(
        help="address of a running Dask scheduler, tcp://host:port")] = None,
    dask_local: Annotated[bool, typer.Option(
        "--dask-local", help="run on a Dask LocalCluster instead of the process pool")] = False,
    json: Annotated[bool, typer.Option("--json", help="print the answer as JSON")] = False,
    plot: Annotated[Path | None, typer.Option(help="write a figure of the answer here")] = None,
    quiet: Annotated[bool, typer.Option(
        "--quiet", "-q", help="no live view of the best candidate so far")] = False,
    sizes: Annotated[str | None, typer.Option(
        help="without --rc: team sizes to find the range of, e.g. 4,10,22; "
             "default: 1 to --max-drones")] = None,
    range_runs: Annotated[int, typer.Option(
        help="without --rc: runs per team size (one flight gives every range)")] = 1000,
) -> None:
    """Find the smallest team, planner and setting whose P_s(t_d) meets a requirement;
    without --rc, the smallest range each team size needs."""
    from sarlink.design import DesignRequest
    from sarlink.design import design as run_design  # pandas: only for this command

    with user_errors():
        if _range_free_request(flags):
            if split:
                raise ConfigError("--split needs --rc: relays fly differently at each range, "
                                  "so the range design cannot tune the split")
            if min_drones != 1:
                raise ConfigError("--min-drones applies with --rc only: without it --sizes "
                                  "names the team sizes")
            _design_range(flags, td, ps, planner, option, max_drones, confidence, seed, out,
                          workers, scheduler, dask_local, json, sizes, range_runs)
            return
        mission = flags.mission()
        fields: dict[str, Any] = {
            "mission": mission, "td": td, "ps": ps,
            "max_drones": max_drones, "min_drones": min_drones, "split": split,
            "confidence": confidence, "max_runs": max_runs,
            "candidate_runs": candidate_runs, "first_runs": first_runs, "margin": margin,
            "alpha_step": alpha_step, "alpha_tol": alpha_tol, "seed": seed,
            "every_planner": every_planner,
        }
        if planner is not None:
            fields["planners"] = tuple(planner)
        if option is not None:  # else the request's default: with and without reporting
            fields["options"] = _options(option)
        try:
            request = DesignRequest.from_dict(fields)
        except ConfigError as exc:
            raise ConfigError(_as_option(str(exc))) from None
        if max_seconds is not None and not max_seconds >= 0:
            raise ConfigError(f"--max-seconds must be 0 or more, got {max_seconds:g}")
        answer = run_design(request, out, workers=workers, scheduler=scheduler,
                            dask_local=dask_local, progress=not quiet and not json,
                            max_seconds=max_seconds)
    if plot is not None:
        import matplotlib.pyplot as plt

        from sarlink.plots.design import plot_design

        fig = plot_design(answer)
        fig.savefig(plot, dpi=150)
        plt.close(fig)
    if json:
        print_json(answer.to_json())
        return
    _print(answer)
    if plot is not None:
        console.print(f"figure written to {plot}")


def _design_range(flags: MissionFlags, td: float, ps: float, planner: list[str] | None,
                  option: list[str] | None, max_drones: int, confidence: float, seed: int,
                  out: Path, workers: int | None, scheduler: str | None, dask_local: bool,
                  json: bool, sizes: str | None, range_runs: int) -> None:
    """``sarlink design`` without ``--rc``: the range each team size needs
    (:mod:`sarlink.design.needed_range`)."""
    from sarlink.design import DesignRequest
    from sarlink.design.needed_range import range_design, to_json
    from sarlink.execution import start_workers
    from sarlink.planners import get_planner

    if option and _options(option):
        raise ConfigError("--option applies with --rc only: without it the design finds the "
                          "range of the paper's drones (on_detect = continue)")
    if range_runs < 10:
        raise ConfigError(f"--range-runs must be at least 10, got {range_runs}")
    team = _team_sizes(sizes, max_drones)
    mission = flags.mission()
    if mission.team.relays:
        raise ConfigError(f"team.relays = {mission.team.relays} needs --rc: relays fly "
                          "differently at each range, so the range design cannot take them")
    fields: dict[str, Any] = {"mission": mission, "td": td, "ps": ps,
                              "max_drones": max_drones, "confidence": confidence, "seed": seed,
                              "options": {}}
    if planner is not None:
        fields["planners"] = tuple(planner)
    else:  # every planner that may fly the same at every range
        from sarlink.planners import planner_names

        fields["planners"] = tuple(name for name in planner_names()
                                   if get_planner(name).rule is None
                                   or get_planner(name).rule.range_free  # type: ignore[union-attr]
                                   or get_planner(name).kind == "hybrid")
    try:
        request = DesignRequest.from_dict(fields)
    except ConfigError as exc:
        raise ConfigError(_as_option(str(exc))) from None
    with start_workers(workers, scheduler=scheduler, dask_local=dask_local) as pool:
        answers = range_design(request, out, team, range_runs, pool=pool)
    if json:
        print_json({"td": td, "ps": ps, "confidence": confidence, "runs": range_runs,
                    "planners": to_json(answers)})
        return
    _print_ranges(request, answers, range_runs)
