"""The Python API of geardesign (docs/api.md): read a spec into a calculator's typed
inputs, solve them into a record, write the record's report, and turn records into rows.

    import geardesign
    inputs = geardesign.load("specs/spur_reducer_through_hardened.toml")
    record = geardesign.solve(inputs)          # geardesign.spur.solve(inputs) alike
    result = geardesign.report(record)         # the report the command line prints
    rows = geardesign.rows([record])           # flat dicts, e.g. for pandas.DataFrame

A calculator with typed inputs has ``geardesign.<kind>.inputs.from_spec``; for the others
:func:`load` returns the validated spec, which :func:`report` computes as the command line
does.
"""

from __future__ import annotations

import importlib
from pathlib import Path


def _kind_of(obj) -> str | None:
    """The calculator kind of a typed inputs or record object (``geardesign.<kind>.…``)."""
    parts = type(obj).__module__.split(".")
    return parts[1] if len(parts) > 2 and parts[0] == "geardesign" else None


def _from_spec(kind: str):
    try:
        mod = importlib.import_module(f"geardesign.{kind}.inputs")
    except ImportError:
        return None
    return getattr(mod, "from_spec", None)


def load(path, kind: str | None = None):
    """Read and validate the spec file ``path``; its calculator's typed inputs (e.g.
    :class:`geardesign.spur.inputs.Inputs`), or the validated spec
    (:class:`geardesign.core.spec.ValidatedSpec`) for a calculator without them.
    ``kind`` refuses a spec of another calculator.  Raises
    :class:`geardesign.core.errors.InputError` naming file, key, value and what is
    allowed."""
    from geardesign.core.registry import load as load_spec

    calc, spec = load_spec(Path(path), expect_kind=kind)
    from_spec = _from_spec(calc.kind)
    return spec if from_spec is None else from_spec(spec)


def solve(inputs):
    """The record of typed inputs, by their calculator's ``solve`` (e.g.
    :func:`geardesign.spur.solve.solve`)."""
    kind = _kind_of(inputs)
    if kind is None or _from_spec(kind) is None:
        raise TypeError(f"not the typed inputs of a calculator: {type(inputs).__name__} "
                        "(read a spec with geardesign.load)")
    mod = importlib.import_module(f"geardesign.{kind}.solve")
    return mod.solve(inputs)


def report(obj, advice: bool = True):
    """The :class:`~geardesign.core.result.Result` (rows, checks, verdict) of a record, of
    typed inputs (solved first) or of a validated spec, as the command line gives it:
    the result guard, and with ``advice`` the fixes of the failed checks found by
    re-rating (for a record whose inputs were read from a spec)."""
    from geardesign.core.registry import get
    from geardesign.core.result import guard
    from geardesign.core.spec import ValidatedSpec

    if isinstance(obj, ValidatedSpec):
        calc = get(obj.data["kind"])
        return calc.compute(obj) if advice else calc.rate(obj)
    kind = _kind_of(obj)
    if kind is not None and type(obj).__module__.endswith(".inputs"):
        obj = solve(obj)
    if kind is None:
        raise TypeError(f"not a record of a calculator: {type(obj).__name__}")
    mod = importlib.import_module(f"geardesign.{kind}.report")
    res = guard(mod.report(obj))
    spec = getattr(obj.inputs, "spec", None)
    if advice and spec is not None and res.failed:
        from geardesign.core.advice import advise

        try:
            levers = importlib.import_module(f"geardesign.{kind}.levers").LEVERS
        except ImportError:
            return res
        res = advise(get(kind), spec, res, levers)
    return res


def rows(records) -> list[dict]:
    """One flat dict per record (its ``flat()``: inputs, geometry, every rating's values
    prefixed by method), JSON-safe: ``pandas.DataFrame(geardesign.rows(records))`` is a
    table of the variants (pandas is not needed here)."""
    return [r.flat() for r in records]


def asdict(record) -> dict:
    """A record as plain, JSON-safe data (its ``asdict()``)."""
    return record.asdict()
