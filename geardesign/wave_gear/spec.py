"""The ``kind = "wave_gear"`` spec: keys, units, ranges and defaults (the single definition
used for validation, ``geardesign schema wave_gear`` and ``geardesign template wave_gear``)."""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table

GEAR = Table("gear", "wave gear and its flexible wheel", (
    Field("module", "number", "module", "mm", "m", minimum=0.05, maximum=20, example=1.0),
    Field("flex_teeth", "integer", "teeth of the flexible wheel", symbol="z_g", minimum=20,
          maximum=2000, example=200),
    Field("waves", "integer", "number of deformation waves", symbol="U", default=2,
          minimum=2, maximum=4),
    Field("rigid_teeth", "integer", "teeth of the rigid wheel (default z_g + U)",
          symbol="z_b", default=None, minimum=22, maximum=2100),
    Field("rim_thickness", "number", "rim thickness under the tooth spaces", "mm", "H0",
          gt=0, example=2.5, hint="H0/m = 2.5...3 recommended"),
    Field("radial_deflection", "number", "radial deflection of the rim at the major axis "
          "(default w0 = m)", "mm", "w0", default=None, gt=0),
    Field("shift", "number", "profile shift coefficient of the flexible wheel", symbol="x_g",
          default=None, minimum=-1.0, maximum=20.0),
    Field("shift_rule", "string", "recommended shift when gear.shift is not given",
          default=None, choices=("eq7", "eq8"),
          hint='"eq7": x = 2.15 + 0.009·z_g (used when neither is given); "eq8": x = 0.022·z_g'),
    Field("effective_tooth_height", "number", "tooth height taking part in bending, × m",
          symbol="h/m", default=0.45, minimum=0.1, maximum=2.25,
          hint="0.45 calibrated on steel racks by Tkachenko et al.; 0.35 from photoelasticity"),
    Field("shell_thickness", "number", "wall thickness of the smooth cylindrical shell (cup)",
          "mm", "δ", default=None, gt=0, hint="gives the torsional shear stress"),
))

RACK = Table("rack", "basic rack of the flexible-wheel teeth (GOST 13755-81)", (
    Field("pressure_angle", "number", "profile angle", "deg", "α", default=20.0, gt=10, lt=35),
    Field("addendum_coef", "number", "addendum coefficient", symbol="h_a*", default=1.0,
          minimum=0.3, maximum=2.0),
    Field("clearance_coef", "number", "bottom clearance coefficient", symbol="c*",
          default=0.25, minimum=0, maximum=1.0),
    Field("root_radius_coef", "number", "root fillet radius coefficient", symbol="ρ_f*",
          default=0.38, minimum=0, maximum=1.0),
), required=False, implicit=True)

GENERATOR = Table("generator", "wave generator", (
    Field("shape_factor", "number", "ring-bending factor of the deformation shape",
          symbol="C_gen", default=1.5, minimum=0.1, maximum=5,
          hint="1.5 for the cos 2φ shape of a cam generator; disc and roller generators "
               "roughly 2...3 (uncertain)"),
), required=False, implicit=True)

MATERIAL = Table("material", "flexible-wheel material", (
    Field("elastic_modulus", "number", "elastic modulus", "MPa", "E", default=206000.0, gt=0),
    Field("sigma_m1", "number", "bending endurance limit (symmetric cycle)", "MPa", "σ_-1",
          gt=0, maximum=3000, example=450.0),
    Field("K_sigma", "number", "effective stress-concentration factor of the tooth spaces",
          symbol="K_σ", minimum=1, maximum=5, example=1.6,
          hint="from endurance tests; typically 1.3...2.0 for H0/m = 1...4 (the paper's "
               "Fig. 4 values are not legible)"),
    Field("tau_m1", "number", "torsional endurance limit (default 0.58·σ_-1)", "MPa", "τ_-1",
          default=None, gt=0),
    Field("psi_tau", "number", "sensitivity to the mean shear stress", symbol="ψ_τ",
          default=0.05, minimum=0, maximum=1),
    Field("required_safety", "number", "required fatigue safety factor", symbol="s_min",
          default=1.5, minimum=1, maximum=5, hint="1.5...1.7 usual"),
))

LOAD = Table("load", "operating data (optional)", (
    Field("output_torque", "number", "output torque", "N·m", "T2", gt=0, maximum=1e8,
          example=500.0),
    Field("input_speed", "number", "wave generator speed", "min^-1", "n_h", default=None, gt=0,
          maximum=1e5),
    Field("life", "number", "required life", "h", "L_h", default=None, gt=0),
    Field("reversing", "boolean", "torque reverses (shell shear alternates)", default=False),
), required=False)

SCHEMA = SpecSchema(
    kind="wave_gear",
    description="wave gear flexible wheel: stiffness factor K_zh, stress increase K_0, "
                "endurance (Tkachenko et al. 2017)",
    tables=(GEAR, RACK, GENERATOR, MATERIAL, LOAD),
    title_example="Wave gear m = 1, z_g = 200, H0 = 2.5 mm",
)
