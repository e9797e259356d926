"""``kind = "novikov"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

inputs → solve → report: :mod:`.inputs` reads the spec (every input rule, every independent
problem in one round), :mod:`.solve` computes the pair into one record, :mod:`.report`
turns the record into rows and checks.
"""

from __future__ import annotations

from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec
from geardesign.novikov import inputs as I
from geardesign.novikov.report import report
from geardesign.novikov.solve import solve

precheck = I.precheck


def compute(spec: ValidatedSpec) -> Result:
    inp = I.read(spec)
    return result(spec, inp, solve(inp))


def result(spec: ValidatedSpec, inp: I.Inputs, sol) -> Result:
    """The report of a solved pair (``sol`` from :func:`~geardesign.novikov.solve.solve`)."""
    from geardesign.novikov import CALCULATOR

    res = CALCULATOR.new_result(spec)
    report(res, inp, sol, spec.data["load"])
    return res
