"""The calculators, by ``kind``, and running a spec file through one of them.

Adding a calculator: write a package ``geardesign/<kind>/`` whose ``__init__`` exposes
``CALCULATOR = Calculator(...)`` with ``kind`` equal to the package name.  Calculators are
found by their package: :data:`KINDS` lists the subpackages of ``geardesign`` (all but
:data:`NOT_CALCULATORS`) without importing them, so running one spec imports only its own
calculator.
"""

from __future__ import annotations

import importlib
import importlib.util
from pathlib import Path
from typing import Callable

from geardesign.core.errors import InputError, Problem, Problems, Unusable
from geardesign.core.records import dataclass
from geardesign.core.result import Result, Row, guard
from geardesign.core.kinds import (CATALOG, KINDS, NOT_CALCULATORS, ORDER,  # noqa: F401 (API)
                                   catalog, get, known_kinds)
from geardesign.core.spec import (SpecSchema, ValidatedSpec, iter_fields, load_toml,
                                  validate_partial)

@dataclass(frozen=True)
class Calculator:
    """A calculator: its spec schema and a pure ``compute(spec) -> Result``.  ``compute``
    gives the failed checks their fixes, found by re-rating (:mod:`geardesign.core.advice`);
    ``rate`` is the same rating without that search (a verdict only, e.g. a sweep's)."""

    kind: str
    summary: str
    methods: tuple[str, ...]
    schema: SpecSchema
    compute: Callable[[ValidatedSpec], Result]
    precheck: Callable[[ValidatedSpec, Problems], None] | None = None
    """The calculator's own input checks (rules of several keys, keys required by a
    mode), run on a partially validated spec when the schema already found problems, so
    that one run reports every problem (:func:`load_data`); ``None``: the schema's
    problems alone."""

    def __post_init__(self) -> None:
        # every result passes the one guard of :mod:`geardesign.core.result` (no NaN, no
        # check judged on infinity, no negative safety factor), whoever computes it
        compute = self.compute

        def guarded(spec: ValidatedSpec) -> Result:
            try:
                return guard(compute(spec))
            except InputError as exc:
                raise InputError([_say_default(p, spec) for p in exc.problems]) from exc

        kind = self.kind

        def advised(spec: ValidatedSpec) -> Result:
            # a failed check whose advice names a spec change carries it, found by
            # re-rating (geardesign.core.advice; the kind's levers, if it has any)
            res = guarded(spec)
            if not res.failed or importlib.util.find_spec(f"geardesign.{kind}.levers") is None:
                return res
            from geardesign.core.advice import advise

            levers = importlib.import_module(f"geardesign.{kind}.levers").LEVERS
            return advise(self, spec, res, levers)

        guarded.__doc__ = advised.__doc__ = compute.__doc__
        object.__setattr__(self, "rate", guarded)
        object.__setattr__(self, "compute", advised)

    def new_result(self, spec: ValidatedSpec) -> Result:
        """An empty result that echoes the inputs (assumed defaults marked)."""
        assumed = set(spec.assumed)
        rows = [
            Row(key, value, field.unit if field.numeric else None, _symbol(key, field.symbol),
                field.description, "", key in assumed)
            for key, field, value in iter_fields(self.schema.root, spec.data)
            if key != "kind"
        ]
        return Result(self.kind, spec.data.get("title"), list(self.methods), spec.data, rows,
                      source=spec.source)


DEFAULT_NOTE = "the default (not in the spec): "
"""How a problem about a value the user did not write, the schema's default or one
the calculator assumed (``spec.assumed``), begins: the user then knows to give it."""


def _say_default(p: Problem, spec: ValidatedSpec) -> Problem:
    if p.key in spec.assumed and "default" not in p.message:
        return Problem(p.key, DEFAULT_NOTE + p.message, p.value)
    return p


def _symbol(key: str, symbol: str) -> str:
    """The report symbol of an input: its own, prefixed by the item of an array of tables
    it belongs to (``stage[1].name``) or by the sub-table that holds it (``pinion.HB``)."""
    head, _, last = key.rpartition(".")
    symbol = symbol or last
    if "[" in head:
        return f"{head}.{symbol}"
    parent = head.rpartition(".")[2]
    # a key of a sub-table that repeats (material.pinion / material.wheel): name the member
    return f"{parent}.{symbol}" if head.count(".") >= 1 else symbol


def lazy_calculator(kind: str, summary: str, methods: tuple[str, ...]):
    """A package's module ``__getattr__`` that builds its ``CALCULATOR`` on first use from
    ``geardesign.<kind>.calculator.compute`` and ``geardesign.<kind>.spec.SCHEMA``: importing
    the package (e.g. for one of its modules) does not import the calculation."""
    from functools import lru_cache

    @lru_cache(maxsize=1)
    def build() -> Calculator:
        module = importlib.import_module(f"geardesign.{kind}.calculator")
        schema = importlib.import_module(f"geardesign.{kind}.spec").SCHEMA
        return Calculator(kind=kind, summary=summary, methods=methods, schema=schema,
                          compute=module.compute, precheck=getattr(module, "precheck", None))

    def __getattr__(name: str):
        if name == "CALCULATOR":
            return build()
        raise AttributeError(name)

    return __getattr__


def all_calculators() -> list[Calculator]:
    return [get(k) for k in KINDS]


def write_catalog() -> None:
    """Rewrite :data:`CATALOG` from the calculators themselves."""
    import json

    rows = [[c.kind, c.summary, list(c.methods)] for c in all_calculators()]
    CATALOG.write_text(json.dumps(rows, indent=1, ensure_ascii=False) + "\n", "utf-8")


def _kind_problem(value: object) -> Problem:
    known = ", ".join(f'"{k}"' for k in KINDS)
    if isinstance(value, str):
        import difflib  # only to name a close match

        close = difflib.get_close_matches(value, list(KINDS), 1, 0.6)
        hint = f' (did you mean "{close[0]}"?)' if close else ""
        return Problem("kind", f"unknown calculator{hint}; known: {known}", value)
    return Problem("kind", f"must be one of {known}", value)


def load(path: Path, expect_kind: str | None = None,
         data: dict | None = None) -> tuple[Calculator, ValidatedSpec]:
    """Read and validate a spec file (``data``: its content already parsed); raise
    :class:`InputError` with every problem."""
    calc, spec = load_data(load_toml(path) if data is None else data, str(path), expect_kind)
    spec.base_dir = Path(path).resolve().parent
    return calc, spec


def load_data(data: dict, source: str = "",
              expect_kind: str | None = None) -> tuple[Calculator, ValidatedSpec]:
    """Validate an already parsed spec (a dict as from TOML)."""
    if "kind" not in data:
        known = ", ".join(f'"{k}"' for k in KINDS)
        raise InputError(Problem("kind", f"missing; required: one of {known} (the calculator)"))
    kind = data["kind"]
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError(_kind_problem(kind))
    if expect_kind is not None and kind != expect_kind:
        raise InputError(Problem(
            "kind", f'this is a {kind} spec; use "geardesign {kind}" or "geardesign run"', kind))
    if "sweep" in data:
        raise InputError(Problem("sweep", "this spec describes a design sweep: run it with "
                                 "`geardesign sweep SPEC.toml` (or remove [sweep])"))
    calc = get(kind)
    spec, found = validate_partial(calc.schema, data, source=source)
    if found:
        problems = Problems(found)
        problems.stage(_precheck, calc, spec, problems)
        problems.raise_all()
    return calc, spec


def _precheck(calc: Calculator, spec: ValidatedSpec, problems: Problems) -> None:
    """The calculator's own input checks on a spec whose schema problems are reported:
    its ``precheck`` when it has one, else its rating without the advice search
    (``rate``), whose input reading reports every problem it finds at once
    (:class:`~geardesign.core.errors.Problems`) and stops there.  The wrong keys hold :data:`~geardesign.core.errors.REPORTED`, so a check
    that needs one is left out; a calculation that trips over one in another way is left
    out too (the problems already found are the answer, never an internal error)."""
    try:
        if calc.precheck is not None:
            calc.precheck(spec, problems)
        else:
            calc.rate(spec)
    except (InputError, Unusable):
        raise
    except Exception:   # noqa: BLE001 - a partial spec: see the docstring
        pass


def run(path: Path, expect_kind: str | None = None) -> Result:
    """Compute a spec file."""
    calc, spec = load(path, expect_kind)
    return calc.compute(spec)


def run_data(data: dict, source: str = "") -> Result:
    """Compute a spec given as a dict (library use and tests)."""
    calc, spec = load_data(data, source)
    return calc.compute(spec)


if __name__ == "__main__":
    write_catalog()
