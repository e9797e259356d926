"""Levers of the rim advice (:mod:`geardesign.core.advice`): a rim short of its required
probability of non-failure, or whose equivalent amplitude exceeds its endurance limit, gets
hardened fillets (``fillet.hardening_factor``, from the present value, 1 without
hardening, in steps of 0.05 up to 2.5, the top of the range that induction hardening,
nitriding or roller burnishing give ([GOST25504] via [Gutyria2017], as the spec key
states)); each re-rated."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever

K_V_MAX = 2.5
"""The largest hardening factor advised."""


def _harder(data: dict, _res):
    fillet = data.get("fillet")
    if not isinstance(fillet, dict):
        return
    k = fillet.get("hardening_factor", 1.0)
    if not isinstance(k, (int, float)) or isinstance(k, bool):
        return
    n = math.floor(k * 20.0 + 1e-9) + 1
    while n / 20.0 <= K_V_MAX + 1e-9:
        yield (("fillet.hardening_factor", n / 20.0),)
        n += 1


LEVERS = (Lever(("PROBABILITY", "ENDURANCE_LIMIT"), _harder,
                "hardened fillets, the least hardening factor that passes"),)
