"""Levers of the wave-gear advice (:mod:`geardesign.core.advice`): a rim thinner than
H0 = 1.5·m is thickened to it (``gear.rim_thickness``, rounded up to 0.01 mm), and a
flexible wheel short of its fatigue safety gets a smaller radial deflection
(``gear.radial_deflection``, 5 % steps below the present one, which defaults to w0 = m);
each re-rated."""

from __future__ import annotations

from geardesign.core.advice import Lever, scaled, to_limit


def _module(data: dict) -> float:
    return float(data["gear"]["module"])


LEVERS = (
    Lever(("RIM_THICKNESS",), to_limit("RIM_THICKNESS", "gear.rim_thickness", up=True,
                                       digits=2, scale=_module), "the least rim thickness"),
    Lever(("FLEX_ENDURANCE",), scaled("gear.radial_deflection",
                                      [1.0 - 0.05 * i for i in range(1, 12)], 3,
                                      default=_module), "a smaller radial deflection"),
)
