"""``kind = "worm"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

inputs → solve → report: :mod:`.inputs` reads the spec (every rule across keys, independent
problems in one round), :mod:`.solve` computes the pair into one record, :mod:`.report`
turns the record into rows and checks (with the advice of a standard pair).
"""

from __future__ import annotations

from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec
from geardesign.worm import inputs as I
from geardesign.worm.report import report
from geardesign.worm.solve import solve


def compute(spec: ValidatedSpec) -> Result:
    return result(spec, solve(I.read(spec)))


def result(spec: ValidatedSpec, rec) -> Result:
    """The report of a solved pair (``rec`` from :func:`~geardesign.worm.solve.solve`)."""
    from geardesign.worm import CALCULATOR

    res = CALCULATOR.new_result(spec)
    report(res, rec, spec)
    return res
