"""Advice for a worm pair that fails its strength, stiffness or thermal checks, found by
re-rating: the smallest standard pair that passes all of them.

A larger centre distance alone is no remedy for a given module and diameter factor: the
wheel shift x = a_w/m − 0.5 (q + z2) soon leaves ±1 (GOST 19650-97) and the spec is
refused.  The advice therefore changes the centre distance, the module and the diameter
factor together, as design mode does: the GOST 2144-76 centre distances (both rows) from
the present one upward, and at each the standard (m, q) pairs of GOST 19672-74 in the order
of :func:`geardesign.worm.design.ranked_pairs`.  Each candidate is analysed by
:func:`geardesign.worm.pair.analyse` and checked by
:func:`geardesign.worm.checks.pair_checks`; the first one at which every failed check of
:data:`RERATED` passes, and no error check that passed fails, is advised as spec keys
(``Check.fix``).  The search is bounded: at most :data:`PAIRS_PER_DISTANCE` pairs at each
of the (about 30) standard centre distances.
"""

from __future__ import annotations

import dataclasses
import math

from geardesign.core.result import Check, fix_text
from geardesign.worm.checks import Advice, pair_checks
from geardesign.worm import design as D
from geardesign.worm.geometry import WormGeometryError, pair_geometry
from geardesign.worm.pair import Analysis, Operation, Options, WheelProps, analyse

RERATED = ("CONTACT_STRESS", "CONTACT_STRESS_PEAK", "BENDING_STRESS", "BENDING_STRESS_PEAK",
           "WORM_DEFLECTION", "OIL_TEMPERATURE", "UNDERCUT_WHEEL", "CONTACT_RATIO")
"""Error checks that a larger standard pair can make pass."""

PAIRS_PER_DISTANCE = 6
"""Standard (m, q) pairs tried at each centre distance, best ranked first."""


def failing(checks: list[Check]) -> set[str]:
    """The codes of the failed error checks of :data:`RERATED`."""
    return {c.code for c in checks
            if c.severity == "error" and not c.passed and c.code in RERATED}


def _candidate(a: Analysis, prop: D.Proposal):
    """The pair input of ``a`` with the standard (m, q, x) of ``prop``: a given face width
    scales with the module (within the largest allowed), a given worm length is lengthened
    to the least required."""
    p = a.g.inp
    bare = dataclasses.replace(p, m=prop.m, q=prop.q, x=prop.x, b2=None, b1=None)
    g0 = pair_geometry(bare)
    b2 = None if p.b2 is None else min(float(round(p.b2 * prop.m / p.m)),
                                       math.floor(g0.b2_max))
    b1 = None if p.b1 is None else max(p.b1, float(math.ceil(g0.b1_min)))
    return dataclasses.replace(bare, b2=b2, b1=b1)


def _candidates(a: Analysis, op: Operation, w: WheelProps, o: Options, self_locking: str):
    """``(a_w, proposal, pair input, {check code: passed})`` of the standard pairs in the
    order of the search (at most :data:`PAIRS_PER_DISTANCE` at each centre distance)."""
    p = a.g.inp
    for a_w in D.standard_center_distances(a.g.a_w):
        for prop in D.ranked_pairs(a_w, p.z2, p.q, False)[:PAIRS_PER_DISTANCE]:
            try:
                pc = _candidate(a, prop)
                ac = analyse(pair_geometry(pc), op, w, o)
            except (WormGeometryError, ValueError, ZeroDivisionError):
                continue
            yield a_w, prop, pc, {c.code: c.passed for c in pair_checks(ac, w, o, self_locking)}


def standard_pair_advice(a: Analysis, checks: list[Check], op: Operation, w: WheelProps,
                         o: Options, self_locking: str, x_given: bool) -> Advice | None:
    """The smallest standard pair that passes every failed check of :data:`RERATED` of
    ``checks`` (the checks of ``a``) without failing an error check that passes now;
    ``None`` when none of them fails.  ``x_given``: the spec gave gear.x (the fix then
    gives it too, agreeing with the centre distance)."""
    todo = failing(checks)
    if not todo:
        return None
    passing = {c.code for c in checks if c.severity == "error" and c.passed}
    quiet = {c.code for c in checks if c.severity == "warning" and c.passed}
    p = a.g.inp
    found = None
    for a_w, prop, pc, now in _candidates(a, op, w, o, self_locking):
        if not all(now.get(k, True) for k in todo | passing):
            continue
        clean = all(now.get(k, True) for k in quiet)
        if found is None or clean:
            found = (a_w, prop, pc)
        if clean:
            break
    if found is not None:
        a_w, prop, pc = found
        fix = [("gear.center_distance", float(a_w)), ("gear.module", float(prop.m)),
               ("gear.diameter_factor", float(prop.q))]
        if x_given:
            fix.append(("gear.x", round(prop.x, 4)))
        if pc.b2 is not None and pc.b2 != p.b2:
            fix.append(("gear.face_width", pc.b2))
        if pc.b1 is not None and pc.b1 != p.b1:
            fix.append(("gear.worm_length", pc.b1))
        shift = "" if x_given else f", x = {_fmt(prop.x)}"
        return Advice(tuple(fix), f"set {fix_text(fix)} (a standard pair{shift}; it "
                      f"passes when re-rated)")
    return Advice(None, f" (no standard pair up to a_w = {_fmt(max(D.standard_center_distances(0)))}"
                        f" mm passes when re-rated)")


def _fmt(v: float) -> str:
    return f"{v:.4f}".rstrip("0").rstrip(".")
