"""Phase bending and contact stresses at one contact point (Korotkin 2017, eq. (3), (4)),
the contact-ellipse size that gives ψ, and the inverse: the force that a printed stress
needs (the consistency check of [Korotkin2017] fig. 1).

Units: N, mm, MPa.  F is the (transverse tangential) force carried by the point, as in
Korotkin's system (2) whose forces add up to F_tΣ = 2000·T2/d2.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.novikov.factors import Y_A, clamp_psi, k_f, k_h, k_psi
from geardesign.novikov.tables import SIGMA_H_CONST


def reduced_modulus(E: float, nu: float) -> float:
    """E* = E/(2(1 − ν²)) of two equal elastic bodies [MPa] (Hertz; steel–steel with
    E = 2.1·10⁵ MPa, ν = 0.3: 115 385 MPa).

    Example: steel–steel, E = 2.1·10⁵ MPa, ν = 0.3:

    >>> round(reduced_modulus(2.1e5, 0.3))
    115385
    """
    return E / (2.0 * (1.0 - nu * nu))


def ellipse_coefficient(rho_p: float, l_k: float, alpha_k: float, E_star: float) -> float:
    """k_a [mm/√N] in a = k_a·√F: the semi-major axis of the contact patch (along the
    tooth) of a run-in Novikov contact, taken as the Hertz half-width of a line contact of
    length l_k under the normal force F/cos α_k with the lengthwise radius ρ_p:

    .. math:: a = \\sqrt{\\frac{4 (F/\\cos α_k) ρ_p}{π l_k E^*}}

    Assumption of [Korotkin2017] eq. (4) (Korotkin 2017 does not give a); flagged in reports.
    """
    return math.sqrt(4.0 * rho_p / (math.pi * l_k * E_star * math.cos(alpha_k)))


def psi_of_force(F: float, k_a: float, b_w: float) -> float:
    """ψ = a/b_w for the force F [N] (unclamped)."""
    return k_a * math.sqrt(max(F, 0.0)) / b_w


def sigma_F(F: float, m: float, Y_v: float, t: float, psi: float, Y_a: float = Y_A) -> float:
    """Phase bending stress at a contact point, Korotkin 2017 eq. (3):

    .. math:: σ_{Fji} = Y_{vj}\\,Y_{aji}\\,K_{Fji}\\,F_{ji}/m^2

    Parameters: F [N]; m normal module [mm]; Y_v form factor of the loaded addendum's gear;
    t, ψ (K_F from polynomial (6), ψ clamped); Y_a (1, see :data:`factors.Y_A`).
    Returns σ_F [MPa].
    """
    if F <= 0.0:
        return 0.0
    return Y_v * Y_a * k_f(t, psi) * F / (m * m)


def sigma_H_base(F: float, l_k: float, rho_p: float, alpha_k: float) -> float:
    """The part of eq. (4) without K_ψ·K_H: 19.93·l_k^−1.074·(F/cos α_k)^0.69·ρ_p^−0.31."""
    c, a, b, r = SIGMA_H_CONST
    if F <= 0.0:
        return 0.0
    return c * l_k ** a * (F / math.cos(alpha_k)) ** b * rho_p ** r


def sigma_H(F: float, l_k: float, rho_p: float, alpha_k: float, t: float, psi: float) -> float:
    """Phase (effective) contact stress at a contact point, Korotkin 2017 eq. (4) in the
    reconstructed reading of [Korotkin2017] eq. (4):

    .. math:: σ_{Hji} = 19.93\\,l_k^{-1.074}\\,(F_{ji}/\\cos α_k)^{0.69}\\,ρ_p^{-0.31}
              \\,K_{ψi}\\,K_{Hji}

    Parameters: F [N]; l_k = l_k*·m [mm] (the run-in working length, read as l_k);
    ρ_p reduced lengthwise radius of curvature [mm]; α_k [rad]; t, ψ (K_ψ eq. (5) and
    K_H Table 4, ψ clamped).  Returns σ_H [MPa] (steel pair: 19.93 contains E^0.31).
    """
    if F <= 0.0:
        return 0.0
    return sigma_H_base(F, l_k, rho_p, alpha_k) * k_psi(psi) * k_h(t, psi)


@dataclass(frozen=True)
class BackSolution:
    """Force that reproduces a given stress at a given point, with the ψ it implies."""

    F: float
    psi: float


def force_for_sigma_H(sigma: float, t: float, l_k: float, rho_p: float, alpha_k: float,
                      k_a: float, b_w: float) -> BackSolution:
    """Invert eq. (4): the force F at a point at t that gives the contact stress ``sigma``,
    with ψ = k_a√F/b_w consistent (fixed point; ψ clamped in the factors).

    .. math:: F = \\cos α_k \\left(\\frac{σ_H}{19.93\\,l_k^{-1.074}ρ_p^{-0.31}K_ψ K_H}
              \\right)^{1/0.69}

    Used for the consistency check of the two stresses printed by Korotkin 2017
    ([Korotkin2017] fig. 1: about 75.7 kN for σ_H = 1111.429 MPa).
    """
    c, a, b, r = SIGMA_H_CONST
    psi = 0.05
    F = 0.0
    for _ in range(100):
        psi_c = clamp_psi(psi)
        base = c * l_k ** a * rho_p ** r * k_psi(psi_c) * k_h(t, psi_c)
        F_new = math.cos(alpha_k) * (sigma / base) ** (1.0 / b)
        psi_new = psi_of_force(F_new, k_a, b_w)
        if abs(F_new - F) <= 1e-9 * F_new:
            return BackSolution(F_new, psi_new)
        F, psi = F_new, psi_new
    return BackSolution(F, psi)


def force_for_sigma_F(sigma: float, t: float, m: float, Y_v: float, k_a: float, b_w: float,
                      Y_a: float = Y_A) -> BackSolution:
    """Invert eq. (3): the force at a point at t that gives the bending stress ``sigma``
    (ψ consistent with F, clamped in K_F):  F = σ_F·m²/(Y_v·Y_a·K_F)."""
    psi = 0.05
    F = 0.0
    for _ in range(100):
        F_new = sigma * m * m / (Y_v * Y_a * k_f(t, clamp_psi(psi)))
        psi_new = psi_of_force(F_new, k_a, b_w)
        if abs(F_new - F) <= 1e-9 * F_new:
            return BackSolution(F_new, psi_new)
        F, psi = F_new, psi_new
    return BackSolution(F, psi)
