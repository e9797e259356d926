"""ISO 1328-1 flank tolerances of one gear, editions 2013 and 1995: the one module that the
gear drawing (``[accuracy]``) and the ISO 6336 rating (f_pb, f_fα, f_Hβ, F_β of K_v, K_Hα
and K_Hβ) call, so that both carry the same numbers.

Each tolerance of class A is its class-5 formula times the step factor √2^(A − 5); the
coefficients are data (``iso1328.toml``).

ISO 1328-1:2013 ([ISO1328-1] 5.3), flank tolerance classes 1…11, at the gear's own reference
diameter d, normal module m_n and face width b [mm]:

* single pitch          f_pT  = (0.001 d + 0.4 m_n + 5)·√2^(A−5)              eq. (5)
* cumulative pitch      F_pT  = (0.002 d + 0.55 √d + 0.7 m_n + 12)·√2^(A−5)   eq. (6)
* profile slope         f_HαT = (0.4 m_n + 0.001 d + 4)·√2^(A−5)              eq. (7)
* profile form          f_fαT = (0.55 m_n + 5)·√2^(A−5)                       eq. (8)
* total profile         F_αT  = √(f_HαT² + f_fαT²)                            eq. (9)
* helix slope           f_HβT = (0.05 √d + 0.35 √b + 4)·√2^(A−5)              eq. (10)
* helix form            f_fβT = (0.07 √d + 0.45 √b + 4)·√2^(A−5)              eq. (11)
* total helix           F_βT  = √(f_HβT² + f_fβT²)                            eq. (12)
* runout                F_rT  = 0.9·F_pT

(9) and (12) combine the unrounded slope and form tolerances.  Validity: 5 ≤ d ≤ 15 000 mm,
0.5 ≤ m_n ≤ 70 mm, 4 ≤ b ≤ 1 200 mm.

ISO 1328-1:1995 ([ISO1328-1-1995]), accuracy grades 0…12, with d, m = m_n and b replaced by
the geometric mean of the bounds of the size range that holds them (ranges "5 ≤ d ≤ 20,
20 < d ≤ 50, …" in ``iso1328.toml``):

* single pitch          f_pt = 0.3 (m + 0.4 √d) + 4                             6.1
* cumulative pitch      F_p  = 0.3 m + 1.25 √d + 7                              6.3
* total profile         F_α  = 3.2 √m + 0.22 √d + 0.7                           6.4
* total helix           F_β  = 0.1 √d + 0.63 √b + 4.2                           6.5
* profile form          f_fα = 2.5 √m + 0.17 √d + 0.5                           B.2.1
* profile slope         f_Hα = 2 √m + 0.14 √d + 0.5                             B.2.2
* helix form and slope  f_fβ = f_Hβ = 0.07 √d + 0.45 √b + 3                     B.2.3
* runout                F_r  = 0.8·F_p                              [ISO1328-2] annex B

each times √2^(Q−5).  Validity: 5 ≤ d ≤ 10 000 mm, 0.5 ≤ m ≤ 70 mm, 4 ≤ b ≤ 1 000 mm.

Rounding, both editions: above 10 µm to the nearest micrometre, from 5 to 10 µm to the
nearest 0.5 µm, below 5 µm to the nearest 0.1 µm, each tolerance from its own unrounded
value of its class ([ISO1328-1] 5.2; [ISO1328-1-1995] 5).

Written with :mod:`geardesign.core.xp`: d, m_n and b may be numbers or numpy arrays (the
sweep kernel); the class is one integer.
"""

from __future__ import annotations

import math
from bisect import bisect_left
from functools import lru_cache
from pathlib import Path

from geardesign.core import xp
from geardesign.core.records import dataclass
from geardesign.spur.tolerances.gost1643 import ToleranceError

STANDARD = "ISO 1328-1:2013"
STANDARD_1995 = "ISO 1328-1:1995"
EDITIONS = (STANDARD, STANDARD_1995)
KEYS = ("f_pT", "F_pT", "f_HalphaT", "f_falphaT", "F_alphaT", "f_HbetaT", "f_fbetaT",
        "F_betaT", "F_rT")


@lru_cache(maxsize=None)
def _data() -> dict:
    from geardesign.core.data import toml_table

    return toml_table(Path(__file__).with_name("iso1328.toml"))


def grades(standard: str = STANDARD) -> range:
    """The classes (2013) or grades (1995) of an edition."""
    lo, hi = _data()[standard]["grades"]
    return range(lo, hi + 1)



def check_standard(standard: str, key: str = "accuracy.standard") -> str:
    if standard not in EDITIONS:
        raise ToleranceError(key, standard, "unknown edition of ISO 1328-1: give "
                             + " or ".join(f'"{e}"' for e in EDITIONS))
    return standard


def check_grade(grade: int, standard: str = STANDARD, key: str = "accuracy.grade") -> int:
    """The class, or :class:`ToleranceError` for a class the edition has not."""
    check_standard(standard)
    r = grades(standard)
    if grade not in r:
        what = "flank tolerance class" if standard == STANDARD else "accuracy grade"
        raise ToleranceError(key, grade, f"unknown {what} of {standard}: give "
                             f"{r.start}…{r.stop - 1}")
    return grade


def round_tolerance(value):
    """[ISO1328-1] 5.2 rounding (the 1995 edition rounds alike): > 10 µm to 1 µm, 5…10 µm to
    0.5 µm, < 5 µm to 0.1 µm; halves up.

    >>> round_tolerance(12.49), round_tolerance(7.3), round_tolerance(3.14)
    (12.0, 7.5, 3.1)
    """
    return xp.where(value > 10.0, xp.floor(value + 0.5),
                    xp.where(value >= 5.0, xp.floor(2.0 * value + 0.5) / 2.0,
                             xp.floor(10.0 * value + 0.5) / 10.0))


def class_mean(value, bounds):
    """The geometric mean of the bounds of the size range that holds ``value``
    ([ISO1328-1-1995]: the first range holds its lower bound, every range its upper bound);
    a value beyond the table takes its first or last range.

    >>> round(class_mean(341.183, [280.0, 560.0, 1000.0]), 3)
    395.98
    """
    if xp.scalar(value):
        i = min(max(bisect_left(bounds, value), 1), len(bounds) - 1)
        return math.sqrt(bounds[i - 1] * bounds[i])
    import numpy as np

    b = np.asarray(bounds, dtype=float)
    i = np.clip(np.searchsorted(b, value, side="left"), 1, len(b) - 1)
    return np.sqrt(b[i - 1] * b[i])


def _formula(c: dict, d, m, b):
    return (c.get("c0", 0.0) + c.get("c_d", 0.0) * d + c.get("c_sd", 0.0) * xp.sqrt(d)
            + c.get("c_m", 0.0) * m + c.get("c_sm", 0.0) * xp.sqrt(m)
            + c.get("c_sb", 0.0) * xp.sqrt(b))


def unrounded(d, m_n, b, A: int, standard: str = STANDARD) -> dict:
    """Every tolerance of class ``A`` [µm] before rounding, keyed as :data:`KEYS`; d is
    taken by its magnitude (an internal gear's negative diameter)."""
    t = _data()[check_standard(standard)]
    d = abs(d)
    if standard == STANDARD_1995:
        r = t["ranges"]
        d, m_n, b = (class_mean(d, r["d"]), class_mean(m_n, r["m_n"]), class_mean(b, r["b"]))
    step = math.sqrt(2.0) ** (A - 5)
    out = {k: _formula(t[k], d, m_n, b) * step for k in KEYS if k in t}
    if "F_alphaT" not in out:
        out["F_alphaT"] = xp.hypot(out["f_HalphaT"], out["f_falphaT"])
    if "F_betaT" not in out:
        out["F_betaT"] = xp.hypot(out["f_HbetaT"], out["f_fbetaT"])
    out["F_rT"] = t["runout"] * out["F_pT"]
    return out


def tolerances(d, m_n, b, A: int, standard: str = STANDARD) -> dict:
    """Every tolerance of class ``A`` [µm], rounded as the standard rounds."""
    return {k: round_tolerance(v) for k, v in unrounded(d, m_n, b, A, standard).items()}


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
    standard: str = STANDARD


def flank_tolerances(grade: int, d: float, m_n: float, b: float,
                     standard: str = STANDARD) -> FlankTolerances:
    """The tolerances of class ``grade`` for reference diameter ``d``, normal module ``m_n``
    and face width ``b`` (mm) to ``standard``, within the edition's range of validity
    (else :class:`ToleranceError`); formulas in the module docstring.

    >>> flank_tolerances(5, 100.0, 4.0, 40.0).f_pT
    6.5
    >>> flank_tolerances(6, 341.183, 14.0, 360.0, STANDARD_1995).f_pT
    14.0
    """
    check_grade(grade, standard)
    for key, value, lo, hi in outside_validity(d, m_n, b, standard)[:1]:
        raise ToleranceError("accuracy.grade", grade,
                             f"{standard} applies to a {SIZE_NAMES[key]} of {lo:g}…{hi:g} mm, "
                             f"not {value:.6g} mm")
    return FlankTolerances(grade=grade, standard=standard,
                           **tolerances(abs(d), m_n, b, grade, standard))


SIZE_NAMES = {"d": "reference diameter d", "m_n": "normal module", "b": "face width"}


def validity(standard: str = STANDARD) -> dict:
    """The edition's range of validity {"d": (lo, hi), "m_n": …, "b": …} [mm] (data)."""
    return {k: tuple(v) for k, v in _data()[check_standard(standard)]["limits"].items()}


def outside_validity(d: float, m_n: float, b: float, standard: str = STANDARD) -> list:
    """The sizes of one gear outside the edition's range of validity, as (key, value, lo,
    hi) with key "d", "m_n" or "b" [mm] (d by its magnitude); empty within the range.
    Beyond it the 2013 formulas are extrapolated and the 1995 edition takes its first or
    last size range (:func:`class_mean`): the drawing refuses such a gear
    (:func:`flank_tolerances`), the ISO 6336 rating warns.

    >>> outside_validity(12000.0, 14.0, 360.0, STANDARD_1995)
    [('d', 12000.0, 5.0, 10000.0)]
    """
    return [(key, value, *validity(standard)[key])
            for key, value in (("d", abs(d)), ("m_n", m_n), ("b", b))
            if not validity(standard)[key][0] <= value <= validity(standard)[key][1]]


def beyond_range_words(standard: str = STANDARD) -> str:
    """What the edition's formulas do beyond their range (for messages)."""
    return ("the 1995 size ranges end there: the first or last range was taken"
            if standard == STANDARD_1995 else "the 2013 formulas were extrapolated")


def rating_deviations(d1, d2, m_n, b, alpha_t, A: int, standard: str = STANDARD) -> dict:
    """The flank deviations ISO 6336-1 takes for a pair [µm], each the larger of the two
    gears' tolerances of class ``A``: f_pb = f_pT·cos α_t (α_t [rad], the single pitch
    tolerance projected on the line of action), f_fα = f_fαT, f_Hβ = f_HβT, F_β = F_βT
    ([ISO6336-1]: f_pb and f_fα in K_v and K_Hα, f_Hβ in K_Hβ; the tolerances of
    :func:`tolerances`)."""
    t1, t2 = (tolerances(d, m_n, b, A, standard) for d in (d1, d2))
    larger = {k: xp.maximum(t1[k], t2[k]) for k in ("f_pT", "f_falphaT", "f_HbetaT", "F_betaT")}
    return {"f_pb": larger["f_pT"] * xp.cos(alpha_t), "f_falpha": larger["f_falphaT"],
            "f_Hbeta": larger["f_HbetaT"], "F_beta": larger["F_betaT"]}


def jbn_min(a_w: float, m_n: float) -> float:
    """Recommended least normal backlash [µm] of industrial drives ([ISO10064-2] eq. for
    j_bn min): j_bn min = ⅔·(0.06 + 0.0005·a_i + 0.03·m_n) mm, a_i the centre distance.

    >>> round(jbn_min(100.0, 4.0), 3)
    153.333
    """
    return 2000.0 / 3.0 * (0.06 + 0.0005 * a_w + 0.03 * m_n)


def source(key: str, standard: str = STANDARD) -> str:
    """Where the standard gives tolerance ``key`` (a report's source column)."""
    if standard == STANDARD:
        return f"{STANDARD} 5.3"
    return "ISO 1328-2:1997 annex B" if key == "F_rT" else f"{STANDARD_1995} cl. 6, annex B"


def designation(grade: int, standard: str = STANDARD) -> str:
    """How the drawing names the accuracy: "ISO 1328-1:2013 class 6", "ISO 1328-1:1995
    grade 6"."""
    return f"{standard} {'class' if standard == STANDARD else 'grade'} {grade}"
