"""The simulation engine: Numba kernels in the model's phases and their Python wrapper.

It takes a mission and a :class:`Steering` (rule and routes); the planners that make
steerings live above it (:mod:`sarlink.planners`, :mod:`sarlink.simulation`).
"""

from sarlink.engine.run import Prepared
from sarlink.engine.scenario import Scenario
from sarlink.engine.steering import Steering

__all__ = ["Prepared", "Scenario", "Steering"]
