"""Configuration: validated, frozen models of a mission and of an experiment over missions."""

from sarlink.config.base import Checked, ConfigError
from sarlink.config.experiment import Experiment, mission_hash
from sarlink.config.mission import (
    Area,
    Channel,
    Mission,
    MtspSettings,
    Sensing,
    Team,
    Timing,
    param_groups,
)

__all__ = [
    "Area",
    "Channel",
    "Checked",
    "ConfigError",
    "Experiment",
    "Mission",
    "MtspSettings",
    "Sensing",
    "Team",
    "Timing",
    "mission_hash",
    "param_groups",
]
