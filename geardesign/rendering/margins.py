"""The governing margins of a result: what the first screen of the report shows as bars.

A margin is a ratio that is 1 at the limit and above 1 on the safe side:

* a safety factor row (key ``S_…``) against its minimum: the limit of the check that
  judges that very value, else the row ``<key>_min`` or ``S_<x>min`` of its section;
  margin = S / S_min;
* every other error-severity check with a positive value and a positive limit: a check
  that requires ``value >= limit`` (a life, a contact ratio) gives value / limit, one that
  requires ``value <= limit`` (a stress against its allowable, a utilisation) gives
  limit / value.  Which of the two is read from the check itself: a passed check whose
  value is at least its limit, or a failed one whose value is below it, is of the first
  kind.  A failed check whose value is not below its limit failed for another reason
  (a contact ratio of teeth that interfere) and is listed with the failed checks only;
  a check whose margin equals that of a safety factor within 0.1 % (the stress against
  its allowable of GOST 21354, σ_H ≤ σ_HP, beside S_H ≥ S_Hmin) is not shown twice.

Margins are sorted worst first; each names its symbol, its section (the method and the
gear: "ISO 6336: pitting", "pinion") and the check that judges it.
"""

from __future__ import annotations

import math
import re

from geardesign.core.records import dataclass
from geardesign.core.result import Check, Result, Row


@dataclass(frozen=True)
class Margin:
    label: str          # the symbol (S_H1) or the check code
    name: str           # what it is (row name or check message)
    section: str        # section title (method and part), or "checks"
    value: float
    limit: float
    at_least: bool      # value must be >= limit (else <=)
    ratio: float        # >= 1 is safe
    code: str = ""      # the check judging it, if any
    passed: bool = True


def _finite_positive(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) \
        and x > 0


def _row_minimum(row: Row, rows: dict[str, Row]) -> float | None:
    for key in (f"{row.key}_min", re.sub(r"\d+$", "", row.key) + "min",
                re.sub(r"(\d+)$", r"min\1", row.key)):
        other = rows.get(key)
        if other is not None and other is not row and _finite_positive(other.value):
            return float(other.value)
    return None


def margins(res: Result) -> list[Margin]:
    """Every margin of ``res`` (not of its parts), worst first."""
    by_value: dict[float, Check] = {}
    for c in res.checks:
        if c.severity == "error" and _finite_positive(c.value) and _finite_positive(c.limit):
            by_value.setdefault(float(c.value), c)
    out: list[Margin] = []
    used: set[str] = set()
    for sec in res.sections:
        rows = {r.key: r for r in sec.rows}
        for row in sec.rows:
            if not row.key.startswith("S_") or "min" in row.key \
                    or not _finite_positive(row.value):
                continue
            c = by_value.get(float(row.value))
            limit = float(c.limit) if c is not None else _row_minimum(row, rows)
            if limit is None:
                continue
            if c is not None:
                used.add(c.code)
            passed = c.passed if c is not None else row.value >= limit
            out.append(Margin(row.symbol or row.key, row.name, sec.title, float(row.value),
                              limit, True, float(row.value) / limit,
                              c.code if c is not None else "", passed))
    for c in res.checks:
        if c.code in used or c.severity != "error" or not _finite_positive(c.value) \
                or not _finite_positive(c.limit):
            continue
        value, limit = float(c.value), float(c.limit)
        if not c.passed and value >= limit:   # failed for another reason (e.g. a contact
            continue                          # ratio of teeth that cannot mesh): listed only
        at_least = (value >= limit) == c.passed
        ratio = value / limit if at_least else limit / value
        if any(abs(m.ratio - ratio) <= 1e-3 * ratio and m.passed == c.passed for m in out):
            continue            # the stress check of a safety factor already shown
        out.append(Margin(c.code, c.message, "checks", value, limit, at_least, ratio,
                          c.code, c.passed))
    out.sort(key=lambda m: (m.ratio, m.label))
    return out
