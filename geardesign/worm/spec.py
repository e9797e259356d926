"""The ``kind = "worm"`` spec: keys, units, ranges and defaults (the single definition used
for validation, ``geardesign schema worm`` and ``geardesign template worm``)."""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table, TableList
from geardesign.materials import worm_wheel
from geardesign.worm.geometry import WORM_TYPES
from geardesign.worm.strength import BENDING_FORMULAS, CV_LAWS
from geardesign.worm.tables import FRICTION_LEVELS

MODES = ("check", "design")

GEAR = Table("gear", "worm pair (orthogonal cylindrical worm, GOST 19650-97)", (
    Field("module", "number", "axial module of the worm (= transverse module of the wheel)",
          "mm", "m", default=None, minimum=0.05, maximum=100, example=6.3,
          hint='required with mode = "check"; design mode proposes it (GOST 19672-74 rows)'),
    Field("diameter_factor", "number", "worm diameter factor d1/m", symbol="q", default=None,
          minimum=5, maximum=40, example=10.0,
          hint='required with mode = "check"; in design mode the smallest first-row q >= '
               '0.212·z2 unless given'),
    Field("z1", "integer", "number of worm starts", symbol="z1", default=None, minimum=1,
          maximum=4, example=2, hint="1, 2 or 4 (3 is allowed with a warning)"),
    Field("z2", "integer", "number of wheel teeth", symbol="z2", default=None, minimum=10,
          maximum=400, example=40),
    Field("ratio", "number", "nominal ratio u = z2/z1 (GOST 2144-76 rows)", symbol="u",
          default=None, gt=1, maximum=400,
          hint="design mode: z1 and z2 follow from it when not given; with z1 and z2 it must "
               "agree with z2/z1 within 4 %"),
    Field("x", "number", "wheel shift coefficient", symbol="x", default=None, minimum=-1.0,
          maximum=1.0, hint="default 0 without center_distance; with center_distance it "
                            "follows: x = a_w/m − 0.5(q + z2)"),
    Field("center_distance", "number", "centre distance; the wheel shift x then follows",
          "mm", "a_w", default=None, gt=0, example=160.0),
    Field("worm_type", "string", "worm type (GOST 18498-89)", default="ZA", choices=WORM_TYPES,
          hint="ZA: straight axial profile; ZI: involute; ZN1: straight normal profile; "
               "ZK1: cone-generated (treated as ZN1)"),
    Field("profile_angle", "number", "profile angle of the basic worm: axial for ZA, normal "
          "for ZI, ZN1, ZK1", "deg", "α", default=20.0, gt=10, lt=30),
    Field("hand", "string", "hand of the worm thread", default="right", choices=("right", "left")),
    Field("face_width", "number", "wheel face width", "mm", "b2", default=None, gt=0,
          hint="default the largest allowed: 0.75·d_a1 (z1 <= 3), 0.67·d_a1 (z1 = 4)"),
    Field("worm_length", "number", "worm thread length", "mm", "b1", default=None, gt=0,
          hint="default the least required by GOST 19650-97 (plus the grinding allowance)"),
))

BASIC_WORM = Table("basic_worm", "basic worm (GOST 19036-94)", (
    Field("addendum_coef", "number", "addendum coefficient", symbol="h_a*", default=1.0, minimum=0.5,
          maximum=2.0),
    Field("clearance_coef", "number", "radial clearance coefficient", symbol="c*", default=0.2,
          minimum=0, maximum=1.0),
    Field("root_radius_coef", "number", "root fillet radius coefficient", symbol="ρ_f*",
          default=0.3, minimum=0, maximum=1.0),
), required=False, implicit=True)

SPECTRUM = TableList("spectrum", "load spectrum: torque ratios T_i/T2 with their time shares",
                     Table("spectrum", "one load level", (
                         Field("torque_ratio", "number", "torque of this level over torque2",
                               symbol="T_i/T2", minimum=1e-3, maximum=1.0, example=1.0),
                         Field("time_share", "number", "share of the running time",
                               symbol="t_i/t", minimum=1e-6, maximum=1.0, example=1.0),
                     )), required=False, examples=({"torque_ratio": 1.0, "time_share": 0.6},
                                                   {"torque_ratio": 0.5, "time_share": 0.4}),
                     hint="without it the load is constant; the shares must add up to 1")

LOAD = Table("load", "operating data", (
    Field("torque2", "number", "torque on the wheel shaft (the largest long-acting torque)",
          "N·m", "T2", gt=0, maximum=1e7, example=500.0),
    Field("speed1", "number", "worm speed", "min^-1", "n1", gt=0, maximum=1e5, example=1450.0),
    Field("peak_torque", "number", "short peak torque on the wheel shaft (start, jam)", "N·m",
          "T_peak", default=None, gt=0, maximum=1e8, hint="default torque2 (peak checks then "
                                                            "use the nominal torque)"),
    Field("life", "number", "required life", "h", "L_h", default=20000.0, gt=0, maximum=1e6),
    Field("reversing", "boolean", "the torque reverses direction (reversing bending "
          "allowable)", default=False),
    Field("self_locking", "string", "self-locking requirement", default="avoid",
          choices=("avoid", "require", "any"),
          hint='"avoid": a power drive that must run back; "require": a hoist or holding '
               'drive; "any": report only'),
    SPECTRUM,
))

WHEEL = Table("wheel", "wheel rim material", (
    Field("material", "string", "rim material from the library, or \"custom\" (give group "
          "and strengths)", choices=worm_wheel.names() + ("custom",),
          example="BrO10N1F1_centrifugal"),
    Field("group", "string", "material group: I tin bronzes, II tin-free bronzes and brass, "
          "III grey iron", default=None, choices=worm_wheel.GROUPS,
          hint="required for a custom material; overrides the library"),
    Field("sigma_B", "number", "tensile strength (bronze, brass)", "MPa", "σ_B", default=None,
          gt=0, maximum=2000),
    Field("sigma_T", "number", "yield strength (bronze, brass)", "MPa", "σ_T", default=None,
          gt=0, maximum=2000),
    Field("sigma_bu", "number", "bending strength (grey iron)", "MPa", "σ_bu", default=None,
          gt=0, maximum=2000),
    Field("v_s_max", "number", "highest sliding speed for the material", "m/s", "v_s,max",
          default=None, gt=0, maximum=50),
    Field("sigma_HP", "number", "allowable contact stress, given instead of computed", "MPa",
          "[σ]_H", default=None, gt=0, maximum=2000),
    Field("sigma_FP", "number", "allowable bending stress, given instead of computed", "MPa",
          "[σ]_F", default=None, gt=0, maximum=2000),
))

WORM = Table("worm", "worm (steel) and its shaft", (
    Field("surface", "string", "worm flank treatment", default="hardened_ground",
          choices=("hardened_ground", "improved"),
          hint='"hardened_ground": >= 45 HRC, ground or polished (0.9·σ_B, grinding allowance '
               'on b1); "improved": <= 350 HB (0.75·σ_B)'),
    Field("elastic_modulus", "number", "elastic modulus of the worm shaft", "MPa", "E",
          default=2.1e5, gt=0, maximum=1e6),
    Field("bearing_span", "number", "distance between the worm bearings", "mm", "l",
          default=None, gt=0, hint="default 0.9·d2"),
    Field("deflection_limit", "number", "allowed deflection as a share of the module",
          symbol="f_lim/m", default=0.01, minimum=1e-4, maximum=0.1,
          hint="textbooks: 0.005 ... 0.01"),
), required=False, implicit=True)

FRICTION = Table("friction", "friction and losses", (
    Field("level", "string", "where in the tabulated range of f' to read", default="mean",
          choices=FRICTION_LEVELS, hint='"low": good running-in, ground worm'),
    Field("coefficient", "number", "reduced friction coefficient, given instead of the table",
          symbol="f'", default=None, minimum=0.005, maximum=0.5),
    Field("material_factor", "number", "multiplier of the table's f' for the wheel material",
          symbol="k_f", default=None, minimum=0.5, maximum=3.0,
          hint="default 1.0 for group I, 1.4 for groups II and III"),
    Field("bearing_efficiency", "number", "efficiency of bearings and oil churning",
          symbol="η_b", default=0.96, gt=0.5, maximum=1.0),
), required=False, implicit=True)

METHOD = Table("method", "textbook constants where the sources disagree", (
    Field("cv_law", "string", "law of the sliding-speed factor C_v (group I)", default="power",
          choices=CV_LAWS, hint='"power": 1.66·v_s^-0.352 <= 1 (Dunaev & Lelikov fit); '
                                '"linear": 1.4 − 0.076·v_s (public Pascal program)'),
    Field("K_HL_max", "number", "upper limit of the contact life factor", symbol="K_HL,max",
          default=1.15, minimum=1.0, maximum=1.5, hint="1.15 textbooks; 1.33 Pascal program"),
    Field("sigma_H0", "number", "constant of the group II/III allowable [σ]_H = σ_H0 − k·v_s",
          "MPa", "σ_H0", default=None, gt=0, maximum=1000,
          hint="default 300 (II, hardened worm), 250 (II, improved), 200 (III)"),
    Field("bending_formula", "string", "wheel bending-stress formula", default="dunaev",
          choices=BENDING_FORMULAS, hint='"dunaev": K·F_t2·Y_F·cos γ_w/(1.3·m²·(q + 2x)); '
                                         '"ivanov": 0.7·Y_F·F_t2·K/(b2·m)'),
    Field("dynamic_factor", "number", "dynamic factor, given instead of the default law",
          symbol="K_v", default=None, minimum=1.0, maximum=2.0,
          hint="default 1.0 for v2 <= 3 m/s, 1.2 above"),
), required=False, implicit=True)

THERMAL = Table("thermal", "thermal balance of the housing", (
    Field("ambient", "number", "ambient air temperature", "°C", "t_0", default=20.0,
          minimum=-60, maximum=80),
    Field("oil_limit", "number", "highest allowed oil temperature", "°C", "t_lim", default=90.0,
          minimum=30, maximum=150, hint="textbooks: 80 ... 95"),
    Field("heat_transfer", "number", "heat-transfer coefficient of the housing (natural "
          "cooling)", "W/(m²·K)", "K_T", default=13.0, minimum=4, maximum=100,
          hint="9 (closed room) ... 17 (good air flow)"),
    Field("housing_area", "number", "cooling surface of the housing", "m²", "A", default=None,
          minimum=0.01, maximum=100, hint="default 20·a_w^1.7 (a_w in m)"),
    Field("base_share", "number", "share of heat taken by the base or frame", symbol="ψ",
          default=0.3, minimum=0, maximum=1.0, hint="0 on a light frame"),
    Field("fan", "boolean", "a fan on the worm shaft blows on the housing", default=False),
    Field("fan_speed", "number", "fan speed", "min^-1", "n_fan", default=None, gt=0,
          maximum=1e5, hint="default the worm speed"),
    Field("fan_share", "number", "share of the surface blown by the fan", symbol="s",
          default=0.35, minimum=0.01, maximum=1.0),
), required=False, implicit=True)

DESIGN = Table("design", "design mode settings", (
    Field("center_distance_rows", "string", "GOST 2144-76 rows of centre distances to round "
          "up to", default="first", choices=("first", "both")),
), required=False, hint='read with mode = "design" only')

SCHEMA = SpecSchema(
    kind="worm",
    description="cylindrical worm pair: geometry to GOST 19650-97, efficiency, strength of "
                "the wheel, worm deflection, thermal balance",
    tables=(
        Field("mode", "string", "\"check\" a given pair or \"design\": propose a_w, m, q",
              default="check", choices=MODES),
        GEAR, BASIC_WORM, LOAD, WHEEL, WORM, FRICTION, METHOD, THERMAL, DESIGN,
    ),
    title_example="Worm reducer 2/40, m = 6.3, q = 10, a_w = 160",
)
