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
    REPORTING = 3  # knows the target, the BS does not: flying straight to the BS to tell it


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


class OnDetect(IntEnum):
    """What a drone does once it knows the target's location and the BS does not."""

    CONTINUE = 0  # the paper: keep flying its plan
    REPORT = 1  # fly straight to the BS until it is notified, then resume


ON_DETECT_CODES = {"continue": OnDetect.CONTINUE, "report": OnDetect.REPORT}


class Reporters(IntEnum):
    """Which drones report when ``on_detect = report``."""

    KNOWERS = 0  # every drone that knows the target's location
    DETECTOR = 1  # only the drone that detected the target first


REPORTERS_CODES = {"knowers": Reporters.KNOWERS, "detector": Reporters.DETECTOR}
