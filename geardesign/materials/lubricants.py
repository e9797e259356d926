"""Lubricating oils: ISO VG grades (``lubricants.csv``), the viscosity at a temperature by
ASTM D341 (Ubbelohde–Walther) and the viscosity index by ASTM D2270.

Units: kinematic viscosity ν in mm²/s, temperature in °C.  The data file is read on first
use only.

>>> round(viscosity_at(40.0, 200.0, 16.0), 1)
200.0
"""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

from geardesign.core.records import dataclass

_FILE = Path(__file__).with_name("lubricants.csv")
T0 = 273.15                 # K at 0 °C
NU_MIN_D341 = 2.0           # mm²/s: below, Z = ν + 0.7 needs the D341 correction terms

#: ASTM D2270 Table X2.1: L = a·Y² + b·Y + c and H = d·Y² + e·Y + f for Y = ν100 (mm²/s)
#: from Y_min (inclusive) to the next row.  Rows: (Y_min, a, b, c, d, e, f).
D2270_X2 = (
    (2.0, 1.14673, 1.7576, -0.109, 0.84155, 1.5521, -0.077),
    (3.8, 3.38095, -15.4952, 33.196, 0.78571, 1.7929, -0.183),
    (4.4, 2.5, -7.2143, 13.812, 0.82143, 1.5679, 0.119),
    (5.0, 0.101, 16.635, -45.469, 0.04985, 9.1613, -18.557),
    (6.4, 3.35714, -23.5643, 78.466, 0.22619, 7.7369, -16.656),
    (7.0, 0.01191, 21.475, -72.87, 0.79762, -0.7321, 14.61),
    (7.7, 0.41858, 16.1558, -56.04, 0.05794, 10.5156, -28.24),
    (9.0, 0.88779, 7.5527, -16.6, 0.26665, 6.7015, -10.81),
    (12.0, 0.7672, 10.7972, -38.18, 0.20073, 8.4658, -22.49),
    (15.0, 0.97305, 5.3135, -2.2, 0.28889, 5.9741, -4.93),
    (18.0, 0.97256, 5.25, -0.98, 0.24504, 7.416, -16.73),
    (22.0, 0.91413, 7.4759, -21.82, 0.20323, 9.1267, -34.23),
    (28.0, 0.87031, 9.7157, -50.77, 0.18411, 10.1015, -46.75),
    (40.0, 0.84703, 12.6752, -133.31, 0.17029, 11.4866, -80.62),
    (55.0, 0.85921, 11.1009, -83.19, 0.1713, 11.368, -76.94),
    (70.0, 0.83531, 14.6731, -216.246, 0.16841, 11.8493, -96.947),
)


class OilError(ValueError):
    """The oil data cannot give a viscosity (outside the methods' range)."""


@dataclass(frozen=True)
class Oil:
    grade: str
    nu40: float
    nu40_min: float
    nu40_max: float
    VI: float
    density_15: float | None
    fzg_stage: float | None
    source: str
    page: str

    @property
    def cite(self) -> str:
        return f"[{self.source}] p. {self.page}"


def _num(x: str) -> float | None:
    return float(x) if x else None


def _parse(text: str) -> list[tuple]:
    """The rows of ``lubricants.csv``: the fields of :class:`Oil` in order."""
    from geardesign.core.data import csv_rows

    return [(r["grade"], float(r["nu40"]), float(r["nu40_min"]), float(r["nu40_max"]),
             float(r["VI"]), _num(r["density_15"]), _num(r["fzg_stage"]), r["source"],
             r["page"]) for r in csv_rows(text)]


@lru_cache(maxsize=1)
def grades() -> tuple[Oil, ...]:
    from geardesign.core.data import parsed

    return tuple(Oil(*row) for row in parsed(_FILE, _parse))


def _key(name: str) -> str:
    k = "".join(str(name).split()).upper().replace("ISO", "")
    return k if k.startswith("VG") else "VG" + k


def find(name: str) -> Oil | None:
    """The grade ``"VG 220"`` (also ``"ISO VG 220"``, ``"220"``), or None."""
    k = _key(name)
    return next((o for o in grades() if _key(o.grade) == k), None)


def close_matches(name: str, n: int = 3) -> list[str]:
    """The grades nearest in viscosity to a number that is not a grade, else by spelling."""
    try:
        x = float(_key(name)[2:])
    except ValueError:
        x = None
    if x is not None and x > 0:
        near = sorted(grades(), key=lambda o: abs(math.log(o.nu40 / x)))[:2]
        return [o.grade for o in sorted(near, key=lambda o: o.nu40)]
    from difflib import get_close_matches  # only to name a close match

    names = {_key(o.grade): o.grade for o in grades()}
    return [names[m] for m in get_close_matches(_key(name), list(names), n, 0.6)]


# ----------------------------------------------------------------------------- ASTM D2270


def l_h(Y: float) -> tuple[float, float]:
    """L and H of ASTM D2270 (Table X2.1 quadratics) for ν100 = Y >= 2 mm²/s."""
    if Y < D2270_X2[0][0]:
        raise OilError(f"ν100 = {Y:.3g} mm²/s is below 2 mm²/s, the range of ASTM D2270")
    row = [r for r in D2270_X2 if Y >= r[0]][-1]
    _, a, b, c, d, e, f = row
    return a * Y * Y + b * Y + c, d * Y * Y + e * Y + f


def viscosity_index(nu40: float, nu100: float) -> float:
    """Viscosity index VI of an oil from ν40 = U and ν100 = Y (ASTM D2270 / ISO 2909):
    VI = 100·(L − U)/(L − H) for U >= H; above 100, N = (log H − log U)/log Y and
    VI = (10^N − 1)/0.00715 + 100.

    >>> round(viscosity_index(22.83, 5.05))
    156
    """
    L, H = l_h(nu100)
    if nu40 >= H:
        return 100.0 * (L - nu40) / (L - H)
    N = (math.log10(H) - math.log10(nu40)) / math.log10(nu100)
    return (10.0 ** N - 1.0) / 0.00715 + 100.0


@lru_cache(maxsize=256)
def nu100_from_vi(nu40: float, VI: float) -> float:
    """ν100 [mm²/s] of an oil with ν40 and viscosity index VI: the inverse of
    :func:`viscosity_index` (VI rises with ν100 at fixed ν40), by bisection (a hundred
    steps: kept for the pairs asked before)."""
    lo, hi = 2.0, nu40
    if viscosity_index(nu40, lo) > VI or viscosity_index(nu40, hi * 0.999) < VI:
        raise OilError(f"no ν100 gives VI = {VI:g} with ν40 = {nu40:g} mm²/s within ASTM "
                       f"D2270 (ν100 >= 2 mm²/s)")
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if viscosity_index(nu40, mid) < VI:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


# ----------------------------------------------------------------------------- ASTM D341


@lru_cache(maxsize=256)
def walther(nu1: float, t1: float, nu2: float, t2: float) -> tuple[float, float]:
    """Constants A, B of ASTM D341: log10 log10(ν + 0.7) = A − B·log10(T), T in K, through
    two points (ν1 at t1, ν2 at t2; ν >= 2 mm²/s)."""
    if min(nu1, nu2) < NU_MIN_D341:
        raise OilError("ASTM D341 with Z = ν + 0.7 needs ν >= 2 mm²/s at both points")
    z1 = math.log10(math.log10(nu1 + 0.7))
    z2 = math.log10(math.log10(nu2 + 0.7))
    x1, x2 = math.log10(t1 + T0), math.log10(t2 + T0)
    B = (z1 - z2) / (x2 - x1)
    return z1 + B * x1, B


def viscosity_at(t: float, nu40: float, nu100: float) -> float:
    """Kinematic viscosity [mm²/s] at t [°C] of an oil with ν40 and ν100 (ASTM D341,
    Ubbelohde–Walther): ν = 10^(10^(A − B·log10 T)) − 0.7."""
    A, B = walther(nu40, 40.0, nu100, 100.0)
    nu = 10.0 ** (10.0 ** (A - B * math.log10(t + T0))) - 0.7
    if not math.isfinite(nu) or nu < NU_MIN_D341:
        raise OilError(f"the oil's viscosity at {t:g} °C falls outside ASTM D341 (ν < 2 "
                       f"mm²/s): give the viscosity at the operating temperature")
    return nu
