"""The ``kind = "connection"`` spec: one shaft-hub connection per spec, a parallel key
([key]), an involute spline ([spline]) or an interference fit ([fit]), and the load ([load])."""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table

LOAD = Table("load", "the load the connection transmits", (
    Field("torque", "number", "nominal torque", "N·m", "T", gt=0, example=250.0),
    Field("application_factor", "number", "application factor (shocks of the driving and "
          "driven machines)", symbol="K_A", default=1.0, minimum=1.0, maximum=5.0),
    Field("axial_force", "number", "axial force on the joint (interference fit only)", "N",
          "F_ax", default=0.0, minimum=0),
))

KEY = Table("key", "parallel key (GOST 23360-78 / DIN 6885-1)", (
    Field("standard", "string", "key standard and method: GOST 23360-78 with the GOST practice "
          "(k = h − t1, permissible [σ]см), or DIN 6885-1 with DIN 6892 method C",
          default="GOST 23360-78", choices=("GOST 23360-78", "DIN 6885-1")),
    Field("shaft_diameter", "number", "shaft diameter", "mm", "d", gt=0, maximum=1000.0,
          example=40.0),
    Field("length", "number", "key length", "mm", "l", gt=0, maximum=1000.0, example=56.0),
    Field("form", "string", "key form: A both ends round (l_p = l − b), B square (l_p = l), "
          "C one end round (l_p = l − b/2)", default="A", choices=("A", "B", "C")),
    Field("count", "integer", "number of keys (two keys at 180° carry 1.5 times one)",
          symbol="n", default=1, choices=(1, 2)),
    Field("hub_length", "number", "hub length (the key must not be longer)", "mm", "L_hub",
          default=None, gt=0, maximum=1000.0),
    Field("hub_material", "string", "hub material", default="steel",
          choices=("steel", "cast_iron")),
    Field("width", "number", "key width b of a key not from the table", "mm", "b",
          default=None, gt=0, maximum=200.0, hint="give width, height and shaft_depth together"),
    Field("height", "number", "key height h of a key not from the table", "mm", "h",
          default=None, gt=0, maximum=200.0),
    Field("shaft_depth", "number", "keyway depth in the shaft t1 of a key not from the table",
          "mm", "t1", default=None, gt=0, maximum=200.0),
    Field("allowable_pressure", "number", "permissible bearing pressure (instead of the "
          "table)", "MPa", "p_zul", default=None, gt=0, maximum=2000.0),
    Field("allowable_shear", "number", "permissible shear stress of the key (instead of the "
          "table)", "MPa", "τ_zul", default=None, gt=0, maximum=2000.0),
    Field("shaft_strength", "number", "shaft yield strength R_e (DIN 6892 method C)", "MPa",
          "R_e,shaft", default=None, gt=0, maximum=3000.0),
    Field("hub_strength", "number", "hub strength: yield R_e (steel) or tensile R_m (cast "
          "iron) (DIN 6892 method C)", "MPa", "R_hub", default=None, gt=0, maximum=3000.0),
    Field("key_strength", "number", "key yield strength R_e (DIN 6892 method C)", "MPa",
          "R_e,key", default=None, gt=0, maximum=3000.0),
    Field("hardness_factor", "number", "hardness influence factor f_H (DIN 6892 method C)",
          symbol="f_H", default=1.0, minimum=1.0, maximum=1.5),
), required=False)

SPLINE = Table("spline", "involute spline, 30° (DIN 5480 / GOST 6033-80)", (
    Field("standard", "string", "spline standard and method (DIN 5480 with DIN 5466 "
          "heights, or GOST 6033-80 with h_w = 0.8·m, d_m = m·z)", default="DIN 5480",
          choices=("DIN 5480", "GOST 6033-80")),
    Field("designation", "string", "designation d_B x m x z, e.g. \"W 40x2x18\", or d_B x m "
          "for a size of the series table (instead of the numbers)", default=None,
          example="W 40x2x18"),
    Field("reference_diameter", "number", "reference (nominal) diameter d_B", "mm", "d_B",
          default=None, gt=0, maximum=1000.0),
    Field("module", "number", "module", "mm", "m", default=None, gt=0, maximum=20.0),
    Field("teeth", "integer", "number of teeth (from the series table when left out)",
          symbol="z", default=None, minimum=6, maximum=200),
    Field("length", "number", "engaged (hub) length", "mm", "l", gt=0, maximum=1000.0,
          example=30.0),
    Field("load_factor", "number", "load-distribution factor (share of teeth carrying)",
          symbol="ψ", default=0.75, minimum=0.3, maximum=1.0),
    Field("use", "string", "fixed hub, or hub sliding without or under load", default="fixed",
          choices=("fixed", "sliding_unloaded", "sliding_loaded")),
    Field("hardness", "string", "tooth hardness: soft up to 350 HB, hardened over 40 HRC",
          default="soft", choices=("soft", "hardened")),
    Field("conditions", "string", "operating conditions (fit, lubrication, shocks)",
          default="average", choices=("poor", "average", "good")),
    Field("allowable_pressure", "number", "permissible flank pressure (instead of the "
          "table)", "MPa", "p_zul", default=None, gt=0, maximum=2000.0),
), required=False)

FIT = Table("fit", "cylindrical interference fit (DIN 7190-1, elastic)", (
    Field("diameter", "number", "joint diameter", "mm", "d_F", gt=0, maximum=1000.0,
          example=50.0),
    Field("hub_outer_diameter", "number", "hub outer diameter", "mm", "D_aA", gt=0,
          maximum=5000.0, example=90.0),
    Field("shaft_bore", "number", "bore of a hollow shaft (0: solid)", "mm", "D_iI",
          default=0.0, minimum=0, maximum=1000.0),
    Field("length", "number", "joint (fit) length", "mm", "l_F", gt=0, maximum=1000.0,
          example=40.0),
    Field("fit", "string", "ISO 286 hole-basis fit, e.g. \"H7/s6\" (or give the "
          "interferences)", default=None, example="H7/s6"),
    Field("interference_min", "number", "smallest interference (instead of a fit)", "µm",
          "U_min", default=None, minimum=-1e4, maximum=1e4),
    Field("interference_max", "number", "largest interference (instead of a fit)", "µm",
          "U_max", default=None, minimum=-1e4, maximum=1e4),
    Field("rz_shaft", "number", "mean roughness depth of the shaft", "µm", "Rz_I",
          default=4.0, minimum=0, maximum=100.0),
    Field("rz_hub", "number", "mean roughness depth of the hub bore", "µm", "Rz_A",
          default=4.0, minimum=0, maximum=100.0),
    Field("joining", "string", "shrink fit (hub heated) or longitudinal press fit",
          default="shrink", choices=("shrink", "press")),
    Field("surface", "string", "joint faces oiled (normal) or degreased (dry)",
          default="oiled", choices=("oiled", "dry")),
    Field("friction", "number", "coefficient of friction against slip (instead of the "
          "table)", symbol="μ", default=None, minimum=0.01, maximum=1.0),
    Field("friction_press_in", "number", "coefficient of friction for the press-in force "
          "(instead of the table of longitudinal press fits)", symbol="μ_e", default=None,
          minimum=0.01, maximum=1.0),
    Field("pressure_limit", "string", "permissible joint pressure: \"DIN 7190-1\" "
          "(R_e·(1 − Q²)/√3 at the bores, 2·R_e/√3 for a solid shaft) or \"von Mises\" (the "
          "exact plane-stress limit)", default="DIN 7190-1",
          choices=("DIN 7190-1", "von Mises")),
    Field("slip_safety", "number", "required safety against slip", symbol="S_R",
          default=1.5, minimum=1.0, maximum=10.0),
    Field("yield_safety", "number", "required safety against yield at the largest "
          "interference", symbol="S_P", default=1.1, minimum=1.0, maximum=10.0),
    Field("hub_material", "string", "hub material (friction table)", default="steel",
          choices=("steel", "cast_iron")),
    Field("shaft_modulus", "number", "shaft elastic modulus", "MPa", "E_I", default=210000.0,
          minimum=1000.0, maximum=1e6),
    Field("shaft_poisson", "number", "shaft Poisson's ratio", symbol="ν_I", default=0.3,
          minimum=0.0, maximum=0.5),
    Field("shaft_yield", "number", "shaft yield strength", "MPa", "R_eI", gt=0,
          maximum=3000.0, example=355.0),
    Field("hub_modulus", "number", "hub elastic modulus", "MPa", "E_A", default=210000.0,
          minimum=1000.0, maximum=1e6),
    Field("hub_poisson", "number", "hub Poisson's ratio", symbol="ν_A", default=0.3,
          minimum=0.0, maximum=0.5),
    Field("hub_yield", "number", "hub yield strength", "MPa", "R_eA", gt=0, maximum=3000.0,
          example=355.0),
    Field("hub_expansion", "number", "hub coefficient of thermal expansion", "1/K", "α_A",
          default=11e-6, minimum=1e-7, maximum=1e-4),
    Field("room_temperature", "number", "temperature of the shaft at assembly", "°C", "ϑ_0",
          default=20.0, minimum=-60.0, maximum=200.0),
    Field("joining_clearance", "number", "clearance needed to slip the heated hub on "
          "(default 0.001·d_F)", "mm", "Δs", default=None, minimum=0, maximum=10.0),
), required=False)

SCHEMA = SpecSchema(
    kind="connection",
    description="shaft-hub connection: parallel key, involute spline or interference fit",
    tables=(LOAD, KEY, SPLINE, FIT),
    title_example="Gear hub on a 40 mm shaft, key 12x8x56",
    one_of=(("key", "spline", "fit"),),
)
