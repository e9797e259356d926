"""``kind = "bevel"``: spec -> inputs -> solve -> report (:mod:`.inputs`, :mod:`.solve`,
:mod:`.report`)."""

from __future__ import annotations

from geardesign.bevel import inputs, report, solve
from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec


def compute(spec: ValidatedSpec) -> Result:
    """Rate the bevel pair of a validated spec."""
    from geardesign.bevel import CALCULATOR

    sol = solve.solve(inputs.read(spec.data))
    return report.report(CALCULATOR.new_result(spec), sol)
