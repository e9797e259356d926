"""One change that passes every failed geometry check of a planetary train, found by
re-rating.

Each geometry check advises its own lever (``increase shift.planet`` against interference
at the planet root, ``reduce shift.planet`` against interference at the ring), and two of
them may pull one shift both ways.  A change of the planet teeth and the centre distance
moves every mesh together: with the sun and ring teeth kept (the ratio and the assembly
condition do not change), candidates z_p + Δz (Δz = 0, −1, +1, −2, +2) and a_w on a grid
of :data:`GRID_STEP`·m within ±:data:`GRID_SPAN`·m of the present centre distance are
tried, nearest first; the shifts follow from a_w by coaxiality
(:func:`geardesign.planetary.shifts.resolve_shifts`) and the geometry checks are
those of :func:`geardesign.planetary.report.geometry_checks`.  The first candidate at
which every failed geometry error check passes and no error check that passes fails is
then rated in full (strength and power included) and advised when that rating fails no
error check that passed; at most :data:`FULL_RERATINGS` full ratings are made.
"""

from __future__ import annotations

import copy
from contextvars import ContextVar

from geardesign.core.errors import InputError
from geardesign.core.result import Check, fix_text
from geardesign.core.spec import ValidatedSpec

DELTA_TEETH = (0, -1, 1, -2, 2)
"""Changes of the planet teeth tried, in this order."""
GRID_STEP = 0.05
"""Step of the centre-distance grid, × the module."""
GRID_SPAN = 1.5
"""Half width of the centre-distance grid, × the module."""
FULL_RERATINGS = 3
"""Candidates rated in full at most (each a complete planetary calculation)."""

_RERATING: ContextVar[bool] = ContextVar("planetary_rerating", default=False)


def _user_data(spec: ValidatedSpec) -> dict:
    """The spec as the user wrote it: the validated data without the assumed defaults."""
    data = copy.deepcopy(spec.data)
    for key in spec.assumed:
        parts = key.split(".")
        node = data
        for part in parts[:-1]:
            node = node.get(part) if isinstance(node, dict) else None
            if node is None:
                break
        if isinstance(node, dict):
            node.pop(parts[-1], None)
    return _given(data)


def _given(v):
    """``v`` without the keys left empty (``None``) by validation."""
    if isinstance(v, dict):
        return {k: _given(x) for k, x in v.items() if x is not None}
    if isinstance(v, list):
        return [_given(x) for x in v]
    return v


def _candidate_data(spec: ValidatedSpec, z_p: int, a_w: float) -> dict:
    """The validated data with teeth.planet = z_p and train.center_distance = a_w, the
    planet and ring shifts left to follow from a_w (a given sun shift is kept)."""
    d = copy.deepcopy(spec.data)
    d["teeth"]["planet"] = z_p
    d["train"]["center_distance"] = a_w
    for g in ("planet", "planet2", "ring", "ring2"):
        d["shift"][g] = None
    if "shift.sun" in spec.assumed:
        d["shift"]["sun"] = None
    return d


def _geometry(spec: ValidatedSpec, d: dict):
    """The geometry checks of the data ``d`` and the shifts (user's sign) it resolved to;
    ``None`` when the data are refused."""
    from geardesign.planetary import report as PR
    from geardesign.planetary import shifts as SH
    from geardesign.planetary import train as TR
    from geardesign.planetary.solve import members_gears

    vs = ValidatedSpec(d, [], spec.source, spec.base_dir)
    try:
        train, conv = TR.train_from_teeth(d)
        lay = TR._layout(d, train)
        TR._check_operation(train, d["operation"])
        shifts, _, _ = SH.resolve_shifts(d, vs, lay, conv)
        meshes = SH._geometry(lay, shifts, conv)
        from geardesign.planetary import CALCULATOR

        res = CALCULATOR.new_result(vs)
        checks = PR.geometry_checks(res, d, train, meshes, lay, shifts, conv,
                                    members_gears(meshes))
    except (InputError, ValueError, ZeroDivisionError, ArithmeticError):
        return None
    user = {g: (SH._gost_to_user(x, conv.get(g, 1)) if g.startswith("ring") else x)
            for g, x in shifts.items()}
    return checks, user


def _errors(checks: list[Check]) -> dict:
    return {c.code: c.passed for c in checks if c.severity == "error"}


def reconcile(spec: ValidatedSpec, meshes, checks: list[Check], rerate) -> list[Check]:
    """``checks`` with one change appended to every failed geometry error check when two or
    more fail (with it as their ``fix``), found by re-rating; unchanged otherwise.
    ``rerate(spec)``: the checks of a candidate spec, its typed inputs solved once
    (:func:`geardesign.planetary.calculator.rerate`)."""
    failed = [c for c in checks if c.severity == "error" and not c.passed]
    d = spec.data
    if (len(failed) < 2 or _RERATING.get() or d["train"]["working_angle"] is not None
            or d["teeth"]["planet"] is None):
        return checks
    found = _search(spec, meshes, checks, {c.code for c in failed}, rerate)
    fix, text = found if found is not None else (
        (), f"; no change of the planet teeth (±{max(DELTA_TEETH)}) and the centre distance "
            f"(±{GRID_SPAN:g}·m) passes the failed geometry checks together")
    ids = {id(c) for c in failed}
    return [(_with(c, text, fix) if id(c) in ids else c) for c in checks]


def _with(c: Check, text: str, fix: tuple) -> Check:
    from dataclasses import replace

    return replace(c, message=c.message + text, fix=fix)


def _search(spec: ValidatedSpec, meshes, checks: list[Check], todo: set, rerate):
    d = spec.data
    passing = {k for k, ok in _errors(checks).items() if ok}
    m = d["train"]["module"]
    a0 = meshes[0].geom.a_w
    z0 = d["teeth"]["planet"]
    steps = sorted(range(-round(GRID_SPAN / GRID_STEP), round(GRID_SPAN / GRID_STEP) + 1),
                   key=abs)
    given = (_user_data(spec).get("shift") or {})
    full = 0
    for dz in DELTA_TEETH:
        z_p = z0 + dz
        if z_p < 8:
            continue
        for j in steps:
            a_w = round(a0 + j * GRID_STEP * m, 2)
            got = _geometry(spec, _candidate_data(spec, z_p, a_w))
            if got is None:
                continue
            now = _errors(got[0])
            if not all(now.get(k, True) for k in todo | passing):
                continue
            fix = ([("teeth.planet", z_p)] if dz else []) + [("train.center_distance", a_w)]
            fix += [(f"shift.{g}", round(x, 4)) for g, x in got[1].items()
                    if given.get(g) is not None and g != "sun"]
            if full >= FULL_RERATINGS:
                return None
            full += 1
            if _passes_in_full(spec, z_p, a_w, fix, todo | passing, rerate):
                return tuple(fix), (f"; one change passes this and the other failed geometry "
                                    f"checks together (re-rated): set {fix_text(fix)}")
    return None


def _passes_in_full(spec: ValidatedSpec, z_p: int, a_w: float, fix: list, codes: set,
                    rerate) -> bool:
    """Whether the train changed by ``fix`` (teeth.planet = ``z_p``, the centre distance
    ``a_w`` and the shifts the user gave, as the advice prints them) fails none of the
    error checks ``codes``: its checks by ``rerate`` (typed inputs solved once, strength
    and power included)."""
    d = _candidate_data(spec, z_p, a_w)
    for key, value in fix:
        table, name = key.split(".")
        d[table][name] = value
    vs = ValidatedSpec(d, list(spec.assumed), spec.source, spec.base_dir)
    token = _RERATING.set(True)
    try:
        checks = rerate(vs)
    except (InputError, ValueError, ZeroDivisionError, ArithmeticError):
        return False
    finally:
        _RERATING.reset(token)
    now = _errors(checks)
    return all(now.get(k, True) for k in codes)
