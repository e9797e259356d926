"""The checks of any rating record, one entry for both methods: :func:`rating_checks`
judges a GOST 21354-87 rating (:mod:`.gost21354.checks`) or an ISO 6336 rating
(:mod:`.iso6336.checks`) by the one :func:`geardesign.spur.strength.verdict.verdict`, with
the advice found by re-rating (:mod:`.advice`); and the light-load check of a load typed
in the wrong unit, for the values of either method.
"""

from __future__ import annotations

import math

from geardesign.core.result import Check
from geardesign.spur.strength.advice import (  # noqa: F401  (the advice's names, as before)
    ADVICE_FACE_MAX, ADVICE_RTOL, PSI_BD_MAX, advised_percent, face_advice_limit,
    face_width_beyond, face_width_fix, face_width_up, least_passing, reconciled_widths)
from geardesign.spur.strength.gost21354.checks import (  # noqa: F401
    HB_DIFFERENCE_MIN, strength_checks)
from geardesign.spur.strength.iso6336 import checks as iso_checks
from geardesign.spur.strength.verdict import GOST, verdict

WHO = ("pinion", "wheel")


def rating_checks(rating, members: tuple[str, str] = WHO, found: dict | None = None,
                  internal: bool = False, peak_key: str = "load.peak_torque1"
                  ) -> list[Check]:
    """The checks of a rating record of either method (a :class:`GostRating` or an
    :class:`IsoRating`): contact and bending fatigue per gear, the static checks at the
    peak torque, and the method's notes on its inputs; judged by
    :func:`geardesign.spur.strength.verdict.verdict`.

    ``members`` name gear 1 and gear 2 in the messages and the codes (a planetary mesh:
    ``("sun", "planet")``); ``found`` carries the advice found by re-rating (``{"b": (b_w,
    b_contact, b_bending), "k": (a_w, k_contact, k_bending), "face_limit": the largest
    face width tried as a multiple of b_w}``); ``internal``: the pair is internal (ISO
    6336: the note on the internal gear's form factors); ``peak_key``: the spec key of the
    peak torque (GOST 21354-87: named when no peak torque was rated)."""
    if verdict(rating).method == GOST:
        return strength_checks(rating, members, found, peak_key)
    return iso_checks.rating_checks(rating, internal, members, found)


LOAD_INPUTS = {"torque1": "N·m", "power": "kW"}
"""The load inputs of a spur spec's [load] table and their fixed units."""


def contact_load_fraction(v: dict) -> tuple[float, str]:
    """The fraction of its contact capacity a rated pair carries, and how it was found.

    .. math:: \\text{fraction} = (σ_{H0}/σ_{Hlim})^2

    σ_H0 [MPa]: the nominal contact stress without load factors (ISO 6336-2 eq. (2) as
    rated; GOST 21354-87: σ_H/√K_H, σ_H ∝ √(F_t K_H)), σ_Hlim [MPa]: the weaker gear's
    endurance limit. σ_H ∝ √F_t, so the square is a load ratio. ``v`` is the value record of
    either method's rating.  Source: [ISO6336-2] eq. (2), [GOST21354]."""
    sH0 = v["sigma_H0"] if "sigma_H0" in v else v["sigma_H"] / math.sqrt(v["K_H"])
    lim = min(v["sigma_Hlim1"], v["sigma_Hlim2"])
    K_v = v.get("K_v", v.get("K_Hv", 1.0))
    fraction = (sH0 / lim) ** 2
    what = (f"the pair carries {100 * fraction:.2g} % of its contact capacity (nominal σ_H0 = "
            f"{sH0:.3g} MPa against σ_Hlim = {lim:.0f} MPa)")
    if K_v > 2.0:
        what += (f"; the dynamic factor {'K_v' if 'K_v' in v else 'K_Hv'} = {K_v:.4g} "
                 f"comes from this light load, far above the 1…2 the method is made for")
    return fraction, what


def light_load_checks(v: dict, inputs: list, code: str = "UNITS_LOAD") -> list[Check]:
    """``UNITS_LOAD`` when a rated pair carries less than 1 % of its contact capacity
    (:func:`geardesign.core.units_guard.light_load`); ``inputs`` from
    :func:`geardesign.core.units_guard.given`."""
    from geardesign.core.units_guard import light_load

    fraction, what = contact_load_fraction(v)
    return light_load(code, fraction, what, inputs, "[ISO6336-1] 6.5.3, 9.3.1 eq. (84)")
