"""The result model shared by every calculator, and the JSON document built from it.

A calculator returns a :class:`Result`: the echoed inputs (with assumed defaults marked),
ordered sections of rows (symbol, name, value, unit, source), and checks.  The JSON
document of ``../DESIGN.md`` and all report formats are derived from this one object.
"""

from __future__ import annotations

import copy
import math
import re
from dataclasses import field
from typing import Any

from geardesign import __version__
from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass

SEVERITIES = ("error", "warning", "info")


@dataclass(frozen=True)
class Row:
    """One reported quantity."""

    key: str
    value: Any
    unit: str | None = None
    symbol: str = ""
    name: str = ""
    source: str = ""
    assumed: bool = False


@dataclass
class Section:
    key: str
    title: str
    rows: list[Row] = field(default_factory=list)

    def add(self, key: str, value: Any, unit: str | None = "-", symbol: str = "", name: str = "",
            source: str = "") -> None:
        """Add a row; angles may be given in ``rad`` and are reported in degrees."""
        if unit == "rad":
            if isinstance(value, (list, tuple)):
                value = [math.degrees(v) for v in value]
            elif isinstance(value, (int, float)):
                value = math.degrees(value)
            unit = "deg"
        if isinstance(value, tuple):
            value = list(value)
        if not _is_number(value) and not _is_number_list(value):
            unit = None
        self.rows.append(Row(key, value, unit, symbol or key, name, source))


@dataclass
class DataTable:
    """A table of records (e.g. one row per stage of a drive): ``columns`` are
    ``(key, header, unit)``; each row is a dict by column key.  In JSON it is
    ``results.<key>`` = a list of objects, with units ``results.<key>[].<column>``."""

    key: str
    title: str
    columns: list
    rows: list = field(default_factory=list)


@dataclass(frozen=True)
class Check:
    """A design check.  ``severity`` is ``error`` (fails the design), ``warning`` or
    ``info``; ``message`` says what is wrong and what to change.  ``fix`` is that advice in
    machine-readable form where the calculator found it by re-rating: ``((key, value), ...)``,
    spec keys (``"gear.module"``) and the values that, written into the spec as printed,
    make the check pass on the next run (JSON: ``checks[].fix``, an object).  ``advice``
    is the change in words, as data: the part of a failed check's message that says what to
    change (the builder's message ends with it), so that a calculator composing another's checks
    (the planetary's meshes) states it without editing the message."""

    code: str
    severity: str
    passed: bool
    message: str
    value: float | None = None
    limit: float | None = None
    source: str = ""
    fix: tuple = ()
    advice: str = ""

    def __post_init__(self) -> None:
        if self.severity not in SEVERITIES:
            raise ValueError(f"check {self.code}: severity {self.severity!r}")
        if _NONFINITE.search(self.message):
            object.__setattr__(self, "passed", self.passed and self.severity == "info")
            object.__setattr__(self, "message", not_rated(self.message))


_NONFINITE = re.compile(r"(?<![\w.])([-+−]?)(nan|inf(?:inity)?)(?![\w])", re.IGNORECASE)
"""A number that is not finite, as Python formats it into a message (``nan``, ``-inf``)."""

NOT_RATED = ("not rated: a quantity of this check is not a finite number at these inputs "
             "(outside the domain of its formula), so the check cannot pass; ")
"""How a check message that holds an undefined or unbounded number begins."""


def not_rated(message: str) -> str:
    """A check message whose non-finite numbers are written as words ("undefined",
    "unbounded") after :data:`NOT_RATED`: a check never shows ``nan`` or ``inf``, and one
    that meets such a number fails (an ``info`` check only reports it)."""
    def word(m: re.Match) -> str:
        if m.group(2).lower() == "nan":
            return "undefined"
        return "unbounded (negative)" if m.group(1) in ("-", "−") else "unbounded"

    return NOT_RATED + _NONFINITE.sub(word, message)


def check(code: str, ok: bool, severity: str, fail_message: str, pass_message: str,
          value: float | None = None, limit: float | None = None, source: str = "",
          fix: tuple = (), advice: str = "") -> Check:
    """Build a :class:`Check` from a condition, with one message for each outcome (and the
    machine-readable ``fix`` and the ``advice`` of a failed one: ``fail_message`` then ends
    with ``advice``).  A non-finite value or limit is judged by :func:`guard` when the
    result is finished."""
    if not ok and advice and not fail_message.endswith(advice):
        raise ValueError(f"check {code}: the message does not end with its advice")
    return Check(code, severity, bool(ok), pass_message if ok else fail_message,
                 value, limit, source, () if ok else tuple(fix), "" if ok else advice)


def fix_text(fix) -> str:
    """A machine-readable fix as the message writes it: ``gear.module = 8, gear.x = 0.25``
    (numbers to at most four decimals, as they are to be typed into the spec)."""
    def show(v):
        if isinstance(v, bool):
            return "true" if v else "false"          # as TOML writes it
        if not isinstance(v, float):
            return f'"{v}"' if isinstance(v, str) else str(v)
        return f"{v:.4f}".rstrip("0").rstrip(".")
    return ", ".join(f"{k} = {show(v)}" for k, v in fix)


def clean_value(v: Any) -> Any:
    """JSON has no NaN or infinity: an undefined number is reported as null (``None``),
    in a list too.  The one cleaning step of every value before any renderer sees it."""
    if type(v) is float:              # most values: exact types before any isinstance
        return v if math.isfinite(v) else None
    if type(v) in (str, int) or v is None:
        return v
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, (list, tuple)):
        return [clean_value(x) for x in v]
    return v


_clean = clean_value


def _unclean(v: Any) -> bool:
    """Whether :func:`clean_value` changes ``v`` (a non-finite float, a tuple, or a list
    holding one)."""
    if type(v) in (str, int) or v is None:
        return False
    if isinstance(v, float):
        return not math.isfinite(v)
    if isinstance(v, tuple):
        return True
    return isinstance(v, list) and any(_unclean(x) for x in v)


def cleaned(res: "Result") -> "Result":
    """A copy of ``res`` with every value (rows, inputs, table cells, check values and
    limits, parts) through :func:`clean_value`: what every renderer receives, so that the
    table, Markdown, HTML, CSV and JSON reports show the same document.  Rows and checks
    (frozen) whose values are clean already are shared, not rebuilt; the copy is marked
    so that its :meth:`Result.document` does not clean (copy) every value again."""
    from dataclasses import replace

    def clean_row(r: Row) -> Row:
        return replace(r, value=clean_value(r.value)) if _unclean(r.value) else r

    out = copy.copy(res)
    out.input_rows = [clean_row(r) for r in res.input_rows]
    out.sections = [Section(s.key, s.title, [clean_row(r) for r in s.rows]) for s in res.sections]
    out.tables = [DataTable(t.key, t.title, t.columns,
                            [{k: clean_value(v) for k, v in row.items()} for row in t.rows])
                  for t in res.tables]
    out.checks = [replace(c, value=clean_value(c.value), limit=clean_value(c.limit))
                  if _unclean(c.value) or _unclean(c.limit) else c for c in res.checks]
    out.parts = [(k, title, cleaned(part)) for k, title, part in res.parts]
    out._values_clean = True      # its document() takes the values as they are, no copy
    return out


@dataclass
class Result:
    kind: str
    title: str | None
    methods: list[str]
    inputs: dict
    input_rows: list[Row]
    sections: list[Section] = field(default_factory=list)
    checks: list[Check] = field(default_factory=list)
    source: str = ""
    tables: list[DataTable] = field(default_factory=list)
    undefined: list = field(default_factory=list)
    """Result keys whose value is unbounded (reported as null and "—"); set by :func:`guard`."""
    parts: list = field(default_factory=list)
    """Nested results ``(key, title, Result)``, e.g. the stages of a drive: reported after
    this one, and in JSON under ``results.<key>`` as full documents."""

    def section(self, key: str, title: str) -> Section:
        for s in self.sections:
            if s.key == key:
                return s
        s = Section(key, title)
        self.sections.append(s)
        return s

    @property
    def failed(self) -> list[Check]:
        """Failed error checks.  A result with parts carries a check of its own for each
        failing part (so that the summary names it)."""
        return [c for c in self.checks if not c.passed and c.severity == "error"]

    @property
    def warnings(self) -> list[Check]:
        return [c for c in self.checks if not c.passed and c.severity == "warning"]

    @property
    def verdict(self) -> str:
        return "fail" if self.failed else "pass"

    @property
    def exit_code(self) -> int:
        return 1 if self.failed else 0

    def document(self) -> dict:
        """The JSON result document (``DESIGN.md``, "JSON result document")."""
        _clean = (lambda v: v) if self.__dict__.get("_values_clean") else clean_value
        units: dict[str, str] = {}
        for row in self.input_rows:
            if row.unit is not None and (_is_number(row.value) or _is_number_list(row.value)):
                units["inputs." + row.key] = row.unit
        results: dict[str, dict] = {}
        for sec in self.sections:
            block = results.setdefault(sec.key, {})
            for row in sec.rows:
                block[row.key] = _clean(row.value)
                if row.unit is not None and (_is_number(row.value) or _is_number_list(row.value)):
                    units[f"results.{sec.key}.{row.key}"] = row.unit
        for t in self.tables:
            results[t.key] = [{k: _clean(row.get(k)) for k, _, _ in t.columns} for row in t.rows]
            for k, _, unit in t.columns:
                if unit is not None:
                    units[f"results.{t.key}[].{k}"] = unit
        for key, _, part in self.parts:
            results.setdefault(key, []).append(part.document())
        return {
            "geardesign": __version__,
            "spec": self.source or None,
            "kind": self.kind,
            "title": self.title,
            "methods": list(self.methods),
            "inputs": _drop_none(self.inputs),
            "assumed": [r.key for r in self.input_rows if r.assumed],
            "results": results,
            "units": units,
            "checks": [
                {
                    "code": c.code,
                    "severity": c.severity,
                    "passed": c.passed,
                    "message": c.message,
                    "value": _clean(c.value),
                    "limit": _clean(c.limit),
                    "source": c.source,
                    **({"fix": dict(c.fix)} if c.fix else {}),
                }
                for c in self.checks
            ],
            "verdict": self.verdict,
            **({"undefined": list(self.undefined)} if self.undefined else {}),
        }


class ResultDomainError(InputError):
    """The inputs lead to a value the method cannot give: NaN, a check judged on an
    unbounded number, an impossible negative (a safety factor, a life, a contact ratio)."""


_NONNEG_PREFIXES = ("S_", "L10", "L_", "eps_alpha", "eps_gamma", "life")
"""Result keys that can never be negative: safety factors, lives, contact ratios."""


def _scan(value: Any) -> str | None:
    """``"nan"``, ``"inf"`` or ``None`` for a value or a (nested) list of values."""
    if isinstance(value, float):
        if value != value:
            return "nan"
        if math.isinf(value):
            return "inf"
        return None
    if isinstance(value, (list, tuple)):
        found = None
        for v in value:
            f = _scan(v)
            if f == "nan":
                return f
            found = found or f
        return found
    return None


def _has_negative(value: Any) -> bool:
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return value < 0
    if isinstance(value, (list, tuple)):
        return any(_has_negative(v) for v in value)
    return False


def refuse_negative(key: str, value: Any, what: str, where: str) -> None:
    """:class:`ResultDomainError` at ``where`` if ``key`` is never negative but ``value`` is."""
    if key.startswith(_NONNEG_PREFIXES) and not key.endswith("_min") and _has_negative(value):
        raise _refuse(what, where, "a negative")


def _refuse(what: str, where: str, how: str) -> ResultDomainError:
    return ResultDomainError(Problem(
        "", f"the inputs give {how} {what} ({where}), which the method cannot compute: "
            f"check the input values and their units"))


def guard(res: "Result") -> "Result":
    """The one place where a finished result is checked before anyone sees it.

    * NaN in a check value or limit, or in a row or table cell of a design that passes every
      check, refuses the input (exit 2) naming the quantity; in a design that already fails
      a check (e.g. sliding at a contact point that interference puts inside the base
      circle) the value is reported as undefined, as below;
    * a safety factor, a life or a contact ratio below zero refuses the input likewise;
    * a check whose value or limit is infinite cannot pass: it is refused as above;
    * an infinite row value (a life that is unbounded, an angle at a point that does not
      exist) is reported as undefined: null in JSON, "—" in the report, and its key is
      listed under ``undefined`` in the document, so that it is never silent.
    """
    undefined = []
    failing = bool(res.failed)
    for sec in res.sections:
        for row in sec.rows:
            where = f"results.{sec.key}.{row.key}"
            found = _scan(row.value)
            if found == "nan" and not failing:
                raise _refuse(row.symbol or row.key, where, "an undefined (NaN)")
            if found:
                undefined.append(where)
            refuse_negative(row.key, row.value, row.symbol or row.key, where)
    for t in res.tables:
        for i, row in enumerate(t.rows):
            for k, _, _ in t.columns:
                found = _scan(row.get(k))
                where = f"results.{t.key}[{i}].{k}"
                if found == "nan" and not failing:
                    raise _refuse(k, where, "an undefined (NaN)")
                if found:
                    undefined.append(where)
    for c in res.checks:
        for what in ("value", "limit"):
            found = _scan(getattr(c, what))
            if found == "nan":
                raise _refuse(f"{what} of check {c.code}", "checks", "an undefined (NaN)")
            if found == "inf" and c.passed and c.severity != "info":
                raise _refuse(f"{what} of check {c.code}", "checks",
                              "an unbounded (infinite)")
    res.undefined = undefined
    return res


def _drop_none(d: Any) -> Any:
    """Inputs echo: leave out optional keys that were not given and have no default, and
    tables left empty by that."""
    if isinstance(d, dict):
        out = {k: _drop_none(v) for k, v in d.items() if v is not None}
        return {k: v for k, v in out.items() if v != {}}
    if isinstance(d, list):
        return [_drop_none(v) for v in d]
    return d


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _is_number_list(v: Any) -> bool:
    """A list of numbers (a curve, a time history): its unit applies to every element."""
    return isinstance(v, list) and bool(v) and all(
        _is_number(x) or _is_number_list(x) or x is None for x in v)
