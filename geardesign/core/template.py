"""A calculator's schema printed: its JSON Schema (``geardesign schema KIND``) and its
complete commented example spec (``geardesign template KIND``), both from the one
declaration of :mod:`geardesign.core.schema`."""

from __future__ import annotations

from typing import Any

from geardesign.core.errors import format_value
from geardesign.core.schema import REQUIRED, Field, SpecSchema, Table, TableList, _join


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
