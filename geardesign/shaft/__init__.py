"""Shafts: a stepped shaft on two or more bearings as an Euler–Bernoulli finite-element beam
in two planes (reactions, bending moment, shear, torque, deflection and slope, first bending
critical speed), static strength at the peak load and fatigue safety by GOST 25.504-82 as
applied in the Russian machine-design textbooks ([Dunaev]; [Ivanov]), or by DIN 743
([DIN743-1]; [DIN743-2]; [DIN743-3]; ``[shaft] method = "DIN743"``).

Modules: :mod:`.beam` (finite elements), :mod:`.strength` (section formulas and factor
tables of the GOST method) and :mod:`.section_gost` (a place rated by it), :mod:`.din743`
(the DIN 743 method, one module per part, :mod:`.din743.section` a place rated by it),
:mod:`.records` (the typed inputs and records), :mod:`.solve` (the typed API:
:func:`.solve.solve`, :func:`.solve.analyse`), :mod:`.inputs` and :mod:`.material_inputs`
(spec -> typed inputs, input rules), :mod:`.spec` (the spec schema), :mod:`.report`,
:mod:`.checks` and :mod:`.scaling` (rows, checks, advice), :mod:`.calculator` (joins them).
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use: importing one of the package's modules does not
# import the calculation
__getattr__ = lazy_calculator(
    "shaft",
    summary="stepped shaft: beam model, deflections and bearing slopes, critical speed, "
    "static and fatigue safety per section (GOST 25.504-82 or DIN 743)",
    methods=("Euler–Bernoulli finite elements", "GOST 25.504-82 (Dunaev & Lelikov)"),
)
