"""GOST 21354-87, load factors: the dynamic factor K_v (specific dynamic force w_v), the
face load factors K_Hβ, K_Fβ, the transverse load factors K_Hα, K_Fα with the mesh
stiffness and the GOST 1643-81 pitch deviations, and the load factors and stresses at the
peak torque.

Pure functions written with :mod:`geardesign.core.xp` (numbers or arrays of candidates);
units and sources (the ZPCIL and DANNYE programs checked against [GOST21354]) as
:mod:`.formulas` says.
"""

from __future__ import annotations

import math

from geardesign.core import xp
from geardesign.spur.strength.gost21354 import tables as T
from geardesign.spur.strength.gost21354.bending import y_eps


# ----------------------------------------------------------------------------- load factors


def module_class(m: float) -> int:
    """Module class of the tables of g_0 and w_max: 0 (m ≤ 3.55), 1 (≤ 10), 2 (> 10) [mm]
    ([GOST21354] tables of g_0 and w_max)."""
    lo, hi = T.MODULE_CLASSES
    return xp.where(m <= lo, 0, xp.where(m <= hi, 1, 2))


def pitch_factors(grade: int, m: float) -> tuple[float, float]:
    """The pitch deviation factor g_0 and the limit w_max [N/mm] of the specific dynamic
    force by accuracy grade and module class (``tables.G0``, ``tables.W_MAX``).
    References: [GOST21354] table 7; [ZPCIL] WV.h."""
    j = module_class(m)
    return 1.0 * xp.take(T.G0[grade], j), 1.0 * xp.take(T.W_MAX[grade], j)


def specific_dynamic_force(delta: float, g_0: float, w_max: float, v: float, a_w: float,
                           u: float) -> float:
    """Specific dynamic force w_v = δ·g_0·v·√(a_w/u) ≤ w_max [N/mm] (:func:`dynamic_load`
    with g_0, w_max of :func:`pitch_factors`).  [GOST21354]."""
    return xp.minimum(delta * g_0 * v * xp.sqrt(a_w / u), w_max)


def dynamic_load(delta: float, grade: int, m: float, v: float, a_w: float, u: float) -> float:
    """Specific dynamic force w_v [N/mm].

    .. math:: w_v = δ\\, g_0\\, v \\sqrt{a_w/u} \\le w_{max}

    δ from ``tables.DELTA_H``/``DELTA_F``, g_0 and w_max by accuracy grade and module
    (``tables.G0``, ``tables.W_MAX``); v [m/s], a_w [mm].
    References: [GOST21354]; [ZPCIL] ``WV.h``; [ZPCIL] DLTH.h, WV.h; [DANNYE] (the δ·g_0
    product of the textbook pairing is 10× too large).
    """
    return specific_dynamic_force(delta, *pitch_factors(grade, m), v, a_w, u)


def k_v(w_v: float, b_w: float, F_t: float, K_A: float) -> float:
    """Dynamic factor K_v = 1 + w_v·b_w/(F_t·K_A).

    References: [GOST21354]; [ZPCIL] ``CONTAU.h``/``IZGIBU.h`` (which floor F_t/b_w at
    150 N/mm, a program option not used here); [GOST21354].
    """
    return 1.0 + w_v * b_w / (F_t * K_A)


def k_h_beta(scheme: int, psi_bd: float, run_in: bool) -> float:
    """Face load factor for contact from the GOST 21354-87 chart.

    .. math:: K_{Hβ} = 1 + A ψ_{bd} + B ψ_{bd}^2, \\qquad ψ_{bd} = b_w/d_1

    A, B per bearing-arrangement scheme 1…7 and running-in class (``tables.KH_BETA_FIT``).
    References: [GOST21354] chart of K_Hβ; [ZPCIL] ``AKHBT.h`` (Fortran order).
    """
    A, B = T.KH_BETA_FIT[scheme][0 if run_in else 1]
    return 1.0 + A * psi_bd + B * psi_bd * psi_bd


def n_f(b_w: float, h: float) -> float:
    """Exponent of the bending face load factor N_F = (b/h)²/(1 + b/h + (b/h)²).

    h = 2m_n for helical gears, 2m_n/ε_α for spur gears [mm]; b_w [mm].
    References: [ZPCIL] ``AKFBTP.h``; ISO 6336-1 (form of N_F).
    """
    r = b_w / h
    return r * r / (1.0 + r + r * r)


def k_f_beta(K0_Hbeta: float, b_w: float, h: float) -> float:
    """Face load factor for bending K_Fβ = (K⁰_Hβ)^N_F (:func:`n_f`).

    K⁰_Hβ is the chart value before running-in (:func:`k_h_beta` with ``run_in=False``):
    the tooth root does not run in, so the bending factor of a soft pair is raised from the
    initial face load distribution, not from the run-in K_Hβ (which made K_Fβ 3–13 % low).
    References: [GOST21354] chart relation of K_Fβ to K⁰_Hβ; [ZPCIL] ``AKFBTP.h``.
    """
    return K0_Hbeta ** n_f(b_w, h)


def mesh_stiffness(z_v1: float, z_v2: float, x1: float, x2: float) -> float:
    """Single-pair tooth stiffness c' [N/(mm·µm)].

    .. math:: 1/c' = 0.05139 + 0.1425/z_{v1} + 0.1860/z_{v2} - 0.01x_1 - 0.1027x_1/z_{v1}
              + 0.00455x_2 + 0.3762x_2/z_{v2} + 0.00734x_1^2 - 0.00054x_2^2

    References: [ZPCIL] ``CE.h`` (Fortran and C++ alike); [ZPCIL] AKHA.h.
    """
    q = (0.05139 + 0.1425 / z_v1 + 0.1860 / z_v2 - 0.01 * x1 - 0.1027 * x1 / z_v1
         + 0.00455 * x2 + 0.3762 * x2 / z_v2 + 0.00734 * x1 * x1 - 0.00054 * x2 * x2)
    return 1.0 / q


def base_pitch_deviation(m: float, d: float, grade: int) -> float:
    """Limit base pitch deviation f_pb [µm] (GOST 1643-81 tolerance as fitted by ZPCIL
    ``FPB.h``): f_pb = (1.25m + 0.31√d + 16)·0.94·1.4^(n − 8); m, d [mm], n the grade.
    [GOST1643] as fitted by [ZPCIL] ``FPB.h``.

    >>> round(float(base_pitch_deviation(4.0, 100.0, 8)), 3)
    22.654"""
    return (1.25 * m + 0.31 * xp.sqrt(d) + 16.0) * 0.94 * 1.4 ** (grade - 8)


def tooth_direction_tolerance(b: float, grade: int) -> float:
    """Tooth direction tolerance F_β [µm] for the contact-norm grade ([GOST1643] as
    fitted by [ZPCIL] ``FCBE.h``, used by its K_Hβ routine ``AKHB0.h``):
    F_β = (2√b + 10)·1.4^(n − 8), b the face width [mm]."""
    return (2.0 * math.sqrt(b) + 10.0) * 1.4 ** (grade - 8)


def k_alpha(eps_alpha: float, eps_beta: float, c_gamma: float, b_w: float, f_pb: float,
            a_alpha: float, F_t: float, K_A: float, K_v: float, K_beta: float) -> float:
    """Transverse load factor K_α of a helical pair (1 for spur gears).

    .. math::
        C = \\frac{c_γ b_w a_α f_{pb}}{F_t K_A K_v K_β}, \\quad
        K_α = 0.9 + 0.4 C \\sqrt{2(ε_γ - 1)/ε_γ}\\;(ε_γ \\ge 2), \\quad
        ε_γ(0.9 + 0.4C)/2\\;(ε_γ < 2), \\quad K_α \\ge 1

    c_γ = c'(0.75ε_α + 0.25) [N/(mm·µm)]; a_α = 0.2 (≤ 350 HB) or 0.3 for contact, 0.4 for
    bending; f_pb = √(f_pb1² + f_pb2²) [µm].
    References: [ZPCIL] ``AKHA.h``; [ZPCIL] AKHA.h.
    """
    eps_gamma = eps_alpha + eps_beta
    C = c_gamma * b_w * a_alpha * f_pb / (F_t * K_A * K_v * K_beta)
    k = xp.where(eps_gamma >= 2.0,
                 0.9 + 0.4 * C * xp.sqrt(xp.maximum(2.0 * (eps_gamma - 1.0) / eps_gamma, 0.0)),
                 eps_gamma * (0.9 + 0.4 * C) / 2.0)
    return xp.maximum(k, 1.0)


def k_h_alpha_max(eps_alpha: float, eps_beta: float, Z_eps: float) -> float:
    """Upper limit of K_Hα: ε_γ/(ε_α Z_ε²) for ε_β < 1; 0.95ε_α for ε_β < ε_α;
    0.95ε_α²/ε_β otherwise.  [GOST21354] as [ZPCIL] ``CONTAU.h``."""
    return xp.where(eps_beta < 1.0, (eps_alpha + eps_beta) / (eps_alpha * Z_eps * Z_eps),
                    xp.where(eps_beta < eps_alpha, 0.95 * eps_alpha,
                             0.95 * eps_alpha * eps_alpha / xp.maximum(eps_beta, 1.0)))


def k_f_alpha_max(eps_alpha: float, eps_beta: float) -> float:
    """Upper limit of K_Fα: 1/Y_ε, with the GOST contact ratio factor Y_ε of :func:`y_eps`.

    The bending stress carries K_Fα·Y_ε; their product is the share of F_t taken by one
    tooth and cannot exceed the whole load, so K_Fα ≤ 1/Y_ε (= ε_α for ε_β > 1).  The
    ISO 6336-1 limit ε_γ/(0.25ε_α + 0.75) pairs with the ISO factor Y_ε = 0.25 + 0.75/ε_α
    and must not be used with the GOST Y_ε = 1/ε_α (it let K_Fα·Y_ε reach 1.69).
    [GOST21354] (Y_ε as :func:`y_eps`).
    """
    return 1.0 / y_eps(eps_alpha, eps_beta)


def limited(k: float, k_max: float) -> tuple[float, bool]:
    """A transverse load factor within its limits: min(k, k_max), then never below 1.

    The floor is applied after the cap: the cap 0.95ε_α²/ε_β of K_Hα falls below 1 for wide
    helical pairs (ε_β > 0.95ε_α²), and a load factor below 1 would rate the pair for less
    than its load.  Returns the factor and whether the cap set it: k > k_max ≥ 1 (with
    k_max < 1 the floor sets the factor to 1, and the report says so, not "capped").
    [GOST21354] as [ZPCIL] ``CONTAU.h``.
    """
    capped = (k > k_max) & (k_max >= 1.0)
    return xp.maximum(1.0, xp.minimum(k, k_max)), capped


# ----------------------------------------------------------------------------- peak loads


def peak_factor(K: float, T: float, T_max: float) -> float:
    """A face or transverse load factor at the peak torque: (K − 1)·T/T_max + 1 (T, T_max
    in the same unit).  [GOST21354] as [ZPCIL] ``SIGMAX.h`` (K_v = 1 at the peak).

    >>> round(peak_factor(1.2, 100.0, 200.0), 6)
    1.1

    K_Hmax and K_Fmax are products of these factors only: the peak torque T_max is an actual
    torque, so the application factor K_A does not enter them (with K_A in them the peak
    stresses grew with K_A although the torque did not).
    """
    return (K - 1.0) * T / T_max + 1.0


def sigma_h_max(sigma_H: float, T: float, T_max: float, K_H: float, K_Hmax: float) -> float:
    """σ_Hmax = σ_H·sqrt(T_max·K_Hmax/(T·K_H)).  [ZPCIL] ``SIGMAX.h``; [GOST21354]."""
    return sigma_H * xp.sqrt(T_max * K_Hmax / (T * K_H))


def sigma_f_max(sigma_F: float, T: float, T_max: float, K_F: float, K_Fmax: float) -> float:
    """Peak bending stress σ_Fmax = σ_F·T_max·K_Fmax/(T·K_F) [MPa].  [GOST21354] as
    [ZPCIL] ``SIGMAX.h``.

    >>> round(sigma_f_max(100.0, 100.0, 200.0, 1.5, 1.2), 6)
    160.0
    """
    return sigma_F * T_max * K_Fmax / (T * K_F)


S_FST = 1.75
"""Safety factor against the static bending limit S_FSt [GOST21354]."""


def sigma_fp_max(sigma_FSt: float, Y_X: float, Y_z: float, S_FSt: float = S_FST) -> float:
    """Allowable bending stress under the peak load σ_FPmax = σ_FSt·Y_z·Y_X/S_FSt,
    S_FSt = 1.75 (Y_z: 1 forging, 0.9 rolled, 0.8 casting).

    References: [GOST21354]; [ZPCIL] ``IZGIBU.h`` (σ_FSt·Y_X/(1.75·Y_z)), Delphi ``TPer``
    (S_FSt = 1.75·Y_z) and MATLAB DANNYE (σ_FSt values); the two programs place Y_z
    differently, here it lowers the limit of a weaker blank.
    """
    return sigma_FSt * Y_z * Y_X / S_FSt
