"""The rolling bearings of a REXS model as the support tables of the drive's shafts."""

from __future__ import annotations

from geardesign.rexs.common import src
from geardesign.rexs.model import Component
from geardesign.rexs.reader import _Reader

BEARING_TYPES = {
    "radial_grooved_ball_bearing": "deep_groove_ball",
    "angular_contact_ball_bearing": "angular_contact_ball",
    "radial_self_aligning_ball_bearing": "self_aligning_ball",
    "self_aligning_ball_bearing": "self_aligning_ball",
    "radial_roller_bearing": "cylindrical_roller",
    "cylindrical_roller_bearing": "cylindrical_roller",
    "radial_tapered_roller_bearing": "tapered_roller",
    "radial_self_aligning_roller_bearing": "spherical_roller",
    "axial_grooved_ball_bearing": "thrust_ball",
    "axial_roller_bearing": "thrust_roller",
}
"""REXS ``bearing_type`` → the bearing calculator's ``type``."""


def _bearing_support(r: _Reader, br: Component) -> tuple[dict | None, str]:
    """The [bearing] table of one REXS bearing and its source, or (None, why not)."""
    from geardesign.bearing import catalogue

    if br.type == "concept_bearing":
        return None, "a concept bearing: no designation, no ratings"
    designation = r.text(br, "catalogue_designation") or r.text(br, "name")
    if designation:
        try:
            found = catalogue.read(designation).row
        except ValueError:
            found = None
        if found is not None:
            key = "catalogue_designation" if br.attributes.get("catalogue_designation") \
                else "name"
            return {"designation": (designation, src(br, key))}, ""
    kind = BEARING_TYPES.get(r.text(br, "bearing_type") or "")
    C, s_C = r.value(br, "dynamic_capacity", "N")
    C0, s_C0 = r.value(br, "static_capacity", "N")
    if kind and C and C0:
        note = f" (\"{designation}\" is not in the catalogue)" if designation else ""
        table = {"type": (kind, src(br, "bearing_type") + note), "C_r": (C, s_C),
                 "C_0r": (C0, s_C0)}
        d, s_d = r.value(br, "inner_diameter", "mm")
        D, s_D = r.value(br, "outer_diameter", "mm")
        if d and D:
            table.update(d=(d, s_d), D=(D, s_D))
        return table, ""
    return None, (f"\"{designation}\" is not in the catalogue and the model gives no ratings"
                  if designation else "no designation and no ratings")
