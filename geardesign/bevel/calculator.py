"""``kind = "bevel"``: spec -> inputs -> (design mode: :mod:`.design`) -> solve -> report
(:mod:`.inputs`, :mod:`.solve`, :mod:`.report`)."""

from __future__ import annotations

from geardesign.bevel import inputs, report, solve
from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec


def solution(data: dict):
    """``(proposal, solution)`` of a validated spec's data: the design mode's proposal (None
    without ``[design]``) and the solved pair.  The one path from a spec to a record, for the
    calculator and for a drive's bevel stage."""
    inp = inputs.read(data)
    des = data.get("design")
    proposal = None
    if des is not None:
        from geardesign.bevel.design import propose

        proposal, inp = propose(inp, des["ratio"], des["z1"], des["face_ratio"])
    return proposal, solve.solve(inp)


def compute(spec: ValidatedSpec) -> Result:
    """Rate the bevel pair of a validated spec (propose it first in design mode)."""
    from geardesign.bevel import CALCULATOR

    proposal, sol = solution(spec.data)
    res = CALCULATOR.new_result(spec)
    if proposal is not None:
        report.design_rows(res, proposal, sol)
    return report.report(res, sol, spec.data.get("load"))
