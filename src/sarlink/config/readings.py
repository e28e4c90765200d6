"""Named readings of the paper: sets of the choices it leaves open (docs/model.md, Readings).

A reading fixes every field of :class:`~sarlink.config.mission.Readings` (how the model reads
what the paper leaves open) and Fig. 3's target duration, which the paper does not state.
Which choices reach which rule, each rule says itself (``DistributedRule.readings``). The
default reading is what ``Mission()`` gives: ``sarlink-4``, each of whose choices follows the
paper's words and what a drone can do (docs/model.md), not how many claims hold under it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from sarlink.config.base import ConfigError

__all__ = ["DEFAULT_READING", "EARLIER_CHOICES", "READINGS", "Reading", "get_reading"]

EARLIER_CHOICES = {"takeoff": "even", "conb_fallback": "contact", "covb_direction": "push",
          "shadowing": "period", "reachability": "direct", "mtsp_plan": "shared",
          "mtsp_prediction": "heading", "turns": "exact", "parked": "relay",
          "shadow_calibration": "median"}
"""The choices sarlink made before they were named: the older presets keep them."""

_SARLINK_3 = {"conb_check": "continuous", "contacts": "routed", "isolated": "keep",
              "concov_fallback": "connectivity", "concov_connected": "heading",
              "takeoff": "jitter", "conb_fallback": "contact", "covb_direction": "push",
              "shadowing": "correlated", "reachability": "multihop", "mtsp_plan": "per-run",
              "mtsp_prediction": "paths", "turns": "exact", "parked": "relay",
              "shadow_calibration": "median"}
"""``sarlink-3``'s choices, which ``sarlink-4`` changes in three."""


@dataclass(frozen=True)
class Reading:
    """One named set of choices."""

    name: str
    about: str
    """Which words of the paper it follows."""
    choices: dict[str, str] = field(default_factory=dict)
    """Every field of :class:`~sarlink.config.mission.Readings`, by name."""
    td_fig3: float = 2000.0
    """Fig. 3's target duration t_d, s (the claims of Figs. 2-3 read P_s there)."""


READINGS: dict[str, Reading] = {r.name: r for r in (
    Reading(
        "literal",
        "closest to the paper's words: the connectivity check at every increment of the sensing "
        "period (Section 3.2), j among all neighbours (Eq. 11's 'the neighbor of UAV i'), "
        "R_con = the heading while connected (Algorithm 2), and Fig. 3 at t_d = 4000 s (the "
        "only t_d the text names with it)",
        {"conb_check": "continuous", "contacts": "all", "isolated": "keep",
         "concov_fallback": "heading", "concov_connected": "heading", **EARLIER_CHOICES},
        td_fig3=4000.0,
    ),
    Reading(
        "sarlink-1",
        "the readings of sarlink 1: the check once per sensing period (Algorithm 1's 'Check if t_s "
        "sec has elapsed'), j among the neighbours that keep a route to the BS, Fig. 3 at "
        "t_d = 2000 s",
        {"conb_check": "period", "contacts": "routed", "isolated": "keep",
         "concov_fallback": "heading", "concov_connected": "heading", **EARLIER_CHOICES},
        td_fig3=2000.0,
    ),
    Reading(
        "sarlink-2",
        "the connectivity check at every increment of the sensing period (Section 3.2's "
        "words), j among the neighbours that keep a route to the BS (Section 3.2: the "
        "connectivity 'of a given UAV i to the BS as well as its neighbors is checked'), and "
        "where Eq. 12's two terms cancel, ConCov follows ConB's 'attraction force against "
        "disconnections'; Fig. 3 at t_d = 2000 s",
        {"conb_check": "continuous", "contacts": "routed", "isolated": "keep",
         "concov_fallback": "connectivity", "concov_connected": "heading", **EARLIER_CHOICES},
        td_fig3=2000.0,
    ),
    Reading(
        "sarlink-3",
        "every choice by the paper's words and what a drone can do: sarlink-2's rules (Section "
        "3.2's check at every increment, j among the routed neighbours, Section 3's 'if ... a "
        "UAV does not have any neighbors, the direction is not changed', ConCov's fallback to "
        "the 'attraction force against disconnections'); a take-off evenly spaced with a "
        "drone's few degrees of heading error (the paper states no headings); where Eq. 9 "
        "vanishes ConB turns to θ_ij (its goal: 'avoiding ... isolated UAVs'); CovB's "
        "neighbours 'push' (Section 3.1.2, Eq. 8's printed direction taken as a slip); "
        "shadowing as 'large-scale fading' that decorrelates with the distance flown; target "
        "reachability as 'a multihop connection to the BS over the drone network' (Section 2); "
        "one GA plan per run, so that mTSP's figures average over the GA's outcomes, not one "
        "draw; mTSP-ConB's ConB drones predict the mTSP drones along their paths (Algorithm "
        "1's input {P_N}); Fig. 3 at t_d = 2000 s",
        _SARLINK_3,
        td_fig3=2000.0,
    ),
    Reading(
        "sarlink-4",
        "sarlink-3, with what a drone does after take-off too: every commanded turn flown "
        "with a drone's few degrees of heading error (Section 2: the drones 'rely on GPS', "
        "whose 'update rate and accuracy' set 'the sensing period and direction change "
        "times'); where Eq. 9 vanishes ConB turns a right angle, to a side drawn, the "
        "equation's own limit as the heading's error vanishes (a turn to θ_ij is the limit "
        "of no heading near it); a drone landed at the BS is part of the BS, not a relay "
        "and not a connected drone (Section 4.2: reachability is the time 'the target can "
        "be connected to the BS over a multihop link'); r_c the range of the path loss "
        "alone under shadowing (Section 4.3: 'we change the channel to log-normal "
        "shadowing', Eq. 13 adds S to the same path loss); Fig. 3 at t_d = 2000 s",
        {**_SARLINK_3, "turns": "jitter", "conb_fallback": "limit", "parked": "base"},
        td_fig3=2000.0,
    ),
)}
"""The presets by name."""

DEFAULT_READING = "sarlink-4"
"""The reading ``Mission()`` gives and ``sarlink reproduce`` uses unless told otherwise."""


def get_reading(name: str) -> Reading:
    """The reading called ``name``; a clear error naming the known ones otherwise."""
    try:
        return READINGS[name]
    except KeyError:
        raise ConfigError(f"unknown reading {name!r}; known: {', '.join(READINGS)}") from None
