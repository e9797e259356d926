"""Strength of the worm wheel (contact and bending, with peak checks) and stiffness of the
worm: the classical calculation of the Russian textbooks.

Pure functions.  Torques in N·m (converted to N·mm inside), lengths in mm, stresses in
MPa.  [Chernavsky]; [Dunaev];
[WormPascal] (a public Pascal worm program confirms the allowables of group I,
K_HL, K_FL, σ_FP, the peak allowables and the Dunaev bending formula, and differs on C_v,
the K_HL limits, the θ table and the group II/III constants; those are inputs here).
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass

CONTACT_CONSTANT = 170.0
"""σ_H = (170 q/z2)·sqrt(T2·K·((z2/q + 1)/a_w)³), T2 in N·mm ([Chernavsky]; Dunaev's 5350 with T2 in
N·m is the same within 0.5 %)."""

K_HL_MIN = 0.67
K_FL_LIMITS = (0.543, 1.0)
BASE_CYCLES_H = 1e7
BASE_CYCLES_F = 1e6


@dataclass(frozen=True)
class SpectrumFactors:
    X: float      # load-regime factor Σ (T_i/T_max)·t_i/t
    K_HE: float   # Σ (T_i/T_max)^4·t_i/t
    K_FE: float   # Σ (T_i/T_max)^9·t_i/t


def spectrum_factors(spectrum: list[tuple[float, float]]) -> SpectrumFactors:
    """Factors of a load spectrum [(T_i/T_max, t_i/t), ...] at constant speed:
    X = Σ r_i s_i (K_β), K_HE = Σ r_i⁴ s_i, K_FE = Σ r_i⁹ s_i ([Chernavsky])."""
    return SpectrumFactors(sum(r * s for r, s in spectrum), sum(r ** 4 * s for r, s in spectrum),
                           sum(r ** 9 * s for r, s in spectrum))


def load_concentration_factor(z2: int, theta: float, X: float) -> float:
    """K_β = 1 + (z2/θ)³·(1 − X), θ the worm deflection coefficient ([Chernavsky];
    Chernavsky; Ivanov).  K_β = 1 for constant load (X = 1)."""
    return 1.0 + (z2 / theta) ** 3 * (1.0 - X)


def dynamic_factor(v2: float) -> float:
    """K_v = 1.0 for v2 <= 3 m/s, else 1.2, the middle of the textbooks' 1.1 ... 1.3
    ([Chernavsky]; the Pascal program uses 1.01 + 0.01 v_s).  Override in the spec."""
    return 1.0 if v2 <= 3.0 else 1.2


def contact_stress(T2: float, K: float, q: float, z2: int, a_w: float) -> float:
    """Contact stress of the wheel teeth [MPa]:

    .. math:: σ_H = \\frac{170\\,q}{z_2}\\sqrt{T_2 K \\Big(\\frac{z_2/q + 1}{a_w}\\Big)^3}

    T2 in N·m (×1000 inside), a_w in mm.  [Chernavsky].
    """
    return CONTACT_CONSTANT * q / z2 * math.sqrt(1000.0 * T2 * K * ((z2 / q + 1.0) / a_w) ** 3)


def required_center_distance(T2: float, K: float, q: float, z2: int, sigma_HP: float) -> float:
    """Least centre distance for σ_H = [σ]_H [mm]:

    .. math:: a_w = \\Big(\\frac{z_2}{q} + 1\\Big)
              \\sqrt[3]{\\Big(\\frac{170\\,q}{z_2 [σ]_H}\\Big)^2 T_2 K}

    (the inverse of :func:`contact_stress`; [Chernavsky]).

    Example: the inverse of :func:`contact_stress` (identity):

    >>> a_w = required_center_distance(500.0, 1.1, 10.0, 40, 200.0)
    >>> round(contact_stress(500.0, 1.1, 10.0, 40, a_w), 9)
    200.0
    """
    return (z2 / q + 1.0) * ((CONTACT_CONSTANT * q / (z2 * sigma_HP)) ** 2
                             * 1000.0 * T2 * K) ** (1.0 / 3.0)


def life_factor_contact(N_HE: float, K_HL_max: float = 1.15) -> float:
    """K_HL = (10⁷/N_HE)^(1/8), limited to 0.67 ... K_HL_max ([Chernavsky]: 1.15; the
    Pascal program clamps N_HE to 10⁶ ... 25·10⁷, i.e. 0.668 ... 1.33)."""
    return min(max((BASE_CYCLES_H / N_HE) ** 0.125, K_HL_MIN), K_HL_max)


def life_factor_bending(N_FE: float) -> float:
    """K_FL = (10⁶/N_FE)^(1/9), limited to 0.543 ... 1 ([Chernavsky]; Pascal PR_KL)."""
    lo, hi = K_FL_LIMITS
    return min(max((BASE_CYCLES_F / N_FE) ** (1.0 / 9.0), lo), hi)


CV_LAWS = ("power", "linear")


def speed_factor(v_s: float, law: str = "power") -> float:
    """Sliding-speed factor C_v of the tin-bronze allowable.

    * ``power`` (default): C_v = 1.66·v_s^(−0.352) ([Chernavsky], a fit of Dunaev's
      table 0.95, 0.88, 0.83, 0.80 at 5, 6, 7, 8 m/s), limited to C_v <= 1: the table
      starts at 5 m/s and the limit keeps the allowable at or below 0.9·σ_B at low speed
      (our choice);
    * ``linear``: the public Pascal program's law, 1.33 (v_s < 1), 1.4 − 0.076·v_s
      (1 ... 8 m/s), 0.8 (above).
    """
    if law == "linear":
        if v_s < 1.0:
            return 1.33
        return 1.4 - 0.076 * v_s if v_s < 8.0 else 0.8
    return min(1.0, 1.66 * max(v_s, 1e-6) ** -0.352)


@dataclass(frozen=True)
class Allowables:
    sigma_HP: float       # [σ]_H [MPa]
    sigma_FP: float       # [σ]_F [MPa]
    sigma_HP_max: float   # [σ]_Hmax, peak [MPa]
    sigma_FP_max: float   # [σ]_Fmax, peak [MPa]
    K_HL: float | None
    K_FL: float
    C_v: float | None
    sigma_H0: float | None   # the constant of groups II and III


def allowables(group: str, hardened: bool, v_s: float, N_HE: float, N_FE: float,
               reversing: bool, sigma_B: float | None, sigma_T: float | None,
               sigma_bu: float | None, cv_law: str = "power", K_HL_max: float = 1.15,
               sigma_H0: float | None = None) -> Allowables:
    """Allowable stresses of the wheel by material group ([Chernavsky]).

    Contact:

    * group I (tin bronzes): [σ]_H = K_HL·C_v·k·σ_B, k = 0.9 for a hardened (>= 45 HRC)
      ground worm, 0.75 for a worm <= 350 HB (:func:`life_factor_contact`,
      :func:`speed_factor`);
    * group II (tin-free bronzes, brass): [σ]_H = σ_H0 − 25·v_s, σ_H0 = 300 (hardened
      worm) or 250 MPa (<= 350 HB);
    * group III (grey iron): [σ]_H = σ_H0 − 35·v_s, σ_H0 = 200 MPa (Dunaev & Lelikov and
      the Pascal program; Sheinblit has 175).

    Bending: groups I and II [σ]_F = K_FL·(0.25 σ_T + 0.08 σ_B) one-way, K_FL·0.16 σ_B
    reversing; group III [σ]_F = K_FL·0.22 σ_bu one-way, K_FL·0.075 σ_bu reversing (K_FL
    applied as in the Pascal program).  Peak: [σ]_Hmax = 4σ_T (I), 2σ_T (II),
    1.65σ_bu (III); [σ]_Fmax = 0.8σ_T (I, II), 0.6σ_bu (III).
    """
    K_FL = life_factor_bending(N_FE)
    K_HL = C_v = None
    if group == "I":
        K_HL = life_factor_contact(N_HE, K_HL_max)
        C_v = speed_factor(v_s, cv_law)
        sigma_HP = K_HL * C_v * (0.9 if hardened else 0.75) * sigma_B
        sigma_H0 = None
    elif group == "II":
        sigma_H0 = sigma_H0 if sigma_H0 is not None else (300.0 if hardened else 250.0)
        sigma_HP = sigma_H0 - 25.0 * v_s
    else:
        sigma_H0 = sigma_H0 if sigma_H0 is not None else 200.0
        sigma_HP = sigma_H0 - 35.0 * v_s
    if group in ("I", "II"):
        sigma_FP = K_FL * (0.16 * sigma_B if reversing else 0.25 * sigma_T + 0.08 * sigma_B)
        sigma_HP_max = (4.0 if group == "I" else 2.0) * sigma_T
        sigma_FP_max = 0.8 * sigma_T
    else:
        sigma_FP = K_FL * (0.075 if reversing else 0.22) * sigma_bu
        sigma_HP_max = 1.65 * sigma_bu
        sigma_FP_max = 0.6 * sigma_bu
    return Allowables(sigma_HP, sigma_FP, sigma_HP_max, sigma_FP_max, K_HL, K_FL, C_v, sigma_H0)


BENDING_FORMULAS = ("dunaev", "ivanov")


def bending_stress(F_t2: float, K: float, Y_F: float, gamma_w: float, m: float, q: float,
                   x: float, b2: float, formula: str = "dunaev") -> float:
    """Bending stress of the wheel teeth [MPa].

    * ``dunaev`` (default): σ_F = K·F_t2·Y_F2·cos γ_w / (1.3·m²·(q + 2x)) (Dunaev &
      Lelikov; the Pascal program's ``Ft*KH*CosGam*YF/(1.3*M*dw1)``);
    * ``ivanov``: σ_F = 0.7·Y_F2·F_t2·K / (b2·m) (Ivanov; Chernavsky), about 10 % higher.

    Y_F2 from :func:`geardesign.worm.tables.form_factor` at z_v2 = z2/cos³γ_w.
    [Chernavsky].
    """
    if formula == "ivanov":
        return 0.7 * Y_F * F_t2 * K / (b2 * m)
    return K * F_t2 * Y_F * math.cos(gamma_w) / (1.3 * m * m * (q + 2.0 * x))


def worm_deflection(F_t1: float, F_r: float, span: float, E: float, d_f1: float,
                    d_a1: float) -> tuple[float, float]:
    """Deflection of the worm shaft at mid-span [mm] and the equivalent second moment of
    area [mm⁴]:

    .. math:: f = \\frac{l^3 \\sqrt{F_{t1}^2 + F_r^2}}{48 E I_{eq}}, \\qquad
              I_{eq} = \\frac{π d_{f1}^4}{64}\\Big(0.375 + 0.625\\frac{d_{a1}}{d_{f1}}\\Big)

    simply supported shaft of span l, central load ([Chernavsky], worm shaft
    stiffness; Dunaev & Lelikov).
    """
    I_eq = math.pi * d_f1 ** 4 / 64.0 * (0.375 + 0.625 * d_a1 / d_f1)
    return span ** 3 * math.hypot(F_t1, F_r) / (48.0 * E * I_eq), I_eq
