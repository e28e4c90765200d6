"""The radio models: the built-in ones (:mod:`.lognormal`: the disc and log-normal shadowing),
registered by :func:`register_radio` as a plug-in model is, and the registry that finds them
by name (:mod:`.registry`)."""

from __future__ import annotations

from sarlink.engine.radios.lognormal import DISC, SHADOWING
from sarlink.engine.radios.registry import RADIOS, get_radio, radio_names, register_radio

__all__ = ["DISC", "RADIOS", "SHADOWING", "get_radio", "radio_names", "register_radio"]
