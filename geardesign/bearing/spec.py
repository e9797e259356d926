"""The ``kind = "bearing"`` spec: keys, units, ranges and defaults (the single definition used
for validation, ``geardesign schema bearing`` and ``geardesign template bearing``)."""

from __future__ import annotations

from geardesign.bearing import tables as T
from geardesign.core.spec import REQUIRED, Field, SpecSchema, Table, TableList

METHOD = Field(
    "method", "string", "edition of the life calculation", default=REQUIRED,
    choices=("gost18855_94", "iso281_2007"), example="iso281_2007",
    hint='"gost18855_94": GOST 18855-94 (= ISO 281:1990), L = a1·a23·L10 with V, K_б, K_т; '
         '"iso281_2007": ISO 281:2007 (= GOST 18855-2013), L = a1·a_ISO·L10')
MODE = Field(
    "mode", "string", "what to do", default="check", choices=("check", "select", "pair"),
    hint='"check": life of the given bearing; "select": the smallest catalogue bearing of '
         'bearing.type and bore bearing.d that reaches requirements.life; "pair": two angular '
         'contact or tapered roller bearings adjusted against each other ([bearing] = bearing A, '
         '[pair] = bearing B), their axial loads solved from the radial loads and load.F_a')

BEARING = Table("bearing", "the bearing: a catalogue designation or its type and ratings", (
    Field("designation", "string", "catalogue designation: ISO (6208, NU 208, 7208 B, 30208, "
          "22208, 51108), the maker's (NU 208 ECP) or GOST (208, 7208 = 30208)", default=None,
          example="6208", hint="`geardesign bearings` lists the catalogue"),
    Field("maker", "string", "manufacturer whose catalogue row is used", default=None,
          hint='default: SKF, else the first maker listing the designation ("NTN")'),
    Field("type", "string", "bearing type", default=None, choices=T.TYPES,
          hint="taken from the catalogue when a designation is given"),
    Field("rows", "integer", "number of rows (double row, or a duplex pair acting as one)",
          default=1, choices=(1, 2)),
    Field("contact_angle", "number", "nominal contact angle", "deg", "α", default=None,
          minimum=0, maximum=90,
          hint="angular contact ball: 10, 12, 15 or 20…45; tapered/spherical/self-aligning: or "
               "give the catalogue e; thrust: 90 (default)"),
    Field("e", "number", "catalogue limit e of F_a/F_r (tapered, spherical, self-aligning; "
          "α follows from e = 1.5·tan α)", symbol="e", default=None, minimum=0.05, maximum=5),
    Field("Y", "number", "catalogue axial factor Y for F_a/F_r > e (replaces 0.4·cot α or "
          "0.67·cot α)", symbol="Y", default=None, minimum=0.1, maximum=20),
    Field("C_r", "number", "basic dynamic load rating (C_a for thrust bearings)", "N", "C_r",
          default=None, minimum=10.0, maximum=1e8),
    Field("C_0r", "number", "basic static load rating (C_0a for thrust bearings)", "N", "C_0r",
          default=None, minimum=10.0, maximum=1e8),
    Field("f0", "number", "catalogue factor f0 (ISO 76) for the f0·F_a/C_0r entry of the X/Y "
          "table", symbol="f_0", default=None, minimum=1.0, maximum=30,
          hint="without it the Fa/C0r column of GOST 18855-94 practice is used"),
    Field("C_u", "number", "fatigue load limit (catalogue P_u)", "N", "C_u", default=None, minimum=1.0,
          maximum=1e7, hint="ISO 281:2007 a_ISO; estimated from C_0r when not given"),
    Field("d", "number", "bore diameter", "mm", "d", default=None, minimum=1.0, maximum=5000),
    Field("D", "number", "outside diameter", "mm", "D", default=None, minimum=2.0, maximum=6000),
    Field("D_pw", "number", "pitch diameter of the rolling elements", "mm", "D_pw", default=None,
          minimum=1.5, maximum=6000, hint="default (d + D)/2"),
    Field("Z", "integer", "rolling elements per row (rating from geometry)", symbol="Z",
          default=None, minimum=3, maximum=200),
    Field("D_w", "number", "ball or roller diameter (rating from geometry)", "mm", "D_w",
          default=None, minimum=0.3, maximum=500),
    Field("L_we", "number", "effective roller length (roller rating from geometry)", "mm", "L_we",
          default=None, minimum=0.3, maximum=1000),
    Field("lubricant", "string", "oil or grease lubrication (axial capacity of NJ/NUP ribs)",
          default="oil", choices=("oil", "grease")),
    Field("series", "array", "catalogue series to search in select mode (e.g. [\"62\", \"63\"])",
          default=None, items="string"),
))

SPECTRUM_ITEM = Table("spectrum", "one block of the load spectrum", (
    Field("F_r", "number", "radial load", "N", "F_r", minimum=0, maximum=1e8, example=4000.0),
    Field("F_a", "number", "axial load", "N", "F_a", default=0.0, minimum=0, maximum=1e8),
    Field("speed", "number", "speed of the rotating ring", "min^-1", "n", minimum=0.01,
          maximum=2e5, example=1000.0),
    Field("time_share", "number", "share of the operating time", symbol="t", minimum=1e-9,
          maximum=1,
          example=0.3),
))

LOAD = Table("load", "loads and speed: one load case, or a spectrum of blocks", (
    Field("F_r", "number", "radial load", "N", "F_r", default=None, minimum=0, maximum=1e8,
          hint="or [[load.spectrum]] blocks"),
    Field("F_a", "number", "axial load", "N", "F_a", default=None, minimum=0, maximum=1e8,
          hint="0 when not given"),
    Field("speed", "number", "speed of the rotating ring", "min^-1", "n", default=None,
          minimum=0.01, maximum=2e5),
    Field("rotating_ring", "string", "ring rotating relative to the load (rotation factor V, "
          "GOST 18855-94 practice)", default="inner", choices=("inner", "outer")),
    Field("regime", "string", "typical load regime of GOST 21354-87 (P_E = K_E·P; loads are "
          "then the maximum loads)", default=None, choices=tuple(T.K_E)),
    Field("F_r0", "number", "peak radial load for the static check", "N", "F_r0", default=None,
          minimum=0, maximum=1e8, hint="default: the largest F_r times K_б"),
    Field("F_a0", "number", "peak axial load for the static check", "N", "F_a0", default=None,
          minimum=0, maximum=1e8, hint="default: the largest F_a times K_б"),
    TableList("spectrum", "blocks of the load spectrum", SPECTRUM_ITEM, required=False,
              examples=({"F_r": 4000.0, "F_a": 0.0, "speed": 1000.0, "time_share": 0.3},
                        {"F_r": 2500.0, "speed": 1500.0, "time_share": 0.7}),
              hint="instead of F_r, F_a, speed; time shares add up to 1"),
))

FACTORS = Table("factors", "service factors", (
    Field("K_b", "number", "dynamic (safety) factor K_б: 1.0 steady, 1.0–1.2 light shocks, "
          "1.3–1.5 moderate shocks (gear reducers), 1.8–2.5 heavy, 2.5–3.0 impacts",
          symbol="K_б", default=1.0, minimum=1.0, maximum=3.0),
    Field("temperature", "number", "bearing temperature (K_т = 1 up to 100 °C)", "°C", "t",
          default=None, minimum=-60, maximum=250),
    Field("a23", "number", "combined material and operating factor (GOST 18855-94 method)",
          symbol="a23", default=None, minimum=0.01, maximum=5,
          hint="default: middle of the textbook range for factors.conditions"),
    Field("conditions", "string", "operating conditions for the textbook a23", default=None,
          choices=T.A23_CONDITIONS,
          hint='"usual" (default), "hydrodynamic" (oil film, no excessive misalignment), '
               '"premium" (ESR/vacuum steel, oil film, no misalignment)'),
), required=False, implicit=True)

LUBRICATION = Table("lubrication", "lubricant and cleanliness (ISO 281:2007 a_ISO)", (
    Field("viscosity", "number", "kinematic viscosity at the operating temperature", "mm^2/s",
          "ν", default=None, minimum=1.0, maximum=20000, example=20.0,
          hint="or oil (+ temperature), or nu40 and nu100 (+ temperature), or kappa"),
    Field("oil", "string", "ISO VG grade of the oil (ISO 3448), e.g. \"VG 220\"", default=None,
          hint="ν at the operating temperature by ASTM D341 from the grade's ν at 40 °C and "
               "its viscosity index (`geardesign materials oil` lists the grades)"),
    Field("temperature", "number", "operating temperature of the bearing (oil film)", "°C", "t",
          default=None, minimum=-40, maximum=200, hint="required with oil or nu40"),
    Field("viscosity_index", "number", "viscosity index of the oil (ISO 2909)", symbol="VI",
          default=None, minimum=-50, maximum=400, hint="default: the library value of the grade"),
    Field("nu40", "number", "kinematic viscosity at 40 °C (instead of a grade)", "mm^2/s",
          "ν_40", default=None, minimum=1.0, maximum=20000),
    Field("nu100", "number", "kinematic viscosity at 100 °C (with nu40: the two points of "
          "ASTM D341)", "mm^2/s", "ν_100", default=None, minimum=0.5, maximum=2000),
    Field("nu1", "number", "rated viscosity ν1, instead of the ISO 281 formula", "mm^2/s",
          "ν_1", default=None, minimum=0.5, maximum=20000),
    Field("kappa", "number", "viscosity ratio κ = ν/ν1 given directly", symbol="κ", default=None,
          minimum=0.01, maximum=100),
    Field("contamination", "string", "contamination level (ISO 281 guide table, middle of the "
          "range)", default=None, choices=tuple(T.E_C_GUIDE), example="normal"),
    Field("e_C", "number", "contamination factor", symbol="e_C", default=None, minimum=0,
          maximum=1, hint="overrides contamination"),
    Field("ep_additives", "boolean", "lubricant with effective EP additives", default=False),
), required=False)

PAIR = Table("pair", "bearing B of a pair (mode = \"pair\"): its data and radial load", (
    Field("arrangement", "string", "arrangement of the two bearings",
          choices=("back_to_back", "face_to_face"), example="back_to_back",
          hint='"back_to_back" (O): a shaft force towards one bearing is carried by the other; '
               '"face_to_face" (X): by the bearing it points to; load.F_a > 0 points from A '
               'to B'),
    Field("F_r", "number", "radial load on bearing B", "N", "F_rB", minimum=0, maximum=1e8,
          example=3000.0),
    Field("designation", "string", "catalogue designation of bearing B", default=None,
          example="30206", hint="default: bearing A's designation (or give B's ratings)"),
    Field("maker", "string", "manufacturer of bearing B", default=None),
    Field("C_r", "number", "basic dynamic load rating of bearing B", "N", "C_rB", default=None,
          minimum=10.0, maximum=1e8),
    Field("C_0r", "number", "basic static load rating of bearing B", "N", "C_0rB", default=None,
          minimum=10.0, maximum=1e8),
    Field("C_u", "number", "fatigue load limit of bearing B", "N", "C_uB", default=None,
          minimum=1.0, maximum=1e7),
    Field("e", "number", "catalogue e of bearing B (tapered roller)", symbol="e_B",
          default=None, minimum=0.05, maximum=5),
    Field("Y", "number", "catalogue Y of bearing B (tapered roller)", symbol="Y_B",
          default=None, minimum=0.1, maximum=20),
    Field("contact_angle", "number", "contact angle of bearing B (angular contact ball)", "deg",
          "α_B", default=None, minimum=10, maximum=45),
    Field("d", "number", "bore of bearing B", "mm", "d_B", default=None, minimum=1.0,
          maximum=5000),
    Field("D", "number", "outside diameter of bearing B", "mm", "D_B", default=None,
          minimum=2.0, maximum=6000),
    Field("induced_factor", "number", "factor of the induced axial force: F_a = k·F_r/Y "
          "(tapered roller) or F_a = R·F_r (angular contact ball)", symbol="k, R",
          default=None, minimum=0.1, maximum=2.0,
          hint="default: k = 0.5 (ISO 281 practice, SKF, NTN; NSK uses 0.6); R of the SKF "
               "table by contact angle (0.5 at 20°, 0.57 at 25°, 0.66 at 30°, 0.88 at 40°)"),
), required=False, in_template=False)

REQUIREMENTS = Table("requirements", "what the design must achieve", (
    Field("life", "number", "required life", "h", "[L_h]", default=None, minimum=1.0, maximum=1e7,
          example=20000.0),
    Field("reliability", "number", "required reliability", "%", "R", default=90.0, minimum=90,
          maximum=99.95),
    Field("s0_min", "number", "least static safety factor C_0r/P_0", symbol="s_0min",
          default=T.S0_MIN_DEFAULT, minimum=0.1, maximum=10),
    Field("system_lives", "array", "lives of the other bearings of the system", "h",
          default=None, minimum=1.0, maximum=1e9),
    Field("weibull_slope", "number", "Weibull slope for the system life", symbol="e",
          default=None, minimum=0.3, maximum=5, hint="default 10/9 ball, 9/8 roller"),
), required=False, implicit=True)

SCHEMA = SpecSchema(
    kind="bearing",
    description="rolling-bearing life to GOST 18855-94 or ISO 281:2007 (GOST 18855-2013)",
    tables=(METHOD, MODE, BEARING, LOAD, FACTORS, LUBRICATION, PAIR, REQUIREMENTS),
    title_example="Deep groove ball bearing 6208, shaft of a gear reducer",
)
