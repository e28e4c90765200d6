"""What a distributed rule sees: the state the drones observed this step (docs/plugins.md).

The kernel builds one :class:`Observation` per run; its arrays are the kernel's own and change
in place every step, so a rule reads the current state through it without a copy. Node
indices: drones ``0 .. N-1``, the BS ``N``, the target ``N + 1`` (with several targets, the
first: the others are sensed, not nodes; docs/model.md, Several targets); bitsets are rows of
``ceil((N + 2) / 64)`` 64-bit words (:mod:`sarlink.engine.graph`: ``has``, ``bit``, ``lowest``).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


class Observation(NamedTuple):
    """The observed state of one step, read by the rule hooks (read-only but for noted fields).

    Position arrays are padded past the target with far-away nodes (``px.shape[0] >= N + 2``).
    """

    px: np.ndarray
    """x of every node, m (float64; drones, the BS, the target, padding)."""
    py: np.ndarray
    """y of every node, m."""
    pz: np.ndarray
    """Height of every node, m (drones at the mission's altitude, the BS and target at 0)."""
    hx: np.ndarray
    """x of every drone's unit heading (length N)."""
    hy: np.ndarray
    """y of every drone's unit heading."""
    mode: np.ndarray
    """What every drone is doing (int8, :class:`sarlink.engine.codes.Mode`)."""
    on_route: np.ndarray
    """Whether a drone flies a route (bool); the rule steers only the others."""
    last_change: np.ndarray
    """Step of every drone's last direction change: its decision clock (int64; a ``due``
    hook that makes a drone decide sets it to the current step)."""
    knows: np.ndarray
    """Whether a drone knows where the target is (bool; with several, any of them)."""
    adj: np.ndarray
    """Communication links of this step: ``adj[a]`` is node ``a``'s neighbour bitset."""
    near: np.ndarray
    """Pairs within the sensing range r, as bitsets like ``adj``: filled on the steps at which
    a drone decides, for rules that ask for it (``DistributedRule.near``)."""
    routed: np.ndarray
    """Bitset of the nodes with a multihop route to the BS this step (the BS included)."""
    spread: np.ndarray
    """Bitset of the nodes that know where the target is (empty before the first detection;
    with several targets, any of them)."""
    rc: float
    """The nominal communication range, m: the range planners predict with (the radio
    model's; shadow-free)."""
    wp: np.ndarray
    """Every route's waypoints, ``(k, 2)`` (x, y), m: drone ``i``'s still ahead of it are
    ``wp[wp_next[i]:wp_end[i]]`` (none for a distributed drone)."""
    wp_next: np.ndarray
    """Index in ``wp`` of every drone's next waypoint (int64)."""
    wp_end: np.ndarray
    """One past the index of every drone's last waypoint (int64)."""
    rng: np.random.Generator
    """The rule's own random stream, from ``(seed, run)`` only (no other part of the run draws
    from it, so a rule's draws change nothing else): draw from it in the hooks."""
    work: np.ndarray
    """A counter a rule may add its work to (int64, one element; writable): the kernel returns
    it as ``RunRecord.work``, so that what a rule computes can be counted independently of
    how fast it runs (ConB counts the nodes its route predictions expand, Fig. 1)."""
