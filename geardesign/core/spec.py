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

from geardesign.core.errors import REPORTED, InputError, Problem, format_value
from geardesign.core.io import MAX_SPEC_BYTES, parse_toml, read_toml  # noqa: F401 (API)


class _Required:
    def __repr__(self) -> str:  # pragma: no cover - debugging aid
        return "REQUIRED"


REQUIRED: Any = _Required()
"""Marks a field without a default: the spec must give it."""

MAX_ARRAY = 10_000
"""Elements of an array field, unless the field says otherwise (time histories, tables)."""
MAX_TABLES = 1_000
"""Entries of an array of tables (spectrum blocks, stages), unless the schema says otherwise."""
MAX_STRING = 1_000
"""Characters of a string value (titles, names)."""

UNIT_DOMAINS = {
    "mm": (1e-3, 1e5), "µm": (1e-3, 1e5), "µm": (1e-3, 1e5),
    "MPa": (1e-3, 1e6), "N": (1e-6, 1e10), "N·m": (1e-6, 1e9), "N·m": (1e-6, 1e9),
    "N·m/rad": (1e-6, 1e10), "N/mm": (1e-6, 1e9), "min^-1": (1e-3, 2e5), "kW": (1e-6, 1e6),
    "h": (1e-3, 1e7), "s": (1e-6, 1e5), "kg": (1e-6, 1e7), "kg*m^2": (1e-9, 1e7),
    "m/s": (1e-6, 1e3), "mm^2/s": (1e-2, 1e5), "deg": (1e-4, 360.0),
    "°C": (1e-3, 1000.0), "%": (1e-4, 100.0), "kg/m^3": (1.0, 25000.0),
    "m/s^2": (1e-6, 1e6), "m²": (1e-4, 1e4), "m^2": (1e-4, 1e4), "l": (1e-3, 1e5),
    "W/(m²·K)": (0.1, 1e4), "km/h": (1e-3, 1e3), "Hz": (1e-3, 1e7), "1/mm": (1e-6, 1e4),
    "N/µm": (1e-6, 1e7), "N/(mm·µm)": (1e-3, 1e4), "1e-6/K": (1e-3, 1e3), "1/K": (1e-9, 1e-2),
    "N/(mm·s^0.5·K)": (1e-3, 1e3), "HB": (1.0, 1000.0), "HV": (1.0, 2000.0),
    "HRC": (1.0, 100.0),
}
"""The physical validity domain of a quantity by its unit, for fields that state no domain of
their own: a value "> 0" becomes ">= the smallest that means anything" (a µm, a mN·m, …),
and a field without an upper bound gets the largest value any machine reaches.  Fields
with a narrower physical domain state it themselves (a module 0.05–100 mm)."""

OTHER_DOMAIN = (1e-9, 1e9)
"""The domain of a number of any other unit (a dimensionless factor, a count): no value
smaller in magnitude than 1e-9 other than 0 (a denormal or 1e-300 is never an input) and
no magnitude above 1e9.  Every numeric field so has a finite range and a resolution; a
field with a narrower physical domain states it (a friction coefficient 0–0.5)."""

_TYPES = ("number", "integer", "string", "boolean", "array")
_NOUNS = {"number": ("a number", "numbers"), "integer": ("an integer", "integers"),
          "string": ("a string", "strings"), "boolean": ("true or false", "booleans")}


@dataclass(frozen=True)
class Field:
    """One key of a spec table.

    Parameters
    ----------
    key : TOML key.
    type : ``"number"`` (int or float accepted), ``"integer"``, ``"string"``, ``"boolean"``, or
        ``"array"``: a list whose elements have the type ``items`` and obey the bounds and
        choices below, with ``min_items``/``max_items`` elements.
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
    items: str = "number"
    min_items: int = 1
    max_items: int | None = None

    def __post_init__(self) -> None:
        if self.type not in _TYPES or self.items not in _NOUNS:
            raise ValueError(f"field {self.key}: unknown type {self.type!r}/{self.items!r}")
        if self.type == "array" and self.max_items is None:
            object.__setattr__(self, "max_items", MAX_ARRAY)
        if self.numeric and self.choices is None:
            known = self.unit in UNIT_DOMAINS
            lo, hi = UNIT_DOMAINS[self.unit] if known else OTHER_DOMAIN
            object.__setattr__(self, "_tiny", lo)
            if known and self.gt is not None and self.gt <= lo and self.minimum is None:
                object.__setattr__(self, "gt", None)
                object.__setattr__(self, "minimum", lo)
            if self.maximum is None and self.lt is None:
                object.__setattr__(self, "maximum", hi)
            if self.minimum is None and self.gt is None:    # a signed quantity: ± its domain
                object.__setattr__(self, "minimum", -(self.maximum if self.maximum is not None
                                                      else self.lt))
        if self.numeric and self.unit is None:
            object.__setattr__(self, "unit", "-")

    @property
    def numeric(self) -> bool:
        """Numbers or a list of numbers (then the unit applies to every element)."""
        return self.type in ("number", "integer") or (
            self.type == "array" and self.items in ("number", "integer"))

    @property
    def element(self) -> "Field":
        """The rule of one element of an array field."""
        return Field(self.key, self.items, self.description, self.unit, default=None,
                     minimum=self.minimum, maximum=self.maximum, gt=self.gt, lt=self.lt,
                     choices=self.choices)

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    def rule(self) -> str:
        """The allowed values in words: ``an integer >= 5``, ``a number > 0``, ..."""
        if self.type == "array":
            count = (f"{self.min_items} to {self.max_items}" if self.max_items is not None
                     else f"at least {self.min_items}")
            element = self.element.rule()
            for single, plural in _NOUNS.values():
                if element.startswith(single):
                    element = plural + element[len(single):]
                    break
            if element.startswith("one of"):
                element = "values, each " + element
            return f"a list of {count} {element}"
        if self.choices is not None:
            return "one of " + ", ".join(format_value(c) for c in self.choices)
        noun = _NOUNS[self.type][0]
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
        if self.type == "array":
            if not isinstance(value, list) or len(value) < self.min_items or (
                    self.max_items is not None and len(value) > self.max_items):
                return None, bad
            element = self.element
            out = []
            for v in value:
                v, message = element.check(v)
                if message:
                    tiny = getattr(element, "_tiny", None)
                    return None, (f"{bad}, each 0 or at least {_num(tiny)} in magnitude"
                                  if message.endswith("in magnitude") else bad)
                out.append(v)
            return out, None
        if self.type == "boolean":
            return (value, None) if isinstance(value, bool) else (None, bad)
        if self.type == "string":
            if not isinstance(value, str):
                return None, bad
            if len(value) > MAX_STRING:
                return None, f"must be a string of at most {MAX_STRING} characters"
        elif self.type == "integer":
            if isinstance(value, bool) or not isinstance(value, int):
                return None, bad
        else:  # number
            if isinstance(value, str) and self.unit not in (None, "-"):
                from geardesign.core.units import convert   # "4 mm", "520 kN*mm" (pint)

                text, (value, why) = value, convert(value, self.unit)
                if why:
                    return None, f"{bad}, or {why}"
                bad = f"{text} = {value:.6g} {self.unit}: {bad}"   # what it became
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                return None, bad
            if not math.isfinite(value):
                return None, bad
            value = float(value)
        if self.choices is not None and value not in self.choices:
            close = difflib.get_close_matches(str(value), [str(c) for c in self.choices], 1, 0.6)
            return None, bad + (f' (did you mean "{close[0]}"?)' if close else "")
        if self.type in ("number", "integer"):
            tiny = getattr(self, "_tiny", None)
            signed_or_zero = self.minimum is None or self.minimum < (tiny or 0.0)
            if tiny is not None and signed_or_zero and value != 0 and abs(value) < tiny:
                return None, f"{bad}, and 0 or at least {_num(tiny)} in magnitude"
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
    open: bool = False
    """An open table keeps keys it does not declare, unvalidated (e.g. a drive stage: its
    own calculator validates them)."""
    in_template: bool = True
    """False: the template shows the table commented out (a table of another mode)."""

    def member(self, key: str) -> "Field | Table | None":
        for f in self.fields:
            if f.key == key:
                return f
        return None


@dataclass(frozen=True)
class TableList:
    """An array of tables (``[[load.spectrum]]``), each validated against ``item``.

    ``examples`` are the entries written in the template (by default one entry of the
    fields' examples).
    """

    key: str
    description: str
    item: Table
    required: bool = True
    min_items: int = 1
    max_items: int | None = None
    examples: tuple = ()
    hint: str = ""
    in_template: bool = True
    """False: the template names the table in a comment instead of writing an example."""

    def __post_init__(self) -> None:
        if self.max_items is None:
            object.__setattr__(self, "max_items", MAX_TABLES)

    def rule(self) -> str:
        count = (f"{self.min_items} to {self.max_items}" if self.max_items is not None
                 else f"at least {self.min_items}")
        return f"{count} [[{self.key}]] tables"


@dataclass(frozen=True)
class SpecSchema:
    """The whole spec of one calculator: ``kind``, optional ``title``, then tables."""

    kind: str
    description: str
    tables: tuple
    title_example: str = ""
    one_of: tuple = ()
    """Groups of top-level tables of which exactly one must be given, e.g.
    ``(("gear", "design"),)``."""

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
    raw: dict | None = None
    """The spec as written (before defaults): advice re-rates it with its fix written in."""


def _num(x: float) -> str:
    return str(int(x)) if float(x).is_integer() else repr(float(x))


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def _validate_table(table: Table, data: Any, path: str, problems: list, assumed: list) -> dict:
    out: dict = {}
    known = [m.key for m in table.fields]
    for key, value in data.items():
        if key not in known and table.open:
            out[key] = value
        elif key not in known:
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
        if isinstance(member, TableList):
            if member.key not in data:
                if member.required:
                    problems.append(Problem(
                        key, f"missing; required: {member.rule()} ({member.description})"))
                    out[member.key] = REPORTED
                else:
                    out[member.key] = None
                continue
            value = data[member.key]
            n = len(value) if isinstance(value, list) else -1
            if (not isinstance(value, list) or not all(isinstance(v, dict) for v in value)
                    or n < member.min_items
                    or (member.max_items is not None and n > member.max_items)):
                problems.append(Problem(
                    key, f"must be {member.rule()} ({member.description})", value))
                out[member.key] = REPORTED
                continue
            out[member.key] = [
                _validate_table(member.item, v, f"{key}[{i}]", problems, assumed)
                for i, v in enumerate(value)
            ]
            continue
        if isinstance(member, Table):
            if member.key not in data and not member.implicit:
                if member.required:
                    problems.append(Problem(key, f"missing table [{key}] ({member.description})"))
                    out[member.key] = REPORTED
                else:
                    out[member.key] = None
                continue
            value = data.get(member.key, {})
            if not isinstance(value, dict):
                problems.append(Problem(key, f"must be a table [{key}] ({member.description})", value))
                out[member.key] = REPORTED
                continue
            out[member.key] = _validate_table(member, value, key, problems, assumed)
            continue
        if member.key not in data:
            if member.required:
                problems.append(
                    Problem(key, f"missing; required: {member.rule()} ({member.description})")
                )
                out[member.key] = REPORTED
            else:
                out[member.key] = member.default
                if member.default is not None:
                    assumed.append(key)
            continue
        value, message = member.check(data[member.key])
        if message:
            problems.append(Problem(key, message, data[member.key]))
            out[member.key] = REPORTED
        else:
            out[member.key] = value
    return out


def validate(schema: SpecSchema, data: dict, source: str = "") -> ValidatedSpec:
    """Check ``data`` against ``schema``; raise :class:`InputError` with every problem."""
    spec, problems = validate_partial(schema, data, source)
    if problems:
        raise InputError(problems)
    return spec


def validate_partial(schema: SpecSchema, data: dict,
                     source: str = "") -> tuple[ValidatedSpec, list[Problem]]:
    """Check ``data`` against ``schema`` and return the spec with every usable value and
    the problems found.  A key that is missing or wrong holds
    :data:`~geardesign.core.errors.REPORTED` (so that a calculator's own checks of the
    other keys can still run and be reported in the same round, while a check that needs
    the wrong value is left out: :class:`~geardesign.core.errors.Problems`)."""
    problems: list[Problem] = []
    assumed: list[str] = []
    out = _validate_table(schema.root, data, "", problems, assumed)
    for group in schema.one_of:
        present = [k for k in group if k in data]
        if len(present) != 1:
            names = " or ".join(f"[{k}] ({schema.root.member(k).description})" for k in group)
            what = "both" if len(present) > 1 else "neither"
            problems.append(Problem("", f"give exactly one of {names}; the spec has {what}"))
    return ValidatedSpec(out, assumed, source, raw=data), problems


def load_toml(path: Path) -> dict:
    """Read a TOML spec file through the one guarded reader
    (:func:`geardesign.core.io.read_toml`); problems become one-line :class:`InputError`
    messages."""
    return read_toml(path)


# --------------------------------------------------------------------------- walking


def iter_fields(table: Table, data: dict | None, path: str = "") -> Iterator[tuple[str, Field, Any]]:
    """Yield ``(key path, field, value)`` for every field present in validated ``data``."""
    if data is None:
        return
    for member in table.fields:
        key = _join(path, member.key)
        if isinstance(member, TableList):
            for i, item in enumerate(data.get(member.key) or ()):
                yield from iter_fields(member.item, item, f"{key}[{i}]")
        elif isinstance(member, Table):
            yield from iter_fields(member, data.get(member.key), key)
        elif data.get(member.key) is not None:
            yield key, member, data[member.key]


# --------------------------------------------------------------------------- JSON Schema


def _field_schema(f: Field) -> dict:
    if f.type == "array":
        js = {"type": "array", "items": _field_schema(f.element), "minItems": f.min_items}
        if f.max_items is not None:
            js["maxItems"] = f.max_items
        js["items"].pop("description", None)
        desc = (f"{f.symbol}: " if f.symbol else "") + f.description
        if f.unit and f.numeric:
            desc += f" [{f.unit}]"
            js["x-unit"] = f.unit
            js["items"].pop("x-unit", None)
        js["description"] = desc + (f". {f.hint}" if f.hint else "")
        if not f.required and f.default is not None:
            js["default"] = f.default
        return js
    js: dict = {"type": f.type}
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
        if isinstance(m, TableList):
            props[m.key] = {"type": "array", "description": m.description,
                            "items": _table_schema(m.item), "minItems": m.min_items}
            if m.max_items is not None:
                props[m.key]["maxItems"] = m.max_items
        else:
            props[m.key] = _table_schema(m) if isinstance(m, Table) else _field_schema(m)
        if (isinstance(m, (Table, TableList)) and m.required and not getattr(m, "implicit", False)) \
                or (isinstance(m, Field) and m.required):
            required.append(m.key)
    js = {"type": "object", "description": t.description + (f". {t.hint}" if t.hint else "")}
    js["properties"] = props
    if required:
        js["required"] = required
    js["additionalProperties"] = bool(t.open)
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
    if schema.one_of:
        js["allOf"] = [{"oneOf": [{"required": [k]} for k in group]} for group in schema.one_of]
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
    if f.unit and f.unit != "-" and f.numeric:
        parts.append(f"[{f.unit}]")
    text = " ".join(parts)
    if f.required:
        text += f"; required, {f.rule()}"
    elif f.default is not None:
        text += f"; default {_toml_value(f.default)}"
        if f.choices is not None or f.numeric:
            text += f", {f.rule()}"
    else:
        text += f"; optional, {f.rule()}"
    if f.hint:
        text += f". {f.hint}"
    return text


def _field_line(f: Field, value: Any = None, comments: bool = True) -> str:
    """``key = value  # comment``; a field without a value is written commented out."""
    comment = f"  # {_comment(f)}" if comments else ""
    if value is not None:
        return f"{f.key} = {_toml_value(value)}{comment}"
    if f.default is not None and f.default is not REQUIRED:
        return f"# {f.key} = {_toml_value(f.default)}{comment}"
    return f"# {f.key} ={comment}"


def _template_items(sub: TableList, path: str, lines: list[str]) -> None:
    """``[[path]]`` entries of an array of tables, from its examples; tables nested in an
    item are written after it (open tables only as a header and a comment)."""
    if not sub.in_template:
        lines.append("")
        lines.append(f"# [[{path}]]: {sub.description} ({sub.rule()}, optional). {sub.hint}")
        return
    examples = sub.examples or ({f.key: f.example for f in sub.item.fields
                                 if isinstance(f, Field) and f.example is not None},)
    lines.append("")
    lines.append(f"# {sub.description}: {sub.rule()}" + ("" if sub.required else " (optional)"))
    if sub.hint:
        lines.append(f"# {sub.hint}")
    for i, example in enumerate(examples):
        lines.append(f"[[{path}]]")
        for f in sub.item.fields:
            if isinstance(f, Field) and (f.key in example or i == 0):
                lines.append(_field_line(f, example.get(f.key), comments=(i == 0)))
        known = {f.key for f in sub.item.fields}
        for key, table in example.items():   # inline tables of an open item (a drive stage)
            if key not in known and isinstance(table, dict):
                _inline_table(f"{path}.{key}", table, lines)
        for f in sub.item.fields:
            if isinstance(f, TableList):
                _template_items(f, f"{path}.{f.key}", lines)
            elif isinstance(f, Table) and (f.required or f.fields):
                lines.append(f"[{path}.{f.key}]  # {f.description}")
                for g in f.fields:
                    if isinstance(g, Field):
                        lines.append(_field_line(g, g.example))


def _inline_table(path: str, table: dict, lines: list[str]) -> None:
    """``[path]`` with its values, sub-tables after them (examples of open tables)."""
    lines.append(f"[{path}]")
    for k, v in table.items():
        if not isinstance(v, dict):
            lines.append(f"{k} = {_toml_value(v)}")
    for k, v in table.items():
        if isinstance(v, dict):
            _inline_table(f"{path}.{k}", v, lines)


def _template_table(t: Table, path: str, lines: list[str], alternatives: dict | None = None
                    ) -> None:
    alternatives = alternatives or {}
    if path:
        lines.append("")
        optional = " (optional table)" if not t.required or t.implicit else ""
        lines.append(f"# {t.description}{optional}")
        if t.hint:
            lines.append(f"# {t.hint}")
        lines.append(f"[{path}]")
    for f in t.fields:
        if isinstance(f, Field):
            if not path and f.key == "kind":
                lines.append(f"kind = {_toml_value(f.example)}")
            else:
                lines.append(_field_line(f, f.example))
    for sub in t.fields:
        sub_path = _join(path, sub.key)
        if isinstance(sub, TableList):
            _template_items(sub, sub_path, lines)
        elif isinstance(sub, Table):
            if sub.key in alternatives or not sub.in_template:
                alt: list[str] = []
                _template_table(sub, sub_path, alt)
                lines.append("")
                lines.append(f"# Instead of [{alternatives[sub.key]}]: [{sub.key}] "
                             f"({sub.description})." if sub.key in alternatives else
                             f"# [{sub.key}]: {sub.description}.")
                lines.extend(("# " + line if line and not line.startswith("#") else line)
                             for line in alt[1:])
                continue
            _template_table(sub, sub_path, lines)


def template(schema: SpecSchema) -> str:
    """A complete, commented example spec that validates as it is."""
    lines = [
        f"# geardesign {schema.kind} spec: {schema.description}",
        *([f"# This example: {schema.title_example} (geardesign run FILE computes it)"]
          if schema.title_example else []),
        "# Units are fixed per quantity (mm, deg, N, N·m, MPa, min^-1, kW, h).",
        "# Keys shown commented out take the default given; uncomment to change them.",
    ]
    alternatives = {k: group[0] for group in schema.one_of for k in group[1:]}
    _template_table(schema.root, "", lines, alternatives)
    return "\n".join(lines) + "\n"
