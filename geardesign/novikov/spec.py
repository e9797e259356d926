"""The ``kind = "novikov"`` spec: keys, units, ranges and defaults (the single definition
used for validation, ``geardesign schema novikov`` and ``geardesign template novikov``).

Single-key ranges follow the method (design practice): shifts within the
domain of the Y_v formulas (−0.5 … 0.3), hardness within the ≤ 350 HB scope, accuracy
grades of GOST 1643-81.  Rules that involve several keys are in the calculator.
"""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table
from geardesign.materials.novikov import steel
from geardesign.novikov.rack import STANDARD

_HB_MAX = steel().hardness_max_HB

GEAR = Table("gear", "Novikov DLZ gear pair (external, helical; pinion 1 drives)", (
    Field("module", "number", "normal module", "mm", "m", minimum=0.05, maximum=50, example=10.0,
          hint="GOST 14186-69 series preferred; GOST 15023-76 covers 1.6…16 mm"),
    Field("z1", "integer", "number of teeth, pinion (driving)", symbol="z1", minimum=6,
          maximum=1000, example=12),
    Field("z2", "integer", "number of teeth, wheel (driven)", symbol="z2", minimum=6,
          maximum=1000, example=71),
    Field("helix_angle", "number", "helix angle (give it or center_distance)", "deg", "β",
          default=None, gt=0, lt=45, example=22.747),
    Field("center_distance", "number",
          "centre distance; the helix angle then follows, cos β = m(z1 + z2)/(2a_w)", "mm",
          "a_w", default=None, gt=0),
    Field("face_width", "number", "working face width", "mm", "b_w", gt=0, maximum=5000,
          example=100.0),
    Field("x1", "number", "rack shift coefficient, pinion", symbol="x1", default=0.0,
          minimum=-0.5, maximum=0.3, hint="x1 + x2 = 0 (the pair works at the standard "
          "centre distance); range of the Y_v formulas"),
    Field("x2", "number", "rack shift coefficient, wheel", symbol="x2", default=0.0,
          minimum=-0.5, maximum=0.3),
))

RACK = Table("rack", "basic rack (GOST 15023-76, or a custom DLZ rack)", (
    Field("name", "string", "basic rack", symbol="rack", default=STANDARD,
          choices=(STANDARD, "custom"),
          hint='"custom" needs profile_angle, lk_star, eps_q, addendum_coef, dedendum_coef'),
    Field("profile_angle", "number", "profile angle at the nominal contact point", "deg",
          "α_k", default=None, gt=10, lt=40),
    Field("lk_star", "number", "active addendum path along the chord, in modules", "-",
          "l_k*", default=None, minimum=0.1, maximum=3),
    Field("eps_q", "number", "phase coefficient of axial overlap q/p_x", "-", "ε_q",
          default=None, minimum=0.05, lt=1),
    Field("addendum_coef", "number", "addendum coefficient", "-", "h_a*", default=None,
          minimum=0.3, maximum=2),
    Field("dedendum_coef", "number", "dedendum coefficient", "-", "h_f*", default=None,
          minimum=0.3, maximum=3),
), required=False, implicit=True)


def _gear_material(key: str, who: str, example: float) -> Table:
    return Table(key, f"material of the {who} (steel, through-hardened, <= 350 HB)", (
        Field("hardness", "number", f"surface hardness, {who}", "HB",
              f"HB{1 if key == 'pinion' else 2}", minimum=100, maximum=_HB_MAX, example=example,
              hint="the method assumes run-in teeth of at most 350 HB (GOST 30224-96 scope)"),
        Field("sigma_Hlim", "number", "contact endurance limit (overrides 2·HB + 70)", "MPa",
              "σ_Hlim", default=None, gt=0, maximum=3000),
        Field("sigma_Flim", "number", "bending endurance limit (overrides 1.75·HB)", "MPa",
              "σ_Flim", default=None, gt=0, maximum=2000),
    ))


MATERIAL = Table("material", "materials", (
    _gear_material("pinion", "pinion", 350.0),
    _gear_material("wheel", "wheel", 320.0),
))

ACCURACY = Table("accuracy", "accuracy and assembly (GOST 1643-81) and the error model", (
    Field("grade_smoothness", "integer", "accuracy grade, smoothness norms (GOST 1643-81)",
          symbol="k_p", default=8, minimum=5, maximum=12),
    Field("grade_contact", "integer", "accuracy grade, contact norms (GOST 1643-81)",
          symbol="k_k", default=8, minimum=5, maximum=12),
    Field("risk", "number", "risk parameter: design deviations are risk·σ (normal quantile)",
          symbol="γ", default=2.17, minimum=0, maximum=5),
    Field("misalignment", "number",
          "misalignment angle from the compliance of shafts, bearings and housing; positive "
          "closes the face end where the contact enters first", "deg", "θ", default=0.0,
          minimum=-0.5, maximum=0.5),
    Field("end_relief", "number", "end relief of the flanks from lengthwise crowning", "mm",
          "Δ", default=0.0, minimum=0, maximum=1.0),
    Field("error_model", "string", "how deviations enter the load sharing", default="grades",
          choices=("grades", "explicit", "none"), example="none",
          hint='"grades": probabilistic design values from k_p, k_k and risk, each tooth in '
               'turn leading; "explicit": pitch_errors and lead_error; "none": only θ'),
    Field("pitch_errors", "array", "gap of each tooth pair in engagement (positive lags, "
          "negative leads), for error_model = \"explicit\"", "µm", "δu", default=None,
          minimum=-1000, maximum=1000, min_items=1, max_items=50),
    Field("lead_error", "number", "lead mismatch over the face for error_model = "
          "\"explicit\" (positive closes the entry end first)", "µm", "f_kβ", default=None,
          minimum=-1000, maximum=1000),
), required=False, implicit=True)

LOAD = Table("load", "load", (
    Field("torque2", "number", "torque on the driven wheel", "N·m", "T2", gt=0, maximum=1e8,
          example=44000.0),
    Field("application_factor", "number", "application factor (multiplies the load)",
          symbol="K_A", default=1.0, minimum=1.0, maximum=4.0),
    Field("speed1", "number", "pinion speed (for the number of load cycles)", "min^-1", "n1",
          default=None, gt=0, maximum=1e6),
    Field("life", "number", "required life (with speed1: the life factors Z_N, Y_N)", "h",
          "L_h", default=None, gt=0, maximum=1e7),
    Field("reversing", "boolean", "reversing (two-way) load: Y_A < 1", default=False),
))

ANALYSIS = Table("analysis", "phase analysis (Korotkin's NOVGOST-17 algorithm)", (
    Field("phases", "integer", "engagement phases per axial pitch", symbol="f_z", default=21,
          minimum=4, maximum=60, hint="18…25 usually suffice (Korotkin 2017)"),
    Field("mesh_stiffness", "number", "tooth-pair stiffness per unit length of the effective "
          "patch length 2a + 2h", "N/(mm·µm)", "c'", default=14.0, minimum=0.1, maximum=1000,
          hint="assumption (ISO 6336 single stiffness); see docs/novikov.md"),
    Field("point_stiffness", "number", "stiffness of one contact point (overrides "
          "mesh_stiffness)", "N/µm", "c_p", default=None, minimum=1e-3, maximum=1e6),
), required=False, implicit=True)

SCHEMA = SpecSchema(
    kind="novikov",
    description="Novikov DLZ pair on the GOST 15023-76 rack: geometry, axial overlap, "
                "multi-pair engagement, phase bending and contact stresses (Korotkin 2017)",
    tables=(GEAR, RACK, MATERIAL, ACCURACY, LOAD, ANALYSIS),
    title_example="Novikov pair 12/71, m = 10 (Korotkin 2017's geometry) with a 100 mm face "
                  "(ε_β = 1.23), HB 350/320, T2 = 44 kN·m, error-free engagement: every "
                  "contact point inside the ψ range of Korotkin's fits, all checks passing",
)
