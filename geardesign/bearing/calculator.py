"""``kind = "bearing"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

inputs → solve → report: :mod:`.inputs` reads the spec (catalogue or given ratings, load case
or spectrum, the edition's factors; every input rule, independent problems in one round),
:mod:`.solve` rates the bearing, the catalogue candidates or the pair into a record,
:mod:`.report` turns the record into rows and checks.
"""

from __future__ import annotations

from geardesign.bearing import inputs as I
from geardesign.bearing import life as L
from geardesign.bearing.report import report
from geardesign.bearing.solve import solve
from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec

precheck = I.precheck


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.bearing import CALCULATOR

    inp = I.read(spec)
    try:
        sol = solve(inp)
    except L.BearingError as exc:
        raise I.assessment_error(exc, spec.data) from None
    res = CALCULATOR.new_result(spec)
    report(res, inp, sol, spec.data)
    return res
