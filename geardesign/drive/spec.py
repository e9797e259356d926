"""The ``kind = "drive"`` spec."""

from __future__ import annotations

from dataclasses import replace

from geardesign.core.spec import Field, SpecSchema, Table, TableList
from geardesign.shaft import spec as SHAFT_SPEC
from geardesign.spur.strength import METHODS
from geardesign.spur.strength.tables import REGIMES

STAGE_KINDS = ("spur", "bevel", "worm", "novikov", "planetary", "drive")

MOTOR = Table("motor", "the driving motor", (
    Field("power", "number", "nominal power", "kW", "P_m", default=None, gt=0, maximum=1e5,
          example=7.5, hint="or torque"),
    Field("torque", "number", "nominal torque (instead of power)", "N·m", "T_m", default=None,
          gt=0, maximum=1e7),
    Field("speed", "number", "nominal speed", "min^-1", "n_m", gt=0, maximum=1e5,
          example=1455.0),
    Field("peak_ratio", "number",
          "largest short-time torque over the nominal (starting torque), for the static checks",
          symbol="T_max/T", default=None, minimum=1.0, maximum=5.0, example=2.0),
))

LOAD = Table("load", "the driven machine and the duty", (
    Field("torque", "number", "torque the driven machine needs at the output shaft; the stages "
          "are rated for it (else for the motor's nominal torque)", "N·m", "T_out", default=None,
          gt=0, maximum=1e8),
    Field("speed", "number", "required output speed", "min^-1", "n_out", default=None, gt=0,
          maximum=1e5, example=58.0),
    Field("speed_tolerance", "number", "allowed deviation of the output speed", "%",
          default=4.0, gt=0, maximum=20),
    Field("life_hours", "number", "required life of every stage and bearing", "h", "L_h", gt=0,
          maximum=1e7, example=20000.0),
    Field("regime", "string", "typical load regime (GOST 21354-87) of the stages that do not "
          "give their own", default="0", choices=REGIMES),
    Field("application_factor", "number", "application factor K_A of the stages that do not "
          "give their own", symbol="K_A", default=1.0, minimum=1.0, maximum=3.0),
    Field("method", "string", "strength method of the spur and planetary stages that do not "
          "give their own (spur: options.method, planetary: strength.method)", default=None,
          choices=tuple(METHODS)),
))

STAGE = Table("stage", "a stage, from the input", (
    Field("name", "string", "name of the stage", default=None),
    Field("file", "string", "spec file of the stage, relative to this drive spec", default=None),
    Field("kind", "string", "calculator of an inline stage (its tables follow: [stage.gear], ...)",
          default=None, choices=STAGE_KINDS),
    Field("efficiency", "number", "efficiency of the stage (else the calculator's, or 0.98 for "
          "a cylindrical stage)", symbol="η", default=None, minimum=0.05, maximum=1.0),
), open=True)

GEAR_ON_SHAFT = Table("gear", "a gear on the shaft", (
    Field("stage", "integer", "stage of the gear: the shaft's index (its input member) or the "
          "index − 1 (its output member)", minimum=1, maximum=50, example=1),
    Field("position", "number", "position of the gear mid-plane along the shaft", "mm", "z",
          minimum=-1e5, maximum=1e5, example=60.0),
    Field("mate_angle", "number", "direction from this shaft's axis to the mating gear's axis",
          "deg", "θ", default=0.0, minimum=-360.0, maximum=360.0),
    Field("axial_sign", "integer", "direction of the gear's axial force: +1 towards bearing B, "
          "-1 towards A (a bevel gear: the direction of its back, the large end; the bevel "
          "calculator signs the force by hand and rotation)", default=1, choices=(-1, 1)),
    Field("mass", "number", "mass of the gear (critical speed of an analysed shaft)", "kg",
          "m", default=None, minimum=0.0, maximum=1e5,
          hint="default: a solid steel disc of the pitch diameter and the face width"),
))

LOAD_ON_SHAFT = Table("load", "an external force on the shaft: a coupling's radial force, "
                      "a belt pulley's pull, a chain sprocket's pull, a gear of a drive "
                      "outside this spec", (
    Field("position", "number", "position of the force along the shaft", "mm", "z",
          minimum=-1e5, maximum=1e5, example=-60.0),
    Field("force", "number", "radial force on the shaft (magnitude)", "N", "F",
          minimum=0.0, maximum=1e8, example=1500.0),
    Field("angle", "number", "direction of the force on the shaft in the drive's x–y plane, "
          "from x (as mate_angle)", "deg", "θ_F", default=0.0, minimum=-360.0,
          maximum=360.0),
    Field("axial", "number", "axial force on the shaft (+ towards bearing B)", "N", "F_a",
          default=0.0, minimum=-1e8, maximum=1e8),
    Field("mass", "number", "mass of the part that applies it (critical speed of an "
          "analysed shaft)", "kg", "m", default=0.0, minimum=0.0, maximum=1e5),
    Field("name", "string", "name of the load", default=None),
))

KEY_ON_SHAFT = Table("key", "a shaft-hub connection (key, spline or interference fit): the "
                     "connection calculator's [key], [spline] or [fit] keys follow", (
    Field("type", "string", "connection type", choices=("key", "spline", "fit"),
          example="key"),
    Field("position", "number", "position of the hub's middle along the shaft", "mm", "z",
          minimum=-1e5, maximum=1e5, example=60.0),
    Field("hub_length", "number", "length of the hub (the key, spline or fit must not be "
          "longer)", "mm", "L_hub", gt=0, maximum=1000.0, example=60.0),
    Field("name", "string", "name of the connection", default=None),
    Field("application_factor", "number", "application factor of the connection (default: "
          "load.application_factor)", symbol="K_A", default=None, minimum=1.0, maximum=5.0),
), open=True)

_SHAFT_LIMITS = tuple(
    replace(f, default=None, hint="default: motor.peak_ratio, else 2") if f.key == "peak_factor"
    # the required safeties default by the method (GOST 2.0 and 1.5, DIN743 1.2): left to
    # the shaft calculator
    else replace(f, default=None, hint=f"default: the shaft calculator's ({f.hint})")
    if f.key in ("S_min", "S_static_min")
    else f for f in SHAFT_SPEC.SHAFT.fields if f.key != "speed")

SHAFT = Table("shaft", "a shaft on two bearings", (
    Field("index", "integer", "shaft number: shaft i carries the output of stage i−1 and the "
          "input of stage i (1: motor side)", minimum=1, maximum=51, example=1),
    Field("name", "string", "name of the shaft", default=None),
    Field("bearing_a", "number", "position of bearing A along the shaft", "mm", "z_A",
          default=0.0, minimum=-1e5, maximum=1e5),
    Field("bearing_b", "number", "position of bearing B along the shaft", "mm", "z_B",
          minimum=-1e5, maximum=1e5, example=160.0),
    Field("fixed", "string", "bearing that takes the axial load", default="a", choices=("a", "b")),
    Field("stiffness_a", "number", "radial stiffness of bearing A for the beam model of an "
          "analysed shaft (its deflection tilts the shaft at the gears)", "N/mm", "c_A",
          default=None, minimum=1e3, maximum=1e9, hint="default: rigid"),
    Field("stiffness_b", "number", "radial stiffness of bearing B, as stiffness_a", "N/mm",
          "c_B", default=None, minimum=1e3, maximum=1e9, hint="default: rigid"),
    Field("method", "string", "bearing life method (see geardesign schema bearing)",
          default="gost18855_94", choices=("gost18855_94", "iso281_2007")),
    TableList("gear", "gears on the shaft", GEAR_ON_SHAFT, max_items=4),
    TableList("load", "external forces on the shaft (couplings, pulleys, sprockets): they "
              "load the bearings and, with steps, the shaft", LOAD_ON_SHAFT,
              required=False, max_items=6),
    Table("support_a", "bearing A: the [bearing] table of the bearing calculator (designation, "
          "or type and ratings)", (), open=True),
    Table("support_b", "bearing B, as support_a", (), open=True),
    Table("lubrication", "lubrication of both bearings (ISO 281:2007 method), as in the "
          "bearing calculator", (), required=False, open=True),
    Field("start", "number", "position of the shaft's left end (the first step) in the "
          "coordinates of bearing_a, bearing_b and the gears", "mm", "z_0", default=None,
          minimum=-1e5, maximum=1e5, hint="default 0"),
    Field("coupling", "number", "position of the coupling where the motor's torque enters "
          "(shaft 1) or the output torque leaves (the last shaft)", "mm", "z_c", default=None,
          minimum=-1e5, maximum=1e5,
          hint="default: the shaft end with the longer overhang beyond its bearing"),
    TableList("step", "the shaft's cylindrical steps from the left end, as in the shaft "
              "calculator: with them the shaft is analysed (strength, deflections, critical "
              "speed)", SHAFT_SPEC.STEP, required=False, max_items=100),
    Table("material", "the shaft steel, as in the shaft calculator (default: steel 45 at "
          "the lowest hardness of the table)", SHAFT_SPEC.MATERIAL.fields, required=False),
    Table("strength", "limits and surface of the shaft analysis, as [shaft] of the shaft "
          "calculator (the speed is the drive's)", _SHAFT_LIMITS, required=False),
    TableList("key", "shaft-hub connections (needs the steps)", KEY_ON_SHAFT, required=False,
              max_items=6),
))

SPLIT = Table("split", "ratio split helper: proposed stage ratios for an overall ratio", (
    Field("ratio", "number", "overall ratio wanted (else motor speed / load.speed)", symbol="u",
          default=None, minimum=1.0, maximum=1e5),
    Field("kinds", "array", "kinds of the stages, from the input", items="string",
          choices=("spur", "novikov", "worm", "bevel"), default=None, min_items=1, max_items=6,
          example=["spur", "spur"]),
    Field("rule", "string", "splitting rule", default="developed", choices=("equal", "developed"),
          hint='"developed": two cylindrical stages, u1 = 1.25·sqrt(u); "equal": u^(1/n)'),
), required=False)

LUBRICATION = Table("lubrication", "the oil and the dip lubrication: with it the stages' "
                    "efficiencies come from their losses and the oil temperature from the "
                    "heat balance ([thermal])", (
    Field("oil", "string", "ISO VG grade of the oil (ISO 3448), e.g. \"VG 220\"",
          example="VG 220", hint="`geardesign materials oil` lists the grades"),
    Field("viscosity_index", "number", "viscosity index of the oil (ISO 2909)", symbol="VI",
          default=None, minimum=0, maximum=400, hint="default: the library value of the grade"),
    Field("base_oil", "string", "base oil, for the lubricant factor X_L of the mesh friction "
          "(ISO/TR 14179-2)", default="mineral",
          choices=("mineral", "pao", "pag_insoluble", "pag_soluble", "traction",
                   "phosphate_ester")),
    Field("density", "number", "density of the oil at 15 °C", "kg/m^3", "ρ_15", default=880.0,
          minimum=700.0, maximum=1200.0),
    Field("roughness_Ra", "number", "mean arithmetic roughness Ra of the tooth flanks (pinion "
          "and wheel) of every cylindrical stage", "µm", "Ra", default=None, minimum=0.05,
          maximum=10.0, hint="default: the mean of the stage's material Ra (pinion, wheel)"),
    Field("immersion", "number", "depth the largest wheel dips into the oil (the oil level "
          "of all parallel gears)", "mm", "h", default=None, minimum=0.0, maximum=2000.0,
          hint="default: one tooth depth, 2.25·m_n of the largest wheel"),
    Field("oil_volume", "number", "oil volume in the sump", "l", "V_0", default=None,
          minimum=0.01, maximum=1e5, hint="default: the housing floor times the oil depth"),
    Field("seal_diameters", "array", "shaft diameters at the lip seals of the input and the "
                                     "output shaft", "mm", "d_s", default=None, min_items=2,
          max_items=2, gt=1.0, maximum=2000.0,
          hint="default: the bearing bore of shaft 1 and of the last shaft, else "
               "d = (T/(0.2·[τ]))^(1/3) with [τ] = 20 MPa"),
), required=False, in_template=False)

THERMAL = Table("thermal", "heat balance of the housing (with [lubrication])", (
    Field("ambient", "number", "ambient air temperature", "°C", "ϑ_0", default=20.0,
          minimum=-40.0, maximum=60.0),
    Field("max_oil_temperature", "number", "permissible oil sump temperature", "°C", "ϑ_max",
          default=90.0, minimum=30.0, maximum=150.0, hint="90–95 °C for mineral oils"),
    Field("area", "number", "cooling area of the housing", "m^2", "A", default=None,
          gt=0.0, maximum=1000.0, hint="default: from length, width and height"),
    Field("length", "number", "housing length (along the stages; the fan's air flow)", "mm",
          "L", default=None, gt=10.0, maximum=1e5,
          hint="default: estimated from the gears (wall gap (L_g)^(1/3) + 3 mm)"),
    Field("width", "number", "housing width (along the shafts)", "mm", "W", default=None,
          gt=10.0, maximum=1e5),
    Field("height", "number", "housing height", "mm", "H", default=None, gt=10.0,
          maximum=1e5),
    Field("base_cooled", "boolean", "the base gives off heat too (not on a foundation)",
          default=False),
    Field("emissivity", "number", "emissivity of the housing surface (painted: 0.9)",
          symbol="ε", default=0.9, minimum=0.0, maximum=1.0),
    Field("fan_velocity", "number", "air velocity of a fan along the housing", "m/s", "v_fan",
          default=0.0, minimum=0.0, maximum=60.0),
    Field("fan_share", "number", "share of the area the fan blows on", symbol="s_fan",
          default=0.5, minimum=0.0, maximum=1.0),
    Field("cooler", "number", "heat taken by an oil cooler", "kW", "P_cool", default=0.0,
          minimum=0.0, maximum=1e4),
), required=False, in_template=False)

SCHEMA = SpecSchema(
    kind="drive",
    description="a whole drive: motor, stages, shafts and bearings",
    tables=(MOTOR, LOAD,
            TableList("stage", "the stages, from the motor to the output", STAGE,
                      required=False, max_items=20,
                      examples=({"name": "high-speed helical", "kind": "spur",
                                 "gear": {"module": 2.0, "z1": 24, "z2": 152,
                                          "helix_angle": 12.0, "face_width": 56.0,
                                          "center_distance": 180.0, "x1": 0.2,
                                          "accuracy_grade": 8, "bearing_scheme": 3},
                                 "material": {
                                     "pinion": {"grade": "40Kh", "treatment": "improved",
                                                "hardness_HB": 290.0},
                                     "wheel": {"grade": "40Kh", "treatment": "improved",
                                               "hardness_HB": 260.0}}},
                                {"name": "low-speed spur", "kind": "spur",
                                 "gear": {"module": 4.0, "z1": 25, "z2": 99,
                                          "face_width": 80.0, "accuracy_grade": 8,
                                          "bearing_scheme": 5},
                                 "material": {
                                     "pinion": {"grade": "40KhN", "treatment": "improved",
                                                "hardness_HB": 300.0},
                                     "wheel": {"grade": "40Kh", "treatment": "improved",
                                               "hardness_HB": 270.0}}}),
                      hint="a stage is kind = ... with the stage's tables inline (as below), or "
                           "file = a spec of any stage kind in this spec's folder"),
            TableList("shaft", "shafts on two bearings: bearing loads and lives", SHAFT,
                      required=False, max_items=21, in_template=False,
                      hint="keys: index, bearing_a, bearing_b, fixed, method, stiffness_a, "
                           "stiffness_b, [[shaft.gear]] "
                           "(stage, position, mate_angle, axial_sign), [[shaft.load]] "
                           "(position, force, angle, axial), [shaft.support_a], "
                           "[shaft.support_b]; see specs/drive_two_stage_reducer.toml; with "
                           "[[shaft.step]], [shaft.material] and [[shaft.key]] the shafts and "
                           "their connections are analysed, see "
                           "specs/drive_reducer_shafts_keys_thermal.toml"),
            SPLIT, LUBRICATION, THERMAL),
    title_example="Two-stage reducer, 7.5 kW, 1455/58 min^-1",
)
