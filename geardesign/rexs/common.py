"""What the REXS export and import share: the attribute written (:func:`A`), the custom
attributes ``custom_geardesign__...`` that carry a spec's keys REXS has no attribute for
(:func:`custom` reads them back), and the source comment of a value read (:func:`src`)."""

from __future__ import annotations

import math
import re

from geardesign.rexs.model import Component, ModelError

CUSTOM = "custom_geardesign__"
"""Prefix of geardesign's own attributes (REXS leaves ``custom_`` to a program's own data)."""

TEXT_SUFFIX = "__str"
"""Suffix of a custom attribute whose text value reads as a number or a boolean ("0", the
GOST regime; "true"): XML does not state the value type, the import keeps it text."""


def A(aid: str, value, unit: str = "none", vtype: str | None = None) -> dict:
    """One attribute; the value type from the Python value unless given."""
    if vtype is None:
        if isinstance(value, bool):
            vtype = "boolean"
        elif isinstance(value, int):
            vtype = "integer"
        elif isinstance(value, float):
            vtype = "floating_point"
        elif isinstance(value, list):
            vtype = "floating_point_array"
        else:
            vtype = "string"
    return {"id": aid, "unit": unit, vtype: value}


def text_suffix(v) -> str:
    """:data:`TEXT_SUFFIX` for a text that reads as a number or a boolean, else ""."""
    if not isinstance(v, str):
        return ""
    low = v.strip().lower()
    if low in ("true", "false"):
        return TEXT_SUFFIX
    try:
        float(low)
    except ValueError:
        return ""
    return TEXT_SUFFIX


def src(comp: Component, attr: str, case: int | None = None) -> str:
    where = f"load case {case}: " if case is not None else ""
    return f"{where}component {comp.id} ({comp.type}) {attr}"


def custom(c: Component) -> dict[str, tuple]:
    """The ``custom_geardesign__<table>__<key>`` attributes of ``c`` (written by
    ``geardesign export`` for keys REXS has no attribute for): path → (value, source)."""
    out = {}
    for aid, a in c.attributes.items():
        if aid.startswith(CUSTOM):
            v = a.value
            if aid.endswith(TEXT_SUFFIX):
                out[aid[len(CUSTOM):-len(TEXT_SUFFIX)]] = (str(v), src(c, aid))
                continue
            if isinstance(v, list):
                v = [str(x) for x in v]
            elif isinstance(v, str):
                low = v.strip().lower()
                if low in ("true", "false"):
                    v = low == "true"
                else:
                    try:
                        v = int(v) if re.fullmatch(r"-?\d+", v.strip()) else float(v)
                    except ValueError:
                        pass
            if isinstance(v, float) and not math.isfinite(v):
                raise ModelError(f"{src(c, aid)} = {a.value!r} is not a finite number")
            out[aid[len(CUSTOM):]] = (v, src(c, aid))
    return out
