"""The built-in bearing catalogue (``catalogue.csv`` beside this module): look-up by
designation (ISO, the maker's full designation or GOST), close matches, candidates for a
selection, and the rows for ``geardesign bearings``.

The data are the manufacturers' own tables, one source named per row (``source`` is a key of
``docs/references.md``, ``page`` its printed page): the SKF General Catalogue 6000 for every
series ([SKF6000]) and the NTN deep groove tables ([NTN]).  A designation made by several
makers resolves to SKF unless ``maker`` names another.  The file is read on the first look-up
only (the command line starts without it) and indexed once.  Ratings are stored in kN and
returned in N.
"""

from __future__ import annotations

import csv
import difflib
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

_FILE = Path(__file__).with_name("catalogue.csv")
DEFAULT_MAKER = "SKF"
MAKERS = ("SKF", "NTN")
SOURCES = {
    "SKF6000": "SKF General Catalogue 6000 (Russian edition)",
    "NTN": "NTN CAT. No. 2202/E",
}


class AmbiguousDesignation(ValueError):
    """A designation that names two different bearings (e.g. GOST 7208 = ISO 30208, while
    ISO 7208 B is an angular contact ball bearing)."""


@dataclass(frozen=True)
class CatalogueBearing:
    designation: str           # ISO designation without the maker's suffixes ("NU 208")
    gost: str                  # GOST 3189 designation of the same dimensions, or ""
    type: str
    series: str
    d: float
    D: float
    B: float                   # width (total width T of tapered, height H of thrust), mm
    C_r: float                 # N (C_a of thrust bearings)
    C_0r: float                # N
    C_u: float | None          # N, fatigue load limit (catalogue P_u)
    e: float | None
    Y: float | None            # F_a/F_r > e
    source: str                # reference key
    note: str
    maker: str = DEFAULT_MAKER
    maker_designation: str = ""
    Y1: float | None = None    # F_a/F_r <= e (double-row and spherical roller bearings)
    Y0: float | None = None
    f0: float | None = None
    alpha: float | None = None  # nominal contact angle, deg
    n_ref: float | None = None  # reference speed, min^-1
    n_lim: float | None = None  # limiting speed, min^-1
    mass: float | None = None   # kg
    page: str = ""

    @property
    def name(self) -> str:
        full = self.maker_designation or self.designation
        return f"{self.maker} {full}" + (f" (GOST {self.gost})" if self.gost else "")

    @property
    def cite(self) -> str:
        """Where the row was read: ``[SKF6000] p. 526``."""
        return f"[{self.source}] p. {self.page}" if self.page else f"[{self.source}]"


def _key(text: str) -> str:
    return "".join(text.split()).replace("-", "").upper()


def _num(text: str) -> float | None:
    return float(text) if text else None


@lru_cache(maxsize=1)
def bearings() -> tuple[CatalogueBearing, ...]:
    """Every catalogue row, in file order (type, maker, series, bore)."""
    with _FILE.open(encoding="utf-8", newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    out = []
    for r in csv.DictReader(lines):
        kn = 1000.0
        out.append(CatalogueBearing(
            r["designation"], r["gost"], r["type"], r["series"], float(r["d"]), float(r["D"]),
            float(r["B"]), float(r["C_r"]) * kn, float(r["C_0r"]) * kn,
            _num(r["C_u"]) * kn if r["C_u"] else None, _num(r["e"]), _num(r["Y"]), r["source"],
            r["note"], r["maker"], r["maker_designation"], _num(r["Y1"]), _num(r["Y0"]),
            _num(r["f0"]), _num(r["alpha"]), _num(r["n_ref"]), _num(r["n_lim"]), _num(r["mass"]),
            r["page"]))
    return tuple(out)


@lru_cache(maxsize=1)
def _index() -> tuple[dict, dict]:
    """(ISO and maker designations -> rows, GOST designations -> rows)."""
    iso: dict[str, list] = {}
    gost: dict[str, list] = {}
    for b in bearings():
        for k in {_key(b.designation), _key(b.maker_designation)} - {""}:
            iso.setdefault(k, []).append(b)
        if b.gost:
            gost.setdefault(_key(b.gost), []).append(b)
    return iso, gost


def makers() -> tuple[str, ...]:
    return tuple(dict.fromkeys(b.maker for b in bearings()))


def _pick(rows: list, maker: str | None) -> CatalogueBearing | None:
    if maker is not None:
        return next((b for b in rows if b.maker.upper() == maker.upper()), None)
    return next((b for b in rows if b.maker == DEFAULT_MAKER), rows[0])


def find(designation: str, maker: str | None = None) -> CatalogueBearing | None:
    """The bearing with this ISO, maker's or GOST designation (case, spaces and hyphens
    ignored), of ``maker`` (default SKF, else the first maker listing it), or None.

    Raises :class:`AmbiguousDesignation` for a bare ``72xx``/``73xx``: GOST 7208 is the
    tapered roller bearing 30208, while catalogues mean the angular contact 7208 B.
    """
    iso, gost = _index()
    k = _key(designation)
    if k in iso:
        return _pick(iso[k], maker)
    if k in gost:
        rows = gost[k]
        if k + "B" in iso:
            b, t = _pick(iso[k + "B"], maker), _pick(rows, maker)
            if b is not None and t is not None:
                raise AmbiguousDesignation(
                    f"ambiguous: ISO {b.designation} (angular contact ball, α = "
                    f"{b.alpha:g}°) or GOST {t.gost} = ISO {t.designation} (tapered roller); "
                    f"write \"{b.designation}\" or \"{t.designation}\"")
        return _pick(rows, maker)
    return None


def close_matches(designation: str, n: int = 3) -> list[str]:
    """ISO designations close to a mistyped one (GOST names only when no ISO name is close)."""
    for names in (sorted({b.designation for b in bearings()}),
                  sorted({b.gost for b in bearings() if b.gost})):
        keyed = {_key(x): x for x in names}
        k = _key(designation)
        swapped = [m for m in keyed if sorted(m) == sorted(k) and m != k]   # transposed digits
        found = list(dict.fromkeys(swapped + difflib.get_close_matches(k, list(keyed), n, 0.5)))
        found = found[:n]
        if found:
            return [keyed[m] for m in found]
    return []


def candidates(kind: str, d: float, series: list | None = None,
               maker: str | None = None) -> list[CatalogueBearing]:
    """Catalogue bearings of a type and bore, smallest first (outside diameter, then width,
    then rating); one row per designation (the default maker's unless ``maker`` is given).
    Of cylindrical roller bearings only the NU design is offered (NJ and NUP share its
    ratings)."""
    found: dict[str, CatalogueBearing] = {}
    for b in bearings():
        if b.type != kind or abs(b.d - d) > 1e-9 or (series and b.series not in series):
            continue
        if kind == "cylindrical_roller" and not b.designation.startswith("NU "):
            continue
        if maker is not None and b.maker.upper() != maker.upper():
            continue
        if b.designation not in found or (maker is None and b.maker == DEFAULT_MAKER):
            found[b.designation] = b
    return sorted(found.values(), key=lambda b: (b.D, b.B, b.C_r))


def bores(kind: str) -> list[float]:
    return sorted({b.d for b in bearings() if b.type == kind})


def series_of(kind: str) -> list[str]:
    return sorted({b.series for b in bearings() if b.type == kind})


def types() -> list[str]:
    return list(dict.fromkeys(b.type for b in bearings()))
