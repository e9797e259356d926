"""Levers of the bearing advice (:mod:`geardesign.core.advice`): life, static safety and
rib capacity fail on too small a bearing; the advice names the next catalogue bearings of
the same type and bore (:func:`geardesign.bearing.catalogue.candidates`, smallest first)
with a higher C_r, each re-rated, as ``bearing.designation``.  A bearing given by its
ratings alone (no designation) has no catalogue row to step from: no fix."""

from __future__ import annotations

from geardesign.bearing import catalogue as CAT
from geardesign.core.advice import Lever


def _value(res, key: str):
    sec = next((s for s in res.sections if s.key == "bearing"), None)
    return None if sec is None else next((r.value for r in sec.rows if r.key == key), None)


def _larger(data: dict, res):
    b = data.get("bearing")
    if not isinstance(b, dict) or not isinstance(b.get("designation"), str):
        return
    kind, d, C_r = _value(res, "type"), _value(res, "d"), _value(res, "C_r")
    if kind is None or d is None or C_r is None:
        return
    for row in CAT.candidates(kind, float(d)):
        if row.C_r > C_r:
            yield (("bearing.designation", row.designation),)


LEVERS = (Lever(("LIFE", "STATIC_SAFETY", "AXIAL_CAPACITY"), _larger,
                "the next catalogue bearing of this type and bore"),)
