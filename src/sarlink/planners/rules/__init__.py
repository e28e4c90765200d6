"""The built-in distributed rules, each one module shaped like a plug-in (docs/plugins.md): its
hooks, its :class:`~sarlink.DistributedRule` and its planner, registered by
:func:`sarlink.register_planner` when the module is imported. Every module of this package is
imported here, so a new built-in rule is one module (and its tests)."""

from __future__ import annotations

import importlib
import pkgutil

for _module in pkgutil.iter_modules(__path__):
    importlib.import_module(f"{__name__}.{_module.name}")
