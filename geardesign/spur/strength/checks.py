"""The strength checks of a spur pair and their advice: the GOST 21354-87 rating's checks
(:func:`strength_checks`: contact, bending, peak loads, judged by the one
:func:`geardesign.spur.strength.verdict.verdict` of both methods), the advice by
re-rating shared by both methods (:func:`least_passing`, the face width and scale
advice) and the light-load check of a load typed in the wrong unit.  The ISO 6336
rating's checks are :mod:`.iso6336.checks`, built on the same advice.
"""

from __future__ import annotations

import math

from geardesign.core.result import Check, check, fix_text

WHO = ("pinion", "wheel")
PSI_BD_MAX = 1.6
"""Largest face width ratio b_w/d_w1 of design practice: the bound of the geometry check
``FACE_WIDTH_RATIO`` (:mod:`geardesign.spur.checks`) and of the face width advice."""

HB_DIFFERENCE_MIN = 20.0   # HB, pinion harder than the wheel for running-in (soft pairs)


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


def strength_checks(v: dict, mats, helical: bool, grade: int, peak_given: bool,
                    b_w: float | None = None, b_contact: float | None = None,
                    b_bending: float | None = None, a_w: float | None = None,
                    k_contact: float | None = None, face_limit: float = ADVICE_FACE_MAX,
                    members: tuple[str, str] = WHO, peak_key: str = "load.peak_torque1"
                    ) -> list[Check]:
    """Checks of a GOST 21354-87 rating ``v`` (a :class:`GostRating` or its values by key),
    judged by :func:`geardesign.spur.strength.verdict.verdict`.

    Contact: σ_H <= σ_HP of the pair; bending: S_F >= S_Fmin per gear (σ_F <= σ_FP); peak
    loads: σ_Hmax <= σ_HPmax and σ_Fmax <= σ_FPmax per gear.  The advice uses the scaling
    of the formulas: σ_H ∝ a_w^(-3/2) at a fixed ψ_ba and ∝ b_w^(-1/2); σ_F ∝ 1/(b_w·m_n).
    ``members`` name gear 1 and gear 2 in the messages and the codes (a planetary mesh:
    ``("sun", "planet")``); ``peak_key`` is the spec key of the peak torque.
    """
    from geardesign.spur.strength.verdict import verdict

    v = v if isinstance(v, dict) else v.v
    src = "GOST 21354-87"
    out: list[Check] = []
    judged = verdict(v)
    sH, sHP = v["sigma_H"], v["sigma_HP"]
    r = sH / sHP
    gov = 1 if v["sigma_HP1"] <= v["sigma_HP2"] else 2
    who = members[gov - 1]
    advice = ((_scale_advice(a_w, k_contact) if k_contact is not None else
               f"increase the centre distance by {advised_percent(r ** (2 / 3) - 1)}")
              + f", or use a harder {who} material" + _face_advice(b_w, b_contact, face_limit))
    out.append(check(
        "CONTACT_FATIGUE", judged.contact_passes, "error",
        f"contact stress σ_H = {sH:.0f} MPa exceeds σ_HP = {sHP:.0f} MPa by {100 * (r - 1):.1f} % "
        f"(S_H{gov} = {v[f'S_H{gov}']:.2f} < {v[f'S_H{gov}_min']:.2f}, {who}): " + advice,
        f"σ_H = {sH:.0f} MPa <= σ_HP = {sHP:.0f} MPa ({100 * (1 - r):.1f} % reserve; S_H1 = "
        f"{v['S_H1']:.2f}, S_H2 = {v['S_H2']:.2f})", sH, sHP, src,
        face_width_fix(b_w, b_contact), advice))
    for k in (1, 2):
        who = members[k - 1]
        S, Smin = v[f"S_F{k}"], v[f"S_F{k}_min"]
        sF, sFP = v[f"sigma_F{k}"], v[f"sigma_FP{k}"]
        advice = (f"increase the module by {advised_percent(sF / sFP - 1)} (same centre distance, fewer "
                  f"teeth), or use a material with a higher σ_Flim"
                  + _face_advice(b_w, b_bending, face_limit))
        out.append(check(
            f"BENDING_FATIGUE_{who.upper()}", judged.bending_ok[k - 1], "error",
            f"{who} root stress σ_F{k} = {sF:.0f} MPa exceeds σ_FP{k} = {sFP:.0f} MPa (S_F{k} = "
            f"{S:.2f} < {Smin:.2f}): " + advice,
            f"{who}: σ_F{k} = {sF:.0f} MPa <= σ_FP{k} = {sFP:.0f} MPa (S_F{k} = {S:.2f} >= "
            f"{Smin:.2f})", S, Smin, src, face_width_fix(b_w, b_bending), advice))
    if peak_given:
        sHm = v["sigma_Hmax"]
        lim = min(v["sigma_HPmax1"], v["sigma_HPmax2"])
        advice = (f"limit the peak torque to {v['T_peak'] * (lim / sHm) ** 2:.0f} N·m (e.g. a "
                  f"slip coupling), or enlarge the gears")
        out.append(check(
            "STATIC_CONTACT", sHm <= lim, "error",
            f"contact stress at the peak torque σ_Hmax = {sHm:.0f} MPa exceeds σ_HPmax = "
            f"{lim:.0f} MPa: " + advice,
            f"σ_Hmax = {sHm:.0f} MPa <= σ_HPmax = {lim:.0f} MPa", sHm, lim, src,
            advice=advice))
        for k in (1, 2):
            who = members[k - 1]
            sFm, limF = v[f"sigma_Fmax{k}"], v[f"sigma_FPmax{k}"]
            advice = (f"limit the peak torque to {v['T_peak'] * limF / sFm:.0f} N·m or "
                      f"increase the module")
            out.append(check(
                f"STATIC_BENDING_{who.upper()}", sFm <= limF, "error",
                f"{who} root stress at the peak torque σ_Fmax{k} = {sFm:.0f} MPa exceeds "
                f"σ_FPmax{k} = {limF:.0f} MPa: " + advice,
                f"{who}: σ_Fmax{k} = {sFm:.0f} MPa <= σ_FPmax{k} = {limF:.0f} MPa", sFm, limF,
                src, advice=advice))
    else:
        out.append(check(
            "STATIC_NOT_CHECKED", False, "info",
            f"no peak torque given ({peak_key}): the static contact and bending checks "
            "were not made", "", None, None, src))
    for k, mat in enumerate(mats, 1):
        for w in mat.warnings:
            out.append(check(f"HARDNESS_RANGE_{members[k - 1].upper()}", False, "warning",
                             w, "", None, None, src))
    m1, m2 = mats
    if m1.soft and m2.soft:
        d = m1.HB - m2.HB
        one, two = members
        advice = f"raise the {one} hardness"
        out.append(check(
            "HARDNESS_DIFFERENCE", d >= HB_DIFFERENCE_MIN, "warning",
            f"the {one} is only {d:.0f} HB harder than the {two}: soft pairs run in best with "
            f"the {one} {HB_DIFFERENCE_MIN:.0f}…50 HB harder; " + advice,
            f"{one} {d:.0f} HB harder than the {two} (>= {HB_DIFFERENCE_MIN:.0f} HB for "
            f"running-in)", d, HB_DIFFERENCE_MIN, "design practice", advice=advice))
    limit = max(m.sigma_Hlim for m in mats)
    out.append(check(
        "UNITS_TORQUE", sH <= 3.0 * limit, "warning",
        f"σ_H = {sH:.0f} MPa is more than three times the strongest material's σ_Hlim = "
        f"{limit:.0f} MPa: check the units (torque1 is in N·m, power in kW, lengths in mm)",
        "stresses within the range of gear materials", sH, 3.0 * limit, "plausibility"))
    from geardesign.spur.strength.tables import V_MAX

    vmax = V_MAX["helical" if helical else "spur"][grade]
    out.append(check(
        "VELOCITY_GRADE", v["v_H"] <= vmax, "warning",
        f"circumferential velocity {v['v_H']:.1f} m/s is above {vmax:g} m/s for accuracy grade "
        f"{grade} {'helical' if helical else 'spur'} gears: choose a finer grade (smaller number)",
        f"v = {v['v_H']:.2f} m/s <= {vmax:g} m/s for grade {grade}", v["v_H"], vmax,
        "handbook (GOST 1643-81 grades)"))
    return out


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
