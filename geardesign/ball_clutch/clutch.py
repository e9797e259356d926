"""Ball overrunning-safety clutch: force sharing and the limit (release) torque ([Malashchenko2025]).

The clutch is two units in series ([Malashchenko2025], Fig. 1-2): a ball *freewheel* (z1 balls on the
diameter d4) that transmits torque one way only, and a ball *safety* part (z3 balls on the
diameter d5 = 2·r0) whose balls sit in sockets and are held in by springs.  A safety ball is
pushed out of its socket (radially outward, compressing its spring) when the circumferential
force overcomes the spring force; it also carries its own centrifugal force outward.

Units: torques N·m, forces N, lengths m inside the functions (the calculator converts mm),
angles rad, speeds rad/s, masses kg.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass


def ball_forces(T: float, z1: int, d4: float, z3: int, d5: float) -> tuple[float, float]:
    """Circumferential force on one freewheel ball and on one safety ball [N].

    .. math:: F_{t1} = \\frac{2T}{d_4 z_1},\\qquad F_{t2} = \\frac{F_{t1} d_4 z_1}{d_5 z_3}
              = \\frac{2T}{d_5 z_3}

    ([Malashchenko2025] eqs. (1)-(4): the torque balance F_t1·d4·z1 = F_t2·d5·z3 between the two
    parts in series; T = P1/ω1).  Parameters: T torque [N·m], z1, z3 ball numbers,
    d4, d5 diameters of the ball-centre circles [m].
    """
    return 2.0 * T / (d4 * z1), 2.0 * T / (d5 * z3)


def centrifugal_force(m: float, r0: float, omega: float) -> float:
    """Centrifugal force of one safety ball (with its plunger), F_c = m·r0·ω² [N]
    ([Malashchenko2025] eqs. (10), (15): the term m·r0·ω²).

    Example: m = 0.01 kg at r0 = 0.05 m and ω = 100 rad/s: F_c = 0.01·0.05·100² = 5 N:

    >>> round(centrifugal_force(0.01, 0.05, 100.0), 9)
    5.0
    """
    return m * r0 * omega * omega


def limit_torque(F_spring: float, F_c: float, z3: int, r0: float, alpha: float,
                 f: float = 0.0, f_g: float = 0.0) -> float:
    """Torque at which the safety balls leave their sockets [N·m].

    Quasi-static limit of [Malashchenko2025] eq. (15) (driven side blocked, I3 -> ∞, gravity
    neglected), all z3 balls sharing equally, with friction added:

    .. math:: T_{lim} = \\frac{z_3 r_0 (c y_0 - m r_0 ω^2)}{\\cot(α_2 + ρ) - f_g},
              \\qquad ρ = \\arctan f

    Without friction (f = f_g = 0) this is z3·r0·tan α2·(c·y0 − m·r0·ω²), the paper's form.
    The friction form is written after M. N. Ivanov's
    ball/cam safety-clutch formula: friction ρ at the socket contact and f_g of the ball
    (plunger) in its guide bore both oppose the outward motion.

    Parameters: F_spring = c·y0 spring force on one ball [N], F_c centrifugal force [N],
    z3 balls, r0 radius of the ball centres [m], alpha socket angle α2 (line of the contact
    force from the radial direction) [rad], f, f_g friction coefficients.
    Returns +inf when the denominator is <= 0 (self-locking: no release), and 0 when the
    centrifugal force reaches the spring force (the balls leave without any torque; the
    formula would give a negative torque).
    """
    den = 1.0 / math.tan(alpha + math.atan(f)) - f_g
    if den <= 0.0:
        return math.inf
    return z3 * r0 * max(F_spring - F_c, 0.0) / den


def self_locking_angle(f: float, f_g: float) -> float:
    """Largest socket angle α2 that still releases [rad]: cot(α2 + ρ) > f_g
    <=> α2 < arctan(1/f_g) − arctan f (:func:`limit_torque`, denominator > 0)."""
    return (math.pi / 2.0 if f_g == 0.0 else math.atan(1.0 / f_g)) - math.atan(f)


def required_spring_force(T: float, F_c: float, z3: int, r0: float, alpha: float,
                          f: float, f_g: float) -> float:
    """Spring force on one ball for a target limit torque T (design mode) [N]:
    c·y0 = T·(cot(α2 + ρ) − f_g)/(z3·r0) + m·r0·ω², :func:`limit_torque` solved for c·y0."""
    return T * (1.0 / math.tan(alpha + math.atan(f)) - f_g) / (z3 * r0) + F_c


def release_speed(F_spring: float, m: float, r0: float) -> float:
    """Speed at which the centrifugal force alone equals the spring force [rad/s]:
    m·r0·ω² = c·y0 ([Malashchenko2025] eq. (15) with T_p = 0)."""
    return math.sqrt(F_spring / (m * r0))


def inertia_factor(z3: int, m: float, r0: float, I1: float, I3: float) -> float:
    """Ratio of the release torque with a free driven inertia to the blocked-drive value.

    [Malashchenko2025] eq. (15): (m r0² + I1 + I3)/(m r0² + I3), the share of a drive torque T_p that
    reaches the balls while the whole train accelerates (eq. (12): R1 = (T_p − I1·φ'')/…,
    φ'' = T_p/(m r0² + I1 + I3)).  The paper writes one ball; here the balls' term is
    z3·m·r0² (all balls move with the sleeve).  I1 drive-side (central part), I3 driven
    (sleeve) inertia [kg·m²].
    """
    mb = z3 * m * r0 * r0
    return (mb + I1 + I3) / (mb + I3)


@dataclass(frozen=True)
class LimitBand:
    """Limit torques [N·m] at the low, nominal and high friction."""

    low: float
    nominal: float
    high: float


def limit_band(F_spring: float, F_c: float, z3: int, r0: float, alpha: float, f: float,
               f_g: float, spread: float) -> LimitBand:
    """Limit torque with both friction coefficients scaled by (1 − spread), 1, (1 + spread):
    the scatter of the release torque (typically ±10...25 % for ball safety clutches,
    [Malashchenko2025])."""
    lo, hi = 1.0 - spread, 1.0 + spread
    return LimitBand(
        limit_torque(F_spring, F_c, z3, r0, alpha, f * lo, f_g * lo),
        limit_torque(F_spring, F_c, z3, r0, alpha, f, f_g),
        limit_torque(F_spring, F_c, z3, r0, alpha, f * hi, f_g * hi))


def ball_mass(d_ball: float, density: float) -> float:
    """Mass of a solid ball, ρ·π·d³/6 [kg] (d in m, ρ in kg/m³)."""
    return density * math.pi * d_ball ** 3 / 6.0
