"""Spur and helical gear pairs, external (GOST 16532-70) and internal (GOST 19274-73);
strength to GOST 21354-87 or ISO 6336:2019.

Modules: the pair geometry is shared gear code (:mod:`geardesign.gears.geometry`,
:mod:`geardesign.gears.internal`); here :mod:`.kinematics` (velocities, sliding),
:mod:`.loads` (forces, cycles), :mod:`.strength` (rating methods), :mod:`.checks`,
:mod:`.design`, :mod:`.spec` (the spec schema), :mod:`.inputs` (typed inputs),
:mod:`.solve` (inputs -> record), :mod:`.report` (record -> result), :mod:`.calculator`
(spec -> result).  The Python API (docs/api.md)::

    from geardesign import spur
    record = spur.solve(spur.Inputs(spur.PairInput(...)))
    result = spur.report(record)

Other calculators reuse :func:`geardesign.gears.geometry.pair_geometry` and the strength
code; importing this package imports neither the calculator nor the API's modules (each on
first use).
"""

from __future__ import annotations

import importlib

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use: importing one of the package's modules does not
# import the calculation
_calculator = lazy_calculator(
    "spur",
    summary="external or internal spur/helical gear pair: geometry, contact ratio, "
    "sliding, measurement, drawing data; strength by GOST 21354-87 or ISO 6336 (with "
    "scuffing); design mode; sweeps (geardesign sweep)",
    methods=("GOST 16532-70", "GOST 13755-81"),
)

_API = {"Inputs": "spur.inputs", "Strength": "spur.inputs", "from_spec": "spur.inputs",
        "from_tables": "spur.inputs", "Record": "spur.solve", "PairInput": "gears.geometry",
        "BasicRack": "gears.geometry", "InternalPairInput": "gears.internal"}
"""Names of the Python API, from the module that defines them (imported on first use)."""


def __getattr__(name: str):
    if name in _API:
        return getattr(importlib.import_module(f"geardesign.{_API[name]}"), name)
    if name in ("solve", "report", "inputs"):
        return importlib.import_module(f"geardesign.spur.{name}")
    return _calculator(name)
