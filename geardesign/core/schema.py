"""The types of a spec's schema: :class:`Field`, :class:`Table`, :class:`TableList`,
:class:`SpecSchema`, and :class:`ValidatedSpec`, the spec they let through.

A calculator describes its TOML spec once with them; :mod:`geardesign.core.spec`
validates a parsed spec against them and :mod:`geardesign.core.template` prints their
JSON Schema and commented template.
"""

from __future__ import annotations

import math
from dataclasses import field
from pathlib import Path
from typing import Any

from geardesign.core.errors import format_value
from geardesign.core.records import dataclass


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
            import difflib  # only to name a close match

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
