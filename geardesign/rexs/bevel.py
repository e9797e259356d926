"""Bevel stages in REXS: written by ``geardesign export`` and read by ``geardesign import``
(docs/rexs.md, "Bevel stages").

A bevel stage is a ``bevel_stage`` with two ``bevel_gear`` components, the pinion
(``gear_1``) and the wheel (``gear_2``) of a ``stage`` relation, each on its shaft (the
REXS 1.5 bevel model, [REXS] "Bevel stages", [REXS-DB] component types ``bevel_stage`` and
``bevel_gear``).  As for planetary and worm stages (:mod:`geardesign.rexs.stages`), the
spec keys REXS has attributes for are written as those (:data:`BEVEL_KEYS`), the others as
``custom_geardesign__spec__<table>__<key>``, and the computed geometry of the calculator
(ISO 23509 / GOST 19624 and 19326 cone geometry) as the standard attributes listed in
:data:`COMPUTED`.  A bevel stage of another program is read from the standard attributes
alone (:func:`read_foreign`).
"""

from __future__ import annotations

from geardesign.rexs.chain import ModelError, Writer, _Reader, src
from geardesign.rexs.model import Component
from geardesign.rexs.stages import spec_customs, spec_value

BEVEL_KEYS = (
    # spec key, member (component role), REXS attribute, unit of the attribute
    ("pair.z1", "pinion", "number_of_teeth", "none"),
    ("pair.z2", "wheel", "number_of_teeth", "none"),
    ("pair.face_width", "pinion", "face_width", "mm"),
    ("pair.spiral_angle", "pinion", "mean_spiral_angle", "deg"),
    ("pair.shaft_angle", "stage", "shaft_angle", "deg"),
    ("pair.x1", "pinion", "profile_shift_coefficient", "none"),
    ("pair.xt1", "pinion", "thickness_modification_coefficient", "none"),
)
"""Keys of a bevel spec written as (and read from) standard REXS 1.5 attributes.  The
module ``pair.module`` is one of two attributes by ``pair.module_at``
(:data:`MODULE_AT`)."""

MODULE_AT = {"outer": ("stage", "outer_transverse_module"),
             "mean": ("pinion", "mean_normal_module")}
"""``pair.module_at`` → (member, REXS attribute) of ``pair.module`` [mm]: the outer
transverse module m_te on the stage, the mean normal module m_nm on the pinion."""

COMPUTED = (
    # REXS attribute of bevel_gear, key of the calculator's geometry (1 or 2 appended), unit
    ("outer_pitch_diameter", "d_e", "mm"),
    ("mean_pitch_diameter", "d_m", "mm"),
    ("pitch_angle", "delta", "deg"),
    ("face_angle", "delta_a", "deg"),
    ("root_angle", "delta_f", "deg"),
    ("outer_addendum", "h_ae", "mm"),
    ("outer_dedendum", "h_fe", "mm"),
)
"""Computed values of each bevel gear written as standard attributes (and compared with
the calculator's when a model states them, :func:`stated`); the cone distances R_e, R_m
(``outer_cone_distance``, ``mean_cone_distance``) are common to both members."""


def key_table(module_at: str) -> dict:
    """Spec key → (member, attribute, unit) of a bevel stage whose module is given at
    ``module_at`` (``"outer"`` or ``"mean"``)."""
    table = {k: (m, a, u) for k, m, a, u in BEVEL_KEYS}
    member, aid = MODULE_AT.get(module_at, MODULE_AT["outer"])
    table["pair.module"] = (member, aid, "mm")
    return table


def export(b, A, data: dict, doc: dict, stage_name: str, shafts: tuple, unit: dict) -> dict:
    """The components of one bevel stage: pinion on ``shafts[0]``, wheel on ``shafts[1]``;
    returns the bevel_stage component."""
    geo = doc["results"]["geometry"]
    pair = _pair(doc)
    table = key_table(str(spec_value(data, "pair.module_at") or "outer"))
    mapped = {k for k in table if spec_value(data, k) is not None}
    bs = b.new("bevel_stage", stage_name, spec_customs(A, data, mapped) + [
        A("shaft_angle", float(pair["shaft_angle"]), "deg"),
        A("outer_transverse_module", float(geo["m_te"]), "mm")])
    b.rel("assembly", ("assembly", unit), ("part", bs))
    hands = ("right", "left") if pair.get("hand", "right") == "right" else ("left", "right")
    gears = []
    for i, member in ((1, "pinion"), (2, "wheel")):
        sign = 1.0 if i == 1 else -1.0
        attrs = [A("number_of_teeth", int(pair[f"z{i}"])),
                 A("face_width", float(pair["face_width"]), "mm"),
                 A("mean_spiral_angle", float(pair.get("spiral_angle", 0.0)), "deg"),
                 A("spiral_angle_pitch_direction", hands[i - 1], vtype="enum"),
                 A("mean_normal_module", float(geo["m_nm"]), "mm"),
                 A("profile_shift_coefficient", sign * float(pair.get("x1", 0.0))),
                 A("thickness_modification_coefficient", sign * float(pair.get("xt1", 0.0))),
                 A("outer_cone_distance", float(geo["R_e"]), "mm"),
                 A("mean_cone_distance", float(geo["R_m"]), "mm")]
        attrs += [A(aid, float(geo[f"{key}{i}"]), u) for aid, key, u in COMPUTED]
        g = b.new("bevel_gear", f"{stage_name} {member}", attrs)
        b.rel("assembly", ("assembly", shafts[i - 1]), ("part", g))
        gears.append(g)
    b.rel("stage", ("stage", bs), ("gear_1", gears[0]), ("gear_2", gears[1]))
    return bs


def _pair(doc: dict) -> dict:
    """The pair as computed: the spec's [pair], in design mode with the proposal of the
    design section (teeth, face width)."""
    pair = dict(doc["inputs"]["pair"])
    design = doc["results"].get("design") or {}
    for key in ("z1", "z2", "face_width"):
        if key not in pair and f"{key}_proposed" in design:
            pair[key] = design[f"{key}_proposed"]
    return pair


def stage_load(doc: dict) -> tuple:
    """(pinion torque [N·m], pinion speed [1/min], life [h], index of the torque's shaft)
    of a bevel spec: the calculator takes the pinion's torque and speed."""
    ld = doc["inputs"].get("load") or {}
    return ld.get("torque"), ld.get("speed"), ld.get("life_hours"), 0


# ------------------------------------------------------------------------------ import

def members(r: _Reader, st: Component) -> dict[str, Component]:
    """Pinion (``gear_1``), wheel (``gear_2``) and the stage of a bevel_stage."""
    out: dict = {"stage": st}
    for rel in r.m.related("stage", stage=st.id):
        out["pinion"] = r.comp(rel.role("gear_1") or "", rel)
        out["wheel"] = r.comp(rel.role("gear_2") or "", rel)
    if "pinion" not in out:
        raise ModelError(f"bevel_stage {st.id} has no stage relation naming its pinion and "
                         f"wheel")
    for g in (out["pinion"], out["wheel"]):
        if r.shaft_of(g) is None:
            raise ModelError(f"{g.type} {g.id} \"{g.name}\" of stage {st.id} is on no "
                             f"shaft (no assembly relation shaft → gear)")
    return out


def stated(r: _Reader, st: Component) -> dict:
    """The cone geometry the model states, keyed as the calculator's geometry section."""
    mem = members(r, st)
    out = {}
    for i, member in ((1, "pinion"), (2, "wheel")):
        for aid, key, unit in COMPUTED:
            v, s_ = r.value(mem[member], aid, unit)
            if v is not None:
                out[f"{key}{i}"] = (v, s_)
    for aid, key in (("outer_cone_distance", "R_e"), ("mean_cone_distance", "R_m")):
        v, s_ = r.value(mem["pinion"], aid, "mm")
        if v is not None:
            out[key] = (v, s_)
    return {"stage": 1, "component": st.id, "stated": out}


def read_foreign(r: _Reader, out: Writer, st: Component, T_in: float, torque_load, case_no,
                 load_shaft, speed, life) -> dict:
    """A bevel stage of another program as a ``bevel`` spec: [pair] from the standard
    attributes of :data:`BEVEL_KEYS` (the module: the mean normal module of the pinion if
    stated, else the outer transverse module of the stage), [load] the pinion's torque and
    speed of the load case (the torque must act on the pinion's shaft)."""
    mem = members(r, st)
    if r.shaft_of(mem["pinion"]) is not load_shaft:
        raise ModelError(f"bevel_stage {st.id}: the bevel calculator takes the pinion torque; "
                         f"the model gives the torque on shaft {load_shaft.id}")
    out.table("pair")
    beta, s_beta = r.value(mem["pinion"], "mean_spiral_angle", "deg")
    out.kv("teeth", "spiral" if beta else "straight",
           f"{s_beta} > 0" if beta else (f"{s_beta} = 0" if s_beta else
                                         "assumed: no mean_spiral_angle stated"))
    at = "mean" if "mean_normal_module" in mem["pinion"].attributes else "outer"
    table = key_table(at)
    member, aid, unit = table["pair.module"]
    m, s_m = r.value(mem[member], aid, unit)
    if m is None:
        raise ModelError(f"bevel_stage {st.id} states no module (mean_normal_module of the "
                         f"pinion or outer_transverse_module of the stage)")
    out.kv("module", m, s_m)
    out.kv("module_at", at, s_m)
    for path, (member, aid, unit) in table.items():
        if path == "pair.module":
            continue
        v, s_ = r.value(mem[member], aid, "" if unit == "none" else unit)
        if v is None:
            if path in ("pair.z1", "pair.z2", "pair.face_width"):
                raise ModelError(f"{mem[member].type} {mem[member].id} states no {aid}")
            continue
        key = path.split(".", 1)[1]
        out.kv(key, int(round(abs(v))) if aid == "number_of_teeth" else abs(v)
               if key == "spiral_angle" else v, s_)
    hand = r.text(mem["pinion"], "spiral_angle_pitch_direction")
    if beta and hand in ("left", "right"):
        out.kv("hand", hand, src(mem["pinion"], "spiral_angle_pitch_direction"))
    out.blank()
    out.table("load")
    out.kv("torque", T_in, src(torque_load, "torque_around_u_axis", case_no))
    out.kv("speed", speed[0], speed[2])
    out.blank()
    r.read.update({"bevel_stage", "bevel_gear"})
    return stated(r, st)
