"""A REXS model (the dictionary :mod:`geardesign.rexs.exporter` builds) as text: JSON (the
``{"model": ...}`` document of REXS 1.5) or XML (``<model>``, ``<relations>``,
``<components>``, ``<load_spectrum>``; array values as ``<array><c>..</c></array>``) [REXS]."""

from __future__ import annotations

import json


def to_json(model: dict) -> str:
    return json.dumps({"model": model}, indent=1, ensure_ascii=False) + "\n"


def _value_key(a: dict) -> str:
    return next(k for k in a if k not in ("id", "unit"))


def to_xml(model: dict) -> str:
    from xml.sax.saxutils import escape, quoteattr

    def val(a):
        k = _value_key(a)
        v = a[k]
        if k.endswith("_array"):
            return "<array>" + "".join(
                f"<c>{escape(x) if isinstance(x, str) else _num(x)}</c>" for x in v) + "</array>"
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, (int, float)):
            return _num(v)
        return escape(str(v))

    def comp(c, indent):
        lines = [f"{indent}<component id=\"{c['id']}\" name={quoteattr(c['name'])} "
                 f"type=\"{c['type']}\">"]
        for a in c["attributes"]:
            lines.append(f"{indent}  <attribute id=\"{a['id']}\" unit={quoteattr(a['unit'])}>"
                         f"{val(a)}</attribute>")
        lines.append(f"{indent}</component>")
        return lines

    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           f"<model applicationId=\"{model['applicationId']}\" applicationVersion="
           f"{quoteattr(model['applicationVersion'])} date=\"{model['date']}\" "
           f"version=\"{model['version']}\">", "  <relations>"]
    for r in model["relations"]:
        out.append(f"    <relation id=\"{r['id']}\" type=\"{r['type']}\">")
        for ref in r["refs"]:
            out.append(f"      <ref hint=\"{ref['hint']}\" id=\"{ref['id']}\" "
                       f"role=\"{ref['role']}\"/>")
        out.append("    </relation>")
    out += ["  </relations>", "  <components>"]
    for c in model["components"]:
        out += comp(c, "    ")
    out += ["  </components>", "  <load_spectrum id=\"1\">"]
    for lc in model["load_spectrum"]["load_cases"]:
        out.append(f"    <load_case id=\"{lc['id']}\">")
        for c in lc["components"]:
            out += comp(c, "      ")
        out.append("    </load_case>")
    out += ["  </load_spectrum>", "</model>"]
    return "\n".join(out) + "\n"


def _num(x) -> str:
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, int):
        return str(x)
    return repr(float(x))
