"""Levers of the planetary strength advice (:mod:`geardesign.core.advice`): the contact and
bending checks of every mesh (``SUN_PLANET_CONTACT_FATIGUE``,
``PLANET_RING_BENDING_FATIGUE_PLANET``, ``…_ISO_PITTING_…``) fail on too small a train.
One change passes all failed mesh checks together, found by re-rating the whole train:

1. **the face width** ``train.face_width`` (and ``train.face_width2`` in proportion),
   from an estimate (σ_H ∝ b^(−1/2), σ_F ∝ 1/b: the face factor r² of the worst contact
   check and r of the worst bending check, r the stress over the allowable or the
   required safety over the present one) in steps of :data:`WIDTH_STEP`, up to
   b_w/d_1 = :data:`geardesign.spur.checks.PSI_BD_MAX` on the smaller gear of the
   sun–planet mesh (the window of the spur rating each mesh is rated by);
2. **the module** ``train.module``: the next modules of the first series of GOST 9563-60 /
   ISO 54 (:data:`geardesign.spur.strength.tables.MODULES_1`) with the teeth, the shifts
   and the cutter kept, the face width and a given centre distance scaled with the module
   (the train scaled alike: the ratio, the assembly condition (z_s + z_r)/n_w and the
   neighbour clearance, a share of the planet circle, do not change), then the same
   modules at the widest face.

A train with a second module (``train.module2``) is not scaled (two standard modules seldom
scale by one factor): its checks keep their words."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever, MAX_TRIES

MESHES = ("SUN_PLANET", "PLANET_RING", "PLANET2_RING", "PLANET_RING2", "PLANET2_RING2")
"""The meshes whose checks are named ``<MESH>_<check>`` (:mod:`geardesign.planetary.checks`)."""

CODES = tuple(f"{mesh}_{code}" for mesh in MESHES for code in (
    "CONTACT_FATIGUE", "BENDING_FATIGUE_PINION", "BENDING_FATIGUE_WHEEL",
    "BENDING_FATIGUE_SUN", "BENDING_FATIGUE_PLANET", "BENDING_FATIGUE_PLANET2",
    "BENDING_FATIGUE_RING", "BENDING_FATIGUE_RING2",
    "ISO_PITTING_PINION", "ISO_PITTING_WHEEL", "ISO_PITTING_SUN", "ISO_PITTING_PLANET",
    "ISO_PITTING_PLANET2", "ISO_PITTING_RING", "ISO_PITTING_RING2",
    "ISO_BENDING_PINION", "ISO_BENDING_WHEEL", "ISO_BENDING_SUN", "ISO_BENDING_PLANET",
    "ISO_BENDING_PLANET2", "ISO_BENDING_RING", "ISO_BENDING_RING2"))
"""The strength checks of every mesh that a wider face or a larger module makes pass."""

WIDTH_STEP = 0.05
"""Relative step of the face width above the estimate."""
MODULE_STEPS = 4
"""First-series modules tried above the present one."""


def _num(v) -> float | None:
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def _face_factor(res) -> float:
    """The face-width factor estimated from the failed strength checks (see the module)."""
    k = 1.0
    for c in res.failed:
        if c.code not in CODES or not c.value or not c.limit or c.value <= 0 or c.limit <= 0:
            continue
        r = max(c.value / c.limit, c.limit / c.value)
        k = max(k, r * r if ("CONTACT" in c.code or "PITTING" in c.code) else r)
    return k


def _train(data: dict):
    """(train table, m, b_w, d_1) of the spec, d_1 the smaller of sun and planet."""
    train, teeth = data.get("train"), data.get("teeth")
    if not isinstance(train, dict) or not isinstance(teeth, dict):
        return None
    m, b = _num(train.get("module")), _num(train.get("face_width"))
    z = [teeth.get(g) for g in ("sun", "planet")]
    if m is None or b is None or not all(isinstance(x, int) and x > 0 for x in z):
        return None
    beta = _num(train.get("helix_angle")) or 0.0
    return train, m, b, m * min(z) / math.cos(math.radians(beta))


def _with_face(train: dict, b: float, w: float) -> list:
    """``train.face_width = w`` and a given ``face_width2`` in proportion."""
    fix = [("train.face_width", w)]
    b2 = _num(train.get("face_width2"))
    if b2 is not None:
        fix.append(("train.face_width2", math.ceil(b2 * w / b * 10.0 - 1e-9) / 10.0))
    return fix


def _wider(data: dict, res):
    from geardesign.spur.checks import PSI_BD_MAX

    got = _train(data)
    if got is None:
        return
    train, _, b, d1 = got
    cap = math.floor(PSI_BD_MAX * d1 * 10.0) / 10.0
    x = max(b, 0.95 * _face_factor(res) * b)
    seen = set()
    for _ in range(MAX_TRIES):
        w = min(math.ceil(x * 10.0 - 1e-9) / 10.0, cap)
        if w > b and w not in seen:
            seen.add(w)
            yield tuple(_with_face(train, b, w))
        if w >= cap:
            return
        x *= 1.0 + WIDTH_STEP


def _modules(data: dict, _res):
    from geardesign.spur.checks import PSI_BD_MAX
    from geardesign.spur.strength.tables import MODULES_1

    got = _train(data)
    if got is None or _num(got[0].get("module2")) is not None:
        return
    train, m, b, d1 = got
    a = _num(train.get("center_distance"))
    modules = [x for x in MODULES_1 if x > m + 1e-9][:MODULE_STEPS]
    for wide in (False, True):
        for m2 in modules:
            k = m2 / m
            cap = math.floor(PSI_BD_MAX * d1 * k * 10.0) / 10.0
            w = cap if wide else min(math.ceil(b * k * 10.0 - 1e-9) / 10.0, cap)
            fix = [("train.module", float(m2))] + _with_face(train, b, w)
            if a is not None:
                fix.append(("train.center_distance", round(a * k, 2)))
            yield tuple(fix)


SUPERSEDED = (r"increase the centre distance (?:to at least|by) [0-9.]+ ?(?:%|mm)"
              r"(?: \([^()]*\))?",
              r"increase the module by [0-9.]+ ?% \(same centre distance, fewer teeth\)",
              r"(?:increase )?the face width by (?:more than )?[0-9.]+ ?%(?: \([^()]*\))*")
"""The clauses of the mesh checks' own words (the spur rating's) that the found change
replaces: the continuous scaling of one mesh, which in a train moves the shifts and the
assembly of the others."""

LEVERS = (Lever(CODES, _wider, "one face width for every mesh, within b_w/d_1 <= 1.6",
                supersedes=SUPERSEDED),
          Lever(CODES, _modules, "the train scaled to a first-series module, GOST 9563 / "
                "ISO 54: teeth, shifts and assembly kept", supersedes=SUPERSEDED))
