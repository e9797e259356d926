"""Spec files: one declarative schema per calculator, used for everything.

A calculator describes its TOML spec once, as nested :class:`Table` objects holding
:class:`Field` objects (type, unit, range, default, description; the types are in
:mod:`geardesign.core.schema`).  From that single definition this module

* validates a parsed spec, collecting every problem as one line (unknown keys with a
  "did you mean", missing keys, wrong types, out-of-range values),
* fills in defaults and records which values were assumed;

:mod:`geardesign.core.template` prints the JSON Schema (``geardesign schema KIND``) and
the commented template (``geardesign template KIND``).

There is no second, hand-kept copy of the rules anywhere.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Iterator

from geardesign.core.errors import REPORTED, InputError, Problem
from geardesign.core.io import MAX_SPEC_BYTES, parse_toml, read_toml  # noqa: F401 (API)
from geardesign.core.schema import (  # noqa: F401 (API: the schema types)
    MAX_ARRAY, MAX_STRING, MAX_TABLES, OTHER_DOMAIN, REQUIRED, UNIT_DOMAINS, Field,
    SpecSchema, Table, TableList, ValidatedSpec, _join, _num)


def _validate_table(table: Table, data: Any, path: str, problems: list, assumed: list) -> dict:
    out: dict = {}
    known = [m.key for m in table.fields]
    for key, value in data.items():
        if key not in known and table.open:
            out[key] = value
        elif key not in known:
            import difflib  # only to name a close match

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


def __getattr__(name: str):
    # the printers of a schema (geardesign.core.template), imported when asked for
    if name in ("template", "json_schema"):
        from geardesign.core import template as printers

        return getattr(printers, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
