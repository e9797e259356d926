"""The advice of a failed safety check of the shaft: the least scale of every step's
diameter (and bore, fillet radius and notch sizes) that makes the shaft pass, found by
analysing the scaled shaft again (:func:`geardesign.shaft.solve.analyse`)."""

from __future__ import annotations

import math
from dataclasses import replace

from geardesign.core.errors import InputError
from geardesign.core.spec import ValidatedSpec
from geardesign.shaft.material_inputs import material
from geardesign.shaft.records import Inputs
from geardesign.shaft.solve import analyse

MAX_SCALE = 3.0      # the largest scale of the diameters the advice looks at


def scaled_steps(steps: list, k: float) -> list:
    """The steps with every diameter, bore and fillet radius times ``k`` (lengths kept)."""
    def times(v):
        return None if v is None else v * k

    return [replace(s, diameter=s.diameter * k, bore=s.bore * k, fillet=s.fillet * k,
                    groove_depth=times(s.groove_depth), groove_radius=times(s.groove_radius),
                    groove_width=times(s.groove_width), cross_bore=times(s.cross_bore))
            for s in steps]


def scale_to_pass(spec: ValidatedSpec, m: Inputs, which: str, S_req: float) -> float | None:
    """The least factor k (rounded up to 0.01) by which every step's diameter, bore and
    fillet radius must grow for the shaft's lowest safety ``which`` ("S": fatigue,
    "S_static": static) to reach ``S_req``, found by analysing the scaled shaft again (its
    size, notch and, by DIN 743, material factors change with the diameters; the bending
    moments of a shaft on more than two supports too).  None when k = ``MAX_SCALE`` does not
    reach it.  The nominal stresses fall as 1/k³, so k = (S_req/S)^(1/3) is the first
    guess; the guess is repeated from the safety it reaches (at most 12 analyses, and 5 to
    check the rounding)."""
    steps, loads, supports, opt = m.steps, list(m.loads), list(m.supports), m.options
    d_max = max(st.diameter for st in steps)

    def lowest(k: float) -> float:
        try:
            mat = material(spec.data["material"], opt.method, d_max * k)[0] \
                if opt.method == "DIN743" else m.material
            r = analyse(scaled_steps(steps, k), loads, supports, mat, opt)
        except InputError:
            return 0.0
        worst = r.critical if which == "S" else r.critical_static
        if worst is None:
            return math.inf
        return worst.S if which == "S" else worst.S_static

    k, S = 1.0, lowest(1.0)
    for _ in range(12):
        if S >= S_req:
            break
        step = (S_req / S) ** (1.0 / 3.0) if S > 0 else 1.25
        k = min(MAX_SCALE, k * max(step, 1.01))
        S = lowest(k)
        if S < S_req and k >= MAX_SCALE:
            return None
    else:
        return None
    k_up = math.ceil(k * 100.0 - 1e-9) / 100.0
    for _ in range(5):                   # rounding up keeps it passing; make sure
        if k_up > MAX_SCALE:
            return None
        if lowest(k_up) >= S_req:
            break
        k_up += 0.01
    return k_up
