"""Spur and helical gear pairs, external (GOST 16532-70) and internal (GOST 19274-73);
strength to GOST 21354-87 or ISO 6336:2019.

Modules: :mod:`.geometry` (pure geometry), :mod:`.kinematics` (velocities, sliding),
:mod:`.loads` (forces, cycles), :mod:`.strength` (rating methods), :mod:`.checks`,
:mod:`.design`, :mod:`.spec` (the spec schema), :mod:`.calculator` (spec -> result).
Other calculators reuse :func:`.geometry.pair_geometry` and the strength code; importing
this package does not import the calculator (``CALCULATOR`` is built on first use).
"""

from __future__ import annotations

from functools import lru_cache


@lru_cache(maxsize=1)
def _calculator():
    from geardesign.core.registry import Calculator
    from geardesign.spur.calculator import compute
    from geardesign.spur.spec import SCHEMA

    return Calculator(
        kind="spur",
        summary="external or internal spur/helical gear pair: geometry, contact ratio, "
                "sliding, measurement; GOST 21354-87 strength; design mode",
        methods=("GOST 16532-70", "GOST 13755-81"),
        schema=SCHEMA,
        compute=compute,
    )


def __getattr__(name: str):
    if name == "CALCULATOR":
        return _calculator()
    raise AttributeError(name)
