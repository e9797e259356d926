"""The ``kind = "bevel"`` spec: keys, units, physical domains and defaults (the single
definition used for validation, ``geardesign schema bevel`` and ``geardesign template
bevel``)."""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table
from geardesign.spur.strength.iso6336.tables import MATERIAL_LINES, RHO_STEEL

PAIR = Table("pair", "bevel gear pair geometry", (
    Field("teeth", "string", "tooth form: straight (GOST 19624, Gleason straight) or spiral "
          "(circular-arc teeth, GOST 19326, ISO 23509)", default="straight",
          choices=("straight", "spiral")),
    Field("module", "number", "module: outer transverse m_te (straight) or mean normal m_nm "
          "(spiral), see module_at", "mm", "m", minimum=0.05, maximum=100, example=4.0,
          default=None, hint="required unless [design] proposes it"),
    Field("module_at", "string", "where the module is given: outer transverse (m_te) or mean "
          "normal (m_nm)", default="outer", choices=("outer", "mean")),
    Field("z1", "integer", "number of teeth of the pinion", symbol="z1", minimum=5,
          maximum=200, example=20, default=None, hint="required unless [design] proposes it"),
    Field("z2", "integer", "number of teeth of the wheel", symbol="z2", minimum=5,
          maximum=400, example=50, default=None, hint="required unless [design] proposes it"),
    Field("shaft_angle", "number", "shaft angle Σ = δ1 + δ2", "deg", "Σ", default=90.0,
          minimum=10, maximum=170),
    Field("face_width", "number", "face width along the pitch cone generator", "mm", "b",
          gt=0, maximum=2000, example=30.0, default=None,
          hint="required unless [design] proposes it"),
    Field("spiral_angle", "number", "mean spiral angle (0 for straight teeth)", "deg", "β_m",
          default=0.0, minimum=0, maximum=45),
    Field("hand", "string", "hand of spiral of the pinion (right: the outer half of a tooth "
          "inclined clockwise, seen looking at the face; the wheel has the other)",
          default="right", choices=("right", "left")),
    Field("pressure_angle", "number", "normal pressure angle of the basic rack", "deg", "α_n",
          default=20.0, minimum=10, maximum=30),
    Field("addendum", "number", "addendum coefficient h_a*", symbol="h_a*", default=1.0,
          minimum=0.5, maximum=1.5),
    Field("clearance", "number", "bottom clearance coefficient c*", symbol="c*", default=0.2,
          minimum=0.0, maximum=0.5, hint="GOST 13754 (straight): 0.2; GOST 16202 (spiral): "
          "0.25"),
    Field("root_radius", "number", "tip radius coefficient of the cutter ρ_a0*",
          symbol="ρ_a0*", default=0.25, minimum=0.0, maximum=0.5),
    Field("x1", "number", "profile shift coefficient of the pinion (wheel −x1)", symbol="x1",
          default=0.0, minimum=-1.0, maximum=1.0),
    Field("xt1", "number", "tangential (thickness) shift coefficient of the pinion "
          "(wheel −xt1)", symbol="x_τ1", default=0.0, minimum=-0.5, maximum=0.5),
    Field("xt2", "number", "tangential (thickness) shift coefficient of the wheel, when not "
          "−xt1 (a thickness modification that includes backlash)", symbol="x_τ2",
          default=None, minimum=-0.5, maximum=0.5),
    Field("root_radius2", "number", "tip radius coefficient of the wheel's cutter ρ_a02*, "
          "when not root_radius", symbol="ρ_a02*", default=None, minimum=0.0, maximum=0.5),
    Field("depth", "string", "tooth depth along the face: constant clearance (the tip cone "
          "parallel to the mating root cone) or tapered (all cones from one apex)",
          default="constant_clearance", choices=("constant_clearance", "tapered")),
))

LOAD = Table("load", "operating load on the pinion", (
    Field("torque", "number", "nominal pinion torque", "N·m", "T1", gt=0, maximum=1e7,
          example=150.0),
    Field("speed", "number", "pinion speed", "min^-1", "n1", gt=0, maximum=1e5,
          example=960.0),
    Field("rotation", "string", "pinion rotation seen from its back (the large end) toward "
          "the apex", default="cw", choices=("cw", "ccw")),
    Field("driver", "string", "driving member", default="pinion",
          choices=("pinion", "wheel")),
    Field("application_factor", "number", "application factor K_A", symbol="K_A",
          default=1.0, minimum=1.0, maximum=3.0),
    Field("dynamic_factor", "number", "dynamic factor K_v", symbol="K_v", default=None,
          minimum=1.0, maximum=3.0, hint="leave out to compute it by ISO 10300-1 method B "
          "from [accuracy]; without [accuracy] 1.1 is assumed"),
    Field("mounting", "string", "how the members are mounted (mounting factor K_Hβ-be)",
          default="one_straddle", choices=("both_straddle", "one_straddle", "cantilever")),
    Field("transverse_factor", "number", "transverse load factor K_Hα = K_Fα", symbol="K_Hα",
          default=None, minimum=1.0, maximum=3.0, hint="leave out to compute it by ISO "
          "10300-1 method B from [accuracy]; without [accuracy] 1.0 is assumed"),
    Field("peak_torque", "number", "largest short-time pinion torque (starting torque, "
          "jam), for the static checks", "N·m", "T_max", default=None, gt=0, maximum=1e7,
          hint="leave out for no peak-load check"),
))

MATERIAL = Table("material", "strength of the flanks and roots (long-life limits)", (
    Field("sigma_Hlim1", "number", "contact endurance limit, pinion", "MPa", "σ_Hlim1",
          gt=0, maximum=3000, example=1300.0),
    Field("sigma_Hlim2", "number", "contact endurance limit, wheel", "MPa", "σ_Hlim2",
          gt=0, maximum=3000, example=1300.0),
    Field("sigma_Flim1", "number", "nominal bending endurance limit, pinion (ISO 6336-5)",
          "MPa", "σ_Flim1", gt=0, maximum=1500, example=460.0),
    Field("sigma_Flim2", "number", "nominal bending endurance limit, wheel (ISO 6336-5)",
          "MPa", "σ_Flim2", gt=0, maximum=1500, example=460.0),
    Field("hardness", "string", "hardness of the pair (GOST factors θ_H, θ_F of circular "
          "teeth)", default="both_hard", choices=("both_soft", "one_hard", "both_hard"),
          hint="soft: up to 350 HB"),
    Field("E", "number", "modulus of elasticity of both members", "MPa", "E",
          default=206000.0, minimum=1e4, maximum=5e5),
    Field("poisson", "number", "Poisson's ratio of both members", symbol="ν", default=0.3,
          minimum=0.1, maximum=0.5),
    Field("type", "string", "material type of ISO 6336-5 of both members (static limits at "
          "the peak torque, running-in of method B): Eh case-hardened, IF induction/flame "
          "hardened, V/V_alloy through-hardened, St normalized, NT/NV nitrided, …",
          default="Eh", choices=tuple(MATERIAL_LINES)),
    Field("sigma_02", "number", "yield strength σ_0.2 (static notch factor Y_δrelT,st of St "
          "and V types)", "MPa", "σ_0.2", default=None, gt=0, maximum=3000,
          hint="600 MPa when not given"),
    Field("sigma_HPmax1", "number", "GOST 21354 allowable contact stress at the peak load, "
          "pinion", "MPa", "σ_HPmax1", default=None, gt=0, maximum=10000,
          hint="2.8·σ_T improved, 44·HRC case-hardened, 3·HV nitrided"),
    Field("sigma_HPmax2", "number", "GOST 21354 allowable contact stress at the peak load, "
          "wheel", "MPa", "σ_HPmax2", default=None, gt=0, maximum=10000),
    Field("sigma_FSt1", "number", "GOST 21354 limit bending stress at the peak load, pinion",
          "MPa", "σ_FSt1", default=None, gt=0, maximum=10000),
    Field("sigma_FSt2", "number", "GOST 21354 limit bending stress at the peak load, wheel",
          "MPa", "σ_FSt2", default=None, gt=0, maximum=10000),
))

ACCURACY = Table("accuracy", "single pitch deviations for K_v and K_Hα by ISO 10300-1 method B "
                 "(leave the table out to give load.dynamic_factor and "
                 "load.transverse_factor, or have them assumed)", (
    Field("f_pt1", "number", "single pitch deviation of the pinion (drawing tolerance or "
          "measured, ISO 17485)", "µm", "f_pt1", gt=0, maximum=500, example=12.0),
    Field("f_pt2", "number", "single pitch deviation of the wheel", "µm", "f_pt2", gt=0,
          maximum=500, example=26.0),
    Field("density", "number", "density of both members (reduced mass)", "kg/m^3", "ρ",
          default=round(RHO_STEEL * 1e9), minimum=1000, maximum=20000),
), required=False)

RATING = Table("rating", "rating method and required safety factors", (
    Field("method", "string", "strength method", default="both",
          choices=("iso10300", "gost21354", "both")),
    Field("S_Hmin", "number", "minimum safety factor for pitting", symbol="S_Hmin",
          default=1.0, minimum=0.5, maximum=5.0),
    Field("S_Fmin", "number", "minimum safety factor for bending", symbol="S_Fmin",
          default=1.3, minimum=0.5, maximum=5.0),
), implicit=True)

DESIGN = Table("design", "design mode: propose z1, z2, the module and the face width for the "
               "load and the materials (leave pair.module, z1, z2, face_width out)", (
    Field("ratio", "number", "gear ratio u = z2/z1 wanted", symbol="u", minimum=1.0,
          maximum=10.0, example=2.5),
    Field("z1", "integer", "number of teeth of the pinion", symbol="z1", default=20,
          minimum=8, maximum=60, hint="handbooks: 18…30 (fewer for large ratios)"),
    Field("face_ratio", "number", "face width over the outer cone distance K_be = b/R_e",
          symbol="K_be", default=0.285, minimum=0.15, maximum=0.35,
          hint="handbooks: 0.285; ISO 23509: at most 1/3"),
), required=False, in_template=False)

SCHEMA = SpecSchema(
    kind="bevel",
    description="bevel gear pair: geometry, ISO 10300 and GOST strength, shaft forces",
    tables=(PAIR, LOAD, MATERIAL, ACCURACY, RATING, DESIGN),
    title_example="straight bevel pair m_te = 4, 20/50 teeth, Σ = 90°",
)
