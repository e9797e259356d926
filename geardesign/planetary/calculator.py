"""``kind = "planetary"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

inputs → solve → report: :mod:`.inputs` reads the spec (every input rule, independent
problems in one round; :mod:`.train`, :mod:`.shifts`), :mod:`.solve` computes the train into
one record, :mod:`.report` turns the record into rows and checks; the failed geometry checks
get one reconciled change, found by re-rating (:mod:`.advice`).
"""

from __future__ import annotations

from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.planetary import inputs as I
from geardesign.planetary import report as R
from geardesign.planetary import sources as S
from geardesign.planetary.solve import solve

precheck = I.precheck


def compute(spec: ValidatedSpec) -> Result:
    inp = I.read(spec)
    return result(spec, inp, solve(inp))


def result(spec: ValidatedSpec, inp: I.Inputs, sol) -> Result:
    """The report of a solved train (``sol`` from :func:`~geardesign.planetary.solve.solve`):
    rows, checks, the reconciled advice of the failed geometry checks."""
    from geardesign.planetary import CALCULATOR

    res = CALCULATOR.new_result(spec)
    R.geometry_rows(res, inp, sol)
    meshes = list(inp.meshes)
    checks = R.geometry_checks(res, spec.data, inp.train, meshes, inp.lay, dict(inp.shifts),
                               dict(inp.conv), sol.gears, sol.assembly)
    if spec.data["synthesis"] is None:
        from geardesign.planetary.advice import reconcile

        checks = reconcile(spec, meshes, checks, rerate)
    if inp.lay.cutter is None:
        checks.append(check("RING_FORM_CIRCLE", True, "info", "",
                            "the rings' form circles are those of the basic rack; give [cutter] "
                            "for a shaper-cut ring (a smaller form circle) and the cutting "
                            "interference check", None, None, S.G19274))
    checks += R.operation_report(res, inp, sol)
    res.checks.extend(checks)
    return res


def rerate(spec: ValidatedSpec) -> list:
    """The checks of a candidate train (the advice by re-rating): its typed inputs
    (:func:`~geardesign.planetary.inputs.read`) solved once and reported."""
    inp = I.read(spec)
    return result(spec, inp, solve(inp)).checks
