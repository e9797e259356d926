"""The strength of a bevel pair, as frozen records (the forces: :mod:`geardesign.bevel.forces`).

ISO route: [ISO10300-2] / [ISO10300-3] method B1 on the virtual cylindrical gear of
[ISO10300-1]; the factors that ISO 10300 shares with ISO 6336 are called from
``spur.strength.iso6336`` (Z_E, Z_H, the tooth form Y_F, Y_S).  The GOST 21354 route
through the virtual spur pair is :mod:`geardesign.bevel.gost_route`.

Life factors, Z_L Z_v Z_R Z_X, Y_δ Y_R Y_X are 1 (long-life limits as given, the
reference test gear): the permissible stresses are σ_Hlim and Y_ST·σ_Flim = 2·σ_Flim.
Stresses [MPa], forces [N], lengths [mm], torque [N·mm].
"""

from __future__ import annotations

import math

from geardesign.bevel.forces import Forces
from geardesign.bevel.geometry import Geometry
from geardesign.bevel.inputs import Inputs
from geardesign.core.records import dataclass
from geardesign.spur.strength.iso6336 import part2, part3

MOUNTING_FACTOR = {"both_straddle": 1.00, "one_straddle": 1.10, "cantilever": 1.25}
"""Mounting factor K_Hβ-be by the mounting of pinion and wheel, contact pattern checked
under a light test load.  [ISO10300-1] table (K_Hβ-be); the value 1.10 (one member
straddle-, the other cantilever-mounted) is checked by [ISOTR10300-30] sample 1
(K_Hβ-C = 1.5·1.10 = 1.650); 1.00 and 1.25 are the neighbouring rows, not checked."""

Z_K = 1.2
"""Bevel gear factor Z_K of the permissible contact stress, method B1:
σ_HP = σ_Hlim·Z_K (the other factors 1).  [ISO10300-2] method B1, formula (4);
[ISOTR10300-30] sample 1 (σ_HP1 = 1 617.8 MPa = 1 500·Z_NT Z_L Z_v Z_R·1.2)."""

E_LS = 3.0
"""Exponent of the parabolic peak-load distribution along the contact lines (low profile
crowning).  [ISO10300-2] method B1, formula (7); [ISOTR10300-30] sample 1."""

Y_ST = 2.0
"""Stress correction factor of the reference test gear.  [ISO6336-3]."""



# ----------------------------------------------------------------------------- ISO 10300


@dataclass(frozen=True)
class IsoMember:
    Y_Fa: float           # tooth form factor, load at the tip
    Y_Sa: float           # stress correction factor, load at the tip
    sigma_F0: float
    sigma_F: float
    S_H: float
    S_F: float


@dataclass(frozen=True)
class IsoRating:
    """[ISO10300-2] / [ISO10300-3] method B1 on the virtual cylindrical gear."""

    K_Hbeta_be: float
    K_Hbeta: float
    K_Fbeta: float
    F_n: float            # normal force at the mean point [N]
    l_bm: float           # length of the middle contact line [mm]
    Z_E: float
    Z_MB: float
    Z_LS: float
    Z_K: float
    sigma_H0: float
    sigma_H: float
    Y_eps: float
    Y_BS: float
    Y_LS: float
    pinion: IsoMember
    wheel: IsoMember


def mid_zone_factor(g: Geometry) -> float:
    """Mid-zone factor Z_M-B: the contact stress moved from the pitch point to the
    determinant point of load application.

    .. math::
        Z_{M-B} = \\frac{\\tan α_{vt}}{\\sqrt{\\big[\\sqrt{(d_{va1}/d_{vb1})^2 - 1} - F_1 π/z_{v1}\\big]
                  \\big[\\sqrt{(d_{va2}/d_{vb2})^2 - 1} - F_2 π/z_{v2}\\big]}}

    F_1 = 2, F_2 = 2(ε_vα − 1) for ε_vβ = 0; F_1 = F_2 = ε_vα for ε_vβ ≥ 1; linear between.
    [ISO10300-2] method B1, formula (6) and its table; [ISOTR10300-30] sample 1
    (Z_M-B = 0.916).
    """
    ea, eb = g.eps_va, min(g.eps_vb, 1.0)
    F1 = 2.0 + (ea - 2.0) * eb
    F2 = 2.0 * (ea - 1.0) + (2.0 - ea) * eb
    P, W = g.members
    s1 = math.sqrt((P.d_va / P.d_vb) ** 2 - 1.0) - F1 * math.pi / P.z_v
    s2 = math.sqrt((W.d_va / W.d_vb) ** 2 - 1.0) - F2 * math.pi / W.z_v
    return math.tan(g.alpha_vt) / math.sqrt(max(s1 * s2, 1e-6))


def contact_line(g: Geometry, f: float) -> float:
    """Length l_b [mm] of the contact line at the signed distance f [mm] from the middle of
    the zone of action of the virtual gear (no hypoid offset), 0 outside the zone.

    .. math::
        l_{b0} = \\frac{g_{vα}}{\\sin β_{vb}}\\ (b_{v,eff} \\text{ for } β_{vb} = 0),\\quad
        f_{max} = \\tfrac12 (g_{vα} + b_{v,eff} \\tan β_{vb}) \\cos β_{vb},

    .. math::
        C_{lb} = \\sqrt{(f/f_{max})^2 + k^2 [1 - (f/f_{max})^2]},\\quad
        k = 1 - \\sqrt{b_{v,eff}/b_v},\\quad l_b = l_{b0} (1 - C_{lb})

    [ISO10300-1] annex A, formulae A.26-A.36 (a = 0); [ISOTR10300-30] sample 1
    (l_bm = 22.442 mm).
    """
    tb = math.tan(g.beta_vb)
    f_max = 0.5 * (g.g_va + g.b_eff * tb) * math.cos(g.beta_vb)
    r = f / f_max
    if abs(r) >= 1.0:
        return 0.0
    l_b0 = g.g_va / math.sin(g.beta_vb) if tb > 0.0 else g.b_eff
    k = 1.0 - math.sqrt(g.b_eff / g.b)
    return l_b0 * (1.0 - math.sqrt(r * r + k * k * (1.0 - r * r)))


def load_sharing(g: Geometry) -> tuple[float, float]:
    """Load sharing factor Z_LS and the middle contact line l_bm [mm]: the peak loads
    p* = 1 − |f/f_max|^e_LS of the tip, middle and root contact lines (f_t = −f_r =
    p_vet cos β_vb, f_m = 0) over their areas A = π/4·p*·l_b:

    .. math:: Z_{LS} = \\sqrt{A_m/(A_t + A_m + A_r)}

    A line outside the zone of action carries nothing: a straight pair (ε_vα < 2) has
    Z_LS = 1.  The line positions are those of ε_vβ ≥ 1, used for every pair.
    [ISO10300-2] method B1, formulae (7)-(10); [ISO10300-1] annex A table A.2;
    [ISOTR10300-30] sample 1 (Z_LS = 0.935).  Y_LS = Z_LS² in [ISO10300-3].
    """
    tb = math.tan(g.beta_vb)
    f_max = 0.5 * (g.g_va + g.b_eff * tb) * math.cos(g.beta_vb)
    f_t = g.p_vet * math.cos(g.beta_vb)
    l_bm = contact_line(g, 0.0)
    A_m = l_bm
    A_tr = 2.0 * (1.0 - min(f_t / f_max, 1.0) ** E_LS) * contact_line(g, f_t)
    return math.sqrt(A_m / (A_m + A_tr)), l_bm


def contact_ratio_factor(eps_va: float, eps_vb: float) -> float:
    """Contact ratio factor Y_ε of the root stress (load at the tip):
    0.25 + 0.75/ε_vα for ε_vβ = 0, 0.625 for ε_vβ ≥ 1, linear between.
    [ISO10300-3] method B1; [ISOTR10300-30] sample 1 (Y_ε = 0.625).

    >>> contact_ratio_factor(1.5, 0.0), contact_ratio_factor(1.5, 2.0)
    (0.75, 0.625)
    """
    y0 = 0.25 + 0.75 / eps_va
    return y0 - min(eps_vb, 1.0) * (y0 - 0.625)


def spiral_angle_factor(g: Geometry, l_bm: float) -> float:
    """Bevel spiral angle factor Y_BS (1 for straight teeth): with the developed tooth
    length b_a = b/cos β_m, the part covered by the contact line l_bb = l_bm cos β_vb/cos β_m
    and x = 2 b_a/(h_m1 + h_m2) (h_m the mean whole depths),

    .. math::
        Y_{BS} = \\frac{a_{BS}}{c_{BS}}\\Big(\\frac{l_{bb}}{b_a} - 1.05\\,b_{BS}\\Big)^2 + 1,

    a_BS = −0.0182x² + 0.4736x − 0.32, b_BS = −0.0032x² + 0.0526x + 0.712,
    c_BS = −0.005x² + 0.085x + 0.54.  [ISO10300-3] method B1, formulae (30)-(35);
    [ISOTR10300-30] sample 1 (Y_BS = 1.054).
    """
    if g.beta_m <= 0.0:
        return 1.0
    b_a = g.b / math.cos(g.beta_m)
    l_bb = l_bm * math.cos(g.beta_vb) / math.cos(g.beta_m)
    x = 2.0 * b_a / sum(m.h_am + m.h_fm for m in g.members)
    a = -0.0182 * x * x + 0.4736 * x - 0.32
    b = -0.0032 * x * x + 0.0526 * x + 0.712
    c = -0.0050 * x * x + 0.0850 * x + 0.54
    return a / c * (l_bb / b_a - 1.05 * b) ** 2 + 1.0


def iso_rating(inp: Inputs, g: Geometry, f: Forces) -> IsoRating:
    """Contact and bending stresses and safety factors, method B1 (no hypoid offset).

    .. math::
        σ_{H0} = \\sqrt{\\frac{F_n}{l_{bm} ρ_{rel}}}\\, Z_{M-B} Z_{LS} Z_E,\\quad
        F_n = \\frac{F_{mt}}{\\cos α_n \\cos β_m},\\quad
        σ_H = σ_{H0}\\sqrt{K_A K_v K_{Hβ} K_{Hα}},\\quad σ_{HP} = σ_{Hlim} Z_K

    .. math::
        σ_{F0} = \\frac{F_{mt}}{b\\, m_{mn}} Y_{Fa} Y_{Sa} Y_ε Y_{BS} Y_{LS},\\quad
        σ_F = σ_{F0} K_A K_v K_{Fβ} K_{Fα},\\quad σ_{FP} = Y_{ST} σ_{Flim}

    K_Hβ = 1.5·K_Hβ-be (method C), K_Fβ = K_Hβ/K_F0 with K_F0 = 1 (no cutter radius given),
    K_Fα = K_Hα.  Y_Fa, Y_Sa with the load at the tip of the virtual gear in the normal
    section z_vn: the tooth form of [ISO6336-3] method B (``spur`` function, called) with
    the single-contact point moved to the tip (ε_αn = 1) and the thickness modification
    x_sm = x_τ/2 (the tangential shift), the method of [ISO10300-3] §6.4.1.2.  [ISO10300-2], [ISO10300-3]
    method B1; [ISO10300-1] §8; every factor checked against [ISOTR10300-30] sample 1.
    """
    ld, mt, p = inp.load, inp.material, inp.pair
    K_be = MOUNTING_FACTOR[ld.mounting]
    K_Hb = 1.5 * K_be
    K_Fb = K_Hb
    Z_E = part2.z_e(mt.E, mt.nu, mt.E, mt.nu)
    Z_MB = mid_zone_factor(g)
    Z_LS, l_bm = load_sharing(g)
    F_n = f.F_mt / (math.cos(g.alpha_n) * math.cos(g.beta_m))
    s_H0 = math.sqrt(F_n / (l_bm * g.rho_rel)) * Z_MB * Z_LS * Z_E
    K = ld.K_A * ld.K_v
    s_H = s_H0 * math.sqrt(K * K_Hb * ld.K_alpha)
    Y_eps = contact_ratio_factor(g.eps_va, g.eps_vb)
    Y_BS = spiral_angle_factor(g, l_bm)
    cb2 = math.cos(g.beta_vb) ** 2
    members = []
    for i, m in enumerate(g.members):
        tf = part3.tooth_form(m.z_v, m.x, g.m_nm, g.alpha_n, g.beta_m, g.beta_vb, m.d_v,
                              m.d_va, cb2, (p.ha + p.c) * g.m_nm, p.rho_a0s[i] * g.m_nm,
                              x_sm=0.5 * m.xt)
        s_F0 = f.F_mt / (g.b * g.m_nm) * tf.Y_F * tf.Y_S * Y_eps * Y_BS * Z_LS ** 2
        s_F = s_F0 * K * K_Fb * ld.K_alpha
        members.append(IsoMember(tf.Y_F, tf.Y_S, s_F0, s_F, mt.sigma_Hlim[i] * Z_K / s_H,
                                 Y_ST * mt.sigma_Flim[i] / s_F))
    return IsoRating(K_be, K_Hb, K_Fb, F_n, l_bm, Z_E, Z_MB, Z_LS, Z_K, s_H0, s_H,
                     Y_eps, Y_BS, Z_LS ** 2, *members)
