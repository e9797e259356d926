"""Levers of the spur advice (:mod:`geardesign.core.advice`) beyond the face width: when no
face width within b_w/d_w1 <= 1.6 makes the contact or bending check pass (the check then
carries no face-width fix), the pair is scaled to the next modules of the first (preferred)
series of GOST 9563-60 / ISO 54 (:data:`geardesign.spur.strength.tables.MODULES_1`): the
tooth numbers and shifts kept, the face width and a given centre distance scaled with the
module (face width rounded up to 0.1 mm, centre distance to 0.01 mm), each re-rated, the
first that passes advised as ``gear.module``, ``gear.face_width``,
``gear.center_distance``.  A standard module instead of the scaled one (4 -> 5.04 mm) is
what can be ordered and cut.  The check's own figures of the same change, a centre
distance scaled by a factor and a module raised by a per cent (:data:`SUPERSEDED`), are
left out of the message that carries the standard module: the user sets the module."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever

CODES = ("CONTACT_FATIGUE", "BENDING_FATIGUE_PINION", "BENDING_FATIGUE_WHEEL",
         "ISO_PITTING_PINION", "ISO_PITTING_WHEEL", "ISO_BENDING_PINION", "ISO_BENDING_WHEEL")
"""Strength checks that a larger standard module makes pass."""

MODULE_STEPS = 6
"""Standard modules tried above the present one."""


def standard_modules(data: dict, _res):
    """The pair scaled to the next first-series modules (see the module docstring)."""
    from geardesign.spur.strength.tables import MODULES_1

    gear = data.get("gear")
    if not isinstance(gear, dict):
        return
    m = gear.get("module")
    if not isinstance(m, (int, float)) or isinstance(m, bool):
        return
    for m2 in [x for x in MODULES_1 if x > m + 1e-9][:MODULE_STEPS]:
        k = m2 / m
        fix = [("gear.module", float(m2))]
        b = gear.get("face_width")
        if isinstance(b, (int, float)) and not isinstance(b, bool):
            fix.append(("gear.face_width", math.ceil(b * k * 10.0 - 1e-9) / 10.0))
        a = gear.get("center_distance")
        if isinstance(a, (int, float)) and not isinstance(a, bool):
            fix.append(("gear.center_distance", round(a * k, 2)))
        yield tuple(fix)


SUPERSEDED = (
    r"increase the centre distance (?:to at least|by) [^()]*\([^()]*in proportion[^()]*\)"
    r"(?: \(found by re-rating\))?",
    r"increase the module by [^()]*\(same centre distance, fewer teeth\)",
)
"""The clauses of the strength checks' words (:mod:`geardesign.spur.checks`, ISO 6336
rating) that a standard module replaces: the continuous scaling of the pair."""

LEVERS = (Lever(CODES, standard_modules, "the pair scaled to a standard module, GOST 9563 / "
                "ISO 54 first series", supersedes=SUPERSEDED),)
