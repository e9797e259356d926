"""Levers of the shaft advice (:mod:`geardesign.core.advice`): fatigue, static strength,
critical speed and bearing slope fail on too thin a shaft; the advice scales every step
diameter by the same factor (the shoulders keep their proportions), rounded up to whole
millimetres, in steps of 5 % up to twice the present size, each re-rated."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever

SCALES = tuple(1.0 + 0.05 * i for i in range(1, 21))
"""Factors on the step diameters tried, smallest first."""


def step_diameters(data: dict, _res):
    """Every step diameter of the shaft spec ``data`` times each of :data:`SCALES`."""
    steps = data.get("step") or []
    if not all(isinstance(s, dict) and isinstance(s.get("diameter"), (int, float))
               for s in steps) or not steps:
        return
    last = None
    for k in SCALES:
        fix = tuple((f"step[{i}].diameter", float(math.ceil(s["diameter"] * k - 1e-9)))
                    for i, s in enumerate(steps))
        if fix != last:
            yield fix
        last = fix


LEVERS = (Lever(("FATIGUE", "STATIC_STRENGTH", "CRITICAL_SPEED", "BEARING_TILT"),
                step_diameters, "every step diameter scaled alike, rounded up to whole mm"),)
