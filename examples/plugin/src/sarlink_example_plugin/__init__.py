"""An example sarlink plug-in: the route planner ``rays`` and the rule ``tether``."""
