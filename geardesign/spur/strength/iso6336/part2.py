"""ISO 6336-2:2019 — surface durability (pitting): zone, elasticity, contact ratio, helix
and single pair contact factors, the contact stress, the life factor Z_NT and the influence
factors Z_L, Z_v, Z_R, Z_W, Z_X of the permissible contact stress.

Pure functions; stresses MPa, lengths mm, roughness µm, viscosity mm²/s, speed m/s, angles
rad.  Where GOST 21354-87 uses the same formula (Z_E, Z_H, Z_ε) the function keeps its ISO
clause and calls the one implementation in :mod:`geardesign.spur.strength.gost21354`.

Written with :mod:`geardesign.core.xp` where the rating of a pair needs it: numbers (the
calculator) or numpy arrays of candidates (the sweep kernel) through one formula; material
types, σ_Hlim and the lubricant are the same for every candidate.
"""

from __future__ import annotations

import math

from geardesign.core import xp
from geardesign.spur.strength import gost21354
from geardesign.spur.strength.iso6336 import tables as T


def z_e(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """Elasticity factor Z_E [√MPa] of two materials, each with its own E [MPa] and ν.
    [ISO6336-2] (Z_E); the formula of :func:`.gost21354.z_e`.

    >>> round(z_e(2.06e5, 0.3, 2.06e5, 0.3), 3)
    189.812
    """
    return gost21354.z_e(E1, nu1, E2, nu2)


def z_h(beta_b: float, alpha_t: float, alpha_wt: float) -> float:
    """Zone factor Z_H = √(2cos β_b cos α_wt/(cos²α_t sin α_wt)).  [ISO6336-2] (Z_H);
    the formula of :func:`.gost21354.z_h`."""
    return gost21354.z_h(beta_b, alpha_t, alpha_wt)


def z_eps(eps_alpha: float, eps_beta: float, helical: bool) -> float:
    """Contact ratio factor Z_ε: √((4 − ε_α)/3) for spur gears, √((4 − ε_α)(1 − ε_β)/3 +
    ε_β/ε_α) for ε_β < 1, √(1/ε_α) for ε_β ≥ 1.  ``helical`` comes from the helix angle
    of the input (β > 0), not from a computed ε_β.  [ISO6336-2] (Z_ε); the formula of
    :func:`.gost21354.z_eps`."""
    return gost21354.z_eps(eps_alpha, xp.where(helical, eps_beta, 0.0))


def z_beta(beta: float) -> float:
    """Helix angle factor Z_β = 1/√cos β.  [ISO6336-2] (Z_β).

    >>> round(z_beta(math.radians(15.8)), 5)
    1.01944
    """
    return 1.0 / xp.sqrt(xp.cos(beta))


def _m(tan_a_wt: float, da1: float, db1: float, z1: float, da2: float, db2: float, z2: float,
       eps_alpha: float) -> float:
    s1 = xp.sqrt((da1 / db1) ** 2 - 1.0) - 2.0 * math.pi / z1
    s2 = xp.sqrt((da2 / db2) ** 2 - 1.0) - (eps_alpha - 1.0) * 2.0 * math.pi / z2
    return tan_a_wt / xp.sqrt(s1 * s2)


def single_pair_factors(alpha_wt: float, d_a: tuple[float, float], d_b: tuple[float, float],
                        z: tuple[int, int], eps_alpha: float, eps_beta: float, helical: bool,
                        internal: bool = False) -> tuple[float, float, float, float]:
    """Single pair tooth contact factors (Z_B, Z_D) and the auxiliary M1, M2.

    .. math::
        M_1 = \\frac{\\tan α_{wt}}{\\sqrt{\\left[\\sqrt{d_{a1}^2/d_{b1}^2 - 1} - 2π/z_1\\right]
        \\left[\\sqrt{d_{a2}^2/d_{b2}^2 - 1} - (ε_α - 1)2π/z_2\\right]}}

    and M2 with the indices exchanged.  Spur gears: Z_B = max(1, M1), Z_D = max(1, M2);
    ε_β ≥ 1: 1; 0 < ε_β < 1: M − ε_β(M − 1), not below 1.  An internal pair has Z_D = 1
    and its M1 from the internal gear's tip circle taken with negative z and diameters.
    [ISO6336-2] (Z_B, Z_D).
    """
    t = xp.tan(alpha_wt)
    if internal:
        M1 = _m(t, d_a[0], d_b[0], z[0], -d_a[1], -d_b[1], -z[1], eps_alpha)
        M2 = 1.0
    else:
        M1 = _m(t, d_a[0], d_b[0], z[0], d_a[1], d_b[1], z[1], eps_alpha)
        M2 = _m(t, d_a[1], d_b[1], z[1], d_a[0], d_b[0], z[0], eps_alpha)

    def f(M: float) -> float:
        return xp.where(helical, xp.where(eps_beta >= 1.0, 1.0,
                                          xp.maximum(1.0, M - eps_beta * (M - 1.0))),
                        xp.maximum(1.0, M))

    return f(M1), (1.0 if internal else f(M2)), M1, M2


def nominal_contact_stress(Z_H: float, Z_E: float, Z_eps: float, Z_beta: float, F_t: float,
                           d1: float, b: float, u: float, internal: bool = False) -> float:
    """Nominal contact stress at the pitch point σ_H0 [MPa].

    .. math:: σ_{H0} = Z_H Z_E Z_ε Z_β\\sqrt{\\frac{F_t}{d_1 b}\\frac{u + 1}{u}}

    F_t [N] at the reference circle, d1, b [mm], u = z2/z1 (an internal pair: u − 1 over
    u, the standard's negative u).  [ISO6336-2] (σ_H0).
    """
    s = -1.0 if internal else 1.0
    return Z_H * Z_E * Z_eps * Z_beta * xp.sqrt(F_t / (d1 * b) * (u + s) / u)


def contact_stress(Z_BD: float, sigma_H0: float, K_A: float, K_gamma: float, K_v: float,
                   K_Hbeta: float, K_Halpha: float) -> float:
    """Contact stress σ_H = Z_B(Z_D)·σ_H0·√(K_A K_γ K_v K_Hβ K_Hα) [MPa].  [ISO6336-2] (σ_H)."""
    return Z_BD * sigma_H0 * xp.sqrt(K_A * K_gamma * K_v * K_Hbeta * K_Halpha)


# ----------------------------------------------------------------------------- life


def life_curve(points: tuple[tuple[float, float], ...], N_L: float, long_life: float) -> float:
    """A life factor on a log–log scale through ``points`` (N, factor), continued from the
    last point (the reference, factor 1) to ``long_life`` at 10¹⁰ cycles and constant
    beyond; constant below the first (static) point.  [ISO6336-2] (Z_NT);
    [ISO6336-3] (Y_NT)."""
    pts = points + ((T.N_LONG_LIFE, long_life),)
    out = pts[-1][1]                       # N_L >= the last point
    for (n0, y0), (n1, y1) in reversed(list(zip(pts, pts[1:]))):
        N = xp.clip(N_L, n0, n1)           # each segment's formula inside its own range
        k = xp.log(N / n0) / math.log(n1 / n0)
        out = xp.where(N_L <= n1, y0 * (y1 / y0) ** k, out)
    return xp.where(N_L <= pts[0][0], pts[0][1], xp.where(N_L >= pts[-1][0], pts[-1][1], out))


def z_nt(material: str, N_L: float, limited_pitting: bool = False,
         optimum: bool = False) -> float:
    """Life factor for contact Z_NT of a material type at N_L load cycles.

    Static, reference and long-life points per material group (``tables.ZNT_CURVES``);
    reference N_L = 5·10⁷ for St, V, GGG (perl., bai.), GTS, Eh, IF (10⁹ when limited
    pitting is permitted), 2·10⁶ for nitrided steels and grey iron; at 10¹⁰ the factor is
    0.85, or 1.0 with optimum lubrication, material, manufacturing and experience.
    [ISO6336-2] (Z_NT, table of life factors).

    >>> round(z_nt("Eh", 1.08e9), 3)
    0.91
    """
    group = T.ZNT_GROUP[material]
    if limited_pitting and group == "steel":
        group = "limited_pitting"
    return life_curve(T.ZNT_CURVES[group], N_L, T.LONG_LIFE["optimum" if optimum else "normal"])


def reference_cycles_contact(material: str, limited_pitting: bool = False) -> tuple[float, float]:
    """(N_L static, N_L reference) of the contact S-N curve of a material type (load
    cycles; ``limited``: limited pitting permitted).  [ISO6336-2] (Z_NT, table of life factors)."""
    group = T.ZNT_GROUP[material]
    if limited_pitting and group == "steel":
        group = "limited_pitting"
    pts = T.ZNT_CURVES[group]
    return pts[0][0], pts[-1][0]


def interpolated(value_ref: float, N_L: float, N_static: float, N_ref: float,
                 value_static: float = 1.0) -> float:
    """An influence factor (Z_L, Z_v, Z_R, Z_W, Z_X; Y_δrelT, Y_RrelT, Y_X) at N_L cycles:
    its static value (1 unless the standard gives another) at and below the static point,
    its reference value at and beyond the reference point, interpolated on log–log scales
    between.  [ISO6336-2] (influence factors in the limited life range); [ISO6336-3]
    likewise."""
    N = xp.clip(N_L, N_static, N_ref)
    k = xp.log(N / N_static) / math.log(N_ref / N_static)
    return xp.where(N_L >= N_ref, value_ref,
                    xp.where(N_L <= N_static, value_static,
                             value_static * (value_ref / value_static) ** k))


# ----------------------------------------------------------------------------- influence


def c_zl(sigma_Hlim: float) -> float:
    """C_ZL = 0.83 below 850 MPa, 0.08(σ_Hlim − 850)/350 + 0.83 up to 1200 MPa, 0.91 above.
    [ISO6336-2] (Z_L)."""
    s = min(max(sigma_Hlim, 850.0), 1200.0)
    return 0.08 * (s - 850.0) / 350.0 + 0.83


def z_l(sigma_Hlim: float, nu40: float) -> float:
    """Lubricant factor Z_L = C_ZL + 4(1 − C_ZL)/(1.2 + 134/ν40)², ν40 [mm²/s] the kinematic
    viscosity at 40 °C; σ_Hlim the smaller of the pair.  [ISO6336-2] (Z_L).

    >>> round(z_l(1500.0, 320.0), 4)
    1.0474
    """
    c = c_zl(sigma_Hlim)
    return c + 4.0 * (1.0 - c) / (1.2 + 134.0 / nu40) ** 2


def z_v(sigma_Hlim: float, v: float) -> float:
    """Velocity factor Z_v = C_Zv + 2(1 − C_Zv)/√(0.8 + 32/v), C_Zv = C_ZL + 0.02, v [m/s]
    at the reference circle.  [ISO6336-2] (Z_v).

    >>> round(z_v(1500.0, 2.664), 4)
    0.9691
    """
    c = c_zl(sigma_Hlim) + 0.02
    return c + 2.0 * (1.0 - c) / xp.sqrt(0.8 + 32.0 / v)


def rho_red(d_b1: float, d_b2: float, alpha_wt: float, internal: bool = False) -> float:
    """Relative radius of curvature at the pitch point ρ_red = ρ1ρ2/(ρ2 ± ρ1) [mm],
    ρ = 0.5d_b tan α_wt (transverse section).  [ISO6336-2] (Z_R)."""
    r1 = 0.5 * d_b1 * xp.tan(alpha_wt)
    r2 = 0.5 * d_b2 * xp.tan(alpha_wt)
    return r1 * r2 / (r2 - r1 if internal else r1 + r2)


def z_r(sigma_Hlim: float, Rz1: float, Rz2: float, rho: float) -> float:
    """Roughness factor Z_R = (3/R_z10)^C_ZR.

    R_z10 = ½(R_z1 + R_z2)·(10/ρ_red)^(1/3) [µm]; C_ZR = 0.15 below 850 MPa,
    0.32 − 0.0002σ_Hlim up to 1200 MPa, 0.08 above.  [ISO6336-2] (Z_R).
    """
    Rz10 = 0.5 * (Rz1 + Rz2) * (10.0 / rho) ** (1.0 / 3.0)
    s = min(max(sigma_Hlim, 850.0), 1200.0)
    return (3.0 / Rz10) ** (0.32 - 0.0002 * s)


def z_w(HB_soft: float, Rz_hard: float | None = None, Rz_soft: float | None = None,
        rho: float | None = None, v: float | None = None, nu40: float | None = None) -> float:
    """Work hardening factor Z_W of a through-hardened gear (HB 130…470) meshing with a
    surface-hardened mate.

    .. math:: Z_W = \\left(1.2 - \\frac{HB - 130}{1700}\\right)\\left(\\frac{3}{R_{zH}}
              \\right)^{0.15},\\quad R_{zH} = \\frac{R_{z1}(10/ρ_{red})^{0.33}
              (R_{z1}/R_{z2})^{0.66}}{(ν_{40} v/1500)^{0.33}},\\; 3 ≤ R_{zH} ≤ 16\\ µm

    HB the Brinell hardness of the softer gear (clamped to 130…470), R_z1 [µm] the flank
    roughness of the surface-hardened gear, R_z2 that of the through-hardened one, ρ_red
    [mm] the relative radius of curvature at the pitch point (:func:`rho_red`), v [m/s] the
    pitch line velocity, ν40 [mm²/s] the oil's viscosity at 40 °C.  [ISO6336-2] clause on
    Z_W, "surface-hardened with through-hardened"; the curvature enters as (10/ρ_red)^0.33,
    the same way as in the mean relative roughness R_z10 of Z_R (:func:`z_r`), so that a
    large, gently curved contact has the smaller equivalent roughness; transcribed alike in
    [PythonGearbox2020] (``__zw``).  Without roughness data (``Rz_hard=None``) the factor is
    1.2 − (HB − 130)/1700, the form the 2006 edition prints ([KISSsoft2017]).

    >>> round(z_w(240.0), 3)
    1.135
    >>> round(z_w(240.0, 4.8, 8.0, 159.4, 1.6, 220.0), 3)   # R_zH below 3 µm: 3
    1.135
    """
    hb = min(max(HB_soft, 130.0), 470.0)
    base = 1.2 - (hb - 130.0) / 1700.0
    if Rz_hard is None:
        return base
    RzH = Rz_hard * (10.0 / rho) ** 0.33 * (Rz_hard / Rz_soft) ** 0.66 / (v * nu40 / 1500.0) ** 0.33
    RzH = xp.clip(RzH, 3.0, 16.0)
    return base * (3.0 / RzH) ** 0.15


def z_x(material: str, m_n: float) -> float:
    """Size factor for contact Z_X = 1: [ISO6336-2] (Z_X) takes it as 1 where no
    experience with larger gears says otherwise; a designer gives another value under
    ``[iso_factors]``."""
    return 1.0


def safety(limit: float, sigma: float) -> float:
    """Safety factor S = σ_G/σ (limit stress including every life and influence factor
    over the working stress).  [ISO6336-2] (S_H); [ISO6336-3] (S_F)."""
    return limit / sigma
