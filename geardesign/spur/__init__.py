"""Spur and helical gear pairs, external (GOST 16532-70) and internal (GOST 19274-73);
strength to GOST 21354-87 or ISO 6336:2019.

Modules: :mod:`.geometry` (pure geometry), :mod:`.kinematics` (velocities, sliding),
:mod:`.loads` (forces, cycles), :mod:`.strength` (rating methods), :mod:`.checks`,
:mod:`.design`, :mod:`.spec` (the spec schema), :mod:`.calculator` (spec -> result).
Other calculators reuse :func:`.geometry.pair_geometry` and the strength code; importing
this package does not import the calculator (``CALCULATOR`` is built on first use).
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use: importing one of the package's modules does not
# import the calculation
__getattr__ = lazy_calculator(
    "spur",
    summary="external or internal spur/helical gear pair: geometry, contact ratio, "
    "sliding, measurement, drawing data; strength by GOST 21354-87 or ISO 6336 (with "
    "scuffing); design mode; sweeps (geardesign sweep)",
    methods=("GOST 16532-70", "GOST 13755-81"),
)
