"""The cylindrical stages of a REXS model as [[stage]] tables of the drive spec: their
order along the power flow, gears, flanks, materials and the lubricant."""

from __future__ import annotations

from geardesign.rexs.common import custom, src
from geardesign.rexs.model import Component, ModelError, convert, number
from geardesign.rexs.reader import DEFAULT_MATERIAL, _Reader
from geardesign.rexs.writer import Writer, fmt

def _chain(r: _Reader, stages, start) -> list:
    """The stages in power-flow order from the shaft ``start``: each stage's driving gear
    is on the shaft the previous one drove.  A cycle or a branch is one line."""
    left = list(stages)
    chain, shaft, seen = [], start, {start.id}
    while left:
        nxt = [(st, a, b) for st, a, b in left
               if r.shaft_of(a) is shaft or r.shaft_of(b) is shaft]
        if not nxt:
            break
        if len(nxt) > 1:
            raise ModelError(f"shaft {shaft.id} \"{shaft.name}\" drives {len(nxt)} stages "
                             f"({', '.join(s.id for s, _, _ in nxt)}): the drive computes one "
                             f"chain of stages, not a split power path")
        st, a, b = nxt[0]
        if r.shaft_of(a) is not shaft:
            a, b = b, a
        left.remove(nxt[0])
        shaft = r.shaft_of(b)
        if shaft.id in seen:
            raise ModelError(f"the stages form a cycle: stage {st.id} leads back to shaft "
                             f"{shaft.id}")
        seen.add(shaft.id)
        chain.append((st, a, b))
    if not chain:
        raise ModelError(f"no stage has a gear on shaft {start.id}, where the torque enters")
    return chain


def _flank(r: _Reader, gear: Component) -> tuple[Component | None, Component | None]:
    for rel in r.m.relations:
        if rel.type == "flank" and rel.role("gear") == gear.id:
            left, right = rel.role("left"), rel.role("right")
            return (r.comp(left, rel) if left else None, r.comp(right, rel) if right else None)
    return None, None


def _stage(r: _Reader, out: Writer, i: int, st: Component, a: Component, b: Component) -> dict:
    out.table("stage", array=True)
    out.kv("name", st.name or f"stage {st.id}", f"component {st.id} ({st.type}) name")
    out.kv("kind", "spur", "a cylindrical stage")
    extra = {k: v for k, v in custom(st).items() if not k.startswith("drive__")}
    if "drive__efficiency" in custom(st):
        out.kv("efficiency", *custom(st)["drive__efficiency"])
    out.table("stage.gear")
    mn, s_mn = r.value(a, "normal_module", "mm")
    mn2, _ = r.value(b, "normal_module", "mm")
    if mn is None:
        raise ModelError(f"cylindrical_gear {a.id} states no normal_module")
    if mn2 is not None and abs(mn2 - mn) > 1e-9 * mn:
        raise ModelError(f"stage {st.id}: the gears' normal modules differ ({mn}, {mn2} mm)")
    out.kv("module", mn, s_mn)
    z = []
    for g in (a, b):
        t = g.attributes.get("number_of_teeth")
        if t is None:
            raise ModelError(f"cylindrical_gear {g.id} states no number_of_teeth")
        zz = number(t, f"component {g.id} (cylindrical_gear)")
        if not zz.is_integer():
            raise ModelError(f"cylindrical_gear {g.id}: number_of_teeth = {t.value} is not "
                             f"a whole number")
        z.append(int(zz))
    internal = z[1] < 0 or z[0] < 0
    out.kv("z1", abs(z[0]), src(a, "number_of_teeth"))
    out.kv("z2", abs(z[1]), src(b, "number_of_teeth"))
    beta, s_beta = r.value(a, "helix_angle_reference_diameter", "deg", 0.0)
    out.kv("helix_angle", abs(beta), (s_beta + " (its magnitude; the hand is the sign)")
           if s_beta else "none stated: spur")
    widths = [(r.value(g, "face_width", "mm"), g) for g in (a, b)]
    common, s_common = r.value(st, "common_face_width", "mm")
    if common is not None:
        out.kv("face_width", common, s_common)
    else:
        given = [(w, g) for (w, _), g in widths if w is not None]
        if not given:
            raise ModelError(f"stage {st.id}: no face_width of its gears")
        w, g = min(given, key=lambda x: x[0])
        out.kv("face_width", w, src(g, "face_width") + " (the narrower gear: the working "
                                                        "face width)")
    xs, alpha = [], None
    for g in (a, b):
        left, right = _flank(r, g)
        f = left or right
        x = None
        if f is not None:
            x, s_x = r.value(f, "addendum_modification_coefficient", "")
            al, s_al = r.value(f, "normal_pressure_angle", "deg")
            if al is not None and alpha is None:
                alpha = (al, s_al)
            if right is not None and left is not None:
                x_r, _ = r.value(right, "addendum_modification_coefficient", "")
                if x is not None and x_r is not None and abs(x_r - x) > 1e-9:
                    r.skip(right, f"right flank shift {x_r} differs from the left flank's {x}: "
                                  f"the left one is used")
            if x is not None:
                r.read.add(f.type)
                xs.append((x, s_x))
                continue
        xs.append((None, None))
    if alpha is not None:
        out.kv("pressure_angle", alpha[0], alpha[1])
    a_w, s_aw = r.value(st, "center_distance", "mm")
    if xs[0][0] is not None and xs[1][0] is not None:
        out.kv("x1", xs[0][0], xs[0][1])
        out.kv("x2", xs[1][0], xs[1][1])
        if a_w is not None:
            out.comment(f"center_distance = {fmt(a_w)} mm stated ({s_aw}): follows from "
                        f"x1 + x2, compared in the report of the import")
    elif a_w is not None:
        out.kv("center_distance", a_w, s_aw)
        if xs[0][0] is not None:
            out.kv("x1", xs[0][0], xs[0][1])
    if internal:
        out.kv("internal", True, "a negative number_of_teeth: an internal gear")
    gear_keys = {k.split("__", 1)[1]: v for k, v in extra.items() if k.startswith("gear__")}
    for k, (v, s_) in gear_keys.items():
        out.kv(k, v, s_)
    if "bearing_scheme" not in gear_keys:
        out.kv("bearing_scheme", 5, "assumed: GOST 21354-87 chart 5 (REXS has no such attribute)")
    tips = {}
    for key, g in (("d_a1", a), ("d_a2", b)):
        da, s_da = r.value(g, "tip_diameter", "mm")
        if da is not None:
            tips[key] = (da, s_da)
            out.comment(f"{key} = {fmt(da)} mm stated ({s_da})")
    for key, g in (("d1", a), ("d2", b)):
        d, s_d = r.value(g, "reference_circle_diameter", "mm")
        if d is not None:
            tips[key] = (d, s_d)
    if a_w is not None:
        tips["a_w"] = (a_w, s_aw)
    ratio, s_u = r.value(st, "gear_ratio", "")
    if ratio is not None:
        tips["u"] = (ratio, s_u)
    tables: dict[str, dict] = {}
    for k, v in extra.items():
        if not k.startswith("gear__") and "__" in k:
            t, key = k.rsplit("__", 1)
            tables.setdefault(t.replace("__", "."), {})[key] = v
    ka, s_ka = r.value(st, "application_factor_iso_6336_2006", "")
    if ka is not None:
        tables.setdefault("load", {})["application_factor"] = (ka, s_ka)
    for t, keys in tables.items():
        out.table(f"stage.{t}")
        for k, (v, s_) in keys.items():
            out.kv(k, v, s_)
    for block in r.spectrum:
        out.table("stage.load.spectrum", array=True)
        for k, (v, s_) in block.items():
            out.kv(k, v, s_)
    for side, g in (("pinion", a), ("wheel", b)):
        out.table(f"stage.material.{side}")
        mat = _material(r, g)
        if mat is None:
            for k, v in DEFAULT_MATERIAL.items():
                out.kv(k, v, "assumed: the model names no material of the library"
                       if k == "grade" else "assumed with the grade")
        else:
            for k, (v, s_) in mat.items():
                out.kv(k, v, s_)
    out.blank()
    return {"stage": i, "component": st.id, "stated": tips,
            "x": [x for x, _ in xs], "internal": internal}


def _lubricant(r: _Reader, out: Writer) -> None:
    lubs = r.m.of_type("lubricant")
    if not lubs:
        return
    lub = lubs[0]
    nu40, s40 = r.value(lub, "viscosity_at_40_degree_celsius", "mm^2 / s")
    nu100, s100 = r.value(lub, "viscosity_at_100_degree_celsius", "mm^2 / s")
    rho, s_rho = r.value(lub, "density_at_15_degree_celsius", "kg / m^3")
    out.comment(f"lubricant: component {lub.id} \"{lub.name}\": ν40 = "
                f"{fmt(nu40) if nu40 else '?'} mm²/s ({s40}), ν100 = "
                f"{fmt(nu100) if nu100 else '?'} mm²/s, ρ15 = {fmt(rho) if rho else '?'} kg/m³:"
                f" the drive rates the losses only with [lubrication] and a housing, which "
                f"REXS does not describe; not applied")
    r.skip(lub, "the losses and the heat balance need the housing, which the model does not "
                "give")
    out.blank()


def _material(r: "_Reader", gear: Component) -> dict[str, tuple] | None:
    """The [material] table of a gear from the material its ``reference`` relation names,
    when that names a grade of the library; else None."""
    from geardesign.materials import gear_steel

    mat = None
    for rel in r.m.relations:
        if rel.type == "reference" and rel.role("origin") == gear.id:
            c = r.comp(rel.role("referenced") or "", rel)
            if c.type == "material":
                mat = c
    if mat is None:
        return None
    name = r.text(mat, "material_designation") or ""
    out = {}
    if name:        # a grade of the library; none named: the treatment and hardness alone
        grade = gear_steel.normalize_grade(name)
        if grade not in gear_steel.grades():
            grade = gear_steel.equivalent_of(name)
        if not grade:
            return None
        out["grade"] = (name.strip(), src(mat, "material_designation"))
    kind = r.text(mat, "heat_treated_material_type_iso_6336_2006")
    hard = {}
    for key, aid, unit in (("hardness_HB", "surface_hardness_brinell", "HB"),
                           ("hardness_HRC", "surface_hardness_rockwell", "HRC"),
                           ("hardness_HV", "surface_hardness_vickers", "HV"),
                           ("core_HRC", "core_hardness_rockwell", "HRC")):
        a = mat.attributes.get(aid)
        if a is not None:
            hard[key] = (number(a, f"component {mat.id} (material)"), src(mat, aid))
    treat = {"normalized_wrought_low_carbon_steel": "normalized",
             "flame_or_induction_hardened_steel": "induction",
             "case_hardened_wrought_steel": "carburized",
             "nitrided_steel": "nitrided",
             "through_hardened_wrought_steel": "improved" if "hardness_HB" in hard
             else "through_hardened"}.get(kind or "")
    if treat is None or not (name or hard):
        return None
    out["treatment"] = (treat, src(mat, "heat_treated_material_type_iso_6336_2006"))
    out.update(hard)
    for k, (v, s_) in custom(mat).items():
        out.setdefault(k, (v, s_))
    for k, aid in (("E", "elastic_modulus"), ("nu", "poisson_ratio")):
        a = mat.attributes.get(aid)
        if a is not None and k not in out:
            out[k] = (convert(a, "MPa" if k == "E" else "", f"component {mat.id} (material)"),
                      src(mat, aid))
    r.read.add("material")
    r.used_materials.add(mat.id)
    return out
