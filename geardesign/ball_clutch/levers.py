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
higher allowable stress at this wire, the least first)."""

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


def _thicker_wire(data: dict, res):
    """A thicker wire of the same rate (see the module)."""
    from geardesign.ball_clutch.calculator import INDEX_RANGE
    from geardesign.ball_clutch.spring import solid_length

    sp = data.get("spring")
    c = next((c for c in res.checks if c.code == "SPRING_STRESS" and not c.passed), None)
    if not isinstance(sp, dict) or c is None or not c.value or not c.limit:
        return
    d, D, n_a = sp.get("wire_diameter"), sp.get("coil_diameter"), sp.get("active_coils")
    if not (_num(d) and _num(D) and _num(n_a)):
        return
    ends = sp.get("ends", "closed_ground")
    L0 = sp.get("free_length")
    first = math.ceil(d * (c.value / c.limit) ** (1.0 / 3.0) * 10.0 - 1e-9) / 10.0
    start = max(first - 0.1, math.floor(d * 10.0 + 1e-9) / 10.0 + 0.1)
    for i in range(MAX_WIRES):
        d2 = round(start + 0.1 * i, 1)
        if D / d2 < INDEX_RANGE[0]:
            return
        n2 = math.ceil(n_a * (d2 / d) ** 4 * 2.0 - 1e-9) / 2.0
        fix = [("spring.wire_diameter", d2), ("spring.active_coils", n2)]
        if _num(L0):
            rise = solid_length(n2, d2, ends) - solid_length(n_a, d, ends)
            fix.append(("spring.free_length", math.ceil((L0 + max(rise, 0.0)) * 10.0 - 1e-9)
                        / 10.0))
        yield tuple(fix)


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
    Lever(("SPRING_SOLID",), scaled("spring.free_length", [1.0 + 0.02 * i for i in range(1, 26)],
                                    1), "a longer free length"),
    Lever(("BALL_CONTACT",), _more_balls, "more balls on the same circle"),
)
