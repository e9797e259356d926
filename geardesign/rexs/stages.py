"""Planetary and worm stages in REXS: written by ``geardesign export`` and read by
``geardesign import`` (docs/rexs.md, "Planetary and worm stages").

A planetary stage is a ``planetary_stage`` with a ``planet_carrier`` (assembly), the sun, one
gear per planet and the ring (``cylindrical_gear``, ``ring_gear``) on their shafts, one
``cylindrical_stage`` per mesh (sun–planet and planet–ring of every planet, ``stage``
relations ``gear_1``/``gear_2``), ``central_shaft`` relations to the sun and ring shafts, a
``planet_carrier_shaft`` relation to the carrier shaft and ``planet_shaft`` relations to the
planets' shafts (the REXS 1.1+ planetary model, [REXS] "Planetary stages").  A worm stage is
a ``worm_stage`` with a ``worm_gear`` and a ``worm_wheel`` (``stage`` relation) on their shafts.

REXS stores the state of a gear unit: every value, given or computed alike.  A geardesign
spec states what was given (a centre distance, or shifts, or a ratio to synthesise); the
export therefore writes the geometry with the standard attributes (:data:`PLANETARY_KEYS`,
:data:`WORM_KEYS` for the spec keys that have one) and the spec's other keys as custom
attributes ``custom_geardesign__spec__<table>__<key>`` on the stage component, and lists in
``custom_geardesign__spec__from_rexs`` which spec keys the import reads from standard
attributes.  A model of another program (no such list) is read from the standard
attributes alone.
"""

from __future__ import annotations

import json
import math

from geardesign.rexs.common import CUSTOM, A, custom, text_suffix

SPEC = CUSTOM + "spec__"
FROM_REXS = SPEC + "from_rexs"
JSON_SUFFIX = "__json"

PLANETARY_KEYS = (
    # spec key, member (component role), REXS attribute, unit of the attribute
    ("train.module", "sun", "normal_module", "mm"),
    ("train.helix_angle", "sun", "helix_angle_reference_diameter", "deg"),
    ("train.face_width", "sun_planet", "common_face_width", "mm"),
    ("train.center_distance", "sun_planet", "center_distance", "mm"),
    ("teeth.sun", "sun", "number_of_teeth", "none"),
    ("teeth.planet", "planet", "number_of_teeth", "none"),
    ("teeth.ring", "ring", "number_of_teeth", "none"),
)
"""Keys of a planetary spec written as (and read from) standard REXS 1.5 attributes; the
planets are counted (``train.planets``: the planet gears of the stage).  A ring given with
a negative tooth count (the ISO 21771 sign) stays a custom attribute: REXS counts the
teeth of a ``ring_gear`` positive."""

WORM_KEYS = (
    ("gear.module", "worm", "axial_module", "mm"),
    ("gear.z1", "worm", "number_of_teeth", "none"),
    ("gear.z2", "wheel", "number_of_teeth", "none"),
    ("gear.center_distance", "stage", "center_distance", "mm"),
    ("gear.x", "wheel", "addendum_modification_coefficient_worm_wheel", "none"),
    ("gear.face_width", "wheel", "face_width_worm_wheel", "mm"),
)
"""Keys of a worm spec written as (and read from) standard REXS 1.5 attributes."""

SPUR_KEYS = (
    ("gear.module", "gear1", "normal_module", "mm"),
    ("gear.z1", "gear1", "number_of_teeth", "none"),
    ("gear.z2", "gear2", "number_of_teeth", "none"),
    ("gear.helix_angle", "gear1", "helix_angle_reference_diameter", "deg"),
    ("gear.face_width", "gear1", "face_width", "mm"),
    ("gear.center_distance", "stage", "center_distance", "mm"),
    ("gear.pressure_angle", "flank1", "normal_pressure_angle", "deg"),
    ("gear.x1", "flank1", "addendum_modification_coefficient", "none"),
    ("gear.x2", "flank2", "addendum_modification_coefficient", "none"),
)
"""Keys of a spur spec written as (and read from) standard REXS 1.5 attributes."""

WORM_TYPES = {"ZA": "za", "ZI": "zi", "ZN": "zn", "ZK": "zk"}
"""GOST 18498-89 worm type → REXS ``flank_form`` (ZT, the toroid worm, has none)."""

MEMBERS = ("sun", "ring", "carrier")


# ------------------------------------------------------------------------------ export

def spec_customs(A, data: dict, mapped: set[str]) -> list[dict]:
    """Custom attributes of every key of a stage spec not in ``mapped`` (nested tables
    flattened with ``__``; a list of tables or numbers as JSON text, its id ending in
    ``__json``), and the list of the mapped keys."""
    out = []

    def walk(prefix: str, table: dict, path: str):
        for k, v in table.items():
            p = f"{path}{k}"
            if v is None or p in mapped:
                continue
            if isinstance(v, dict):
                walk(f"{prefix}{k}__", v, p + ".")
            elif isinstance(v, (bool, int, float, str)):
                out.append(A(f"{SPEC}{prefix}{k}{text_suffix(v)}", v))
            elif isinstance(v, list):
                out.append(A(f"{SPEC}{prefix}{k}{JSON_SUFFIX}", json.dumps(v), vtype="string"))

    walk("", data, "")
    out.append(A(FROM_REXS, sorted(mapped), vtype="string_array"))
    return out


def spec_value(data: dict, path: str):
    t = data
    for part in path.split("."):
        if not isinstance(t, dict) or part not in t:
            return None
        t = t[part]
    return t


def planetary(b, A, data: dict, doc: dict, stage_name: str, shafts: dict, unit: dict) -> dict:
    """The components of one planetary stage; ``shafts`` maps each member (sun, ring,
    carrier) to its shaft component.  Returns the planetary_stage component."""
    sec = doc["results"]
    g, sp, pr = sec["gears"], sec["sun_planet"], sec["planet_ring"]
    train = data.get("train") or {}
    n_p = int(train.get("planets", 3))
    mapped = {k for k, *_ in PLANETARY_KEYS if spec_value(data, k) is not None
              and not (k == "teeth.ring" and spec_value(data, k) < 0)}
    ps = b.new("planetary_stage", stage_name, spec_customs(A, data, mapped))
    b.rel("assembly", ("assembly", unit), ("part", ps))
    carrier = b.new("planet_carrier", f"{stage_name} carrier")
    b.rel("assembly", ("assembly", ps), ("part", carrier))
    m_n = float(sp["m_n"])
    beta = float(train.get("helix_angle", 0.0) or 0.0)
    width = float(train.get("face_width") or 0.0)

    def gear(ctype, member, hand):
        z = abs(int(g[f"z_{member}"]))
        attrs = [A("normal_module", m_n, "mm"), A("number_of_teeth", z),
                 A("helix_angle_reference_diameter", hand * beta, "deg"),
                 A("reference_circle_diameter", float(g[f"d_{member}"]), "mm"),
                 A("tip_diameter", float(g[f"d_a_{member}"]), "mm"),
                 A("root_diameter", float(g[f"d_f_{member}"]), "mm"),
                 A("base_circle_diameter", float(g[f"d_b_{member}"]), "mm")]
        if width:
            attrs.append(A("face_width", width, "mm"))
        c = b.new(ctype, f"{stage_name} {member}", attrs)
        x = g.get(f"x_{member}_iso", g.get(f"x_{member}"))
        flanks = [b.new("cylindrical_gear_flank", f"{stage_name} {member} {side} flank",
                        [A("normal_pressure_angle", 20.0, "deg"),
                         A("addendum_modification_coefficient", float(x))])
                  for side in ("left", "right")]
        b.rel("flank", ("gear", c), ("left", flanks[0]), ("right", flanks[1]))
        return c

    sun = gear("cylindrical_gear", "sun", 1.0)
    ring = gear("ring_gear", "ring", -1.0)
    b.rel("assembly", ("assembly", shafts["sun"]), ("part", sun))
    b.rel("assembly", ("assembly", shafts["ring"]), ("part", ring))
    b.rel("central_shaft", ("planetary_stage", ps), ("shaft", shafts["sun"]))
    b.rel("central_shaft", ("planetary_stage", ps), ("shaft", shafts["ring"]))
    b.rel("planet_carrier_shaft", ("planetary_stage", ps), ("shaft", shafts["carrier"]))
    b.rel("assembly", ("assembly", carrier), ("part", shafts["carrier"]))
    a_w = float(sp["a_w"])
    for k in range(n_p):
        ang = 2.0 * math.pi * k / n_p
        psh = b.new("shaft", f"{stage_name} planet {k + 1} shaft", [
            A("support_vector", [0.0, a_w * math.cos(ang), a_w * math.sin(ang)], "mm")])
        b.rel("assembly", ("assembly", carrier), ("part", psh))
        b.rel("planet_shaft", ("planetary_stage", ps), ("shaft", psh))
        planet = gear("cylindrical_gear", "planet", -1.0)
        b.rel("assembly", ("assembly", psh), ("part", planet))
        for mesh, (g1, g2), name in ((sp, (sun, planet), "sun–planet"),
                                     (pr, (planet, ring), "planet–ring")):
            st = b.new("cylindrical_stage", f"{stage_name} {name} {k + 1}", [
                A("center_distance", float(mesh["a_w"]), "mm"),
                A("gear_ratio", abs(float(mesh["u"]))),
                A("radial_contact_ratio", float(mesh["eps_alpha"])),
                A("overlap_contact_ratio", float(mesh.get("eps_beta") or 0.0))]
                + ([A("common_face_width", width, "mm")] if width else []))
            b.rel("assembly", ("assembly", ps), ("part", st))
            b.rel("stage", ("stage", st), ("gear_1", g1), ("gear_2", g2))
    return ps


def worm(b, A, data: dict, doc: dict, stage_name: str, shafts: tuple, unit: dict) -> dict:
    """The components of one worm stage: worm on ``shafts[0]``, wheel on ``shafts[1]``."""
    geo = doc["results"]["geometry"]
    gear = data.get("gear") or {}
    mapped = {k for k, *_ in WORM_KEYS if spec_value(data, k) is not None}
    ws = b.new("worm_stage", stage_name, spec_customs(A, data, mapped) + [
        A("center_distance", float(geo["a_w"]), "mm"), A("gear_ratio", float(geo["u"]))])
    b.rel("assembly", ("assembly", unit), ("part", ws))
    hand = -1.0 if gear.get("hand") == "left" else 1.0
    wt = WORM_TYPES.get(str(gear.get("worm_type", "ZA")))
    wa = [A("axial_module", float(geo["m"]), "mm"), A("normal_module", float(geo["m_n"]), "mm"),
          A("number_of_teeth", int(geo["z1"])),
          A("reference_diameter_worm_gear", float(geo["d1"]), "mm"),
          A("tip_diameter_worm_gear", float(geo["d_a1"]), "mm"),
          A("root_diameter_worm_gear", float(geo["d_f1"]), "mm"),
          A("lead_angle_worm_gear", hand * float(geo["gamma"]), "deg"),
          A("pressure_angle_worm_gear", float(geo["alpha_x"]), "deg")]
    if wt:
        wa.append(A("flank_form", wt, vtype="enum"))
    w = b.new("worm_gear", f"{stage_name} worm", wa)
    wheel = b.new("worm_wheel", f"{stage_name} wheel", [
        A("axial_module", float(geo["m"]), "mm"), A("number_of_teeth", int(geo["z2"])),
        A("reference_diameter_worm_gear", float(geo["d2"]), "mm"),
        A("tip_diameter_worm_gear", float(geo["d_a2"]), "mm"),
        A("root_diameter_worm_gear", float(geo["d_f2"]), "mm"),
        A("outer_diameter_worm_wheel", float(geo["d_aM2"]), "mm"),
        A("addendum_modification_coefficient_worm_wheel", float(geo["x"])),
        A("face_width_worm_wheel", float(geo["b2"]), "mm")])
    b.rel("assembly", ("assembly", shafts[0]), ("part", w))
    b.rel("assembly", ("assembly", shafts[1]), ("part", wheel))
    b.rel("stage", ("stage", ws), ("gear_1", w), ("gear_2", wheel))
    return ws


# ------------------------------------------------------------------------------ import

def restored(c) -> dict:
    """The stage spec stored in the custom attributes of ``c``: path → (value, source)."""
    out = {}
    for k, (v, s_) in custom(c).items():
        if not k.startswith("spec__") or k == "spec__from_rexs":
            continue
        path = k[len("spec__"):]
        if path.endswith(JSON_SUFFIX):
            try:
                path, v = path[: -len(JSON_SUFFIX)], json.loads(str(v))
            except ValueError:
                from geardesign.rexs.model import ModelError

                raise ModelError(f"{s_}: not JSON text") from None
        out[path.replace("__", ".")] = (v, s_)
    return out


def from_rexs(c) -> list[str] | None:
    a = c.attributes.get(FROM_REXS)
    if a is None:
        return None
    v = a.value
    return [str(x) for x in v] if isinstance(v, list) else [str(v)] if v else []


def nest(flat: dict) -> dict:
    """path → (value, source) as nested tables."""
    out: dict = {}
    for path, vs in flat.items():
        t = out
        parts = path.split(".")
        for p in parts[:-1]:
            t = t.setdefault(p, {})
        t[parts[-1]] = vs
    return out


def _is_aot(v) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def write_tables(out, prefix: str, tree: dict) -> None:
    """Nested tables of (value, source) leaves under ``prefix`` (``"stage."`` or ``""``):
    the table's own keys, then its sub-tables, then its lists of tables (``[[...]]``)."""
    plain = [(k, v) for k, v in tree.items() if isinstance(v, tuple) and not _is_aot(v[0])]
    aots = [(k, v) for k, v in tree.items() if isinstance(v, tuple) and _is_aot(v[0])]
    for k, (v, s_) in plain:
        out.kv(k, v, s_)
    for k, sub in tree.items():
        if isinstance(sub, dict):
            if any(isinstance(v, tuple) and not _is_aot(v[0]) for v in sub.values()):
                out.table(f"{prefix}{k}")
            write_tables(out, f"{prefix}{k}.", sub)
    for k, (v, s_) in aots:
        for item in v:
            out.table(f"{prefix}{k}", array=True, note=s_)
            for kk, vv in item.items():
                out.kv(kk, vv, None)


def stage_load(kind: str, doc: dict) -> tuple:
    """(input torque [N·m], input speed [1/min], life [h], index of the torque's shaft) of a
    planetary or worm spec: the planetary's input member (shaft 1, the input); the worm's
    wheel torque T2 on the wheel shaft (shaft 2) with the worm speed, as the worm
    calculator takes them."""
    inp, res = doc["inputs"], doc["results"]
    if kind == "worm":
        ld = inp.get("load") or {}
        return ld.get("torque2"), ld.get("speed1"), ld.get("life"), 1
    op = inp.get("operation") or {}
    member = op.get("input")
    T = (res.get("power") or {}).get(f"T_{member}") if op.get("torque") or op.get("power") \
        else None
    n = (res.get("kinematics") or {}).get(f"n_{member}")
    life = (inp.get("strength") or {}).get("life_hours")
    return (abs(T) if T is not None else None), (abs(n) if n else None), life, 0


def other_stage(b, kind: str, sdata: dict, doc: dict, name: str, shafts: list,
                 k: int, unit: dict) -> dict:
    """A planetary or worm stage between shafts k-1 (input) and k (output)
    (:mod:`geardesign.rexs.stages`); a planetary's third member (held, or the control
    member of a differential) gets a shaft of its own."""
    if kind == "worm":
        return worm(b, A, sdata, doc, name, (shafts[k - 1], shafts[k]), unit)
    op = doc["inputs"].get("operation") or {}
    where = {op.get("input"): shafts[k - 1], op.get("output"): shafts[k]}
    for member in MEMBERS:
        if member not in where:
            where[member] = b.new("shaft", f"{name} {member} shaft")
            b.rel("assembly", ("assembly", unit), ("part", where[member]))
    return planetary(b, A, sdata, doc, name, where, unit)


def drive_keys(kind: str, k: int, eta) -> list[dict]:
    """The drive's own keys of stage k: its place in the chain and a given efficiency."""
    if kind != "drive":
        return []
    out = [A(f"{CUSTOM}drive__order", int(k))]
    if eta is not None:
        out.append(A(f"{CUSTOM}drive__efficiency", float(eta)))
    return out


def designed(doc: dict) -> dict:
    """The gear keys of a spur spec in design mode: the proposal of its design section."""
    d = doc["results"]["design"]
    return {"module": d["module_proposed"], "z1": d["z1_proposed"], "z2": d["z2_proposed"],
            "helix_angle": d["helix_angle_proposed"], "face_width": d["face_width_proposed"]}
