"""The built-in bearing catalogue (``catalogue.toml`` beside this module): lookup by
designation (ISO or GOST), close matches, and candidates for a selection.

The data are the manufacturers' (NTN CAT. No. 2202/E for deep groove ball bearings, SKF for
tapered roller bearings); each row names its source and says which value was not read in
it (``note``).  Ratings are stored in kN and returned in N.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

_FILE = Path(__file__).with_name("catalogue.toml")


@dataclass(frozen=True)
class CatalogueBearing:
    designation: str
    gost: str
    type: str
    series: str
    d: float
    D: float
    B: float                   # width (total width T for tapered roller bearings), mm
    C_r: float                 # N
    C_0r: float                # N
    C_u: float | None          # N
    e: float | None
    Y: float | None
    source: str
    note: str

    @property
    def name(self) -> str:
        return f"{self.designation} (GOST {self.gost})"


def _key(text: str) -> str:
    return "".join(text.split()).upper()


@lru_cache(maxsize=1)
def bearings() -> tuple[CatalogueBearing, ...]:
    try:
        import tomllib
    except ModuleNotFoundError:  # pragma: no cover - Python < 3.11
        import tomli as tomllib  # type: ignore[no-redef]
    rows = tomllib.loads(_FILE.read_text(encoding="utf-8"))["bearing"]
    out = []
    for r in rows:
        out.append(CatalogueBearing(
            r["designation"], r["gost"], r["type"], r["series"], r["d"], r["D"], r["B"],
            r["C_r"] * 1000.0, r["C_0r"] * 1000.0,
            r["C_u"] * 1000.0 if "C_u" in r else None, r.get("e"), r.get("Y"),
            r["source"], r["note"]))
    return tuple(out)


def find(designation: str) -> CatalogueBearing | None:
    """The bearing with this ISO or GOST designation (case and spaces ignored), or None."""
    k = _key(designation)
    for b in bearings():
        if k in (_key(b.designation), _key(b.gost)):
            return b
    return None


def close_matches(designation: str, n: int = 3) -> list[str]:
    names = [b.designation for b in bearings()] + [b.gost for b in bearings()]
    return difflib.get_close_matches(_key(designation), names, n, 0.5)


def candidates(kind: str, d: float, series: list | None = None) -> list[CatalogueBearing]:
    """Catalogue bearings of a type and bore, smallest first (outside diameter, then width,
    then rating)."""
    found = [b for b in bearings() if b.type == kind and abs(b.d - d) < 1e-9
             and (not series or b.series in series)]
    return sorted(found, key=lambda b: (b.D, b.B, b.C_r))


def bores(kind: str) -> list[float]:
    return sorted({b.d for b in bearings() if b.type == kind})


def series_of(kind: str) -> list[str]:
    return sorted({b.series for b in bearings() if b.type == kind})
