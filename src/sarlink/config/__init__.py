"""Configuration: validated, frozen models of a mission and of an experiment over missions."""

from sarlink.config.base import Checked, ConfigError
from sarlink.config.experiment import Experiment, mission_hash
from sarlink.config.mission import (
    Area,
    Battery,
    Channel,
    Mission,
    MtspSettings,
    Readings,
    Sensing,
    Target,
    Team,
    Timing,
    param_groups,
)
from sarlink.config.readings import DEFAULT_READING, READINGS, Reading, get_reading

__all__ = [
    "DEFAULT_READING",
    "READINGS",
    "Area",
    "Battery",
    "Channel",
    "Checked",
    "ConfigError",
    "Experiment",
    "Mission",
    "MtspSettings",
    "Reading",
    "Readings",
    "Sensing",
    "Target",
    "Team",
    "Timing",
    "get_reading",
    "mission_hash",
    "param_groups",
]
