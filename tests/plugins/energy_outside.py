"""An energy model defined outside sarlink: Zeng's rotorcraft drawing twice the power, on
sarlink's own hooks with parameters of its own."""

from sarlink import EnergyModel
from sarlink.engine.energy import rotor

HEAVY = EnergyModel("heavy", rotor.level, rotor.vertical, (*rotor.ZENG2019[:-1], 2.0),
                    source="tests: zeng2019 at twice the power")
