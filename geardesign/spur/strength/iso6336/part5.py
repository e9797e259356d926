"""ISO 6336-5:2016 — strength and quality of materials: the endurance limits σ_Hlim and
σ_Flim from the surface hardness, per material type and quality grade ML, MQ, ME, as the
lines σ = A·x + B of the standard (``tables.MATERIAL_LINES``).

A spec names the type, quality and hardness, or gives σ_Hlim and σ_Flim itself.
"""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.spur.strength.iso6336 import tables as T

HB_PER_HV = 0.95
"""Brinell over Vickers hardness of steel in the range of through-hardened gears
(ISO 18265 conversion table: 240 HBW ≈ 252 HV, 300 HBW ≈ 316 HV)."""


@dataclass(frozen=True)
class Limits:
    sigma_Hlim: float
    sigma_Flim: float
    hardness: float        # in the scale of the line (HBW or HV), within its range
    scale: str
    clamped: bool          # the given hardness lay outside the line's range


def hardness_on_scale(scale: str, HB: float | None, HV: float | None) -> float:
    """The hardness in the scale of a material line (HBW or HV) from what is known
    ([ISO6336-5]: the figure of each material line names its scale)."""
    if scale == "HV":
        return HV if HV is not None else HB / HB_PER_HV
    return HB if HB is not None else HV * HB_PER_HV


def limits(material: str, quality: str, hardness: float) -> Limits:
    """σ_Hlim and σ_Flim [MPa] of a material type and quality grade at a hardness in the
    line's own scale (HBW for St, cast iron and cast steel, HV otherwise); a hardness
    outside the line's range is taken at the nearer end and flagged.
    [ISO6336-5] Table 2 (lines of Figures 4–16).

    >>> limits("Eh", "MQ", 700.0).sigma_Hlim
    1500.0
    """
    line = T.MATERIAL_LINES[material]
    lo, hi = line["range"]
    x = min(max(hardness, lo), hi)
    aH, bH = line["H"][quality]
    aF, bF = line["F"][quality]
    return Limits(aH * x + bH, aF * x + bF, x, line["scale"], not lo <= hardness <= hi)


#: The ISO material type that a GOST 21354-87 heat treatment corresponds to, for a spec
#: that names only the treatment (alloy steels for quenched and tempered gears).
FROM_TREATMENT = {"normalized": "St", "improved": "V_alloy", "through_hardened": "V_alloy",
                  "induction": "IF", "carburized": "Eh", "nitrided": "NV"}


def type_from_treatment(treatment: str, label: str) -> str:
    """Material type of ISO 6336-5 for a library material: the type its grade's row names for
    the treatment (``iso6336_5`` in ``materials/gear_steel.toml``: 42CrMo4 improved V_alloy,
    31CrMo12 nitrided NT, 40KhL cast V_cast_alloy, ...); for a GOST row, which names none, the
    nitriding steel 38Kh2MYuA is NT, the carbon steel 45 through-hardened is V, otherwise
    :data:`FROM_TREATMENT`.  [ISO6336-5] (the material types).

    >>> type_from_treatment("improved", "40KhL, quenched and tempered (improved), 220 HB")
    'V_cast_alloy'
    """
    from geardesign.materials.gear_steel import iso_type

    grade = label.split(",")[0].strip()
    typ = iso_type(grade, treatment)
    if typ is not None:
        return typ
    if treatment == "nitrided" and grade == "38Kh2MYuA":
        return "NT"
    if treatment in ("improved", "through_hardened") and grade == "45":
        return "V"
    return FROM_TREATMENT[treatment]
