"""ISO 1328-1:2013 "Cylindrical gears — ISO system of flank tolerance classification —
Part 1: Definitions and allowable values of deviations relevant to flanks of gear teeth".

Tolerance classes A = 1 (finest) … 11; each tolerance is a formula in the reference diameter
d, the normal module m_n and the face width b (mm), multiplied by the step factor
√2^(A − 5) between neighbouring classes ([ISO1328-1] 5.3):

* single pitch          f_pT  = (0.001 d + 0.4 m_n + 5)·√2^(A−5)
* cumulative pitch      F_pT  = (0.002 d + 0.55 √d + 0.7 m_n + 12)·√2^(A−5)
* profile slope         f_HαT = (0.4 m_n + 0.001 d + 4)·√2^(A−5)
* profile form          f_fαT = (0.55 m_n + 5)·√2^(A−5)
* total profile         F_αT  = √(f_HαT² + f_fαT²)
* helix slope and form  f_HβT = f_fβT = (0.05 √d + 0.35 √b + 4)·√2^(A−5)
* total helix           F_βT  = √(f_HβT² + f_fβT²)
* runout                F_rT  = 0.9·F_pT ([ISO1328-1] runout annex)

Rounding ([ISO1328-1] 5.2): above 10 µm to the nearest micrometre, from 5 to 10 µm to the
nearest 0.5 µm, below 5 µm to the nearest 0.1 µm; each tolerance is rounded from its own
unrounded value.  Range of validity: 5 ≤ z ≤ 1000, 5 ≤ d ≤ 15 000 mm,
0.5 ≤ m_n ≤ 70 mm, 4 ≤ b ≤ 1 200 mm, β ≤ 45°.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from geardesign.spur.tolerances.gost1643 import ToleranceError

STANDARD = "ISO 1328-1:2013"
GRADES = tuple(range(1, 12))


def check_grade(grade: int) -> int:
    """The flank tolerance class, or :class:`ToleranceError` for a class the standard has not."""
    if grade not in GRADES:
        raise ToleranceError("accuracy.grade", grade,
                             "unknown flank tolerance class of ISO 1328-1:2013: give 1…11")
    return grade


def round_tolerance(value: float) -> float:
    """[ISO1328-1] 5.2 rounding: > 10 µm to 1 µm, 5…10 µm to 0.5 µm, < 5 µm to 0.1 µm.

    >>> round_tolerance(12.49), round_tolerance(7.3), round_tolerance(3.14)
    (12.0, 7.5, 3.1)
    """
    if value > 10.0:
        return float(math.floor(value + 0.5))
    if value >= 5.0:
        return math.floor(2.0 * value + 0.5) / 2.0
    return math.floor(10.0 * value + 0.5) / 10.0


@dataclass(frozen=True)
class FlankTolerances:
    """Flank tolerances of one gear [µm], rounded as the standard prescribes."""

    grade: int
    f_pT: float
    F_pT: float
    f_HalphaT: float
    f_falphaT: float
    F_alphaT: float
    f_HbetaT: float
    f_fbetaT: float
    F_betaT: float
    F_rT: float


def flank_tolerances(grade: int, d: float, m_n: float, b: float) -> FlankTolerances:
    """The tolerances of class ``grade`` for reference diameter ``d``, normal module ``m_n``
    and face width ``b`` (mm); formulas in the module docstring ([ISO1328-1] 5.3).

    >>> flank_tolerances(5, 100.0, 4.0, 40.0).f_pT
    6.5
    """
    check_grade(grade)
    for key, value, lo, hi in (("reference diameter d", d, 5.0, 15000.0),
                               ("normal module", m_n, 0.5, 70.0),
                               ("face width", b, 4.0, 1200.0)):
        if not lo <= value <= hi:
            raise ToleranceError("accuracy.grade", grade,
                                 f"ISO 1328-1:2013 applies to a {key} of {lo:g}…{hi:g} mm, "
                                 f"not {value:.6g} mm")
    step = math.sqrt(2.0) ** (grade - 5)
    f_pT = (0.001 * d + 0.4 * m_n + 5.0) * step
    F_pT = (0.002 * d + 0.55 * math.sqrt(d) + 0.7 * m_n + 12.0) * step
    f_Ha = (0.4 * m_n + 0.001 * d + 4.0) * step
    f_fa = (0.55 * m_n + 5.0) * step
    f_Hb = (0.05 * math.sqrt(d) + 0.35 * math.sqrt(b) + 4.0) * step
    r = round_tolerance
    return FlankTolerances(
        grade=grade, f_pT=r(f_pT), F_pT=r(F_pT), f_HalphaT=r(f_Ha), f_falphaT=r(f_fa),
        F_alphaT=r(math.hypot(f_Ha, f_fa)), f_HbetaT=r(f_Hb), f_fbetaT=r(f_Hb),
        F_betaT=r(math.sqrt(2.0) * f_Hb), F_rT=r(0.9 * F_pT))


def jbn_min(a_w: float, m_n: float) -> float:
    """Recommended least normal backlash [µm] of industrial drives ([ISO10064-2] eq. for
    j_bn min): j_bn min = ⅔·(0.06 + 0.0005·a_i + 0.03·m_n) mm, a_i the centre distance.

    >>> round(jbn_min(100.0, 4.0), 3)
    153.333
    """
    return 2000.0 / 3.0 * (0.06 + 0.0005 * a_w + 0.03 * m_n)


def designation(grade: int) -> str:
    return f"ISO 1328-1:2013 class {grade}"
