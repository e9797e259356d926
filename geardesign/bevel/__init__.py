"""Bevel gear pairs, straight and spiral (circular-arc) teeth, any shaft angle: geometry to
[GOST19624] / [GOST19326] / [ISO23509], strength to [ISO10300-2] / [ISO10300-3] through the
virtual cylindrical gear of [ISO10300-1] and to [GOST21354] through the virtual spur pair
of the handbook method ([Dunaev]), and the forces on the shafts.

Modules: :mod:`.spec` (the spec schema), :mod:`.inputs` (spec -> typed inputs, every input
rule in one round), :mod:`.geometry` (cones, diameters, virtual gears, contact ratios),
:mod:`.rating` (forces and both strength methods, frozen records), :mod:`.solve` (inputs ->
record), :mod:`.report` (record -> rows and checks), :mod:`.calculator` (the kind).
"""

from geardesign.core.registry import lazy_calculator

__getattr__ = lazy_calculator(
    "bevel", "bevel gear pair (straight or spiral): geometry, ISO 10300 / GOST strength, forces",
    ("ISO 23509 / GOST 19624-74 / GOST 19326-73 geometry", "ISO 10300-1/-2/-3 (method B1 "
     "virtual cylindrical gear)", "GOST 21354-87 via the virtual spur pair (θ_H, θ_F)"))
