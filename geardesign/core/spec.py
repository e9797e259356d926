"""Spec files: one declarative schema per calculator, used for everything.

A calculator describes its TOML spec once, as nested :class:`Table` objects holding
:class:`Field` objects (type, unit, range, default, description).  From that single
definition this module

* validates a parsed spec, collecting every problem as one line (unknown keys with a
  "did you mean", missing keys, wrong types, out-of-range values),
* fills in defaults and records which values were assumed,
* prints the JSON Schema (``geardesign schema KIND``), and
* prints the commented template (``geardesign template KIND``).

There is no second, hand-kept copy of the rules anywhere.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator

from geardesign.core.errors import InputError, Problem, format_value


class _Required:
    def __repr__(self) -> str:  # pragma: no cover - debugging aid
        return "REQUIRED"


REQUIRED: Any = _Required()
"""Marks a field without a default: the spec must give it."""

_TYPES = ("number", "integer", "string", "boolean")


@dataclass(frozen=True)
class Field:
    """One key of a spec table.

    Parameters
    ----------
    key : TOML key.
    type : ``"number"`` (int or float accepted), ``"integer"``, ``"string"`` or ``"boolean"``.
    description : what the value means, in a few words (shown in reports and templates).
    unit : unit of a numeric value (``"mm"``, ``"deg"``, ``"-"`` for dimensionless).
    symbol : the standard's symbol, e.g. ``"m_n"``.
    default : value assumed when the key is absent; ``REQUIRED`` if the key must be given;
        ``None`` for an optional key without a default.
    minimum, maximum : inclusive bounds; ``gt``, ``lt`` : exclusive bounds.
    choices : allowed values of a string (or number) field.
    example : value written in the template (defaults to ``default``).
    hint : extra sentence for the template and the schema.
    """

    key: str
    type: str
    description: str
    unit: str | None = None
    symbol: str = ""
    default: Any = REQUIRED
    minimum: float | None = None
    maximum: float | None = None
    gt: float | None = None
    lt: float | None = None
    choices: tuple | None = None
    example: Any = None
    hint: str = ""

    def __post_init__(self) -> None:
        if self.type not in _TYPES:
            raise ValueError(f"field {self.key}: unknown type {self.type!r}")
        if self.type in ("number", "integer") and self.unit is None:
            object.__setattr__(self, "unit", "-")

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    def rule(self) -> str:
        """The allowed values in words: ``an integer >= 5``, ``a number > 0``, ..."""
        if self.choices is not None:
            return "one of " + ", ".join(format_value(c) for c in self.choices)
        noun = {
            "number": "a number",
            "integer": "an integer",
            "string": "a string",
            "boolean": "true or false",
        }[self.type]
        bounds = []
        if self.minimum is not None:
            bounds.append(f">= {_num(self.minimum)}")
        if self.gt is not None:
            bounds.append(f"> {_num(self.gt)}")
        if self.maximum is not None:
            bounds.append(f"<= {_num(self.maximum)}")
        if self.lt is not None:
            bounds.append(f"< {_num(self.lt)}")
        if bounds:
            noun += " " + " and ".join(bounds)
        if self.unit not in (None, "-") and self.type in ("number", "integer"):
            noun += f" ({self.unit})"
        return noun

    def check(self, value: Any) -> tuple[Any, str | None]:
        """Return ``(normalised value, None)`` or ``(None, message)``."""
        bad = f"must be {self.rule()}"
        if self.type == "boolean":
            return (value, None) if isinstance(value, bool) else (None, bad)
        if self.type == "string":
            if not isinstance(value, str):
                return None, bad
        elif self.type == "integer":
            if isinstance(value, bool) or not isinstance(value, int):
                return None, bad
        else:  # number
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                return None, bad
            if not math.isfinite(value):
                return None, bad
            value = float(value)
        if self.choices is not None and value not in self.choices:
            close = difflib.get_close_matches(str(value), [str(c) for c in self.choices], 1, 0.6)
            return None, bad + (f' (did you mean "{close[0]}"?)' if close else "")
        if self.type in ("number", "integer"):
            if self.minimum is not None and value < self.minimum:
                return None, bad
            if self.maximum is not None and value > self.maximum:
                return None, bad
            if self.gt is not None and value <= self.gt:
                return None, bad
            if self.lt is not None and value >= self.lt:
                return None, bad
        return value, None


@dataclass(frozen=True)
class Table:
    """A TOML table (``[gear]``) of fields and sub-tables.

    An optional table (``required=False``) may be left out of a spec altogether; the
    calculator then receives ``None`` for it.  An ``implicit`` table may be left out too,
    but then it is read as an empty table: all its fields take their defaults (and are
    echoed as assumed).
    """

    key: str
    description: str
    fields: tuple = ()
    required: bool = True
    hint: str = ""
    implicit: bool = False

    def member(self, key: str) -> "Field | Table | None":
        for f in self.fields:
            if f.key == key:
                return f
        return None


@dataclass(frozen=True)
class SpecSchema:
    """The whole spec of one calculator: ``kind``, optional ``title``, then tables."""

    kind: str
    description: str
    tables: tuple
    title_example: str = ""

    @property
    def root(self) -> Table:
        return Table(
            "",
            self.description,
            (
                Field("kind", "string", "calculator", choices=(self.kind,), example=self.kind),
                Field("title", "string", "title of the design, shown in the report", default=None,
                      example=self.title_example or None),
            )
            + tuple(self.tables),
        )


@dataclass
class ValidatedSpec:
    """A spec after validation: values with defaults filled in, and what was assumed."""

    data: dict
    assumed: list = field(default_factory=list)
    source: str = ""
    base_dir: Path | None = None


def _num(x: float) -> str:
    return str(int(x)) if float(x).is_integer() else repr(float(x))


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def _validate_table(table: Table, data: Any, path: str, problems: list, assumed: list) -> dict:
    out: dict = {}
    known = [m.key for m in table.fields]
    for key, value in data.items():
        if key not in known:
            close = difflib.get_close_matches(key, known, 1, 0.6) or [
                k for k in known if k.lower() == key.lower()
            ]
            where = f"[{path}]" if path else "the top level"
            if close:
                msg = f'unknown key in {where} (did you mean "{close[0]}"?)'
            else:
                msg = f"unknown key in {where}; allowed: " + ", ".join(known)
            problems.append(Problem(_join(path, key), msg, value))
    for member in table.fields:
        key = _join(path, member.key)
        if isinstance(member, Table):
            if member.key not in data and not member.implicit:
                if member.required:
                    problems.append(Problem(key, f"missing table [{key}] ({member.description})"))
                else:
                    out[member.key] = None
                continue
            value = data.get(member.key, {})
            if not isinstance(value, dict):
                problems.append(Problem(key, f"must be a table [{key}] ({member.description})", value))
                continue
            out[member.key] = _validate_table(member, value, key, problems, assumed)
            continue
        if member.key not in data:
            if member.required:
                problems.append(
                    Problem(key, f"missing; required: {member.rule()} ({member.description})")
                )
            else:
                out[member.key] = member.default
                if member.default is not None:
                    assumed.append(key)
            continue
        value, message = member.check(data[member.key])
        if message:
            problems.append(Problem(key, message, data[member.key]))
        else:
            out[member.key] = value
    return out


def validate(schema: SpecSchema, data: dict, source: str = "") -> ValidatedSpec:
    """Check ``data`` against ``schema``; raise :class:`InputError` with every problem."""
    problems: list[Problem] = []
    assumed: list[str] = []
    out = _validate_table(schema.root, data, "", problems, assumed)
    if problems:
        raise InputError(problems)
    return ValidatedSpec(out, assumed, source)


def load_toml(path: Path) -> dict:
    """Read a TOML spec file; problems become one-line :class:`InputError` messages."""
    try:
        import tomllib
    except ModuleNotFoundError:  # pragma: no cover - Python < 3.11
        import tomli as tomllib  # type: ignore[no-redef]
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        raise InputError(Problem("", "file not found")) from None
    except IsADirectoryError:
        raise InputError(Problem("", "is a directory, not a spec file")) from None
    except OSError as exc:
        raise InputError(Problem("", f"cannot be read ({exc.strerror})")) from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(Problem("", f"not UTF-8 text (byte {exc.start})")) from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(Problem("", f"not valid TOML: {exc}")) from None


# --------------------------------------------------------------------------- walking


def iter_fields(table: Table, data: dict | None, path: str = "") -> Iterator[tuple[str, Field, Any]]:
    """Yield ``(key path, field, value)`` for every field present in validated ``data``."""
    if data is None:
        return
    for member in table.fields:
        key = _join(path, member.key)
        if isinstance(member, Table):
            yield from iter_fields(member, data.get(member.key), key)
        elif data.get(member.key) is not None:
            yield key, member, data[member.key]


# --------------------------------------------------------------------------- JSON Schema


def _field_schema(f: Field) -> dict:
    js: dict = {}
    if f.type == "number":
        js["type"] = "number"
    elif f.type == "integer":
        js["type"] = "integer"
    elif f.type == "string":
        js["type"] = "string"
    else:
        js["type"] = "boolean"
    desc = f.description
    if f.symbol:
        desc = f"{f.symbol}: {desc}"
    if f.unit and f.type in ("number", "integer"):
        desc += f" [{f.unit}]"
    if f.hint:
        desc += f". {f.hint}"
    js["description"] = desc
    if f.unit and f.type in ("number", "integer"):
        js["x-unit"] = f.unit
    if f.choices is not None:
        js["enum"] = list(f.choices)
    if f.minimum is not None:
        js["minimum"] = f.minimum
    if f.maximum is not None:
        js["maximum"] = f.maximum
    if f.gt is not None:
        js["exclusiveMinimum"] = f.gt
    if f.lt is not None:
        js["exclusiveMaximum"] = f.lt
    if not f.required and f.default is not None:
        js["default"] = f.default
    return js


def _table_schema(t: Table) -> dict:
    props = {}
    required = []
    for m in t.fields:
        props[m.key] = _table_schema(m) if isinstance(m, Table) else _field_schema(m)
        if (isinstance(m, Table) and m.required and not m.implicit) or (
                isinstance(m, Field) and m.required):
            required.append(m.key)
    js = {"type": "object", "description": t.description + (f". {t.hint}" if t.hint else "")}
    js["properties"] = props
    if required:
        js["required"] = required
    js["additionalProperties"] = False
    return js


def json_schema(schema: SpecSchema) -> dict:
    """JSON Schema (draft 2020-12) of a calculator's spec, built from the same definitions
    that :func:`validate` uses; units are in each description and in ``x-unit``."""
    js = _table_schema(schema.root)
    js = {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": f"geardesign {schema.kind} spec",
        **js,
    }
    js["properties"]["kind"]["const"] = schema.kind
    return js


# --------------------------------------------------------------------------- template


def _toml_value(v: Any) -> str:
    if isinstance(v, float):
        return repr(v)
    return format_value(v)


def _comment(f: Field) -> str:
    parts = []
    if f.symbol:
        parts.append(f.symbol + ":")
    parts.append(f.description)
    if f.unit and f.unit != "-" and f.type in ("number", "integer"):
        parts.append(f"[{f.unit}]")
    text = " ".join(parts)
    if f.required:
        text += f"; required, {f.rule()}"
    elif f.default is not None:
        text += f"; default {_toml_value(f.default)}"
        if f.choices is not None or f.type in ("number", "integer"):
            text += f", {f.rule()}"
    else:
        text += f"; optional, {f.rule()}"
    if f.hint:
        text += f". {f.hint}"
    return text


def _template_table(t: Table, path: str, lines: list[str]) -> None:
    scalars = [m for m in t.fields if isinstance(m, Field)]
    tables = [m for m in t.fields if isinstance(m, Table)]
    if path:
        lines.append("")
        optional = " (optional table)" if not t.required or t.implicit else ""
        lines.append(f"# {t.description}{optional}")
        if t.hint:
            lines.append(f"# {t.hint}")
        lines.append(f"[{path}]")
    for f in scalars:
        if not path and f.key == "kind":
            lines.append(f"kind = {_toml_value(f.example)}")
            continue
        comment = _comment(f)
        if f.example is not None:
            lines.append(f"{f.key} = {_toml_value(f.example)}  # {comment}")
        elif f.default is not None and f.default is not REQUIRED:
            lines.append(f"# {f.key} = {_toml_value(f.default)}  # {comment}")
        else:
            lines.append(f"# {f.key} =   # {comment}")
    for sub in tables:
        _template_table(sub, _join(path, sub.key), lines)


def template(schema: SpecSchema) -> str:
    """A complete, commented example spec that validates as it is."""
    lines = [
        f"# geardesign {schema.kind} spec: {schema.description}",
        "# Units are fixed per quantity (mm, deg, N, N*m, MPa, min^-1, kW, h).",
        "# Keys shown commented out take the default given; uncomment to change them.",
    ]
    _template_table(schema.root, "", lines)
    return "\n".join(lines) + "\n"
