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

from typing import TYPE_CHECKING

from geardesign.rexs.common import src
from geardesign.rexs.model import Component, ModelError
from geardesign.rexs.stages import spec_customs, spec_value

if TYPE_CHECKING:
    from geardesign.rexs.reader import _Reader
    from geardesign.rexs.writer import Writer

BEVEL_KEYS = (
    # spec key, member (component role), REXS attribute, unit of the attribute
    ("pair.z1", "pinion", "number_of_teeth", "none"),
    ("pair.z2", "wheel", "number_of_teeth", "none"),
    ("pair.face_width", "pinion", "face_width", "mm"),
    ("pair.spiral_angle", "pinion", "mean_spiral_angle", "deg"),
    ("pair.shaft_angle", "stage", "shaft_angle", "deg"),
    ("pair.x1", "pinion", "profile_shift_coefficient", "none"),
    ("pair.xt1", "pinion", "thickness_modification_coefficient", "none"),
    ("pair.addendum", "pinion", "basic_addendum_coefficient", "none"),
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


ALLOWABLE = (("sigma_Hlim", "allowable_stress_number_for_contact_stress_iso_10300_2014"),
             ("sigma_Flim", "allowable_stress_number_bending_iso_10300_2014"))
"""Material keys (1 pinion, 2 wheel) → attribute of the gear's ``bevel_stage_gear_data``
[N/mm²] (ISO 10300-2 σ_H,lim and ISO 10300-3 σ_F,lim, the long-life limits)."""
ASSUMED_LIMITS = {"sigma_Hlim": 1500.0, "sigma_Flim": 500.0}
"""Long-life limits [MPa] assumed when a model states none: case-hardened wrought steel,
quality MQ ([ISO6336-5]: σ_Hlim = 1500 MPa, σ_Flim = 500 MPa at a core hardness of 30 HRC
or more), the steel geardesign assumes for the cylindrical gears of a model
(:data:`geardesign.rexs.reader.DEFAULT_MATERIAL`)."""


def _gear_data(r: _Reader, st: Component, gear: Component) -> Component | None:
    for rel in r.m.related("stage_gear_data", stage=st.id):
        if rel.role("gear") == gear.id:
            return r.comp(rel.role("stage_gear_data") or "", rel)
    return None


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
    mat = doc["inputs"].get("material") or {}
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
                 A("basic_addendum_coefficient", float(pair["addendum"])),
                 A("basic_dedendum_coefficient",
                   float(pair["addendum"]) + float(pair["clearance"])),
                 A("outer_cone_distance", float(geo["R_e"]), "mm"),
                 A("mean_cone_distance", float(geo["R_m"]), "mm")]
        attrs += [A(aid, float(geo[f"{key}{i}"]), u) for aid, key, u in COMPUTED]
        g = b.new("bevel_gear", f"{stage_name} {member}", attrs)
        b.rel("assembly", ("assembly", shafts[i - 1]), ("part", g))
        gears.append(g)
        limits = [A(aid, float(mat[f"{key}{i}"]), "N / mm^2")
                  for key, aid in ALLOWABLE if mat.get(f"{key}{i}") is not None]
        if limits:
            gd = b.new("bevel_stage_gear_data", f"{stage_name} {member} data", limits)
            b.rel("stage_gear_data", ("stage", bs), ("gear", g), ("stage_gear_data", gd))
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
    from geardesign.rexs.foreign import pair_members

    return pair_members(r, st, "pinion", "wheel")


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


def _depth(r: _Reader, mem: dict) -> tuple[str, str] | None:
    """The depth form the stated cone angles show: constant clearance when the pinion's
    face angle is its pitch angle plus the wheel's dedendum angle, δ_a1 = δ1 + (δ2 − δ_f2)
    (the tip cone parallel to the mating root cone, ISO 23509 tooth depth forms), else tapered (all
    cones from one apex); None when the angles are not stated."""
    p, w = mem["pinion"], mem["wheel"]
    d1, s_1 = r.value(p, "pitch_angle", "deg")
    da1, _ = r.value(p, "face_angle", "deg")
    d2, _ = r.value(w, "pitch_angle", "deg")
    df2, _ = r.value(w, "root_angle", "deg")
    if None in (d1, da1, d2, df2):
        return None
    parallel = abs(da1 - (d1 + d2 - df2)) <= 1e-6 * max(1.0, abs(da1))
    return (("constant_clearance" if parallel else "tapered"),
            f"face_angle of {p.type} {p.id} {'=' if parallel else '≠'} pitch_angle + the "
            f"dedendum angle of {w.type} {w.id}")


def read_foreign(r: _Reader, out: Writer, st: Component, T_in: float, torque_load, case_no,
                 load_shaft, speed, life) -> dict:
    """A bevel stage of another program as a ``bevel`` spec: [pair] from the standard
    attributes of :data:`BEVEL_KEYS` (the module: whichever of :data:`MODULE_AT` is stated;
    both stated, the mean normal module of spiral teeth and the outer transverse module of
    straight teeth, as ISO 23509 and GOST 19624 give them), [load] the pinion's torque and
    speed of the load case (the torque must act on the pinion's shaft).  What REXS has no
    attribute for (clearance and addendum coefficients, depth form, the rating's factors)
    takes the calculator's defaults."""
    mem = members(r, st)
    if r.shaft_of(mem["pinion"]) is not load_shaft:
        raise ModelError(f"bevel_stage {st.id}: the bevel calculator takes the pinion torque; "
                         f"the model gives the torque on shaft {load_shaft.id}")
    out.table("pair")
    beta, s_beta = r.value(mem["pinion"], "mean_spiral_angle", "deg")
    out.kv("teeth", "spiral" if beta else "straight",
           f"{s_beta} > 0" if beta else (f"{s_beta} = 0" if s_beta else
                                         "assumed: no mean_spiral_angle stated"))
    stated_at = [at for at, (member, aid) in MODULE_AT.items()
                 if aid in mem[member].attributes]
    at = ("mean" if beta else "outer") if len(stated_at) == 2 else \
        (stated_at[0] if stated_at else "outer")
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
    h_a, s_a = r.value(mem["pinion"], "basic_addendum_coefficient", "")
    h_f, s_f = r.value(mem["pinion"], "basic_dedendum_coefficient", "")
    if h_a is not None and h_f is not None:
        out.kv("clearance", round(h_f - h_a, 9), f"{s_f} − basic_addendum_coefficient")
    depth = _depth(r, mem)
    if depth is not None:
        out.kv("depth", *depth)
    out.blank()
    out.table("load")
    out.kv("torque", T_in, src(torque_load, "torque_around_u_axis", case_no))
    out.kv("speed", speed[0], speed[2])
    out.blank()
    out.table("material")
    for i, member in ((1, "pinion"), (2, "wheel")):
        gd = _gear_data(r, st, mem[member])
        for key, aid in ALLOWABLE:
            v, s_ = r.value(gd, aid, "MPa") if gd is not None else (None, None)
            if v is None:
                v, s_ = ASSUMED_LIMITS[key], (f"assumed: the model states no {aid} of "
                                               f"{mem[member].type} {mem[member].id}")
            out.kv(f"{key}{i}", v, s_)
    out.blank()
    r.read.update({"bevel_stage", "bevel_gear", "bevel_stage_gear_data"})
    return stated(r, st)
