"""The gears and meshes of a REXS stage by role (:func:`members`), the geometry it states
(:func:`stated`), and one planetary or worm stage of another program's model as a
``planetary`` or ``worm`` spec: the spec keys from the standard attributes, what the model
does not state assumed and said (docs/rexs.md, "Planetary and worm stages")."""

from __future__ import annotations

from geardesign.rexs import stages as ST
from geardesign.rexs.common import src
from geardesign.rexs.cylindrical import _flank, _material
from geardesign.rexs.model import Component, ModelError
from geardesign.rexs.reader import DEFAULT_LIFE_HOURS, DEFAULT_MATERIAL, _Reader
from geardesign.rexs.writer import Writer


def _shift(r: _Reader, g: Component):
    left, right = _flank(r, g)
    for f in (left, right):
        if f is not None:
            x, s_x = r.value(f, "addendum_modification_coefficient", "")
            if x is not None:
                r.read.add(f.type)
                return x, s_x
    return None, None


def planetary(r: _Reader, out: Writer, st: Component, T_in: float, torque_load, case_no,
               load_shaft, speed, life, output: str | None = None) -> dict:
    """A planetary stage of another program: [train], [teeth], [shift], [operation],
    [strength], [material.*] from the standard attributes; the output member ``output``
    (in a chain: the member the next stage is on), else the one whose shaft carries the
    other torque-transmitting external_load."""
    mem = members(r, st, "planetary")
    sun, planet, ring, mesh = mem["sun"], mem["planet"], mem["ring"], mem["sun_planet"]
    shafts = {"sun": r.shaft_of(sun), "ring": r.shaft_of(ring)}
    for rel in r.m.related("planet_carrier_shaft", planetary_stage=st.id):
        shafts.setdefault("carrier", r.comp(rel.role("shaft") or "", rel))
    carriers = {rel.role("shaft") for rel in r.m.related("planet_carrier_shaft",
                                                         planetary_stage=st.id)}
    member_of = {sh.id: k for k, sh in shafts.items() if sh is not None}
    member_of.update({cid: "carrier" for cid in carriers})
    inp = member_of.get(load_shaft.id)
    if inp is None or speed[1].id != load_shaft.id:
        raise ModelError(f"the torque (shaft {load_shaft.id}) and the speed (shaft "
                         f"{speed[1].id}) must be given on one member of planetary_stage "
                         f"{st.id} (its sun, ring or carrier shaft)")
    given = output is not None
    driven = {output} if given else set()
    for ld in (() if output else r.m.of_type("external_load")):
        if ld is torque_load:
            continue
        tt = ld.attributes.get("transmits_torque")
        if tt is not None and str(tt.value).lower() == "true":
            for rel in r.m.relations:
                if rel.type == "assembly" and rel.role("part") == ld.id:
                    if rel.role("assembly") in member_of:
                        driven.add(member_of[rel.role("assembly")])
    driven.discard(inp)
    if len(driven) != 1:
        raise ModelError(f"planetary_stage {st.id}: the driven member is the one whose shaft "
                         f"carries the other torque-transmitting external_load; found "
                         f"{sorted(driven) or 'none'}")
    output = driven.pop()
    fixed = ({"sun", "ring", "carrier"} - {inp, output}).pop()
    out.table("train")
    out.kv("planets", mem["planets"], f"the planet gears of planetary_stage {st.id}")
    mn, s_mn = r.value(sun, "normal_module", "mm")
    out.kv("module", mn, s_mn)
    beta, s_beta = r.value(sun, "helix_angle_reference_diameter", "deg", 0.0)
    if beta:
        out.kv("helix_angle", abs(beta), s_beta + " (its magnitude)")
    b, s_b = r.value(mesh, "common_face_width", "mm")
    if b is None:
        widths = [(r.value(g, "face_width", "mm"), g) for g in (sun, planet)]
        (b, s_b), _ = min(((w, g) for w, g in widths if w[0] is not None),
                          key=lambda x: x[0][0])
    out.kv("face_width", b, s_b)
    a_w, s_aw = r.value(mesh, "center_distance", "mm")
    if a_w is not None:
        out.kv("center_distance", a_w, s_aw)
    out.blank()
    out.table("teeth")
    for key, g in (("sun", sun), ("planet", planet), ("ring", ring)):
        z = r.value(g, "number_of_teeth", "")
        if z[0] is None:
            raise ModelError(f"{g.type} {g.id} states no number_of_teeth")
        out.kv(key, int(round(abs(z[0]))), z[1])
    out.blank()
    x_sun = _shift(r, sun)
    if x_sun[0] is not None and a_w is not None:
        out.table("shift")
        out.kv("sun", x_sun[0], x_sun[1] + " (the planet's follows from the centre distance)")
        out.blank()
    out.table("operation")
    out.kv("fixed", fixed, "the member whose shaft carries neither the input torque nor a "
                           "torque-transmitting load")
    out.kv("input", inp, f"the member on shaft {load_shaft.id}, which carries the torque")
    out.kv("output", output, "the member whose shaft carries the other torque-transmitting "
                             "external_load" if not given else
                             "the member whose shaft the next stage is on")
    out.kv("speed", speed[0], speed[2])
    out.kv("torque", T_in, src(torque_load, "torque_around_u_axis", case_no))
    out.blank()
    out.table("strength")
    out.kv("life_hours", life[0] or DEFAULT_LIFE_HOURS,
           life[1] or "assumed: the gear unit states no operating_time")
    out.blank()
    from geardesign.drive.stages import ETA_CYLINDRICAL

    out.table("efficiency")
    out.kv("model", "given", "assumed: the model states no mesh efficiency (the H_V model "
                             "holds for ε_α ≤ 2 only)")
    for key in ("external", "internal"):
        out.kv(key, ETA_CYLINDRICAL, "assumed: the drive's handbook efficiency of a "
                                     "cylindrical mesh")
    out.blank()
    for key, g in (("sun", sun), ("planet", planet), ("ring", ring)):
        mat = _material(r, g)
        out.table(f"material.{key}")
        if mat is None:
            for k, v in DEFAULT_MATERIAL.items():
                out.kv(k, v, "assumed: the model names no material of the library with its "
                             "heat treatment" if k == "grade" else "assumed with the grade")
        else:
            for k, (v, s_) in mat.items():
                out.kv(k, v, s_)
        out.blank()
    r.read.update({"planetary_stage", "planet_carrier", "cylindrical_stage",
                   "cylindrical_gear", "ring_gear"})
    return stated(r, st, "planetary")


def worm(r: _Reader, out: Writer, st: Component, T_in: float, torque_load, case_no,
          load_shaft, speed, life) -> dict:
    """A worm stage of another program: [gear], [load], [wheel] from the standard
    attributes; the torque must act on the wheel shaft (the worm calculator takes T2)."""
    mem = members(r, st, "worm")
    w, wheel = mem["worm"], mem["wheel"]
    if r.shaft_of(wheel) is not load_shaft or r.shaft_of(w) is not speed[1]:
        raise ModelError(f"worm_stage {st.id}: the worm calculator takes the wheel torque and "
                         f"the worm speed; the model gives the torque on shaft "
                         f"{load_shaft.id} and the speed on shaft {speed[1].id}")
    out.table("gear")
    m_x, s_m = r.value(w, "axial_module", "mm")
    if m_x is None:
        raise ModelError(f"worm_gear {w.id} states no axial_module")
    out.kv("module", m_x, s_m)
    d1, s_d1 = r.value(w, "reference_diameter_worm_gear", "mm")
    if d1 is not None:
        out.kv("diameter_factor", round(d1 / m_x, 9), s_d1 + " / axial_module")
    for key, g in (("z1", w), ("z2", wheel)):
        z = r.value(g, "number_of_teeth", "")
        if z[0] is None:
            raise ModelError(f"{g.type} {g.id} states no number_of_teeth")
        out.kv(key, int(round(abs(z[0]))), z[1])
    a_w, s_aw = r.value(st, "center_distance", "mm")
    if a_w is not None:
        out.kv("center_distance", a_w, s_aw)
    form = r.text(w, "flank_form")
    types = {v: k for k, v in ST.WORM_TYPES.items()}
    if form in types:
        out.kv("worm_type", types[form], src(w, "flank_form"))
    gamma, s_g = r.value(w, "lead_angle_worm_gear", "deg")
    if gamma is not None and gamma < 0:
        out.kv("hand", "left", s_g + " < 0")
    b2, s_b2 = r.value(wheel, "face_width_worm_wheel", "mm")
    if b2 is None:
        b2, s_b2 = r.value(wheel, "effective_face_width_worm_wheel", "mm")
    if b2 is not None:
        out.kv("face_width", b2, s_b2)
    L, s_L = r.value(w, "length_worm_gear", "mm")
    if L is not None:
        out.kv("worm_length", L, s_L)
    out.blank()
    out.table("load")
    out.kv("torque2", T_in, src(torque_load, "torque_around_u_axis", case_no))
    out.kv("speed1", speed[0], speed[2])
    out.kv("life", life[0] or DEFAULT_LIFE_HOURS,
           life[1] or "assumed: the gear unit states no operating_time")
    out.blank()
    out.table("wheel")
    out.kv("material", "BrO10F1_chill", "assumed: REXS names the wheel's material by "
                                        "designation, not by the rim bronzes of the library")
    out.blank()
    r.read.update({"worm_stage", "worm_gear", "worm_wheel"})
    return stated(r, st, "worm")


def members(r: _Reader, st: Component, kind: str) -> dict[str, Component]:
    """The stage's gears and meshes by role: sun, planet, ring, sun_planet (the first
    sun–planet cylindrical_stage), planets (their count); worm, wheel, stage."""
    m = r.m
    out: dict = {"stage": st}
    if kind == "spur":
        rel = m.related("stage", stage=st.id)
        if not rel:
            raise ModelError(f"cylindrical_stage {st.id} has no stage relation")
        for i, role in ((1, "gear_1"), (2, "gear_2")):
            g = r.comp(rel[0].role(role) or "", rel[0])
            out[f"gear{i}"] = g
            left, right = _flank(r, g)
            if left is not None or right is not None:
                out[f"flank{i}"] = left or right
        return out
    if kind == "worm":
        return pair_members(r, st, "worm", "wheel")
    meshes = [rel.role("part") for rel in m.relations if rel.type == "assembly"
              and rel.role("assembly") == st.id]
    planets = set()
    for cid in meshes:
        c = r.comp(cid)
        if c.type != "cylindrical_stage":
            continue
        for rel in m.related("stage", stage=c.id):
            g1, g2 = r.comp(rel.role("gear_1") or "", rel), r.comp(rel.role("gear_2") or "", rel)
            for g in (g1, g2):
                if r.shaft_of(g) is None:
                    raise ModelError(f"{g.type} {g.id} \"{g.name}\" of stage {c.id} is on no "
                                     f"shaft (no assembly relation shaft → gear)")
            if g2.type == "ring_gear":
                out.setdefault("ring", g2)
                out.setdefault("planet_ring", c)
                planets.add(g1.id)
            else:
                out.setdefault("sun", g1)
                out.setdefault("sun_planet", c)
                out.setdefault("planet", g2)
                planets.add(g2.id)
    for need in ("sun", "planet", "ring"):
        if need not in out:
            raise ModelError(f"planetary_stage {st.id} \"{st.name}\": no {need} found (its "
                             f"cylindrical stages' relations gear_1/gear_2)")
    out["planets"] = len(planets)
    return out


def pair_members(r: _Reader, st: Component, first: str, second: str) -> dict[str, Component]:
    """The two gears of a worm or bevel stage by role: ``first`` is ``gear_1`` of its
    ``stage`` relation, ``second`` ``gear_2``, each on a shaft (else one line)."""
    out: dict = {"stage": st}
    for rel in r.m.related("stage", stage=st.id):
        out[first] = r.comp(rel.role("gear_1") or "", rel)
        out[second] = r.comp(rel.role("gear_2") or "", rel)
    if first not in out:
        raise ModelError(f"{st.type} {st.id} has no stage relation naming its {first} and "
                         f"{second}")
    for g in (out[first], out[second]):
        if r.shaft_of(g) is None:
            raise ModelError(f"{g.type} {g.id} \"{g.name}\" of stage {st.id} is on no "
                             f"shaft (no assembly relation shaft → gear)")
    return out


def stated(r: _Reader, st: Component, kind: str) -> dict:
    """The geometry the model states, for the comparison with the computed one."""
    mem = members(r, st, kind)
    stated = {}
    if kind == "spur":
        for key, role, aid in (("a_w", "stage", "center_distance"),
                               ("d1", "gear1", "reference_circle_diameter"),
                               ("d_a1", "gear1", "tip_diameter"),
                               ("d2", "gear2", "reference_circle_diameter"),
                               ("d_a2", "gear2", "tip_diameter"), ("u", "stage", "gear_ratio")):
            v, s_ = r.value(mem[role], aid, "" if key == "u" else "mm")
            if v is not None:
                stated[key] = (v, s_)
    elif kind == "worm":
        for key, role, aid in (("a_w", "stage", "center_distance"),
                               ("d1", "worm", "reference_diameter_worm_gear"),
                               ("d_a1", "worm", "tip_diameter_worm_gear"),
                               ("d_f1", "worm", "root_diameter_worm_gear"),
                               ("gamma", "worm", "lead_angle_worm_gear"),
                               ("d2", "wheel", "reference_diameter_worm_gear"),
                               ("d_a2", "wheel", "tip_diameter_worm_gear"),
                               ("d_f2", "wheel", "root_diameter_worm_gear"),
                               ("u", "stage", "gear_ratio")):
            v, s_ = r.value(mem[role], aid, "deg" if key == "gamma" else
                            "" if key == "u" else "mm")
            if v is not None:
                stated[key] = (abs(v), s_)
    else:
        for key, role, aid in (("a_w", "sun_planet", "center_distance"),
                               ("a_w_ring", "planet_ring", "center_distance"),
                               ("d_sun", "sun", "reference_circle_diameter"),
                               ("d_a_sun", "sun", "tip_diameter"),
                               ("d_planet", "planet", "reference_circle_diameter"),
                               ("d_a_planet", "planet", "tip_diameter"),
                               ("d_ring", "ring", "reference_circle_diameter"),
                               ("d_a_ring", "ring", "tip_diameter")):
            v, s_ = r.value(mem[role], aid, "mm")
            if v is not None:
                stated[key] = (v, s_)
    return {"stage": 1, "component": st.id, "stated": stated}


REASONS = {
    "gear_casing": "the housing is not modelled",
    "concept_bearing": "the stage calculators rate no shaft bearings",
    "rolling_bearing_with_catalog_geometry": "the stage calculators rate no shaft bearings",
    "shaft_section": "the stage calculators analyse no shafts",
    "coupling": "the stage calculators model no couplings",
    "switchable_coupling": "the stage calculators model no couplings",
    "side_plate": "the carrier's structure is not modelled",
    "material": "names no grade of the library, or no heat treatment (the calculator's "
                "default material)",
    "stage_gear_data": "per-stage gear data (tolerances, roughness) are not used",
    "worm_stage_gear_data": "per-stage gear data (tolerances, roughness) are not used",
    "cylindrical_gear_flank": "the flank data are computed from the spec's keys",
    "flank_geometry": "the flank data are computed from the spec's keys",
    "worm_gear_flank": "the flank data are computed from the spec's keys",
}
"""Why a component type of a planetary, worm or bevel model is not imported (else: not
computed by the stage's calculator)."""


def _rest(r: _Reader, kind: str) -> None:
    """Every component not read is listed as not imported, with the reason."""
    r.read.update({"gear_unit", "shaft", "external_load"})
    listed = {(t, item.split(" ", 1)[0]) for t, items in r.not_imported.items()
              for item in items}
    for c in r.m.components.values():
        if c.type not in r.read and c.type != "lubricant" and (c.type, c.id) not in listed:
            r.skip(c, REASONS.get(c.type, f"not computed by the {kind} calculator"))
    for c in r.m.of_type("material"):
        if c.type in r.read and c.id not in r.used_materials:
            r.skip(c, REASONS["material"])
