"""[DIN743-3]: steels (strength at the reference diameter d_B) and the technological size
factor K_1(d_eff) of the blank that was heat-treated."""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.shaft.din743 import tables

STEEL_TYPES = ("structural", "quenched_tempered", "case_hardening", "case_hardening_CrNiMo",
               "nitriding")
"""Steel types of [DIN743-3] that select the branch of K_1 (structural steel EN 10025,
quenched and tempered steel EN 10083, case-hardening steel EN 10084 (CrNiMo or other),
nitriding steel EN 10085)."""

# reference diameters by type when the steel is given by its strengths ([DIN743-3] tables
# A.1-A.5 as transcribed in [din743py]): (d_B of σ_B, d_B of σ_S)
REFERENCE_DIAMETER = {"structural": (100.0, 16.0), "quenched_tempered": (16.0, 16.0),
                      "case_hardening": (16.0, 16.0), "case_hardening_CrNiMo": (16.0, 16.0),
                      "nitriding": (100.0, 100.0)}


@dataclass(frozen=True)
class Steel:
    """A steel of [DIN743-3]: strengths [MPa] at the reference diameters [mm]."""
    name: str
    type: str
    sigma_B: float        # σ_B(d_B)
    sigma_S: float        # σ_S(d_B)
    d_B: float
    d_B_S: float


def steel(name: str) -> Steel | None:
    """The steel of the table by its EN name (case and blanks ignored), else None.

    >>> steel("c45").sigma_B
    700.0
    """
    rows = tables()["steel"]
    key = name.strip().replace(" ", "").lower()
    for k, row in rows.items():
        if k.lower() == key:
            return Steel(k, row["type"], row["sigma_B"], row["sigma_S"], row["d_B"],
                         row.get("d_B_S", row["d_B"]))
    return None


def gost_equivalent(grade: str) -> str | None:
    """The EN grade that stands for a GOST grade of the shaft-steel table, if any."""
    return tables()["gost_equivalent"].get(grade)


def K_1(steel_type: str, d_eff: float, strength: str) -> float:
    """Technological size factor K_1(d_eff) [-] ([DIN743-2] eqs. (10)-(14), for the steels
    of [DIN743-3]):

    .. math::
        K_1 = 1 \\;(d_{eff} \\le d_1),\\quad
        K_1 = 1 - a\\,\\lg\\frac{d_{eff}}{d_{ref}} \\;(d_1 < d_{eff} < d_2),\\quad
        K_1 = K_{min} \\;(d_2 \\le d_{eff})

    with (d_1, d_ref, a, d_2, K_min) by steel type and strength (``tables.toml`` [K_1]).

    Parameters
    ----------
    steel_type : one of :data:`STEEL_TYPES`; d_eff : diameter of the blank at heat treatment
        [mm]; strength : ``"B"`` (tensile) or ``"S"`` (yield).

    >>> round(K_1("quenched_tempered", 100.0, "B"), 4)
    0.7931
    """
    row = tables()["K_1"][f"{steel_type}_{strength}"]
    if d_eff <= row["d_1"]:
        return 1.0
    if d_eff < row["d_2"]:
        return 1.0 - row["a"] * math.log10(d_eff / row["d_ref"])
    return row["K_min"]


def endurance_limits(sigma_B_dB: float) -> tuple[float, float, float]:
    """Endurance limits of the smooth specimen at d_B [MPa] ([DIN743-3]):
    σ_zdW = 0.4·σ_B(d_B), σ_bW = 0.5·σ_B(d_B), τ_tW = 0.3·σ_B(d_B).

    >>> endurance_limits(1000.0)
    (400.0, 500.0, 300.0)
    """
    e = tables()["endurance"]
    return e["tension"] * sigma_B_dB, e["bending"] * sigma_B_dB, e["torsion"] * sigma_B_dB
