"""GOST 21354-87, contact strength: the elasticity, zone and contact ratio factors, the
contact stress σ_H, the life, roughness, velocity and size factors of the permissible
contact stress σ_HP, and the design centre distance.

Pure functions written with :mod:`geardesign.core.xp` (numbers or arrays of candidates);
units and sources (the ZPCIL and DANNYE programs checked against [GOST21354]) as
:mod:`.formulas` says.
"""

from __future__ import annotations

import math

from geardesign.core import xp
from geardesign.spur.strength.gost21354 import tables as T


# ----------------------------------------------------------------------------- contact


def z_e(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """Elasticity factor Z_E [√MPa].

    .. math:: Z_E = \\sqrt{\\frac{1}{π\\,[(1-ν_1^2)/E_1 + (1-ν_2^2)/E_2]}}

    189.8 √MPa for two steels with E = 2.06·10⁵ MPa, ν = 0.3 (GOST 21354-87 tabulates 190).
    References: [GOST21354] table 6 item 1 (per [ZPCIL] ``CONTAU.h``); [ISO6336-2] eq. (4).

    >>> round(z_e(2.06e5, 0.3, 2.06e5, 0.3), 1)
    189.8
    """
    return xp.sqrt(1.0 / (math.pi * ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)))


def z_h(beta_b: float, alpha_t: float, alpha_tw: float) -> float:
    """Zone factor Z_H, to be used with F_t and d at the reference circle.

    .. math:: Z_H = \\frac{1}{\\cos α_t}\\sqrt{\\frac{2\\cos β_b}{\\tan α_{tw}}}

    (2.495 for α = 20°, x_Σ = 0, β = 0.)  References: [GOST21354]; [ZPCIL] ``GEOM.h``;
    [ZPCIL] CONTAU.h (the textbook pairing with d_w1 understates σ_H of
    shifted pairs by cos α_tw/cos α_t).
    """
    return xp.sqrt(2.0 * xp.cos(beta_b) / xp.tan(alpha_tw)) / xp.cos(alpha_t)


def z_eps(eps_alpha: float, eps_beta: float) -> float:
    """Contact ratio factor Z_ε.

    .. math::
        Z_ε = \\sqrt{(4-ε_α)/3} \\;(ε_β = 0);\\quad
        \\sqrt{(4-ε_α)(1-ε_β)/3 + ε_β/ε_α} \\;(0 < ε_β < 1);\\quad
        \\sqrt{1/ε_α} \\;(ε_β \\ge 1)

    References: [GOST21354]; [ZPCIL] ``GEOM.h``; [GOST21354].
    """
    spur = xp.sqrt(xp.maximum((4.0 - eps_alpha) / 3.0, 0.0))
    low = xp.sqrt(xp.maximum((4.0 - eps_alpha) * (1.0 - eps_beta) / 3.0 + eps_beta / eps_alpha,
                             0.0))
    return xp.where(eps_beta <= 0.0, spur,
                    xp.where(eps_beta < 1.0, low, xp.sqrt(1.0 / eps_alpha)))


def sigma_h(Z_E: float, Z_H: float, Z_eps: float, F_t: float, K_H: float, u: float,
            b_w: float, d1: float, internal: bool = False) -> float:
    """Contact stress σ_H [MPa] of an external (or internal) pair.

    .. math:: σ_H = Z_E Z_H Z_ε \\sqrt{\\frac{F_{tH} K_H (u \\pm 1)}{b_w d_1 u}}

    F_tH = 2000·T1/d1 [N] at the reference circle, K_H = K_A K_Hv K_Hβ K_Hα, b_w [mm];
    "+" for an external pair, "−" for an internal pair (``internal=True``, u = z2/z1 of
    the internal gear over the pinion): the reduced curvature of concave and convex flanks.
    References: [GOST21354]; [ZPCIL] ``CONTAU.h`` (``FTH = 2000*TQ/D1``, ``DSH = D1``);
    ISO 6336-2 §5 (u < 0 for internal gears); [GOST21354].
    """
    s = -1.0 if internal else 1.0
    return Z_E * Z_H * Z_eps * xp.sqrt(F_t * K_H * (u + s) / (b_w * d1 * u))


def n_hg(HB: float) -> float:
    """Base number of contact stress cycles N_HG = 30·HB^2.4 ≤ 1.2·10⁸ (HB Brinell).

    References: [GOST21354] p. 24 ([ZPCIL] ``CONTAU.h`` «ГОСТ стр.24»; MATLAB [DANNYE]).
    At 200 HB about 10⁷ cycles, at the cap from about 560 HB:

    >>> round(n_hg(200.0) / 1e7, 3), n_hg(600.0)
    (0.999, 120000000.0)
    """
    return xp.minimum(30.0 * HB ** 2.4, 1.2e8)


def z_n(N_HG: float, N_HE: float, Z_N_max: float) -> float:
    """Life factor for contact Z_N.

    .. math:: Z_N = (N_{HG}/N_{HE})^{1/6} \\le Z_{N,max} \\;(N_{HE} \\le N_{HG});\\quad
              (N_{HG}/N_{HE})^{1/20} \\ge 0.75 \\;(N_{HE} > N_{HG})

    Z_N,max = 2.6 for a homogeneous structure, 1.8 for a hardened surface.
    References: [GOST21354]; [ZPCIL] ``ZLIFE.h``, ``CONTAU.h`` (floor 0.75);
    [ZPCIL] SGMHLB.h, CONTAU.h; [DANNYE].
    """
    low = N_HE <= N_HG
    z = (N_HG / N_HE) ** xp.where(low, 1.0 / 6.0, 1.0 / 20.0)
    return xp.where(low, xp.minimum(z, Z_N_max), xp.maximum(z, 0.75))


def z_v(v: float, soft: bool) -> float:
    """Velocity factor Z_v: 1 for v ≤ 5 m/s, else 0.85·v^0.1 (≤ 350 HB) or 0.925·v^0.05.

    References: [GOST21354]; [ZPCIL] ``ZV.h``; [ZPCIL] (Z_v row).
    """
    if xp.scalar(soft):    # one material: only its branch
        fast = 0.85 * v ** 0.1 if soft else 0.925 * v ** 0.05
    else:
        fast = xp.where(soft, 0.85 * v ** 0.1, 0.925 * v ** 0.05)
    return xp.where(v <= 5.0, 1.0, fast)


def z_r(Ra: float) -> float:
    """Roughness factor Z_R of the flanks from the arithmetic mean roughness Ra [µm]:
    1.0 (Ra ≤ 1.25), 0.95 (≤ 2.5), 0.9 (coarser).  [GOST21354] (the Z_R table,
    ``tables.Z_R_TABLE``).

    >>> z_r(0.8), z_r(2.0), z_r(3.2)
    (1.0, 0.95, 0.9)"""
    for limit, value in T.Z_R_TABLE:
        if Ra <= limit:
            return value
    return T.Z_R_TABLE[-1][1]  # pragma: no cover


def z_x(d: float) -> float:
    """Size factor Z_X = sqrt(1.07 − 10⁻⁴·d), between 0.75 and 1 (d [mm]).

    References: [GOST21354]; [ZPCIL] ``CONTAU.h``.
    """
    return xp.minimum(1.0, xp.maximum(0.75, xp.sqrt(xp.maximum(1.07 - 1e-4 * d, 0.0))))


def contact_limit(sigma_Hlim: float, Z_N: float, Z_R: float, Z_v: float, Z_X: float) -> float:
    """Contact endurance limit of the gear as built [MPa]: σ_Hlim·Z_N·Z_R·Z_v·Z_X; divided
    by S_Hmin it is the allowable σ_HP, divided by σ_H the safety factor S_H.
    References: [GOST21354]; [ZPCIL] CONTAU.h."""
    return sigma_Hlim * Z_N * Z_R * Z_v * Z_X


def sigma_hp_pair(s1: float, s2: float, helical: bool) -> float:
    """Allowable contact stress of the pair.

    Spur gears (and helical gears with ε_β < 1): the smaller of the two.  Helical gears
    with ε_β ≥ 1: 0.45(σ_HP1 + σ_HP2), not less than σ_HPmin and not more than
    1.25·σ_HPmin.

    References: [GOST21354], the simplified rule for helical pairs as printed in the textbook
    literature (limit 1.23σ_HPmin); the limit 1.25 is the one of the Fortran line
    ``SGHP=.45*(SGHP1+SGHP2)`` / ``IF(SGHP.GT.1.25*AU)`` that [ZPCIL] ``CONTAU.h`` keeps as a
    comment only (its active routine ``SGHPBE`` integrates along the contact lines).
    """
    low = xp.minimum(s1, s2)
    return xp.where(helical, xp.minimum(xp.maximum(0.45 * (s1 + s2), low), 1.25 * low), low)



# ----------------------------------------------------------------------------- design


def center_distance_estimate(T1: float, u: float, K_Hbeta: float, psi_ba: float,
                             sigma_HP: float, helical: bool) -> float:
    """Design centre distance of an external steel pair [mm].

    .. math:: a_w = K_a (u + 1) \\sqrt[3]{\\frac{T_1 K_{Hβ}}{ψ_{ba} u σ_{HP}^2}}

    K_a = 495 (spur) / 430 (helical) MPa^(1/3) with T1 in N·m (``tables.K_A_DESIGN``).
    References: [GOST21354] (design formula; verify K_a).
    """
    Ka = T.K_A_DESIGN["helical" if helical else "spur"]
    return Ka * (u + 1.0) * (T1 * K_Hbeta / (psi_ba * u * sigma_HP ** 2)) ** (1.0 / 3.0)
