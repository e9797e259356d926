"""Levers of the overload-clutch spring advice (:mod:`geardesign.core.advice`): an
overstressed spring ``n`` gets a thicker wire (``spring[n-1].wire_diameter``), from the
least the check names (d_min, rounded up to 0.1 mm) in 0.1 mm steps, each re-rated."""

from __future__ import annotations

from geardesign.core.advice import Lever

MAX_SPRINGS = 8
"""Springs whose stress advice carries a fix."""


def _thicker(n: int):
    def gen(data: dict, res):
        springs = data.get("spring") or []
        if n > len(springs) or not isinstance(springs[n - 1], dict):
            return
        d = springs[n - 1].get("wire_diameter")
        c = next((c for c in res.checks if c.code == f"SPRING_STRESS_{n}"), None)
        if not isinstance(d, (int, float)) or c is None or not c.value or not c.limit:
            return
        # σ ∝ 1/d³ at a given torque: the least wire, then 0.1 mm steps
        first = max(d * (c.value / c.limit) ** (1.0 / 3.0), d)
        start = int(first * 10.0 - 1e-9) + 1
        for i in range(15):
            yield ((f"spring[{n - 1}].wire_diameter", (start + i) / 10.0),)
    return gen


LEVERS = tuple(Lever((f"SPRING_STRESS_{n}",), _thicker(n), "a thicker wire")
               for n in range(1, MAX_SPRINGS + 1))
