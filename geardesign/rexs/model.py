"""A REXS model read safely: XML, JSON or a zip of either, into plain components,
relations and load cases.

REXS (Reusable Engineering EXchange Standard, FVA, versions 1.0–1.7 [REXS]) stores a gear
unit as components (an id, a type such as ``cylindrical_gear``, attributes with a unit)
tied by relations (``assembly``, ``stage``, ``side``, ``flank``, ...: roles naming component
ids) and a load spectrum of load cases (per component, the attributes of that case).

Reading is bounded: the file through :func:`geardesign.core.io.read_regular` (at most
:data:`MAX_MODEL_BYTES`); a zip (``.rexsz``) with at most :data:`MAX_ZIP_MEMBERS` members,
the model member inflated by at most :data:`MAX_MODEL_BYTES` (counted while inflating, the
size the archive declares is not trusted) and at most :data:`MAX_RATIO` times its
compressed size; XML with no document type declaration (REXS has none: refusing it leaves
no entity to expand and no external resource to fetch, so the standard library's expat
parser is safe here without ``defusedxml``); JSON nested at most
:data:`geardesign.core.io.MAX_JSON_DEPTH` deep; at most :data:`MAX_COMPONENTS` components,
:data:`MAX_RELATIONS` relations and :data:`MAX_LOAD_CASES` load cases.  Every problem is
one :class:`~geardesign.core.errors.InputError` line.
"""

from __future__ import annotations

import io
import json
import math
import re
import sys
from dataclasses import field
from pathlib import Path
from typing import Any

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass

MiB = 1024 * 1024
MAX_MODEL_BYTES = 64 * MiB
"""A REXS file (or the model inside a zip) larger than this is refused (the public models
are 30 kB–1.2 MB)."""
MAX_ZIP_MEMBERS = 64
"""Members of a ``.rexsz`` archive (the model and a few attached files)."""
MAX_RATIO = 200
"""Largest inflated/compressed size ratio of the model member of a zip (XML models pack
about 20:1; a zip bomb packs 1000:1 and more)."""
MAX_COMPONENTS = 100_000
MAX_RELATIONS = 200_000
MAX_LOAD_CASES = 1_000

KNOWN_VERSIONS = ("1.0", "1.1", "1.2", "1.3", "1.4", "1.5", "1.6", "1.7")
"""REXS versions read: those whose database this tool was checked against (the FVA's
rexs_schema files); a 2.x model has another structure."""


class ModelError(InputError):
    """A REXS file that cannot be used: one line."""

    def __init__(self, message: str):
        super().__init__(Problem("", message))


@dataclass
class Attribute:
    id: str
    value: Any
    unit: str


@dataclass
class Component:
    id: str
    type: str
    name: str
    attributes: dict[str, Attribute] = field(default_factory=dict)


@dataclass
class Ref:
    role: str
    id: str
    hint: str


@dataclass
class Relation:
    id: str
    type: str
    refs: list[Ref]
    order: int | None = None

    def role(self, role: str) -> str | None:
        for r in self.refs:
            if r.role == role:
                return r.id
        return None


@dataclass
class Model:
    version: str
    application: str
    application_version: str
    date: str
    components: dict[str, Component]
    relations: list[Relation]
    load_cases: list[dict[str, dict[str, Attribute]]]
    fmt: str = "xml"

    def of_type(self, *types: str) -> list[Component]:
        return [c for c in self.components.values() if c.type in types]

    def related(self, rel_type: str, **roles: str) -> list[Relation]:
        """Relations of ``rel_type`` whose refs have the given role → id pairs."""
        return [r for r in self.relations if r.type == rel_type
                and all(r.role(k) == v for k, v in roles.items())]


# --------------------------------------------------------------------------- units

_UNITS = {
    # quantity: {unit spelling: factor to the tool's unit}
    "mm": {"mm": 1.0, "m": 1000.0, "mum": 1e-3, "µm": 1e-3, "μm": 1e-3, "cm": 10.0},
    "deg": {"deg": 1.0, "°": 1.0, "rad": 180.0 / math.pi},
    "N m": {"N m": 1.0, "Nm": 1.0, "N mm": 1e-3, "Nmm": 1e-3, "kN m": 1e3, "kNm": 1e3},
    "N": {"N": 1.0, "kN": 1e3},
    "1 / min": {"1 / min": 1.0, "1/min": 1.0, "rpm": 1.0, "1 / s": 60.0, "1/s": 60.0},
    "mm^2 / s": {"mm^2 / s": 1.0, "mm²/s": 1.0, "cSt": 1.0, "m^2 / s": 1e6},
    "kg / m^3": {"kg / dm^3": 1000.0, "kg/dm^3": 1000.0, "kg / m^3": 1.0, "g / cm^3": 1000.0},
    "MPa": {"N / mm^2": 1.0, "N/mm^2": 1.0, "MPa": 1.0, "GPa": 1000.0},
    "C": {"C": 1.0, "°C": 1.0},
    "%": {"%": 1.0},
    "h": {"h": 1.0},
    "kW": {"kW": 1.0, "W": 1e-3},
    "": {"": 1.0, "none": 1.0, "-": 1.0},
}


def convert(attr: Attribute, to: str, where: str) -> float:
    """The number of ``attr`` in the tool's unit ``to`` (a key of the unit table; °C only
    as °C), from the unit the file states.  An unknown unit or a value that is not a
    finite number is one :class:`ModelError` line naming ``where``."""
    factors = _UNITS[to]
    unit = (attr.unit or "").strip()
    if unit not in factors:
        raise ModelError(f"{where}: attribute {attr.id} has unit \"{unit}\"; "
                         f"expected one of {', '.join(repr(u) for u in factors if u)}"
                         if to else f"{where}: attribute {attr.id} has unit \"{unit}\"; "
                         f"expected a number without unit")
    value = number(attr, where) * factors[unit]
    if not math.isfinite(value):
        raise ModelError(f"{where}: attribute {attr.id} = {attr.value!r} {unit} is out of "
                         f"range: over {sys.float_info.max / factors[unit]:.3g} {unit}")
    return value


def number(attr: Attribute, where: str) -> float:
    v = attr.value
    if isinstance(v, bool):
        raise ModelError(f"{where}: attribute {attr.id} = {v!r} is not a number")
    try:
        x = float(v)
    except (TypeError, ValueError):
        raise ModelError(f"{where}: attribute {attr.id} = {str(v)[:40]!r} is not a number") \
            from None
    if not math.isfinite(x):
        raise ModelError(f"{where}: attribute {attr.id} = {v!r} is not a finite number")
    return x


# --------------------------------------------------------------------------- reading


def read_model(path: Path) -> Model:
    """The REXS model in ``path`` (XML ``.rexs``, JSON ``.rexsj``/``.json``, or a zip of
    either); every problem is one :class:`InputError` line."""
    from geardesign.core.io import read_problem, read_regular

    try:
        raw = read_regular(path, MAX_MODEL_BYTES, "a REXS model is a few MB at most")
    except OSError as exc:
        raise InputError(read_problem(exc, "REXS model")) from None
    if raw[:4] == b"PK\x03\x04":
        raw = _unzip(raw)
    return parse(raw)


def _unzip(raw: bytes) -> bytes:
    import zipfile

    try:
        zf = zipfile.ZipFile(io.BytesIO(raw))
        infos = zf.infolist()
    except (zipfile.BadZipFile, ValueError, OSError) as exc:
        raise ModelError(f"not a usable zip archive ({exc})") from None
    if len(infos) > MAX_ZIP_MEMBERS:
        raise ModelError(f"a zip of {len(infos)} members, more than {MAX_ZIP_MEMBERS}; "
                         f"a .rexsz holds the model and a few files")
    models = [i for i in infos if not i.is_dir()
              and i.filename.lower().endswith((".rexs", ".rexsj", ".json", ".xml"))]
    if len(models) != 1:
        raise ModelError(f"a zip with {len(models)} REXS models (.rexs, .rexsj) in it; "
                         f"a .rexsz holds exactly one")
    info = models[0]
    limit = min(MAX_MODEL_BYTES, max(info.compress_size, 1) * MAX_RATIO)
    out, total = [], 0
    try:
        with zf.open(info) as fh:
            while True:
                chunk = fh.read(1 << 16)
                if not chunk:
                    break
                total += len(chunk)
                if total > limit:
                    raise ModelError(
                        f"the zip member {info.filename} inflates to more than "
                        f"{limit // MiB if limit >= MiB else limit} "
                        f"{'MiB' if limit >= MiB else 'bytes'} (at most {MAX_RATIO} times "
                        f"its packed size and {MAX_MODEL_BYTES // MiB} MiB): refused as a "
                        f"zip bomb")
                out.append(chunk)
    except (zipfile.BadZipFile, OSError, EOFError, NotImplementedError, RuntimeError) as exc:
        raise ModelError(f"the zip member {info.filename} cannot be read ({exc})") from None
    return b"".join(out)


def parse(raw: bytes) -> Model:
    """A model from the bytes of a REXS file (XML or JSON, told apart by the first
    character)."""
    head = raw.lstrip(b"\xef\xbb\xbf \t\r\n")[:1]
    if head == b"<":
        return _inert(_parse_xml(raw))
    if head == b"{":
        return _inert(_parse_json(raw))
    raise ModelError("not a REXS model: neither XML (<model ...>) nor JSON ({\"model\": ...})")


def _inert(m: Model) -> Model:
    """``m`` with every text (ids, names, units, values, program, date) escaped by
    :func:`geardesign.core.text.escape_controls`: no line break, control, bidi override or
    lone surrogate (JSON ``\\udcff``) of a model ends a line of the spec written from it."""
    from dataclasses import fields, is_dataclass, replace

    from geardesign.core.text import escape_controls

    def clean(v):
        if isinstance(v, str):
            return escape_controls(v)
        if isinstance(v, list):
            return [clean(x) for x in v]
        if isinstance(v, dict):
            return {clean(k): clean(x) for k, x in v.items()}
        if is_dataclass(v):
            return replace(v, **{f.name: clean(getattr(v, f.name)) for f in fields(v)})
        return v

    return clean(m)


def _check_version(version: Any) -> str:
    v = str(version or "").strip()
    if not v:
        raise ModelError("not a REXS model: the model states no version")
    if v not in KNOWN_VERSIONS:
        if re.fullmatch(r"\d+(\.\d+)*", v):
            raise ModelError(f"REXS version {v} is not one this tool reads "
                             f"({KNOWN_VERSIONS[0]}–{KNOWN_VERSIONS[-1]})")
        raise ModelError(f"not a REXS model: version {v[:20]!r} is no REXS version")
    return v


def _parse_xml(raw: bytes) -> Model:
    import xml.etree.ElementTree as ET

    if re.search(rb"<!(?:DOCTYPE|ENTITY)", raw, re.I):
        raise ModelError("an XML document type declaration (<!DOCTYPE>/<!ENTITY>): REXS "
                         "has none, and entities are not expanded")
    try:
        root = ET.fromstring(raw)
    except ET.ParseError as exc:
        raise ModelError(f"not well-formed XML ({exc})") from None
    if root.tag != "model":
        raise ModelError(f"not a REXS model: the XML root is <{root.tag[:40]}>, not <model>")
    version = _check_version(root.get("version"))
    comps: dict[str, Component] = {}
    rels: list[Relation] = []
    cases: list[dict] = []
    box = root.find("components")
    for c in (box if box is not None else ()):
        if c.tag != "component":
            continue
        comp = Component(str(c.get("id")), str(c.get("type") or ""), c.get("name") or "")
        comp.attributes = _xml_attributes(c)
        _add(comps, comp)
    box = root.find("relations")
    for r in (box if box is not None else ()):
        if r.tag != "relation":
            continue
        refs = [Ref(x.get("role") or "", str(x.get("id")), x.get("hint") or "")
                for x in r if x.tag == "ref"]
        order = r.get("order")
        rels.append(Relation(str(r.get("id")), r.get("type") or "", refs,
                             int(order) if order and order.isdigit() else None))
        if len(rels) > MAX_RELATIONS:
            raise ModelError(f"more than {MAX_RELATIONS} relations")
    for lc in root.iter("load_case"):
        cases.append({str(c.get("id")): _xml_attributes(c) for c in lc if c.tag == "component"})
        if len(cases) > MAX_LOAD_CASES:
            raise ModelError(f"more than {MAX_LOAD_CASES} load cases")
    return Model(version, root.get("applicationId") or "", root.get("applicationVersion") or "",
                 root.get("date") or "", comps, rels, cases, "xml")


def _add(comps: dict, comp: Component) -> None:
    if comp.id in comps:
        raise ModelError(f"component id {comp.id} is given twice")
    comps[comp.id] = comp
    if len(comps) > MAX_COMPONENTS:
        raise ModelError(f"more than {MAX_COMPONENTS} components")


def _xml_attributes(c) -> dict[str, Attribute]:
    out = {}
    for a in c:
        if a.tag != "attribute":
            continue
        arr = a.find("array")
        if arr is not None:
            value: Any = [(x.text or "").strip() for x in arr]
        else:
            value = (a.text or "").strip()
        out[a.get("id") or ""] = Attribute(a.get("id") or "", value, a.get("unit") or "")
    return out


_JSON_VALUE_KEYS = ("floating_point", "integer", "boolean", "string", "enum", "reference_component",
                    "floating_point_array", "integer_array", "boolean_array", "string_array",
                    "enum_array", "floating_point_matrix", "file_reference", "date_time")


def _parse_json(raw: bytes) -> Model:
    from geardesign.core.io import MAX_JSON_DEPTH, _depth, decode

    try:
        doc = json.loads(decode(raw))
    except InputError:
        raise
    except RecursionError:
        raise ModelError(f"JSON nested more than {MAX_JSON_DEPTH} deep") from None
    except ValueError as exc:
        raise ModelError(f"not valid JSON ({exc})") from None
    if _depth(doc) > MAX_JSON_DEPTH:
        raise ModelError(f"JSON nested more than {MAX_JSON_DEPTH} deep")
    m = doc.get("model") if isinstance(doc, dict) else None
    if not isinstance(m, dict):
        raise ModelError("not a REXS model: the JSON has no \"model\" object")
    version = _check_version(m.get("version"))
    comps: dict[str, Component] = {}
    for c in _list(m.get("components"), "components"):
        comp = Component(str(c.get("id")), str(c.get("type") or ""), str(c.get("name") or ""))
        comp.attributes = _json_attributes(c)
        _add(comps, comp)
    rels = []
    for r in _list(m.get("relations"), "relations"):
        refs = [Ref(str(x.get("role") or ""), str(x.get("id")), str(x.get("hint") or ""))
                for x in _list(r.get("refs"), "refs")]
        order = r.get("order")
        rels.append(Relation(str(r.get("id")), str(r.get("type") or ""), refs,
                             order if isinstance(order, int) else None))
        if len(rels) > MAX_RELATIONS:
            raise ModelError(f"more than {MAX_RELATIONS} relations")
    cases = []
    spectrum = m.get("load_spectrum")
    if isinstance(spectrum, dict):
        for lc in _list(spectrum.get("load_cases"), "load_cases"):
            cases.append({str(c.get("id")): _json_attributes(c)
                          for c in _list(lc.get("components"), "components")})
            if len(cases) > MAX_LOAD_CASES:
                raise ModelError(f"more than {MAX_LOAD_CASES} load cases")
    return Model(version, str(m.get("applicationId") or ""),
                 str(m.get("applicationVersion") or ""), str(m.get("date") or ""),
                 comps, rels, cases, "json")


def _list(v: Any, what: str) -> list[dict]:
    if v is None:
        return []
    if not isinstance(v, list) or not all(isinstance(x, dict) for x in v):
        raise ModelError(f"\"{what}\" is not a list of objects")
    return v


def _json_attributes(c: dict) -> dict[str, Attribute]:
    out = {}
    for a in _list(c.get("attributes"), "attributes"):
        value = None
        for k in _JSON_VALUE_KEYS:
            if k in a:
                value = a[k]
                break
        aid = str(a.get("id") or "")
        out[aid] = Attribute(aid, value, str(a.get("unit") or ""))
    return out
