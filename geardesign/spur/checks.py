"""Geometric quality checks of an external pair (GOST 16532-70 quality indices and the
rules of design practice).  Each check says what is wrong and what to change.

Limits used here (design practice): ε_α >= 1 (spur) / ε_γ >= 1
(helical), warning below 1.2; s_an >= 0.25·m_n (0.4·m_n for case-hardened teeth is named
in the message); radial clearance >= 0.1·m_n; 0.2 <= ψ_bd <= 1.6 (:func:`face_width_ratio_ok`); u <= 8 for one stage;
|ϑ| <= 4 at the roots.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.core.result import Check, check, fix_text
from geardesign.spur import sources as S
from geardesign.spur.geometry import PairGeometry, span_measurable
from geardesign.spur.kinematics import Sliding

EPS_MIN = 1.0
EPS_WARN = 1.2
TIP_THICKNESS_MIN = 0.25     # × m_n, through-hardened teeth
TIP_THICKNESS_HARD = 0.4     # × m_n, case-hardened teeth (named in the advice)
CLEARANCE_WARN = 0.1         # × m_n
PSI_BD_MIN = 0.2
PSI_BD_MAX = 1.6
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


def interference_check(code: str, gear, own: str, mate: str, index: str, advice_tangency: str,
                       advice_form: str, prefix: str = "") -> Check:
    """Involute interference at the root of ``gear`` (GOST 16532-70 quality check): the
    lower point of active profile must lie on the generated involute, ρ_p >= ρ_l, and
    before the tangency point, ρ_p > 0.  ``own``/``mate`` name the gears, ``index`` the
    symbol suffix, the advice phrases say what to change; ``prefix`` names the mesh."""
    if gear.rho_p <= 0.0:
        ok, msg = False, (
            f"{prefix}the {mate} tip reaches beyond the {own}'s tangency point "
            f"(ρ_p{index} = {gear.rho_p:.3f} mm <= 0): the teeth cannot mesh; {advice_tangency}")
    elif gear.rho_p < gear.rho_l - 1e-9:
        ok, msg = False, (
            f"{prefix}involute interference at the {own} root: the {mate} tip works below "
            f"the {own}'s form circle (ρ_p{index} = {gear.rho_p:.3f} mm < ρ_l{index} = "
            f"{gear.rho_l:.3f} mm); {advice_form}")
    else:
        ok, msg = True, ""
    return check(
        code, ok, "error", msg,
        f"{prefix}no interference at the {own} root (ρ_p{index} = {gear.rho_p:.3f} mm >= "
        f"ρ_l{index} = {gear.rho_l:.3f} mm)", gear.rho_p, gear.rho_l, S.G16532)


@dataclass(frozen=True)
class InternalNames:
    """How the checks of an internal mesh name its gears and the keys to change.

    ``pinion``/``gear``: words for the external pinion and the internal gear; ``x1``,
    ``x2``, ``z2``: the spec keys of the pinion's shift, the internal gear's shift and
    teeth; ``tip``: the words for shortening the internal gear's tip, with its key
    (``"ring tip (ring.tip_shortening"``, closed by the advice); ``prefix``: the mesh's
    name before a message (``"planet–ring"``), ``""`` for a single pair; ``codes``: the
    pinion's and the internal gear's part of the check codes."""

    pinion: str
    gear: str
    x1: str
    x2: str
    z1: str
    z2: str
    tip: str
    prefix: str = ""
    codes: tuple[str, str] = ("PINION", "WHEEL")


def round_up(x: float) -> str:
    """``x`` rounded up to three decimals, for advice ("increase x to at least ...")."""
    return f"{math.ceil(x * 1000 - 1e-9) / 1000:.3f}"


def internal_mesh_checks(g, code: str, names: InternalNames, src: str, src_tip: str
                         ) -> list[Check]:
    """Involute interference at both roots, tip interference and cutting interference of
    an internal mesh (:class:`geardesign.spur.internal.InternalPairGeometry`).

    * pinion root: the internal gear's tip must meet the pinion on its involute,
      0 < ρ_p1 and ρ_p1 >= ρ_l1; the advice gives the tip shortening k2 that puts ρ_p1 on
      the form circle: d_a2 = 2·sqrt(r_b2² + (ρ_l1 + g_w)²), Δk2 = (d_a2,need − d_a2)/(2m_n)
    * internal gear: the pinion's tip must work on the involute generated by the shaper
      (or the rack), ρ_p2 <= ρ_l2
    * trochoidal tip interference δ >= 0 (:func:`geardesign.spur.internal.tip_interference`)
    * cutting interference of the shaper δ0 >= 0, when a cutter is given

    ``code`` is the prefix of the check codes (``"PLANET_RING_"``, ``""``); ``src`` cites
    the geometry, ``src_tip`` the handbook form of the tip interference.  Used by the
    planetary calculator for every planet–ring mesh and by the spur calculator for an
    internal pair.  References: [GOST19274]; [Kudryavtsev].
    """
    out = []
    g1, g2 = g.g1, g.g2
    m = g.inp.m_n
    n = names
    pre = f"{n.prefix}: " if n.prefix else ""
    at = f" ({n.prefix})" if n.prefix else ""
    # the internal gear's tip radius that would put the pinion's lower active point on its
    # form circle
    rho_need = g1.rho_l + g.g_w
    d_a2_need = 2.0 * math.hypot(0.5 * g2.d_b, max(rho_need, 0.0))
    k_more = (d_a2_need - g2.d_a) / (2.0 * m)
    if g1.rho_p <= 0.0:
        ok, msg = False, (
            f"{pre}the {n.gear} tip reaches beyond the {n.pinion}'s tangency point "
            f"(ρ_p = {g1.rho_p:.3f} mm <= 0): involute interference; shorten the "
            f"{n.tip} += {round_up(k_more)}), increase {n.x1} or {n.z2}")
    elif g1.rho_p < g1.rho_l - 1e-9:
        ok, msg = False, (
            f"involute interference at the {n.pinion} root{at}: the {n.gear} tip "
            f"works below the {n.pinion}'s form circle (ρ_p = {g1.rho_p:.3f} mm < ρ_l = "
            f"{g1.rho_l:.3f} mm); shorten the {n.tip} += {round_up(k_more)}) or increase {n.x1}")
    else:
        ok, msg = True, ""
    out.append(check(
        f"{code}INTERFERENCE_{n.codes[0]}", ok, "error", msg,
        f"{pre}no interference at the {n.pinion} root (ρ_p = {g1.rho_p:.3f} mm >= ρ_l = "
        f"{g1.rho_l:.3f} mm)", g1.rho_p, g1.rho_l, src))
    how = "the shaper cutter" if g.cutting is not None else "the basic rack"
    out.append(check(
        f"{code}INTERFERENCE_{n.codes[1]}", g2.rho_p <= g2.rho_l + 1e-9,
        "error",
        f"involute interference at the {n.gear}{at}: the {n.pinion} tip works "
        f"beyond the {n.gear}'s form circle made by {how} (ρ_p = {g2.rho_p:.3f} mm > "
        f"ρ_l = {g2.rho_l:.3f} mm); reduce {n.x1} (a smaller {n.pinion} tip), or cut the "
        f"{n.gear} with a shaper of more teeth (its form circle grows with them)",
        f"{pre}the {n.pinion} tip works on the {n.gear}'s involute (ρ_p = "
        f"{g2.rho_p:.3f} mm <= ρ_l = {g2.rho_l:.3f} mm, form circle from {how})",
        g2.rho_p, g2.rho_l, src))
    if g.delta_tip is not None:
        out.append(check(
            f"{code}TIP_INTERFERENCE", g.delta_tip >= 0.0, "error",
            f"{pre}the tips of the {n.pinion} and the {n.gear} interfere outside the "
            f"line of action (trochoidal tip interference, δ = {g.delta_tip:.4f} < 0); increase "
            f"{n.z2} − {n.z1}, shorten the {n.tip}) or increase {n.x2} (GOST sign)",
            f"{pre}no tip interference (δ = {g.delta_tip:.4f} >= 0)", g.delta_tip, 0.0,
            src_tip))
    if g.cutting is not None:
        d0 = g.cutting.delta0
        out.append(check(
            f"{code}CUTTING_INTERFERENCE", d0 >= 0.0, "error",
            f"{pre}the shaper cutter (z0 = {g.cutting.z0}) cuts into the {n.gear} tips "
            f"(δ0 = {d0:.4f} < 0); use a cutter with fewer teeth (z0 well below "
            f"{g.inp.z2}) or shorten the {n.gear} tips",
            f"{pre}the shaper cutter (z0 = {g.cutting.z0}) leaves the {n.gear} tips intact "
            f"(δ0 = {d0:.4f} >= 0)" if math.isfinite(d0) else
            f"{pre}the shaper cutter (z0 = {g.cutting.z0}) leaves the {n.gear} tips intact "
            f"(its tip circle does not cross them)", d0, 0.0, src_tip))
    return out


def _tip_at_shift(g: PairGeometry, i: int, x: float) -> float:
    """Normal tip thickness [mm] gear ``i`` would have with the shift ``x`` (nominal tip,
    d_a = d + 2(h_a* + x)m_n), for advice on the shift."""
    from geardesign.spur.geometry import tip_thickness

    p, gear = g.inp, g.gears[i]
    d_a = gear.d + 2.0 * (p.rack.h_a + x) * p.m_n
    if d_a <= gear.d * math.cos(g.alpha_t):
        return 0.0
    return tip_thickness(gear.z, x, gear.d, d_a, g.alpha_t, p.rack.alpha_n, p.beta)


#: How the checks of an internal pair name its gears and keys (the spur spec).
SPUR_INTERNAL = InternalNames("pinion", "internal gear", "gear.x1", "gear.x2", "gear.z1",
                              "gear.z2", "internal gear's tip (gear.internal_tip_shortening")


def geometry_checks(g: PairGeometry, sliding: Sliding, allow_undercut: bool = False) -> list[Check]:
    """Checks of an external pair, or of an internal pair
    (:class:`geardesign.spur.internal.InternalPairGeometry`): there the internal gear has
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


# ----------------------------------------------------------------------------- strength

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


def _pct(x: float) -> str:
    """An advised increase in per cent; beyond +300 % the design is far from passing."""
    return f"{100 * x:.0f} %" if x <= 3.0 else "more than 300 % (far from passing: check the " \
                                                 "inputs and their units)"


def strength_checks(v: dict, mats, helical: bool, grade: int, peak_given: bool,
                    b_w: float | None = None, b_contact: float | None = None,
                    b_bending: float | None = None, a_w: float | None = None,
                    k_contact: float | None = None, face_limit: float = ADVICE_FACE_MAX,
                    members: tuple[str, str] = _NAMES, peak_key: str = "load.peak_torque1"
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
               f"increase the centre distance by {_pct(r ** (2 / 3) - 1)}")
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
        advice = (f"increase the module by {_pct(sF / sFP - 1)} (same centre distance, fewer "
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
