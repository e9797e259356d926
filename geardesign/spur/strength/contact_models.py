"""Contact of two cylinders (line contact) and of a crowned flank (point contact): Hertz
theory and the nonlinear deformation model (W = C_m·σ^n, n = 0.7) of Popov, Mironenko,
Mozgovoi and Savenkov, "Contact strength of gears accounting for the nonlinear relation
between tooth deformations and stresses", Bulletin of NTU "KhPI" 2017 No. 25 ([Popov2017]).

These are informative: the allowables of GOST 21354-87 are calibrated against Hertz
stresses, so the rating uses σ_H of :mod:`.gost21354`; the n = 0.7 model shows the reserve
the paper attributes to the real tooth compliance.  Forces N, lengths mm, stresses MPa;
numbers or arrays of candidates (:mod:`geardesign.core.xp`).
"""

from __future__ import annotations

import math

from geardesign.core import xp


def _k(E: float, nu: float) -> float:
    return (1.0 - nu * nu) / E


def hertz_line(F_n: float, b_w: float, rho: float, E1: float, nu1: float, E2: float,
               nu2: float) -> tuple[float, float]:
    """Hertz line contact: half-width b0 and maximum pressure σ_H.

    .. math:: b_0 = \\sqrt{\\frac{4 F_n ρ (k_1 + k_2)}{π b_w}}, \\qquad
              σ_H = \\sqrt{\\frac{F_n}{π b_w ρ (k_1 + k_2)}}, \\qquad k_i = \\frac{1-ν_i^2}{E_i}

    For equal materials: b0 = 1.522·sqrt(F_n ρ/(E b_w)), σ_H = 0.418·sqrt(F_n E/(ρ b_w))
    with ν = 0.3 (Popov et al. 2017, constants quoted before eq. (10), (11)).
    ρ is the reduced radius of curvature ρ1ρ2/(ρ1 + ρ2).
    """
    k = _k(E1, nu1) + _k(E2, nu2)
    return xp.sqrt(4.0 * F_n * rho * k / (math.pi * b_w)), xp.sqrt(F_n / (math.pi * b_w * rho * k))


def popov_line(F_n: float, b_w: float, rho: float, E1: float, nu1: float, E2: float,
               nu2: float) -> tuple[float, float]:
    """Line contact with the n = 0.7 deformation law: half-width and maximum stress.

    .. math::
        S = \\Big(\\frac{k_1 ρ F_n}{b_w}\\Big)^{0.7} + \\Big(\\frac{k_2 ρ F_n}{b_w}\\Big)^{0.7},
        \\quad b_0 = 1.025\\,S^{5/7}, \\quad σ_H = 0.62\\,\\frac{F_n/b_w}{S^{5/7}}

    References: Popov et al. 2017, eqs. (8) and (9) (exponent 5/7 and the place of b_w
    reconstructed; for equal steels they reduce to the printed
    eqs. (10) b0 = 1.604·sqrt(ρF/(Eb)) and (11) σ_H = 0.396·sqrt(FE/(ρb))).
    """
    S = (_k(E1, nu1) * rho * F_n / b_w) ** 0.7 + (_k(E2, nu2) * rho * F_n / b_w) ** 0.7
    return 1.025 * S ** (5.0 / 7.0), 0.62 * (F_n / b_w) / S ** (5.0 / 7.0)


def crowning_ellipse_ratio(rho: float, b_w: float, crowning: float) -> float:
    """Axis ratio α = b0/b_K = sqrt(ρ_w/R) of the contact ellipse of a crowned flank,
    R = b_w²/(8ΔS) the crowning radius for a crowning depth ΔS at the face ends.

    References: Popov et al. 2017, text before eq. (12) ([Popov2017]: R from the
    sagitta, α as printed "α = b0/b_K = √(ρ_w/R)").
    """
    R = b_w * b_w / (8.0 * crowning)
    return xp.sqrt(rho / R)


def popov_point(F_n: float, rho: float, alpha: float, E1: float, nu1: float, E2: float,
                nu2: float) -> tuple[float, float, float]:
    """Point contact of a crowned pinion with the n = 0.7 law: semi-axes b0, b_K and the
    maximum stress.

    .. math::
        S = \\sum_i \\Big[\\frac{(1-ν_i^2) α ρ F_n}{(α + ν_i) E_i}\\Big]^{0.7},\\quad
        b_0 = 0.946\\,S^{10/21},\\quad b_K = b_0/α,\\quad
        σ_{max} = \\frac{3F_n}{2π b_0 b_K} = \\frac{0.534\\,α F_n}{S^{20/21}}

    References: Popov et al. 2017, eqs. (19), (20), (21), (22).  The paper prints 0.859 in
    eq. (18); 0.889 is needed for its own 0.946 of eq. (19) (0.889^(10/21) = 0.9455), so
    eq. (18) is a misprint.  For equal steels these reduce to the printed eqs. (23)-(25):
    b0 = 1.275·∛(αρF/((α+ν)E)), σ_max = 0.294·∛(α(α+ν)²E²F/ρ²).
    """
    S = sum(((1 - nu * nu) * alpha * rho * F_n / ((alpha + nu) * E)) ** 0.7
            for E, nu in ((E1, nu1), (E2, nu2)))
    b0 = 0.946 * S ** (10.0 / 21.0)
    bK = b0 / alpha
    return b0, bK, 3.0 * F_n / (2.0 * math.pi * b0 * bK)
