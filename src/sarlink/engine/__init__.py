"""The simulation engine: Numba kernels and their Python wrapper."""

from sarlink.engine.run import Prepared, prepare, simulate
from sarlink.engine.scenario import Scenario

__all__ = ["Prepared", "Scenario", "prepare", "simulate"]
