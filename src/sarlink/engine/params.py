"""The scalars of one mission in kernel units, and the integer codes as Numba constants."""

from __future__ import annotations

from typing import NamedTuple

from sarlink.engine.codes import (
    Check,
    ConbFallback,
    Connected,
    Contacts,
    CovbDirection,
    Fallback,
    Isolated,
    Look,
    Mode,
    OnDetect,
    Parked,
    Prediction,
    Reachability,
    Reporters,
    Shadowing,
    Stop,
)

SEARCHING = int(Mode.SEARCHING)
RETURNING = int(Mode.RETURNING)
LANDED = int(Mode.LANDED)
REPORTING = int(Mode.REPORTING)
RELAYING = int(Mode.RELAYING)
CHAINING = int(Mode.CHAINING)
CONTINUE = int(OnDetect.CONTINUE)
REPORT = int(OnDetect.REPORT)
RELAY = int(OnDetect.RELAY)
DETECTOR_ONLY = int(Reporters.DETECTOR)
PER_PERIOD = int(Look.PER_PERIOD)
STOP_DETECTED = int(Stop.DETECTED)
STOP_NOTIFIED = int(Stop.NOTIFIED)
CONTINUOUS = int(Check.CONTINUOUS)
ALL_CONTACTS = int(Contacts.ALL)
ISOLATED_HOME = int(Isolated.HOME)
FALLBACK_CONNECTIVITY = int(Fallback.CONNECTIVITY)
CONNECTED_NONE = int(Connected.NONE)
CONB_KEEP_HEADING = int(ConbFallback.HEADING)
CONB_LIMIT = int(ConbFallback.LIMIT)
COVB_PRINTED = int(CovbDirection.PRINTED)
SHADOW_RUN = int(Shadowing.RUN)
SHADOW_CORRELATED = int(Shadowing.CORRELATED)
REACH_MULTIHOP = int(Reachability.MULTIHOP)
PREDICT_PATHS = int(Prediction.PATHS)
PARKED_BASE = int(Parked.BASE)


class Params(NamedTuple):
    """Scalars of one mission, in kernel units (metres, seconds, steps)."""

    size: float
    bs_x: float
    bs_y: float
    speed: float
    alpha: float
    flight_time: float
    r: float
    p_miss: float
    look: int
    rc: float
    sigma: float
    pathloss_exponent: float
    altitude: float
    decorrelation: float
    dt: float
    ts_steps: int
    coherence_steps: int
    n_steps: int
    stop: int
    record: bool
    trace: bool
    """Record the drones' positions at every step and nothing else (the run may still settle):
    what :mod:`sarlink.engine.critical_ranges` finds a range-free flight's notification
    staircase from. A traced flight finds no routes and floods no knowledge (its records, its
    notification and a stop at it are not kept: the scan at each range gives them)."""
    on_detect: int
    reporters: int
    conb_check: int
    contacts: int
    isolated: int
    concov_fallback: int
    concov_connected: int
    conb_fallback: int
    covb_direction: int
    shadowing: int
    reachability: int
    mtsp_prediction: int
    parked: int
    turn_error: float
    """The largest error of a commanded change of heading, rad (``readings.turns``)."""
    fade_bias: float
    """Added to every fade's log-range factor: 0 puts the median link range at r_c,
    ``-(sigma ln10 / 5n)² / 2`` the mean link area at the disc's (``shadow_calibration``)."""
    relays: int
    """Relay drones, the last ``relays`` of the team (``team.relays``; 0: every drone
    searches, and the kernel is compiled without the relay seam)."""
    relay_priority: int
    """Whom relays too few for the tree connect first (:class:`~sarlink.engine.codes.Priority`)."""
    relay_estimate: int
    """Where the BS believes a searcher it has not heard since (``team.relay_estimate``;
    :class:`~sarlink.engine.codes.Estimate`)."""
    battery_j: float
    """A full battery, J (``inf``: no battery, and the kernel is compiled without endurance,
    :mod:`sarlink.engine.endurance`)."""
    reserve_j: float
    """What a drone keeps for landing safely, J: it turns home before it would draw on it."""
    fly_w: float
    """The energy model's power at ``V_m``, W."""
    hover_w: float
    """Its power holding in place, W."""
    climb_j: float
    """A take-off's climb to the mission's altitude, J."""
    descent_j: float
    """A landing's descent from it, J."""
    swap_steps: int
    """A battery swap at the BS, steps."""
    spares: int
    """Spare batteries at the BS (``-1``: unlimited)."""
    target_delay: int
    """Steps the target moves before take-off (``target.delay``; 0 for a still target)."""
    target_every: int
    """A moving target's own time step, in steps (``target.step``; 1: every step)."""
    success: int
    """With several targets, whose events are the mission's (``target.success``,
    :class:`~sarlink.engine.codes.Success`)."""
