"""``kind = "epicycle_rim"``: from a validated spec to a
:class:`~geardesign.core.result.Result`: :mod:`.inputs` (typed inputs, every input rule),
:mod:`.solve` (the pure calculation, a typed record), :mod:`.report` (rows and checks).
"""

from __future__ import annotations

from geardesign.core.errors import Problems
from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec
from geardesign.epicycle_rim import inputs as I
from geardesign.epicycle_rim.report import report
from geardesign.epicycle_rim.solve import solve


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """The input rules on a spec whose schema problems are reported (one round)."""
    I.precheck(spec, problems)


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.epicycle_rim import CALCULATOR

    inp = I.read(spec)
    sol = solve(inp)
    rz = spec.data.get("resonance")
    if sol.resonance is not None and rz["chart_b_max"] is None:
        # the chart's default extent follows from the instability regions found
        rz["chart_b_max"] = sol.resonance.chart_b_max
        spec.assumed.append("resonance.chart_b_max")
    return report(CALCULATOR.new_result(spec), inp, sol)
