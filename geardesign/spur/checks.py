"""Geometric quality checks of an external pair (GOST 16532-70 quality indices and the
rules of design practice).  Each check says what is wrong and what to change.  The
strength checks are :mod:`geardesign.spur.strength.checks` (re-exported here).

Limits used here (design practice): ε_α >= 1 (spur) / ε_γ >= 1
(helical), warning below 1.2; s_an >= 0.25·m_n (0.4·m_n for case-hardened teeth is named
in the message); radial clearance >= 0.1·m_n; 0.2 <= ψ_bd <= 1.6 (:func:`face_width_ratio_ok`); u <= 8 for one stage;
|ϑ| <= 4 at the roots.
"""

from __future__ import annotations

import math

from geardesign.core.result import Check, check
from geardesign.spur import sources as S
from geardesign.gears.geometry import PairGeometry
from geardesign.gears.span import span_measurable
from geardesign.spur.internal_checks import (  # noqa: F401
    SPUR_INTERNAL, InternalNames, interference_check, internal_mesh_checks, round_up)
from geardesign.spur.kinematics import Sliding
from geardesign.spur.strength.checks import (  # noqa: F401  (the strength checks' home)
    ADVICE_FACE_MAX, ADVICE_RTOL, HB_DIFFERENCE_MIN, LOAD_INPUTS, PSI_BD_MAX,
    contact_load_fraction, face_advice_limit, face_width_beyond, face_width_fix,
    face_width_up, least_passing, light_load_checks, reconciled_widths)

EPS_MIN = 1.0
EPS_WARN = 1.2
TIP_THICKNESS_MIN = 0.25     # × m_n, through-hardened teeth
TIP_THICKNESS_HARD = 0.4     # × m_n, case-hardened teeth (named in the advice)
CLEARANCE_WARN = 0.1         # × m_n
PSI_BD_MIN = 0.2
"""Window of the face width ratio ψ_bd = b_w/d_w1 of a cylindrical pair: the smallest and
the largest ψ_bd of the handbook tables of ψ_bd by the arrangement of the gears between the
bearings and the hardness ([Ivanov] table of ψ_bd: 0.2…0.25 for a hardened overhung pinion,
up to 1.4 for a soft pair between symmetric bearings; [Dunaev] table of ψ_ba with
ψ_bd = 0.5·ψ_ba·(u + 1); the upper 1.6 of the GOST 21354-87 K_Hβ charts).  Below the window
the wheel is a narrow disc of a large diameter for its load (heavy, a long centre
distance); above it the load concentrates along the face."""

PSI_BA_WINDOW = (0.1, 1.25)
"""Window of ψ_ba = b_w/a_w: the ends of the GOST 2185-66 series of ψ_ba ([GOST2185];
:data:`geardesign.spur.strength.tables.PSI_BA`)."""


def face_width_ratio_ok(psi_bd, low: float = PSI_BD_MIN, high: float = PSI_BD_MAX):
    """True where the face width ratio ψ_bd = b_w/d_w1 [-] lies in the window
    [``low``, ``high``] (default :data:`PSI_BD_MIN` … :data:`PSI_BD_MAX`, design practice
    after [Ivanov] and [Dunaev]); a number or a numpy array.  The one rule of the spur
    check ``FACE_WIDTH_RATIO`` and of the sweep's ψ_bd window."""
    return (psi_bd >= low * (1 - 1e-12)) & (psi_bd <= high * (1 + 1e-12))
RATIO_MAX = 8.0
SLIDING_MAX = 4.0

_NAMES = ("pinion", "wheel")
_SUFFIX = ("PINION", "WHEEL")


def _tip_at_shift(g: PairGeometry, i: int, x: float) -> float:
    """Normal tip thickness [mm] gear ``i`` would have with the shift ``x`` (nominal tip,
    d_a = d + 2(h_a* + x)m_n), for advice on the shift."""
    from geardesign.gears.geometry import tip_thickness

    p, gear = g.inp, g.gears[i]
    d_a = gear.d + 2.0 * (p.rack.h_a + x) * p.m_n
    if d_a <= gear.d * math.cos(g.alpha_t):
        return 0.0
    return tip_thickness(gear.z, x, gear.d, d_a, g.alpha_t, p.rack.alpha_n, p.beta)


def geometry_checks(g: PairGeometry, sliding: Sliding, allow_undercut: bool = False) -> list[Check]:
    """Checks of an external pair, or of an internal pair
    (:class:`geardesign.gears.internal.InternalPairGeometry`): there the internal gear has
    no undercut, root or span check, and the interference at both roots is that of
    :func:`internal_mesh_checks`."""
    p = g.inp
    m = p.m_n
    helical = p.beta > 0.0
    internal = getattr(g, "internal", False)
    src = S.G19274 if internal else S.G16532
    # a smaller working pressure angle lengthens the line of action
    smaller_angle = "reduce x2 − x1" if internal else "reduce x1 + x2"
    out: list[Check] = []

    # -- continuity of the mesh
    if helical:
        out.append(check(
            "CONTACT_RATIO", g.eps_gamma >= EPS_MIN, "error",
            f"ε_γ = {g.eps_gamma:.3f} < 1: the mesh is not continuous; increase the face width "
            f"or the helix angle, increase the tooth numbers or {smaller_angle}",
            f"ε_γ = {g.eps_gamma:.3f} >= 1: continuous mesh", g.eps_gamma, EPS_MIN, src))
        low_value, low_name = g.eps_gamma, "ε_γ"
    else:
        out.append(check(
            "CONTACT_RATIO", g.eps_alpha >= EPS_MIN, "error",
            f"ε_α = {g.eps_alpha:.3f} < 1: the mesh is not continuous; increase the tooth "
            f"numbers, {smaller_angle} or use helical teeth",
            f"ε_α = {g.eps_alpha:.3f} >= 1: continuous mesh", g.eps_alpha, EPS_MIN, src))
        low_value, low_name = g.eps_alpha, "ε_α"
    if low_value >= EPS_MIN:
        out.append(check(
            "CONTACT_RATIO_LOW", low_value >= EPS_WARN, "warning",
            f"{low_name} = {low_value:.3f} < {EPS_WARN}: little overlap of tooth pairs (noisy, "
            f"sensitive to pitch errors); increase the tooth numbers or {smaller_angle}",
            f"{low_name} = {low_value:.3f} >= {EPS_WARN}", low_value, EPS_WARN, S.PRACTICE))

    for i, gear in enumerate(g.gears):
        n, idx, suf = _NAMES[i], i + 1, _SUFFIX[i]
        mate_idx = 2 - i
        if internal and i == 1:
            out += _internal_gear_tip(gear, m)
            continue
        # -- undercut
        z_needed = math.ceil(2.0 * math.cos(p.beta) * (p.rack.h_straight - gear.x)
                             / math.sin(g.alpha_t) ** 2 - 1e-9)
        ok = gear.x >= gear.x_min - 1e-9
        x_need = math.ceil(gear.x_min * 1000) / 1000
        s_need = _tip_at_shift(g, i, x_need)
        if s_need < TIP_THICKNESS_MIN * m:   # the shift that removes the undercut points the tip
            left = (f"leaves s_an{idx} = {s_need / m:.2f}·m_n" if s_need > 0.0
                    else "makes the tooth pointed")
            shift_advice = (f"no shift removes it and keeps a tip of {TIP_THICKNESS_MIN}·m_n "
                            f"(x{idx} = {x_need:.3f} {left}): use z{idx} >= {z_needed}")
        else:
            shift_advice = f"increase x{idx} to at least {x_need:.3f} (or use z{idx} >= {z_needed})"
        out.append(check(
            f"UNDERCUT_{suf}", ok, "warning" if allow_undercut else "error",
            f"{n} undercut: x{idx} = {gear.x:.4f} < x_min{idx} = {gear.x_min:.4f}; "
            f"{shift_advice}, or set gear.allow_undercut = true if it is deliberate",
            f"{n} not undercut (x{idx} = {gear.x:.4f} >= x_min{idx} = {gear.x_min:.4f})",
            gear.x, gear.x_min, S.G16532))
        # -- tip thickness
        out.append(check(
            f"POINTED_TIP_{suf}", gear.s_an > 0.0, "error",
            f"{n} tooth is pointed (s_an{idx} = {gear.s_an:.3f} mm <= 0); reduce x{idx} or the "
            f"addendum coefficient, or increase z{idx}",
            f"{n} tip not pointed (s_an{idx} = {gear.s_an:.3f} mm)", gear.s_an, 0.0, S.G16532))
        if gear.s_an > 0.0:
            out.append(check(
                f"TIP_THICKNESS_{suf}", gear.s_an >= TIP_THICKNESS_MIN * m, "warning",
                f"{n} tip is thin: s_an{idx} = {gear.s_an:.3f} mm = {gear.s_an / m:.2f}·m_n "
                f"< {TIP_THICKNESS_MIN}·m_n ({TIP_THICKNESS_HARD}·m_n for case-hardened teeth); "
                f"reduce x{idx} or the addendum coefficient",
                f"{n} tip thickness s_an{idx} = {gear.s_an / m:.2f}·m_n >= {TIP_THICKNESS_MIN}·m_n "
                f"(case-hardened teeth need {TIP_THICKNESS_HARD}·m_n)",
                gear.s_an, TIP_THICKNESS_MIN * m, S.G16532))
        # -- involute interference: the mate's tip must work on the involute
        if not internal:
            out.append(interference_check(
                f"INTERFERENCE_{suf}", gear, n, _NAMES[1 - i], str(idx),
                f"increase x{idx} or z{idx}, or reduce x{mate_idx}",
                f"increase x{idx}, reduce x{mate_idx} or the addendum coefficient, or increase "
                f"z{idx}"))
        out.append(check(
            f"ROOT_DIAMETER_{suf}", gear.d_f > 0.0, "error",
            f"{n} root diameter d_f{idx} = {gear.d_f:.3f} mm <= 0: no gear body; increase "
            f"z{idx} or x{idx}",
            f"{n} root diameter d_f{idx} = {gear.d_f:.3f} mm > 0", gear.d_f, 0.0, S.G16532))

    if internal:
        out += internal_mesh_checks(g, "", SPUR_INTERNAL, S.G19274, S.G19274_MEMORY)
        if g.cutting is None:
            out.append(check(
                "INTERNAL_FORM_CIRCLE", True, "info", "",
                "the internal gear's form circle is that of the basic rack; give "
                "gear.cutter_teeth for a shaper-cut gear (a smaller form circle) and the "
                "cutting interference check", None, None, S.G19274))

    # -- radial clearance
    c = min(g.c_12, g.c_21)
    out.append(check(
        "ROOT_CLEARANCE", c >= -1e-9, "error",
        f"radial clearance {c:.3f} mm < 0: a tip touches the mating root; reduce the addendum "
        f"coefficient or increase the clearance coefficient"
        + (", or shorten the internal gear's tip (gear.internal_tip_shortening)" if internal
           else ""),
        f"radial clearance {c:.3f} mm >= 0", c, 0.0, src))
    if c >= -1e-9:
        out.append(check(
            "ROOT_CLEARANCE_SMALL", c >= CLEARANCE_WARN * m - 1e-9, "warning",
            f"radial clearance {c:.3f} mm < {CLEARANCE_WARN}·m_n: little room for lubricant and "
            f"tolerances; increase the clearance coefficient c*",
            f"radial clearance {c:.3f} mm >= {CLEARANCE_WARN}·m_n", c, CLEARANCE_WARN * m, S.PRACTICE))

    # -- proportions
    psi = p.b_w / g.g1.d_w
    if psi < PSI_BD_MIN:
        low = (f"face width ratio b_w/d_w1 = {psi:.3f} < {PSI_BD_MIN}: a narrow wheel of a "
               f"large diameter for its load (heavy, a long centre distance); widen the face "
               f"to at least {PSI_BD_MIN * g.g1.d_w:.1f} mm and take a smaller module or "
               f"centre distance")
    else:
        low = (f"face width ratio b_w/d_w1 = {psi:.2f} > {PSI_BD_MAX}: load will concentrate "
               f"along the face; reduce the face width or increase the pinion diameter")
    out.append(check(
        "FACE_WIDTH_RATIO", bool(face_width_ratio_ok(psi)), "warning", low,
        f"face width ratio b_w/d_w1 = {psi:.2f} within {PSI_BD_MIN} … {PSI_BD_MAX}", psi,
        PSI_BD_MIN if psi < PSI_BD_MIN else PSI_BD_MAX, S.PRACTICE))
    out.append(check(
        "GEAR_RATIO", g.u <= RATIO_MAX, "warning",
        f"u = {g.u:.3f} > {RATIO_MAX:g}: large for one stage (bulky wheel); consider two stages",
        f"u = {g.u:.3f} <= {RATIO_MAX:g} for one stage", g.u, RATIO_MAX, S.PRACTICE))

    # -- sliding: both root ends are rated, or the check says which end is undefined
    ends = {"ϑ1(A)": sliding.theta1_A, "ϑ2(E)": sliding.theta2_E}
    undefined = [name for name, v in ends.items() if not math.isfinite(v)]
    if undefined:
        out.append(check(
            "SPECIFIC_SLIDING", False, "warning",
            f"specific sliding at the roots not rated: {' and '.join(undefined)} undefined, "
            f"because that end of the active line of action lies at or beyond the gear's "
            f"tangency point (interference, see the undercut and interference checks); "
            f"change the shifts or the tooth numbers so that the contact stays on the "
            f"involutes", "", None, SLIDING_MAX, S.SLIDING))
    else:
        worst = max(abs(sliding.theta1_A), abs(sliding.theta2_E))
        out.append(check(
            "SPECIFIC_SLIDING", worst <= SLIDING_MAX, "warning",
            f"specific sliding at the roots is high (ϑ1(A) = {sliding.theta1_A:.2f}, ϑ2(E) = "
            f"{sliding.theta2_E:.2f}; limit ±{SLIDING_MAX:g}): wear and scuffing risk; increase x1 "
            + ("(and reduce x2, GOST sign) to balance them" if internal else
               "(and reduce x2) to balance them, e.g. gear.shift_split = \"sliding\""),
            f"specific sliding at the roots within ±{SLIDING_MAX:g} (ϑ1(A) = "
            f"{sliding.theta1_A:.2f}, ϑ2(E) = {sliding.theta2_E:.2f})", worst, SLIDING_MAX,
            S.SLIDING))

    # -- span measurement (the internal gear's span is reported, not checked)
    for i, gear in enumerate(g.gears[:1] if internal else g.gears):
        n, idx, suf = _NAMES[i], i + 1, _SUFFIX[i]
        lo = max(gear.d_p, gear.d_l)
        ok = span_measurable(gear.W, gear.d_W, lo, gear.d_a, g.beta_b, p.b_w)
        on_flank = span_measurable(gear.W, gear.d_W, lo, gear.d_a, 0.0, p.b_w)
        need = gear.W * math.sin(g.beta_b)
        if on_flank:   # the diameter is right: the face is too narrow for the anvils
            why = (f"the face width b_w = {p.b_w:g} mm is not more than W{idx}·sin β_b = "
                   f"{need:.2f} mm, so the anvils cannot both bear on the same teeth")
        else:
            why = (f"the calliper would touch at d = {gear.d_W:.3f} mm, outside the active "
                   f"flank {lo:.3f}…{gear.d_a:.3f} mm")
        out.append(check(
            f"SPAN_{suf}", ok, "warning",
            f"the span W{idx} over k{idx} = {gear.k} teeth cannot be measured: {why}; measure "
            f"over balls or the chordal thickness instead",
            f"span W{idx} over k{idx} = {gear.k} teeth measurable (contact on d = "
            f"{gear.d_W:.3f} mm)", gear.d_W, None, S.G16532_SPAN))
    return _no_contact_ratio_without_mesh(out)


def _internal_gear_tip(gear, m: float) -> list[Check]:
    """Pointed and thin tips of the internal gear (its tooth widens outwards: a larger
    GOST-sign x2 or a longer tip thins the tip)."""
    advice = ("reduce x2 (GOST 19274-73 sign: a larger one thins the internal teeth) or "
              "shorten the tip (gear.internal_tip_shortening)")
    out = [check(
        "POINTED_TIP_WHEEL", gear.s_an > 0.0, "error",
        f"internal gear tooth is pointed (s_an2 = {gear.s_an:.3f} mm <= 0); {advice}",
        f"internal gear tip not pointed (s_an2 = {gear.s_an:.3f} mm)", gear.s_an, 0.0,
        S.G19274)]
    if gear.s_an > 0.0:
        out.append(check(
            "TIP_THICKNESS_WHEEL", gear.s_an >= TIP_THICKNESS_MIN * m, "warning",
            f"internal gear tip is thin: s_an2 = {gear.s_an:.3f} mm = {gear.s_an / m:.2f}·m_n "
            f"< {TIP_THICKNESS_MIN}·m_n ({TIP_THICKNESS_HARD}·m_n for case-hardened teeth); "
            + advice,
            f"internal gear tip thickness s_an2 = {gear.s_an / m:.2f}·m_n >= "
            f"{TIP_THICKNESS_MIN}·m_n (case-hardened teeth need {TIP_THICKNESS_HARD}·m_n)",
            gear.s_an, TIP_THICKNESS_MIN * m, S.G19274))
    return out


def _no_contact_ratio_without_mesh(out: list[Check]) -> list[Check]:
    """A pair whose teeth interfere cannot mesh as computed: its contact ratio is not shown
    as fulfilled (the ratio of the theoretical line of action means nothing then)."""
    blocking = [c for c in out if c.code.startswith("INTERFERENCE_") and not c.passed]
    if not blocking:
        return out
    names = " and ".join(c.code.split("_", 1)[1].lower() for c in blocking)
    return [check("CONTACT_RATIO", False, "error",
                  f"the contact ratio cannot be relied on: the teeth cannot mesh (interference "
                  f"at the {names} root, see {blocking[0].code}); correct the interference "
                  f"first", "", c.value, c.limit, c.source)
            if c.code == "CONTACT_RATIO" else c for c in out]
