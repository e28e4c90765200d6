"""Integer codes shared by the kernels and the Python layer (Numba freezes them as constants)."""

from enum import IntEnum


class Mode(IntEnum):
    """What a drone is doing."""

    SEARCHING = 0  # distributed planner steering, or flying its mTSP route
    RETURNING = 1  # out of budget: flying straight home
    LANDED = 2  # at the BS; still relays
    REPORTING = 3  # knows the target, the BS does not: flying straight to the BS to tell it
    RELAYING = 4  # a relay drone: flying to, or holding, its point of the searchers' link
    CHAINING = 5  # on_detect = relay: flying to, or holding, a point of the chain from the BS
    # to a found target (the detector holds where it found it)


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


class Success(IntEnum):
    """With several targets (``target.success``), whose events are the mission's."""

    ALL = 0  # every target: the last detection, the last notification
    FIRST = 1  # the first detection, the first notification


SUCCESS_CODES = {"all": Success.ALL, "first": Success.FIRST}


class OnDetect(IntEnum):
    """What a drone does once it knows the target's location (``report``: while the BS does
    not; ``relay``: for good)."""

    CONTINUE = 0  # the paper: keep flying its plan
    REPORT = 1  # fly straight to the BS until it is notified, then resume
    RELAY = 2  # the detector holds over the target, the knowers form a chain to the BS


ON_DETECT_CODES = {"continue": OnDetect.CONTINUE, "report": OnDetect.REPORT,
                   "relay": OnDetect.RELAY}


class Reporters(IntEnum):
    """Which drones report when ``on_detect = report``."""

    KNOWERS = 0  # every drone that knows the target's location
    DETECTOR = 1  # only the drone that detected the target first


REPORTERS_CODES = {"knowers": Reporters.KNOWERS, "detector": Reporters.DETECTOR}


class Check(IntEnum):
    """When a ConB drone checks its connectivity to the BS (Section 3.2; docs/model.md)."""

    PERIOD = 0  # at the end of each sensing period, for the graph at t + t_s
    CONTINUOUS = 1  # every step, for the graph at every increment up to t + t_s


CHECK_CODES = {"period": Check.PERIOD, "continuous": Check.CONTINUOUS}


class Contacts(IntEnum):
    """Which neighbours Eq. 11's longest-contact neighbour j is chosen from."""

    ROUTED = 0  # those predicted to keep a route to the BS (all if none is)
    ALL = 1  # every communication neighbour


CONTACTS_CODES = {"routed": Contacts.ROUTED, "all": Contacts.ALL}


class Isolated(IntEnum):
    """What ConB's term is for a drone without any communication neighbour."""

    KEEP = 0  # its own heading (Eq. 9 without F_ij)
    HOME = 1  # the direction to the BS


ISOLATED_CODES = {"keep": Isolated.KEEP, "home": Isolated.HOME}


class Fallback(IntEnum):
    """ConCov's heading when Eq. 12's resultant vanishes (the two unit terms cancel)."""

    HEADING = 0  # keep the heading
    CONNECTIVITY = 1  # the connectivity term's direction


FALLBACK_CODES = {"heading": Fallback.HEADING, "connectivity": Fallback.CONNECTIVITY}


class Connected(IntEnum):
    """ConCov's connectivity term for a drone predicted to keep its route to the BS."""

    HEADING = 0  # its own heading (Algorithm 2)
    NONE = 1  # no term: the coverage term alone steers it


CONNECTED_CODES = {"heading": Connected.HEADING, "none": Connected.NONE}


class Takeoff(IntEnum):
    """How the distributed drones' take-off headings are spread (docs/model.md, Readings)."""

    EVEN = 0  # exactly evenly spaced, one random offset per run
    RANDOM = 1  # independent uniform headings
    JITTER = 2  # evenly spaced, each off by a small uniform error


TAKEOFF_CODES = {"even": Takeoff.EVEN, "random": Takeoff.RANDOM, "jitter": Takeoff.JITTER}


class ConbFallback(IntEnum):
    """ConB's heading when Eq. 9's two unit terms cancel."""

    CONTACT = 0  # turn to θ_ij
    HEADING = 1  # keep the heading
    LIMIT = 2  # Eq. 9's limit as the heading's error vanishes: a right angle, to a drawn side


CONB_FALLBACK_CODES = {"contact": ConbFallback.CONTACT, "heading": ConbFallback.HEADING,
                       "limit": ConbFallback.LIMIT}


class CovbDirection(IntEnum):
    """The direction of Eq. 8's neighbour term."""

    PUSH = 0  # from j to i: neighbours push (the text)
    PRINTED = 1  # from i to j, as Eq. 8 is printed: neighbours pull


COVB_DIRECTION_CODES = {"push": CovbDirection.PUSH, "printed": CovbDirection.PRINTED}


class Shadowing(IntEnum):
    """How log-normal fades change over a run."""

    PERIOD = 0  # drawn anew per link every coherence time
    RUN = 1  # one fade per link for the whole run
    CORRELATED = 2  # Gudmundson: decorrelating with the distance flown


SHADOWING_CODES = {"period": Shadowing.PERIOD, "run": Shadowing.RUN,
                   "correlated": Shadowing.CORRELATED}


class Reachability(IntEnum):
    """Which routes make the target reachable."""

    DIRECT = 0  # a target-BS link counts
    MULTIHOP = 1  # only a route over the drones


REACHABILITY_CODES = {"direct": Reachability.DIRECT, "multihop": Reachability.MULTIHOP}


class Parked(IntEnum):
    """What a drone landed at the BS is to the network."""

    RELAY = 0  # a drone like any other: it relays and counts as connected
    BASE = 1  # part of the BS: its links are the BS's, and it is not a connected drone


PARKED_CODES = {"relay": Parked.RELAY, "base": Parked.BASE}


class Turns(IntEnum):
    """How exactly a drone flies a heading it is commanded to change to."""

    EXACT = 0
    JITTER = 1  # off by a small uniform error, drawn at each change


TURNS_CODES = {"exact": Turns.EXACT, "jitter": Turns.JITTER}


class ShadowCalibration(IntEnum):
    """Which range of a log-normal link r_c is."""

    MEDIAN = 0  # the path loss alone reaches r_c (Eq. 13 with S = 0): half the fades do
    MEAN_AREA = 1  # the mean link area is the disc's, pi r_c^2


SHADOW_CALIBRATION_CODES = {"median": ShadowCalibration.MEDIAN,
                            "mean-area": ShadowCalibration.MEAN_AREA}


class Prediction(IntEnum):
    """How mTSP-ConB's ConB drones predict the drones that fly routes."""

    HEADING = 0  # each keeps its heading
    PATHS = 1  # each flies on along its known route


PREDICTION_CODES = {"heading": Prediction.HEADING, "paths": Prediction.PATHS}


class Priority(IntEnum):
    """Which searchers relays connect when they are fewer than the tree needs (docs/model.md,
    Relays)."""

    NEAREST = 0  # "nearest first": searchers whose path needs fewest relays first
    MOST = 1  # "most connected": the most searchers the relays can connect
    BOTTLENECK = 2  # "k-bottleneck": the tree's longest hop as short as the relays make it


PRIORITY_CODES = {"nearest-first": Priority.NEAREST, "most-connected": Priority.MOST,
                  "k-bottleneck": Priority.BOTTLENECK}


class Estimate(IntEnum):
    """Where the BS believes a searcher out of contact (docs/model.md, Relays)."""

    RECKONED = 0  # dead reckoning from its last hearing: on along its route or heading
    HEARD = 1  # where it was last heard


ESTIMATE_CODES = {"reckoned": Estimate.RECKONED, "heard": Estimate.HEARD}
