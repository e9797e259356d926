"""``kind = "spur"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

Three steps: :func:`geardesign.spur.inputs.from_spec` reads the typed inputs (every input
rule), :func:`geardesign.spur.solve.solve` computes the record (geometry, kinematics, the
ratings), :func:`geardesign.spur.report.report` writes its rows and checks.  The names
other calculators reuse are re-exported here.
"""

from __future__ import annotations

from geardesign.core.errors import Problems
from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec
from geardesign.spur.inputs import from_spec
from geardesign.spur.report import add_geometry_rows, internal_rows, report
from geardesign.spur.solve import ratable, solve
from geardesign.spur.spec_inputs import (
    _strength_inputs,
    internal_input_from_spec,
    pair_input_from_spec,
    solve_geometry,
)

__all__ = ["compute", "precheck", "advised_report", "add_geometry_rows", "internal_rows", "ratable",
           "pair_input_from_spec", "internal_input_from_spec", "solve_geometry",
           "_strength_inputs"]


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """The checks of :func:`compute` that need no computed geometry, run on a spec whose
    schema problems are already reported (:func:`geardesign.core.registry.load_data`):
    the pair's own rules and the strength inputs, each left out when it reads a wrong key."""
    d = spec.data
    if (d["design"] is None) == (d["gear"] is None):
        return   # both or neither: the schema's problem says to give one
    from geardesign.spur.strength.iso6336.spec import unused_tables

    problems.stage(unused_tables, spec)
    if d["gear"] is not None:
        problems.stage(solve_geometry, spec)
    problems.stage(_strength_inputs, spec, d["gear"] if d["gear"] is not None else d["design"])


def compute(spec: ValidatedSpec) -> Result:
    """The spur report of a validated spec: inputs, solve, report."""
    return report(solve(from_spec(spec)))


def advised_report(record) -> Result:
    """The spur calculator's result of a solved pair, as a run of its spec gives it: the
    report (:func:`geardesign.spur.report.report`), the result guard, and the advice of the
    failed checks found by re-rating (:func:`geardesign.core.advice.advise` with the spur
    levers; left out while a re-rating reads verdicts only).  ``record.inputs.spec`` must be
    set.  Other calculators that nest a spur report (the pzdn coupling gear) call this."""
    from geardesign.core.errors import InputError
    from geardesign.core.registry import _say_default
    from geardesign.core.result import guard

    spec = record.inputs.spec
    try:
        res = guard(report(record))
    except InputError as exc:
        raise InputError([_say_default(p, spec) for p in exc.problems]) from exc
    if not res.failed:
        return res
    from geardesign.core.rerating import rerating

    if not rerating():
        from geardesign.core.advice import advise
        from geardesign.spur import CALCULATOR
        from geardesign.spur.levers import LEVERS

        res = advise(CALCULATOR, spec, res, LEVERS)
    return res
