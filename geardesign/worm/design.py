"""Design mode: propose the centre distance and a standard (m, q, x) set for a torque, a
ratio and a wheel material ([Chernavsky] "design centre distance", design practice; GOST 2144-76
series).

Pure functions; the contact-stress design formula itself is
:func:`geardesign.worm.strength.required_center_distance`.
"""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.worm import tables
from geardesign.worm.geometry import X_MAX, shift_for_center_distance

STIFFNESS_Q_RATIO = 0.212
"""q >= 0.212·z2 keeps the worm stiff enough (Dunaev & Lelikov; [Dunaev])."""

PREFERRED_SHIFT = (-0.5, 0.7)
"""Preferred range of the wheel shift (design practice; GOST 19650-97 allows ±1)."""


def starts_for_ratio(u: float) -> int:
    """Worm starts for a ratio: 4 for u <= 14, 2 for 14 < u <= 30, 1 above ([Dunaev]; the Pascal
    program splits at 16 and 32)."""
    if u <= 14.0:
        return 4
    if u <= 30.0:
        return 2
    return 1


def default_q(z2: int) -> float:
    """Smallest first-row diameter factor (GOST 19672-74) with q >= 0.212·z2, at most 25."""
    need = STIFFNESS_Q_RATIO * z2
    for q in tables.series()["q_1"]:
        if q >= need - 1e-9:
            return q
    return tables.series()["q_1"][-1]


def round_up_center_distance(a_w: float, rows: str = "first") -> float | None:
    """The next GOST 2144-76 centre distance >= ``a_w`` (first row, or both rows), None when
    ``a_w`` exceeds the series."""
    s = tables.series()
    values = list(s["center_distance_1"])
    if rows == "both":
        values = sorted(values + list(s["center_distance_2"]))
    for v in values:
        if v >= a_w - 1e-9:
            return v
    return None


def is_standard_pair(m: float, q: float) -> tuple[bool, bool, bool]:
    """(m in a GOST 19672-74 module row, q in a q row, (m, q) a recommended pair)."""
    s = tables.series()
    m_ok = any(abs(m - v) < 1e-9 for v in s["module_1"] + s["module_2"])
    q_ok = any(abs(q - v) < 1e-9 for v in s["q_1"] + s["q_2"])
    rec = tables.recommended_q(m)
    return m_ok, q_ok, rec is not None and any(abs(q - v) < 1e-9 for v in rec)


@dataclass(frozen=True)
class Proposal:
    m: float
    q: float
    x: float
    standard: bool   # m and q from the series with |x| <= 1


def ranked_pairs(a_w: float, z2: int, q0: float, q_fixed: bool) -> list[Proposal]:
    """Every standard (m, q) of the GOST 19672-74 rows (only q = q0 when ``q_fixed``) with
    |x| <= 1 at the centre distance ``a_w``, x = a_w/m − 0.5 (q + z2), best first: first-row
    m, first-row q, a recommended pair, x within −0.5 ... +0.7, q closest to q0, smallest
    |x|."""
    s = tables.series()
    ranked = []
    for m in s["module_1"] + s["module_2"]:
        for q in ([q0] if q_fixed else s["q_1"] + s["q_2"]):
            x = shift_for_center_distance(a_w, m, q, z2)
            if abs(x) > X_MAX:
                continue
            _, _, rec = is_standard_pair(m, q)
            score = (m not in s["module_1"], q not in s["q_1"], not rec,
                     not PREFERRED_SHIFT[0] <= x <= PREFERRED_SHIFT[1], abs(q - q0), abs(x))
            ranked.append((score, Proposal(m, q, x, True)))
    ranked.sort(key=lambda r: r[0])
    return [p for _, p in ranked]


def choose_module(a_w: float, z2: int, q0: float, q_fixed: bool) -> Proposal:
    """Standard module and diameter factor for the centre distance ``a_w``: the best of
    :func:`ranked_pairs`.  Without any, the module m = 2 a_w/(q0 + z2) with x = 0 is
    returned as not standard.
    """
    ranked = ranked_pairs(a_w, z2, q0, q_fixed)
    if not ranked:
        return Proposal(2.0 * a_w / (q0 + z2), q0, 0.0, False)
    return ranked[0]


def standard_center_distances(start: float) -> list[float]:
    """The GOST 2144-76 centre distances >= ``start``: the first (preferred) row ascending,
    then the second row ascending."""
    s = tables.series()
    return [v for row in ("center_distance_1", "center_distance_2")
            for v in sorted(s[row]) if v >= start - 1e-9]
