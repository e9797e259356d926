"""The ``kind = "epicycle_rim"`` spec: keys, units, ranges and defaults (the single definition
used for validation, ``geardesign schema epicycle_rim`` and ``geardesign template
epicycle_rim``).

Two analyses share the ring and planet data: the probabilistic fatigue of the rim (tables
[fillet], [material], [load], [[stage]] and the optional [fatigue]) and the parametric
resonance of the ring ([resonance], with [vehicle] for the speeds).  A spec gives one or
both.  Rules that involve several keys are checked in :mod:`.inputs`.
"""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table, TableList
from geardesign.epicycle_rim.stress import MEAN_STRESS_MODELS
from geardesign.epicycle_rim.tables import loading_modes
from geardesign.materials.fatigue_steel import grades

RING = Table("ring", "ring gear (internal, spur)", (
    Field("module", "number", "module", "mm", "m", minimum=0.05, maximum=100, example=3.25),
    Field("z", "integer", "number of teeth of the ring", symbol="z_r", minimum=12,
          maximum=1000, example=64),
    Field("face_width", "number", "working face width of the ring", "mm", "b", gt=0,
          maximum=2000, example=60.0),
    Field("rim_thickness", "number", "rim thickness from the root circle to the outer surface",
          "mm", "δ", gt=0, maximum=500, example=12.0),
    Field("tooth_height", "number", "tooth height", "mm", "h", default=None, gt=0,
          maximum=200, example=7.3, hint="default 2.25·m"),
))

PLANETS = Table("planets", "planets of the 2K-H train (fixed ring)", (
    Field("count", "integer", "number of planets", symbol="n_p", minimum=2, maximum=12,
          example=3),
    Field("z_sun", "integer", "number of teeth of the sun", symbol="z_s", default=None,
          minimum=6, maximum=1000, example=26,
          hint="with z_planet: coaxiality and assembly checks"),
    Field("z_planet", "integer", "number of teeth of a planet", symbol="z_p", default=None,
          minimum=6, maximum=1000, example=19),
    Field("x_sun", "number", "profile shift coefficient of the sun", symbol="x_s", default=0.0,
          minimum=-1.0, maximum=2.0, hint="used for the neighbouring (spacing) check"),
    Field("x_planet", "number", "profile shift coefficient of the planets", symbol="x_p",
          default=0.0, minimum=-1.0, maximum=2.0),
    Field("angles", "array", "angular positions of the planet axes on the carrier", "deg",
          "ψ", default=None, minimum=0, lt=360, min_items=2, max_items=12,
          hint="default: equally spaced; give angles or shifts, not both"),
    Field("shifts", "array", "relative shifts k of adjacent planet axes from equal spacing, "
          "in ring pitches (paper B)", "-", "k", default=None, minimum=-1, maximum=1,
          min_items=2, max_items=12, hint="sum 0; planet i+1 at ψ_i + 360°/n_p + k_i·360°/z_r"),
    Field("contact_ratio", "number", "transverse contact ratio of the ring-planet mesh",
          symbol="ε_α", default=None, gt=1, maximum=4, example=1.42,
          hint="required by [resonance]"),
))

FILLET = Table("fillet", "tooth-root fillet of the ring (fatigue analysis)", (
    Field("root_chord", "number", "tooth thickness at the root, chord across the fillets",
          "mm", "S", gt=0, maximum=200, example=9.0),
    Field("radius", "number", "minimum radius of the fillet (transition curve)", "mm", "ρ",
          gt=0, maximum=50, example=0.6),
    Field("radius_tolerance", "number", "tolerance of the fillet radius, taken as ±3 standard "
          "deviations", "mm", "Δρ", default=0.0, minimum=0, maximum=50, example=0.06),
    Field("roughness", "number", "roughness of the fillet", "µm", "Rz", gt=0, maximum=320,
          example=25.0),
    Field("hardening_factor", "number", "surface hardening factor (1 without; 2-2.5 induction "
          "hardening, nitriding, roller burnishing)", "-", "K_V", default=1.0, minimum=1,
          maximum=3),
), required=False)

_GRADES = tuple(grades())

MATERIAL = Table("material", "ring material (fatigue analysis)", (
    Field("grade", "string", "steel grade from the library (its values fill the strengths "
          "not given)", default=None, choices=_GRADES, example=_GRADES[0]),
    Field("sigma_u", "number", "ultimate tensile strength", "MPa", "σ_u", default=None,
          gt=0, maximum=3000),
    Field("sigma_y", "number", "yield strength", "MPa", "σ_y", default=None, gt=0,
          maximum=3000),
    Field("sigma_m1", "number", "bending endurance limit of smooth standard specimens",
          "MPa", "σ_-1", default=None, gt=0, maximum=2000),
    Field("specimen_diameter", "number", "diameter of the standard specimen", "mm", "d0",
          default=7.5, gt=0, maximum=100),
    Field("blank_size", "number", "wall thickness of the tubular blank (or bar diameter) the "
          "ring is made from", "mm", "δ3", gt=0, maximum=2000, example=34.0),
    Field("scatter", "number", "coefficient of variation of σ_-1 between heats", "-",
          "v_σ-1", default=0.06, minimum=0, maximum=0.5,
          hint="GOST 25.504-82 gives 0.04-0.10; 0.06 as taken in paper A"),
    Field("anisotropy_factor", "number", "anisotropy factor; default 1 − σ_u/6000", "-",
          "K_A", default=None, minimum=0.3, maximum=1),
), required=False)

LOAD = Table("load", "loads at the rated ring torque (fatigue analysis)", (
    Field("bending_stress", "number", "root bending stress of the ring teeth by GOST 21354-87",
          "MPa", "σ_F", default=None, gt=0, maximum=5000, example=259.3,
          hint="with form_factor; or give nominal_bending_stress"),
    Field("form_factor", "number", "tooth form factor (includes the root concentration)", "-",
          "Y_F", default=None, minimum=0.5, maximum=10, example=3.3),
    Field("nominal_bending_stress", "number", "nominal tooth bending stress without "
          "concentration, σ_F/Y_F", "MPa", "σ_Fn", default=None, gt=0, maximum=3000),
    Field("load_sharing", "number", "load-sharing non-uniformity factor between planets", "-",
          "K_c", minimum=0.5, maximum=5, example=1.4),
    Field("hoop_source", "string", "where the rim hoop stresses come from", default="given",
          choices=("given", "thin_ring"),
          hint='"given": hoop_stress_loaded and hoop_stress_between (e.g. from FE); '
               '"thin_ring": a free thin-ring estimate from ring_torque (rough)'),
    Field("hoop_stress_loaded", "number", "rim hoop stress on the inner surface under the "
          "loaded tooth", "MPa", "σ_t,load", default=None, minimum=-3000, maximum=3000,
          example=-72.5),
    Field("hoop_stress_between", "number", "rim hoop stress on the inner surface midway "
          "between loaded teeth", "MPa", "σ_t,betw", default=None, minimum=-3000,
          maximum=3000, example=51.6),
    Field("ring_torque", "number", "ring torque at which the stresses are given", "N·m",
          "T0", default=None, gt=0, example=4023.0, hint="required by hoop_source = "
          '"thin_ring"'),
    Field("pressure_angle", "number", "working pressure angle of the ring-planet mesh, for "
          "the thin-ring estimate", "deg", "α_w", default=None, gt=10, lt=40,
          hint="default 20 with hoop_source = \"thin_ring\""),
    Field("fatigue_exponent", "integer", "exponent of the tooth fatigue curve (loading-mode "
          "factor)", symbol="q_F", default=6, choices=(6, 9), hint="6 for HB < 350, 9 above"),
), required=False)

_MODES = tuple(loading_modes())

STAGE = TableList("stage", "operating stages (e.g. traction, electrodynamic braking)", Table(
    "stage", "stage", (
        Field("name", "string", "name of the stage", example="acceleration"),
        Field("tension_fillet", "string", "fillet on the tension side of the loaded tooth in "
              "this stage", choices=("left", "right"), example="right"),
        Field("mu_F", "number", "loading-mode factor of the stage", "-", "μ_F", default=None,
              minimum=0.01, maximum=1, example=0.606,
              hint="or give mode, or torque_levels with time_fractions"),
        Field("mode", "string", "GOST 21354-87 typical loading mode (μ_F = K_FE^(1/q_F))",
              default=None, choices=_MODES),
        Field("torque_levels", "array", "torque spectrum: relative torques T_i/T_max", "-",
              "T_i'", default=None, minimum=1e-3, maximum=1, max_items=100),
        Field("time_fractions", "array", "durations of the torque levels (any unit)", "-",
              "t_i", default=None, minimum=1e-9, maximum=1e9, max_items=100),
        Field("distance_share", "number", "share of the distance run in this stage (for the "
              "life in km)", "-", default=None, minimum=1e-4, maximum=1, example=0.36),
    )), required=False,
    examples=({"name": "acceleration", "tension_fillet": "right", "mu_F": 0.606,
               "distance_share": 0.36},
              {"name": "ed_braking", "tension_fillet": "left", "mu_F": 0.549,
               "distance_share": 0.29}))

FATIGUE = Table("fatigue", "fatigue method options", (
    Field("mean_stress_model", "string", "limiting-amplitude diagram for the mean stress",
          default="cubic", choices=MEAN_STRESS_MODELS,
          hint='"cubic": paper A eq. (8); "kinasoshvili": σ_a + ψ_σD·σ_m (GOST 25.504-82)'),
    Field("stress_concentration", "number", "theoretical SCF of the fillet; default "
          "(1 + 3.25·S/ρ)^0.22", "-", "α_σ", default=None, minimum=1, maximum=20),
    Field("stress_gradient", "number", "relative stress gradient at the fillet; default from "
          "concentrator_depth", "1/mm", "G", default=None, gt=0, maximum=1000),
    Field("concentrator_depth", "number", "depth of the concentrator in the gradient formula",
          "mm", "t", default=None, gt=0, maximum=100, example=0.635,
          hint="paper A does not state it; its G = 13.01 mm⁻¹ needs t = 0.635 mm"),
    Field("stressed_perimeter", "number", "perimeter of the working section; default 2·b",
          "mm", "L", default=None, gt=0),
    Field("knee_cycles", "number", "cycles at the knee of the S-N curve", "-", "N_G",
          default=2e6, minimum=1e5, maximum=1e8),
    Field("slgn_alpha", "number", "coefficient α of lg S_lgN = α + β·lg σ̄", "-", "α",
          default=-0.8, minimum=-2, maximum=0,
          hint="10^α is the scatter S_lgN of lg N at the endurance limit: 0.01...1 decade"),
    Field("slgn_beta", "number", "coefficient β of lg S_lgN = α + β·lg σ̄", "-", "β",
          default=-2.3, minimum=-10, maximum=0,
          hint="β <= 0: the scatter of lg N falls as the stress rises"),
    Field("probabilities", "array", "probabilities of non-failure for the quantile and life "
          "tables", "%", "P", default=[50.0, 70.0, 90.0, 95.0], minimum=50, lt=100,
          max_items=20),
    Field("scatter_total", "number", "coefficient of variation of the part endurance limit; "
          "overrides eq. (14)", "-", "v_σ-1D", default=None, minimum=0.01, maximum=0.5),
    Field("stress_scatter", "number", "coefficient of variation of the acting stress "
          "amplitude", "-", "v_σa", default=0.0, minimum=0, maximum=0.5),
    Field("required_probability", "number", "required probability of non-failure", "%",
          "P_req", default=90.0, minimum=50, lt=100),
), required=False, hint="optional; defaults apply when the fatigue analysis runs")

VEHICLE = Table("vehicle", "vehicle drive kinematics (resonance speeds, life in km)", (
    Field("wheel_radius", "number", "rolling radius of the wheel", "mm", "R", gt=0,
          maximum=5000, example=500.0),
    Field("carrier_ratio", "number", "carrier speed over wheel speed (1: the carrier is the "
          "wheel hub)", "-", "i_HW", default=1.0, minimum=1e-3, maximum=1000),
    Field("speed_range", "array", "operating speed range", "km/h", "[V]", default=None,
          minimum=0, maximum=1000, min_items=2, max_items=2, example=[5.0, 55.0]),
), required=False)

RESONANCE = Table("resonance", "parametric resonance of the ring (Mathieu)", (
    Field("natural_frequencies", "array", "natural frequencies of the ring (e.g. FE modal "
          "analysis)", "Hz", "k0", minimum=1.0, maximum=1e6, max_items=50,
          example=[2233.0, 2442.0, 2654.0, 3284.0, 3346.0, 3770.0]),
    Field("orders", "array", "orders n of the resonances (a = n²)", "-", "n", items="integer",
          default=[1, 2, 3, 4], minimum=1, maximum=30, max_items=30),
    Field("phase_model", "string", "mesh phases of the planets", default="actual",
          choices=("actual", "paper"),
          hint='"actual": from the tooth count, frac(z_r·ψ/360°); "paper": equally spaced '
               'planets in phase (paper B)'),
    Field("depth", "string", "pulsation depth μ used in the Mathieu equation",
          default="harmonic", choices=("harmonic", "half_range"),
          hint='"harmonic": amplitude of the dominant harmonic of the stiffness; '
               '"half_range": (c_max − c_min)/(2·c_mean) as in paper B'),
    Field("stiffness_model", "string", "shape of the stiffness in time", default="sinusoid",
          choices=("sinusoid", "stepwise"),
          hint='"sinusoid": Mathieu (Ince-Strutt); "stepwise": Floquet transfer matrix of '
               'the exact pair count'),
    Field("harmonics", "integer", "number of stiffness harmonics reported", default=6,
          minimum=1, maximum=50),
    Field("floquet_check", "boolean", "check the Mathieu bands by numerical integration "
          "(Floquet trace, a few milliseconds)", default=False),
    Field("chart_b_max", "number", "largest b of the Ince-Strutt chart data; default "
          "covers the working line", "-", "b_max", default=None, minimum=0.01, maximum=100),
    Field("chart_points", "integer", "points of the Ince-Strutt chart data", default=21,
          minimum=2, maximum=401),
), required=False)

SCHEMA = SpecSchema(
    kind="epicycle_rim",
    description="ring gear (epicycle) rim: probabilistic fatigue (GOST 25.504-82, "
                "Serensen-Kogaev) and parametric resonance (Mathieu)",
    tables=(RING, PLANETS, FILLET, MATERIAL, LOAD, STAGE, FATIGUE, VEHICLE, RESONANCE),
    title_example="Ring gear m = 3.25, z = 64 of a three-planet wheel hub (Raba 118/77 "
                  "layout) with a 12 mm rim (3.7·m): fillet fatigue, reliability and "
                  "resonance, all checks passing",
)

FATIGUE_TABLES = ("fillet", "material", "load", "stage")
