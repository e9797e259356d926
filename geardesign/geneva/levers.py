"""Levers of the Geneva advice (:mod:`geardesign.core.advice`), each re-rated.

A roller that does not fit (``ROLLER_FIT``) is reduced to the largest that fits
(``geneva.roller_diameter``, the check's limit rounded down to 0.1 mm) when that keeps at
least :data:`MIN_ROLLER_SHARE` of the given roller: the roller, its pin and bearing were
sized for the slot force, and a roller of less than half its size is another design.
Beyond it, or when no roller fits at all (the web, the locking disc or the cross shaft
leave no room), the next lever keeps the roller and enlarges the mechanism: the least
centre distance at which the roller fits (``geneva.center_distance``, whole millimetres,
found on the calculator's own geometry :func:`geardesign.geneva.kinematics.geometry`,
whose largest roller grows with a); the motion law is dimensionless and the motor power
does not depend on a, so only the slot force (∝ 1/a) changes, for the better.

A motor below the indexing peak is replaced by one rated for it (``drive.rated_power``,
the peak rounded up to 0.01 kW)."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever, to_limit

MIN_ROLLER_SHARE = 0.5
"""The smallest roller advised, as a share of the given one."""

A_STEPS = 5
"""Centre distances tried above the least one the geometry gives (whole mm)."""


def _smaller_roller(data: dict, res):
    c = next((c for c in res.checks if c.code == "ROLLER_FIT" and not c.passed), None)
    if c is None or not c.value or c.limit is None or c.limit < MIN_ROLLER_SHARE * c.value:
        return
    yield from to_limit("ROLLER_FIT", "geneva.roller_diameter", up=False)(data, res)


def _larger_a(data: dict, res):
    from geardesign.geneva import kinematics as K

    g = res.inputs.get("geneva") if isinstance(res.inputs, dict) else None
    if not isinstance(g, dict) or not any(c.code == "ROLLER_FIT" and not c.passed
                                          for c in res.checks):
        return
    z, a, d_r = g["slots"], g["center_distance"], g["roller_diameter"]
    internal = g["type"] == "internal"

    def fits(x: float) -> bool:
        m = K.geometry(z, internal, x, d_r, g["clearance"], g["shaft_diameter"] or 0.0)
        return 0.0 < m.max_roller and d_r <= m.max_roller

    hi = a
    for _ in range(20):                      # the largest roller grows with a
        hi *= 2.0
        if fits(hi):
            break
    else:
        return
    lo = a
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if fits(mid) else (mid, hi)
    first = math.ceil(hi - 1e-9)
    for i in range(A_STEPS + 1):
        yield (("geneva.center_distance", float(first + i)),)


LEVERS = (
    Lever(("ROLLER_FIT",), _smaller_roller, "the largest roller that fits"),
    Lever(("ROLLER_FIT",), _larger_a, "the least centre distance at which the roller fits"),
    Lever(("MOTOR_POWER",), to_limit("MOTOR_POWER", "drive.rated_power", up=True, digits=2,
                                     of="value"), "a motor rated for the indexing peak"),
)
