"""Levers of the overload-clutch spring advice (:mod:`geardesign.core.advice`), each
re-rated, for spring ``n`` (keys ``spring[n-1].…``):

* ``SPRING_STRESS_n``: a thicker wire (``wire_diameter``), from the least the check names
  (d_min, rounded up to 0.1 mm) in 0.1 mm steps, with a given pitch grown by as much (the
  gap between the coils kept), and next to each wire the
  same with the stop angle set so that the torque limit lies between the working torque and
  the thicker wire's T_allow (the stiffer spring may reach its stop at a torque that
  overstresses it);
* ``COUPLING_SLIP_n`` (the stop is reached below the working torque): a larger
  ``stop_angle``, from φ = T/C_f (the check's T/T_lim times the present stop, rounded up to
  0.1°) in 0.1° steps; ``SPRING_STRESS_AT_LIMIT_n`` (the coils are overstressed at the stop):
  a smaller one, from T_allow/C_f down; the other of the two checks must keep passing, so
  a spring whose working torque overstresses it has no stop angle and is advised the wire
  (above, one change for both checks);
* ``COILS_TOUCH_n``: a larger ``pitch`` (the wound pitch p' grows with p: p·d/p', rounded
  up to 0.01 mm), up to a gap of one wire diameter (p = 2·d), beyond which the next lever
  lets the body lengthen (``ends_fixed_axially = false``);
* ``ARBOR_CLEARANCE_n``: a thinner arbor (``arbor_diameter``), the largest below the inner
  diameter at the full wind-up (0.1 mm);
* ``SPRING_INDEX_n``: the coil diameter (``coil_diameter``, mean or outer as given) moved to
  the nearest end of the index range D/d, 0.1 mm steps inwards."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever

MAX_SPRINGS = 8
"""Springs whose checks carry a fix."""

STEPS = 3
"""Candidates per lever beyond the first: each re-rating runs the whole spec (with a
start-up simulation about half a second), and the first candidates are the exact
solutions of linear laws (T_lim ∝ φ_stop, p' ∝ p, D/d)."""

MAX_GAP = 1.0
"""The largest gap between the coils advised, in wire diameters (p <= 2·d)."""


def _num(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def _spring(data: dict, n: int) -> dict | None:
    springs = data.get("spring") or []
    if n > len(springs) or not isinstance(springs[n - 1], dict):
        return None
    return springs[n - 1]


def _failed(res, code: str):
    return next((c for c in res.checks if c.code == code and not c.passed and c.value
                 and c.limit), None)


def _row(res, key: str, n: int):
    """The value of row ``key`` of spring n's section of the result."""
    sec = next((s for s in res.sections if s.key == f"spring{n}"), None)
    return None if sec is None else next((r.value for r in sec.rows if r.key == key), None)


def _steps(key: str, first: float, step: float, digits: int, up: bool):
    for i in range(STEPS + 1):
        x = round(first + (i if up else -i) * step, digits)
        if x > 0:
            yield ((key, x),)


def _thicker(n: int):
    def gen(data: dict, res):
        sp, c = _spring(data, n), _failed(res, f"SPRING_STRESS_{n}")
        d = None if sp is None else sp.get("wire_diameter")
        d_min = _row(res, "d_min", n)
        if c is None or not _num(d):
            return
        # the least wire the calculator names (σ ∝ k/d³ at the torque), else σ ∝ 1/d³
        first = d_min if _num(d_min) and d_min > d else max(
            d * (c.value / c.limit) ** (1.0 / 3.0), d)
        key = f"spring[{n - 1}]."
        for (_, d2), in _steps(key + "wire_diameter", (int(first * 10.0 - 1e-9) + 1) / 10.0,
                               0.1, 1, True):
            fix = [(key + "wire_diameter", d2)]
            if _num(sp.get("pitch")):          # the gap between the coils kept
                fix.append((key + "pitch", round(sp["pitch"] + d2 - d, 2)))
            yield tuple(fix)
            stop = _stop_for(sp, res, n, d2 / d)
            if stop is not None:
                yield tuple(fix) + ((key + "stop_angle", stop),)
    return gen


def _stop_for(sp: dict, res, n: int, k: float) -> float | None:
    """The stop angle of a wire k times as thick: the torque limit kept where it lies
    between the working torque and the new T_allow (∝ d³), else midway between them; the
    stiffness at the finger grows as d⁴ (J = π·d⁴/64)."""
    phi, T, T_lim, T_allow = (sp.get("stop_angle"), _row(res, "T", n), _row(res, "T_limit", n),
                              _row(res, "T_allow", n))
    if not all(_num(x) and x > 0 for x in (phi, T, T_lim, T_allow)):
        return None
    top = T_allow * k ** 3
    target = T_lim if T <= T_lim <= top else 0.5 * (T + top)
    return round(phi * target / T_lim / k ** 4, 1)


def _stop(n: int, code: str, up: bool):
    """Stop angles from the present one times the check's limit/value (see the module),
    within the range in which the torque limit carries the working torque and keeps the
    coils within [σ] (none when the working torque overstresses them)."""
    def gen(data: dict, res):
        sp, c = _spring(data, n), _failed(res, code)
        phi = None if sp is None else sp.get("stop_angle")
        T, T_lim, T_allow = _row(res, "T", n), _row(res, "T_limit", n), _row(res, "T_allow", n)
        if c is None or not all(_num(x) and x > 0 for x in (phi, T, T_lim, T_allow)):
            return
        lo, hi = phi * T / T_lim, phi * T_allow / T_lim
        x = phi * c.limit / c.value * 10.0
        first = (math.ceil(x - 1e-9) if up else math.floor(x + 1e-9)) / 10.0
        for fix in _steps(f"spring[{n - 1}].stop_angle", first, 0.1, 1, up):
            if not lo - 1e-9 <= fix[0][1] <= hi + 1e-9:
                return
            yield fix
    return gen


def _pitch(n: int):
    def gen(data: dict, res):
        sp, c = _spring(data, n), _failed(res, f"COILS_TOUCH_{n}")
        p, d = _row(res, "p", n), _row(res, "d", n)
        if sp is None or c is None or not _num(p) or not _num(d):
            return
        first = math.ceil(p * c.limit / c.value * 100.0 - 1e-9) / 100.0
        for (key, x), in _steps(f"spring[{n - 1}].pitch", first, 0.01, 2, True):
            if x > (1.0 + MAX_GAP) * d + 1e-9:
                return
            yield ((key, x),)
    return gen


def _free_body(n: int):
    def gen(data: dict, _res):
        if _spring(data, n) is not None:
            yield ((f"spring[{n - 1}].ends_fixed_axially", False),)
    return gen


def _arbor(n: int):
    def gen(data: dict, res):
        sp, c = _spring(data, n), _failed(res, f"ARBOR_CLEARANCE_{n}")
        if sp is None or c is None:
            return
        first = (math.ceil(c.value * 10.0 - 1e-9) - 1) / 10.0
        yield from _steps(f"spring[{n - 1}].arbor_diameter", first, 0.1, 1, False)
    return gen


def _coil(n: int):
    def gen(data: dict, res):
        sp, c = _spring(data, n), _failed(res, f"SPRING_INDEX_{n}")
        D, d = (None, None) if sp is None else (sp.get("coil_diameter"), _row(res, "d", n))
        if c is None or not _num(D) or not _num(d):
            return
        up = c.value < c.limit           # the index is too small: a larger coil
        x = (D + (c.limit - c.value) * d) * 10.0
        first = (math.ceil(x - 1e-9) if up else math.floor(x + 1e-9)) / 10.0
        yield from _steps(f"spring[{n - 1}].coil_diameter", first, 0.1, 1, up)
    return gen


def _levers(n: int) -> tuple:
    return (
        Lever((f"COUPLING_SLIP_{n}",), _stop(n, f"COUPLING_SLIP_{n}", True),
              "the least stop angle that carries the working torque"),
        Lever((f"SPRING_STRESS_AT_LIMIT_{n}",), _stop(n, f"SPRING_STRESS_AT_LIMIT_{n}", False),
              "the largest stop angle at which the coils stay within [σ]"),
        Lever((f"SPRING_STRESS_{n}", f"COUPLING_SLIP_{n}"), _thicker(n),
              "a thicker wire, the stop angle set between the working torque and T_allow"),
        Lever((f"COILS_TOUCH_{n}",), _pitch(n), "the least pitch at which the coils stay "
              "clear, within a gap of one wire diameter"),
        Lever((f"COILS_TOUCH_{n}",), _free_body(n), "the body free to lengthen (no pitch "
              "within a gap of one wire diameter keeps the coils clear)"),
        Lever((f"ARBOR_CLEARANCE_{n}",), _arbor(n), "the largest arbor that clears the "
              "wound-up coils"),
        Lever((f"SPRING_INDEX_{n}",), _coil(n), "the coil diameter at the nearest end of the "
              "index range"),
    )


def _coupling_gear(data: dict, res):
    """The fixes of the coupling gear's own failed checks (its nested spur report), at the
    pzdn's keys: ``gear.face_width`` -> ``coupling_gear.face_width`` (and the module, the
    shifts: the fields of ``[coupling_gear]``); merged into one change, then each alone."""
    from geardesign.pzdn.spec import COUPLING_GEAR

    if not isinstance(data.get("coupling_gear"), dict):
        return
    names = {f.key for f in COUPLING_GEAR.fields}
    spur = next((r for key, _, r in res.parts if key == "coupling_gear_rating"), None)
    fixes = []
    for c in () if spur is None else spur.failed:
        fix = tuple((f"coupling_gear.{k[5:]}", v) for k, v in c.fix)
        if not c.fix or not all(k.startswith("gear.") and k[5:] in names for k, _ in c.fix):
            return                       # a failed check that the pzdn's keys cannot pass
        if fix not in fixes:
            fixes.append(fix)
    merged: dict = {}
    for fix in fixes:
        for k, v in fix:
            merged.setdefault(k, v)
    if len(fixes) > 1 and all(merged[k] == v for fix in fixes for k, v in fix):
        yield tuple(merged.items())
    yield from fixes


LEVERS = tuple(lever for n in range(1, MAX_SPRINGS + 1) for lever in _levers(n)) + (
    Lever(("COUPLING_GEAR",), _coupling_gear, "the change the coupling gear's own report "
          "advises, at the [coupling_gear] keys"),)
