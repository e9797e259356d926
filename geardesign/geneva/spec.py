"""The ``kind = "geneva"`` spec: keys, units, ranges and defaults (the single definition used
for validation, ``geardesign schema geneva`` and ``geardesign template geneva``)."""

from __future__ import annotations

from geardesign.core.spec import Field, SpecSchema, Table

GENEVA = Table("geneva", "Geneva mechanism (crank with rollers, slotted cross)", (
    Field("type", "string", "external or internal Geneva", default="external",
          choices=("external", "internal")),
    Field("slots", "integer", "number of slots of the cross", symbol="z", minimum=3,
          maximum=36, example=4),
    Field("pins", "integer", "number of rollers (pins) on the crank, equally spaced",
          symbol="k", default=1, minimum=1, maximum=12),
    Field("center_distance", "number", "distance between crank and cross axes", "mm", "a",
          gt=0, maximum=1e5, example=200.0),
    Field("roller_diameter", "number", "diameter of the crank roller (pin)", "mm", "d_r",
          gt=0, example=20.0),
    Field("crank_speed", "number", "crank (distributing shaft) speed while indexing",
          "min^-1", "n_r", gt=0, maximum=1e5, example=30.0),
    Field("clearance", "number", "radial clearance at the slot end and the locking disc",
          "mm", "c", default=0.5, minimum=0),
    Field("shaft_diameter", "number", "diameter of the cross shaft (slot bottoms must clear it)",
          "mm", "d_sh", default=None, gt=0),
    Field("points", "integer", "number of crank angles at which the motion law is tabulated",
          default=181, minimum=11, maximum=2001,
          hint="odd numbers include the middle position φ = 0"),
))

LOAD = Table("load", "load on the cross shaft (optional): gives crank torque and slot force", (
    Field("inertia", "number", "moment of inertia driven by the cross, reduced to its shaft",
          "kg*m^2", "J_2", minimum=0, example=0.5),
    Field("friction_torque", "number", "friction moment on the cross shaft while it turns",
          "N·m", "M_f", default=0.0, minimum=0),
), required=False)

BARREL = Table("barrel", "indexed spindle block (barrel) of a multi-spindle automatic (optional)", (
    Field("stations", "integer", "index positions of the barrel (it turns 360°/stations per "
          "index)", symbol="n_pos", minimum=2, maximum=72, example=6),
    Field("inertia", "number", "barrel with cross and intermediate gears, without spindles",
          "kg*m^2", "J_b", gt=0, example=25.0),
    Field("friction_torque", "number", "friction moments resisting the barrel rotation",
          "N·m", "ΣM_tr", default=0.0, minimum=0),
    Field("efficiency", "number", "efficiency from the motor to the barrel", symbol="η_b",
          minimum=0.1, maximum=1, example=0.8),
), required=False, hint="the [RotaryDevices] spindle-block model; needs [geneva]")

SPINDLES = Table("spindles", "spindles carried by the barrel (optional, with [barrel])", (
    Field("count", "integer", "number of spindles", symbol="n_sh", minimum=1, maximum=72,
          example=6),
    Field("inertia", "number", "one spindle with its gears and the clamped workpiece",
          "kg*m^2", "J_sh", gt=0, example=0.03),
    Field("mass", "number", "mass of one spindle with connected parts", "kg", "m_sh",
          gt=0, example=25.0),
    Field("orbit_radius", "number", "distance between spindle and barrel axes", "mm", "R_b",
          gt=0, example=120.0),
    Field("central_gear_teeth", "integer", "teeth of the central gear", symbol="z_ts",
          minimum=5, maximum=1000, example=60),
    Field("spindle_gear_teeth", "integer", "teeth of the spindle gear", symbol="z_sh",
          minimum=5, maximum=1000, example=30),
    Field("working_speed", "number", "spindle speed with the barrel at rest", "min^-1",
          "n_sh.rab", minimum=0, maximum=1e5, example=1000.0),
    Field("direction", "string", "barrel rotation relative to the spindles' rotation",
          default="same", choices=("same", "opposite", "declutched"),
          hint='"declutched": spindle drive disengaged while indexing (u_p = 0)'),
    Field("efficiency", "number", "efficiency from the motor to the spindles' planetary "
          "motion", symbol="η_sh", minimum=0.1, maximum=1, example=0.85),
), required=False)

DRIVE = Table("drive", "motor and distributing shaft (optional, with [barrel])", (
    Field("motor_speed", "number", "motor speed", "min^-1", "n_d", gt=0, maximum=1e5,
          example=1450.0),
    Field("motor_inertia", "number", "motor rotor inertia", "kg*m^2", "J_d", default=0.0,
          minimum=0),
    Field("shaft_inertia", "number", "distributing shaft with crank and worm wheel",
          "kg*m^2", "J_r", default=0.0, minimum=0),
    Field("idle_torque", "number", "idle moment reduced to the distributing shaft", "N·m",
          "M_x", default=0.0, minimum=0),
    Field("rated_power", "number", "motor rating: the indexing peak must not exceed it", "kW",
          "P_rated", default=None, gt=0),
), required=False)

SCHEMA = SpecSchema(
    kind="geneva",
    description="Geneva indexing mechanism: motion law, geometry, spindle-block drive power",
    tables=(GENEVA, LOAD, BARREL, SPINDLES, DRIVE),
    title_example="4-slot Geneva, a = 200 mm, spindle block of a 6-spindle automatic",
)
