"""Levers of the Novikov advice (:mod:`geardesign.core.advice`): the contact and bending
stresses (``SIGMA_H``, ``SIGMA_F_PINION``, ``SIGMA_F_WHEEL``) fall as the face width, the
module or the hardness grows.  Candidates, each re-rated, the first at which every failed
stress check passes advised:

1. **the face width** ``gear.face_width``, from an estimate (σ_F ∝ 1/b_w, σ_H about
   ∝ b_w^(−0.9): more points of contact share the load) in steps of
   :data:`WIDTH_STEP`, up to b_w/d1 = :data:`geardesign.novikov.checks.FACE_RATIO_MAX`
   (the pair's practical proportion, the ``FACE_WIDTH_RATIO`` warning);
2. **the hardness** ``material.*.hardness``: pinion 350 HB (the method's scope, through-
   hardened run-in teeth) and the wheel :data:`HB_DIFFERENCE` softer, when the spec gives no
   endurance limits of its own;
3. **the module** ``gear.module``: the next modules of the first series of GOST 14186-69
   within the rack's module range (GOST 15023-76), the teeth, helix angle and b_w/d1 kept
   (the face width and a given centre distance scaled with the module), then the same
   modules with the face width at b_w/d1 = 1.5.

Beyond these (the largest module of the rack at the widest face) no fix: the message names
the torque and the accuracy grades."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever, MAX_TRIES

CODES = ("SIGMA_H", "SIGMA_F_PINION", "SIGMA_F_WHEEL")

WIDTH_STEP = 0.05
"""Relative step of the face width above the estimate."""
HB_MAX = 350.0
"""Hardness of the pinion advised [HB] (the method's upper scope, GOST 30224-96)."""
HB_DIFFERENCE = 20.0
"""Pinion − wheel hardness kept for run-in [HB] (the ``HARDNESS_DIFFERENCE`` warning)."""
MODULE_STEPS = 4
"""First-series modules tried above the present one."""


def _num(v) -> float | None:
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def _pinion_diameter(gear: dict, m: float) -> float | None:
    """d1 = m·z1/cos β [mm], β given or from the centre distance."""
    z1, z2 = gear.get("z1"), gear.get("z2")
    if not isinstance(z1, int) or not isinstance(z2, int):
        return None
    beta, a = _num(gear.get("helix_angle")), _num(gear.get("center_distance"))
    if beta is not None:
        cos_b = math.cos(math.radians(beta))
    elif a is not None:
        cos_b = m * (z1 + z2) / (2.0 * a)
    else:
        return None
    return m * z1 / cos_b if 0.0 < cos_b <= 1.0 else None


def _widths(b: float, d1: float, need: float):
    """Face widths from ``need``·b_w in steps of :data:`WIDTH_STEP`, up to 1.5·d1."""
    from geardesign.novikov.checks import FACE_RATIO_MAX

    cap = math.floor(FACE_RATIO_MAX * d1)
    x = max(b, 0.95 * need * b)
    seen = set()
    for _ in range(MAX_TRIES):
        w = min(math.ceil(x), cap)
        if w > b and w not in seen:
            seen.add(w)
            yield float(w)
        if w >= cap:
            return
        x *= 1.0 + WIDTH_STEP


def _need(res) -> float:
    """Face-width factor estimated from the failed stress checks (see the module)."""
    k = 1.0
    for c in res.failed:
        if c.code in CODES and c.value and c.limit:
            k = max(k, (c.value / c.limit) ** (1.0 / 0.9 if c.code == "SIGMA_H" else 1.0))
    return k


def _pair(data: dict):
    """(gear table, m, b_w, d1) of the spec, or ``None``."""
    gear = data.get("gear")
    if not isinstance(gear, dict):
        return None
    m, b = _num(gear.get("module")), _num(gear.get("face_width"))
    d1 = None if m is None else _pinion_diameter(gear, m)
    return None if m is None or b is None or d1 is None else (gear, m, b, d1)


def _wider(data: dict, res):
    pair = _pair(data)
    if pair is not None:
        for w in _widths(pair[2], pair[3], _need(res)):
            yield (("gear.face_width", w),)


def _harder(data: dict, _res):
    mat = data.get("material") or {}
    p, w_ = mat.get("pinion") or {}, mat.get("wheel") or {}
    own = any(k in g for g in (p, w_) for k in ("sigma_Hlim", "sigma_Flim"))
    HB1, HB2 = _num(p.get("hardness")), _num(w_.get("hardness"))
    if not own and HB1 is not None and HB2 is not None:
        fix = []
        if HB1 < HB_MAX:
            fix.append(("material.pinion.hardness", HB_MAX))
        if HB2 < HB_MAX - HB_DIFFERENCE:
            fix.append(("material.wheel.hardness", HB_MAX - HB_DIFFERENCE))
        if fix:
            yield tuple(fix)


def _modules(data: dict, _res):
    from geardesign.novikov.checks import FACE_RATIO_MAX
    from geardesign.novikov.rack import STANDARD, module_range, module_series

    pair = _pair(data)
    if pair is None:
        return
    gear, m, b, d1 = pair
    rack = (data.get("rack") or {}).get("name", STANDARD)
    hi = module_range(STANDARD)[1] if rack == STANDARD else math.inf
    modules = [x for x in module_series()[0] if m + 1e-9 < x <= hi][:MODULE_STEPS]
    a = _num(gear.get("center_distance"))
    for wide in (False, True):
        for m2 in modules:
            k = m2 / m
            cap = math.floor(FACE_RATIO_MAX * d1 * k)
            w = float(cap) if wide else min(math.ceil(b * k * 10.0 - 1e-9) / 10.0, cap)
            fix = [("gear.module", float(m2)), ("gear.face_width", w)]
            if a is not None:
                fix.append(("gear.center_distance", round(a * k, 2)))
            yield tuple(fix)


LEVERS = (Lever(CODES, _wider, "the face width, within b_w/d1 <= 1.5"),
          Lever(CODES, _harder, "harder through-hardened steel, within 350 HB"),
          Lever(CODES, _modules, "a first-series module of GOST 14186-69, the teeth and "
                "helix angle kept"))
