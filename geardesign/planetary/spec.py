"""The ``kind = "planetary"`` spec: keys, units, ranges and defaults (the single definition
used for validation, ``geardesign schema planetary`` and ``geardesign template planetary``).

Modes: a spec with ``[teeth]`` analyses a given train; a spec with ``[synthesis]`` searches
tooth numbers (and shifts) for a target ratio, then analyses the best candidate.
"""

from __future__ import annotations

from dataclasses import replace

from geardesign.core.spec import Field, SpecSchema, Table
from geardesign.planetary.iso_inputs import ISO, ISO_FACTORS
from geardesign.spur.spec import PRESSURE_ANGLE, RACK, _material
from geardesign.spur.strength import METHODS
from geardesign.spur.strength import tables as T

MEMBER_CHOICES = ("sun", "ring", "ring2", "carrier")

TRAIN = Table("train", "the planetary train", (
    Field("scheme", "string", "scheme: 2K-H (sun, planet, ring, carrier), 2K-H-stepped "
          "(planet with two crowns: sun–planet, planet2–ring) or 3K (sun, planet, rings b and "
          "e, free carrier)", default="2K-H", choices=("2K-H", "2K-H-stepped", "3K")),
    Field("planets", "integer", "number of planets", symbol="n_w", minimum=1, maximum=24,
          example=3),
    Field("module", "number", "normal module of the sun, planet and ring", "mm", "m", minimum=0.05,
          maximum=100, example=3.0),
    Field("module2", "number", "normal module of the second planet crown and its ring "
          "(stepped planet or two-crown 3K planet)", "mm", "m2", default=None, gt=0,
          maximum=100, hint="default: module"),
    PRESSURE_ANGLE,
    Field("helix_angle", "number", "reference helix angle of all gears, 0 for spur gears",
          "deg", "β", default=0.0, minimum=0, lt=45),
    Field("face_width", "number", "working face width of the sun–planet and planet–ring "
          "meshes", "mm", "b_w", gt=0, example=30.0),
    Field("face_width2", "number", "working face width of the second crown's mesh", "mm",
          "b_w2", default=None, gt=0, hint="default: face_width"),
    Field("center_distance", "number", "working centre distance (radius of the planet axes); "
          "the shifts then follow by coaxiality", "mm", "a_w", default=None, gt=0, example=68.0),
    Field("working_angle", "number", "working pressure angle of the sun–planet mesh; a_w and "
          "the shifts then follow (instead of center_distance)", "deg", "α_tw", default=None,
          gt=5, lt=45),
    Field("spacing", "string", "planet spacing: equal, or the admissible uneven angles nearest "
          "to equal when equal spacing cannot be assembled", default="equal",
          choices=("equal", "uneven")),
    Field("allow_undercut", "boolean", "accept undercut sun or planet teeth (the check only "
          "warns)", default=False),
))

TEETH = Table("teeth", "numbers of teeth (analysis mode)", (
    Field("sun", "integer", "teeth of the sun", symbol="z_a", minimum=5, maximum=1000,
          example=18),
    Field("planet", "integer", "teeth of the planet (crown meshing the sun)", symbol="z_g",
          minimum=5, maximum=1000, example=27),
    Field("ring", "integer", "teeth of the ring; negative: ISO 21771 convention (then "
          "shift.ring too)", symbol="z_b", minimum=-3000, maximum=3000, example=72),
    Field("planet2", "integer", "teeth of the second planet crown (stepped planet; two-crown "
          "3K planet)", symbol="z_f", default=None, minimum=5, maximum=1000),
    Field("ring2", "integer", "teeth of the second (output) ring of a 3K train", symbol="z_e",
          default=None, minimum=-3000, maximum=3000),
), required=False)

SHIFT = Table("shift", "profile shift coefficients (normal)", (
    Field("sun", "number", "shift of the sun", symbol="x_a", default=None, minimum=-1.5,
          maximum=3.0, hint="default 0; with center_distance or working_angle: equal "
          "specific sliding of the sun–planet mesh"),
    Field("planet", "number", "shift of the planet", symbol="x_g", default=None, minimum=-1.5,
          maximum=3.0, hint="default 0; follows from a_w if center_distance or working_angle"),
    Field("ring", "number", "shift of the ring: GOST 19274-73 sign (positive away from the "
          "axis, thinner teeth) for teeth.ring > 0; ISO 21771 sign for teeth.ring < 0",
          symbol="x_b", default=None, minimum=-3.0, maximum=3.0),
    Field("planet2", "number", "shift of the second planet crown", symbol="x_f", default=None,
          minimum=-1.5, maximum=3.0, hint="default 0 (a single-crown 3K planet uses x_g)"),
    Field("ring2", "number", "shift of the second ring (sign as for the ring)", symbol="x_e",
          default=None, minimum=-3.0, maximum=3.0),
), required=False, implicit=True)

RING = Table("ring", "internal gears (rings)", (
    Field("tip_shortening", "number", "tip shortening coefficient of the rings: "
          "d_a = d − 2(h_a* − x − k2)m (GOST 19274-73 sign)", symbol="k2", default=0.0,
          minimum=-0.5, maximum=1.0, example=0.15,
          hint="0 (the default): the ISO 21771 nominal tip; a zero-shift ring usually needs "
               "about 0.1-0.2 against interference at the planet root"),
    Field("root_radius_coef", "number", "root fillet radius coefficient of the rings' basic "
          "rack", symbol="ρ_f*", default=None, minimum=0, maximum=1.0,
          hint="default: rack.root_radius_coef"),
), required=False, implicit=True)

CUTTER = Table("cutter", "shaper cutter of the rings (for their form circle, the cutting "
               "interference and the ISO 6336-3 Y_F, Y_S of their fillet)", (
    Field("teeth", "integer", "teeth of the shaper cutter", symbol="z_0", minimum=8,
          maximum=300, example=36),
    Field("shift", "number", "profile shift of the cutter", symbol="x_0", default=0.0,
          minimum=-1.0, maximum=1.5),
    Field("tip_radius_coef", "number", "tip radius coefficient of the cutter", symbol="ρ_a0*",
          default=None, minimum=0, maximum=1.0, hint="default: the ring's root radius coef."),
), required=False)

OPERATION = Table("operation", "members and the input", (
    Field("fixed", "string", "member held still; \"none\" for a differential with a "
          "controlled member", choices=MEMBER_CHOICES + ("none",), example="ring"),
    Field("input", "string", "driving member", choices=MEMBER_CHOICES, example="sun"),
    Field("output", "string", "driven member", choices=MEMBER_CHOICES, example="carrier"),
    Field("speed", "number", "speed of the input member", "min^-1", "n_in", default=None,
          minimum=-1e6, maximum=1e6, example=1450.0,
          hint="needed for speeds, velocities, frequencies and the strength"),
    Field("torque", "number", "torque on the input member", "N·m", "T_in", default=None,
          gt=0, maximum=1e9, example=40.0, hint="or give power"),
    Field("power", "number", "input power (instead of torque)", "kW", "P", default=None, gt=0,
          maximum=1e6),
    Field("control", "string", "member whose speed is imposed when fixed = \"none\" (e.g. a "
          "hydraulically braked carrier)", default=None, choices=MEMBER_CHOICES),
    Field("control_speed", "number", "imposed speed of the control member", "min^-1",
          "n_c", default=None, minimum=-1e6, maximum=1e6),
))

EFFICIENCY = Table("efficiency", "mesh losses and self-locking", (
    Field("model", "string", "mesh loss model: \"niemann\" (loss factor H_V and a mean "
          "coefficient of friction) or \"given\" mesh efficiencies", default="niemann",
          choices=("niemann", "given")),
    Field("friction", "number", "mean coefficient of friction of the teeth", symbol="μ_m",
          default=0.06, minimum=0.0, maximum=0.3),
    Field("external", "number", "efficiency of one external (sun–planet) mesh (model "
          "\"given\")", symbol="η_e", default=None, minimum=0.5, maximum=1.0),
    Field("internal", "number", "efficiency of one internal (planet–ring) mesh (model "
          "\"given\")", symbol="η_i", default=None, minimum=0.5, maximum=1.0),
    Field("self_locking", "string", "reverse-drive requirement: warn if self-locking, forbid it, "
          "or require it (e.g. a hoist)", default="warn", choices=("warn", "forbid", "require")),
    Field("near_self_locking", "number", "reverse efficiency below which the train is reported "
          "as nearly self-locking", symbol="η_rev,min", default=0.1, minimum=0.0, maximum=1.0),
), required=False, implicit=True)

LIMITS = Table("limits", "design limits", (
    Field("neighbour_gap", "number", "least gap between the tips of neighbouring planets, in "
          "modules", symbol="c_n/m", default=0.5, minimum=0.0, maximum=10.0),
    Field("tip_thickness", "number", "least normal tooth thickness at the tip, in modules "
          "(0.4 for case-hardened teeth)", symbol="s_a/m", default=0.25, minimum=0.0,
          maximum=1.0),
    Field("coaxiality", "number", "largest difference of the meshes' centre distances, in "
          "modules", symbol="Δa_w/m", default=0.001, minimum=1e-6, maximum=0.5),
    Field("specific_sliding", "number", "largest specific sliding at the roots",
          symbol="|ϑ|max", default=4.0, minimum=0.1, maximum=100.0),
), required=False, implicit=True)

def _scuffing_table() -> Table:
    """``[strength.scuffing]``: the oil of the scuffing rating of every mesh (ISO/TS 6336-21,
    with ``method = "ISO 6336:2019"``); the table of the spur calculator's ``[iso.scuffing]``
    without the mesh count, which the train gives (X_mp)."""
    from geardesign.spur.strength.iso6336.spec import SCUFFING

    return replace(SCUFFING, fields=tuple(f for f in SCUFFING.fields
                                          if getattr(f, "key", None) not in ("meshes",
                                                                             "driving")),
                   description="scuffing of every mesh by the integral temperature method "
                               "(ISO/TS 6336-21; needs method = \"ISO 6336:2019\")",
                   in_template=False)


STRENGTH = Table("strength", "strength to GOST 21354-87 or ISO 6336:2019 (with [material] and a torque)", (
    Field("life_hours", "number", "required life", "h", "L_h", gt=0, maximum=1e7,
          example=20000.0),
    Field("application_factor", "number", "application factor", symbol="K_A", default=1.0,
          minimum=1.0, maximum=3.0),
    Field("load_sharing", "number", "load-sharing factor of the planets: 1.0-1.1 with a "
          "floating member, 1.1-1.3 rigid (Kudryavtsev)", symbol="K_γ", default=1.1,
          minimum=1.0, maximum=2.0),
    Field("accuracy_grade", "integer", "accuracy grade (GOST 1643-81; the ISO 1328-1 class when iso.accuracy_grade is not "
          "given)", symbol="n_st",
          default=8, minimum=6, maximum=11),
    Field("tip_relief", "boolean", "teeth with tip relief (GOST 21354-87 only; ISO: "
          "iso.tip_relief)", default=False),
    Field("bearing_scheme", "integer", "arrangement for K_Hβ, GOST 21354-87 chart 1…7 (planets "
          "between carrier cheeks: 6 or 7; GOST only)", default=6, minimum=1, maximum=7,
          hint="; ".join(f"{k}: {v}" for k, v in T.SCHEMES.items())),
    Field("regime", "string", "typical load regime of GOST 21354-87: "
          + ", ".join(f"{k} {v}" for k, v in T.REGIME_NAMES.items()), default="0",
          choices=T.REGIMES),
    Field("peak_torque", "number", "largest short-time input torque (static checks)", "N·m",
          "T_max", default=None, gt=0, maximum=1e10),
    Field("ring_form_factor", "number", "tooth form factor Y_FS of the rings, given instead of "
          "the rack-limit approximation (GOST only; ISO: iso_factors.<mesh>.Y_F2, Y_S2)", symbol="Y_FS", default=None, gt=1.0, maximum=10.0),
    Field("method", "string", "strength method", default="GOST 21354-87", choices=tuple(METHODS)),
    Field("lubricant_viscosity", "number", "kinematic viscosity of the oil at 40 °C (ISO VG; "
          "ISO 6336 Z_L, Z_v and scuffing)", "mm^2/s", "ν40", default=None, minimum=2,
          maximum=3200, hint="220 (ISO VG 220) when not given"),
    _scuffing_table(),
), required=False)


def _optional(table: Table) -> Table:
    return replace(table, required=False)


def _hardness(table: Table, hb: float) -> Table:
    """``table`` with ``hb`` as the template's hardness: the sun harder than the planet and
    the planet harder than the ring, as soft pairs run in best (the template passes without
    warnings)."""
    return replace(table, fields=tuple(replace(f, example=hb) if getattr(f, "key", "") ==
                                       "hardness_HB" else f for f in table.fields))


MATERIAL = Table("material", "materials (for the strength calculation)", (
    _hardness(_material("sun"), 290.0), _hardness(_material("planet"), 260.0),
    _hardness(_material("ring"), 230.0),
    _optional(_material("planet2")), _optional(_material("ring2")),
), required=False, hint="planet2 and ring2 default to the planet's and the ring's material; "
                           "they are used only by trains that have those gears")

FREQUENCIES = Table("frequencies", "diagnostic frequencies (with operation.speed)", (
    Field("harmonics", "integer", "mesh harmonics listed", default=3, minimum=1, maximum=10),
    Field("sideband_orders", "integer", "sideband orders k, l of h·f_z ± k·f_d ± l·f_h",
          default=2, minimum=0, maximum=6),
    Field("speed_fluctuation", "number", "admissible fluctuation of the speeds (±)",
          symbol="δ", default=0.15, minimum=0.0, maximum=1.0),
    Field("amplitudes", "array", "measured amplitudes of the first mesh harmonics "
          "(discriminant S_fz)", "m/s^2", "S_nfz", default=None, minimum=0.0, maximum=1e4, max_items=20),
    Field("baseline", "array", "amplitudes of the same harmonics at the start of monitoring "
          "(relative growth P_fz)", "m/s^2", "S_nfz0", default=None, minimum=0.0, maximum=1e4,
          max_items=20),
), required=False, implicit=True)

SYNTHESIS = Table("synthesis", "synthesis mode: search tooth numbers (and shifts) for a ratio",
                  (
    Field("ratio", "number", "required ratio n_input/n_output (magnitude)", symbol="i",
          gt=1.0, maximum=100000.0, example=5.0),
    Field("tolerance", "number", "allowed deviation of the ratio", "%", default=2.0, gt=0,
          maximum=20.0),
    Field("sun_min", "integer", "fewest sun teeth", default=13, minimum=6, maximum=200),
    Field("planet_min", "integer", "fewest planet teeth", default=13, minimum=6, maximum=200),
    Field("ring_max", "integer", "most ring teeth", default=200, minimum=20, maximum=1000),
    Field("sum_deviation", "integer", "largest |z_b − z_a − 2z_g| (non-zero needs shifts)",
          default=2, minimum=0, maximum=6),
    Field("candidates", "integer", "candidates listed", default=5, minimum=1, maximum=20),
), required=False)

SCHEMA = SpecSchema(
    kind="planetary",
    description="planetary train 2K-H / 3K: kinematics (Willis), assembly, geometry of every "
                "mesh with shifts, efficiency and self-locking, strength (GOST 21354-87), "
                "diagnostic frequencies, synthesis",
    tables=(TRAIN, TEETH, SYNTHESIS, SHIFT, RACK, RING, CUTTER, OPERATION, EFFICIENCY, LIMITS,
            STRENGTH, MATERIAL, ISO, ISO_FACTORS, FREQUENCIES),
    title_example="2K-H reducer 18/27/72, m = 3, three planets",
    one_of=(("teeth", "synthesis"),),
)
