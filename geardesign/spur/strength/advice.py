"""The advice of the strength checks, found by re-rating and shared by both methods:
:func:`least_passing` (the least face width or scale that passes), the face-width and
scale advice and their ``fix`` of the spec."""

from __future__ import annotations

import math

from geardesign.core.result import fix_text

PSI_BD_MAX = 1.6
"""Largest face width ratio b_w/d_w1 of design practice: the bound of the geometry check
``FACE_WIDTH_RATIO`` (:mod:`geardesign.spur.checks`) and of the face width advice."""

ADVICE_FACE_MAX = 20.0
"""Face widths up to this multiple of the given one are tried when the advice is sought."""
ADVICE_RTOL = 1e-6
"""Relative width of the bracket at which the search for the advice stops (each step
re-rates the pair; a failing design with a load spectrum takes seconds at 40 steps)."""


def least_passing(rerate, start: float, passes, limit: float = ADVICE_FACE_MAX
                  ) -> float | None:
    """The least value ``v >= start`` at which ``passes(rerate(v))`` holds, found by
    re-running the rating (the load factors change with the size, so a scaling law
    understates it): doubling up to ``limit``·start, then bisections until the bracket is
    within ``ADVICE_RTOL`` of the value (the advice prints 3 to 4 digits); ``None`` if no
    value in that range passes (also when ``limit`` <= 1: nothing above ``start`` may be
    tried)."""
    if limit <= 1.0:
        return None
    lo, hi = start, start
    while True:
        hi = min(2.0 * hi, limit * start)
        try:
            ok = passes(rerate(hi))
        except Exception:   # a size beyond what the geometry allows: stop looking
            return None
        if ok:
            break
        if hi >= limit * start:
            return None
        lo = hi
    while hi - lo > ADVICE_RTOL * hi:
        mid = 0.5 * (lo + hi)
        if passes(rerate(mid)):
            hi = mid
        else:
            lo = mid
    return hi


def face_advice_limit(b_w: float, d_w1: float) -> float:
    """The largest face width the advice may propose, as a multiple of the present ``b_w``:
    b_w/d_w1 <= :data:`PSI_BD_MAX` (the bound of the ``FACE_WIDTH_RATIO`` check, just above
    the ψ_bd ranges of the handbook table, [Ivanov] ch. 8: wider faces concentrate the
    load), and at most :data:`ADVICE_FACE_MAX`."""
    return min(ADVICE_FACE_MAX, PSI_BD_MAX * d_w1 / b_w)


def face_width_beyond(b_w: float, limit: float) -> str:
    """The advice when no face width up to ``limit``·``b_w`` passes."""
    if limit < ADVICE_FACE_MAX:
        return (f"no face width within b_w/d_w1 <= {PSI_BD_MAX} (up to "
                f"{max(limit, 1.0) * b_w:.1f} mm) passes")
    return f"no face width up to {ADVICE_FACE_MAX:g}× the present {b_w:g} mm passes " \
           f"(K_Hβ grows with it)"


def _face_advice(b_w: float | None, b_pass: float | None, limit: float = ADVICE_FACE_MAX
                 ) -> str:
    if b_w is None:
        return ""
    if b_pass is None:
        return "; " + face_width_beyond(b_w, limit)
    b = face_width_up(b_pass)
    return f"; or the face width to at least {b:g} mm (+{100 * (b / b_w - 1):.0f} %, " \
           f"found by re-rating: set {fix_text(face_width_fix(b_w, b_pass))})"


def face_width_up(b: float) -> float:
    """An advised face width as printed: rounded up to 0.1 mm, so that the value written
    into the spec is not below the one that passes."""
    return math.ceil(b * 10.0 - 1e-9) / 10.0


def reconciled_widths(b_contact: float | None, b_bending: float | None
                      ) -> tuple[float | None, float | None]:
    """One face width for contact and bending when both fail: the larger of the two least
    passing widths, advised to both checks (σ_H ∝ b^(-1/2) and σ_F ∝ 1/b fall as the face
    widens, so the wider passes both; each check advising its own width would leave the
    other failing).  A width that only one check found is left to it."""
    if b_contact is None or b_bending is None:
        return b_contact, b_bending
    b = max(b_contact, b_bending)
    return b, b


def face_width_fix(b_w: float | None, b_pass: float | None) -> tuple:
    """The face-width advice as a check's ``fix`` (``gear.face_width``), or none."""
    if b_w is None or b_pass is None:
        return ()
    return (("gear.face_width", face_width_up(b_pass)),)


def _scale_advice(a_w: float | None, k: float | None) -> str:
    """The centre distance that passes, the pair scaled (module and face width with it)."""
    if a_w is None or k is None:
        return ""
    return (f"increase the centre distance to at least {k * a_w:.1f} mm (+{100 * (k - 1):.0f} %, "
            f"module and face width in proportion, found by re-rating)")


def advised_percent(x: float) -> str:
    """An advised increase in per cent; beyond +300 % the design is far from passing."""
    return f"{100 * x:.0f} %" if x <= 3.0 else "more than 300 % (far from passing: check the " \
                                                 "inputs and their units)"
