"""The life modification factor a_ISO of ISO 281:2007 (= GOST 18855-2013) clause 9.3 and
its inputs: the reference viscosity ν1, the fatigue load limit C_u, the contamination
factor e_C, the temperature factor and the a23 factor of GOST 18855-94."""

from __future__ import annotations


from geardesign.bearing import tables as T
from geardesign.bearing.life import interp, is_ball
from geardesign.core.records import dataclass


def nu1(n: float, D_pw: float) -> float:
    """Reference kinematic viscosity ν1 [mm²/s] (ISO 281:2007 eq. (28)/(29), standards check §1):
    ν1 = 45000·n^−0.83·D_pw^−0.5 for n < 1000 min⁻¹, ν1 = 4500·n^−0.5·D_pw^−0.5 for n >= 1000
    (n [min⁻¹], D_pw [mm]).  The two branches differ by ~2 % at n = 1000 (inherent).

    Example: n = 1000 min⁻¹, D_pw = 100 mm: ν1 = 4500/(√1000·√100) = 14.23 mm²/s:

    >>> round(nu1(1000.0, 100.0), 2)
    14.23
    """
    if n < 1000.0:
        return 45000.0 * n ** -0.83 * D_pw ** -0.5
    return 4500.0 * n ** -0.5 * D_pw ** -0.5


@dataclass(frozen=True)
class AIso:
    value: float
    kappa_used: float
    ratio: float                 # e_C·C_u/P (thrust: divided by 3 or 2.5)
    capped: bool
    limit: float
    kappa_clamped: str           # "", "low" (κ < 0.1) or "high" (κ > 4)
    ep_rule: bool


def a_iso(kind: str, kappa: float, e_C: float, C_u: float, P: float,
          ep_additives: bool = False) -> AIso:
    """Life modification factor a_ISO (ISO 281:2007, systems approach; standards check §5).

    Radial ball: a_ISO = 0.1·[1 − (2.5671 − c2/κ^c3)^0.83·(e_C·C_u/P)^(1/3)]^−9.3;
    radial roller: a_ISO = 0.1·[1 − (1.5859 − c2/κ^c3)·(e_C·C_u/P)^0.4]^−9.185, with (c2, c3)
    by κ band (0.1 <= κ < 0.4, 0.4 <= κ < 1, 1 <= κ <= 4; :data:`.tables.A_ISO_BALL`).
    Thrust ball/roller: the same with e_C·C_u/(3·P) / e_C·C_u/(2.5·P) (medium confidence).
    κ is limited to 0.1 … 4; a_ISO <= 50 (and 50 where the bracket is <= 0).  With effective
    EP additives, κ < 1 and e_C >= 0.2, κ = 1 is used and a_ISO <= 3 (ISO 281 §9.3.3.4 as
    transcribed, secondary).

    **Ball exponent c3 for 0.4 <= κ < 1: 0.19087 is used, not 0.019087.**  The standard's
    print could not be read.  One public implementation (Dessia MechanicalComponents) uses
    0.019087; the one that transcribes ISO 281 equation (32) uses 0.19087, as do both roller
    branches.  Only 0.19087 keeps a_ISO continuous at κ = 0.4 (bracket constant
    1.9987/0.4^0.19087 = 2.3807 against 2.2649/0.4^0.054381 = 2.3806); 0.019087 gives 2.0340,
    a jump of a_ISO by a factor of 4 to 35 for e_C·C_u/P between 0.2 and 1.
    """
    ball = is_ball(kind)
    bands = T.A_ISO_BALL if ball else T.A_ISO_ROLLER
    const, expo, r_expo, slope = T.A_ISO_BALL_CONST if ball else T.A_ISO_ROLLER_CONST
    clamped = "low" if kappa < T.KAPPA_MIN else ("high" if kappa > T.KAPPA_MAX else "")
    k = min(max(kappa, T.KAPPA_MIN), T.KAPPA_MAX)
    limit = T.A_ISO_MAX
    ep = ep_additives and k < 1.0 and e_C >= T.EP_E_C_MIN
    if ep:
        k, limit = 1.0, T.A_ISO_MAX_EP
    c2, c3 = bands[0][1:]
    for start, b2, b3 in bands:
        if k >= start:
            c2, c3 = b2, b3
    r = e_C * C_u / (P * T.THRUST_LOAD_DIVISOR.get(kind, 1.0))
    base = const - c2 / k ** c3
    term = (max(base, 0.0) ** expo) * r ** r_expo
    bracket = 1.0 - term
    if bracket <= 0.0:
        return AIso(limit, k, r, True, limit, clamped, ep)
    value = 0.1 * bracket ** -slope
    return AIso(min(value, limit), k, r, value > limit, limit, clamped, ep)


def c_u_estimate(kind: str, C_0: float, D_pw: float) -> float:
    """Approximate fatigue load limit C_u [N] from the static rating (ISO 281:2007 annex
    approximation via [Haidamaka2017], unverified): C_0/22 (ball), C_0/8.2 (roller)
    for D_pw <= 100 mm, times (100/D_pw)^0.5 / ^0.3 beyond."""
    div, expo = T.C_U_ESTIMATE["ball" if is_ball(kind) else "roller"]
    c = C_0 / div
    if D_pw > 100.0:
        c *= (100.0 / D_pw) ** expo
    return c


def e_c_guide(level: str, D_pw: float) -> float:
    """Contamination factor e_C from the ISO 281:2007 guide table: the middle of the range of
    the contamination level for D_pw < 100 mm or >= 100 mm."""
    lo, hi = T.E_C_GUIDE[level][0 if D_pw < 100.0 else 1]
    return 0.5 * (lo + hi)


def k_t(temperature: float | None) -> float:
    """Temperature factor K_т (Russian practice, :data:`.tables.K_T`): 1 up to 100 °C,
    linear interpolation to 1.40 at 250 °C."""
    if temperature is None or temperature <= T.K_T[0][0]:
        return 1.0
    return interp(temperature, [r[0] for r in T.K_T], [r[1] for r in T.K_T])


def a23_default(kind: str, conditions: str) -> float:
    """Middle of the textbook a23 range for the bearing type and conditions (GOST 18855-94
    practice, :data:`.tables.A23`)."""
    lo, hi = T.A23[kind][T.A23_CONDITIONS.index(conditions)]
    return 0.5 * (lo + hi)
