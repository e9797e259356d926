"""The data tables of the connection calculator (``keys.csv``, ``splines.csv``,
``iso286.csv``, ``tables.toml``), read once.  A CSV row is returned with its number (data rows
counted from 1) so that a report can cite it."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from geardesign.core.records import dataclass

HERE = Path(__file__).resolve().parent


def _rows(name: str) -> list[dict]:
    from geardesign.core.data import csv_table

    return csv_table(HERE / name)


@lru_cache(maxsize=None)
def toml() -> dict:
    from geardesign.core.data import toml_table

    return toml_table(HERE / "tables.toml")


@dataclass(frozen=True)
class KeySize:
    """A parallel key section of [GOST23360] / [DIN6885-1] table 1 [mm]."""

    row: int
    d_over: float
    d_to: float
    b: float
    h: float
    t1: float
    t2: float


@lru_cache(maxsize=None)
def key_sizes() -> tuple[KeySize, ...]:
    return tuple(KeySize(i, *(float(r[k]) for k in ("d_over", "d_to", "b", "h", "t1", "t2")))
                 for i, r in enumerate(_rows("keys.csv"), 1))


def key_for_diameter(d: float) -> KeySize | None:
    """The key section for shaft diameter ``d`` (over d_over up to and including d_to), or
    ``None`` outside the table.

    >>> key_for_diameter(40.0).b, key_for_diameter(40.0).h, key_for_diameter(40.0).t1
    (12.0, 8.0, 5.0)
    """
    for k in key_sizes():
        if k.d_over < d <= k.d_to:
            return k
    return None


def key_lengths() -> tuple[float, ...]:
    return tuple(float(v) for v in toml()["key_lengths"])


@dataclass(frozen=True)
class SplineSize:
    row: int
    d_B: float
    m: float
    z: int


@lru_cache(maxsize=None)
def spline_sizes() -> tuple[SplineSize, ...]:
    return tuple(SplineSize(i, float(r["d_B"]), float(r["m"]), int(r["z"]))
                 for i, r in enumerate(_rows("splines.csv"), 1))


def spline_size(d_B: float, m: float) -> SplineSize | None:
    for s in spline_sizes():
        if abs(s.d_B - d_B) < 1e-9 and abs(s.m - m) < 1e-9:
            return s
    return None


@lru_cache(maxsize=None)
def iso286_rows() -> tuple[dict, ...]:
    out = []
    for i, r in enumerate(_rows("iso286.csv"), 1):
        out.append({"row": i, **{k: (float(v) if v != "" else None) for k, v in r.items()}})
    return tuple(out)
