"""Spur and helical external gear pairs: geometry to GOST 16532-70.

Modules: :mod:`.geometry` (pure geometry), :mod:`.kinematics` (velocities, sliding),
:mod:`.checks` (quality checks), :mod:`.spec` (the spec schema), :mod:`.calculator`
(spec -> result).  Other calculators reuse :func:`.geometry.pair_geometry`.
"""

from geardesign.core.registry import Calculator
from geardesign.spur.calculator import compute
from geardesign.spur.spec import SCHEMA

CALCULATOR = Calculator(
    kind="spur",
    summary="external spur/helical gear pair: geometry, contact ratio, sliding, measurement",
    methods=("GOST 16532-70", "GOST 13755-81"),
    schema=SCHEMA,
    compute=compute,
)
