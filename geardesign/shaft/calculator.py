"""``kind = "shaft"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

inputs → solve → report: :func:`.inputs.model` reads the spec into the typed inputs (every
input rule; the material and method in :mod:`.material_inputs`), :func:`.solve.analyse`
computes the record, :func:`.report.report` writes the rows, the tables and the checks
(with advice, :mod:`.checks`, :mod:`.scaling`).  The drive calls ``model`` and ``report``
from here for each of its shafts.
"""

from __future__ import annotations

from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec
from geardesign.shaft.inputs import model
from geardesign.shaft.report import report
from geardesign.shaft.solve import solve

__all__ = ["compute", "model", "report"]


def compute(spec: ValidatedSpec) -> Result:
    """The shaft report of a validated spec: inputs, solve, report."""
    m = model(spec)
    return report(spec, m, solve(m))
