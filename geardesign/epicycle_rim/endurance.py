"""Endurance limit of the rim as a part, its scatter, quantiles, probability of non-failure
and life (paper A, steps 7-10: the Serensen-Kogaev statistical similarity theory as applied
by GOST 25.504-82).

Pure functions on plain data; stresses in MPa, lengths in mm.  The text of GOST 25.504-82
could not be consulted: every formula here is taken from paper A
(Gutyria et al. 2017), which applies it to the Raba 118/77 ring, and the equation numbers
are the paper's.  Reconstructed pieces (garbled in the printed source) are marked.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache


@lru_cache(maxsize=1)
def _phi():
    """The standard normal distribution (statistics is imported on first use: the shaft
    calculator imports this module for K_σD only)."""
    from statistics import NormalDist

    return NormalDist()


def blank_size_factor(blank_size: float, d0: float = 7.5) -> float:
    """Blank-size factor of the material's endurance limit.

    .. math:: K_1 = 1 - 0.2 \\lg(δ_3/d_0)

    Parameters
    ----------
    blank_size : δ3, wall thickness of a tubular blank or bar diameter [mm].
    d0 : diameter of the standard specimen [mm] (7.5 mm in GOST 25.504-82).

    References
    ----------
    Gutyria et al. 2017, eq. (9) and text (δ3 = 34 mm → K1 = 0.869).
    """
    return 1.0 - 0.2 * math.log10(blank_size / d0)


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
    Gutyria et al. 2017, eq. (12) (their ref. [14]); exponent reconstructed: it reproduces
    α_σ = 3.0 at ρ = 0.2 mm and 2.5 at ρ = 0.46 mm (S = 9 mm) as printed.
    """
    return (1.0 + 3.25 * root_chord / fillet_radius) ** ALPHA_EXPONENT


def fillet_scf_slope(root_chord: float, fillet_radius: float) -> float:
    """|∂α_σ/∂ρ| of :func:`fillet_scf` [1/mm].

    .. math:: \\Big|\\frac{∂α_σ}{∂ρ}\\Big| = 0.22\\,(1 + 3.25S/ρ)^{-0.78}\\,\\frac{3.25 S}{ρ^2}

    References
    ----------
    Gutyria et al. 2017, eq. (15) first factor (printed 3.289 mm⁻¹ for S = 9, ρ = 0.2 mm;
    the reconstructed exponent gives 3.276, 0.4 % lower).
    """
    u = 1.0 + 3.25 * root_chord / fillet_radius
    return ALPHA_EXPONENT * u ** (ALPHA_EXPONENT - 1.0) * 3.25 * root_chord / fillet_radius ** 2


def stress_gradient(fillet_radius: float, rim_thickness: float, depth: float) -> float:
    """Relative gradient of the first principal stress at the fillet of a bent rim.

    .. math:: \\bar G = \\frac{2.3(1 + φ)}{ρ} + \\frac{2}{δ},
              \\qquad φ = \\frac{1}{4\\sqrt{t/ρ} + 2}

    Parameters
    ----------
    fillet_radius : ρ [mm]; rim_thickness : δ [mm];
    depth : t, depth of the concentrator [mm] (not stated in the paper; its printed
    G = 13.01 mm⁻¹ needs t ≈ 0.635 mm, [Gutyria2017]).

    References
    ----------
    Gutyria et al. 2017, text before eq. (11) (GOST 25.504-82 form for a fillet in bending).
    """
    phi = 1.0 / (4.0 * math.sqrt(depth / fillet_radius) + 2.0)
    return 2.3 * (1.0 + phi) / fillet_radius + 2.0 / rim_thickness


def similarity_criterion(perimeter: float, gradient: float, d0: float = 7.5) -> float:
    """Kogaev's similarity criterion of fatigue failure.

    .. math:: θ = \\frac{L/\\bar G}{L_0/\\bar G_0},\\qquad \\frac{L_0}{\\bar G_0} = \\frac{π d_0^2}{2}

    (standard specimen in rotating bending: L0 = π·d0, G0 = 2/d0; 88.36 mm² for d0 = 7.5 mm).

    Parameters
    ----------
    perimeter : L, perimeter of the working section in the high-stress zone [mm]
        (2b for the inner rim surface: twice the line length).
    gradient : relative stress gradient [1/mm].

    References
    ----------
    Gutyria et al. 2017, text before eq. (11) (θ = 0.1044 with L = 120 mm, G = 13.01 mm⁻¹).
    """
    return (perimeter / gradient) / (math.pi * d0 * d0 / 2.0)


def sensitivity_nu(sigma_u: float) -> float:
    """Material sensitivity to concentration and size, structural steels.

    .. math:: ν_σ = 0.211 - 0.000143\\,σ_u

    Positive for σ_u < 1475 MPa only.

    References
    ----------
    Gutyria et al. 2017, text after eq. (12) (0.1085 for σ_u = 717 MPa); GOST 25.504-82.
    """
    return 0.211 - 0.000143 * sigma_u


def concentration_size_ratio(alpha: float, theta: float, nu: float) -> float:
    """Ratio of the effective SCF to the size factor (Kogaev similarity).

    .. math:: K_σ/K_{dσ} = \\frac{2 α_σ}{1 + θ^{-ν_σ}}

    References
    ----------
    Gutyria et al. 2017, eq. (11) (printed 2.643 for the Raba ring; 2.634 is what their own
    K = 3.228 needs: transposed digits).
    """
    return 2.0 * alpha / (1.0 + theta ** (-nu))


def roughness_factor(Rz: float, sigma_u: float) -> float:
    """Surface roughness factor.

    .. math:: K_F = 1 - 0.22 \\lg R_z\\,(\\lg(σ_u/20) - 1)

    Parameters
    ----------
    Rz : roughness of the fillet [µm]; sigma_u [MPa].

    References
    ----------
    Gutyria et al. 2017, text after eq. (12) (0.829 for Rz = 25 µm, σ_u = 717 MPa).
    """
    return 1.0 - 0.22 * math.log10(Rz) * (math.log10(sigma_u / 20.0) - 1.0)


def anisotropy_factor(sigma_u: float) -> float:
    """Anisotropy factor K_A = 1 − σ_u/6000 (σ_u in MPa).

    References
    ----------
    Gutyria et al. 2017, text after eq. (12) (0.88 for σ_u = 717 MPa), as printed; other
    literature gives other forms ([Gutyria2017]).
    """
    return 1.0 - sigma_u / 6000.0


def reduction_factor(k_ratio: float, K_F: float, K_V: float, K_A: float) -> float:
    """Total reduction factor of the endurance limit.

    .. math:: K = \\Big[\\frac{K_σ}{K_{dσ}} + \\frac{1}{K_F} - 1\\Big]\\frac{1}{K_V K_A}

    References
    ----------
    Gutyria et al. 2017, eq. (10) (K = 3.228 for the Raba ring).
    """
    return (k_ratio + 1.0 / K_F - 1.0) / (K_V * K_A)


def scatter_failure_stress(theta: float, nu: float) -> float:
    """Coefficient of variation of the failure stress (similarity theory).

    .. math:: v_{σ\\max} = \\frac{0.1}{1 + θ^{ν_σ}}

    References
    ----------
    Gutyria et al. 2017, text after eq. (14): form reconstructed from the printed 0.056
    alone ([Gutyria2017]); unverified against GOST 25.504-82.
    """
    return 0.1 / (1.0 + theta ** nu)


def scatter_scf(alpha: float, slope: float, fillet_radius: float, radius_tol: float) -> float:
    """Coefficient of variation of the theoretical SCF from the fillet-radius scatter.

    .. math:: v_{ασ} = \\Big|\\frac{∂α_σ}{∂ρ}\\Big| \\frac{ρ}{α_σ} v_ρ,\\qquad
              v_ρ = \\frac{Δρ/3}{ρ}

    Parameters
    ----------
    radius_tol : Δρ, tolerance of the fillet radius taken as ±3 standard deviations [mm].

    References
    ----------
    Gutyria et al. 2017, eq. (15) (Δρ = 0.06 mm → v_ρ = 0.1, v_ασ = 0.022).
    """
    v_rho = (radius_tol / 3.0) / fillet_radius
    return slope * fillet_radius / alpha * v_rho


def total_scatter(v_max: float, v_material: float, v_alpha: float) -> float:
    """Coefficient of variation of the part endurance limit.

    .. math:: v_{σ-1D} = \\sqrt{v_{σ\\max}^2 + v_{σ-1}^2 + v_{ασ}^2}

    References
    ----------
    Gutyria et al. 2017, eq. (14).  The paper prints v_σ-1 = 0.06 but v_σ-1D = 0.10, which
    needs v_σ-1 ≈ 0.08; its Table 2 uses 0.10 ([Gutyria2017]).
    """
    return math.sqrt(v_max ** 2 + v_material ** 2 + v_alpha ** 2)


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

    with K from :func:`reduction_factor`.  ``alpha``, ``gradient`` and ``K_A`` override the
    computed α_σ (eq. (12)), G (needs ``depth`` otherwise) and K_A; ``v_override`` replaces the
    coefficient of variation of eq. (14) (paper A's Table 2 uses 0.10).

    References
    ----------
    Gutyria et al. 2017, eq. (9)-(15) (σ_-1D = 84.5 MPa for the Raba ring, 95.8 MPa with
    ρ = 0.46 mm).
    """
    K1 = blank_size_factor(blank_size, d0)
    a = fillet_scf(root_chord, fillet_radius) if alpha is None else alpha
    slope = fillet_scf_slope(root_chord, fillet_radius)
    G = stress_gradient(fillet_radius, rim_thickness, depth) if gradient is None else gradient
    theta = similarity_criterion(perimeter, G, d0)
    nu = sensitivity_nu(sigma_u)
    k_ratio = concentration_size_ratio(a, theta, nu)
    K_F = roughness_factor(Rz, sigma_u)
    KA = anisotropy_factor(sigma_u) if K_A is None else K_A
    K = reduction_factor(k_ratio, K_F, K_V, KA)
    s1D = K1 * sigma_m1 / K
    v_max = scatter_failure_stress(theta, nu)
    v_alpha = scatter_scf(a, slope, fillet_radius, radius_tol)
    v_comp = total_scatter(v_max, v_material, v_alpha)
    return PartEndurance(K1, a, slope, G, perimeter, theta, nu, k_ratio, K_F, K_V, KA, K, s1D,
                         v_max, v_alpha, v_comp, v_comp if v_override is None else v_override)


# ----------------------------------------------------------------- probability and life


def normal_quantile(P: float) -> float:
    """Quantile z_P of the standard normal distribution for the probability P (0 < P < 1)."""
    return _phi().inv_cdf(P)


def normal_cdf(z: float) -> float:
    """Standard normal distribution function Φ(z)."""
    return _phi().cdf(z)


def quantile_endurance(sigma_m1D: float, v: float, P: float) -> float:
    """P-quantile of the part endurance limit (the horizontal branch of the S-N curve).

    .. math:: σ_{-1D}^{(P)} = σ_{-1D}(1 - z_P v_{σ-1D})

    P is the probability of non-failure (0 < P < 1); z_P ≥ 0 for P ≥ 50 %.

    References
    ----------
    Gutyria et al. 2017, eq. (13) and (16), Table 2.
    """
    return sigma_m1D * (1.0 - normal_quantile(P) * v)


def probability_of_non_failure(sigma_eq: float, sigma_m1D: float, v: float,
                               v_stress: float = 0.0) -> float:
    """Probability that the part endures the equivalent amplitude σ_-1eq.

    .. math:: P = Φ(z),\\qquad z = \\frac{\\bar n - 1}{\\sqrt{\\bar n^2 v_{σ-1D}^2 + v_{σa}^2}},
              \\qquad \\bar n = σ_{-1D}/σ_{-1eq}

    With v_σa = 0 (paper A) z = (1 − σ_-1eq/σ_-1D)/v_σ-1D, the inverse of eq. (13).

    Parameters
    ----------
    sigma_eq : equivalent symmetric amplitude [MPa]; sigma_m1D : median part endurance limit
    [MPa]; v : its coefficient of variation; v_stress : coefficient of variation of the
    acting stress amplitude (0 in paper A).

    References
    ----------
    Inverse of Gutyria et al. 2017 eq. (13); general form with v_σa: GOST 25.504-82 (from
    [Gutyria2017]; the GOST text was not consulted).
    """
    if sigma_eq <= 0.0:          # no alternating stress: the part cannot fail by fatigue
        return 1.0
    n = sigma_m1D / sigma_eq
    spread = math.sqrt(n * n * v * v + v_stress * v_stress)
    if spread == 0.0:            # no scatter: certain survival above the limit
        return 1.0 if n > 1.0 else (0.5 if n == 1.0 else 0.0)
    return _phi().cdf((n - 1.0) / spread)


def sn_slope(sigma_u: float, K: float) -> float:
    """Slope of the left branch of the part S-N curve.

    .. math:: m = \\frac{5 + σ_u/80}{K} = \\frac{400 + σ_u}{80 K}

    References
    ----------
    Gutyria et al. 2017, after eq. (18) (4.325 for the Raba ring); GOST 25.504-82.
    """
    return (5.0 + sigma_u / 80.0) / K


def lg_life(sigma_eq: float, sigma_m1D: float, v: float, P: float, m: float, N_G: float,
            slgn_alpha: float, slgn_beta: float) -> float:
    """lg N_P: decimal log of the cycles to failure at the probability of non-failure P.

    .. math::
        \\lg N_P = \\lg N_G - m \\lg\\bar σ - u_P\\, 10^{α + β \\lg \\bar σ},
        \\qquad \\bar σ = σ_{-1eq}/σ_{-1D},\\ u_P = Φ^{-1}(P)

    and +∞ when σ_-1eq lies at or below the horizontal branch σ_-1D(P) of eq. (13).  The paper
    prints the scatter term with "+z_P" (z_P < 0 for P > 50 %); here u_P ≥ 0 is subtracted.

    Parameters
    ----------
    m : S-N slope; N_G : knee-point cycles; slgn_alpha, slgn_beta : coefficients of
    lg S_lgN = α + β lg σ̄ (−0.8 and −2.3 for medium-carbon structural steels).

    References
    ----------
    Gutyria et al. 2017, eq. (17)-(21) and Table 3 (graphical read-out in the paper).
    """
    u = normal_quantile(P)
    if sigma_eq <= sigma_m1D * (1.0 - u * v):
        return math.inf
    sb = sigma_eq / sigma_m1D
    return math.log10(N_G) - m * math.log10(sb) - u * 10.0 ** (slgn_alpha + slgn_beta
                                                              * math.log10(sb))
