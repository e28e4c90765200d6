"""The planner contract: a named maker of the engine's :class:`Steering` for a mission."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

from sarlink.engine.codes import Rule
from sarlink.engine.steering import Steering

if TYPE_CHECKING:
    from sarlink.config import Mission


class Planner(Protocol):
    """A path planner, registered by name in :mod:`sarlink.planners`."""

    @property
    def name(self) -> str:
        """Registry key used in configs and the CLI (``covb``)."""
        ...

    @property
    def label(self) -> str:
        """Name as the paper writes it (``CovB``)."""
        ...

    @property
    def colour(self) -> str:
        """Its line colour in every figure (a Matplotlib colour)."""
        ...

    @property
    def marker(self) -> str:
        """Its marker in every figure (a Matplotlib marker)."""
        ...

    @property
    def rule(self) -> Rule:
        """The rule its distributed drones run (``Rule.NONE``: routes only); which of the
        paper's readings reach it (:data:`sarlink.config.readings.AFFECTS`)."""
        ...

    def steering(self, mission: Mission) -> Steering:
        """What the engine needs to fly ``mission`` with this planner."""
        ...
