"""``kind = "pzdn"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

The spec's tables select what is computed (several may be combined in one spec):
``[[spring]]`` (with ``[motor]`` for the wind-up of method A) sizes the torsion springs;
``[coupling_gear]`` rates the coupling's spur gear with the spur calculator; ``[startup]``
runs the three-mass start-up (closed form and/or numerical integration, a comparison with
the drive without the PZDN and a stiffness sweep); ``[regression]`` evaluates the KO-2
regression.  :mod:`.inputs` reads the spec into typed inputs (every input rule, all
independent problems in one round, before the result is created, so that the echoed inputs
carry the defaults actually used), :mod:`.solve` computes the typed record (pure),
:mod:`.report` turns it into rows and checks; the plot is written last.
"""

from __future__ import annotations

from geardesign.core.errors import Problems
from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec
from geardesign.pzdn import inputs as I
from geardesign.pzdn.report import report
from geardesign.pzdn.solve import solve


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """The input rules on a spec whose schema problems are reported (one round)."""
    I.precheck(spec, problems)


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.pzdn import CALCULATOR

    inp = I.read(spec)
    sol = solve(inp)
    res = report(CALCULATOR.new_result(spec), inp, sol, CALCULATOR.methods)
    if inp.startup is not None and inp.startup.plot is not None:
        from geardesign.pzdn.report_startup import write_plot

        write_plot(res, spec, inp.startup.plot)
    return res
