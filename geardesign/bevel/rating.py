"""Forces on the shafts and the strength of a bevel pair, as frozen records.

ISO route: [ISO10300-2] / [ISO10300-3] method B1 on the virtual cylindrical gear of
[ISO10300-1]; the factors that ISO 10300 shares with ISO 6336 are called from
``spur.strength.iso6336`` (Z_E, Z_H, the tooth form Y_F, Y_S).  GOST route: [GOST21354]
on the virtual spur pair with the bevel factors θ_H, θ_F of the handbook method
([Dunaev] §2.6; [Ivanov] ch. 4), the stresses by ``spur.strength.gost21354``.

Life factors, Z_L Z_v Z_R Z_X, Y_δ Y_R Y_X are 1 (long-life limits as given, the
reference test gear): the permissible stresses are σ_Hlim and Y_ST·σ_Flim = 2·σ_Flim.
Stresses [MPa], forces [N], lengths [mm], torque [N·mm].
"""

from __future__ import annotations

import math

from geardesign.bevel.geometry import Geometry
from geardesign.bevel.inputs import Inputs
from geardesign.core.records import dataclass
from geardesign.spur.strength import gost21354 as G
from geardesign.spur.strength.iso6336 import part2, part3

MOUNTING_FACTOR = {"both_straddle": 1.00, "one_straddle": 1.10, "cantilever": 1.25}
"""Mounting factor K_Hβ-be by the mounting of pinion and wheel.  [ISO10300-1] table 6, not
consulted: unverified (the report's METHOD_UNVERIFIED warning, docs/bevel.md)."""

Z_K = 0.8
"""Bevel gear factor Z_K (method B1).  [ISO10300-2] §7, not consulted: unverified (the
report's METHOD_UNVERIFIED warning, docs/bevel.md)."""

Y_ST = 2.0
"""Stress correction factor of the reference test gear.  [ISO6336-3]."""

THETA = {  # (θ_H, θ_F) = (a_H + b_H·u, a_F + b_F·u) for circular teeth
    "both_soft": ((1.22, 0.21), (0.94, 0.08)),
    "one_hard": ((1.13, 0.13), (0.85, 0.043)),
    "both_hard": ((0.81, 0.15), (0.65, 0.11)),
}
"""Bevel factors of circular teeth θ_H, θ_F against the pair's hardness ([Dunaev] §2.6,
table 2.6, written without the table at hand: unverified, the report's METHOD_UNVERIFIED
warning); straight teeth: :data:`THETA_STRAIGHT`."""

THETA_STRAIGHT = 0.85
"""θ_H = θ_F = 0.85 for straight bevel teeth ([Dunaev] §2.6; [Ivanov] ch. 4)."""


# ----------------------------------------------------------------------------- forces


@dataclass(frozen=True)
class MemberForces:
    """Forces on one member at the mean cone [N]: F_a > 0 points from the apex to the
    back of the member, F_r > 0 toward its axis (separating)."""

    F_t: float
    F_a: float
    F_r: float


@dataclass(frozen=True)
class Forces:
    F_mt: float           # tangential force at the mean cone
    T2: float             # wheel torque [N·mm] (no losses)
    v_mt: float           # pitch line speed at the mean cone [m/s]
    pinion: MemberForces
    wheel: MemberForces


def thrust_sign(hand: str, rotation: str, driving: bool) -> int:
    """+1 when the member's axial force points away from the apex: a driving member
    with a right hand spiral turning clockwise (or left hand, counter-clockwise), seen from
    its back; a driven member the other way.  [ISO23509] annex (force directions)."""
    same = (hand == "right") == (rotation == "cw")
    return 1 if same == driving else -1


def member_forces(F_mt: float, alpha_n: float, beta_m: float, delta: float, s: int
                  ) -> MemberForces:
    """Axial and radial forces of a member with pitch cone angle δ and sign s
    (:func:`thrust_sign`).

    .. math::
        F_a = \\frac{F_{mt}}{\\cos β_m}(\\tan α_n \\sin δ + s \\sin β_m \\cos δ),\\quad
        F_r = \\frac{F_{mt}}{\\cos β_m}(\\tan α_n \\cos δ - s \\sin β_m \\sin δ)

    At Σ = 90° the wheel (sign −s) carries F_a2 = F_r1 and F_r2 = F_a1.  [ISO10300-1] §5;
    [ISO23509] annex; [Dunaev] §2.6 (straight teeth: F_a1 = F_t tan α sin δ1).

    >>> f = member_forces(1000.0, math.radians(20), 0.0, math.radians(45), 1)
    >>> round(f.F_a, 3), round(f.F_r, 3)
    (257.366, 257.366)
    """
    k = F_mt / math.cos(beta_m)
    ta, sb = math.tan(alpha_n), math.sin(beta_m)
    return MemberForces(F_mt, k * (ta * math.sin(delta) + s * sb * math.cos(delta)),
                        k * (ta * math.cos(delta) - s * sb * math.sin(delta)))


def forces(inp: Inputs, g: Geometry) -> Forces:
    """F_mt = 2 T1/d_m1 and the members' forces (the pinion's hand, rotation, driver)."""
    p, ld = inp.pair, inp.load
    F_mt = 2.0 * ld.T1 / g.pinion.d_m
    s1 = thrust_sign(p.hand, ld.rotation, ld.driver == "pinion")
    return Forces(F_mt, ld.T1 * g.u, math.pi * g.pinion.d_m * ld.n1 / 60000.0,
                  member_forces(F_mt, g.alpha_n, g.beta_m, g.pinion.delta, s1),
                  member_forces(F_mt, g.alpha_n, g.beta_m, g.wheel.delta, -s1))


# ----------------------------------------------------------------------------- ISO 10300


@dataclass(frozen=True)
class IsoMember:
    Y_F: float
    Y_S: float
    sigma_F: float
    sigma_FP: float       # Y_ST·σ_Flim / S_Fmin
    S_H: float
    S_F: float


@dataclass(frozen=True)
class IsoRating:
    """[ISO10300-2] / [ISO10300-3] method B1 on the virtual cylindrical gear."""

    K_Hbeta_be: float
    K_Hbeta: float
    K_Fbeta: float
    Z_E: float
    Z_H: float
    Z_MB: float
    Z_LS: float
    Z_beta: float
    Z_K: float
    Y_LS: float
    b_eH: float
    sigma_H0: float
    sigma_H: float
    pinion: IsoMember
    wheel: IsoMember


def mid_zone_factor(g: Geometry) -> float:
    """Mid-zone factor Z_M-B: the contact stress moved from the pitch point to the
    determinant point of load application.

    .. math::
        Z_{M-B} = \\frac{\\tan α_{vt}}{\\sqrt{\\big[\\sqrt{(d_{va1}/d_{vb1})^2 - 1} - F_1 π/z_{v1}\\big]
                  \\big[\\sqrt{(d_{va2}/d_{vb2})^2 - 1} - F_2 π/z_{v2}\\big]}}

    F_1 = 2, F_2 = 2(ε_vα − 1) for ε_vβ = 0; F_1 = F_2 = ε_vα for ε_vβ ≥ 1; linear between.
    [ISO10300-2] §6 (method B1); the spur counterpart is Z_B of [ISO6336-2].
    """
    ea, eb = g.eps_va, min(g.eps_vb, 1.0)
    F1 = 2.0 + (ea - 2.0) * eb
    F2 = 2.0 * (ea - 1.0) + (2.0 - ea) * eb
    P, W = g.members
    s1 = math.sqrt((P.d_va / P.d_vb) ** 2 - 1.0) - F1 * math.pi / P.z_v
    s2 = math.sqrt((W.d_va / W.d_vb) ** 2 - 1.0) - F2 * math.pi / W.z_v
    return math.tan(g.alpha_vt) / math.sqrt(max(s1 * s2, 1e-6))


def load_sharing(g: Geometry) -> float:
    """Load sharing factor Z_LS: 1 for straight teeth (and ε_vγ ≤ 2), else

    .. math:: Z_{LS} = \\Big(1 + 2\\big[1 - (2/ε_{vγ})^{1.5}\\big]\\sqrt{1 - 4/ε_{vγ}^2}\\Big)^{-1/2}

    [ISO10300-2] §7 (method B1); Y_LS = Z_LS² in [ISO10300-3].

    >>> class _G: eps_vb = 1.5; eps_vg = 2.5
    >>> round(load_sharing(_G), 4)
    0.8634
    """
    if g.eps_vb <= 0.0 or g.eps_vg <= 2.0:
        return 1.0
    e = g.eps_vg
    return (1.0 + 2.0 * (1.0 - (2.0 / e) ** 1.5) * math.sqrt(1.0 - 4.0 / (e * e))) ** -0.5


def iso_rating(inp: Inputs, g: Geometry, f: Forces) -> IsoRating:
    """Contact and bending stresses and safety factors, method B1.

    .. math::
        σ_{H0} = \\sqrt{\\frac{F_{mt}}{d_{v1} b_{eH}}\\frac{u_v + 1}{u_v}}\\,
                 Z_{M-B} Z_H Z_E Z_{LS} Z_β Z_K,\\quad
        σ_H = σ_{H0}\\sqrt{K_A K_v K_{Hβ} K_{Hα}},\\quad b_{eH} = 0.85 b

    .. math::
        σ_F = \\frac{F_{mt}}{b\\, m_{mn}} Y_F Y_S Y_{LS}\\, K_A K_v K_{Fβ} K_{Fα}

    K_Hβ = 1.5·K_Hβ-be (method C), K_Fβ = K_Hβ/K_F0 with K_F0 = 1 (no cutter radius
    given); Z_β = √cos β_m.  Y_F, Y_S at the outer point of single contact of the virtual
    gear ([ISO6336-3] method B, called), which carries the load-sharing of Y_ε; the
    bevel spiral factor Y_BS = 1.  [ISO10300-2], [ISO10300-3] method B1; [ISO10300-1] §7.
    """
    ld, mt, p, rt = inp.load, inp.material, inp.pair, inp.rating
    K_be = MOUNTING_FACTOR[ld.mounting]
    K_Hb = 1.5 * K_be
    K_Fb = K_Hb
    Z_E = part2.z_e(mt.E, mt.nu, mt.E, mt.nu)
    Z_H = part2.z_h(g.beta_vb, g.alpha_vt, g.alpha_vt)
    Z_MB, Z_LS = mid_zone_factor(g), load_sharing(g)
    Z_beta = math.sqrt(math.cos(g.beta_m))
    b_eH = 0.85 * g.b
    s_H0 = (math.sqrt(f.F_mt / (g.pinion.d_v * b_eH) * (g.u_v + 1.0) / g.u_v)
            * Z_MB * Z_H * Z_E * Z_LS * Z_beta * Z_K)
    K = ld.K_A * ld.K_v
    s_H = s_H0 * math.sqrt(K * K_Hb * ld.K_alpha)
    members = []
    for i, m in enumerate(g.members):
        tf = part3.tooth_form(m.z_v, m.x, g.m_nm, g.alpha_n, g.beta_m, g.beta_vb, m.d_v,
                              m.d_va, g.eps_va, (p.ha + p.c) * g.m_nm, p.rho_a0 * g.m_nm)
        s_F = (f.F_mt / (g.b * g.m_nm) * tf.Y_F * tf.Y_S * Z_LS ** 2
               * K * K_Fb * ld.K_alpha)
        members.append(IsoMember(tf.Y_F, tf.Y_S, s_F, Y_ST * mt.sigma_Flim[i] / rt.S_Fmin,
                                 mt.sigma_Hlim[i] / s_H, Y_ST * mt.sigma_Flim[i] / s_F))
    return IsoRating(K_be, K_Hb, K_Fb, Z_E, Z_H, Z_MB, Z_LS, Z_beta, Z_K, Z_LS ** 2, b_eH,
                     s_H0, s_H, *members)


# ----------------------------------------------------------------------------- GOST 21354


@dataclass(frozen=True)
class GostMember:
    z_vn: float
    Y_FS: float
    sigma_F: float
    S_H: float
    S_F: float


@dataclass(frozen=True)
class GostRating:
    """[GOST21354] on the virtual spur pair with θ_H, θ_F ([Dunaev] §2.6)."""

    theta_H: float
    theta_F: float
    K_H: float
    K_F: float
    Z_E: float
    Z_H: float
    sigma_H: float
    pinion: GostMember
    wheel: GostMember


def theta_factors(spiral: bool, hardness: str, u: float) -> tuple[float, float]:
    """θ_H, θ_F: the load capacity of a bevel pair over that of its virtual spur pair.

    .. math:: θ = a + b\\,u \\text{ (circular teeth, :data:`THETA`)},\\quad θ = 0.85
              \\text{ (straight teeth)}

    [Dunaev] §2.6 table 2.6; [Ivanov] ch. 4.

    >>> theta_factors(True, "both_hard", 2.0)
    (1.11, 0.87)
    """
    if not spiral:
        return THETA_STRAIGHT, THETA_STRAIGHT
    (aH, bH), (aF, bF) = THETA[hardness]
    return round(aH + bH * u, 10), round(aF + bF * u, 10)


def gost_rating(inp: Inputs, g: Geometry, f: Forces) -> GostRating:
    """σ_H and σ_F through the virtual spur pair ([GOST21354] formulas, called):

    .. math::
        σ_H = Z_E Z_H \\sqrt{\\frac{F_{mt} K_H (u_v + 1)}{θ_H\\, b\\, d_{v1} u_v}},\\quad
        σ_F = \\frac{F_{mt} K_F}{θ_F\\, b\\, m_{nm}} Y_{FS}(z_{vn}, x)

    K_H = K_F = K_A K_v K_Hβ K_Hα (K_Hβ as :func:`iso_rating`), Z_H of the spur pair
    (α_n, β = 0: the circular-teeth gain is in θ_H), Z_ε = 1, z_vn = z/(cos δ cos³β_m);
    at Σ = 90° (u_v + 1)/(d_v1 u_v) = √(u² + 1)/(u d_m1), the handbook form.
    [Dunaev] §2.6; [GOST21354].
    """
    ld, mt, p = inp.load, inp.material, inp.pair
    th_H, th_F = theta_factors(p.spiral, mt.hardness, g.u)
    K = ld.K_A * ld.K_v * 1.5 * MOUNTING_FACTOR[ld.mounting] * ld.K_alpha
    Z_E = G.z_e(mt.E, mt.nu, mt.E, mt.nu)
    Z_H = G.z_h(0.0, g.alpha_n, g.alpha_n)
    s_H = G.sigma_h(Z_E, Z_H, 1.0, f.F_mt, K, g.u_v, th_H * g.b, g.pinion.d_v)
    members = []
    for i, m in enumerate(g.members):
        z_vn = m.z / (math.cos(m.delta) * math.cos(g.beta_m) ** 3)
        Y = G.y_fs(z_vn, m.x)
        s_F = G.sigma_f(f.F_mt, K, th_F * g.b, g.m_nm, Y, 1.0, 1.0)
        members.append(GostMember(z_vn, Y, s_F, mt.sigma_Hlim[i] / s_H,
                                  Y_ST * mt.sigma_Flim[i] / s_F))
    return GostRating(th_H, th_F, K, K, Z_E, Z_H, s_H, *members)
