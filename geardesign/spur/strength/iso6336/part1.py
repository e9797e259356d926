"""ISO 6336-1:2019 — general influence factors: tooth stiffness, running-in allowances,
dynamic factor K_v (method B), face load factors K_Hβ (method C) and K_Fβ, transverse load
factors K_Hα and K_Fα.

Pure functions.  Forces N, lengths mm, deviations µm, stiffness N/(mm·µm), speeds min⁻¹,
mass per face width kg/mm, angles rad.  Each function names its clause of [ISO6336-1].

The functions the rating of a pair calls are written with :mod:`geardesign.core.xp`: they
take Python numbers (the calculator) or numpy arrays of candidates (the sweep kernel) with
the same formula; a branch is an ``xp.where`` whose unused side is kept inside its domain.
Material types are strings, the same for every candidate.
"""

from __future__ import annotations

import math

from geardesign.core import xp
from geardesign.spur.strength.iso6336 import tables as T

# ----------------------------------------------------------------------------- stiffness

#: coefficients C1 … C9 of the theoretical single stiffness, [ISO6336-1] 9.3.2 Table 10
_Q = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)


def theoretical_single_stiffness(z_n1: float, z_n2: float | None, x1: float, x2: float) -> float:
    """Theoretical single stiffness c'_th = 1/q' [N/(mm·µm)] of a solid steel pair.

    .. math:: q' = C_1 + \\frac{C_2}{z_{n1}} + \\frac{C_3}{z_{n2}} + C_4 x_1
              + C_5\\frac{x_1}{z_{n1}} + C_6 x_2 + C_7\\frac{x_2}{z_{n2}} + C_8 x_1^2
              + C_9 x_2^2

    z_n virtual numbers of teeth; an internal gear has z_n2 = ∞ (``None``) and its shift x2
    in the ISO 21771 sign (negative for a thicker internal tooth).  [ISO6336-1] 9.3.2,
    eq. (85) and Table 10.

    >>> round(theoretical_single_stiffness(18.905, 114.543, 0.145, 0.0), 3)
    17.856
    """
    C = _Q
    inv2 = 0.0 if z_n2 is None else 1.0 / z_n2
    q = (C[0] + C[1] / z_n1 + C[2] * inv2 + C[3] * x1 + C[4] * x1 / z_n1 + C[5] * x2
         + C[6] * x2 * inv2 + C[7] * x1 * x1 + C[8] * x2 * x2)
    return 1.0 / q


def basic_rack_factor(h_fP1: float, h_fP2: float, alpha_n: float) -> float:
    """Basic rack factor C_B: the mean of both gears'
    [1 + 0.5(1.2 − h_fP/m_n)][1 − 0.02(20° − α_n)] (h_fP/m_n the dedendum coefficient of
    the basic rack, α_n [rad]).  [ISO6336-1] 9.3.4 eq. (88), as corrected by its 2008
    corrigendum."""
    tilt = 1.0 - 0.02 * (20.0 - math.degrees(alpha_n))
    return 0.5 * sum((1.0 + 0.5 * (1.2 - h)) * tilt for h in (h_fP1, h_fP2))


def blank_factor(web_ratio: float | None, rim_ratio: float | None) -> float:
    """Gear blank factor C_R: 1 for solid gears, else 1 + ln(b_s/b)/(5·e^(s_R/(5m_n))) with
    b_s/b in 0.2…1.2 and s_R/m_n ≥ 1 clamped to those ranges.  [ISO6336-1] 9.3.3 eq. (87).

    >>> round(blank_factor(0.25, 5.0), 3)
    0.898
    """
    if web_ratio is None:
        return 1.0
    bs = min(max(web_ratio, 0.2), 1.2)
    sr = xp.maximum(rim_ratio if rim_ratio is not None else 1.0, 1.0)
    return 1.0 + math.log(bs) / (5.0 * xp.exp(sr / 5.0))


C_M = 0.8
"""Correction factor C_M of the single stiffness (solid disc gears). [ISO6336-1] 9.3.1."""


def single_stiffness(c_th: float, C_R: float, C_B: float, beta: float, line_load: float,
                     E_ratio: float = 1.0) -> float:
    """Single stiffness c' = c'_th C_M C_R C_B cos β (E/E_st) [N/(mm·µm)], reduced by
    (K_A F_t/b / 100)^0.25 below 100 N/mm.  [ISO6336-1] 9.3.1 eq. (84)."""
    c = c_th * C_M * C_R * C_B * xp.cos(beta) * E_ratio
    return xp.where(line_load < 100.0, c * xp.minimum(line_load / 100.0, 1.0) ** 0.25, c)


def mesh_stiffness_alpha(c_prime: float, eps_alpha: float) -> float:
    """Mesh stiffness c_γα = c'(0.75ε_α + 0.25) [N/(mm·µm)].  [ISO6336-1] 9.3.5 eq. (90)."""
    return c_prime * (0.75 * eps_alpha + 0.25)


def mesh_stiffness_beta(c_gamma_alpha: float) -> float:
    """Mesh stiffness for K_Hβ, c_γβ = 0.85c_γα.  [ISO6336-1] 9.3.5 eq. (91)."""
    return 0.85 * c_gamma_alpha


# ----------------------------------------------------------------------------- running-in


def running_in_alpha(f_pb: float, material: str, sigma_Hlim: float, v: float) -> float:
    """Running-in allowance y_α [µm] of one gear for the base pitch deviation f_pb [µm].

    St, V, GGG (perl., bai.), GTS: 160/σ_Hlim·f_pb, at most 12800/σ_Hlim for 5 < v ≤ 10 m/s
    and 6400/σ_Hlim above; GG, GGG (ferr.): 0.275f_pb (≤ 22 µm, ≤ 11 µm); surface-hardened:
    0.075f_pb ≤ 3 µm.  A pair of two materials takes the mean (:func:`pair_mean`).
    [ISO6336-1] 8.3.5 eqs. (75)–(77).  At most f_pb (as y_β at most F_βx,
    :func:`running_in_beta`; 160/σ_Hlim > 1 for σ_Hlim < 160 N/mm²)."""
    if material in T.SURFACE_HARDENED:
        return xp.minimum(0.075 * f_pb, 3.0)
    if material in T.CAST_IRON_GREY:
        y = 0.275 * f_pb
        return xp.where(v <= 5.0, y, xp.minimum(y, xp.where(v <= 10.0, 22.0, 11.0)))
    y = xp.minimum(160.0 / sigma_Hlim * f_pb, f_pb)
    return xp.where(v <= 5.0, y,
                    xp.minimum(y, xp.where(v <= 10.0, 12800.0, 6400.0) / sigma_Hlim))


def running_in_beta(F_beta_x: float, material: str, sigma_Hlim: float, v: float) -> float:
    """Running-in allowance y_β [µm] of one gear for the initial misalignment F_βx [µm].

    St, V, GGG (perl., bai.), GTS: 320/σ_Hlim·F_βx, at most 25600/σ_Hlim for 5 < v ≤ 10 m/s
    and 12800/σ_Hlim above; GG, GGG (ferr.): 0.55F_βx (≤ 45 µm, ≤ 22 µm); surface-hardened:
    0.15F_βx ≤ 6 µm.  [ISO6336-1] 7.6.4 eqs. (61)–(63).  At most F_βx: running-in wears
    in no more than the misalignment there is (F_βy = F_βx − y_β >= 0; 320/σ_Hlim > 1 for
    σ_Hlim < 320 N/mm², where eq. (61) would leave a negative F_βy and load factor)."""
    if material in T.SURFACE_HARDENED:
        return xp.minimum(0.15 * F_beta_x, 6.0)
    if material in T.CAST_IRON_GREY:
        y = 0.55 * F_beta_x
        return xp.where(v <= 5.0, y, xp.minimum(y, xp.where(v <= 10.0, 45.0, 22.0)))
    y = xp.minimum(320.0 / sigma_Hlim * F_beta_x, F_beta_x)
    return xp.where(v <= 5.0, y,
                    xp.minimum(y, xp.where(v <= 10.0, 25600.0, 12800.0) / sigma_Hlim))


def pair_mean(y1: float, y2: float) -> float:
    """Allowance of a pair of different materials: the mean of both gears' values.
    [ISO6336-1] 7.6.4 and 8.3.5."""
    return 0.5 * (y1 + y2)


def tip_relief_running_in(sigma_Hlim: float) -> float:
    """Amount of tip relief from running-in C_ay = (σ_Hlim/97 − 18.45)²/18 + 1.5 [µm], used
    for C_a when no tip relief is given.  [ISO6336-1] 6.5.9 eq. (26)."""
    return (sigma_Hlim / 97.0 - 18.45) ** 2 / 18.0 + 1.5


# ----------------------------------------------------------------------------- dynamic factor


def gear_mass(d_a: float, d_f: float, d_b: float, d_i: float, rho: float = T.RHO_STEEL) -> float:
    """Mass per unit face width of one gear reduced to the line of action [kg/mm]:
    m* = (π/8)ρ(1 − q⁴)d_m⁴/d_b², d_m = (d_a + d_f)/2, q = d_i/d_m.  [ISO6336-1] 6.5.9
    eq. (30)."""
    d_m = 0.5 * (d_a + d_f)
    q = d_i / d_m
    return math.pi / 8.0 * rho * (1.0 - q ** 4) * d_m ** 4 / (d_b * d_b)


def reduced_mass(m1: float, m2: float | None, n1: int = 1, n2: int = 1) -> float:
    """Reduced mass of the mesh per face width [kg/mm]:

    .. math:: m_{red} = \\frac{m_1^* m_2^*}{n_2 m_1^* + n_1 m_2^*}

    m1*, m2* the gears' masses per face width reduced to the line of action (:func:`gear_mass`);
    n1, n2 how many meshes of this kind each gear carries.  A pair (n1 = n2 = 1):
    m_red = m1*m2*/(m1* + m2*), [ISO6336-1] 6.5.9 eq. (30).  Planetary gears, the same
    clause: a sun carrying n_P planets vibrates against all of them at once,
    m_red = m_P m_S/(n_P m_P + m_S) (n = n_P for the sun); the ring gear of a planet–ring
    mesh is taken as rigid (``m2=None``: m_red = m1*/n1, the planet's own mass).  An
    internal gear of an ordinary pair is rigid in the same way.
    """
    if m2 is None:
        return m1 / n1
    return m1 * m2 / (n2 * m1 + n1 * m2)


def resonance_speed(z1: int, c_gamma_alpha: float, m_red: float) -> float:
    """Resonance speed of the pinion n_E1 = 30000/(πz1)·√(c_γα/m_red) [min⁻¹].
    [ISO6336-1] 6.5.2 eq. (6)."""
    return 30000.0 / (math.pi * z1) * xp.sqrt(c_gamma_alpha / m_red)


def lower_resonance_limit(line_load: float) -> float:
    """N_S = 0.5 + 0.35√(K_A F_t/(100 b)) below 100 N/mm, else 0.85.  [ISO6336-1] 6.5.3
    eqs. (11), (12)."""
    return xp.where(line_load < 100.0, 0.5 + 0.35 * xp.sqrt(xp.minimum(line_load / 100.0, 1.0)),
                    0.85)


def dynamic_constants(eps_gamma: float) -> tuple[float, ...]:
    """C_v1 … C_v7 of K_v method B by the total contact ratio.  [ISO6336-1] 6.5.9 Table 8."""
    low = eps_gamma <= 2.0
    e = xp.where(low, 3.0, eps_gamma)          # the formulas' domain ε_γ > 2 for both sides
    cv2 = xp.where(low, 0.34, 0.57 / (e - 0.3))
    cv3 = xp.where(low, 0.23, 0.096 / (e - 1.56))
    cv4 = xp.where(low, 0.90, (0.57 - 0.05 * e) / (e - 1.44))
    cv6 = xp.where(low, 0.47, 0.12 / (e - 1.74))
    cv7 = xp.where(eps_gamma <= 1.5, 0.75,
                   xp.where(eps_gamma <= 2.5, 0.125 * xp.sin(math.pi * (eps_gamma - 2.0)) + 0.875,
                            1.0))
    return T.CV1, cv2, cv3, cv4, T.CV5, cv6, cv7


def dynamic_factor(N: float, N_S: float, c_prime: float, f_pb_eff: float, f_f_eff: float,
                   C_a: float, line_load: float, eps_gamma: float,
                   N_main: float = 1.15) -> tuple[float, str]:
    """Dynamic factor K_v by method B and the resonance range it was taken from.

    .. math::
        B_p = \\frac{c' f_{pb,eff}}{K_A F_t/b},\\; B_f = \\frac{c' f_{fα,eff}}{K_A F_t/b},\\;
        B_k = \\left|1 - \\frac{c' C_a}{K_A F_t/b}\\right|

    subcritical N ≤ N_S: K_v = N(C_v1 B_p + C_v2 B_f + C_v3 B_k) + 1; main resonance
    N_S < N ≤ 1.15: C_v1 B_p + C_v2 B_f + C_v4 B_k + 1; supercritical N ≥ 1.5:
    C_v5 B_p + C_v6 B_f + C_v7; between 1.15 and 1.5 interpolated linearly.
    f_pb,eff, f_fα,eff [µm] after running-in, C_a tip relief [µm], K_A F_t/b [N/mm].
    [ISO6336-1] 6.5.4–6.5.7 eqs. (13)–(22).  ``N_main`` the upper end of the main
    resonance range (1.15 in [ISO6336-1]; 1.25 for bevel gears, [ISO10300-1] method B,
    :func:`geardesign.bevel.factors.dynamic_factor`).
    """
    cv1, cv2, cv3, cv4, cv5, cv6, cv7 = dynamic_constants(eps_gamma)
    B_p = c_prime * xp.maximum(f_pb_eff, 0.0) / line_load
    B_f = c_prime * xp.maximum(f_f_eff, 0.0) / line_load
    B_k = abs(1.0 - c_prime * C_a / line_load)
    main = cv1 * B_p + cv2 * B_f + cv4 * B_k + 1.0
    super_ = cv5 * B_p + cv6 * B_f + cv7
    sub, mid = N <= N_S, N <= N_main
    inter = N < 1.5
    width = round(1.5 - N_main, 12)        # 0.35 exactly for ISO 6336-1
    K = xp.where(sub, N * (cv1 * B_p + cv2 * B_f + cv3 * B_k) + 1.0,
                 xp.where(mid, main,
                          xp.where(inter, super_ + (main - super_) * (1.5 - N) / width, super_)))
    rng = xp.where(sub, "subcritical", xp.where(mid, "main resonance",
                                                xp.where(inter, "intermediate", "supercritical")))
    return K, rng


# ----------------------------------------------------------------------------- face load


def shaft_deflection(F_m_b: float, b: float, d1: float, K_prime: float = 0.0,
                     span: float | None = None, offset: float = 0.0,
                     d_shaft: float | None = None) -> float:
    """Equivalent misalignment from the pinion shaft deflection f_sh [µm] (whole torque
    through the mesh, B* = 1):

    .. math:: f_{sh} = \\frac{F_m}{b}\\,0.023\\left[\\left|1 + K'\\frac{l s}{d_1^2}
              \\left(\\frac{d_1}{d_{sh}}\\right)^4 - 0.3\\right| + 0.3\\right]
              \\left(\\frac{b}{d_1}\\right)^2

    F_m/b [N/mm]; K' of the pinion arrangement, l the bearing span, s the pinion offset,
    d_sh the shaft diameter [mm] (s = 0: a pinion midway between its bearings).
    [ISO6336-1] 7.6.3 eqs. (56)–(58).
    """
    term = 0.0
    if offset and span and d_shaft:
        term = K_prime * span * offset / (d1 * d1) * (d1 / d_shaft) ** 4
    return F_m_b * 0.023 * (abs(1.0 + term - 0.3) + 0.3) * (b / d1) ** 2


def initial_misalignment(f_sh: float, f_ma: float, modification: str, F_m_b: float,
                         f_Hbeta: float) -> float:
    """Initial equivalent misalignment F_βx = 1.33B1 f_sh + B2 f_ma [µm], not below
    F_βx,min = max(0.005F_m/b, 0.5f_Hβ).  B1, B2 by the helix modification
    (``tables.HELIX_MODIFICATION``).  [ISO6336-1] 7.6.2 eqs. (53), (54), Table 9."""
    B1, B2 = T.HELIX_MODIFICATION[modification]
    return xp.maximum(xp.maximum(1.33 * B1 * f_sh + B2 * f_ma, 0.005 * F_m_b), 0.5 * f_Hbeta)


def face_load_factor(F_beta_y: float, c_gamma_beta: float, F_m_b: float) -> float:
    """Face load factor for contact K_Hβ by method C.

    .. math:: K_{Hβ} = 1 + \\frac{F_{βy} c_{γβ}}{2F_m/b} \\;(\\le 2), \\qquad
              K_{Hβ} = \\sqrt{\\frac{2F_{βy} c_{γβ}}{F_m/b}} \\;(> 2)

    F_βy = F_βx − y_β [µm], F_m/b = F_t K_A K_v/b [N/mm].  [ISO6336-1] 7.6.1 eqs. (38), (39).

    >>> round(face_load_factor(20.0, 15.0, 500.0), 3)
    1.3
    """
    k = F_beta_y * c_gamma_beta / (2.0 * F_m_b)
    return xp.where(k <= 1.0, 1.0 + k, xp.sqrt(xp.maximum(4.0 * k, 0.0)))


def n_f(b_h: float) -> float:
    """Exponent N_F = (b/h)²/(1 + b/h + (b/h)²), b/h the smaller of both gears' face width
    over tooth depth, not below 3.  [ISO6336-1] 7.7 eq. (64)."""
    r = xp.maximum(b_h, 3.0)
    return r * r / (1.0 + r + r * r)


def face_load_factor_bending(K_Hbeta: float, b_h: float) -> float:
    """K_Fβ = K_Hβ^N_F (:func:`n_f`).  [ISO6336-1] 7.7 eq. (63)."""
    return K_Hbeta ** n_f(b_h)


# ----------------------------------------------------------------------------- transverse load


def transverse_load_factor(eps_gamma: float, c_gamma_alpha: float, f_pb_eff: float,
                           F_tH_b: float) -> float:
    """Transverse load factor K_Hα = K_Fα before its limits (method B).

    .. math::
        K = \\frac{ε_γ}{2}\\left(0.9 + 0.4\\frac{c_{γα}(f_{pb} - y_α)}{F_{tH}/b}\\right)
        \\;(ε_γ \\le 2);\\quad
        0.9 + 0.4\\sqrt{\\frac{2(ε_γ - 1)}{ε_γ}}\\frac{c_{γα}(f_{pb} - y_α)}{F_{tH}/b}
        \\;(ε_γ > 2)

    f_pb − y_α [µm] with f_pb the larger base pitch deviation of the pair (or the profile
    form deviation f_fα where it is larger), F_tH/b = F_t K_A K_v K_Hβ/b [N/mm].
    [ISO6336-1] 8.3.2 eqs. (71), (72).
    """
    t = c_gamma_alpha * xp.maximum(f_pb_eff, 0.0) / F_tH_b
    return xp.where(eps_gamma <= 2.0, 0.5 * eps_gamma * (0.9 + 0.4 * t),
                    0.9 + 0.4 * xp.sqrt(xp.maximum(2.0 * (eps_gamma - 1.0) / eps_gamma, 0.0)) * t)


def transverse_limit_contact(eps_gamma: float, eps_alpha: float, Z_eps: float) -> float:
    """Upper limit of K_Hα: ε_γ/(ε_α Z_ε²) with the ISO 6336-2 Z_ε.  [ISO6336-1] 8.3.4
    eq. (73)."""
    return eps_gamma / (eps_alpha * Z_eps * Z_eps)


def transverse_limit_bending(eps_gamma: float, eps_alpha: float) -> float:
    """Upper limit of K_Fα: ε_γ/(0.25ε_α + 0.75) = ε_γ/(ε_α Y_ε) with the contact ratio
    factor Y_ε = 0.25 + 0.75/ε_α that the limit was derived with.  [ISO6336-1] 8.3.4
    eq. (74)."""
    return eps_gamma / (0.25 * eps_alpha + 0.75)


def limited(k: float, k_max: float) -> tuple[float, bool]:
    """A transverse load factor within 1 ≤ K ≤ K_max; and whether the cap was active.
    The cap is active when it sets the factor: k > K_max ≥ 1 (with K_max < 1 the floor
    sets it to 1, whatever k).  [ISO6336-1] 8.3.4."""
    return xp.maximum(1.0, xp.minimum(k, k_max)), (k > k_max) & (k_max >= 1.0)
