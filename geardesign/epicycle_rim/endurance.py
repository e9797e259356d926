"""Endurance limit of the rim as a part and its scatter (paper A, steps 7-9: the
Serensen-Kogaev statistical similarity theory of GOST 25.504-82 applied to the Raba 118/77
ring, [Gutyria2017]).

The factors of GOST 25.504-82 are those of :mod:`geardesign.fatigue.gost25504`; here are
only the rim's own pieces: the stress concentration of the tooth-root fillet, its scatter,
and the composition :func:`part_endurance`.  Probability and life:
:mod:`geardesign.fatigue.probability`.  Stresses in MPa, lengths in mm; reconstructed
pieces (garbled in the printed source) are marked.
"""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.fatigue import gost25504 as g25

ALPHA_EXPONENT = 0.22
"""Exponent of the fillet SCF formula (12); unreadable in the printed source, 0.22 fits the
three values the paper prints from it ([Gutyria2017] eq. (12))."""


def fillet_scf(root_chord: float, fillet_radius: float) -> float:
    """Theoretical stress concentration factor of the tooth-root fillet.

    .. math:: α_σ = (1 + 3.25\\,S/ρ)^{0.22}

    Parameters
    ----------
    root_chord : S, tooth thickness at the root across the fillets [mm].
    fillet_radius : ρ, minimum radius of the fillet (transition curve) [mm].

    References
    ----------
    [Gutyria2017] eq. (12) (their ref. [14]); exponent reconstructed: it reproduces
    α_σ = 3.0 at ρ = 0.2 mm and 2.5 at ρ = 0.46 mm (S = 9 mm) as printed.
    """
    return (1.0 + 3.25 * root_chord / fillet_radius) ** ALPHA_EXPONENT


def fillet_scf_slope(root_chord: float, fillet_radius: float) -> float:
    """|∂α_σ/∂ρ| of :func:`fillet_scf` [1/mm].

    .. math:: \\Big|\\frac{∂α_σ}{∂ρ}\\Big| = 0.22\\,(1 + 3.25S/ρ)^{-0.78}\\,\\frac{3.25 S}{ρ^2}

    References
    ----------
    [Gutyria2017] eq. (15) first factor (printed 3.289 mm⁻¹ for S = 9, ρ = 0.2 mm;
    the reconstructed exponent gives 3.276, 0.4 % lower).
    """
    u = 1.0 + 3.25 * root_chord / fillet_radius
    return ALPHA_EXPONENT * u ** (ALPHA_EXPONENT - 1.0) * 3.25 * root_chord / fillet_radius ** 2


def scatter_scf(alpha: float, slope: float, fillet_radius: float, radius_tol: float) -> float:
    """Coefficient of variation of the theoretical SCF from the fillet-radius scatter.

    .. math:: v_{ασ} = \\Big|\\frac{∂α_σ}{∂ρ}\\Big| \\frac{ρ}{α_σ} v_ρ,\\qquad
              v_ρ = \\frac{Δρ/3}{ρ}

    Parameters
    ----------
    radius_tol : Δρ, tolerance of the fillet radius taken as ±3 standard deviations [mm].

    References
    ----------
    [Gutyria2017] eq. (15) (Δρ = 0.06 mm → v_ρ = 0.1, v_ασ = 0.022).
    """
    v_rho = (radius_tol / 3.0) / fillet_radius
    return slope * fillet_radius / alpha * v_rho


@dataclass(frozen=True)
class PartEndurance:
    """Median endurance limit of the rim and the factors that lead to it."""

    K1: float
    alpha: float
    alpha_slope: float
    gradient: float
    perimeter: float
    theta: float
    nu: float
    k_ratio: float
    K_F: float
    K_V: float
    K_A: float
    K: float
    sigma_m1D: float
    v_max: float
    v_alpha: float
    v_computed: float
    v: float


def part_endurance(*, sigma_u: float, sigma_m1: float, d0: float, blank_size: float,
                   root_chord: float, fillet_radius: float, radius_tol: float,
                   rim_thickness: float, perimeter: float, Rz: float, K_V: float,
                   v_material: float, alpha: float | None = None,
                   gradient: float | None = None, depth: float | None = None,
                   K_A: float | None = None, v_override: float | None = None) -> PartEndurance:
    """Median endurance limit σ_-1D of the rim and its coefficient of variation.

    .. math:: σ_{-1D} = K_1 σ_{-1} / K

    with K from :func:`geardesign.fatigue.gost25504.reduction_factor`.  ``alpha``,
    ``gradient`` and ``K_A`` override the computed α_σ (eq. (12)), G (needs ``depth``
    otherwise) and K_A; ``v_override`` replaces the coefficient of variation of eq. (14)
    (paper A's Table 2 uses 0.10).

    References
    ----------
    [Gutyria2017] eq. (9)-(15) (σ_-1D = 84.5 MPa for the Raba ring, 95.8 MPa with
    ρ = 0.46 mm).
    """
    K1 = g25.blank_size_factor(blank_size, d0)
    a = fillet_scf(root_chord, fillet_radius) if alpha is None else alpha
    slope = fillet_scf_slope(root_chord, fillet_radius)
    G = g25.stress_gradient(fillet_radius, rim_thickness, depth) if gradient is None else gradient
    theta = g25.similarity_criterion(perimeter, G, d0)
    nu = g25.sensitivity_nu(sigma_u)
    k_ratio = g25.concentration_size_ratio(a, theta, nu)
    K_F = g25.roughness_factor(Rz, sigma_u)
    KA = g25.anisotropy_factor(sigma_u) if K_A is None else K_A
    K = g25.reduction_factor(k_ratio, K_F, K_V, KA)
    s1D = K1 * sigma_m1 / K
    v_max = g25.scatter_failure_stress(theta, nu)
    v_alpha = scatter_scf(a, slope, fillet_radius, radius_tol)
    v_comp = g25.total_scatter(v_max, v_material, v_alpha)
    return PartEndurance(K1, a, slope, G, perimeter, theta, nu, k_ratio, K_F, K_V, KA, K, s1D,
                         v_max, v_alpha, v_comp, v_comp if v_override is None else v_override)
