"""The ``kind = "spur"`` spec: keys, units, ranges and defaults (the single definition used
for validation, ``geardesign schema spur`` and ``geardesign template spur``).

Modes: a spec with ``[gear]`` checks a given pair (geometry; with ``[material]`` and a
torque also the strength); a spec with ``[design]`` proposes a pair for a torque and
ratio and then checks it.
"""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table, TableList
from geardesign.spur import drawing_spec as DR
from geardesign.spur.strength import METHODS
from geardesign.spur.strength import tables as T
from geardesign.spur.strength.iso6336.spec import ISO, ISO_FACTORS, OPTIONS_METHODS

ACCURACY = Field("accuracy_grade", "integer", "accuracy grade (GOST 1643-81 smoothness norm)",
                 symbol="n_st", default=8, minimum=6, maximum=11)
TIP_RELIEF = Field("tip_relief", "boolean", "teeth with tip relief (lower dynamic load)",
                   default=False)
SCHEME = Field("bearing_scheme", "integer",
               "arrangement of the gears on their shafts, GOST 21354-87 chart 1…7 (for K_Hβ)",
               default=None, minimum=1, maximum=7,
               hint="; ".join(f"{k}: {v}" for k, v in T.SCHEMES.items())
               + "; required for the strength calculation", example=5)
PRESSURE_ANGLE = Field("pressure_angle", "number", "normal pressure angle of the basic rack",
                       "deg", "α", default=20.0, gt=10, lt=35)

GEAR = Table("gear", "gear pair (external or internal, spur or helical)", (
    Field("module", "number", "normal module", "mm", "m_n", minimum=0.05, maximum=100, example=4.0,
          hint="GOST 9563 series preferred"),
    Field("z1", "integer", "number of teeth, pinion", symbol="z1", minimum=5, maximum=1000,
          example=25),
    Field("z2", "integer", "number of teeth, wheel", symbol="z2", minimum=5, maximum=1000,
          example=100),
    PRESSURE_ANGLE,
    Field("helix_angle", "number", "reference helix angle, 0 for spur gears", "deg", "β",
          default=0.0, minimum=0, lt=45),
    Field("face_width", "number", "working face width", "mm", "b_w", gt=0, example=63.0),
    Field("x1", "number", "profile shift coefficient, pinion", symbol="x1", default=None,
          minimum=-1.0, maximum=2.0,
          hint="default 0 without center_distance; with center_distance, x2 = x_Σ − x1"),
    Field("x2", "number", "profile shift coefficient, wheel", symbol="x2", default=None,
          minimum=-1.0, maximum=2.0,
          hint="default 0 without center_distance; with center_distance, x1 = x_Σ − x2"),
    Field("center_distance", "number", "working centre distance; x1 + x2 then follows from it",
          "mm", "a_w", default=None, gt=0),
    Field("shift_split", "string",
          "split of x1 + x2 when center_distance is given without x1 or x2", default=None,
          choices=("sliding", "equal"),
          hint='"sliding" (used when not given) equalises the specific sliding at both roots; '
               '"equal" gives x1 = x2'),
    Field("allow_undercut", "boolean",
          "accept an undercut tooth (deliberate, e.g. a small pinion): the check only warns",
          default=False),
    Field("tip_shortening", "boolean",
          "shorten the tips by Δy·m_n (GOST 16532-70); false keeps d_a = d + 2(h_a* + x)m_n",
          default=True),
    Field("internal", "boolean",
          "gear 2 is an internal gear (a ring) meshing the external pinion: z2 > z1, both "
          "given positive, x2 in the GOST 19274-73 sign (positive away from the axis, thinner "
          "teeth; x2_ISO = −x2)", default=False,
          hint="geometry GOST 19274-73 / ISO 21771, a_w = m_t(z2 − z1)/2 without shifts"),
    Field("cutter_teeth", "integer", "teeth of the shaper cutter that generates the internal "
          "gear (its form circle, the cutting interference and the ISO 6336-3 Y_F, Y_S of "
          "its fillet; internal pairs only)",
          symbol="z_0", default=None, minimum=8, maximum=300,
          hint="leave out: the form circle of the basic rack, as for a planetary ring without "
               "[cutter]; at most z2 − 4"),
    Field("cutter_shift", "number", "profile shift coefficient of the shaper cutter "
          "(with cutter_teeth)", symbol="x_0", default=0.0, minimum=-1.0, maximum=1.5),
    Field("cutter_tip_radius_coef", "number", "tip radius coefficient of the shaper cutter "
          "(with cutter_teeth)", symbol="ρ_a0*", default=None, minimum=0, maximum=1.0,
          hint="default: rack.root_radius_coef"),
    Field("internal_tip_shortening", "number", "tip shortening coefficient of the internal "
          "gear: d_a2 = d2 − 2(h_a* − x2 − k2)m_n (internal pairs only)", symbol="k2",
          default=0.0, minimum=-0.5, maximum=1.0,
          hint="0: the ISO 21771 nominal tip; a zero-shift internal gear usually needs about "
               "0.1-0.2 against interference at the pinion root"),
    ACCURACY,
    TIP_RELIEF,
    SCHEME,
), required=False)

DESIGN = Table("design", "design mode: propose a pair for the load, then check it", (
    Field("ratio", "number", "required gear ratio z2/z1", symbol="u", minimum=1.0, maximum=12.5,
          example=4.0),
    Field("ratio_tolerance", "number", "allowed deviation of the ratio", "%", default=4.0,
          gt=0, maximum=10),
    Field("psi_ba", "number", "face width ratio b_w/a_w (GOST 2185 series)", symbol="ψ_ba",
          default=0.315, choices=T.PSI_BA),
    Field("helix_angle", "number", "helix angle to aim at, 0 for spur gears", "deg", "β",
          default=0.0, minimum=0, maximum=40),
    Field("z1_min", "integer", "fewest pinion teeth", symbol="z1_min", default=17, minimum=8,
          maximum=60),
    Field("center_distance_series", "integer", "GOST 2185 series of a_w: 1 only, or 1 and 2",
          default=2, minimum=1, maximum=2),
    PRESSURE_ANGLE,
    ACCURACY,
    TIP_RELIEF,
    SCHEME,
), required=False)

RACK = Table("rack", "basic rack (GOST 13755-81)", (
    Field("addendum_coef", "number", "addendum coefficient", symbol="h_a*", default=1.0,
          minimum=0.5, maximum=2.0,
          hint="1 for GOST 13755 / ISO 53; 0.8 stub, up to 1.4 high-contact-ratio teeth"),
    Field("clearance_coef", "number", "bottom clearance coefficient", symbol="c*", default=0.25,
          minimum=0, maximum=1.0),
    Field("root_radius_coef", "number", "root fillet radius coefficient of the rack",
          symbol="ρ_f*", default=0.38, minimum=0, maximum=1.0),
), required=False, implicit=True)

BLOCK = Table("spectrum", "load block", (
    Field("torque_ratio", "number", "torque of the block over the nominal torque T1",
          symbol="T_i/T1", minimum=1e-3, maximum=1.0, example=1.0),
    Field("time_share", "number", "share of the life spent in the block", symbol="t_i/L_h",
          minimum=1e-6, maximum=1.0, example=1.0),
    Field("speed_ratio", "number", "speed of the block over the nominal speed", symbol="n_i/n1",
          default=1.0, minimum=1e-3, maximum=10.0),
))

LOAD = Table("load", "operating data", (
    Field("speed1", "number", "pinion speed", "min^-1", "n1", gt=0, maximum=1e6, example=960.0),
    Field("torque1", "number", "nominal pinion torque: the largest long-acting torque", "N·m",
          "T1", default=None, gt=0, maximum=1e8, example=250.0,
          hint="or give power; required for the strength calculation"),
    Field("power", "number", "transmitted power (instead of torque1)", "kW", "P", default=None,
          gt=0, maximum=1e6),
    Field("application_factor", "number",
          "application factor: 1 uniform, 1.25 light shocks, 1.5 moderate, 1.75-2.25 heavy",
          symbol="K_A", default=1.0, minimum=1.0, maximum=3.0),
    Field("peak_torque1", "number", "largest short-time pinion torque, for the static checks",
          "N·m", "T_max", default=None, gt=0, maximum=1e9, example=500.0),
    Field("life_hours", "number", "required life", "h", "L_h", default=None, gt=0, maximum=1e7,
          example=20000.0, hint="required for the strength calculation"),
    Field("regime", "string", "typical load regime of GOST 21354-87 (instead of a spectrum): "
          + ", ".join(f"{k} {v}" for k, v in T.REGIME_NAMES.items()),
          default=None, choices=T.REGIMES, hint='"0" when neither regime nor spectrum is given'),
    Field("meshes_pinion", "integer", "meshes per revolution of the pinion", symbol="c1",
          default=1, minimum=1, maximum=20),
    Field("meshes_wheel", "integer", "meshes per revolution of the wheel", symbol="c2",
          default=1, minimum=1, maximum=20),
    Field("reverse_torque_ratio", "number",
          "reversed torque over T1 for teeth loaded both ways (0: one-way loading)",
          symbol="T_rev/T1", default=0.0, minimum=0.0, maximum=1.0),
    TableList("spectrum", "load spectrum (instead of a regime)", BLOCK, required=False,
              examples=({"torque_ratio": 1.0, "time_share": 0.3},
                        {"torque_ratio": 0.6, "time_share": 0.5},
                        {"torque_ratio": 0.3, "time_share": 0.2, "speed_ratio": 1.0}),
              hint="the time shares must add up to 1; torque1 is the largest block"),
), required=False, hint="speed1 alone gives the velocities; torque1 (or power) and life_hours "
                        "with [material] give the strength")


def _material(who: str) -> Table:
    return Table(who, f"material of the {who}", (
        Field("grade", "string", "steel grade from the library (`geardesign materials` lists "
              "them): GOST 45, 40Kh, 40KhN, 35KhM, 30KhGSA, 20Kh, 18KhGT, 20KhN3A, 12KhN3A, "
              "38Kh2MYuA, 40KhL (cast); EN 42CrMo4, C45, 34CrNiMo6, 16MnCr5, 20MnCr5, "
              "18CrNiMo7-6, 31CrMo12, 33CrMoV12-9, 34CrAlMo5-10; AISI/SAE 4340, 8620, 9310; "
              "equivalent names (1.7131, AISI 4140) are read as their row",
              default=None, example="40Kh",
              hint="leave out to give the properties yourself"),
        Field("treatment", "string", "heat treatment", example="improved",
              choices=("normalized", "improved", "through_hardened", "induction", "carburized",
                       "nitrided")),
        Field("hardness_HB", "number", "surface hardness (normalized, improved)", "HB",
              default=None, minimum=100, maximum=700, example=280.0 if who == "pinion" else 250.0),
        Field("hardness_HRC", "number",
              "surface hardness (through_hardened, induction, carburized)", "HRC", default=None,
              minimum=20, maximum=70),
        Field("hardness_HV", "number", "surface hardness (nitrided)", "HV", default=None,
              minimum=100, maximum=1200),
        Field("core_HRC", "number", "core hardness (nitrided: σ_Flim = 12·HRC_core + 290)",
              "HRC", default=None, minimum=10, maximum=60),
        Field("roughness_Ra", "number", "flank roughness Ra", "µm", "Ra", default=1.25, gt=0,
              maximum=40),
        Field("root_ground", "boolean", "root ground after hardening (then q_F = 6)",
              default=False),
        Field("blank", "string", "blank", default="forging", choices=("forging", "rolled",
                                                                     "casting")),
        Field("E", "number", "Young's modulus", "MPa", "E", default=None, gt=0, maximum=1e6),
        Field("nu", "number", "Poisson's ratio", symbol="ν", default=None, minimum=0, lt=0.5),
        Field("sigma_T", "number", "yield strength of the blank", "MPa", "σ_T", default=None,
              gt=0, maximum=5000),
        Field("sigma_Hlim", "number", "contact endurance limit", "MPa", "σ_Hlim", default=None,
              minimum=150, maximum=5000,
              hint="the weakest gear materials (grey cast iron) have about 300 MPa"),
        Field("sigma_Flim", "number", "bending endurance limit", "MPa", "σ_Flim", default=None,
              minimum=30, maximum=3000,
              hint="the weakest gear materials (grey cast iron) have about 50 MPa"),
        Field("S_H", "number", "required contact safety factor", symbol="S_Hmin", default=None,
              minimum=1.0, maximum=5.0),
        Field("S_F", "number", "required bending safety factor", symbol="S_Fmin", default=None,
              minimum=1.0, maximum=5.0),
        Field("sigma_HPmax", "number", "allowable contact stress at the peak load", "MPa",
              "σ_HPmax", default=None, gt=0, maximum=10000),
        Field("sigma_FSt", "number", "limit bending stress at the peak load", "MPa", "σ_FSt",
              default=None, gt=0, maximum=10000),
    ))


MATERIAL = Table("material", "materials (for the strength calculation)",
                 (_material("pinion"), _material("wheel")), required=False)

_FACTOR_NAMES = (
    # key, name, minimum, maximum: each factor's physical domain (a load factor is never
    # below 1; life, size and surface factors stay within what GOST 21354-87 can produce)
    ("K_Hv", "dynamic factor, contact", 1.0, 10.0),
    ("K_Hbeta", "face load factor, contact", 1.0, 10.0),
    ("K_Halpha", "transverse load factor, contact", 1.0, 10.0),
    ("K_Fv", "dynamic factor, bending", 1.0, 10.0),
    ("K_Fbeta", "face load factor, bending", 1.0, 10.0),
    ("K_Falpha", "transverse load factor, bending", 1.0, 10.0),
    ("Z_E", "elasticity factor [√MPa]", 50.0, 300.0),
    ("Z_H", "zone factor", 1.0, 3.5),
    ("Z_eps", "contact ratio factor", 0.5, 1.0),
    ("Z_N1", "life factor, contact, pinion", 0.5, 3.0),
    ("Z_N2", "life factor, contact, wheel", 0.5, 3.0),
    ("Z_Nmax1", "upper limit of Z_N, pinion", 1.0, 3.0),
    ("Z_Nmax2", "upper limit of Z_N, wheel", 1.0, 3.0),
    ("N_HG1", "base number of contact cycles, pinion", 1e5, 1e9),
    ("N_HG2", "base number of contact cycles, wheel", 1e5, 1e9),
    ("Z_R1", "roughness factor, pinion", 0.5, 1.2),
    ("Z_R2", "roughness factor, wheel", 0.5, 1.2),
    ("Z_v1", "velocity factor, pinion", 0.8, 1.5),
    ("Z_v2", "velocity factor, wheel", 0.8, 1.5),
    ("Z_X1", "size factor, contact, pinion", 0.5, 1.2),
    ("Z_X2", "size factor, contact, wheel", 0.5, 1.2),
    ("Y_FS1", "tooth form factor, pinion", 2.0, 8.0),
    ("Y_FS2", "tooth form factor, wheel", 2.0, 8.0),
    ("Y_R", "root surface factor (1 if not given)", 0.5, 1.5),
    ("Y_beta", "helix factor", 0.5, 1.0),
    ("Y_eps", "contact ratio factor, bending", 0.1, 1.0),
    ("Y_delta", "notch sensitivity factor", 0.5, 1.5),
    ("N_FG", "base number of bending cycles", 1e5, 1e9),
    ("Y_N1", "life factor, bending, pinion", 0.5, 4.0),
    ("Y_N2", "life factor, bending, wheel", 0.5, 4.0),
    ("Y_X1", "size factor, bending, pinion", 0.5, 1.2),
    ("Y_X2", "size factor, bending, wheel", 0.5, 1.2),
    ("Y_A1", "reversed-load factor, pinion", 0.3, 1.0),
    ("Y_A2", "reversed-load factor, wheel", 0.3, 1.0),
    ("S_FSt", "safety factor against the static bending limit", 1.0, 5.0),
)
FACTORS = Table("factors", "load and strength factors given instead of computed", tuple(
    Field(key, "number", name, symbol=key.replace("beta", "β").replace("alpha", "α")
          .replace("eps", "ε").replace("delta", "δ"),
          default=None, minimum=lo, maximum=hi) for key, name, lo, hi in _FACTOR_NAMES
), required=False, hint="each given factor replaces the computed one and is marked in the report")

OPTIONS = Table("options", "calculation options", (
    Field("method", "string", "strength method", default="GOST 21354-87",
          choices=tuple(METHODS)),
    OPTIONS_METHODS,
    Field("contact_model", "string", "extra contact stress model, informative: the n = 0.7 "
          "deformation law of Popov et al. 2017", default="hertz", choices=("hertz", "popov_n07")),
    Field("crowning", "number", "crowning depth of the pinion at the face ends (informative "
          "point-contact stress)", "mm", "ΔS", default=None, gt=0, maximum=1.0),
), required=False, implicit=True)

SCHEMA = SpecSchema(
    kind="spur",
    description="external or internal spur/helical gear pair: geometry (GOST 16532-70, "
                "GOST 19274-73) and strength (GOST 21354-87 or ISO 6336:2019)",
    tables=(GEAR, DESIGN, RACK, LOAD, MATERIAL, FACTORS, OPTIONS, ISO, ISO_FACTORS, DR.ACCURACY,
            DR.DRAWING),
    title_example="Reducer stage 25/100, m = 4",
    one_of=(("gear", "design"),),
)
