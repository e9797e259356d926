"""The ``kind = "shaft"`` spec: keys, units, ranges and defaults (the single definition used
for validation, ``geardesign schema shaft`` and ``geardesign template shaft``)."""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table, TableList

METHODS = ("GOST", "DIN743")

BEARING_TYPES = ("deep_groove_ball", "cylindrical_roller", "tapered_roller", "spherical_roller",
                 "other")

SHAFT = Table("shaft", "operating conditions and design limits", (
    Field("speed", "number", "shaft speed", "min^-1", "n", gt=0, maximum=2e5, example=200.0),
    Field("peak_factor", "number", "peak torque and load over the nominal (static check)",
          symbol="K_p", default=2.0, minimum=1.0, maximum=10.0,
          hint="starting torque of the motor over the rated, or the overload of the drive"),
    Field("torsion_cycle", "string", "how the torsional stress varies", default="pulsating",
          choices=("pulsating", "reversed", "steady"),
          hint='"pulsating": 0 -> τ (τ_a = τ_m = τ/2, the textbook rule for a drive that '
               'starts and stops); "reversed": ±τ; "steady": constant τ'),
    Field("Rz", "number", "surface roughness R_z of the shaft (steps may give their own)",
          "µm", "R_z", default=6.3, minimum=0.1, maximum=320.0,
          hint="ground 1.6…3.2, fine turned 6.3…12.5"),
    Field("K_V", "number", "surface hardening factor (1: none; induction hardening, rolling, "
          "shot peening raise it)", symbol="K_V", default=1.0, minimum=0.5, maximum=3.0),
    Field("S_min", "number", "required fatigue safety factor", symbol="[S]", default=2.0,
          minimum=1.0, maximum=10.0,
          hint="[S] = 1.5…2.5 (Dunaev & Lelikov); method DIN743: default 1.2 (DIN 743-1)"),
    Field("S_static_min", "number", "required static safety factor against yield",
          symbol="[S_T]", default=1.5, minimum=1.0, maximum=10.0,
          hint="[S_T] = 1.3…2 (Dunaev & Lelikov); method DIN743: default 1.2 (DIN 743-1)"),
    Field("critical_speed_margin", "number", "required ratio of the first critical speed to "
          "the speed", symbol="n_cr/n", default=1.3, minimum=1.0, maximum=10.0),
    Field("method", "string", "strength method of the sections (fatigue and static)",
          default=None, choices=METHODS,
          hint='default "GOST" (GOST 25.504-82 as in Dunaev & Lelikov); "DIN743": DIN 743-1/-2/-3 '
               '(2012), with an EN steel grade or sigma_B, sigma_T and steel_type'),
    Field("din743_load_case", "integer", "DIN 743-1 load case of the mean stress under "
          "overload: 1 (σ_mv constant) or 2 (σ_mv/σ_a constant)", default=None, minimum=1,
          maximum=2, hint="default 2; method DIN743 only"),
    Field("din743_hard_surface", "boolean", "DIN 743 hard surface layer (case-hardened, "
          "nitrided, induction-hardened): support number, K_2F and γ_F", default=None,
          hint="default false; method DIN743 only"),
))

MATERIAL = Table("material", "shaft steel: a grade of the library, or its properties", (
    Field("grade", "string", "steel grade of the shaft-steel table (45, 40Kh, 40KhN, 20Kh, "
          "12KhN3A, 18KhGT; Cyrillic accepted); method DIN743: an EN grade of DIN 743-3 "
          "(C45, 42CrMo4, 34CrNiMo6, 16MnCr5, 18CrNiMo7-6, S235, E335, ...) or 45, 40Kh",
          default=None, example="45"),
    Field("hardness_HB", "number", "hardness of the blank; picks the row of the grade",
          symbol="HB", default=None, minimum=100.0, maximum=700.0, example=270.0,
          hint="default: the lowest hardness listed for the grade"),
    Field("sigma_B", "number", "ultimate tensile strength", "MPa", "σ_B", default=None,
          minimum=200.0, maximum=3000.0),
    Field("sigma_T", "number", "yield strength", "MPa", "σ_T", default=None, minimum=100.0,
          maximum=3000.0),
    Field("sigma_m1", "number", "endurance limit in rotating bending (smooth specimen)", "MPa",
          "σ_-1", default=None, minimum=50.0, maximum=1500.0, hint="default 0.43·σ_B"),
    Field("tau_m1", "number", "endurance limit in torsion", "MPa", "τ_-1", default=None,
          minimum=30.0, maximum=1000.0, hint="default 0.58·σ_-1"),
    Field("psi_sigma", "number", "mean-stress sensitivity in bending", symbol="ψ_σ",
          default=None, minimum=0.0, maximum=0.5, hint="default 0.02 + 2·10⁻⁴·σ_B"),
    Field("psi_tau", "number", "mean-stress sensitivity in torsion", symbol="ψ_τ",
          default=None, minimum=0.0, maximum=0.5, hint="default: the grade's, else 0.5·ψ_σ"),
    Field("alloy", "boolean", "alloy steel (size factor in bending)", default=None,
          hint="default: from the grade, else false"),
    Field("steel_type", "string", "DIN 743-3 steel type (technological size factor K_1), "
          "with sigma_B and sigma_T in place of a grade", default=None,
          choices=("structural", "quenched_tempered", "case_hardening",
                   "case_hardening_CrNiMo", "nitriding"), hint="method DIN743 only"),
    Field("d_eff", "number", "DIN 743 diameter of the blank at heat treatment (K_1)", "mm",
          "d_eff", default=None, gt=0, maximum=5000.0,
          hint="default: the largest step diameter; method DIN743 only"),
    Field("E", "number", "modulus of elasticity", "MPa", "E", default=2.06e5, minimum=1e4,
          maximum=5e5),
    Field("density", "number", "density (critical speed)", "kg/m^3", "ρ", default=7850.0,
          minimum=500.0, maximum=25000.0),
))

STEP = Table("step", "one cylindrical step of the shaft, from the left end", (
    Field("length", "number", "length of the step", "mm", "l", gt=0, example=60.0),
    Field("diameter", "number", "outside diameter", "mm", "d", gt=0, maximum=5000.0,
          example=50.0),
    Field("bore", "number", "bore of a hollow shaft", "mm", "d_0", default=0.0, minimum=0.0,
          maximum=5000.0),
    Field("start", "number", "position of the left end (optional check of the layout)", "mm",
          "x_0", default=None, minimum=0.0),
    Field("fillet", "number", "fillet radius of the shoulder at the right end", "mm", "r",
          default=1.0, gt=0, maximum=500.0),
    Field("keyway", "boolean", "a keyway in this step", default=False),
    Field("keyway_cutter", "string", "how the keyway is cut", default="end_mill",
          choices=("end_mill", "disc_cutter")),
    Field("press_fit", "boolean", "a hub (gear, bearing ring) fitted with interference",
          default=False),
    Field("groove_K_sigma", "number", "effective stress concentration factor in bending of a "
          "groove at the right end (from a handbook table)", symbol="K_σ", default=None,
          minimum=1.0, maximum=6.0,
          hint="method DIN743: the notch factor β_σ; or give the groove by its geometry "
               "(groove_depth, groove_radius, groove_width)"),
    Field("groove_K_tau", "number", "its factor in torsion (default: K_σ)", symbol="K_τ",
          default=None, minimum=1.0, maximum=6.0),
    Field("Rz", "number", "surface roughness of this step", "µm", "R_z", default=None,
          minimum=0.1, maximum=320.0),
    Field("groove_depth", "number", "DIN 743: depth of a groove cut into this step at its "
          "right end (round, or rectangular with groove_width)", "mm", "t", default=None,
          gt=0, maximum=1250.0,
          hint="method DIN743 only; the section is the groove root d = diameter − 2t"),
    Field("groove_radius", "number", "DIN 743: radius of a round groove, or the root radius "
          "of a rectangular groove", "mm", "r", default=None, minimum=0.0, maximum=1250.0,
          hint="method DIN743 only; with groove_depth"),
    Field("groove_width", "number", "DIN 743: width of a rectangular groove (retaining "
          "ring); leave out for a round groove", "mm", "m", default=None, gt=0,
          maximum=5000.0, hint="method DIN743 only; with groove_depth and groove_radius"),
    Field("groove_shape", "string", "DIN 743: shape of the groove (default: rectangular with "
          "groove_width, else round)", default=None, choices=("round", "rectangular", "V"),
          hint='method DIN743 only; "V": a sharp V-notch (Spitzkerbe), given by groove_depth '
               'alone'),
    Field("cross_bore", "number", "DIN 743: diameter of a radial hole through this step "
          "(pin, lubrication)", "mm", "d_L", default=None, gt=0, maximum=1500.0,
          hint="method DIN743 only; solid steps, d_L <= 0.3·diameter"),
    Field("cross_bore_at", "number", "DIN 743: position of the cross-bore from the step's "
          "left end", "mm", "x_L", default=None, minimum=0.0,
          hint="default: the middle of the step"),
))

LOAD = Table("load", "a load on the shaft: gear, pulley, coupling", (
    Field("name", "string", "name shown in the report", default=None, example="gear"),
    Field("position", "number", "distance from the left end of the shaft", "mm", "x",
          minimum=0.0, example=120.0),
    Field("Fy", "number", "radial force in y", "N", "F_y", default=0.0),
    Field("Fz", "number", "radial force in z", "N", "F_z", default=0.0),
    Field("Fx", "number", "axial force (+x)", "N", "F_x", default=0.0),
    Field("torque", "number", "torque put into the shaft here (input +, output −)", "N·m",
          "T", default=0.0),
    Field("moment_y", "number", "bending couple in the x–y plane (e.g. F_a·d/2)", "N·m",
          "M_y", default=0.0),
    Field("moment_z", "number", "bending couple in the x–z plane", "N·m", "M_z", default=0.0),
    Field("mass", "number", "mass of the part (critical speed)", "kg", "m", default=0.0,
          minimum=0.0),
    Field("module", "number", "module of a gear here: deflection limit 0.01·m", "mm", "m",
          default=None, gt=0, maximum=100.0),
))

SUPPORT = Table("support", "a bearing", (
    Field("name", "string", "name shown in the report", default=None, example="A"),
    Field("position", "number", "distance of the bearing centre from the left end", "mm",
          "x", minimum=0.0, example=20.0),
    Field("type", "string", "bearing type (permissible tilt)", default="other",
          choices=BEARING_TYPES),
    Field("stiffness", "number", "radial stiffness (default rigid)", "N/mm", "c_r",
          default=None, gt=0),
    Field("axial", "boolean", "this bearing takes the axial force (default the first)",
          default=False),
))

SCHEMA = SpecSchema(
    kind="shaft",
    description="Shaft: beam model (reactions, diagrams, deflection, slopes, critical speed), "
                "static strength and fatigue (GOST 25.504-82 / Dunaev & Lelikov, or DIN 743)",
    tables=(
        SHAFT, MATERIAL,
        TableList("step", "cylindrical steps from the left end", STEP, max_items=100,
                  examples=(
                      {"length": 40.0, "diameter": 45.0, "fillet": 1.5, "Rz": 3.2},
                      {"length": 80.0, "diameter": 55.0, "fillet": 2.0, "keyway": True,
                       "press_fit": True},
                      {"length": 10.0, "diameter": 62.0, "fillet": 2.0},
                      {"length": 30.0, "diameter": 45.0, "fillet": 1.0, "Rz": 3.2},
                      {"length": 70.0, "diameter": 40.0, "keyway": True},
                  )),
        TableList("load", "loads on the shaft", LOAD, min_items=1, max_items=100, examples=(
            {"name": "gear", "position": 80.0, "Fy": -2600.0, "Fz": 7000.0,
             "torque": 560.0, "moment_y": -150.0, "mass": 8.0, "module": 3.0},
            {"name": "coupling", "position": 195.0, "Fz": -1500.0, "torque": -560.0,
             "mass": 3.0},
        )),
        TableList("support", "bearings (at least two)", SUPPORT, min_items=1, max_items=20,
                  examples=(
                      {"name": "A", "position": 20.0, "type": "deep_groove_ball",
                       "axial": True},
                      {"name": "B", "position": 145.0, "type": "deep_groove_ball"},
                  )),
    ),
    title_example="output shaft of a helical reducer",
)
