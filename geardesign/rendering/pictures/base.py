"""What every picture module shares: :class:`Figure` and the lookup of a result's
section rows and tables."""

from __future__ import annotations

from geardesign.core.records import dataclass


@dataclass(frozen=True)
class Figure:
    caption: str
    svg: str          # an <svg> element


def rows(res, key: str) -> dict:
    for s in res.sections:
        if s.key == key:
            return {r.key: r for r in s.rows}
    return {}


def table(res, key: str):
    for t in res.tables:
        if t.key == key:
            return t
    return None


def value(row, unit):
    v = row.get(unit) if isinstance(row, dict) else None
    return v if isinstance(v, (int, float)) and not isinstance(v, bool) else None
