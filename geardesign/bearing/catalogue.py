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

from functools import lru_cache
from pathlib import Path

from geardesign.core.records import dataclass

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


def _parse(text: str) -> tuple[list[tuple], dict[str, list[int]], dict[str, list[int]]]:
    """The catalogue file as its rows (the fields of :class:`CatalogueBearing` in order,
    ratings in N) and two indexes of row numbers: ISO and maker designations, GOST
    designations (keys by :func:`_key`).  Kept parsed (:func:`geardesign.core.data.parsed`)."""
    from geardesign.core.data import csv_rows

    rows, iso, gost = [], {}, {}
    kn = 1000.0
    for i, r in enumerate(csv_rows(text)):
        rows.append((
            r["designation"], r["gost"], r["type"], r["series"], float(r["d"]), float(r["D"]),
            float(r["B"]), float(r["C_r"]) * kn, float(r["C_0r"]) * kn,
            _num(r["C_u"]) * kn if r["C_u"] else None, _num(r["e"]), _num(r["Y"]), r["source"],
            r["note"], r["maker"], r["maker_designation"], _num(r["Y1"]), _num(r["Y0"]),
            _num(r["f0"]), _num(r["alpha"]), _num(r["n_ref"]), _num(r["n_lim"]), _num(r["mass"]),
            r["page"]))
        for k in sorted({_key(r["designation"]), _key(r["maker_designation"])} - {""}):
            iso.setdefault(k, []).append(i)
        if r["gost"]:
            gost.setdefault(_key(r["gost"]), []).append(i)
    return rows, iso, gost


@lru_cache(maxsize=1)
def _table() -> tuple[list[tuple], dict[str, list[int]], dict[str, list[int]]]:
    from geardesign.core.data import parsed

    return parsed(_FILE, _parse)


@lru_cache(maxsize=None)
def _row(i: int) -> CatalogueBearing:
    """Row ``i`` of the file (made on first use: a look-up makes only the rows it finds)."""
    return CatalogueBearing(*_table()[0][i])


@lru_cache(maxsize=1)
def bearings() -> tuple[CatalogueBearing, ...]:
    """Every catalogue row, in file order (type, maker, series, bore)."""
    return tuple(_row(i) for i in range(len(_table()[0])))


_MAKER = 14
"""Where ``maker`` is in a row of :func:`_table` (the order of the fields)."""


class _Rows(dict):
    """An index of :func:`_table` (key -> row numbers) that gives the rows themselves."""

    def __init__(self, numbers: dict[str, list[int]]):
        super().__init__(numbers)

    def __getitem__(self, key: str) -> list[CatalogueBearing]:
        return [_row(i) for i in super().__getitem__(key)]


@lru_cache(maxsize=1)
def _index() -> tuple[dict, dict]:
    """(ISO and maker designations -> rows, GOST designations -> rows)."""
    _, iso, gost = _table()
    return _Rows(iso), _Rows(gost)


def makers() -> tuple[str, ...]:
    return tuple(dict.fromkeys(row[_MAKER] for row in _table()[0]))


def _pick(rows: list, maker: str | None) -> CatalogueBearing | None:
    if maker is not None:
        return next((b for b in rows if b.maker.upper() == maker.upper()), None)
    return next((b for b in rows if b.maker == DEFAULT_MAKER), rows[0])


SUFFIXES = {
    # suffix (spaces, hyphens and "/" removed, upper case): what it means.  Seals and shields
    # of deep groove and other ball bearings ([SKF6000] designation system; NTN LLU/LLB/ZZ,
    # NSK DDU/VV), the radial internal clearance groups (ISO 5753-1) and the snap ring groove.
    "2RS1": "contact seals on both sides", "2RSH": "contact seals on both sides",
    "2RSL": "low-friction seals on both sides", "2RS2": "contact seals on both sides",
    "2RS": "contact seals on both sides", "RS1": "a contact seal on one side",
    "RSH": "a contact seal on one side", "RSL": "a low-friction seal on one side",
    "RS": "a contact seal on one side", "2RZ": "non-contact seals on both sides",
    "RZ": "a non-contact seal on one side", "2Z": "shields on both sides",
    "ZZ": "shields on both sides", "Z": "a shield on one side",
    "2RSR": "contact seals on both sides", "RSR": "a contact seal on one side",
    "2ZR": "shields on both sides", "ZR": "a shield on one side",
    "LLU": "contact seals on both sides", "LLB": "non-contact seals on both sides",
    "LLH": "low-friction seals on both sides", "LU": "a contact seal on one side",
    "DDU": "contact seals on both sides", "DU": "a contact seal on one side",
    "VV": "non-contact seals on both sides", "2RU": "contact seals on both sides",
    "NR": "a snap ring groove with its snap ring", "N": "a snap ring groove",
    "C2": "radial internal clearance C2", "CN": "normal radial internal clearance",
    "C3": "radial internal clearance C3", "C4": "radial internal clearance C4",
    "C5": "radial internal clearance C5",
}
"""Suffixes of a designation that name a variant of the same catalogue row: the same
dimensions and load ratings (a sealed or shielded bearing has a lower limiting speed, and
its grease fill replaces the oil of the lubrication factors)."""

MAKER_PREFIXES = ("SKF", "NTN", "FAG", "INA", "NSK", "KOYO", "TIMKEN", "NACHI", "ZKL", "SNR",
                  "GPZ")
"""Makers' names a designation may start with (``SKF 6208``, as the report prints it)."""


@dataclass(frozen=True)
class Reading:
    """How a written designation was read: the catalogue row, the maker named in it (or
    None) and a sentence saying which variant was read as which row ("" when the text is
    the row's own designation)."""
    row: CatalogueBearing | None
    maker: str | None
    note: str


def _suffixes(rest: str) -> list[str] | None:
    """``rest`` split into known :data:`SUFFIXES` (longest first), or None."""
    out = []
    while rest:
        hit = next((x for x in sorted(SUFFIXES, key=len, reverse=True) if rest.startswith(x)),
                   None)
        if hit is None:
            return None
        out.append(hit)
        rest = rest[len(hit):]
    return out


def read(designation: str, maker: str | None = None) -> Reading:
    """A designation as written on a drawing, a catalogue page or this tool's report,
    read as a catalogue row: a maker's name in front (``SKF 6208``), a GOST name in
    brackets behind (``SKF 6208 (GOST 208)``) and suffixes of seals, shields, clearance or
    snap ring (``6208-2RS1``, ``6208-2Z``, ``6208 ZZ``, ``6208-2RS1/C3``,
    :data:`SUFFIXES`) are read off; the rest is looked up by :func:`find`.  A maker named
    in the text and another in ``maker`` is an ambiguity (ValueError)."""
    import re

    text = re.sub(r"\(\s*GOST[^)]*\)\s*$", "", designation.strip(), flags=re.I).strip()
    named = None
    head = text.split(None, 1)
    if len(head) == 2 and head[0].upper() in MAKER_PREFIXES:
        named, text = head[0].upper(), head[1]
    notes = []
    use_maker = maker
    if named is not None:
        known = {m.upper(): m for m in makers()}
        if maker is not None and maker.upper() != named:
            raise ValueError(f"names the maker {named}, while bearing.maker = \"{maker}\"; "
                             f"give one")
        if named in known:
            use_maker = known[named]
        else:
            notes.append(f"{named} is not in the built-in catalogue: the ISO dimensions are "
                         f"those of {named}'s bearing, the ratings those of the catalogue row")
    row = find(text, use_maker)
    if row is None:
        iso, _ = _index()
        k = "".join(text.split()).replace("-", "").replace("/", "").upper()
        for n in range(len(k) - 1, 2, -1):
            if k[:n] in iso:
                parts = _suffixes(k[n:])
                if parts is not None:
                    row = _pick(iso[k[:n]], use_maker)
                    if row is not None:
                        sealed = any(not x.startswith("C") and x not in ("N", "NR")
                                     for x in parts)
                        notes.insert(0, f"\"{designation.strip()}\" read as the catalogue "
                                        f"row {row.maker} {row.designation}: "
                                        + ", ".join(f"{x} = {SUFFIXES[x]}" for x in parts)
                                        + "; the same dimensions and load ratings"
                                        + (" (a sealed or shielded bearing has a lower "
                                           "limiting speed: see the maker's table)"
                                           if sealed else ""))
                    break
    return Reading(row, named, "; ".join(notes))


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
    from difflib import get_close_matches

    for names in (sorted({b.designation for b in bearings()}),
                  sorted({b.gost for b in bearings() if b.gost})):
        keyed = {_key(x): x for x in names}
        k = _key(designation)
        swapped = [m for m in keyed if sorted(m) == sorted(k) and m != k]   # transposed digits
        found = list(dict.fromkeys(swapped + get_close_matches(k, list(keyed), n, 0.5)))
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
