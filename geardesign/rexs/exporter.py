"""A spur, planetary, worm, bevel or drive spec as a REXS 1.5 model (XML or JSON).

The gear unit is written with the standard attribute ids and units of the REXS 1.5
database (geardesign/rexs/rexs_database_1.5.json, [REXS-DB]): shafts (sections from
``[[shaft.step]]``, external forces from ``[[shaft.load]]``), cylindrical stages and gears
with their flanks and materials, planetary and worm stages (:mod:`geardesign.rexs.stages`),
bevel stages (:mod:`geardesign.rexs.bevel`),
rolling bearings by catalogue designation, the load case (input torque and speed), and the computed
values REXS has attributes for (reference, tip, root and base diameters, centre distance,
ratio, transverse, overlap and total contact ratio).  A key of the spec that REXS has no
attribute for (``bearing_scheme``, ``accuracy_grade``, the GOST regime, ...) is written as a
custom attribute ``custom_geardesign__<table>__<key>`` (REXS reserves the ``custom_`` prefix
for a program's own data) so that ``geardesign import`` restores it.  What is written,
attribute by attribute: docs/rexs.md.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from geardesign.core.errors import InputError, Problem
from geardesign.rexs.common import CUSTOM, A, text_suffix
from geardesign.rexs.serialize import to_json, to_xml
from geardesign.rexs.stages import designed, drive_keys, other_stage, stage_load

VERSION = "1.5"
KINDS = ("spur", "planetary", "worm", "bevel", "drive")
"""Spec kinds ``export`` writes (a drive of spur, planetary, worm and bevel stages)."""
STAGE_KINDS = ("spur", "planetary", "worm", "bevel")
"""Stage kinds of a drive ``export`` writes."""

TREATMENT_ISO6336 = {
    "normalized": "normalized_wrought_low_carbon_steel",
    "improved": "through_hardened_wrought_steel",
    "through_hardened": "through_hardened_wrought_steel",
    "induction": "flame_or_induction_hardened_steel",
    "carburized": "case_hardened_wrought_steel",
    "nitrided": "nitrided_steel",
}
"""Our heat treatment → REXS ``heat_treated_material_type_iso_6336_2006`` (ISO 6336-5
material types); improved and through-hardened share one type and are told apart by the
hardness scale (HB or HRC)."""
HARDNESS = (("hardness_HB", "surface_hardness_brinell", "HB"),
            ("hardness_HRC", "surface_hardness_rockwell", "HRC"),
            ("hardness_HV", "surface_hardness_vickers", "HV"),
            ("core_HRC", "core_hardness_rockwell", "HRC"))


class _Builder:
    def __init__(self):
        self.components: list[dict] = []
        self.relations: list[dict] = []
        self.case: list[dict] = []
        self._next = 1

    def new(self, ctype: str, name: str, attrs: list | None = None) -> dict:
        c = {"id": self._next, "type": ctype, "name": name, "attributes": list(attrs or [])}
        self._next += 1
        self.components.append(c)
        return c

    def rel(self, rtype: str, *refs: tuple[str, dict]) -> None:
        self.relations.append({"id": len(self.relations) + 1, "type": rtype,
                               "refs": [{"id": c["id"], "role": role, "hint": c["type"]}
                                        for role, c in refs]})


def _custom(prefix: str, table: dict, skip=()) -> list[dict]:
    """The scalar keys of ``table`` (nested tables flattened with ``__``) as custom
    attributes; lists are not written."""
    out = []
    for k, v in table.items():
        if k in skip or v is None:
            continue
        if isinstance(v, dict):
            out.extend(_custom(f"{prefix}{k}__", v))
        elif isinstance(v, (bool, int, float, str)):
            out.append(A(f"{CUSTOM}{prefix}{k}{text_suffix(v)}", v))
        elif isinstance(v, list) and v and all(isinstance(x, str) for x in v):
            out.append(A(f"{CUSTOM}{prefix}{k}", list(v), vtype="string_array"))
    return out


def export_spec(path: Path, fmt: str = "xml") -> str:
    """The REXS text of the spec at ``path`` (a spur, planetary, worm, bevel or drive spec); a
    spec of another kind, or a drive with a stage of another kind, is one
    :class:`InputError` line."""
    from geardesign.core import registry
    from geardesign.core.spec import load_toml

    calc, spec = registry.load(path)
    if calc.kind not in KINDS:
        raise InputError(Problem("kind", f"export writes {', '.join(KINDS)} specs; this is a "
                                         f"{calc.kind} spec", calc.kind))
    result = calc.compute(spec)
    doc = result.document()
    b = _Builder()
    unit = b.new("gear_unit", doc.get("title") or path.stem)
    casing = b.new("gear_casing", "casing")
    b.rel("assembly", ("assembly", unit), ("part", casing))
    load_at = 0            # the shaft of the input torque (index into the shafts)
    if calc.kind == "spur":
        stages = [doc]
        kinds = [("spur", None, None, None)]
        data = spec.data
        ld = doc["inputs"].get("load") or {}
        T_in, n_in = ld.get("torque1"), ld.get("speed1")
        if T_in is None and ld.get("power") is not None and n_in:
            T_in = ld["power"] * 1000.0 / (2.0 * math.pi * n_in / 60.0)
        life = ld.get("life_hours")
        shafts_spec: list[dict] = []
        unit["attributes"].append(A(f"{CUSTOM}source_kind", "spur"))
        raw_spur = load_toml(path)
    elif calc.kind in ("planetary", "worm", "bevel"):
        stages, data, shafts_spec = [doc], {}, []
        raw = load_toml(path)
        kinds = [(calc.kind, raw, doc.get("title") or path.stem, None)]
        unit["attributes"].append(A(f"{CUSTOM}source_kind", calc.kind))
        if calc.kind == "bevel":
            from geardesign.rexs.bevel import stage_load as bevel_load

            T_in, n_in, life, load_at = bevel_load(doc)
        else:
            T_in, n_in, life, load_at = stage_load(calc.kind, doc)
    else:
        from geardesign.drive.calculator import resolve_stages

        stages = doc["results"].get("stage_reports") or []
        resolved = resolve_stages(spec.data["stage"] or [], spec.base_dir)
        kinds = []
        for k, (st, (_, name, sdata, eta)) in enumerate(zip(stages, resolved), 1):
            if st.get("kind") not in STAGE_KINDS:
                raise InputError(Problem(f"stage[{k - 1}]", f"is a {st.get('kind')} stage; "
                                         f"export writes drives of "
                                         f"{', '.join(STAGE_KINDS)} stages"))
            kinds.append((st["kind"], sdata, name, eta))
        data = spec.data
        drv = doc["results"]["drive"]
        T_in, n_in = drv.get("T_in"), data["motor"]["speed"]
        life = data["load"].get("life_hours")
        shafts_spec = data.get("shaft") or []
        for table, value in data.items():     # [motor], [load], [split], [thermal], ...
            if isinstance(value, dict):
                unit["attributes"] += _custom(f"{table}__", value)
    if life:
        unit["attributes"].append(A("operating_time", float(life), "h"))
    n_shafts = len(stages) + 1
    by_index = {int(s["index"]): s for s in shafts_spec}
    shafts = []
    for i in range(1, n_shafts + 1):
        sh = b.new("shaft", (by_index.get(i) or {}).get("name") or f"shaft {i}")
        b.rel("assembly", ("assembly", unit), ("part", sh))
        shafts.append(sh)
    gear_pos, gear_extra = {}, {}
    for i, sd in by_index.items():
        for g in sd.get("gear") or []:
            gear_pos[(i, int(g["stage"]))] = (float(g.get("position", 0.0)),
                                             float(g.get("mate_angle", 0.0)))
            gear_extra[(i, int(g["stage"]))] = _custom("", {k: v for k, v in g.items()
                                                            if k in ("axial_sign", "mass")})
    centres = [(0.0, 0.0)]
    for k, st in enumerate(stages, 1):
        kind, sdata, sname, eta = kinds[k - 1]
        if kind != "spur":
            centres.append(centres[-1])
            if kind == "bevel":
                from geardesign.rexs.bevel import export as bevel_stage

                comp = bevel_stage(b, A, sdata, st, sname or f"stage {k}",
                                   (shafts[k - 1], shafts[k]), unit)
            else:
                comp = other_stage(b, kind, sdata, st, sname or f"stage {k}", shafts, k, unit)
            comp["attributes"] += drive_keys(calc.kind, k, eta)
            if kind in ("worm", "bevel"):
                _place(b, comp, k, gear_pos, gear_extra)
            continue
        inp = st["inputs"]
        geo = st["results"]["geometry"]
        gear = inp.get("gear") or designed(st)
        stage = b.new("cylindrical_stage", (data.get("stage") or [{}])[k - 1].get("name")
                      if calc.kind == "drive" and (data.get("stage") or [{}])[k - 1].get("name")
                      else f"stage {k}")
        b.rel("assembly", ("assembly", unit), ("part", stage))
        stage["attributes"] += [
            A("center_distance", float(geo["a_w"]), "mm"),
            A("gear_ratio", float(geo["u"])),
            A("radial_contact_ratio", float(geo["eps_alpha"])),
            A("overlap_contact_ratio", float(geo["eps_beta"])),
            A("total_contact_ratio", float(geo["eps_gamma"])),
        ]
        stage["attributes"] += drive_keys(calc.kind, k, eta)
        ka = (inp.get("load", {}) if sdata is None else sdata.get("load") or {}).get(
            "application_factor")
        if ka is not None:
            stage["attributes"].append(A("application_factor_iso_6336_2006", float(ka)))
        standard = ("module", "z1", "z2", "helix_angle", "face_width", "x1", "x2",
                    "center_distance", "pressure_angle", "shift_split")
        if sdata is not None:
            # a drive's stage: its tables as written (the report's inputs hold what the drive
            # set: the loads, the shaft's misalignment f_sh, the oil of the heat balance)
            extra = {t: v for t, v in sdata.items()
                     if isinstance(v, dict) and t not in ("gear", "material", "load")}
            extra["gear"] = {kk: v for kk, v in (sdata.get("gear") or {}).items()
                             if kk not in standard}
            extra["load"] = {kk: v for kk, v in (sdata.get("load") or {}).items()
                             if kk not in ("torque1", "speed1", "power", "application_factor")}
        else:
            extra = {t: inp.get(t) for t in ("rack", "options", "iso")
                     if isinstance(inp.get(t), dict)}
            extra["gear"] = {kk: v for kk, v in gear.items() if kk not in standard}
            extra["load"] = {kk: v for kk, v in inp.get("load", {}).items() if kk in (
                "regime", "meshes_pinion", "meshes_wheel", "reverse_torque_ratio")}
        if calc.kind == "spur":     # the spec as written (geometry keys: standard attributes)
            from geardesign.rexs.stages import SPUR_KEYS, spec_customs, spec_value

            stage["attributes"] += spec_customs(A, raw_spur, {
                key for key, *_ in SPUR_KEYS if spec_value(raw_spur, key) is not None})
        else:
            stage["attributes"] += _custom("", extra)
        # shafts placed in the v-w plane by the mate angle of the driving gear
        z_in, theta = gear_pos.get((k, k), (0.0, 0.0))
        z_out, _ = gear_pos.get((k + 1, k), (0.0, 0.0))
        cy, cz = centres[-1]
        th = math.radians(theta)
        centres.append((cy + geo["a_w"] * math.cos(th), cz + geo["a_w"] * math.sin(th)))
        gears = []
        for side, (j, z_u, sign) in zip(("1", "2"), ((k - 1, z_in, 1.0), (k, z_out, -1.0))):
            m = st["inputs"]["material"][("pinion", "wheel")[int(side) - 1]] \
                if isinstance(st["inputs"].get("material"), dict) else None
            g = b.new("cylindrical_gear", f"stage {k} gear {side}", [
                A("normal_module", float(gear["module"]), "mm"),
                A("number_of_teeth", int(gear[f"z{side}"])),
                A("helix_angle_reference_diameter", sign * float(gear.get("helix_angle", 0.0)),
                  "deg"),
                A("face_width", float(gear["face_width"]), "mm"),
                A("reference_circle_diameter", float(geo[f"d{side}"]), "mm"),
                A("tip_diameter", float(geo[f"d_a{side}"]), "mm"),
                A("root_diameter", float(geo[f"d_f{side}"]), "mm"),
                A("base_circle_diameter", float(geo[f"d_b{side}"]), "mm"),
                A("u_coordinate_on_shaft", float(z_u), "mm"),
                A("support_vector", [float(z_u), float(centres[j][0]), float(centres[j][1])],
                  "mm"),
            ] + gear_extra.get((j + 1, k), []))
            gears.append(g)
            b.rel("assembly", ("assembly", shafts[j]), ("part", g))
            flanks = []
            for hand in ("left", "right"):
                f = b.new("cylindrical_gear_flank", f"stage {k} gear {side} {hand} flank", [
                    A("normal_pressure_angle", float(gear.get("pressure_angle", 20.0)), "deg"),
                    A("addendum_modification_coefficient", float(geo[f"x{side}"])),
                ])
                flanks.append(f)
            b.rel("flank", ("gear", g), ("left", flanks[0]), ("right", flanks[1]))
            if m:
                _material(b, g, m)
        b.rel("stage", ("stage", stage), ("gear_1", gears[0]), ("gear_2", gears[1]))
    _shaft_details(b, shafts, by_index, casing)
    # the load case: torque and speed at the input shaft (a geometry-only spur spec has none)
    cases = []
    if T_in is not None and n_in is not None:
        load = b.new("external_load", "input torque", [
            A("u_coordinate_on_shaft", float((by_index.get(1) or {}).get("coupling") or 0.0),
              "mm"),
            A("transmits_torque", True), A("defines_torque", True)])
        b.rel("assembly", ("assembly", shafts[load_at]), ("part", load))
        shafts[0]["attributes"].append(A("defines_speed", True))
        blocks = ((doc["inputs"].get("load") or {}).get("spectrum") or []) \
            if calc.kind == "spur" else []
        blocks = blocks or [{"torque_ratio": 1.0, "speed_ratio": 1.0, "time_share": None}]
        for k, blk in enumerate(blocks, 1):
            comps = [
                {"id": shafts[0]["id"], "type": "shaft", "name": shafts[0]["name"],
                 "attributes": [A("rotational_speed",
                                  float(n_in) * float(blk.get("speed_ratio", 1.0)),
                                  "1 / min")]},
                {"id": load["id"], "type": "external_load", "name": load["name"],
                 "attributes": [A("torque_around_u_axis",
                                  float(T_in) * float(blk["torque_ratio"]), "N m")]}]
            if blk.get("time_share") is not None:
                comps.insert(0, {"id": unit["id"], "type": "gear_unit", "name": unit["name"],
                                 "attributes": [A("operating_time_fraction",
                                                  100.0 * float(blk["time_share"]), "%")]})
            cases.append({"id": k, "components": comps})
    _external_loads(b, shafts, by_index)
    model = {"version": VERSION, "applicationId": "geardesign",
             "applicationVersion": _version(), "date": "1970-01-01T00:00:00+00:00",
             "relations": b.relations, "components": b.components,
             "load_spectrum": {"id": 1, "load_cases": cases}}
    return to_json(model) if fmt == "json" else to_xml(model)


def _place(b: _Builder, stage: dict, k: int, gear_pos: dict, gear_extra: dict) -> None:
    """The places of the two gears of worm or bevel stage k on their shafts (``gear_1`` on
    shaft k, ``gear_2`` on shaft k + 1, from ``[[shaft.gear]]``): ``u_coordinate_on_shaft``
    [mm] and, as their axes cross, the mate angle of the drive (the direction of the mesh
    force in the plane normal to the shaft) as the custom attribute
    ``custom_geardesign__mate_angle`` [deg] rather than a ``support_vector``."""
    rel = next(r for r in b.relations if r["type"] == "stage"
               and r["refs"][0]["id"] == stage["id"])
    by_id = {c["id"]: c for c in b.components}
    for j, ref in zip((k, k + 1), rel["refs"][1:]):
        g = by_id[ref["id"]]
        if (j, k) in gear_pos:
            z, theta = gear_pos[(j, k)]
            g["attributes"] += [A("u_coordinate_on_shaft", z, "mm"),
                                A(f"{CUSTOM}mate_angle", theta)]
        g["attributes"] += gear_extra.get((j, k), [])


def _external_loads(b: _Builder, shafts: list, by_index: dict) -> None:
    """The forces of ``[[shaft.load]]`` as ``external_load`` components at
    ``u_coordinate_on_shaft`` [mm]: ``force_u_direction`` the axial force, the radial force
    F at the angle θ (from the drive's x axis, as the mate angle) as ``force_v_direction``
    = F cos θ and ``force_w_direction`` = F sin θ [N] (REXS's v–w plane is the drive's
    x–y plane, as for ``support_vector``); the name and the mass as custom attributes."""
    for i, sd in by_index.items():
        for n, ld in enumerate(sd.get("load") or [], 1):
            F, th = float(ld.get("force", 0.0)), math.radians(float(ld.get("angle", 0.0)))
            attrs = [A("u_coordinate_on_shaft", float(ld.get("position", 0.0)), "mm"),
                     A("transmits_torque", False),
                     A("force_u_direction", float(ld.get("axial", 0.0)), "N"),
                     A("force_v_direction", F * math.cos(th), "N"),
                     A("force_w_direction", F * math.sin(th), "N")]
            attrs += _custom("", {kk: v for kk, v in ld.items() if kk in ("mass", "name")})
            c = b.new("external_load", ld.get("name") or f"shaft {i} load {n}", attrs)
            b.rel("assembly", ("assembly", shafts[i - 1]), ("part", c))


def _version() -> str:
    from geardesign import __version__

    return __version__


def _material(b: _Builder, gear: dict, m: dict) -> None:
    attrs = []
    if m.get("grade"):
        attrs.append(A("material_designation", str(m["grade"])))
    t = m.get("treatment")
    if t in TREATMENT_ISO6336:
        attrs.append(A("heat_treated_material_type_iso_6336_2006", TREATMENT_ISO6336[t],
                       vtype="enum"))
    for key, aid, u in HARDNESS:
        if m.get(key) is not None:
            attrs.append(A(aid, float(m[key]), u))
    if m.get("E") is not None:
        attrs.append(A("elastic_modulus", float(m["E"]), "N / mm^2"))
    if m.get("nu") is not None:
        attrs.append(A("poisson_ratio", float(m["nu"])))
    attrs += _custom("", {k: v for k, v in m.items()
                          if k not in ("grade", "treatment", "E", "nu")
                          and k not in {h[0] for h in HARDNESS}})
    mat = b.new("material", f"{gear['name']} material", attrs)
    b.rel("reference", ("origin", gear), ("referenced", mat))


def _shaft_details(b: _Builder, shafts: list, by_index: dict, casing: dict) -> None:
    for i, sh in enumerate(shafts, 1):
        sd = by_index.get(i)
        if not sd:
            continue
        sh["attributes"] += _custom("", {k: v for k, v in sd.items()
                                         if k in ("fixed", "method", "stiffness_a",
                                                  "stiffness_b", "coupling")})
        for table, value in sd.items():     # the shaft's own tables: [shaft.lubrication], ...
            if isinstance(value, dict) and table not in ("support_a", "support_b"):
                sh["attributes"] += _custom(f"{table}__", value)
        if sd.get("key"):   # REXS 1.5 has no shaft-hub connection: the spec's tables
            keys = [{k: v for k, v in key.items() if v is not None} for key in sd["key"]]
            sh["attributes"].append(A(f"{CUSTOM}key__json", json.dumps(keys), vtype="string"))
        for side, key in (("a", "bearing_a"), ("b", "bearing_b")):
            sup = sd.get(f"support_{side}") or {}
            u = float(sd.get(key, 0.0) or 0.0)
            attrs = [A("u_coordinate_on_shaft_inner_side", u, "mm"),
                     A("u_coordinate_on_shaft_outer_side", u, "mm")]
            if sup.get("designation"):
                br = b.new("rolling_bearing_with_catalog_geometry", str(sup["designation"]),
                           attrs + [A("catalogue_designation", str(sup["designation"]))])
            else:
                br = b.new("concept_bearing", f"shaft {i} bearing {side.upper()}", attrs)
            b.rel("side", ("assembly", br), ("inner_part", sh), ("outer_part", casing))
        u = float(sd.get("start") or 0.0)
        for k, step in enumerate(sd.get("step") or [], 1):
            L, d, bore = float(step["length"]), float(step["diameter"]), float(step.get("bore", 0.0))
            sec = b.new("shaft_section", f"shaft {i} step {k}", [
                A("u_coordinate_on_shaft", u, "mm"), A("length", L, "mm"),
                A("outer_diameter_begin", d, "mm"), A("outer_diameter_end", d, "mm"),
                A("inner_diameter_begin", bore, "mm"), A("inner_diameter_end", bore, "mm")]
                + _custom("", {kk: v for kk, v in step.items()     # fillet, Rz, keyway, ...
                               if kk not in ("length", "diameter", "bore")}))
            b.rel("assembly", ("assembly", sh), ("part", sec))
            u += L


