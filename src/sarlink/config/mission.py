"""Mission configuration: validated, frozen, hashable.

A :class:`Mission` groups one small model per concept (area, team, sensing, channel, timing).
Every leaf field has a name that is unique across the groups, so a mission can also be read and
changed as a flat ``{name: value}`` mapping (:meth:`Mission.params`, :meth:`Mission.replace`):
that is what experiment grids and tidy result rows use. Defaults are the paper's Table 3.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal, Self

from pydantic import (
    BaseModel,
    Field,
    SerializerFunctionWrapHandler,
    ValidationInfo,
    field_validator,
    model_serializer,
    model_validator,
)

from sarlink.config.base import Checked, ConfigError
from sarlink.config.geo import FILE_KEYS, resolve_files
from sarlink.config.leeway import Forcing, forcing_table, leeway_class
from sarlink.config.region import Region, check_region

__all__ = [
    "ENERGY_MODEL_WITH_BATTERY",
    "Area",
    "Battery",
    "Channel",
    "Mission",
    "MtspSettings",
    "Readings",
    "Region",
    "Sensing",
    "Team",
    "Timing",
]


class Area(Checked):
    """The square search area ``[0, size]²`` and the base station (BS) on the ground.

    A mission's :class:`Region` may replace the square by a polygon (then ``bs`` is required
    and ``size`` is unused) and put it on the map.
    """

    size: float = Field(4000.0, gt=0, description="side a of the square area, m")
    bs: tuple[float, float] | None = Field(
        None, description="BS position (x, y), m; None puts it at the centre"
    )

    @property
    def bs_xy(self) -> tuple[float, float]:
        """The BS position, resolving the centre default."""
        return self.bs if self.bs is not None else (self.size / 2, self.size / 2)


class Team(Checked):
    """The drones and the planner that steers them."""

    drones: int = Field(10, ge=1, le=1000, strict=True, description="number of drones N_m")
    speed: float = Field(5.0, gt=0, description="flight speed V_m, m/s")
    planner: str = Field("covb", min_length=1,
                         description="planner name, see sarlink.planner_names() (checked where "
                         "a mission becomes work: sarlink.prepare)")
    alpha: float = Field(0.5, ge=0, le=1, description="ConCov weight of coverage (Eq. 12)")
    nr: int = Field(6, ge=1, strict=True,
                    description="mTSP-ConB: drones reserved for the mTSP plan")
    flight_time: float = Field(4000.0, gt=0, description="flight budget T_max, s")
    on_detect: Literal["continue", "report", "relay"] = Field(
        "continue",
        description="continue: the paper, drones keep their plan after learning where the "
        "target is; report: such a drone flies straight to the BS until it is notified, then "
        "resumes; relay: the detector holds over the target and the drones that know form a "
        "chain of links from the BS to it (beyond the paper; docs/model.md)",
    )
    reporters: Literal["knowers", "detector"] = Field(
        "knowers",
        description="with on_detect = report, who reports: every drone that knows the "
        "target's location, or only the first detector",
    )
    relays: int = Field(
        0, ge=0, strict=True,
        description="relay drones among the team's drones: the last ones, which keep the "
        "searchers linked to the BS instead of searching (beyond the paper; docs/model.md, "
        "Relays); 0: every drone searches",
    )
    relay_strategy: str = Field(
        "tree", min_length=1,
        description="where relays stand, by name (sarlink.relay_strategy_names()): tree, the "
        "bounded-edge Steiner tree over the BS and the searchers where it last heard of them",
    )
    relay_priority: Literal["nearest-first", "most-connected", "k-bottleneck"] = Field(
        "nearest-first",
        description="with fewer relays than the tree needs, whom they connect: the searchers "
        "needing fewest relays first, the most searchers, or the shortest longest hop",
    )
    relay_estimate: Literal["reckoned", "heard"] = Field(
        "reckoned",
        description="where the relays' tree puts a searcher the BS has not heard since: "
        "dead reckoning from its last hearing (on along its route or heading), or where it "
        "was last heard",
    )


class Sensing(Checked):
    """The drones' target sensor (Eq. 2) and its imperfection (Section 4.3)."""

    r: float = Field(500.0, gt=0, description="sensing range r, m")
    p_miss: float = Field(0.0, ge=0, le=1, description="probability that one look misses")
    look: Literal["per-pass", "per-period"] = Field(
        "per-pass",
        description="per-pass: one look each time a drone's range newly covers the target; "
        "per-period: one look every t_s while in range",
    )


class Channel(Checked):
    """Radio links: disc model (Eq. 4), optionally with log-normal shadowing (Eq. 13), or a
    radio model of a plug-in (docs/plugins.md)."""

    radio: str | None = Field(
        None, min_length=1,
        description="radio model by name (sarlink.engine.radios.radio_names()); None: the "
        "paper's, disc if sigma = 0, else log-normal shadowing",
    )
    rc: float = Field(1000.0, gt=0, description="communication range r_c, m")
    sigma: float = Field(0.0, ge=0, le=30, description="shadowing standard deviation, dB")
    pathloss_exponent: float = Field(1.75, gt=0, description="path-loss exponent n")
    coherence: float | None = Field(
        None, gt=0, description="shadowing redraw period, s, with readings.shadowing = "
        "period; None means t_s"
    )
    altitude: float = Field(
        0.0, ge=0, description="drone altitude h, m, added to drone-ground link distances"
    )
    decorrelation: float = Field(
        50.0, gt=0, description="shadowing decorrelation distance d_c, m: with readings."
        "shadowing = correlated, a link's fades a distance x of flight apart correlate by "
        "exp(-x / d_c)"
    )


class Timing(Checked):
    """Time step, sensing period, horizon and the grid of cumulative records."""

    dt: float = Field(1.0, gt=0, description="time increment t_i, s")
    ts: float = Field(2.0, gt=0, description="sensing (direction-change) period t_s, s")
    horizon: float = Field(4000.0, gt=0, description="simulated time, the largest t_d, s")
    checkpoint: float = Field(
        50.0, gt=0, description="spacing of the cumulative reachability records, s"
    )
    stop: Literal["horizon", "detected", "notified"] = Field(
        "horizon",
        description="when a run ends: at the horizon, at the first detection or at the BS's "
        "notification; an early stop is faster, and reachability and connectivity are then "
        "recorded only up to it (NaN after)",
    )


class Readings(Checked):
    """How the distributed rules read what the paper leaves open (docs/model.md, Readings).

    Each field is one choice; :data:`sarlink.config.readings.READINGS` names sets of them
    (``literal``, ``sarlink-1``, ...), and ``Mission.build(reading=...)`` applies one.
    """

    conb_check: Literal["period", "continuous"] = Field(
        "continuous",
        description="ConB's connectivity check (Section 3.2): period: at the end of each "
        "sensing period, for the graph at t + t_s; continuous: every step, for the graph at "
        "every increment up to t + t_s, turning at once if a loss of the route is predicted",
    )
    contacts: Literal["routed", "all"] = Field(
        "routed",
        description="Eq. 11's neighbour j: routed: the longest contact among the neighbours "
        "predicted to keep a route to the BS (all if none is); all: among every neighbour",
    )
    isolated: Literal["keep", "home"] = Field(
        "keep",
        description="ConB's term for a drone with no communication neighbour: keep its "
        "heading, or turn towards the BS",
    )
    concov_fallback: Literal["heading", "connectivity"] = Field(
        "connectivity",
        description="ConCov's heading when Eq. 12's two unit terms cancel: keep the heading, "
        "or follow the connectivity term",
    )
    concov_connected: Literal["heading", "none"] = Field(
        "heading",
        description="ConCov's connectivity term for a drone predicted to keep its route: its "
        "heading (Algorithm 2), or none (coverage alone steers it)",
    )
    takeoff: Literal["even", "random", "jitter"] = Field(
        "jitter",
        description="the distributed drones' take-off headings: even: exactly evenly spaced, "
        "2πk/N plus one random offset per run; random: independent uniform headings; "
        "jitter: evenly spaced, each off by a uniform error of at most HEADING_ERROR (5°)",
    )
    conb_fallback: Literal["contact", "heading", "limit"] = Field(
        "limit",
        description="ConB's heading when Eq. 9's two unit terms cancel (a drone flying straight "
        "away from its contact): contact: turn to θ_ij (a reversal); heading: keep it; limit: "
        "Eq. 9's limit as the heading's error vanishes, a right angle to a side drawn at random",
    )
    turns: Literal["exact", "jitter"] = Field(
        "jitter",
        description="how a distributed drone flies a commanded change of heading: exact; or "
        "jitter: off by a uniform error of at most HEADING_ERROR (5°), drawn at each change",
    )
    covb_direction: Literal["push", "printed"] = Field(
        "push",
        description="Eq. 8's neighbour term: push: from j to i, neighbours push (the text); "
        "printed: θ_ij from i to j as Eq. 8 is printed (neighbours pull)",
    )
    shadowing: Literal["period", "run", "correlated"] = Field(
        "correlated",
        description="how log-normal fades change (sigma > 0): period: drawn anew per link "
        "every coherence time; run: one fade per link for the whole run; correlated: each "
        "link's fade decorrelates with the distance its ends fly (Gudmundson, "
        "channel.decorrelation)",
    )
    shadow_calibration: Literal["median", "mean-area"] = Field(
        "median",
        description="which range of a log-normal link r_c is (sigma > 0): median: the path "
        "loss alone reaches r_c (Eq. 13 with S = 0); mean-area: the mean link area is the "
        "disc's, pi r_c²",
    )
    parked: Literal["relay", "base"] = Field(
        "base",
        description="a drone landed at the BS: relay: a drone like any other, relaying and "
        "counted connected; base: part of the BS, its links the BS's, not a connected drone",
    )
    reachability: Literal["direct", "multihop"] = Field(
        "multihop",
        description="target reachability: direct: a target-BS link counts; multihop: only a "
        "route over the drones",
    )
    mtsp_plan: Literal["shared", "per-run"] = Field(
        "per-run",
        description="mTSP plans: shared: one GA plan per team size for every run; per-run: a "
        "GA plan per run, seeded from (seed, run)",
    )
    mtsp_prediction: Literal["heading", "paths"] = Field(
        "paths",
        description="how mTSP-ConB's ConB drones predict the mTSP drones: heading: each keeps "
        "its heading; paths: each flies on along its known tour",
    )


ENERGY_MODEL_WITH_BATTERY = "rodrigues2021"
"""The energy model of a battery whose model is not named: the one measured on a small
quadcopter, which draws the most power of the built-in models (the cautious prediction)."""


class Battery(Checked):
    """The drones' battery and the energy model that drains it (beyond the paper, which flies
    without one; docs/model.md, Energy). A sortie may use the capacity less the reserve."""

    energy_model: str | None = Field(
        None, min_length=1,
        description="the power a drone draws as it flies, by name (sarlink.engine.energy."
        f"energy_model_names()): none, the paper's, no battery; zeng2019; rodrigues2021. None: "
        f"none without a battery, {ENERGY_MODEL_WITH_BATTERY} with one",
    )
    battery_wh: float | None = Field(
        None, gt=0, description="battery capacity, Wh; None: no battery (the paper)")
    reserve: float = Field(
        0.2, ge=0, lt=1,
        description="fraction of the capacity kept for the unforeseen: a sortie uses at most "
        "the rest (the 80 % rule of mission planners)",
    )
    swap_time: float = Field(
        120.0, gt=0, description="time to land, swap the battery and take off again at the "
        "BS, s")
    spares: int | None = Field(
        None, ge=0, strict=True,
        description="spare batteries at the BS, shared by the team; None: as many as needed. "
        "A drone that lands for a swap when none is left stays parked")


MAX_TARGETS = 1000
"""Most targets in one mission: each is a row of the kernel's per-target state."""


class Target(Checked):
    """The target and how it moves (beyond the paper, whose target stays where it is drawn;
    docs/model.md, Target motion). The prior (uniform, or ``region.zones``) is where it was
    last seen; it moves from there for ``delay`` seconds before take-off, then on."""

    count: int = Field(
        1, ge=1, le=MAX_TARGETS, strict=True,
        description="how many targets, each drawn from the prior and moving by the same model, "
        "independently (1: the paper's one target)")
    success: Literal["all", "first"] = Field(
        "all", description="with several targets, what counts as found and notified: all, "
        "every target detected and the BS told of each; first, the first of them")
    motion: str = Field(
        "still", min_length=1,
        description="how the target moves, by name (sarlink.engine.target_motion."
        "target_motion_names()): still, the paper's; walk, a lost person on land")
    delay: float = Field(
        0.0, ge=0, description="seconds between the last sighting and take-off, during which "
        "the target moves (a multiple of timing.dt)")
    motion_step: float = Field(
        10.0, ge=0, description="a moving target's time step, s: it moves once every step "
        "seconds, by the motion of that time, and stands where it went in between (a "
        "multiple of timing.dt; 0: every time step)")
    walk_speed: float = Field(
        0.5, gt=0, description="walk: the person's speed, m/s (a slow pace off trail)")
    walk_turn: float = Field(
        0.5, ge=0, description="walk: the standard deviation of the heading's change over "
        "one minute, rad (the heading is a random walk)")
    walk_mobile: float = Field(
        14400.0, gt=0, description="walk: the median time the person keeps moving after the "
        "last sighting, s (log-normal; then the person stops)")
    walk_spread: float = Field(
        1.0, ge=0, description="walk: the standard deviation of the log of the time mobile")
    drift_object: str = Field(
        "PIW-1", min_length=1,
        description="with motion = drift: the Leeway object class, by OpenDrift's key "
        "(sarlink.config.leeway.LEEWAY_CLASSES): PIW-1, a person in water of unknown state, "
        "PIW-2 to PIW-6, life rafts, boats")
    drift_wind: Forcing = Field(
        ((0.0, 0.0, 0.0),),
        description="with motion = drift: the 10 m wind, m/s: a pair east,north, or a table "
        "of rows t,east,north (t in s since the target was last seen, increasing), linear "
        "between rows")
    drift_current: Forcing = Field(
        ((0.0, 0.0, 0.0),),
        description="with motion = drift: the surface current, m/s, a pair or a table as "
        "drift_wind")

    @field_validator("drift_object")
    @classmethod
    def _known_class(cls, name: str) -> str:
        leeway_class(name)
        return name

    @field_validator("drift_wind", "drift_current", mode="before")
    @classmethod
    def _table(cls, value: Any) -> Forcing:
        return forcing_table(value)


class MtspSettings(Checked):
    """How mTSP plans are made (Section 3.1.1): solver, objective and GA settings.

    The ``[mtsp]`` table of a mission file; the planner that flies the plans is
    :class:`sarlink.planners.mtsp.Mtsp`.
    """

    solver: Literal["ga", "ortools"] = Field(
        "ga", description="ga: the paper's genetic algorithm; ortools: the strong solver, "
        "OR-Tools routing for minsum and a ruin-and-recreate search for minmax (docs/mtsp.md)"
    )
    objective: Literal["minsum", "minmax"] = Field(
        "minsum", description="minsum: total distance (paper); minmax: longest tour"
    )
    min_cells: int | None = Field(
        None, ge=1, strict=True,
        description="minimum cells per drone; None means floor(cells / drones)"
    )
    population: int = Field(80, ge=8, strict=True,
                            description="GA population (rounded down to groups of 8)")
    iterations: int = Field(5000, ge=1, strict=True, description="GA iterations")
    plan_seed: int = Field(0, ge=0, le=2**63 - 1, strict=True,
                           description="seed of the plan solver")


def _multiple_of(value: float, dt: float) -> bool:
    ratio = value / dt
    return abs(ratio - round(ratio)) < 1e-9 * max(1.0, ratio) and round(ratio) >= 1


MAX_STEPS = 10_000_000
"""Most time steps in one run (the paper's runs have 4000): a run's arrays stay in memory."""
MAX_RECORDS = 1_000_000
"""Most cumulative records (checkpoints) in one run (the paper's runs have 81)."""

class Mission(Checked):
    """One mission: everything a run depends on besides the seed and the run index.

    ``Mission.from_toml`` reads tables ``[area]``, ``[team]``, ... (all optional).
    """

    area: Area = Field(default_factory=Area)
    team: Team = Field(default_factory=Team)
    sensing: Sensing = Field(default_factory=Sensing)
    channel: Channel = Field(default_factory=Channel)
    timing: Timing = Field(default_factory=Timing)
    readings: Readings = Field(default_factory=Readings)
    mtsp: MtspSettings = Field(default_factory=MtspSettings)
    battery: Battery = Field(default_factory=Battery)
    target: Target = Field(default_factory=Target)
    region: Region | None = Field(
        None, description="a polygon area, holes, a target prior and a place on the map "
        "(sarlink.config.region); None: the paper's square and uniform target")

    @model_validator(mode="before")
    @classmethod
    def _read_map_files(cls, data: Any, info: ValidationInfo) -> Any:
        """``[region]`` naming an area or prior file, or the BS's longitude/latitude: read
        them (relative to the mission file's folder) into the region they describe."""
        region = data.get("region") if isinstance(data, dict) else None
        if not (isinstance(region, dict) and any(key in region for key in FILE_KEYS)):
            return data
        folder = (info.context or {}).get("folder") or Path()
        return resolve_files(data, Path(folder), Area.model_fields["size"].default)

    @model_serializer(mode="wrap")
    def _without_default_region(self, handler: SerializerFunctionWrapHandler) -> dict[str, Any]:
        """Leave out ``region`` when it is None and ``battery`` and ``target`` when they are
        the default: the paper's missions serialise, and so hash
        (:func:`sarlink.config.mission_hash`, the names of result folders), as before regions,
        batteries and moving targets."""
        data: dict[str, Any] = handler(self)
        if self.region is None:
            data.pop("region", None)
        if self.battery == Battery():
            data.pop("battery", None)
        if self.target == Target():
            data.pop("target", None)
        return data

    @model_validator(mode="after")
    def _consistent(self) -> Self:
        self._area_fits()
        t = self.timing
        if t.dt > t.ts:
            raise ValueError(f"timing.dt must be at most timing.ts = {t.ts} s, got {t.dt}")
        for name in ("ts", "horizon", "checkpoint"):
            value = getattr(t, name)
            if not _multiple_of(value, t.dt):
                raise ValueError(f"timing.{name} must be a multiple of timing.dt = {t.dt} s, "
                                 f"got {value}")
        steps, records = t.horizon / t.dt, t.horizon / t.checkpoint
        if steps > MAX_STEPS:
            raise ValueError(f"timing.horizon / timing.dt must be at most {MAX_STEPS:,} steps, "
                             f"got {t.horizon:g} s / {t.dt:g} s = {steps:,.0f}")
        if records > MAX_RECORDS:
            raise ValueError(f"timing.horizon / timing.checkpoint must be at most "
                             f"{MAX_RECORDS:,} records, got {t.horizon:g} s / {t.checkpoint:g} s "
                             f"= {records:,.0f}")
        if self.target.count > 1 and self.team.on_detect != "continue":
            raise ValueError(f"team.on_detect = {self.team.on_detect!r} follows one target; with "
                             f"target.count = {self.target.count} it must be 'continue' "
                             "(docs/model.md, Several targets)")
        for name in ("delay", "motion_step"):
            value = getattr(self.target, name)
            if value > 0 and not _multiple_of(value, t.dt):
                raise ValueError(f"target.{name} must be a multiple of timing.dt = {t.dt} s, "
                                 f"got {value:g}")
        coh = self.channel.coherence
        if coh is not None and not _multiple_of(coh, t.dt):
            raise ValueError(f"channel.coherence must be a multiple of timing.dt = {t.dt} s, "
                             f"got {coh}")
        return self

    def _area_fits(self) -> None:
        region, area = self.region, self.area
        if region is not None and region.outline is not None and area.bs is None:
            raise ValueError("area.bs: an area given as a polygon needs the BS's position")
        if region is None or region.outline is None:
            x, y = area.bs_xy
            if not (0 <= x <= area.size and 0 <= y <= area.size):
                raise ValueError(f"area.bs must lie inside the area [0, {area.size}]², got "
                                 f"({x}, {y})")
        problem = check_region(region, area.size, area.bs_xy)
        if problem:
            raise ValueError(f"region: {problem}")

    # -- construction -------------------------------------------------------------------------

    @classmethod
    def build(cls, reading: str | None = None, **params: Any) -> Mission:
        """A mission from flat parameters, e.g. ``Mission.build(drones=22, rc=500)``.

        ``reading`` names a set of the paper's readings (:data:`sarlink.config.READINGS`)
        applied first; explicit parameters override it.
        """
        from sarlink.config.readings import get_reading

        base = {} if reading is None else get_reading(reading).choices
        return cls().replace(**{**base, **params})

    # -- flat view ----------------------------------------------------------------------------

    def params(self) -> dict[str, Any]:
        """Every leaf parameter by its unique name (``drones``, ``rc``, ``p_miss``, ...)."""
        flat: dict[str, Any] = {}
        for group in flat_groups():
            flat.update(getattr(self, group).model_dump())
        return flat

    def replace(self, **params: Any) -> Mission:
        """A copy with some flat parameters changed, validated again."""
        owner = param_groups()
        data = self.model_dump()
        for name, value in params.items():
            if name not in owner:
                raise ConfigError(
                    f"unknown mission parameter {name!r}; known: {', '.join(sorted(owner))}"
                )
            data.setdefault(owner[name], {})[name] = value
        return Mission.from_dict(data)

    # -- derived quantities used by the engine -------------------------------------------------

    @property
    def n_steps(self) -> int:
        """Number of time increments in the horizon."""
        return round(self.timing.horizon / self.timing.dt)

    def checkpoint_steps(self) -> list[int]:
        """The steps of the cumulative records: every ``checkpoint`` and the horizon."""
        every = self.steps(self.timing.checkpoint)
        steps = list(range(0, self.n_steps + 1, every))
        return steps if steps[-1] == self.n_steps else [*steps, self.n_steps]

    def searching(self) -> Mission:
        """The mission its planner plans: the searchers alone (``team.drones - team.relays``
        drones, no relays); the relays are the team's last drones (docs/model.md, Relays)."""
        if self.team.relays == 0:
            return self
        return self.replace(drones=self.team.drones - self.team.relays, relays=0)

    def steps(self, seconds: float) -> int:
        """A duration in whole time increments (durations are validated as multiples of dt)."""
        return max(1, round(seconds / self.timing.dt))

    @model_validator(mode="after")
    def _searchers_left(self) -> Self:
        """At least one drone searches (here, not in :class:`Team`, so that the line names
        ``team.relays`` once: a team's own check would be prefixed ``team:``)."""
        t = self.team
        if t.relays >= t.drones:
            raise ValueError(f"team.relays = {t.relays} leaves no searcher among team.drones "
                             f"= {t.drones}; allowed: 0 to {t.drones - 1}")
        return self

    @model_validator(mode="after")
    def _disc_has_no_fades(self) -> Self:
        if self.channel.radio == "disc" and self.channel.sigma > 0:
            raise ValueError(f"channel.radio 'disc' has no shadowing; channel.sigma = "
                             f"{self.channel.sigma} needs channel.radio = 'shadowing' (or none)")
        return self

    @model_validator(mode="after")
    def _battery_has_a_model(self) -> Self:
        b = self.battery
        if b.energy_model == "none" and b.battery_wh is not None:
            raise ValueError(f"battery.energy_model 'none' draws no power, so battery."
                             f"battery_wh = {b.battery_wh:g} would never run down; name a model "
                             f"that draws power, or leave battery.energy_model unset "
                             f"({ENERGY_MODEL_WITH_BATTERY})")
        return self

    @property
    def energy_model(self) -> str:
        """The energy model's name, resolving the default: none without a battery, else
        :data:`ENERGY_MODEL_WITH_BATTERY`."""
        b = self.battery
        if b.energy_model is not None:
            return b.energy_model
        return "none" if b.battery_wh is None else ENERGY_MODEL_WITH_BATTERY

    @property
    def radio(self) -> str:
        """The radio model's name, resolving the paper's default."""
        c = self.channel
        return c.radio or ("shadowing" if c.sigma > 0 else "disc")

    @property
    def coherence(self) -> float:
        """Shadowing coherence time, resolving the ``t_s`` default."""
        c = self.channel.coherence
        return self.timing.ts if c is None else c


def flat_groups() -> dict[str, type[BaseModel]]:
    """The groups whose fields are flat mission parameters (every group but ``region``)."""
    return {"area": Area, "team": Team, "sensing": Sensing, "channel": Channel,
            "timing": Timing, "readings": Readings, "mtsp": MtspSettings, "battery": Battery,
            "target": Target}


def param_groups() -> dict[str, str]:
    """Flat parameter name -> the group that holds it."""
    return {field: group for group, model in flat_groups().items()
            for field in model.model_fields}
