"""ISO 286 limit deviations of a hole-basis fit such as ``H7/s6`` ([ISO286] tables 1 and 2,
``iso286.csv``): the hole H (EI = 0, ES = +IT) and a shaft of letters f ... u.

The interference of a fit is ``U = shaft − hole``: largest ``U_max = es − EI``, smallest
``U_min = ei − ES`` [µm] ([ISO286]).  A negative ``U_min`` means the fit may have clearance.
"""

from __future__ import annotations

import re

from geardesign.connection import tables
from geardesign.core.records import dataclass

SHAFT_LETTERS = ("f", "g", "h", "js", "k", "m", "n", "p", "r", "s", "t", "u")
GRADES = range(5, 12)
MAX_SIZE = 500.0
_FIT = re.compile(r"^\s*H(\d{1,2})\s*/\s*([a-z]{1,2})(\d{1,2})\s*$")


class FitError(ValueError):
    """A fit the tables cannot give; the message says what is allowed."""


@dataclass(frozen=True)
class Fit:
    """Limit deviations [µm] of hole and shaft at one nominal size."""

    name: str
    row: int
    ES: float
    EI: float
    es: float
    ei: float

    @property
    def U_max(self) -> float:
        """Largest interference [µm]."""
        return self.es - self.EI

    @property
    def U_min(self) -> float:
        """Smallest interference [µm] (negative: clearance)."""
        return self.ei - self.ES


def _row(size: float) -> dict:
    for r in tables.iso286_rows():
        if r["over"] < size <= r["to"]:
            return r
    raise FitError(f"ISO 286 tables cover nominal sizes up to {MAX_SIZE:g} mm")


def fit(name: str, size: float) -> Fit:
    """The limit deviations of the hole-basis fit ``name`` at nominal size ``size`` [mm].

    >>> f = fit("H7/r6", 25.0)
    >>> (f.ES, f.EI, f.es, f.ei, f.U_max, f.U_min)
    (21.0, 0.0, 41.0, 28.0, 41.0, 7.0)
    """
    m = _FIT.match(name)
    if not m:
        raise FitError("must be a hole-basis fit such as \"H7/s6\" (hole H, grade 5...11 / "
                       "shaft " + ", ".join(SHAFT_LETTERS) + ", grade 5...11)")
    hole_grade, letter, shaft_grade = int(m.group(1)), m.group(2), int(m.group(3))
    if letter not in SHAFT_LETTERS or hole_grade not in GRADES or shaft_grade not in GRADES:
        raise FitError("the tables hold hole H and shafts " + ", ".join(SHAFT_LETTERS)
                       + " in grades 5...11")
    r = _row(size)
    it_hole, it_shaft = r[f"IT{hole_grade}"], r[f"IT{shaft_grade}"]
    if letter in ("f", "g", "h"):
        es = 0.0 if letter == "h" else r[letter]
        ei = es - it_shaft
    elif letter == "js":
        es, ei = it_shaft / 2.0, -it_shaft / 2.0
    else:
        if letter == "k":
            ei = r["k"] if 4 <= shaft_grade <= 7 else 0.0
        else:
            ei = r[letter]
        if ei is None:
            raise FitError(f"shaft deviation {letter} is defined by ISO 286 only above 24 mm")
        es = ei + it_shaft
    return Fit(f"H{hole_grade}/{letter}{shaft_grade}", r["row"], it_hole, 0.0, es, ei)
