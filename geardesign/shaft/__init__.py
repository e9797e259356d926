"""Shafts: a stepped shaft on two or more bearings as an Euler–Bernoulli finite-element beam
in two planes (reactions, bending moment, shear, torque, deflection and slope, first bending
critical speed), static strength at the peak load and fatigue safety by GOST 25.504-82 as
applied in the Russian machine-design textbooks ([Dunaev]; [Ivanov]), or by DIN 743
([DIN743-1]; [DIN743-2]; [DIN743-3]; ``[shaft] method = "DIN743"``).

Modules: :mod:`.beam` (finite elements), :mod:`.strength` (section formulas and factor
tables of the GOST method), :mod:`.din743` (the DIN 743 method, one module per part), :mod:`.solve` (plain-data API: :func:`.solve.analyse`), :mod:`.inputs` (spec ->
plain data, input rules), :mod:`.spec` (the spec schema), :mod:`.calculator` (report rows
and checks).
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
