"""PZDN — the device reducing start-up dynamic loads of knitting-machine drives: a safety
elastic gear coupling whose elastic element is a cylindrical torsion spring (KO-2 thesis,
[Lopukhov]).

Modules: :mod:`.spring` (torsion spring sizing, methods A and B), :mod:`.startup` (closed
form of the three-mass start-up, corrected), :mod:`.simulate` (its numerical integration
with torque rise, motor characteristic, damping and sticking masses; scipy inside),
:mod:`.regression` (KO-2 regression), :mod:`.coupling` (the coupling gear, rated by the
spur calculator), :mod:`.plot` (optional matplotlib plot), :mod:`.spec`; the calculator:
:mod:`.inputs` (with :mod:`.spring_inputs`, :mod:`.startup_inputs`) → :mod:`.solve` (with
:mod:`.solve_startup`) → :mod:`.report` (with :mod:`.report_spring`,
:mod:`.report_startup`), joined by :mod:`.calculator`.
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use (geardesign.pzdn.calculator.compute and
# geardesign.pzdn.spec.SCHEMA): importing one of the package's modules does not import the
# calculation, and the calculator's modules import the package without a cycle
__getattr__ = lazy_calculator(
    "pzdn",
    summary="PZDN torsion-spring coupling of knitting-machine drives: spring sizing, coupling "
            "gear, three-mass start-up dynamics, KO-2 regression",
    methods=("KO-2 thesis (Lopukhov), corrected", "EN 13906-3", "Shigley §10-12"),
)
