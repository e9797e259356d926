"""Tooth loss factor H_V of a gear mesh (Ohlendorf; Niemann & Winter; ISO/TR 14179-2):
the share of the transmitted power lost by tooth friction per unit coefficient of friction,
for external and internal pairs, and the range of transverse contact ratios it holds for.

References
----------
[ISOTR14179-2] (H_V of Ohlendorf); [Niemann] Band II.
"""

from __future__ import annotations

import math

from geardesign.core import xp


EPS_ALPHA_RANGE = (1.0, 2.0)
"""Transverse contact ratios for which :func:`loss_factor` holds: one or two pairs in
contact, each pair carrying its share of the load."""


def loss_factor(eps_alpha: float, eps_1: float, z1: int, u: float, beta_b: float) -> float:
    """Tooth loss factor H_V of a mesh (Ohlendorf; Niemann & Winter; ISO/TR 14179-2):

    .. math:: H_V = \\frac{π (u + 1)}{z_1 u \\cos β_b}\\,(1 - ε_α + ε_1^2 + ε_2^2),
              \\qquad ε_2 = ε_α - ε_1

    ε_1 = (ρ_a1 − ρ_w1)/p_bt the addendum contact ratio of the pinion; u = z2/z1,
    negative for an internal gear.  The mesh loses P_V = μ_m H_V P (μ_m the mean
    coefficient of friction), so its efficiency is 1 − μ_m H_V.  KISSsoft prints
    H_V = 0.181 and 0.161 for the sun–planet and planet–ring meshes of the NREL 5 MW
    stage 1 (``tests/reference/planetary``).

    Validity.  The closed form is Ohlendorf's mean sliding-to-rolling ratio along the path
    of contact with the load shared equally by the pairs in contact, derived for one or two
    pairs in contact, 1 ≤ ε_α ≤ 2 (:data:`EPS_ALPHA_RANGE`): below 1 the mesh does not
    transmit continuously, above 2 three pairs share the load.  It is used as printed over
    that whole range, also when the pitch point lies in double contact (ε_1 > 1 on the
    planet of the NREL planet–ring mesh: ε_1 = 1.24, ε_2 = 0.04, and KISSsoft prints the
    closed form's 0.161).  Then ½ ≤ 1 − ε_α + ε_1² + ε_2² ≤ 1 − ε_α + ε_α², and ≤ 1 when
    0 ≤ ε_1, ε_2 ≤ 1.  Outside the range the calculators refuse a computed mesh efficiency
    (:func:`loss_factor_applies`); a pair that cannot mesh (inv α_tw ≤ 0) is refused by the
    geometry before.

    Parameters: ε_α, ε_1 [-], z1 [-], u [-] (< 0 internal), β_b [rad].  An external spur pair
    z = 16/24, ε_α = 1.4625, ε_1 = 0.7341 (the example of :mod:`geardesign.drive.losses`):

    >>> round(loss_factor(1.4625, 0.7341, 16, 1.5, 0.0), 4)
    0.1986
    """
    eps_2 = eps_alpha - eps_1
    return math.pi * (u + 1.0) / (z1 * u * xp.cos(beta_b)) * (
        1.0 - eps_alpha + eps_1 * eps_1 + eps_2 * eps_2)


def loss_factor_applies(eps_alpha: float) -> bool:
    """Whether :func:`loss_factor` holds for a mesh of transverse contact ratio ε_α."""
    lo, hi = EPS_ALPHA_RANGE
    return lo <= eps_alpha <= hi


def mesh_loss_factor(geom) -> float:
    """H_V of a spur/internal pair geometry (see :func:`loss_factor`)."""
    rho_w1 = 0.5 * geom.g1.d_w * math.sin(geom.alpha_tw)
    eps_1 = (geom.g1.rho_a - rho_w1) / geom.p_bt
    u = -geom.u if getattr(geom, "internal", False) else geom.u
    return loss_factor(geom.eps_alpha, eps_1, geom.inp.z1, u, geom.beta_b)
