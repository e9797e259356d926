"""Flexible wheel of a wave (strain-wave) gear: kinematics, rim geometry, bending stress and
endurance.  Lengths mm, stresses MPa, torques N·m.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass


def ratios(z_flex: int, z_rigid: int) -> tuple[float, float]:
    """Gear ratios with the wave generator as input.

    Rigid wheel fixed, output on the flexible wheel: u = −z_g/(z_b − z_g) (output reverses);
    flexible wheel fixed, output on the rigid wheel: u = z_b/(z_b − z_g).

    Reference: M. N. Ivanov, "Volnovye zubchatye peredachi" (1981); [IvanovWave].

    Example: z_f = 200, z_r = 202 (Δz = 2) gives −100 with the rigid gear fixed and 101 with
    the flexwheel fixed:

    >>> ratios(200, 202)
    (-100.0, 101.0)
    """
    dz = z_rigid - z_flex
    return -z_flex / dz, z_rigid / dz


def root_radius(m: float, z: int, x: float, h_a: float, c: float) -> float:
    """Root radius of the flexible wheel r_f = m·(z/2 + x − h_a* − c*) [mm] (GOST 16532-70
    d_f = d − 2(h_a* + c* − x)m)."""
    return m * (0.5 * z + x - h_a - c)


def smooth_ring_stress(E: float, w0: float, H0: float, r_m: float, C_gen: float) -> float:
    """Bending stress of a smooth ring of thickness H0 bent by the wave generator [MPa].

    A thin inextensible ring deformed radially by w = w0·cos 2φ changes its curvature by
    (w'' + w)/r² = −3w0·cos 2φ/r_m², so the extreme fibre stress is
    σ = E·(3w0/r_m²)·(H0/2) = 1.5·E·w0·H0/r_m²; other generator shapes change the factor:
    σ = C_gen·E·w0·H0/r_m² (C_gen = 1.5 for the pure cos 2φ shape of a cam generator;
    roughly 2...3 near the rollers of disc or roller generators: uncertain).

    Reference: thin-ring theory (Ivanov, wave gears), [IvanovWave] [standard].
    """
    return C_gen * E * w0 * H0 / r_m ** 2


def shell_shear(T: float, r: float, delta: float) -> float:
    """Torsional shear stress in the thin cylindrical shell of the flexible wheel,
    τ = T/(2π·r²·δ) [MPa] (T in N·m -> N·mm; r, δ in mm).  Thin-walled tube in torsion;
    [IvanovWave]."""
    return T * 1000.0 / (2.0 * math.pi * r * r * delta)


@dataclass(frozen=True)
class Endurance:
    s_sigma: float
    s_tau: float | None
    s: float


def endurance(sigma_m1: float, sigma_a: float, tau_m1: float | None = None,
              tau_a: float = 0.0, tau_m: float = 0.0, psi_tau: float = 0.0) -> Endurance:
    """Safety factors against fatigue of the flexible wheel.

    Bending by the generator is a symmetric cycle (mean 0): s_σ = σ_-1/σ_a.  Torsion:
    s_τ = τ_-1/(τ_a + ψ_τ·τ_m).  Combined: s = s_σ·s_τ/√(s_σ² + s_τ²).

    Reference: Serensen's combined safety factor (the usual shaft and flexible-wheel
    endurance check); [IvanovWave]; the same combination n = n_σ·n_τ/√(n_σ² + n_τ²) and
    s_F = σ_F0/σ_a are the criteria of a published wave-gear design procedure (Vestnik MGTU
    im. N. E. Baumana, ser. Mashinostroenie, article 1072, eqs. (31)-(32)).
    """
    s_sigma = sigma_m1 / sigma_a if sigma_a > 0 else math.inf
    if tau_m1 is None or (tau_a <= 0.0 and tau_m <= 0.0):
        return Endurance(s_sigma, None, s_sigma)
    den = tau_a + psi_tau * tau_m
    s_tau = tau_m1 / den if den > 0 else math.inf
    if not math.isfinite(s_tau):
        return Endurance(s_sigma, s_tau, s_sigma)
    return Endurance(s_sigma, s_tau, s_sigma * s_tau / math.hypot(s_sigma, s_tau))
