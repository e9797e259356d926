"""Rolling-bearing life to GOST 18855-94 (a1·a23) or ISO 281:2007 = GOST 18855-2013 (a_ISO).

Modules: :mod:`.tables` (coefficient tables, data), :mod:`.life` (pure formulas),
:mod:`.assess` (one bearing under a load case or spectrum), :mod:`.catalogue` (built-in
catalogue, ``catalogue.toml``), :mod:`.spec` (the spec schema), :mod:`.inputs` (spec ->
typed inputs; :mod:`.resolve`, :mod:`.conditions`), :mod:`.solve` (inputs -> records,
including the catalogue selection of ``mode = "select"``), :mod:`.report` and
:mod:`.checks` (records -> rows and checks), :mod:`.calculator`.
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use (geardesign.bearing.calculator.compute and
# geardesign.bearing.spec.SCHEMA): importing one of the package's modules does not import the
# calculation, and the calculator's modules import the package without a cycle
__getattr__ = lazy_calculator(
    "bearing",
    summary="rolling-bearing life: equivalent load, L10, a1·a23 or a1·a_ISO, spectra, static "
            "safety, catalogue selection",
    methods=("GOST 18855-94", "ISO 281:2007 (GOST 18855-2013)", "ISO 76"),
)
