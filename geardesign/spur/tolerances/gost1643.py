"""GOST 1643-81 "Cylindrical gears. Tolerances": the backlash norms of a gear pair.

* accuracy degrees 3…12 (degrees 1 and 2 are reserved by the standard for the future);
* types of mating H, E, D, C, B, A with the guaranteed (least) normal backlash j_n min,
  printed by the standard as the standard tolerances IT7 (E) … IT11 (A) of the centre
  distance (H: j_n min = 0), and the class of centre-distance deviation II…VI paired with
  each type; the limit deviation ±f_a of a class is half of IT6…IT11 of the centre
  distance ([GOST1643]; the IT values of [ISO286], ``it_grades.toml``);
* the additional shift of the basic rack E_Hs (least, toward the gear axis) and its tolerance
  T_H, and the derived allowances of the tooth thickness, E_cs = 2·E_Hs·tan α and
  T_c = 2·T_H·tan α, and of the base tangent length, E_W = E_c·cos α ([GOST1643];
  [ISO21771] for the thickness–span relation).

The tables of E_Hs (by accuracy degree, type of mating and reference diameter) and T_H (by
radial runout tolerance F_r and type of backlash tolerance) are not built in: the spec gives
T_H, and E_Hs either from the standard's table or, by default, from the backlash balance
of :func:`geardesign.spur.tolerances.backlash.upper_allowances`.
"""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

STANDARD = "GOST 1643-81"
GRADES = tuple(range(3, 13))
MATINGS = ("H", "E", "D", "C", "B", "A")
CLASSES = ("I", "II", "III", "IV", "V", "VI")


class ToleranceError(ValueError):
    """A value outside the standard's tables; ``key`` names the spec key to change."""

    def __init__(self, key: str, value, message: str):
        super().__init__(message)
        self.key = key
        self.value = value


@lru_cache(maxsize=None)
def _data() -> dict:
    from geardesign.core.data import toml_table

    return toml_table(Path(__file__).with_name("it_grades.toml"))


def it_value(grade: int, size: float) -> float:
    """Standard tolerance IT``grade`` [µm] of the GOST 1643-81 interval holding ``size``
    [mm] (``it_grades.toml``; [ISO286] table 1).

    >>> it_value(10, 160.0)
    160
    """
    d = _data()
    for i, upper in enumerate(d["upper"]):
        if size <= upper:
            return d["IT"][str(grade)][i]
    raise ToleranceError("gear.center_distance", size,
                         f"beyond the {d['upper'][-1]} mm of the backlash tables of GOST 1643-81: "
                         f"give accuracy.jn_min and accuracy.fa")


def check_grade(grade: int) -> int:
    """The accuracy degree, or :class:`ToleranceError` for a degree the standard has not."""
    if grade not in GRADES:
        raise ToleranceError("accuracy.grade", grade,
                             f"unknown accuracy grade of GOST 1643-81: give 3…12 (1 and 2 are "
                             f"reserved by the standard)")
    return grade


def mating(kind: str) -> dict:
    """The row of a type of mating: ``jn_grade`` (0 for H), ``fa_class``, ``tolerance``."""
    rows = _data()["mating"]
    if kind not in rows:
        raise ToleranceError("accuracy.mating", kind,
                             "unknown type of mating: give one of " + ", ".join(MATINGS))
    return rows[kind]


def jn_min(kind: str, a_w: float) -> float:
    """Guaranteed normal backlash j_n min [µm] of a type of mating at the centre distance
    a_w [mm]: IT7…IT11 of a_w for E…A, 0 for H ([GOST1643] guaranteed backlash table).

    >>> jn_min("B", 160.0), jn_min("H", 160.0)
    (160, 0)
    """
    g = mating(kind)["jn_grade"]
    return 0 if g == 0 else it_value(g, a_w)


def fa(cls: str, a_w: float) -> float:
    """Limit deviation ±f_a [µm] of the centre distance for a class I…VI of centre-distance
    deviation: half of IT6…IT11 of a_w ([GOST1643] f_a table, printed rounded).

    >>> fa("V", 160.0)
    80.0
    """
    grades = _data()["fa_class"]
    if cls not in grades:
        raise ToleranceError("accuracy.center_distance_class", cls,
                             "unknown class of centre-distance deviation: give one of "
                             + ", ".join(CLASSES))
    return 0.5 * it_value(grades[cls], a_w)


def thickness_from_rack_shift(E_H: float, alpha_n: float) -> float:
    """Tooth thickness change [µm] from an additional shift E_H [µm] of the basic rack
    toward the axis: ΔS = −2·E_H·tan α ([GOST1643], E_cs = 2 E_Hs tan α)."""
    return -2.0 * E_H * math.tan(alpha_n)


def rack_shift_from_thickness(E_s: float, alpha_n: float) -> float:
    """The inverse of :func:`thickness_from_rack_shift`: E_H = −ΔS / (2 tan α) [µm]."""
    return -E_s / (2.0 * math.tan(alpha_n))


def designation(grade: int, kind: str) -> str:
    """Drawing designation of the accuracy, e.g. ``8-B GOST 1643-81`` (one degree for all
    norms, type of backlash tolerance as for the type of mating)."""
    return f"{grade}-{kind} {STANDARD}"
