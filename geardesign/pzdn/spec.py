"""The ``kind = "pzdn"`` spec: keys, units, ranges and defaults (the single definition used
for validation, ``geardesign schema pzdn`` and ``geardesign template pzdn``).

The tables present select the modes computed (several may be combined in one spec):

* spring mode: ``[[spring]]`` (one or more torsion springs) and, for the motor wind-up of
  method A, ``[motor]``;
* coupling_gear mode: ``[coupling_gear]`` with ``[coupling_gear.pinion]``,
  ``[coupling_gear.wheel]`` and optional ``[coupling_gear.factors]``;
* startup mode: ``[startup]`` (a link stiffness may name a ``[[spring]]``);
* regression mode: ``[regression]``.
"""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table, TableList
from geardesign.materials import spring_steel
from geardesign.pzdn.spring import CURVATURE_MODELS, LEG_MODELS
from geardesign.spur.strength import METHODS

STIFFNESS = "N·m/rad"
INERTIA = "kg*m^2"

MOTOR = Table("motor", "drive motor, for the wind-up angle of the spring during the motor "
              "start (method A)", (
    Field("speed", "number", "nominal motor speed", "min^-1", "n", gt=0, maximum=1e5,
          example=950.0),
    Field("power", "number", "nominal motor power", "kW", "P", default=None, gt=0,
          maximum=1e5, example=2.2, hint="gives the nominal torque P/ω when "
          "nominal_torque is not given"),
    Field("nominal_torque", "number", "nominal motor torque (default P/ω)", "N·m", "T_c",
          default=None, gt=0, maximum=1e6),
    Field("breakaway_time", "number", "break-away time of the driving mass (rotor with the "
          "coupling)", "s", "t1", default=1.5e-3, gt=0, maximum=10.0),
    Field("windup_factor", "number", "wind-up time of the spring over t1 (t = factor·t1)",
          symbol="t/t1", default=10.0, minimum=1.0, maximum=1000.0),
), required=False)

SPRING = Table("spring", "cylindrical torsion spring of the coupling", (
    Field("name", "string", "name of the spring (used by startup.C12_spring/C13_spring)",
          default=None, example="knitting"),
    Field("torque", "number", "design (working) torque carried by the spring", "N·m", "T",
          gt=0, maximum=1e6, example=30.0),
    Field("wire_diameter", "number", "wire diameter", "mm", "d", default=None, gt=0,
          maximum=100.0, example=6.5,
          hint="leave out to take d_min rounded up to the GOST 9389-75 series"),
    Field("index", "number", "design spring index c = D/d, used for the curvature factor",
          symbol="c", default=None, gt=1.0, maximum=50.0, example=8.0,
          hint="the thesis recommends 4…12; default D/d"),
    Field("coil_diameter", "number", "coil diameter (mean, or outer: see diameter_basis)",
          "mm", "D", default=None, gt=0, maximum=5000.0, example=60.0,
          hint="default c·d"),
    Field("diameter_basis", "string", "what coil_diameter measures", default="mean",
          choices=("mean", "outer"),
          hint='"mean" reproduces the thesis\' numbers (its eq. (11) says "outer")'),
    Field("coils", "number", "number of working coils", symbol="i", default=None,
          minimum=0.5, maximum=1000.0, example=4.0,
          hint="leave out to compute it from the design angle (method A) and round up"),
    Field("pitch", "number", "coil pitch (p = d: close-wound)", "mm", "p", default=None, gt=0,
          maximum=1000.0, example=8.0, hint="default d + 2 mm"),
    Field("material", "string", "spring material from the built-in table (gives [σ] and E)",
          default=None, choices=spring_steel.names()),
    Field("E", "number", "Young's modulus of the wire", "MPa", "E", default=None, gt=0,
          maximum=1e6, example=215000.0,
          hint="default: the material's, else 2.15·10⁵ MPa (the thesis' value)"),
    Field("tau_allow", "number", "allowable torsional stress of the wire", "MPa", "[τ]",
          default=None, gt=0, maximum=5000.0),
    Field("sigma_over_tau", "number", "[σ]/[τ] (the thesis: 1.25…1.5)", symbol="[σ]/[τ]",
          default=None, gt=0.5, maximum=3.0, hint="default 1.5 with tau_allow"),
    Field("sigma_allow", "number", "allowable bending stress of the coils", "MPa", "[σ]",
          default=None, gt=0, maximum=5000.0, example=1500.0,
          hint="or give tau_allow (× sigma_over_tau) or a material"),
    Field("curvature_factor", "string", "curvature (stress correction) factor",
          default="thesis", choices=CURVATURE_MODELS,
          hint='"thesis" (4c − 1)/(4c − 4) of the thesis, "wahl" Shigley K_i, "en13906" q'),
    Field("leg_arm", "number", "arm of the loaded leg: distance from the spring axis to the "
          "finger in the slot", "mm", "l", default=None, gt=0, maximum=10000.0,
          hint="moving the finger sets the stiffness; leave out to neglect the legs "
               "(method B)"),
    Field("leg2_arm", "number", "arm of the second leg if it is free (not clamped)", "mm",
          "l2", default=None, gt=0, maximum=10000.0),
    Field("leg_model", "string", "bending model of the legs", default="thesis",
          choices=LEG_MODELS,
          hint='"thesis" F·l²/(2EJ) of the thesis, "shigley" l/3, EN 13906-3 radial or '
               'tangential leg'),
    Field("design_angle", "number", "design wind-up angle", "deg", "φ", default=None, gt=0,
          maximum=3600.0, hint="default: the motor wind-up + leg bending rounded up to 5°"),
    Field("stop_angle", "number", "largest wind-up the coupling allows (its stop): sets the "
          "torque limit C·φ_stop", "deg", "φ_stop", default=None, gt=0, maximum=3600.0),
    Field("slot_arms", "array", "ends of the slot of the finger: least and largest arm",
          "mm", "l_min, l_max", default=None, gt=0, maximum=10000.0, min_items=2,
          max_items=2),
    Field("target_stiffness", "number", "stiffness wanted at the finger: the arm that gives it "
          "follows", STIFFNESS, "C_target", default=None, gt=0, maximum=1e9),
    Field("arbor_diameter", "number", "diameter of the arbor (mandrel) inside the spring",
          "mm", "d_arbor", default=None, gt=0, maximum=5000.0),
    Field("ends_fixed_axially", "boolean", "the body is held at its height between the "
          "half-couplings (the coils can touch when wound up)", default=True),
))

SPRINGS = TableList("spring", "torsion springs of the coupling", SPRING, required=False,
                    examples=({"name": "knitting", "torque": 30.0, "wire_diameter": 6.5,
                               "index": 9.0, "coil_diameter": 58.5, "coils": 4.0,
                               "pitch": 8.0, "E": 215000.0, "sigma_allow": 1500.0},
                              {"name": "take_down", "torque": 7.5, "wire_diameter": 4.5,
                               "index": 11.0, "coil_diameter": 49.5, "coils": 3.0,
                               "pitch": 6.0, "E": 215000.0, "sigma_allow": 1500.0}))


def _gear_material(who: str) -> Table:
    n = 1 if who == "pinion" else 2
    return Table(who, f"material of the {who} (as in the spur calculator)", (
        Field("grade", "string", "steel grade of the spur library (45, 40Kh, ...)",
              symbol=f"grade{n}", default=None, example="45"),
        Field("treatment", "string", "heat treatment", symbol=f"treatment{n}",
              example="improved",
              choices=("normalized", "improved", "through_hardened", "induction", "carburized",
                       "nitrided")),
        Field("hardness_HB", "number", "surface hardness", "HB", f"HB{n}", default=None,
              minimum=100, maximum=700, example=250.0 if who == "pinion" else 230.0),
        Field("hardness_HRC", "number", "surface hardness (hardened steels)", "HRC", f"HRC{n}",
              default=None, minimum=20, maximum=70),
        Field("blank", "string", "blank", symbol=f"blank{n}", default="forging",
              choices=("forging", "rolled", "casting")),
        Field("sigma_T", "number", "yield strength of the blank", "MPa", f"σ_T{n}",
              default=None, gt=0, maximum=5000, example=540.0 if who == "pinion" else 440.0),
        Field("sigma_Hlim", "number", "contact endurance limit", "MPa", f"σ_Hlim{n}",
              default=None, gt=0, maximum=5000),
        Field("sigma_Flim", "number", "bending endurance limit", "MPa", f"σ_Flim{n}",
              default=None, gt=0, maximum=3000),
        Field("S_H", "number", "required contact safety factor", symbol=f"S_Hmin{n}",
              default=None, minimum=1.0, maximum=5.0),
        Field("S_F", "number", "required bending safety factor", symbol=f"S_Fmin{n}",
              default=None, minimum=1.0, maximum=5.0),
    ))


_FACTORS = (("K_Hv", "dynamic factor, contact"), ("K_Hbeta", "face load factor, contact"),
            ("K_Fv", "dynamic factor, bending"), ("K_Fbeta", "face load factor, bending"),
            ("Y_FS1", "tooth form factor, pinion"), ("Y_FS2", "tooth form factor, wheel"))

COUPLING_GEAR = Table("coupling_gear", "open spur gear of the coupling (rated by the spur "
                      "calculator)", (
    Field("z1", "integer", "number of teeth, pinion", symbol="z1", minimum=5, maximum=1000,
          example=20),
    Field("z2", "integer", "number of teeth, wheel", symbol="z2", minimum=5, maximum=1000,
          example=42),
    Field("module", "number", "module", "mm", "m", default=None, minimum=0.05, maximum=100,
          example=2.5, hint="leave out to use the bending estimate rounded up to GOST 9563"),
    Field("face_width", "number", "working face width", "mm", "b_w", default=None, gt=0,
          maximum=5000, example=20.0, hint="default ψ_bd·m·z1"),
    Field("psi_bd", "number", "face width ratio b/d1 (module estimate; default face width)",
          symbol="ψ_bd", default=0.4, minimum=0.05, maximum=2.0),
    Field("x1", "number", "profile shift, pinion", symbol="x1", default=0.0, minimum=-1.0,
          maximum=2.0, example=0.3),
    Field("x2", "number", "profile shift, wheel", symbol="x2", default=0.0, minimum=-1.0,
          maximum=2.0, example=-0.3),
    Field("planets", "integer", "number of planet meshes sharing the torque", symbol="n_w",
          default=2, minimum=1, maximum=20),
    Field("torque", "number", "working torque of the coupling", "N·m", "T", gt=0,
          maximum=1e7, example=22.1),
    Field("torque_on", "string", "the gear that carries `torque` (the other follows from u)",
          default="wheel", choices=("wheel", "pinion")),
    Field("peak_torque", "number", "largest short-time torque (motor start), on the same gear",
          "N·m", "T_max", default=None, gt=0, maximum=1e8, example=48.6,
          hint="for the static checks and the module estimate"),
    Field("speed", "number", "pinion speed", "min^-1", "n1", gt=0, maximum=1e6,
          example=950.0),
    Field("life_hours", "number", "required life", "h", "L_h", default=10000.0, gt=0,
          maximum=1e7),
    Field("accuracy_grade", "integer", "accuracy grade (GOST 1643-81)", symbol="n_st",
          default=9, minimum=6, maximum=11, example=8),
    Field("bearing_scheme", "integer", "arrangement of the gears on their shafts, GOST "
          "21354-87 chart 1…7 (1: overhung gear on ball bearings)", default=1, minimum=1,
          maximum=7),
    Field("method", "string", "strength method of the spur calculator (the given [factors] "
          "are GOST 21354-87 factors)", default="GOST 21354-87", choices=tuple(METHODS)),
    _gear_material("pinion"),
    _gear_material("wheel"),
    Table("factors", "load factors given instead of computed (e.g. the thesis' values)",
          tuple(Field(k, "number", n, symbol=k.replace("beta", "β"), default=None,
                      minimum=1.0 if k.startswith("K") else 1.5, maximum=10.0 if k.startswith("K")
                      else 20.0) for k, n in _FACTORS), required=False),
), required=False)

STARTUP = Table("startup", "three-mass start-up model, driving mass in the middle "
                "(all values reduced to the motor shaft)", (
    Field("T1", "number", "motor starting torque", "N·m", "T1", gt=0, maximum=1e7,
          example=44.0),
    Field("T2", "number", "resisting moment of mass 2 (take-down mechanism)", "N·m", "T2",
          gt=0, maximum=1e7, example=4.4),
    Field("T3", "number", "resisting moment of mass 3 (knitting mechanism)", "N·m", "T3",
          gt=0, maximum=1e7, example=17.7),
    Field("J1", "number", "moment of inertia of the driving mass", INERTIA, "J1", gt=0,
          maximum=1e6, example=0.038),
    Field("J2", "number", "moment of inertia of mass 2", INERTIA, "J2", gt=0, maximum=1e6,
          example=0.026),
    Field("J3", "number", "moment of inertia of mass 3", INERTIA, "J3", gt=0, maximum=1e6,
          example=0.021),
    Field("C12", "number", "stiffness of link 1-2 (the PZDN spring of line 2)", STIFFNESS,
          "C12", default=None, gt=0, maximum=1e9, example=8.33,
          hint="or C12_spring"),
    Field("C13", "number", "stiffness of link 1-3 (the PZDN spring of line 3)", STIFFNESS,
          "C13", default=None, gt=0, maximum=1e9, example=25.0, hint="or C13_spring"),
    Field("C12_spring", "string", "name of the [[spring]] that gives C12", default=None),
    Field("C13_spring", "string", "name of the [[spring]] that gives C13", default=None),
    Field("C12_drive", "number", "stiffness of the rest of line 2 in series with its spring "
          "(the drive without the PZDN)", STIFFNESS, "C12_drive", default=None, gt=0,
          maximum=1e9, example=1940.0, hint="give both drive stiffnesses for the comparison "
          "with and without the PZDN"),
    Field("C13_drive", "number", "stiffness of the rest of line 3 in series with its spring",
          STIFFNESS, "C13_drive", default=None, gt=0, maximum=1e9, example=1940.0),
    Field("method", "string", "solution", default="both",
          choices=("closed_form", "ode", "both"),
          hint='"closed_form": the corrected thesis solution (step torque, no damping); '
               '"ode": numerical integration (needs scipy)'),
    Field("t_end", "number", "duration of the start-up computed", "s", "t_end", default=None,
          gt=0, maximum=1000.0, hint="default: time for the mean speed to reach "
                                     "motor_speed"),
    Field("motor_speed", "number", "nominal motor speed (reduced)", "min^-1", "n",
          default=None, gt=0, maximum=1e5, example=950.0),
    Field("motor_model", "string", "motor torque during the start", default="constant",
          choices=("constant", "kloss", "curve"),
          hint='"constant": T1; "kloss": Kloss characteristic; "curve": curve_speed/'
               'curve_torque'),
    Field("rise_time", "number", "rise time of the motor torque (linear ramp; 0: a step)",
          "s", "t_r", default=0.0, minimum=0, maximum=100.0),
    Field("kloss_max_torque", "number", "breakdown torque of the motor (Kloss)", "N·m",
          "T_k", default=None, gt=0, maximum=1e7),
    Field("kloss_critical_slip", "number", "critical slip (Kloss)", symbol="s_k",
          default=None, minimum=0.01, maximum=0.9),
    Field("synchronous_speed", "number", "synchronous speed (Kloss)", "min^-1", "n0",
          default=None, gt=0, maximum=1e5),
    Field("curve_speed", "array", "motor characteristic: speeds", "min^-1", "n_i",
          default=None, minimum=0, maximum=1e5, min_items=2, max_items=200),
    Field("curve_torque", "array", "motor characteristic: torques at curve_speed", "N·m",
          "T_i", default=None, minimum=-1e7, maximum=1e7, min_items=2, max_items=200),
    Field("damping_ratio", "number", "damping ratio of each link (viscous, ODE only)",
          symbol="ζ", default=0.0, minimum=0, maximum=2.0),
    Field("stick", "boolean", "a mass that comes to rest sticks (reactive resisting moment; "
          "ODE only)", default=True),
    Field("history_points", "integer", "points of the time histories in the output (0: none)",
          default=101, minimum=0, maximum=100000),
    Field("sweep", "array", "factors on both link stiffnesses for a stiffness sweep",
          symbol="λ", default=None, minimum=1e-3, maximum=1e3, min_items=1, max_items=50,
          example=[0.5, 1.0, 2.0]),
    Field("plot", "string", "write the start-up transient to this .png or .svg file "
          "(relative to the spec file; needs matplotlib)", default=None),
), required=False)

REGRESSION = Table("regression", "regression of the KO-2 drive (thesis §2.3): maximum "
                   "moments vs. link stiffness", (
    Field("pzdn_stiffness", "number", "stiffness of the PZDN coupling", STIFFNESS, "C_M",
          default=None, gt=0, maximum=1e9, example=25.0),
    Field("drive_stiffness", "number", "stiffness of the drive in series with it (V-belt "
          "drive); alone it is the drive without the PZDN", STIFFNESS, "C_belt",
          default=None, gt=0, maximum=1e9, example=1940.0),
    Field("C12", "number", "link stiffness given directly (instead of the two above)",
          STIFFNESS, "C12", default=None, gt=0, maximum=1e9),
    Field("T_ref_12", "number", "reference moment of k12", "N·m", "T_ref12", default=26.5,
          gt=0, maximum=1e7),
    Field("T_ref_23", "number", "reference moment of k23", "N·m", "T_ref23", default=17.7,
          gt=0, maximum=1e7),
    Field("sweep", "array", "link stiffnesses for a table of the regression", STIFFNESS,
          "C_i", default=None, gt=0, maximum=1e9, min_items=1, max_items=100),
), required=False, in_template=False,
   hint="fitted to the KO-2 drive only (centre C0 = 1940 N·m/rad); for another drive "
        "use [startup]")

SCHEMA = SpecSchema(
    kind="pzdn",
    description="PZDN (torsion-spring device reducing start-up dynamic loads): spring sizing, "
                "coupling gear, three-mass start-up, KO-2 regression",
    tables=(MOTOR, SPRINGS, COUPLING_GEAR, STARTUP, REGRESSION),
    title_example="Knitting-machine drive with a two-spring PZDN (KO-2 layout, "
                  "starting torque 2·T_nom): springs, coupling gear and start-up, all "
                  "checks passing",
)
