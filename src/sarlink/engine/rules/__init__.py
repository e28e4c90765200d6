"""The engine's own rule: that of a team without distributed drones (:mod:`.none`), whose hooks
are also the defaults of a rule that leaves one out. The built-in rules are plug-ins
(:mod:`sarlink.planners.rules`)."""
