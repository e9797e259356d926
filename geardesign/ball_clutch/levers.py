"""Levers of the ball-clutch advice (:mod:`geardesign.core.advice`), each re-rated: a
socket that self-locks gets the largest angle below the locking one
(``safety.socket_angle``, 0.1° steps); a clutch that trips at the rated torque or releases
by speed gets a larger spring preload (``spring.preload``, 5 % steps up to three times);
a spring that goes solid a longer free length (``spring.free_length``, 2 % steps); an
overloaded ball contact more balls (``safety.balls``, one at a time up to twice).

An overstressed spring (``SPRING_STRESS``, τ = K_W·8·F·D/(π·d³)) gets a thicker wire of the
same rate: ``spring.wire_diameter`` in 0.1 mm steps from one below the least that the
stress estimates (τ ∝ K_W/d³ at the same force and coil), the active coils
``spring.active_coils`` = n_a·(d'/d)⁴ rounded up to half a coil (c = G·d⁴/(8·D³·n_a), so
the preload force and the limit torque stay), and a given free length grown by the rise of
the solid length (``spring.free_length``), so that the spring does not go solid; down to
the spring index D/d = 4, below which a spring is hard to coil (``SPRING_INDEX``).  Beyond
it the next lever is a stronger wire (``spring.material``: the grades of the table with a
higher allowable stress at this wire, the least first).

A clutch that trips at the rated torque or releases by speed, whose larger preload alone
overstresses the spring, gets the preload with a thicker wire of the same rate together
(:func:`_preload_and_wire`): the preload factor from the limit band (T_lim,min grows with
F_pre − F_c), the wire from the stress at the new lifted force (τ ∝ c·(y0 + h_s)/d³), the
coils for the same rate and the free length grown by the rise of the solid length and of
the preload, so that the spring does not go solid."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever, scaled, to_limit

MAX_WIRES = 12
"""Wire diameters tried above the estimate."""


def _more_balls(data: dict, _res):
    z = (data.get("safety") or {}).get("balls")
    if isinstance(z, int) and not isinstance(z, bool):
        for n in range(z + 1, 2 * z + 1):
            yield (("safety.balls", n),)


def _num(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def _row(res, section: str, key: str):
    sec = next((s for s in res.sections if s.key == section), None)
    return None if sec is None else next((r.value for r in sec.rows if r.key == key), None)


def _same_rate(sp: dict, d2: float, dy: float = 0.0) -> list:
    """Wire ``d2`` with the active coils for the same rate (half coils, up) and a given
    free length grown by the rise of the solid length and ``dy`` (a larger preload)."""
    from geardesign.ball_clutch.spring import solid_length

    d, n_a, ends = sp["wire_diameter"], sp["active_coils"], sp.get("ends", "closed_ground")
    n2 = math.ceil(n_a * (d2 / d) ** 4 * 2.0 - 1e-9) / 2.0
    fix = [("spring.wire_diameter", d2), ("spring.active_coils", n2)]
    L0 = sp.get("free_length")
    if _num(L0):
        rise = max(solid_length(n2, d2, ends) - solid_length(n_a, d, ends), 0.0) + dy
        fix.append(("spring.free_length", math.ceil((L0 + rise) * 10.0 - 1e-9) / 10.0))
    return fix


def _preload_and_wire(data: dict, res):
    """A larger preload with a thicker wire of the same rate (see the module)."""
    from geardesign.ball_clutch.calculator import INDEX_RANGE

    sp, sa = data.get("spring"), data.get("safety")
    if not isinstance(sp, dict) or not isinstance(sa, dict):
        return
    d, D, n_a, y0 = (sp.get(k) for k in ("wire_diameter", "coil_diameter", "active_coils",
                                           "preload"))
    h_s = sa.get("socket_depth")
    F_pre, F_c = _row(res, "safety", "F_pre"), _row(res, "safety", "F_c")
    tau, tau_adm = _row(res, "spring", "tau_max"), _row(res, "spring", "tau_adm")
    if not all(_num(x) and x > 0 for x in (d, D, n_a, y0, h_s, F_pre, tau, tau_adm)) \
            or not _num(F_c):
        return
    f0 = 1.0
    for c in res.failed:
        if c.code == "LIMIT_ABOVE_RATED" and c.value and c.value > 0 and F_pre > F_c:
            f0 = max(f0, (F_c + (F_pre - F_c) * c.limit / c.value) / F_pre)
        elif c.code == "CENTRIFUGAL_RELEASE":
            f0 = max(f0, 1.05 * F_c / F_pre)
    first = math.ceil(f0 * 20.0 - 1e-9) / 20.0
    for i in range(6):
        y2 = round(y0 * (first + 0.05 * i), 2)
        lifted = tau * (y2 + h_s) / (y0 + h_s)
        d2 = max(math.ceil(d * (lifted / tau_adm) ** (1.0 / 3.0) * 10.0 - 1e-9) / 10.0, d)
        if D / d2 < INDEX_RANGE[0]:
            return
        yield tuple([("spring.preload", y2)] + _same_rate(sp, d2, y2 - y0))


def _thicker_wire(data: dict, res):
    """A thicker wire of the same rate (see the module)."""
    from geardesign.ball_clutch.calculator import INDEX_RANGE

    sp = data.get("spring")
    c = next((c for c in res.checks if c.code == "SPRING_STRESS" and not c.passed), None)
    if not isinstance(sp, dict) or c is None or not c.value or not c.limit:
        return
    d, D, n_a = sp.get("wire_diameter"), sp.get("coil_diameter"), sp.get("active_coils")
    if not (_num(d) and _num(D) and _num(n_a)):
        return
    first = math.ceil(d * (c.value / c.limit) ** (1.0 / 3.0) * 10.0 - 1e-9) / 10.0
    start = max(first - 0.1, math.floor(d * 10.0 + 1e-9) / 10.0 + 0.1)
    for i in range(MAX_WIRES):
        d2 = round(start + 0.1 * i, 1)
        if D / d2 < INDEX_RANGE[0]:
            return
        yield tuple(_same_rate(sp, d2))


def _stronger_wire(data: dict, res):
    """The grades of the table with a higher allowable shear stress at this wire."""
    from geardesign.materials import spring_steel

    sp = data.get("spring")
    if not isinstance(sp, dict) or not isinstance(sp.get("material"), str) or any(
            sp.get(k) is not None for k in ("tensile_strength", "allowable_share",
                                            "shear_modulus")):
        return
    d = sp.get("wire_diameter")
    if not _num(d) or sp["material"] not in spring_steel.names():
        return
    now = spring_steel.get(sp["material"]).allowable_shear(d)
    better = sorted((m.allowable_shear(d), m.key) for m in spring_steel.table().values()
                    if m.covers(d) and m.allowable_shear(d) > now)
    for _, key in better:
        yield (("spring.material", key),)


LEVERS = (
    Lever(("SPRING_STRESS",), _thicker_wire, "a thicker wire of the same rate, down to the "
          "spring index D/d = 4"),
    Lever(("SPRING_STRESS",), _stronger_wire, "a stronger wire, the least that passes"),
    Lever(("SELF_LOCKING",), to_limit("SELF_LOCKING", "safety.socket_angle", up=False),
          "the largest socket angle that does not self-lock"),
    Lever(("LIMIT_ABOVE_RATED", "CENTRIFUGAL_RELEASE"),
          scaled("spring.preload", [1.0 + 0.05 * i for i in range(1, 41)], 2),
          "a larger spring preload"),
    Lever(("LIMIT_ABOVE_RATED", "CENTRIFUGAL_RELEASE"), _preload_and_wire,
          "a larger spring preload with a thicker wire of the same rate"),
    Lever(("SPRING_SOLID",), scaled("spring.free_length", [1.0 + 0.02 * i for i in range(1, 26)],
                                    1), "a longer free length"),
    Lever(("BALL_CONTACT",), _more_balls, "more balls on the same circle"),
)
