"""The mission flags: one table that every command taking mission flags builds on.

A row of :data:`FLAGS` declares a flag once: its name, its type, its help, the mission
parameter it sets (its range is that parameter's, read from the mission model) and the
commands that take it. :func:`mission_flags` adds a command's rows to it as Typer options, in a
"Mission" panel of its ``--help``, and hands the command a :class:`MissionFlags` with what the
user typed; :meth:`MissionFlags.mission` builds the mission, and every error about a value
names the flag as the user typed it (``--td (timing.horizon): ...``).

Adding a flag is one row. A flag that sets no single mission parameter (``--reading``) has
``param=None`` and an ``apply`` function that makes the mission with it; ``--config``, the
mission every flag starts from, and the three that put it on the map (``--area``, ``--bs``,
``--prior``, read together since the area file's projection depends on the BS) are read by
:meth:`MissionFlags.mission` itself.
"""

from __future__ import annotations

import functools
import inspect
import re
import typing
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Literal, get_args, get_origin

import typer
from pydantic.fields import FieldInfo

from sarlink.config import READINGS, ConfigError, Mission, get_reading, param_groups
from sarlink.config.base import read_toml
from sarlink.config.geo import parse_lonlat
from sarlink.config.leeway import LEEWAY_CLASSES
from sarlink.config.mission import ENERGY_MODEL_WITH_BATTERY, flat_groups
from sarlink.engine import relay_strategy_names, target_motion_names
from sarlink.engine.energy import energy_model_names
from sarlink.planners import planner_names
from sarlink.simulation import check_mission

__all__ = ["FLAGS", "Flag", "MissionFlags", "flags_of", "mission_flags"]

ONE_RUN = frozenset({"simulate", "replay"})
"""The commands that fly one mission (``replay`` with several planners)."""
PANEL = "Mission"
"""The ``--help`` panel of the mission flags."""


@dataclass(frozen=True)
class Flag:
    """One mission flag: how it is typed, what it sets, and which commands take it."""

    name: str
    """The flag as typed, ``--td``."""
    type: type
    """What its value is converted to: ``int``, ``float``, ``str`` or ``Path``."""
    help: str
    """What it sets, for ``--help``; the range is added from the parameter."""
    param: str | None
    """The flat mission parameter it sets (``horizon``), or None: read by
    :meth:`MissionFlags.mission` itself."""
    commands: frozenset[str]
    """The commands that take it."""
    apply: Callable[[Mission, Any], Mission] | None = None
    """For a flag with no ``param``: the mission with the flag's value applied (a
    :class:`ConfigError` it raises is reported with the flag's name)."""

    @property
    def dest(self) -> str:
        """Its Python name (Typer's): ``--p-miss`` -> ``p_miss``."""
        return self.name.removeprefix("--").replace("-", "_")

    @property
    def range(self) -> str:
        """The values the mission allows, from the model's constraints: ``> 0``, ``[0, 1]``,
        ``one of per-pass, per-period``; empty when unconstrained."""
        return "" if self.param is None else allowed(_field(self.param))

    def option(self) -> Any:
        """The Typer annotation of its command-line parameter."""
        allowed_text = f" ({self.range})" if self.range else ""
        return Annotated[self.type | None, typer.Option(
            self.name, help=self.help + allowed_text, rich_help_panel=PANEL, show_default=False)]


def _field(param: str) -> FieldInfo:
    return flat_groups()[param_groups()[param]].model_fields[param]


def allowed(field: FieldInfo) -> str:
    """A field's constraints as a reader writes them: ``> 0``, ``[0, 1]``, ``one of a, b``."""
    if get_origin(field.annotation) is Literal:
        return "one of " + ", ".join(map(str, get_args(field.annotation)))
    bounds = {attr: getattr(m, attr) for m in field.metadata
              for attr in ("gt", "ge", "lt", "le") if getattr(m, attr, None) is not None}
    if "ge" in bounds and "le" in bounds:
        return f"[{bounds['ge']}, {bounds['le']}]"
    signs = {"gt": ">", "ge": ">=", "lt": "<", "le": "<="}
    return ", ".join(f"{signs[attr]} {bound}" for attr, bound in bounds.items())


def _rows(*rows: tuple[str, type, str, str | None, Iterable[str]] | Flag) -> tuple[Flag, ...]:
    return tuple(row if isinstance(row, Flag) else
                 Flag(row[0], row[1], row[2], row[3], frozenset(row[4])) for row in rows)


def _read(mission: Mission, name: str) -> Mission:
    """``mission`` with the choices of the reading ``name``."""
    return mission.replace(**get_reading(name).choices)


FLAGS: tuple[Flag, ...] = _rows(
    # name, type, help, mission parameter, commands
    ("--planner", str, f"planner: {', '.join(planner_names())}", "planner",
     {"simulate", "export"}),
    ("--drones", int, "number of drones N_m", "drones", {*ONE_RUN, "plan", "export"}),
    ("--rc", float, "communication range r_c, m", "rc", {*ONE_RUN, "design", "export"}),
    ("--alpha", float, "ConCov coverage weight", "alpha", ONE_RUN),
    ("--nr", int, "mTSP-ConB: drones flying the plan", "nr", {*ONE_RUN, "export"}),
    ("--relays", int, "relay drones among the N_m drones: the last ones, holding the "
     "searchers' link to the BS (0: every drone searches)", "relays", {*ONE_RUN, "export"}),
    ("--relay-strategy", str, f"where the relays stand: {', '.join(relay_strategy_names())}",
     "relay_strategy", {*ONE_RUN, "export"}),
    ("--relay-priority", str, "with fewer relays than the tree needs, whom they connect",
     "relay_priority", {*ONE_RUN, "export"}),
    ("--relay-estimate", str, "where the relays' tree puts a searcher the BS has not heard "
     "since", "relay_estimate", {*ONE_RUN, "export"}),
    ("--td", float, "target duration t_d = horizon, s", "horizon", ONE_RUN),
    ("--size", float, "side a of the square area, m", "size", {"design", "plan"}),
    ("--r", float, "sensing range r (the mTSP cell side), m", "r",
     {*ONE_RUN, "design", "plan", "export"}),
    ("--speed", float, "flight speed V_m, m/s", "speed", {"plan", "export"}),
    ("--p-miss", float, "miss probability per look", "p_miss", {*ONE_RUN, "design"}),
    ("--look", str, "when a drone looks", "look", {*ONE_RUN, "design"}),
    ("--shadowing-sigma", float, "log-normal shadowing sigma, dB", "sigma",
     {*ONE_RUN, "design"}),
    ("--pathloss-exponent", float, "path-loss exponent n", "pathloss_exponent",
     {*ONE_RUN, "design"}),
    ("--stop", str, "end the run at", "stop", ONE_RUN),
    ("--on-detect", str, "what a drone does once it knows where the target is: continue (keep "
     "its plan, the paper), report (fly to the BS) or relay (the detector holds, the others "
     "form a chain to the BS)", "on_detect", ONE_RUN),
    ("--solver", str, "mTSP solver: ga (the paper's) or ortools (the strong one)", "solver",
     {"plan"}),
    ("--objective", str, "mTSP objective: minsum (total distance, the paper's) or minmax "
     "(longest tour)", "objective", {"plan"}),
    ("--min-cells", int, "minimum cells per drone (default floor(cells / drones))",
     "min_cells", {"plan"}),
    ("--seed", int, "seed of the plan search (the GA, or the min-max search)", "plan_seed",
     {"plan"}),
    ("--population", int, "GA population", "population", {"plan"}),
    ("--iterations", int, "GA iterations", "iterations", {"plan"}),
    ("--battery-wh", float, "battery capacity, Wh: drones swap batteries at the BS when it "
     "runs low; the export splits each route into sorties that fit it", "battery_wh",
     {*ONE_RUN, "design", "export"}),
    ("--energy-model", str, "the power a drone draws as it flies: "
     f"{', '.join(energy_model_names())} (default: none without --battery-wh, "
     f"{ENERGY_MODEL_WITH_BATTERY} with it)", "energy_model", {*ONE_RUN, "design", "export"}),
    ("--reserve", float, "fraction of the battery kept in reserve: a sortie uses at most the "
     "rest", "reserve", {*ONE_RUN, "design", "export"}),
    ("--swap-time", float, "time to swap a battery at the BS, s", "swap_time",
     {*ONE_RUN, "design", "export"}),
    ("--spares", int, "spare batteries at the BS (default: as many as needed)", "spares",
     {*ONE_RUN, "design"}),
    ("--altitude", float, "flight altitude, m: the links' height, and the climb and descent "
     "of every sortie on a battery", "altitude", {*ONE_RUN, "design"}),
    ("--targets", int, "how many targets, each drawn from the prior and moving by the "
     "same model, independently (docs/model.md, Several targets)", "count",
     {*ONE_RUN, "design"}),
    ("--success", str, "with several targets, the mission's success: all (every target "
     "found and the BS told of each) or first (the first of them)", "success",
     {*ONE_RUN, "design"}),
    ("--target-motion", str, "how the target moves: "
     f"{', '.join(target_motion_names())} (docs/model.md, Target motion)", "motion", ONE_RUN),
    ("--delay", float, "seconds from the last sighting to take-off, in which the target "
     "moves (a multiple of --dt)", "delay", ONE_RUN),
    ("--motion-step", float, "a moving target's time step, s: it moves once every so many "
     "seconds (a multiple of --dt; 0: every time step)", "motion_step", ONE_RUN),
    ("--walk-speed", float, "walk: the lost person's speed, m/s", "walk_speed", ONE_RUN),
    ("--walk-turn", float, "walk: the spread of the heading's change over a minute, rad",
     "walk_turn", ONE_RUN),
    ("--walk-mobile", float, "walk: the median time the person keeps moving, s",
     "walk_mobile", ONE_RUN),
    ("--drift-object", str, "with a drifting target: its Leeway object class, "
     f"{', '.join(LEEWAY_CLASSES)}", "drift_object", {*ONE_RUN, "design"}),
    ("--wind", str, "with a drifting target: the 10 m wind, m/s, 'east,north', or rows "
     "'t,east,north; ...' over the seconds since it was last seen", "drift_wind",
     {*ONE_RUN, "design"}),
    ("--current", str, "with a drifting target: the surface current, m/s, as --wind",
     "drift_current", {*ONE_RUN, "design"}),
    Flag("--reading", str, f"a named reading of what the paper leaves open "
         f"({', '.join(READINGS)}; docs/model.md); it overrides the config's readings table, "
         "flags override both", None, ONE_RUN | {"design"}, apply=_read),
    ("--area", Path, "the search area: a GeoJSON polygon in longitude/latitude, its holes "
     "no-fly zones (docs/missions.md)", None, {*ONE_RUN, "design", "plan", "export"}),
    ("--bs", str, "the BS's longitude,latitude in degrees (else the area file's Point)", None,
     {*ONE_RUN, "design", "plan", "export"}),
    ("--prior", Path, "where the target is likely to be: GeoJSON polygons with a probability "
     "property, or a GeoTIFF raster", None, {*ONE_RUN, "design", "export"}),
    ("--config", Path, "mission TOML; flags override it", None,
     {*ONE_RUN, "design", "plan", "export"}),
)
"""Every mission flag of every command. Range and help's allowed values come from the
mission model, so a flag never states a range of its own."""


def flags_of(command: str) -> tuple[Flag, ...]:
    """The rows of ``command``, in the table's order."""
    return tuple(flag for flag in FLAGS if command in flag.commands)


@dataclass(frozen=True)
class MissionFlags:
    """The mission flags a user typed (values not None), by row."""

    given: tuple[tuple[Flag, Any], ...]

    def value(self, name: str) -> Any:
        """The value of flag ``name`` (``--config``), or None if it was not typed."""
        return next((value for flag, value in self.given if flag.name == name), None)

    def mission(self) -> Mission:
        """The mission: ``--config``'s file (or the paper's defaults) put on the map by
        ``--area``, ``--bs`` and ``--prior``, then the flags with an ``apply`` (``--reading``),
        then the flags that set parameters. An error about a value names the flag the user
        typed."""
        config = self.value("--config")
        placed = [name for name in MAP_FLAGS if self.value(name) is not None]
        typed = " ".join(["--config"] * (config is not None) + placed)
        try:
            data = read_toml(config) if config is not None else {}
            if placed:
                data = self._placed(data)
            base = Mission.from_file_data(config, data) if config is not None else \
                Mission.from_dict(data)
        except ConfigError as exc:
            raise ConfigError(f"{typed}: {exc}" if placed else f"--config {exc}") from None
        for flag, value in self.given:
            if flag.apply is not None:
                try:
                    base = flag.apply(base, value)
                except ConfigError as exc:
                    raise ConfigError(f"{flag.name}: {exc}") from None
        params = {flag: value for flag, value in self.given if flag.param is not None}
        try:
            mission = base.replace(**{str(flag.param): value for flag, value in params.items()})
            check_mission(mission)  # planner, radio model, relay strategy by name, plug-ins loaded
            return mission
        except ConfigError as exc:
            raise ConfigError(_named(str(exc), params)) from None


    def _placed(self, data: dict[str, Any]) -> dict[str, Any]:
        """Mission data whose ``[region]`` names the typed ``--area`` and ``--prior`` files
        (in place of the file's) and ``--bs``; the mission reads them when it is built."""
        area, bs, prior = (self.value(name) for name in MAP_FLAGS)
        region = dict(data.get("region") or {})
        if area is not None:  # the file's polygon replaces one given in metres
            region.pop("outline", None)
            region.pop("holes", None)
            region["area"] = str(Path(area).resolve())
        if prior is not None:
            region["prior"] = str(Path(prior).resolve())
        if bs is not None:
            region["bs"] = parse_lonlat(bs, "--bs")
        return {**data, "region": region}


MAP_FLAGS = ("--area", "--bs", "--prior")
"""The flags that put a mission on the map (docs/missions.md), read together."""


def _named(message: str, params: dict[Flag, Any]) -> str:
    """``message`` with each ``group.param`` of a typed flag written ``--flag (group.param)``."""
    groups = param_groups()
    for flag in params:
        assert flag.param is not None
        dotted = f"{groups[flag.param]}.{flag.param}"
        message = re.sub(rf"(?<![\w.-]){re.escape(dotted)}(?!\w)", f"{flag.name} ({dotted})",
                         message)
    return message


def mission_flags(command: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Give a command function the mission flags of ``command``.

    The function takes a parameter ``flags: MissionFlags`` instead of one per flag; its
    signature, as Typer reads it, has that parameter replaced by the rows of
    :func:`flags_of`. A row whose name is also one of the command's own parameters is an
    error at import.
    """
    rows = flags_of(command)

    def decorate(func: Callable[..., Any]) -> Callable[..., Any]:
        signature = inspect.signature(func, eval_str=True)
        own = [p for name, p in signature.parameters.items() if name != "flags"]
        clash = {p.name for p in own} & {flag.dest for flag in rows}
        if clash or "flags" not in signature.parameters:
            raise TypeError(f"{func.__name__}: needs a 'flags' parameter and no parameter "
                            f"named like a mission flag ({', '.join(sorted(clash))})")
        added = [inspect.Parameter(flag.dest, inspect.Parameter.KEYWORD_ONLY, default=None,
                                   annotation=flag.option()) for flag in rows]

        @functools.wraps(func)
        def command_function(*args: Any, **kwargs: Any) -> Any:
            values = [(flag, kwargs.pop(flag.dest, None)) for flag in rows]
            given = tuple((flag, value) for flag, value in values if value is not None)
            return func(*args, flags=MissionFlags(given), **kwargs)

        command_function.__signature__ = signature.replace(  # type: ignore[attr-defined]
            parameters=[*(p.replace(kind=inspect.Parameter.KEYWORD_ONLY) for p in own),
                        *added])
        hints = typing.get_type_hints(func, include_extras=True)
        command_function.__annotations__ = {
            **{name: hint for name, hint in hints.items() if name != "flags"},
            **{flag.dest: flag.option() for flag in rows}}
        return command_function

    return decorate
