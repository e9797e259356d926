"""Shafts: a stepped shaft on two or more bearings as an Euler–Bernoulli finite-element beam
in two planes (reactions, bending moment, shear, torque, deflection and slope, first bending
critical speed), static strength at the peak load and fatigue safety by GOST 25.504-82 as
applied in the Russian machine-design textbooks ([Dunaev]; [Ivanov]).

Modules: :mod:`.beam` (finite elements), :mod:`.strength` (section formulas and factor
tables), :mod:`.solve` (plain-data API: :func:`.solve.analyse`), :mod:`.inputs` (spec ->
plain data, input rules), :mod:`.spec` (the spec schema), :mod:`.calculator` (report rows
and checks).
"""

from __future__ import annotations

from functools import lru_cache


@lru_cache(maxsize=1)
def _calculator():
    # built on first use: a drive that reads the shaft spec (geardesign.shaft.spec) without
    # analysing a shaft does not import numpy
    from geardesign.core.registry import Calculator
    from geardesign.shaft.calculator import compute
    from geardesign.shaft.spec import SCHEMA

    return Calculator(
        kind="shaft",
        summary="stepped shaft: beam model, deflections and bearing slopes, critical speed, "
                "static and fatigue safety per section",
        methods=("Euler–Bernoulli finite elements", "GOST 25.504-82 (Dunaev & Lelikov)"),
        schema=SCHEMA,
        compute=compute,
    )


def __getattr__(name: str):
    if name == "CALCULATOR":
        return _calculator()
    raise AttributeError(name)
