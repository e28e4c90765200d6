"""Integer codes shared by the kernels and the Python layer (Numba freezes them as constants)."""

from enum import IntEnum


class Rule(IntEnum):
    """The direction-update rule that a team's distributed drones run."""

    COVB = 0
    CONB = 1
    CONCOV = 2
    NONE = 3  # no distributed drone: every drone flies a route (mTSP)


class Mode(IntEnum):
    """What a drone is doing."""

    SEARCHING = 0  # distributed planner steering, or flying its mTSP route
    RETURNING = 1  # out of budget: flying straight home
    LANDED = 2  # at the BS; still relays


class Look(IntEnum):
    """When a drone with the target in range takes a look (imperfect sensing)."""

    PER_PASS = 0
    PER_PERIOD = 1


LOOK_CODES = {"per-pass": Look.PER_PASS, "per-period": Look.PER_PERIOD}


class Stop(IntEnum):
    """When a run ends."""

    HORIZON = 0
    DETECTED = 1  # at the first detection
    NOTIFIED = 2  # at the BS's notification


STOP_CODES = {"horizon": Stop.HORIZON, "detected": Stop.DETECTED, "notified": Stop.NOTIFIED}
