"""Rolling-bearing life to GOST 18855-94 (a1·a23) or ISO 281:2007 = GOST 18855-2013 (a_ISO).

Modules: :mod:`.tables` (coefficient tables, data), :mod:`.life` (pure formulas),
:mod:`.assess` (one bearing under a load case or spectrum), :mod:`.catalogue` (built-in
catalogue, ``catalogue.toml``), :mod:`.spec` (the spec schema), :mod:`.inputs` (spec ->
typed inputs; :mod:`.resolve`, :mod:`.conditions`), :mod:`.solve` (inputs -> records,
including the catalogue selection of ``mode = "select"``), :mod:`.report` and
:mod:`.checks` (records -> rows and checks), :mod:`.calculator`.
"""

from geardesign.bearing.calculator import compute, precheck
from geardesign.bearing.spec import SCHEMA
from geardesign.core.registry import Calculator

CALCULATOR = Calculator(
    kind="bearing",
    summary="rolling-bearing life: equivalent load, L10, a1·a23 or a1·a_ISO, spectra, static "
            "safety, catalogue selection",
    methods=("GOST 18855-94", "ISO 281:2007 (GOST 18855-2013)", "ISO 76"),
    schema=SCHEMA,
    compute=compute,
    precheck=precheck,
)
