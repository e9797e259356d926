"""The checks of a GOST 21354-87 rating (:func:`strength_checks`): contact, bending,
peak loads, judged by the one :func:`geardesign.spur.strength.verdict.verdict` of both
methods, and the notes on the materials and the inputs' ranges."""

from __future__ import annotations

from geardesign.core.result import Check, check
from geardesign.spur.strength.advice import (
    ADVICE_FACE_MAX, _face_advice, _scale_advice, advised_percent, face_width_fix)
from geardesign.spur.strength.verdict import verdict

WHO = ("pinion", "wheel")
HB_DIFFERENCE_MIN = 20.0   # HB, pinion harder than the wheel for running-in (soft pairs)


def strength_checks(rating, members: tuple[str, str] = WHO, found: dict | None = None,
                    peak_key: str = "load.peak_torque1") -> list[Check]:
    """Checks of a GOST 21354-87 rating record (:class:`GostRating`: its values, materials,
    accuracy grade and whether a peak torque was rated), judged by
    :func:`geardesign.spur.strength.verdict.verdict`.

    Contact: σ_H <= σ_HP of the pair; bending: S_F >= S_Fmin per gear (σ_F <= σ_FP); peak
    loads: σ_Hmax <= σ_HPmax and σ_Fmax <= σ_FPmax per gear.  The advice names the face
    width and the scale found by re-rating when ``found`` carries them (as
    :func:`geardesign.spur.strength.checks.rating_checks`), else it uses the scaling of the
    formulas: σ_H ∝ a_w^(-3/2) at a fixed ψ_ba and ∝ b_w^(-1/2); σ_F ∝ 1/(b_w·m_n).
    ``members`` name gear 1 and gear 2 in the messages and the codes (a planetary mesh:
    ``("sun", "planet")``); ``peak_key`` is the spec key of the peak torque.
    """
    found = found or {}
    b_w, b_contact, b_bending = found.get("b", (None, None, None))
    a_w, k_contact = found.get("k", (None, None, None))[:2]
    face_limit = found.get("face_limit", ADVICE_FACE_MAX)
    mats = rating.materials
    helical, grade = bool(rating.factors.helical), rating.factors.grade
    peak_given = rating.static is not None
    v = rating.v
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
