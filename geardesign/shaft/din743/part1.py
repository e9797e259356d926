"""[DIN743-1]: influence factor K_σ, component fatigue limits σ_WK, mean-stress sensitivity
ψ_σK, component yield limits σ_FK, amplitude strengths σ_ADK (load case 1 or 2), safety
against fatigue (S_Dauer) and against permanent deformation (S_Verform).

Indices: zd tension/compression, b bending, t torsion; a amplitude, m mean, max peak.
Stresses MPa.
"""

from __future__ import annotations

import math

from geardesign.fatigue import gost25504 as g25
from geardesign.shaft.din743 import tables


def K_sigma(beta: float, K_2: float, K_F: float, K_V: float) -> float:
    """Total influence factor K_σ (K_τ likewise) [-] ([DIN743-1] eqs. (8), (9)):

    .. math:: K_σ = \\Big(\\frac{β_σ}{K_2(d)} + \\frac{1}{K_{Fσ}} - 1\\Big)\\frac{1}{K_V}

    The same form as K_σD of [GOST25504] (delegated).

    >>> round(K_sigma(2.0, 0.9, 0.9, 1.0), 4)
    2.3333
    """
    return g25.reduction_factor(beta / K_2, K_F, K_V)


def fatigue_limit(sigma_W_dB: float, K_1: float, K: float) -> float:
    """Component fatigue limit σ_WK = σ_W(d_B)·K_1(d_eff)/K_σ [MPa] ([DIN743-1] eqs.
    (5)-(7); τ_tWK likewise)."""
    return sigma_W_dB * K_1 / K


def mean_stress_sensitivity(sigma_WK: float, K_1: float, sigma_B_dB: float) -> float:
    """ψ_σK = σ_WK/(2·K_1(d_eff)·σ_B(d_B) − σ_WK) [-] ([DIN743-1] eqs. (20)-(22))."""
    return sigma_WK / (2.0 * K_1 * sigma_B_dB - sigma_WK)


def gamma_F(alpha: float, circumferential: bool, hard_surface: bool) -> float:
    """Static support factor γ_F [-] ([DIN743-1] table 2): 1 for a notch that is not
    circumferential, for a hard surface layer and for torsion; else by α (1.5, 2, 3:
    1.05, 1.1, 1.15)."""
    if not circumferential or hard_surface:
        return 1.0
    g = 1.0
    for a_from, value in tables()["static"]["gamma_F"]:
        if alpha >= a_from:
            g = value
    return g


def K_2F(load: str, hard_surface: bool, hollow: bool) -> float:
    """Static size factor K_2F [-] ([DIN743-1] table 3): tension 1; bending 1.2 (solid),
    1.1 (hollow); torsion 1.2 (solid), 1.0 (hollow); with a hard surface layer 1."""
    s = tables()["static"]
    if load == "tension":
        return s["K_2F_tension"]
    if hard_surface:
        return s["K_2F_hard"]
    return s[f"K_2F_{load}_{'hollow' if hollow else 'solid'}"]


def yield_limit(K_1S: float, K_2F_: float, gamma_F_: float, sigma_S_dB: float,
                torsion: bool = False) -> float:
    """Component yield limit [MPa] ([DIN743-1] eqs. (31), (32)):
    σ_FK = K_1(d_eff)·K_2F·γ_F·σ_S(d_B), τ_tFK = K_1(d_eff)·K_2F·γ_F·σ_S(d_B)/√3."""
    v = K_1S * K_2F_ * gamma_F_ * sigma_S_dB
    return v / math.sqrt(3.0) if torsion else v


def equivalent_mean(sigma_zdm: float, sigma_bm: float, tau_tm: float) -> tuple[float, float]:
    """Equivalent mean stresses ([DIN743-1] eqs. (23), (24)):
    σ_mv = √((σ_zdm + σ_bm)² + 3τ_tm²), τ_mv = σ_mv/√3 [MPa].  (Tensile mean stresses;
    the shaft calculator passes the axial stress as its magnitude.)"""
    s = math.sqrt((sigma_zdm + sigma_bm) ** 2 + 3.0 * tau_tm ** 2)
    return s, s / math.sqrt(3.0)


def amplitude_strength(load_case: int, mv: float, a: float, FK: float, WK: float,
                       psi: float) -> float:
    """Amplitude strength σ_ADK (τ_tADK likewise) [MPa] ([DIN743-1] eqs. (10)-(19)).

    Load case 1 (σ_mv constant):

    .. math:: σ_{ADK} = σ_{WK} - ψ_{σK}σ_{mv}\\ \\text{for}\\
              σ_{mv} \\le \\frac{σ_{FK} - σ_{WK}}{1 - ψ_{σK}},\\quad
              σ_{ADK} = σ_{FK} - σ_{mv}\\ \\text{else}

    Load case 2 (σ_mv/σ_a constant):

    .. math:: σ_{ADK} = \\frac{σ_{WK}}{1 + ψ_{σK}σ_{mv}/σ_a}\\ \\text{for}\\
              \\frac{σ_{mv}}{σ_a} \\le \\frac{σ_{FK} - σ_{WK}}{σ_{WK} - ψ_{σK}σ_{FK}},\\quad
              σ_{ADK} = \\frac{σ_{FK}}{1 + σ_{mv}/σ_a}\\ \\text{else}

    (σ_a = 0 in case 2 with σ_mv > 0: σ_mv/σ_a is infinite, σ_ADK = 0; the safety takes
    the term σ_a/σ_ADK as 0.)

    >>> round(amplitude_strength(2, 100.0, 100.0, 500.0, 200.0, 0.1), 4)
    181.8182
    """
    if load_case == 1:
        if mv <= _limit(FK - WK, 1.0 - psi):
            return WK - psi * mv
        return FK - mv
    ratio = mv / a if a > 0 else (math.inf if mv > 0 else 0.0)
    if ratio <= _limit(FK - WK, WK - FK * psi):
        return WK / (1.0 + psi * ratio)
    return FK / (1.0 + ratio)


def _limit(num: float, den: float) -> float:
    """The branch limit num/den of σ_ADK; where den <= 0 (ψ_σK >= 1, or σ_WK <= ψ·σ_FK:
    the fatigue line never meets the yield line for a positive mean stress) infinite."""
    return num / den if den > 0 else math.inf


def _q(a: float, b: float) -> float:
    """a/b with 0/0 = 0 and a/0 = ∞ (a > 0)."""
    if a == 0.0:
        return 0.0
    return a / b if b > 0 else math.inf


def safety(sigma_zd: float, sigma_b: float, tau_t: float, zd_K: float, b_K: float,
           t_K: float) -> float:
    """Safety [-] ([DIN743-1] eqs. (1), (2)); against fatigue with amplitudes and σ_ADK,
    against permanent deformation with peak stresses and σ_FK:

    .. math:: S = 1\\Big/\\sqrt{\\Big(\\frac{σ_{zd}}{σ_{zdK}} + \\frac{σ_b}{σ_{bK}}\\Big)^2
              + \\Big(\\frac{τ_t}{τ_{tK}}\\Big)^2}

    A term without stress is 0; no stress at all gives an infinite safety.  A strength of 0
    or below with a stress (σ_ADK = σ_FK − σ_mv < 0 in load case 1: the mean stress alone
    exceeds the yield limit) gives S = 0.

    >>> round(safety(0.0, 100.0, 50.0, 1.0, 200.0, 100.0), 4)
    1.4142
    """
    inv = math.hypot(_q(sigma_zd, zd_K) + _q(sigma_b, b_K), _q(tau_t, t_K))
    return 1.0 / inv if inv > 0 else math.inf
