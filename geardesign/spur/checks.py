"""Geometric quality checks of an external pair (GOST 16532-70 quality indices and the
rules of the method note §10.3).  Each check says what is wrong and what to change.

Limits used here (design practice, method note §10.3): ε_α >= 1 (spur) / ε_γ >= 1
(helical), warning below 1.2; s_an >= 0.25·m_n (0.4·m_n for case-hardened teeth is named
in the message); radial clearance >= 0.1·m_n; ψ_bd <= 1.6; u <= 8 for one stage;
|ϑ| <= 4 at the roots.
"""

from __future__ import annotations

import math

from geardesign.core.result import Check, check
from geardesign.spur import sources as S
from geardesign.spur.geometry import PairGeometry, span_measurable
from geardesign.spur.kinematics import Sliding

EPS_MIN = 1.0
EPS_WARN = 1.2
TIP_THICKNESS_MIN = 0.25     # × m_n, through-hardened teeth
TIP_THICKNESS_HARD = 0.4     # × m_n, case-hardened teeth (named in the advice)
CLEARANCE_WARN = 0.1         # × m_n
PSI_BD_MAX = 1.6
RATIO_MAX = 8.0
SLIDING_MAX = 4.0

_NAMES = ("pinion", "wheel")
_SUFFIX = ("PINION", "WHEEL")


def geometry_checks(g: PairGeometry, sliding: Sliding, allow_undercut: bool = False) -> list[Check]:
    p = g.inp
    m = p.m_n
    helical = p.beta > 0.0
    out: list[Check] = []

    # -- continuity of the mesh
    if helical:
        out.append(check(
            "CONTACT_RATIO", g.eps_gamma >= EPS_MIN, "error",
            f"ε_γ = {g.eps_gamma:.3f} < 1: the mesh is not continuous; increase the face width "
            f"or the helix angle, increase the tooth numbers or reduce x1 + x2",
            f"ε_γ = {g.eps_gamma:.3f} >= 1: continuous mesh", g.eps_gamma, EPS_MIN, S.G16532))
        low_value, low_name = g.eps_gamma, "ε_γ"
    else:
        out.append(check(
            "CONTACT_RATIO", g.eps_alpha >= EPS_MIN, "error",
            f"ε_α = {g.eps_alpha:.3f} < 1: the mesh is not continuous; increase the tooth "
            f"numbers, reduce x1 + x2 or use helical teeth",
            f"ε_α = {g.eps_alpha:.3f} >= 1: continuous mesh", g.eps_alpha, EPS_MIN, S.G16532))
        low_value, low_name = g.eps_alpha, "ε_α"
    if low_value >= EPS_MIN:
        out.append(check(
            "CONTACT_RATIO_LOW", low_value >= EPS_WARN, "warning",
            f"{low_name} = {low_value:.3f} < {EPS_WARN}: little overlap of tooth pairs (noisy, "
            f"sensitive to pitch errors); increase the tooth numbers or reduce x1 + x2",
            f"{low_name} = {low_value:.3f} >= {EPS_WARN}", low_value, EPS_WARN, S.PRACTICE))

    for i, gear in enumerate(g.gears):
        n, idx, suf = _NAMES[i], i + 1, _SUFFIX[i]
        mate_idx = 2 - i
        # -- undercut
        z_needed = math.ceil(2.0 * math.cos(p.beta) * (p.rack.h_straight - gear.x)
                             / math.sin(g.alpha_t) ** 2 - 1e-9)
        ok = gear.x >= gear.x_min - 1e-9
        out.append(check(
            f"UNDERCUT_{suf}", ok, "warning" if allow_undercut else "error",
            f"{n} undercut: x{idx} = {gear.x:.4f} < x_min{idx} = {gear.x_min:.4f}; increase "
            f"x{idx} to at least {math.ceil(gear.x_min * 1000) / 1000:.3f} (or use "
            f"z{idx} >= {z_needed}), or set gear.allow_undercut = true if it is deliberate",
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
        if gear.rho_p <= 0.0:
            ok, msg = False, (
                f"the {_NAMES[1 - i]} tip reaches beyond the {n}'s tangency point "
                f"(ρ_p{idx} = {gear.rho_p:.3f} mm <= 0): the teeth cannot mesh; increase "
                f"x{idx} or z{idx}, or reduce x{mate_idx}")
        elif gear.rho_p < gear.rho_l - 1e-9:
            ok, msg = False, (
                f"involute interference at the {n} root: the {_NAMES[1 - i]} tip works below "
                f"the {n}'s form circle (ρ_p{idx} = {gear.rho_p:.3f} mm < ρ_l{idx} = "
                f"{gear.rho_l:.3f} mm); increase x{idx}, reduce x{mate_idx} or the addendum "
                f"coefficient, or increase z{idx}")
        else:
            ok, msg = True, ""
        out.append(check(
            f"INTERFERENCE_{suf}", ok, "error", msg,
            f"no interference at the {n} root (ρ_p{idx} = {gear.rho_p:.3f} mm >= ρ_l{idx} = "
            f"{gear.rho_l:.3f} mm)", gear.rho_p, gear.rho_l, S.G16532))
        out.append(check(
            f"ROOT_DIAMETER_{suf}", gear.d_f > 0.0, "error",
            f"{n} root diameter d_f{idx} = {gear.d_f:.3f} mm <= 0: no gear body; increase "
            f"z{idx} or x{idx}",
            f"{n} root diameter d_f{idx} = {gear.d_f:.3f} mm > 0", gear.d_f, 0.0, S.G16532))

    # -- radial clearance
    c = min(g.c_12, g.c_21)
    out.append(check(
        "ROOT_CLEARANCE", c >= -1e-9, "error",
        f"radial clearance {c:.3f} mm < 0: a tip touches the mating root; reduce the addendum "
        f"coefficient or increase the clearance coefficient",
        f"radial clearance {c:.3f} mm >= 0", c, 0.0, S.G16532))
    if c >= -1e-9:
        out.append(check(
            "ROOT_CLEARANCE_SMALL", c >= CLEARANCE_WARN * m - 1e-9, "warning",
            f"radial clearance {c:.3f} mm < {CLEARANCE_WARN}·m_n: little room for lubricant and "
            f"tolerances; increase the clearance coefficient c*",
            f"radial clearance {c:.3f} mm >= {CLEARANCE_WARN}·m_n", c, CLEARANCE_WARN * m, S.PRACTICE))

    # -- proportions
    psi = p.b_w / g.g1.d_w
    out.append(check(
        "FACE_WIDTH_RATIO", psi <= PSI_BD_MAX, "warning",
        f"ψ_bd = b_w/d_w1 = {psi:.2f} > {PSI_BD_MAX}: load will concentrate along the face; "
        f"reduce the face width or increase the pinion diameter",
        f"ψ_bd = b_w/d_w1 = {psi:.2f} <= {PSI_BD_MAX}", psi, PSI_BD_MAX, S.PRACTICE))
    out.append(check(
        "GEAR_RATIO", g.u <= RATIO_MAX, "warning",
        f"u = {g.u:.3f} > {RATIO_MAX:g}: large for one stage (bulky wheel); consider two stages",
        f"u = {g.u:.3f} <= {RATIO_MAX:g} for one stage", g.u, RATIO_MAX, S.PRACTICE))

    # -- sliding
    worst = max(abs(sliding.theta1_A), abs(sliding.theta2_E))
    if math.isfinite(worst):
        out.append(check(
            "SPECIFIC_SLIDING", worst <= SLIDING_MAX, "warning",
            f"specific sliding at the roots is high (ϑ1(A) = {sliding.theta1_A:.2f}, ϑ2(E) = "
            f"{sliding.theta2_E:.2f}; limit ±{SLIDING_MAX:g}): wear and scuffing risk; increase x1 "
            f"(and reduce x2) to balance them, e.g. gear.shift_split = \"sliding\"",
            f"specific sliding at the roots within ±{SLIDING_MAX:g} (ϑ1(A) = "
            f"{sliding.theta1_A:.2f}, ϑ2(E) = {sliding.theta2_E:.2f})", worst, SLIDING_MAX,
            S.SLIDING))

    # -- span measurement
    for i, gear in enumerate(g.gears):
        n, idx, suf = _NAMES[i], i + 1, _SUFFIX[i]
        lo = max(gear.d_p, gear.d_l)
        ok = span_measurable(gear.W, gear.d_W, lo, gear.d_a, g.beta_b, p.b_w)
        out.append(check(
            f"SPAN_{suf}", ok, "warning",
            f"the span W{idx} over k{idx} = {gear.k} teeth cannot be measured as computed "
            f"(calliper contact diameter {gear.d_W:.3f} mm outside {lo:.3f}…{gear.d_a:.3f} mm"
            + (f", or face width below W·sin β_b = {gear.W * math.sin(g.beta_b):.2f} mm"
               if helical else "") + "); measure over balls or the chordal thickness instead",
            f"span W{idx} over k{idx} = {gear.k} teeth measurable (contact on d = "
            f"{gear.d_W:.3f} mm)", gear.d_W, None, S.G16532_SPAN))
    return out
