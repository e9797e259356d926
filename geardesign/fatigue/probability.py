"""Probability of non-failure and life of a part by the Serensen-Kogaev statistical
similarity theory of GOST 25.504-82 ([GOST25504]), in the form applied by [Gutyria2017]
(whose equation numbers are cited; the text of GOST 25.504-82 was not consulted).

Pure functions on floats; stresses in MPa.
"""

from __future__ import annotations

import math
from functools import lru_cache


@lru_cache(maxsize=1)
def _phi():
    """The standard normal distribution (statistics is imported on first use)."""
    from statistics import NormalDist

    return NormalDist()


def normal_quantile(P: float) -> float:
    """Quantile z_P of the standard normal distribution for the probability P (0 < P < 1).

    >>> round(normal_quantile(0.9), 4)
    1.2816
    """
    return _phi().inv_cdf(P)


def normal_cdf(z: float) -> float:
    """Standard normal distribution function Φ(z).

    >>> round(normal_cdf(0.0), 2)
    0.5
    """
    return _phi().cdf(z)


def quantile_endurance(sigma_m1D: float, v: float, P: float) -> float:
    """P-quantile of the part endurance limit (the horizontal branch of the S-N curve)
    [MPa].

    .. math:: σ_{-1D}^{(P)} = σ_{-1D}(1 - z_P v_{σ-1D})

    Parameters
    ----------
    sigma_m1D : median endurance limit of the part [MPa]; v : its coefficient of variation
    [-]; P : probability of non-failure (0 < P < 1); z_P ≥ 0 for P ≥ 50 %.

    References
    ----------
    [Gutyria2017] eq. (13) and (16), Table 2; [GOST25504].

    >>> round(quantile_endurance(84.5, 0.1, 0.5), 1)
    84.5
    """
    return sigma_m1D * (1.0 - normal_quantile(P) * v)


def probability_of_non_failure(sigma_eq: float, sigma_m1D: float, v: float,
                               v_stress: float = 0.0) -> float:
    """Probability that the part endures the equivalent amplitude σ_-1eq [-].

    .. math:: P = Φ(z),\\qquad z = \\frac{\\bar n - 1}{\\sqrt{\\bar n^2 v_{σ-1D}^2 + v_{σa}^2}},
              \\qquad \\bar n = σ_{-1D}/σ_{-1eq}

    With v_σa = 0 ([Gutyria2017]) z = (1 − σ_-1eq/σ_-1D)/v_σ-1D, the inverse of eq. (13).

    Parameters
    ----------
    sigma_eq : equivalent symmetric amplitude [MPa]; sigma_m1D : median part endurance limit
    [MPa]; v : its coefficient of variation [-]; v_stress : coefficient of variation of the
    acting stress amplitude [-] (0 in [Gutyria2017]).

    References
    ----------
    Inverse of [Gutyria2017] eq. (13); general form with v_σa: [GOST25504] (as quoted by
    [Gutyria2017]; the GOST text was not consulted).

    >>> round(probability_of_non_failure(84.5, 84.5, 0.1), 2)
    0.5
    """
    if sigma_eq <= 0.0:          # no alternating stress: the part cannot fail by fatigue
        return 1.0
    n = sigma_m1D / sigma_eq
    spread = math.sqrt(n * n * v * v + v_stress * v_stress)
    if spread == 0.0:            # no scatter: certain survival above the limit
        return 1.0 if n > 1.0 else (0.5 if n == 1.0 else 0.0)
    return _phi().cdf((n - 1.0) / spread)


def sn_slope(sigma_u: float, K: float) -> float:
    """Slope of the left branch of the part S-N curve [-].

    .. math:: m = \\frac{5 + σ_u/80}{K} = \\frac{400 + σ_u}{80 K}

    Parameters
    ----------
    sigma_u : ultimate strength [MPa]; K : total reduction factor of the part [-].

    References
    ----------
    [Gutyria2017] after eq. (18) (4.325 for the Raba ring); [GOST25504].

    >>> round(sn_slope(717.0, 3.228), 3)
    4.325
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
    sigma_eq, sigma_m1D : equivalent amplitude and median part endurance limit [MPa];
    v : coefficient of variation of σ_-1D [-]; P : probability of non-failure (0 < P < 1);
    m : S-N slope [-]; N_G : knee-point cycles; slgn_alpha, slgn_beta : coefficients of
    lg S_lgN = α + β lg σ̄ (−0.8 and −2.3 for medium-carbon structural steels).

    References
    ----------
    [Gutyria2017] eq. (17)-(21) and Table 3 (graphical read-out in the paper); [GOST25504].

    >>> lg_life(80.0, 84.5, 0.1, 0.5, 4.3, 2e6, -0.8, -2.3)
    inf
    """
    u = normal_quantile(P)
    if sigma_eq <= sigma_m1D * (1.0 - u * v):
        return math.inf
    sb = sigma_eq / sigma_m1D
    return math.log10(N_G) - m * math.log10(sb) - u * 10.0 ** (slgn_alpha + slgn_beta
                                                              * math.log10(sb))
