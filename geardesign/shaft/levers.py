"""Levers of the shaft advice (:mod:`geardesign.core.advice`): fatigue, static strength,
critical speed and bearing slope fail on too thin a shaft; the advice scales every step
diameter by the same factor (the shoulders keep their proportions), rounded up to whole
millimetres, in steps of 5 % up to twice the present size, each re-rated.

The search starts one step below the factor that the failed checks estimate
(:func:`first_scale`: the safety factors grow about as d³, the critical speed as d², the
bearing slope falls as d⁻⁴ — beam theory, [Roark] ch. 8 and 10), so that a few re-ratings
find the least passing step instead of a scan from 5 % up.  A drive's shaft keeps its
bearing seats (their diameter is the bearing's bore) and the steps outboard of them no
larger than the seat, over which the bearing is mounted (:func:`scaled_steps`)."""

from __future__ import annotations

import math
from collections.abc import Iterator

from geardesign.core.advice import Lever

SCALES = tuple(1.0 + 0.05 * i for i in range(1, 21))
"""Factors on the step diameters tried, smallest first."""

CODES = ("FATIGUE", "STATIC_STRENGTH", "CRITICAL_SPEED", "BEARING_TILT")
"""The checks a thicker shaft makes pass."""

EXPONENT = {"FATIGUE": 3.0, "STATIC_STRENGTH": 3.0, "CRITICAL_SPEED": 2.0, "BEARING_TILT": 4.0}
"""How each check's value changes with the diameters (value ∝ d^e or d^-e): section
modulus d³, critical speed √(EI/m) ∝ d², slope 1/(EI) ∝ d⁻⁴."""


def first_scale(res) -> float:
    """The factor on the diameters that the failed checks of ``res`` estimate (at least 1):
    the largest (value/limit or limit/value, whichever exceeds 1)^(1/e)."""
    k = 1.0
    for c in res.failed:
        e = EXPONENT.get(c.code)
        if e is None or not c.value or not c.limit or c.value <= 0 or c.limit <= 0:
            continue
        k = max(k, max(c.value / c.limit, c.limit / c.value) ** (1.0 / e))
    return k


def scale_order(res) -> Iterator[float]:
    """:data:`SCALES` from one step below :func:`first_scale` upwards."""
    k0 = first_scale(res)
    i0 = next((i for i, k in enumerate(SCALES) if k >= k0 - 1e-9), len(SCALES))
    yield from SCALES[max(i0 - 1, 0):]


def scaled_steps(diameters: list[float], k: float, seats: set[int] = frozenset(),
                 prefix: str = "step") -> tuple:
    """Every step diameter times ``k``, rounded up to whole mm, as a fix
    ``((f"{prefix}[i].diameter", d), ...)``; the steps in ``seats`` keep their diameter and
    a step outboard of the seats (before the first, after the last) grows to at most the
    nearest seat's diameter."""
    lo, hi = (min(seats), max(seats)) if seats else (None, None)
    fix = []
    for i, d in enumerate(diameters):
        if i in seats:
            new = d
        else:
            new = float(math.ceil(d * k - 1e-9))
            cap = diameters[lo] if lo is not None and i < lo else (
                diameters[hi] if hi is not None and i > hi else None)
            if cap is not None:
                new = max(d, min(new, cap))
        fix.append((f"{prefix}[{i}].diameter", new))
    return tuple(fix)


def step_diameters(data: dict, res):
    """Every step diameter of the shaft spec ``data`` times each of :func:`scale_order`."""
    steps = data.get("step") or []
    if not all(isinstance(s, dict) and isinstance(s.get("diameter"), (int, float))
               for s in steps) or not steps:
        return
    last = None
    for k in scale_order(res):
        fix = scaled_steps([s["diameter"] for s in steps], k)
        if fix != last:
            yield fix
        last = fix


LEVERS = (Lever(CODES, step_diameters, "every step diameter scaled alike, rounded up to "
                "whole mm"),)
