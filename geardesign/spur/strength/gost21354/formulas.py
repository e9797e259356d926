"""Strength of cylindrical involute gears to GOST 21354-87: contact and bending fatigue,
peak (static) loads.  Pure functions; stresses MPa, forces N, lengths mm, angles rad.

The standard's text could not be consulted.
Every formula below was checked against the public implementations named there — ZPCIL
(GitHub ``s-berlin/ZPCIL_test``, a port of the Fortran GOST 21354-87 program, file names
given per function) and MATLAB DANNYE — and [GOST21354] with the corrections of [ZPCIL].  Where
those sources disagree, the docstring says which was chosen.
"""

from __future__ import annotations

import math

from geardesign.core import xp
from geardesign.spur.strength.gost21354 import tables as T

# ----------------------------------------------------------------------------- contact


def z_e(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """Elasticity factor Z_E [√MPa].

    .. math:: Z_E = \\sqrt{\\frac{1}{π\\,[(1-ν_1^2)/E_1 + (1-ν_2^2)/E_2]}}

    189.8 √MPa for two steels with E = 2.06·10⁵ MPa, ν = 0.3 (GOST 21354-87 tabulates 190).
    References: GOST 21354-87 (table 6 item 1 per ZPCIL ``CONTAU.h``); ISO 6336-2 eq. (4).
    """
    return xp.sqrt(1.0 / (math.pi * ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)))


def z_h(beta_b: float, alpha_t: float, alpha_tw: float) -> float:
    """Zone factor Z_H, to be used with F_t and d at the reference circle.

    .. math:: Z_H = \\frac{1}{\\cos α_t}\\sqrt{\\frac{2\\cos β_b}{\\tan α_{tw}}}

    (2.495 for α = 20°, x_Σ = 0, β = 0.)  References: GOST 21354-87; ZPCIL ``GEOM.h``;
    [ZPCIL] CONTAU.h (the textbook pairing with d_w1 understates σ_H of
    shifted pairs by cos α_tw/cos α_t).
    """
    return xp.sqrt(2.0 * xp.cos(beta_b) / xp.tan(alpha_tw)) / xp.cos(alpha_t)


def z_eps(eps_alpha: float, eps_beta: float) -> float:
    """Contact ratio factor Z_ε.

    .. math::
        Z_ε = \\sqrt{(4-ε_α)/3} \\;(ε_β = 0);\\quad
        \\sqrt{(4-ε_α)(1-ε_β)/3 + ε_β/ε_α} \\;(0 < ε_β < 1);\\quad
        \\sqrt{1/ε_α} \\;(ε_β \\ge 1)

    References: GOST 21354-87; ZPCIL ``GEOM.h``; [GOST21354].
    """
    spur = xp.sqrt(xp.maximum((4.0 - eps_alpha) / 3.0, 0.0))
    low = xp.sqrt(xp.maximum((4.0 - eps_alpha) * (1.0 - eps_beta) / 3.0 + eps_beta / eps_alpha,
                             0.0))
    return xp.where(eps_beta <= 0.0, spur,
                    xp.where(eps_beta < 1.0, low, xp.sqrt(1.0 / eps_alpha)))


def sigma_h(Z_E: float, Z_H: float, Z_eps: float, F_t: float, K_H: float, u: float,
            b_w: float, d1: float, internal: bool = False) -> float:
    """Contact stress σ_H [MPa] of an external (or internal) pair.

    .. math:: σ_H = Z_E Z_H Z_ε \\sqrt{\\frac{F_{tH} K_H (u \\pm 1)}{b_w d_1 u}}

    F_tH = 2000·T1/d1 [N] at the reference circle, K_H = K_A K_Hv K_Hβ K_Hα, b_w [mm];
    "+" for an external pair, "−" for an internal pair (``internal=True``, u = z2/z1 of
    the internal gear over the pinion): the reduced curvature of concave and convex flanks.
    References: GOST 21354-87; ZPCIL ``CONTAU.h`` (``FTH = 2000*TQ/D1``, ``DSH = D1``);
    ISO 6336-2 §5 (u < 0 for internal gears); [GOST21354].
    """
    s = -1.0 if internal else 1.0
    return Z_E * Z_H * Z_eps * xp.sqrt(F_t * K_H * (u + s) / (b_w * d1 * u))


def n_hg(HB: float) -> float:
    """Base number of contact stress cycles N_HG = 30·HB^2.4 ≤ 1.2·10⁸.

    References: GOST 21354-87 (ZPCIL ``CONTAU.h`` «ГОСТ стр.24»; MATLAB DANNYE).
    """
    return xp.minimum(30.0 * HB ** 2.4, 1.2e8)


def z_n(N_HG: float, N_HE: float, Z_N_max: float) -> float:
    """Life factor for contact Z_N.

    .. math:: Z_N = (N_{HG}/N_{HE})^{1/6} \\le Z_{N,max} \\;(N_{HE} \\le N_{HG});\\quad
              (N_{HG}/N_{HE})^{1/20} \\ge 0.75 \\;(N_{HE} > N_{HG})

    Z_N,max = 2.6 for a homogeneous structure, 1.8 for a hardened surface.
    References: GOST 21354-87; ZPCIL ``ZLIFE.h``, ``CONTAU.h`` (floor 0.75);
    [ZPCIL] SGMHLB.h, CONTAU.h; [DANNYE].
    """
    low = N_HE <= N_HG
    z = (N_HG / N_HE) ** xp.where(low, 1.0 / 6.0, 1.0 / 20.0)
    return xp.where(low, xp.minimum(z, Z_N_max), xp.maximum(z, 0.75))


def z_v(v: float, soft: bool) -> float:
    """Velocity factor Z_v: 1 for v ≤ 5 m/s, else 0.85·v^0.1 (≤ 350 HB) or 0.925·v^0.05.

    References: GOST 21354-87; ZPCIL ``ZV.h``; [ZPCIL] (Z_v row).
    """
    if xp.scalar(soft):    # one material: only its branch
        fast = 0.85 * v ** 0.1 if soft else 0.925 * v ** 0.05
    else:
        fast = xp.where(soft, 0.85 * v ** 0.1, 0.925 * v ** 0.05)
    return xp.where(v <= 5.0, 1.0, fast)


def z_r(Ra: float) -> float:
    """Roughness factor Z_R of the flanks from the arithmetic mean roughness Ra [µm]:
    1.0 (Ra ≤ 1.25), 0.95 (≤ 2.5), 0.9 (coarser).  GOST 21354-87; ``tables.Z_R_TABLE``."""
    for limit, value in T.Z_R_TABLE:
        if Ra <= limit:
            return value
    return T.Z_R_TABLE[-1][1]  # pragma: no cover


def z_x(d: float) -> float:
    """Size factor Z_X = sqrt(1.07 − 10⁻⁴·d), between 0.75 and 1 (d [mm]).

    References: GOST 21354-87; ZPCIL ``CONTAU.h``.
    """
    return xp.minimum(1.0, xp.maximum(0.75, xp.sqrt(xp.maximum(1.07 - 1e-4 * d, 0.0))))


def contact_limit(sigma_Hlim: float, Z_N: float, Z_R: float, Z_v: float, Z_X: float) -> float:
    """Contact endurance limit of the gear as built [MPa]: σ_Hlim·Z_N·Z_R·Z_v·Z_X; divided
    by S_Hmin it is the allowable σ_HP, divided by σ_H the safety factor S_H.
    References: [GOST21354]; [ZPCIL] CONTAU.h."""
    return sigma_Hlim * Z_N * Z_R * Z_v * Z_X


def sigma_hp_pair(s1: float, s2: float, helical: bool) -> float:
    """Allowable contact stress of the pair.

    Spur gears (and helical gears with ε_β < 1): the smaller of the two.  Helical gears
    with ε_β ≥ 1: 0.45(σ_HP1 + σ_HP2), not less than σ_HPmin and not more than
    1.25·σ_HPmin.

    References: [GOST21354], the simplified rule for helical pairs as printed in the textbook
    literature (limit 1.23σ_HPmin); the limit 1.25 is the one of the Fortran line
    ``SGHP=.45*(SGHP1+SGHP2)`` / ``IF(SGHP.GT.1.25*AU)`` that [ZPCIL] ``CONTAU.h`` keeps as a
    comment only (its active routine ``SGHPBE`` integrates along the contact lines).
    """
    low = xp.minimum(s1, s2)
    return xp.where(helical, xp.minimum(xp.maximum(0.45 * (s1 + s2), low), 1.25 * low), low)


# ----------------------------------------------------------------------------- bending


def y_fs(z_v_: float, x: float) -> float:
    """Tooth form and stress concentration factor Y_FS of an external tooth.

    .. math:: Y_{FS} = 3.47 + \\frac{13.2}{z_v} - \\frac{29.7 x}{z_v} + 0.092 x^2

    z_v = z/cos³β.  The coefficient of x/z_v is 29.7 in all four public GOST programs found
    (Delphi CalculateCWheel and TPer, two MATLAB programs); a textbook prints 27.9.
    Within −3…+4 % of the GOST chart (ZPCIL ``YFS.h`` regression) for z_v 17…200.
    References: GOST 21354-87 (chart); [ZPCIL] (Y_FS rows).
    """
    return 3.47 + 13.2 / z_v_ - 29.7 * x / z_v_ + 0.092 * x * x


def y_fs_internal(x: float) -> float:
    """Tooth form factor Y_FS of an internal gear: the rack limit (z_v -> ∞) of
    :func:`y_fs`.

    .. math:: Y_{FS} = 3.47 + 0.092 x^2

    x in the GOST 19274-73 sign (positive: thinner internal teeth).  The GOST 21354-87
    chart of Y_FS for internal teeth could not be consulted:
    an internal tooth is wider at its root than the basic-rack tooth, so the rack value
    overestimates the root stress.  KISSsoft (ISO 6336-3 method B, shaper-cut rings)
    prints Y_F·Y_S = 2.71 and 2.81 for the NREL 5 MW stage-1 and stage-2 rings, where
    this gives 3.49 and 3.47: conservative by about 25 %.  An approximation, to be
    replaced by the standard's chart; a designer may give Y_FS directly.
    """
    return 3.47 + 0.092 * x * x


def y_beta(eps_beta: float, beta: float) -> float:
    """Helix factor Y_β = 1 − ε_β·β°/120 ≥ 0.7 (1 for spur gears).

    References: GOST 21354-87; ZPCIL ``IZGIBU.h``.
    """
    return xp.maximum(1.0 - eps_beta * (beta * (180.0 / math.pi)) / 120.0, 0.7)


def y_eps(eps_alpha: float, eps_beta: float) -> float:
    """Contact ratio factor for bending Y_ε: 1 (spur), 0.2 + 0.8/ε_α (0 < ε_β ≤ 1),
    1/ε_α (ε_β > 1).  References: GOST 21354-87; ZPCIL ``IZGIBU.h``;
    [ZPCIL] IZGIBU.h, YLIFE.h."""
    return xp.where(eps_beta <= 0.0, 1.0,
                    xp.where(eps_beta <= 1.0, 0.2 + 0.8 / eps_alpha, 1.0 / eps_alpha))


def y_delta(m: float) -> float:
    """Notch sensitivity factor Y_δ = 1.082 − 0.172·lg m (m [mm]).
    GOST 21354-87; ZPCIL ``IZGIBU.h``."""
    return 1.082 - 0.172 * xp.log10(m)


def y_x(d: float) -> float:
    """Size factor for bending Y_X = 1.05 − 1.25·10⁻⁴·d ≥ 0.8 (d [mm]).
    GOST 21354-87; ZPCIL ``IZGIBU.h`` (the textbook 1.03 − 0.006m is ISO 6336-3)."""
    return xp.maximum(1.05 - 1.25e-4 * d, 0.8)


def y_a(gamma_A: float, reverse_ratio: float) -> float:
    """Reversed-loading factor Y_A = 1 − γ_A·T_rev/T (1 for one-way loading).

    γ_A = 0.35 (≤ 350 HB), 0.25 (hardened), 0.10 (nitrided).
    References: GOST 21354-87; ZPCIL ``IZGIBU.h`` (``GA``); [ZPCIL].
    """
    return 1.0 - gamma_A * reverse_ratio


N_FG = 4e6
"""Base number of bending stress cycles N_FG [GOST21354]."""


def y_n(N_FE: float, q_F: int, N_FG: float = N_FG) -> float:
    """Life factor for bending Y_N = (N_FG/N_FE)^(1/q_F), N_FG = 4·10⁶, capped at 4 (q_F = 6)
    or 2.5 (q_F = 9); 1 for N_FE ≥ N_FG (the standard's variant: no decline beyond N_FG).

    References: GOST 21354-87; ZPCIL ``YLIFE.h`` (which continues below 1 beyond N_FG
    with an exponent 0.05, a plant option; GOST keeps Y_N = 1).
    """
    cap = xp.where(q_F == 6, 4.0, 2.5)
    return xp.where(N_FE >= N_FG, 1.0, xp.minimum((N_FG / N_FE) ** (1.0 / q_F), cap))


def sigma_f(F_t: float, K_F: float, b_w: float, m_n: float, Y_FS: float, Y_beta: float,
            Y_eps: float) -> float:
    """Bending stress at the tooth root [MPa].

    .. math:: σ_F = \\frac{F_{tF} K_F}{b_w m_n} Y_{FS} Y_β Y_ε

    F_tF = 2000·T/d1 at the reference circle; K_F = K_A K_Fv K_Fβ K_Fα.
    References: GOST 21354-87; ZPCIL ``IZGIBU.h`` (``FTF = 2000*TQ/D1``).
    """
    return F_t * K_F / (b_w * m_n) * Y_FS * Y_beta * Y_eps


def bending_limit(sigma_Flim: float, Y_N: float, Y_delta: float, Y_R: float, Y_X: float,
                  Y_A: float) -> float:
    """Bending endurance limit of the gear as built [MPa]: σ_Flim·Y_N·Y_δ·Y_R·Y_X·Y_A;
    divided by S_Fmin it is the allowable σ_FP, divided by σ_F the safety factor S_F.
    References: [GOST21354]; [ZPCIL] IZGIBU.h."""
    return sigma_Flim * Y_N * Y_delta * Y_R * Y_X * Y_A


# ----------------------------------------------------------------------------- load factors


def module_class(m: float) -> int:
    """Module class of the tables of g_0 and w_max: 0 (m ≤ 3.55), 1 (≤ 10), 2 (> 10) [mm]."""
    lo, hi = T.MODULE_CLASSES
    return xp.where(m <= lo, 0, xp.where(m <= hi, 1, 2))


def pitch_factors(grade: int, m: float) -> tuple[float, float]:
    """The pitch deviation factor g_0 and the limit w_max [N/mm] of the specific dynamic
    force by accuracy grade and module class (``tables.G0``, ``tables.W_MAX``).
    References: GOST 21354-87 table 7; [ZPCIL] WV.h."""
    j = module_class(m)
    return 1.0 * xp.take(T.G0[grade], j), 1.0 * xp.take(T.W_MAX[grade], j)


def specific_dynamic_force(delta: float, g_0: float, w_max: float, v: float, a_w: float,
                           u: float) -> float:
    """Specific dynamic force w_v = δ·g_0·v·√(a_w/u) ≤ w_max [N/mm] (:func:`dynamic_load`
    with g_0, w_max of :func:`pitch_factors`)."""
    return xp.minimum(delta * g_0 * v * xp.sqrt(a_w / u), w_max)


def dynamic_load(delta: float, grade: int, m: float, v: float, a_w: float, u: float) -> float:
    """Specific dynamic force w_v [N/mm].

    .. math:: w_v = δ\\, g_0\\, v \\sqrt{a_w/u} \\le w_{max}

    δ from ``tables.DELTA_H``/``DELTA_F``, g_0 and w_max by accuracy grade and module
    (``tables.G0``, ``tables.W_MAX``); v [m/s], a_w [mm].
    References: GOST 21354-87; ZPCIL ``WV.h``; [ZPCIL] DLTH.h, WV.h; [DANNYE] (the δ·g_0
    product of the textbook pairing is 10× too large).
    """
    return specific_dynamic_force(delta, *pitch_factors(grade, m), v, a_w, u)


def k_v(w_v: float, b_w: float, F_t: float, K_A: float) -> float:
    """Dynamic factor K_v = 1 + w_v·b_w/(F_t·K_A).

    References: GOST 21354-87; ZPCIL ``CONTAU.h``/``IZGIBU.h`` (which floor F_t/b_w at
    150 N/mm, a program option not used here); [GOST21354].
    """
    return 1.0 + w_v * b_w / (F_t * K_A)


def k_h_beta(scheme: int, psi_bd: float, run_in: bool) -> float:
    """Face load factor for contact from the GOST 21354-87 chart.

    .. math:: K_{Hβ} = 1 + A ψ_{bd} + B ψ_{bd}^2, \\qquad ψ_{bd} = b_w/d_1

    A, B per bearing-arrangement scheme 1…7 and running-in class (``tables.KH_BETA_FIT``).
    References: GOST 21354-87 chart; ZPCIL ``AKHBT.h`` (Fortran order).
    """
    A, B = T.KH_BETA_FIT[scheme][0 if run_in else 1]
    return 1.0 + A * psi_bd + B * psi_bd * psi_bd


def n_f(b_w: float, h: float) -> float:
    """Exponent of the bending face load factor N_F = (b/h)²/(1 + b/h + (b/h)²).

    h = 2m_n for helical gears, 2m_n/ε_α for spur gears [mm]; b_w [mm].
    References: ZPCIL ``AKFBTP.h``; ISO 6336-1 (form of N_F).
    """
    r = b_w / h
    return r * r / (1.0 + r + r * r)


def k_f_beta(K0_Hbeta: float, b_w: float, h: float) -> float:
    """Face load factor for bending K_Fβ = (K⁰_Hβ)^N_F (:func:`n_f`).

    K⁰_Hβ is the chart value before running-in (:func:`k_h_beta` with ``run_in=False``):
    the tooth root does not run in, so the bending factor of a soft pair is raised from the
    initial face load distribution, not from the run-in K_Hβ (which made K_Fβ 3–13 % low).
    References: GOST 21354-87 chart relation of K_Fβ to K⁰_Hβ; ZPCIL ``AKFBTP.h``.
    """
    return K0_Hbeta ** n_f(b_w, h)


def mesh_stiffness(z_v1: float, z_v2: float, x1: float, x2: float) -> float:
    """Single-pair tooth stiffness c' [N/(mm·µm)].

    .. math:: 1/c' = 0.05139 + 0.1425/z_{v1} + 0.1860/z_{v2} - 0.01x_1 - 0.1027x_1/z_{v1}
              + 0.00455x_2 + 0.3762x_2/z_{v2} + 0.00734x_1^2 - 0.00054x_2^2

    References: ZPCIL ``CE.h`` (Fortran and C++ alike); [ZPCIL] AKHA.h.
    """
    q = (0.05139 + 0.1425 / z_v1 + 0.1860 / z_v2 - 0.01 * x1 - 0.1027 * x1 / z_v1
         + 0.00455 * x2 + 0.3762 * x2 / z_v2 + 0.00734 * x1 * x1 - 0.00054 * x2 * x2)
    return 1.0 / q


def base_pitch_deviation(m: float, d: float, grade: int) -> float:
    """Limit base pitch deviation f_pb [µm] (GOST 1643-81 tolerance as fitted by ZPCIL
    ``FPB.h``): f_pb = (1.25m + 0.31√d + 16)·0.94·1.4^(n − 8)."""
    return (1.25 * m + 0.31 * xp.sqrt(d) + 16.0) * 0.94 * 1.4 ** (grade - 8)


def tooth_direction_tolerance(b: float, grade: int) -> float:
    """Tooth direction tolerance F_β [µm] for the contact-norm grade (GOST 1643-81 as
    fitted by ZPCIL ``FCBE.h``, used by its K_Hβ routine ``AKHB0.h``):
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
    References: ZPCIL ``AKHA.h``; [ZPCIL] AKHA.h.
    """
    eps_gamma = eps_alpha + eps_beta
    C = c_gamma * b_w * a_alpha * f_pb / (F_t * K_A * K_v * K_beta)
    k = xp.where(eps_gamma >= 2.0,
                 0.9 + 0.4 * C * xp.sqrt(xp.maximum(2.0 * (eps_gamma - 1.0) / eps_gamma, 0.0)),
                 eps_gamma * (0.9 + 0.4 * C) / 2.0)
    return xp.maximum(k, 1.0)


def k_h_alpha_max(eps_alpha: float, eps_beta: float, Z_eps: float) -> float:
    """Upper limit of K_Hα: ε_γ/(ε_α Z_ε²) for ε_β < 1; 0.95ε_α for ε_β < ε_α;
    0.95ε_α²/ε_β otherwise.  ZPCIL ``CONTAU.h``."""
    return xp.where(eps_beta < 1.0, (eps_alpha + eps_beta) / (eps_alpha * Z_eps * Z_eps),
                    xp.where(eps_beta < eps_alpha, 0.95 * eps_alpha,
                             0.95 * eps_alpha * eps_alpha / xp.maximum(eps_beta, 1.0)))


def k_f_alpha_max(eps_alpha: float, eps_beta: float) -> float:
    """Upper limit of K_Fα: 1/Y_ε, with the GOST contact ratio factor Y_ε of :func:`y_eps`.

    The bending stress carries K_Fα·Y_ε; their product is the share of F_t taken by one
    tooth and cannot exceed the whole load, so K_Fα ≤ 1/Y_ε (= ε_α for ε_β > 1).  The
    ISO 6336-1 limit ε_γ/(0.25ε_α + 0.75) pairs with the ISO factor Y_ε = 0.25 + 0.75/ε_α
    and must not be used with the GOST Y_ε = 1/ε_α (it let K_Fα·Y_ε reach 1.69).
    """
    return 1.0 / y_eps(eps_alpha, eps_beta)


def limited(k: float, k_max: float) -> tuple[float, bool]:
    """A transverse load factor within its limits: min(k, k_max), then never below 1.

    The floor is applied after the cap: the cap 0.95ε_α²/ε_β of K_Hα falls below 1 for wide
    helical pairs (ε_β > 0.95ε_α²), and a load factor below 1 would rate the pair for less
    than its load.  Returns the factor and whether the cap set it: k > k_max ≥ 1 (with
    k_max < 1 the floor sets the factor to 1, and the report says so, not "capped").
    """
    capped = (k > k_max) & (k_max >= 1.0)
    return xp.maximum(1.0, xp.minimum(k, k_max)), capped


# ----------------------------------------------------------------------------- peak loads


def peak_factor(K: float, T: float, T_max: float) -> float:
    """A face or transverse load factor at the peak torque: (K − 1)·T/T_max + 1.
    ZPCIL ``SIGMAX.h`` (K_v = 1 at the peak).

    K_Hmax and K_Fmax are products of these factors only: the peak torque T_max is an actual
    torque, so the application factor K_A does not enter them (with K_A in them the peak
    stresses grew with K_A although the torque did not).
    """
    return (K - 1.0) * T / T_max + 1.0


def sigma_h_max(sigma_H: float, T: float, T_max: float, K_H: float, K_Hmax: float) -> float:
    """σ_Hmax = σ_H·sqrt(T_max·K_Hmax/(T·K_H)).  ZPCIL ``SIGMAX.h``; [GOST21354]."""
    return sigma_H * xp.sqrt(T_max * K_Hmax / (T * K_H))


def sigma_f_max(sigma_F: float, T: float, T_max: float, K_F: float, K_Fmax: float) -> float:
    """σ_Fmax = σ_F·T_max·K_Fmax/(T·K_F).  ZPCIL ``SIGMAX.h``."""
    return sigma_F * T_max * K_Fmax / (T * K_F)


S_FST = 1.75
"""Safety factor against the static bending limit S_FSt [GOST21354]."""


def sigma_fp_max(sigma_FSt: float, Y_X: float, Y_z: float, S_FSt: float = S_FST) -> float:
    """Allowable bending stress under the peak load σ_FPmax = σ_FSt·Y_z·Y_X/S_FSt,
    S_FSt = 1.75 (Y_z: 1 forging, 0.9 rolled, 0.8 casting).

    References: ZPCIL ``IZGIBU.h`` (σ_FSt·Y_X/(1.75·Y_z)), Delphi ``TPer``
    (S_FSt = 1.75·Y_z) and MATLAB DANNYE (σ_FSt values); the two programs place Y_z
    differently, here it lowers the limit of a weaker blank.
    """
    return sigma_FSt * Y_z * Y_X / S_FSt


# ----------------------------------------------------------------------------- design


def module_estimate(T1: float, K_Fbeta: float, Y_FS: float, psi_bd: float, z1: int,
                    sigma_FP: float, K_m: float = 14.0) -> float:
    """Design module of a spur pair from the bending strength of the weaker gear [mm].

    .. math:: m = K_m \\sqrt[3]{\\frac{K_{Fβ} T_1 Y_{FS}}{ψ_{bd} z_1^2 σ_{FP}}}

    T1 [N·m] the pinion torque, Y_FS and σ_FP of the gear with the larger Y_FS/σ_FP,
    ψ_bd = b_w/d1; K_m = 14 for spur gears with T1 in N·m (1.4 with T1 in N·mm; textbook
    form of the GOST 21354-87 design calculation, as used by the KO-2 thesis, [Lopukhov] §2.1;
    verify).
    """
    return K_m * (K_Fbeta * T1 * Y_FS / (psi_bd * z1 * z1 * sigma_FP)) ** (1.0 / 3.0)


def center_distance_estimate(T1: float, u: float, K_Hbeta: float, psi_ba: float,
                             sigma_HP: float, helical: bool) -> float:
    """Design centre distance of an external steel pair [mm].

    .. math:: a_w = K_a (u + 1) \\sqrt[3]{\\frac{T_1 K_{Hβ}}{ψ_{ba} u σ_{HP}^2}}

    K_a = 495 (spur) / 430 (helical) MPa^(1/3) with T1 in N·m (``tables.K_A_DESIGN``).
    References: GOST 21354-87 (design formula; verify K_a).
    """
    Ka = T.K_A_DESIGN["helical" if helical else "spur"]
    return Ka * (u + 1.0) * (T1 * K_Hbeta / (psi_ba * u * sigma_HP ** 2)) ** (1.0 / 3.0)
