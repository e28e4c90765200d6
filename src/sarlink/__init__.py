"""sarlink: plan and simulate search-and-rescue drone teams that must notify their base station."""

from sarlink.config import Area, Channel, ConfigError, Mission, Mtsp, Sensing, Team, Timing
from sarlink.engine import Scenario, prepare, simulate
from sarlink.experiments import Experiment, sweep
from sarlink.planners import get_planner, planner_names
from sarlink.result import RunResult, Trajectory
from sarlink.storage import load

__version__ = "0.1.0"

__all__ = [
    "Area",
    "Channel",
    "ConfigError",
    "Experiment",
    "Mission",
    "Mtsp",
    "RunResult",
    "Scenario",
    "Sensing",
    "Team",
    "Timing",
    "Trajectory",
    "get_planner",
    "load",
    "planner_names",
    "prepare",
    "simulate",
    "sweep",
]
