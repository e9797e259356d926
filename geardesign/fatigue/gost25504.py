"""GOST 25.504-82 ([GOST25504]): the factors of the endurance limit of a part and its
safety factors, one place for the shaft (:mod:`geardesign.shaft.strength`, and DIN 743
where it has the same form) and the ring-gear rim (:mod:`geardesign.epicycle_rim.endurance`).

The text of GOST 25.504-82 could not be consulted: the forms are those quoted and applied by
[Gutyria2017] (its equation numbers are cited) and, for shafts, by [Dunaev] and [Ivanov];
reconstructed pieces are marked.  Pure functions on floats; stresses in MPa, lengths in mm.
"""

from __future__ import annotations

import math

# ----------------------------------------------------------------------------- size


def blank_size_factor(blank_size: float, d0: float = 7.5) -> float:
    """Blank-size factor of the material's endurance limit [-].

    .. math:: K_1 = 1 - 0.2 \\lg(δ_3/d_0)

    Parameters
    ----------
    blank_size : δ3, wall thickness of a tubular blank or bar diameter [mm].
    d0 : diameter of the standard specimen [mm] (7.5 mm in GOST 25.504-82).

    References
    ----------
    [Gutyria2017] eq. (9) and text (δ3 = 34 mm → K1 = 0.869); [GOST25504].

    >>> round(blank_size_factor(34.0), 3)
    0.869
    """
    return 1.0 - 0.2 * math.log10(blank_size / d0)


def stress_gradient(fillet_radius: float, thickness: float, depth: float) -> float:
    """Relative gradient of the first principal stress at a fillet in bending [1/mm].

    .. math:: \\bar G = \\frac{2.3(1 + φ)}{ρ} + \\frac{2}{δ},
              \\qquad φ = \\frac{1}{4\\sqrt{t/ρ} + 2}

    Parameters
    ----------
    fillet_radius : ρ [mm]; thickness : δ, the bent section's thickness (the rim
    thickness, a shaft's diameter) [mm]; depth : t, depth of the concentrator [mm].

    References
    ----------
    [Gutyria2017], text before eq. (11) ([GOST25504] form for a fillet in bending; its
    printed G = 13.01 mm⁻¹ needs t ≈ 0.635 mm).

    >>> round(stress_gradient(0.2, 8.0, 0.635), 2)
    13.01
    """
    phi = 1.0 / (4.0 * math.sqrt(depth / fillet_radius) + 2.0)
    return 2.3 * (1.0 + phi) / fillet_radius + 2.0 / thickness


def similarity_criterion(perimeter: float, gradient: float, d0: float = 7.5) -> float:
    """Kogaev's similarity criterion of fatigue failure [-].

    .. math:: θ = \\frac{L/\\bar G}{L_0/\\bar G_0},\\qquad \\frac{L_0}{\\bar G_0} = \\frac{π d_0^2}{2}

    (standard specimen in rotating bending: L0 = π·d0, G0 = 2/d0; 88.36 mm² for d0 = 7.5 mm).

    Parameters
    ----------
    perimeter : L, perimeter of the working section in the high-stress zone [mm]
        (2b for the inner rim surface: twice the line length).
    gradient : relative stress gradient [1/mm]; d0 : specimen diameter [mm].

    References
    ----------
    [Gutyria2017], text before eq. (11) (θ = 0.1044 with L = 120 mm, G = 13.01 mm⁻¹);
    [GOST25504].

    >>> round(similarity_criterion(120.0, 13.01), 4)
    0.1044
    """
    return (perimeter / gradient) / (math.pi * d0 * d0 / 2.0)


def sensitivity_nu(sigma_u: float) -> float:
    """Material sensitivity to concentration and size, structural steels [-].

    .. math:: ν_σ = 0.211 - 0.000143\\,σ_u

    Positive for σ_u < 1475 MPa only.

    References
    ----------
    [Gutyria2017], text after eq. (12) (0.1085 for σ_u = 717 MPa); [GOST25504].

    >>> round(sensitivity_nu(717.0), 4)
    0.1085
    """
    return 0.211 - 0.000143 * sigma_u


def concentration_size_ratio(alpha: float, theta: float, nu: float) -> float:
    """Ratio of the effective stress concentration factor to the size factor (Kogaev
    similarity) [-].

    .. math:: K_σ/K_{dσ} = \\frac{2 α_σ}{1 + θ^{-ν_σ}}

    Parameters
    ----------
    alpha : theoretical stress concentration factor α_σ [-]; theta : similarity criterion
    [-]; nu : sensitivity ν_σ [-].

    References
    ----------
    [Gutyria2017] eq. (11) (printed 2.643 for the Raba ring; 2.634 is what their own
    K = 3.228 needs: transposed digits); [GOST25504].

    >>> round(concentration_size_ratio(3.0, 0.1044, 0.1085), 3)
    2.634
    """
    return 2.0 * alpha / (1.0 + theta ** (-nu))


# ----------------------------------------------------------------------------- surface


def roughness_factor(Rz: float, sigma_u: float) -> float:
    """Surface roughness factor in bending K_Fσ [-].

    .. math:: K_F = 1 - 0.22 \\lg R_z\\,(\\lg(σ_u/20) - 1)

    Parameters
    ----------
    Rz : roughness [µm]; sigma_u : ultimate strength [MPa].

    References
    ----------
    [Gutyria2017], text after eq. (12) (0.829 for Rz = 25 µm, σ_u = 717 MPa); [GOST25504].

    >>> round(roughness_factor(25.0, 717.0), 3)
    0.829
    """
    return 1.0 - 0.22 * math.log10(Rz) * (math.log10(sigma_u / 20.0) - 1.0)


def torsion_roughness_factor(K_F_sigma: float) -> float:
    """Surface roughness factor in torsion from the one in bending [-].

    .. math:: K_{Fτ} = 0.575\\,K_{Fσ} + 0.425

    References
    ----------
    [GOST25504] as applied by [Dunaev] and [Ivanov]; the same form in [DIN743-2].

    >>> round(torsion_roughness_factor(0.8462), 4)
    0.9116
    """
    return 0.575 * K_F_sigma + 0.425


def anisotropy_factor(sigma_u: float) -> float:
    """Anisotropy factor K_A = 1 − σ_u/6000 [-] (σ_u in MPa).

    References
    ----------
    [Gutyria2017], text after eq. (12) (0.88 for σ_u = 717 MPa), as printed; other
    literature gives other forms.

    >>> round(anisotropy_factor(717.0), 2)
    0.88
    """
    return 1.0 - sigma_u / 6000.0


def reduction_factor(k_ratio: float, K_F: float, K_V: float, K_A: float = 1.0) -> float:
    """Total reduction factor of the endurance limit K (K_σD of a shaft section) [-].

    .. math:: K = \\Big[\\frac{K_σ}{K_{dσ}} + \\frac{1}{K_F} - 1\\Big]\\frac{1}{K_V K_A}

    Parameters
    ----------
    k_ratio : K_σ/K_dσ [-]; K_F : roughness factor [-]; K_V : surface hardening factor
    [-]; K_A : anisotropy factor [-] (1 for shafts).

    References
    ----------
    [Gutyria2017] eq. (10) (K = 3.228 for the Raba ring); [GOST25504]; [Dunaev] ch. 10.

    >>> round(reduction_factor(2.634, 0.829, 1.0, 0.88), 3)
    3.228
    """
    return (k_ratio + 1.0 / K_F - 1.0) / (K_V * K_A)


# ----------------------------------------------------------------------------- mean stress


def mean_stress_sensitivity(sigma_u: float) -> tuple[float, float]:
    """Mean-stress sensitivities ψ_σ and ψ_τ of smooth specimens of structural steel [-].

    .. math:: ψ_σ = 0.02 + 2·10^{-4} σ_u,\\qquad ψ_τ = 0.5\\,ψ_σ  \\quad (σ_u \\text{ in MPa})

    References
    ----------
    [GOST25504] (as quoted in [Gutyria2017] eqs. (4)-(8), and by [Ivanov]; the GOST text
    was not consulted).

    >>> [round(p, 4) for p in mean_stress_sensitivity(717.0)]
    [0.1634, 0.0817]
    """
    psi = 0.02 + 2e-4 * sigma_u
    return psi, 0.5 * psi


# ----------------------------------------------------------------------------- scatter


def scatter_failure_stress(theta: float, nu: float) -> float:
    """Coefficient of variation of the failure stress (similarity theory) [-].

    .. math:: v_{σ\\max} = \\frac{0.1}{1 + θ^{ν_σ}}

    References
    ----------
    [Gutyria2017], text after eq. (14): form reconstructed from the printed 0.056 alone;
    unverified against [GOST25504].

    >>> round(scatter_failure_stress(0.1044, 0.1085), 3)
    0.056
    """
    return 0.1 / (1.0 + theta ** nu)


def total_scatter(v_max: float, v_material: float, v_alpha: float) -> float:
    """Coefficient of variation of the part endurance limit [-].

    .. math:: v_{σ-1D} = \\sqrt{v_{σ\\max}^2 + v_{σ-1}^2 + v_{ασ}^2}

    References
    ----------
    [Gutyria2017] eq. (14).  The paper prints v_σ-1 = 0.06 but v_σ-1D = 0.10, which needs
    v_σ-1 ≈ 0.08; its Table 2 uses 0.10.

    >>> round(total_scatter(0.056, 0.08, 0.022), 3)
    0.1
    """
    return math.sqrt(v_max ** 2 + v_material ** 2 + v_alpha ** 2)


# ----------------------------------------------------------------------------- safety


def safety_factor(limit: float, K_D: float, psi: float, amplitude: float,
                  mean: float) -> float:
    """Fatigue safety factor in one kind of stress (normal or shear) [-].

    .. math:: S_σ = \\frac{σ_{-1}}{K_{σD} σ_a + ψ_σ σ_m}

    Infinite when the stresses give no damage (a zero or negative denominator).

    Parameters
    ----------
    limit : endurance limit of smooth specimens σ_-1 (τ_-1) [MPa]; K_D : reduction factor
    K_σD (K_τD) [-]; psi : mean-stress sensitivity ψ_σ (ψ_τ) [-]; amplitude, mean : nominal
    stress amplitude and mean stress [MPa].

    References
    ----------
    [GOST25504] as applied by [Dunaev] ch. 10 and [Ivanov].

    >>> round(safety_factor(300.0, 2.0, 0.1, 50.0, 0.0), 2)
    3.0
    """
    den = K_D * amplitude + psi * mean
    return limit / den if den > 0 else math.inf


def combined_safety(S_sigma: float, S_tau: float) -> float:
    """Fatigue safety factor under bending and torsion together [-].

    .. math:: S = \\frac{S_σ S_τ}{\\sqrt{S_σ^2 + S_τ^2}}

    written as 1/|(1/S_σ, 1/S_τ)|: no overflow when one of the two is barely loaded;
    infinite when neither is.

    References
    ----------
    [GOST25504] as applied by [Dunaev] ch. 10 and [Ivanov].

    >>> round(combined_safety(3.0, 4.0), 2)
    2.4
    """
    inv = math.hypot(1.0 / S_sigma, 1.0 / S_tau)
    return 1.0 / inv if inv > 0 else math.inf
