"""A REXS model (the dictionary :mod:`geardesign.rexs.exporter` builds) as text: JSON (the
``{"model": ...}`` document of REXS 1.5) or XML (``<model>``, ``<relations>``,
``<components>``, ``<load_spectrum>``; array values as ``<array><c>..</c></array>``) [REXS]."""

from __future__ import annotations

import re

_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")
"""What XML 1.0 cannot hold, raw or as a character reference (its ``Char`` production): C0
controls but tab, line feed and carriage return, lone surrogates, U+FFFE and U+FFFF."""


def _xml_chars(text) -> str:
    """``text`` with each character XML cannot hold written as its escape ``\\xNN`` /
    ``\\uNNNN`` (a title with an ESC exports as a well-formed model that shows it)."""
    from geardesign.core.text import escape_matching

    return escape_matching(str(text), _NOT_XML)


def _text(text) -> str:
    """Character data of an element."""
    from xml.sax.saxutils import escape

    return escape(_xml_chars(text))


def _attr(text) -> str:
    """A quoted attribute value."""
    from xml.sax.saxutils import quoteattr

    return quoteattr(_xml_chars(text))


def to_json(model: dict) -> str:
    """The JSON document (:func:`geardesign.core.text.json_text`: what JSON leaves raw and
    no encoder writes, a lone surrogate, as its ``\\uNNNN`` escape)."""
    from geardesign.core.text import json_text

    return json_text({"model": model}, indent=1) + "\n"


def _value_key(a: dict) -> str:
    return next(k for k in a if k not in ("id", "unit"))


def to_xml(model: dict) -> str:
    """The XML document: every text through :func:`_text` or :func:`_attr` (escaped, and
    what XML cannot hold written as its escape)."""
    def val(a):
        k = _value_key(a)
        v = a[k]
        if k.endswith("_array"):
            return "<array>" + "".join(
                f"<c>{_text(x) if isinstance(x, str) else _num(x)}</c>" for x in v) + "</array>"
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, (int, float)):
            return _num(v)
        return _text(v)

    def comp(c, indent):
        lines = [f"{indent}<component id={_attr(c['id'])} name={_attr(c['name'])} "
                 f"type={_attr(c['type'])}>"]
        for a in c["attributes"]:
            lines.append(f"{indent}  <attribute id={_attr(a['id'])} unit={_attr(a['unit'])}>"
                         f"{val(a)}</attribute>")
        lines.append(f"{indent}</component>")
        return lines

    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           f"<model applicationId={_attr(model['applicationId'])} applicationVersion="
           f"{_attr(model['applicationVersion'])} date={_attr(model['date'])} "
           f"version={_attr(model['version'])}>", "  <relations>"]
    for r in model["relations"]:
        out.append(f"    <relation id={_attr(r['id'])} type={_attr(r['type'])}>")
        for ref in r["refs"]:
            out.append(f"      <ref hint={_attr(ref['hint'])} id={_attr(ref['id'])} "
                       f"role={_attr(ref['role'])}/>")
        out.append("    </relation>")
    out += ["  </relations>", "  <components>"]
    for c in model["components"]:
        out += comp(c, "    ")
    out += ["  </components>", "  <load_spectrum id=\"1\">"]
    for lc in model["load_spectrum"]["load_cases"]:
        out.append(f"    <load_case id={_attr(lc['id'])}>")
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
