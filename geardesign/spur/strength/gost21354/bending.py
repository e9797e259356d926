"""GOST 21354-87, bending strength: the tooth form factor Y_FS, the helix, contact ratio,
notch, size, reversal and life factors, the root stress σ_F and the bending limit, and the
design module.

Pure functions written with :mod:`geardesign.core.xp` (numbers or arrays of candidates);
units and sources (the ZPCIL and DANNYE programs checked against [GOST21354]) as
:mod:`.formulas` says.
"""

from __future__ import annotations

import math

from geardesign.core import xp


# ----------------------------------------------------------------------------- bending


def y_fs(z_v_: float, x: float) -> float:
    """Tooth form and stress concentration factor Y_FS of an external tooth.

    .. math:: Y_{FS} = 3.47 + \\frac{13.2}{z_v} - \\frac{29.7 x}{z_v} + 0.092 x^2

    z_v = z/cos³β.  The coefficient of x/z_v is 29.7 in all four public GOST programs found
    (Delphi CalculateCWheel and TPer, two MATLAB programs); a textbook prints 27.9.
    Within −3…+4 % of the GOST chart ([ZPCIL] ``YFS.h`` regression) for z_v 17…200.
    References: [GOST21354] (chart); [ZPCIL] (Y_FS rows).
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
    replaced by the standard's chart; a designer may give Y_FS directly.  [GOST21354] (the
    rack limit of its Y_FS chart, as :func:`y_fs`).

    >>> round(float(y_fs_internal(0.0)), 2), round(float(y_fs_internal(0.5)), 3)
    (3.47, 3.493)
    """
    return 3.47 + 0.092 * x * x


def y_beta(eps_beta: float, beta: float) -> float:
    """Helix factor Y_β = 1 − ε_β·β°/120 ≥ 0.7 (1 for spur gears); β [rad].

    References: [GOST21354]; [ZPCIL] ``IZGIBU.h``.

    >>> round(float(y_beta(1.0, math.radians(12.0))), 6), float(y_beta(2.0, math.radians(30.0)))
    (0.9, 0.7)
    """
    return xp.maximum(1.0 - eps_beta * (beta * (180.0 / math.pi)) / 120.0, 0.7)


def y_eps(eps_alpha: float, eps_beta: float) -> float:
    """Contact ratio factor for bending Y_ε: 1 (spur), 0.2 + 0.8/ε_α (0 < ε_β ≤ 1),
    1/ε_α (ε_β > 1).  References: [GOST21354]; [ZPCIL] ``IZGIBU.h``;
    [ZPCIL] IZGIBU.h, YLIFE.h."""
    return xp.where(eps_beta <= 0.0, 1.0,
                    xp.where(eps_beta <= 1.0, 0.2 + 0.8 / eps_alpha, 1.0 / eps_alpha))


def y_delta(m: float) -> float:
    """Notch sensitivity factor Y_δ = 1.082 − 0.172·lg m (m [mm]).
    [GOST21354]; [ZPCIL] ``IZGIBU.h``."""
    return 1.082 - 0.172 * xp.log10(m)


def y_x(d: float) -> float:
    """Size factor for bending Y_X = 1.05 − 1.25·10⁻⁴·d ≥ 0.8 (d [mm]).
    [GOST21354]; [ZPCIL] ``IZGIBU.h`` (the textbook 1.03 − 0.006m is ISO 6336-3)."""
    return xp.maximum(1.05 - 1.25e-4 * d, 0.8)


def y_a(gamma_A: float, reverse_ratio: float) -> float:
    """Reversed-loading factor Y_A = 1 − γ_A·T_rev/T (1 for one-way loading).

    γ_A = 0.35 (≤ 350 HB), 0.25 (hardened), 0.10 (nitrided).
    References: [GOST21354]; [ZPCIL] ``IZGIBU.h`` (``GA``); [ZPCIL].
    """
    return 1.0 - gamma_A * reverse_ratio


N_FG = 4e6
"""Base number of bending stress cycles N_FG [GOST21354]."""


def y_n(N_FE: float, q_F: int, N_FG: float = N_FG) -> float:
    """Life factor for bending Y_N = (N_FG/N_FE)^(1/q_F), N_FG = 4·10⁶, capped at 4 (q_F = 6)
    or 2.5 (q_F = 9); 1 for N_FE ≥ N_FG (the standard's variant: no decline beyond N_FG).

    References: [GOST21354]; [ZPCIL] ``YLIFE.h`` (which continues below 1 beyond N_FG
    with an exponent 0.05, a plant option; GOST keeps Y_N = 1).

    >>> round(float(y_n(1e6, 6)), 4), float(y_n(1e8, 6)), float(y_n(1.0, 9))
    (1.2599, 1.0, 2.5)
    """
    cap = xp.where(q_F == 6, 4.0, 2.5)
    return xp.where(N_FE >= N_FG, 1.0, xp.minimum((N_FG / N_FE) ** (1.0 / q_F), cap))


def sigma_f(F_t: float, K_F: float, b_w: float, m_n: float, Y_FS: float, Y_beta: float,
            Y_eps: float) -> float:
    """Bending stress at the tooth root [MPa].

    .. math:: σ_F = \\frac{F_{tF} K_F}{b_w m_n} Y_{FS} Y_β Y_ε

    F_tF = 2000·T/d1 at the reference circle; K_F = K_A K_Fv K_Fβ K_Fα.
    References: [GOST21354]; [ZPCIL] ``IZGIBU.h`` (``FTF = 2000*TQ/D1``).
    """
    return F_t * K_F / (b_w * m_n) * Y_FS * Y_beta * Y_eps


def bending_limit(sigma_Flim: float, Y_N: float, Y_delta: float, Y_R: float, Y_X: float,
                  Y_A: float) -> float:
    """Bending endurance limit of the gear as built [MPa]: σ_Flim·Y_N·Y_δ·Y_R·Y_X·Y_A;
    divided by S_Fmin it is the allowable σ_FP, divided by σ_F the safety factor S_F.
    References: [GOST21354]; [ZPCIL] IZGIBU.h."""
    return sigma_Flim * Y_N * Y_delta * Y_R * Y_X * Y_A



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
