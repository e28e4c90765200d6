"""The built-in distributed rules, on the same seam as plug-in ones (:class:`DistributedRule`)."""

from __future__ import annotations

from sarlink.engine.hooks import DistributedRule
from sarlink.engine.rules import conb, concov, covb

__all__ = ["CONB", "CONCOV", "COVB"]

_CONB_READINGS = ("conb_check", "contacts", "isolated", "conb_fallback", "takeoff")
_COVB_READINGS = ("covb_direction", "takeoff")

COVB = DistributedRule("covb", covb.decide, prepare=covb.prepare, near=True,
                       readings=_COVB_READINGS, range_free=True, ignores_reporting=True)
"""CovB's repulsion (Eqs. 6-8): it reads the pairs within the sensing range, never a link."""
CONB = DistributedRule("conb", conb.decide, prepare=conb.prepare, due=conb.due,
                       readings=_CONB_READINGS, ignores_reporting=True)
"""ConB's attachment to the BS (Eqs. 9-11)."""
CONCOV = DistributedRule("concov", concov.decide, prepare=concov.prepare, due=concov.due,
                         near=True,
                         readings=(*_CONB_READINGS, "covb_direction", "concov_fallback",
                                   "concov_connected"),
                         ignores_reporting=True)
"""ConCov's blend of the two (Eq. 12)."""
