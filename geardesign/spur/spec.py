"""The ``kind = "spur"`` spec: keys, units, ranges and defaults (the single definition used
for validation, ``geardesign schema spur`` and ``geardesign template spur``)."""

from __future__ import annotations

from geardesign.core.spec import REQUIRED, Field, SpecSchema, Table

GEAR = Table("gear", "gear pair (external, spur or helical)", (
    Field("module", "number", "normal module", "mm", "m_n", gt=0, maximum=100, example=5.0,
          hint="GOST 9563 series preferred"),
    Field("z1", "integer", "number of teeth, pinion", symbol="z1", minimum=5, maximum=1000,
          example=32),
    Field("z2", "integer", "number of teeth, wheel", symbol="z2", minimum=5, maximum=1000,
          example=33),
    Field("pressure_angle", "number", "normal pressure angle of the basic rack", "deg", "α",
          default=20.0, gt=10, lt=35),
    Field("helix_angle", "number", "reference helix angle, 0 for spur gears", "deg", "β",
          default=0.0, minimum=0, lt=45),
    Field("face_width", "number", "working face width", "mm", "b_w", gt=0, example=15.0),
    Field("x1", "number", "profile shift coefficient, pinion", symbol="x1", default=None,
          minimum=-1.0, maximum=2.0,
          hint="default 0 without center_distance; with center_distance, x2 = x_Σ − x1"),
    Field("x2", "number", "profile shift coefficient, wheel", symbol="x2", default=None,
          minimum=-1.0, maximum=2.0,
          hint="default 0 without center_distance; with center_distance, x1 = x_Σ − x2"),
    Field("center_distance", "number", "working centre distance; x1 + x2 then follows from it",
          "mm", "a_w", default=None, gt=0),
    Field("shift_split", "string",
          "split of x1 + x2 when center_distance is given without x1 or x2", default=None,
          choices=("sliding", "equal"),
          hint='"sliding" (used when not given) equalises the specific sliding at both roots; '
               '"equal" gives x1 = x2'),
    Field("allow_undercut", "boolean",
          "accept an undercut tooth (deliberate, e.g. a small pinion): the check only warns",
          default=False),
))

RACK = Table("rack", "basic rack (GOST 13755-81)", (
    Field("addendum_coef", "number", "addendum coefficient", symbol="h_a*", default=1.0,
          gt=0, maximum=2.0),
    Field("clearance_coef", "number", "bottom clearance coefficient", symbol="c*", default=0.25,
          minimum=0, maximum=1.0),
    Field("root_radius_coef", "number", "root fillet radius coefficient of the rack",
          symbol="ρ_f*", default=0.38, minimum=0, maximum=1.0),
), required=False, implicit=True)

LOAD = Table("load", "operating data", (
    Field("speed1", "number", "pinion speed", "min^-1", "n1", gt=0, maximum=1e6, example=1000.0),
), required=False, hint="gives the pitch-line and sliding velocities")

SCHEMA = SpecSchema(
    kind="spur",
    description="external spur/helical gear pair, geometry to GOST 16532-70",
    tables=(GEAR, RACK, LOAD),
    title_example="Spur pair 32/33, m = 5",
)

__all__ = ["SCHEMA", "REQUIRED"]
