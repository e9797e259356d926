"""Scuffing load capacity by the integral temperature method: ISO/TS 6336-21:2017, which
replaced ISO/TR 13989-2:2000 ([ISO6336-21], [ISOTR13989-2]).

The integral temperature Θ_int = Θ_M + C_2·Θ_flaint (the bulk temperature plus a weighted
mean of the flash temperatures along the path of contact) is compared with the integral
scuffing temperature Θ_intS of the oil, found from its FZG test (ISO 14635-1 A/8.3/90 load
stage): S_intS = Θ_intS/Θ_int ≥ S_Smin.

Pure functions; lengths mm, velocities m/s, loads N/mm, temperatures °C, dynamic viscosity
mPa·s, roughness µm, angles rad.  Every function names its equation by symbol (the
standard's equation numbers differ between the TR and the TS); the constants of the tables
are in :mod:`.tables` (``SCUFFING_*``).  The printed KISSsoft report of the NREL 5 MW
stage 3 ([KISSsoft2017], section 5 "Scuffing load capacity", method ISO/TR 13989:2000)
checks each factor in ``tests/reference/spur/test_iso6336_scuffing.py``.
"""

from __future__ import annotations

import math

from geardesign.spur.strength.iso6336 import tables as T

C_1 = 0.70
"""Weighting factor of the bulk temperature, Θ_M = Θ_oil + C_1·X_mp·X_S·Θ_flaint
([ISO6336-21], Θ_M; KISSsoft prints "theMC = theoil + XS*0.70*theflaint")."""

C_2 = 1.5
"""Weighting factor of the mean flash temperature in Θ_int, spur and helical gears
([ISO6336-21], Θ_int; the same C_2 in the integral scuffing temperature of the test)."""


def helical_load_factor(eps_gamma: float) -> float:
    """Helical load factor K_Bγ: 1 for ε_γ ≤ 2, 1 + 0.2·√((ε_γ − 2)(5 − ε_γ)) for
    2 < ε_γ < 3.5, 1.3 from ε_γ = 3.5 on ([ISO6336-21], K_Bγ).

    >>> round(helical_load_factor(2.884099), 3)   # KISSsoft NREL stage 3 prints 1.274
    1.274
    """
    if eps_gamma <= 2.0:
        return 1.0
    if eps_gamma < 3.5:
        return 1.0 + 0.2 * math.sqrt((eps_gamma - 2.0) * (5.0 - eps_gamma))
    return 1.3


def flash_factor(E_r: float, B_M: float) -> float:
    """Thermo-elastic (flash) factor X_M = E_r^¼/B_M [K·N^-¾·s^½·m^-½·mm] for two gears of
    the same thermal contact coefficient B_M = √(λ_M ρ_M c_M) [N/(mm·s^½·K)]; E_r = the
    reduced modulus 2/((1 − ν1²)/E1 + (1 − ν2²)/E2) [N/mm²].  The √1000 turns the
    velocity's m into the mm of B_M ([ISO6336-21], X_M; [ISOTR13989-1], flash factor).

    >>> round(flash_factor(206000 / 0.91, 13.78), 2)   # KISSsoft prints 50.058 for steel
    50.06
    """
    return math.sqrt(1000.0) * E_r ** 0.25 / B_M


def angle_factor(alpha_wt: float, alpha_n: float, alpha_t: float, beta: float) -> float:
    """Angle factor X_αβ = 1.22·sin^¼α_wt·cos^¼α_n·cos^¼β/(cos^½α_t·cos^½α_wt)
    ([ISO6336-21], X_αβ); 0.978 for a spur gear of α = 20°.

    >>> round(angle_factor(*(math.radians(a) for a in (20, 20, 20, 0))), 3)
    0.978
    """
    return 1.22 * (math.sin(alpha_wt) * math.cos(alpha_n) * math.cos(beta)) ** 0.25 / \
        math.sqrt(math.cos(alpha_t) * math.cos(alpha_wt))


def sum_velocity_pitch(v_w: float, alpha_wt: float) -> float:
    """Sum of the tangential (rolling) velocities at the pitch point C [m/s]:

    .. math:: v_{ΣC} = 2 v_w \\sin α_{wt}

    v_w = π d_w1 n1/60000 [m/s] the velocity at the operating pitch circle, α_wt [rad].  At
    C each flank moves along the line of action's normal with ω_i ρ_Ci, ρ_Ci = ½ d_wi sin α_wt
    (external and internal pairs alike), and ω_1 d_w1 = ω_2 d_w2: the sum is 2 v_w sin α_wt
    ([ISO6336-21], v_ΣC; [ISOTR14179-2], the same sum in μ_mz).  The reference circle's v
    instead of v_w misstates it by d1/d_w1 on every shifted pair (x1 + x2 ≠ 0).

    >>> round(sum_velocity_pitch(21.2, math.radians(22.856)), 3)
    16.469
    """
    return 2.0 * v_w * math.sin(alpha_wt)


def geometry_factor_tip(rho_E1: float, rho_E2: float, u: float, internal: bool = False) -> float:
    """Geometry factor at the pinion tip X_BE = 0.51·√(u ± 1)·|√ρ_E1 − √(ρ_E2/u)|/
    (ρ_E1·ρ_E2)^¼, ρ_E1, ρ_E2 [mm] the transverse radii of curvature of pinion and wheel
    at the pinion tip E, u = z2/z1 > 0 (+ external, − internal pair) ([ISO6336-21], X_BE).

    The form follows from Blok's flash temperature with the rolling velocities ω_i·ρ_i:
    v_g/(√v_r1 + √v_r2) = √(ω_1)·|√ρ_1 − √(ρ_2/u)| and ω_1 = v/r_w1 = v(u ± 1)/a; for the
    internal pair ρ_E2 = ρ_E1 + a·sin α_wt (concave flank), hence the √(u − 1).
    """
    k = u - 1.0 if internal else u + 1.0
    return 0.51 * math.sqrt(k) * abs(math.sqrt(rho_E1) - math.sqrt(rho_E2 / u)) / \
        (rho_E1 * rho_E2) ** 0.25


def contact_ratio_factor(eps_1: float, eps_2: float) -> tuple[float, str]:
    """Contact ratio factor X_ε from the addendum contact ratios ε_1 (pinion) and ε_2 (wheel),
    ε_α = ε_1 + ε_2 ([ISO6336-21], table of X_ε), and the branch used:

    * ε_α < 1:                       X_ε = (ε_1² + ε_2²)/(2ε_αε_1)
    * 1 ≤ ε_α < 2, ε_1 < 1, ε_2 < 1:  [0.70(ε_1² + ε_2²) − 0.22ε_α + 0.52 − 0.60ε_1ε_2]/(2ε_αε_1)
    * 1 ≤ ε_α < 2, ε_1 ≥ 1, ε_2 < 1:  [0.18ε_1² + 0.70ε_2² + 0.82ε_1 − 0.52ε_2 − 0.30ε_1ε_2]/(2ε_αε_1)
    * 1 ≤ ε_α < 2, ε_1 < 1, ε_2 ≥ 1:  [0.70ε_1² + 0.18ε_2² − 0.52ε_1 + 0.82ε_2 − 0.30ε_1ε_2]/(2ε_αε_1)
    * 2 ≤ ε_α < 3, ε_1 ≥ 1, ε_2 ≥ 1:  [0.44ε_1² + 0.59ε_2² + 0.30ε_1 − 0.30ε_2 − 0.15ε_1ε_2]/(2ε_αε_1)

    The first four branches join continuously (at ε_α = 1, ε_1 = 1 and ε_2 = 1) and meet the
    last at ε_1 = ε_2 = 1 (0.88/(2ε_αε_1)); the second is checked against KISSsoft (0.263).
    High contact ratios outside the table (ε_α ≥ 2 with ε_1 or ε_2 < 1, ε_α ≥ 3) take the
    nearest branch, reported as such (``branch`` ends in "(nearest)").

    >>> round(contact_ratio_factor(0.85196, 0.61081)[0], 3)
    0.263
    """
    e1, e2 = eps_1, eps_2
    ea = e1 + e2
    if ea < 1.0:
        br, name = e1 * e1 + e2 * e2, "ε_α < 1"
    elif ea < 2.0 and e1 < 1.0 and e2 < 1.0:
        br, name = 0.70 * (e1 * e1 + e2 * e2) - 0.22 * ea + 0.52 - 0.60 * e1 * e2, \
            "1 ≤ ε_α < 2, ε_1 < 1, ε_2 < 1"
    elif ea >= 2.0 and e1 >= 1.0 and e2 >= 1.0:
        br = 0.44 * e1 * e1 + 0.59 * e2 * e2 + 0.30 * e1 - 0.30 * e2 - 0.15 * e1 * e2
        name = "2 ≤ ε_α < 3, ε_1 ≥ 1, ε_2 ≥ 1" + (" (nearest)" if ea >= 3.0 else "")
    elif e1 >= 1.0:
        br = 0.18 * e1 * e1 + 0.70 * e2 * e2 + 0.82 * e1 - 0.52 * e2 - 0.30 * e1 * e2
        name = "1 ≤ ε_α < 2, ε_1 ≥ 1, ε_2 < 1" + (" (nearest)" if ea >= 2.0 else "")
    else:
        br = 0.70 * e1 * e1 + 0.18 * e2 * e2 - 0.52 * e1 + 0.82 * e2 - 0.30 * e1 * e2
        name = "1 ≤ ε_α < 2, ε_1 < 1, ε_2 ≥ 1" + (" (nearest)" if ea >= 2.0 else "")
    return br / (2.0 * ea * e1), name


def approach_factor(eps_f: float, eps_a: float) -> float:
    """Approach factor X_Q from the ratio of the approach path ε_f (tip of the driven gear) to
    the recess path ε_a (tip of the driving gear): 1 up to ε_f/ε_a = 1.5, 1.40 − 4/15·ε_f/ε_a
    up to 3, then 0.6 ([ISO6336-21], X_Q)."""
    r = eps_f / eps_a
    if r <= 1.5:
        return 1.0
    if r < 3.0:
        return 1.40 - 4.0 / 15.0 * r
    return 0.6


def tip_relief_factor(C_a: float, C_eff: float, eps_max: float) -> float:
    """Tip relief factor X_Ca = 1 + (0.06 + 0.18·C_a/C_eff)·ε_max + (0.02 + 0.69·C_a/C_eff)·ε_max²,
    C_a [µm] the relevant tip relief (at most C_eff), C_eff = K_A·F_t/(b·c_γ) [µm] the
    optimal one, ε_max the larger of ε_1 and ε_2 ([ISO6336-21], X_Ca).

    >>> round(tip_relief_factor(2.0, 44.74, 0.85196), 3)   # KISSsoft prints 1.095
    1.095
    """
    r = min(C_a, C_eff) / C_eff
    return 1.0 + (0.06 + 0.18 * r) * eps_max + (0.02 + 0.69 * r) * eps_max ** 2


def roughness_factor(Ra: float, rho_redC: float) -> float:
    """Roughness factor X_R = 2.2·(Ra/ρ_redC)^¼, Ra = (Ra_1 + Ra_2)/2 [µm], ρ_redC [mm]
    ([ISO6336-21], X_R).

    >>> round(roughness_factor(0.6, 54.577), 3)   # KISSsoft prints 0.712
    0.712
    """
    return 2.2 * (Ra / rho_redC) ** 0.25


def mean_friction(w_Bt_K: float, v_sum: float, rho_redC: float, eta: float, X_R: float,
                  X_L: float) -> float:
    """Mean coefficient of friction μ_mC = 0.045·(w_Bt·K_Bγ/(v_ΣC·ρ_redC))^0.2·η_oil^-0.05·X_R·X_L,
    w_Bt·K_Bγ [N/mm], v_ΣC = 2v·sin α_wt [m/s], ρ_redC [mm], η_oil [mPa·s] at the oil
    temperature ([ISO6336-21], μ_mC)."""
    return 0.045 * (w_Bt_K / (v_sum * rho_redC)) ** 0.2 * eta ** -0.05 * X_R * X_L


def flash_temperature_tip(mu: float, X_M: float, X_BE: float, X_ab: float, w_Bt_K: float,
                          v: float, a: float, X_E: float, X_Q: float, X_Ca: float) -> float:
    """Flash temperature at the pinion tip Θ_flaE = μ_mC·X_M·X_BE·X_αβ·(K_Bγ·w_Bt)^¾·v^½/|a|^¼
    ·X_E/(X_Q·X_Ca) [K], v [m/s] at the reference circle, a [mm] the centre distance
    ([ISO6336-21], Θ_flaE)."""
    return mu * X_M * X_BE * X_ab * w_Bt_K ** 0.75 * math.sqrt(v) / abs(a) ** 0.25 * \
        X_E / (X_Q * X_Ca)


def bulk_temperature(theta_oil: float, theta_flaint: float, X_S: float, X_mp: float) -> float:
    """Bulk temperature Θ_M = Θ_oil + C_1·X_mp·X_S·Θ_flaint [°C] ([ISO6336-21], Θ_M)."""
    return theta_oil + C_1 * X_mp * X_S * theta_flaint


def multiple_mesh_factor(n_p: int) -> float:
    """Multiple mesh factor X_mp = (1 + n_p)/2 of a gear in mesh with n_p gears (a planet 2)
    ([ISO6336-21], X_mp)."""
    return (1.0 + n_p) / 2.0


def fzg_torque(stage: int) -> float:
    """Pinion torque T_1T [N·m] of an FZG A/8.3/90 load stage ([ISO14635-1]; data
    :data:`.tables.FZG_TORQUE`)."""
    return T.FZG_TORQUE[stage]


def integral_scuffing_temperature(stage: int, nu40: float, X_L: float, X_WrelT: float
                                  ) -> tuple[float, float, float]:
    """Integral scuffing temperature of the oil from its FZG A/8.3/90 failure load stage:
    Θ_intS = Θ_MT + C_2·X_WrelT·Θ_flaintT with Θ_MT = 80 + 0.23·T_1T·X_L and
    Θ_flaintT = 0.2·T_1T·(100/ν40)^0.02·X_L, T_1T [N·m] the stage's pinion torque, ν40
    [mm²/s] ([ISO6336-21], Θ_intS).  Returns (Θ_intS, Θ_MT, Θ_flaintT).

    >>> round(integral_scuffing_temperature(14, 220.0, 1.0, 1.0)[0], 2)  # KISSsoft: 455.17
    455.17
    """
    T1 = fzg_torque(stage)
    th_M = 80.0 + 0.23 * T1 * X_L
    th_fla = 0.2 * T1 * (100.0 / nu40) ** 0.02 * X_L
    return th_M + C_2 * X_WrelT * th_fla, th_M, th_fla


def oil_density(rho15: float, theta: float) -> float:
    """Density [kg/m³] of a mineral oil at θ [°C] from its density at 15 °C, with the
    volumetric expansion 0.0007 1/K of mineral oils (:data:`.tables.OIL_EXPANSION`;
    [ISO6336-21])."""
    return rho15 * (1.0 - T.OIL_EXPANSION * (theta - 15.0))
