"""The ``kind = "ball_clutch"`` spec: keys, units, ranges and defaults (the single definition
used for validation, ``geardesign schema ball_clutch`` and ``geardesign template ball_clutch``)."""

from __future__ import annotations

from geardesign.ball_clutch.spring import END_TYPES
from geardesign.core.spec import Field, SpecSchema, Table
from geardesign.materials import spring_steel

OPERATION = Table("operation", "operating point of the drive", (
    Field("torque", "number", "rated torque to be transmitted", "N·m", "T", gt=0, maximum=1e6,
          example=15.0),
    Field("speed", "number", "clutch speed", "min^-1", "n", minimum=0, maximum=1e5,
          example=1000.0),
))

SAFETY = Table("safety", "torque-limiting (safety) part: balls held in sockets by springs", (
    Field("balls", "integer", "number of safety balls", symbol="z3", minimum=1, maximum=100,
          example=6),
    Field("ball_diameter", "number", "safety ball diameter", "mm", "d_b", gt=0, maximum=200,
          example=16.0),
    Field("ball_circle", "number", "diameter of the circle of ball centres", "mm", "d5", gt=0,
          maximum=5000, example=60.0),
    Field("socket_angle", "number", "angle of the contact force from the radial direction",
          "deg", "α2", gt=0, lt=90, example=45.0,
          hint="larger angles give a larger limit torque; near 90° the balls self-lock"),
    Field("socket_depth", "number", "radial lift of the ball needed to leave its socket",
          "mm", "h_s", gt=0, example=4.0),
    Field("socket_radius", "number", "radius of a spherical socket (omit for a conical "
          "socket or flat flank)", "mm", "R_s", default=None, gt=0),
    Field("friction", "number", "friction coefficient ball/socket (nominal)", symbol="f",
          default=0.1, minimum=0, maximum=0.5),
    Field("guide_friction", "number", "friction coefficient of the ball (plunger) in its "
          "guide bore (nominal)", symbol="f_g", default=0.1, minimum=0, maximum=0.5),
    Field("friction_spread", "number", "relative scatter of both friction coefficients for "
          "the min/max band", symbol="±Δf/f", default=0.5, minimum=0, lt=1,
          hint="0.5 gives f = 0.05...0.15 around 0.1"),
    Field("ball_density", "number", "density of the ball", "kg/m^3", "ρ", default=7850.0,
          minimum=1000.0, maximum=20000.0,
          hint="steel 7850; ceramic 3200; tungsten carbide 15600"),
    Field("extra_mass", "number", "mass moving radially with each ball (plunger, cup)", "kg",
          "m_p", default=0.0, minimum=0),
    Field("limit_torque", "number", "target limit torque at the operating speed (design "
          "mode: the spring preload follows)", "N·m", "T_lim", default=None, gt=0),
    Field("elastic_modulus", "number", "elastic modulus of ball and socket", "MPa", "E",
          default=206000.0, gt=0),
    Field("poisson", "number", "Poisson's ratio of ball and socket", symbol="ν", default=0.3,
          minimum=0, lt=0.5),
    Field("allowable_contact", "number", "allowable peak contact pressure ball/socket",
          "MPa", "p_0,adm", default=4200.0, gt=0,
          hint="4200 MPa: ISO 76 static limit for hardened ball contacts"),
))

SPRING = Table("spring", "spring pressing one safety ball", (
    Field("preload", "number", "spring deflection with the clutch engaged (set by the "
          "adjusting screw)", "mm", "y0", default=None, gt=0, example=5.0,
          hint="omit it and give safety.limit_torque to have it designed"),
    Field("rate", "number", "spring rate (omit it and give the wire and coil data)", "N/mm",
          "c", default=None, gt=0),
    Field("wire_diameter", "number", "wire diameter", "mm", "d", default=None, gt=0,
          example=2.5),
    Field("coil_diameter", "number", "mean coil diameter", "mm", "D", default=None, gt=0,
          example=16.0),
    Field("active_coils", "number", "number of active coils", symbol="n_a", default=None,
          minimum=1.0, maximum=1000.0, example=4.5),
    Field("ends", "string", "end type", default="closed_ground", choices=END_TYPES),
    Field("free_length", "number", "free length (gives the solid-length check)", "mm", "L0",
          default=None, gt=0, example=40.0),
    Field("material", "string", "spring material from the built-in table", default=None,
          choices=spring_steel.names(), example="oil_tempered"),
    Field("shear_modulus", "number", "shear modulus (overrides the material)", "MPa", "G",
          default=None, gt=0),
    Field("tensile_strength", "number", "tensile strength of the wire (overrides the "
          "material)", "MPa", "R_m", default=None, gt=0),
    Field("allowable_share", "number", "allowable shear stress as a share of R_m (overrides "
          "the material)", symbol="[τ]/R_m", default=None, minimum=0.1, maximum=1),
))

FREEWHEEL = Table("freewheel", "overrunning (freewheel) part (optional)", (
    Field("balls", "integer", "number of freewheel balls", symbol="z1", minimum=1, maximum=100,
          example=8),
    Field("ball_circle", "number", "diameter of the circle of freewheel ball centres", "mm",
          "d4", gt=0, example=50.0),
), required=False)

INERTIA = Table("inertia", "inertias for the dynamic release torque of [Malashchenko2025] eq. (15) "
                "(optional)", (
    Field("drive", "number", "drive side (central half-coupling and what turns with it)",
          "kg*m^2", "I1", minimum=0, example=0.02),
    Field("driven", "number", "driven side (sleeve and driven machine)", "kg*m^2", "I3",
          minimum=0, example=0.5),
), required=False)

SCHEMA = SpecSchema(
    kind="ball_clutch",
    description="ball overrunning-safety clutch: freewheel forces, limit torque, spring, contact",
    tables=(OPERATION, SAFETY, SPRING, FREEWHEEL, INERTIA),
    title_example="Ball overrunning-safety clutch, 6 safety balls 16 mm on 60 mm",
)
