"""Manufacturing and assembly deviations of a Novikov pair and the design gaps they cause
at the contact points: the error model that Korotkin 2017 uses but does not print.

[Korotkin2017] takes the deviations from the GOST 1643-81 tolerances on
the pitch, the tooth direction, the profile and the parallelism and skew of the axes, for
the smoothness grade k_p and the contact grade k_k, "in the probabilistic sense" with the
risk parameter γ (its ref. [5]).  The combination is not printed.  This module implements
the assumption stated in [GOST1643]:

* each deviation is a zero-mean normal variable with σ_k = T_k/6, T_k the width of its
  tolerance field; the design value of a sum is ±γ·sqrt(Σσ_k²);
* per tooth pair (*pitch gap*): the pitch deviations of pinion and wheel.  The worst sign
  pattern is applied: the tooth pair under study leads by γσ_p, the others by 0;
* along the face (*lead gap*, linear in b): the tooth direction deviations of both gears
  and the axis parallelism f_x and skew f_y (projected on the contact normal), plus the
  misalignment θ of the drive (deterministic), plus the end relief Δ.

Profile deviations are left out: the method assumes run-in teeth ([Korotkin2017] input data), and no
GOST 1643-81 profile value was available.  Units: µm for deviations.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.spur.strength.gost21354 import base_pitch_deviation, tooth_direction_tolerance


def f_pb(grade: int, m: float, d: float) -> float:
    """Limit deviation of the pitch ±f_pb [µm] for the smoothness grade ``grade`` (GOST
    1643-81 base pitch tolerance as fitted by ZPCIL, :func:`geardesign.spur.strength.
    gost21354.base_pitch_deviation`), used as the pitch deviation of a Novikov tooth (which
    has no base pitch): an approximation."""
    return base_pitch_deviation(m, d, grade)


def f_beta(grade: int, b: float) -> float:
    """Tooth direction tolerance F_β [µm] for the contact grade (GOST 1643-81 as fitted by
    ZPCIL, :func:`geardesign.spur.strength.gost21354.tooth_direction_tolerance`)."""
    return tooth_direction_tolerance(b, grade)


F_X_OVER_F_BETA = 1.0
"""Axis parallelism tolerance f_x = F_β (GOST 1643-81, from memory; the same ratio as
ISO/TR 10064-3 f_Σδ = (L/b)·F_β).  Unverified."""
F_Y_OVER_F_BETA = 0.5
"""Axis skew tolerance f_y = 0.5·F_β (GOST 1643-81, from memory; ISO/TR 10064-3
f_Σβ = 0.5·(L/b)·F_β).  Unverified."""
SIGMA_PER_FIELD = 1.0 / 6.0
"""σ = T/6: a tolerance field T covers ±3σ ([GOST1643])."""


@dataclass(frozen=True)
class Tolerances:
    """GOST 1643-81 tolerances of the pair [µm] and the design deviations derived from
    them (:func:`design_deviations`)."""

    f_pb1: float
    f_pb2: float
    F_beta1: float
    F_beta2: float
    f_x: float
    f_y: float
    sigma_pitch: float
    sigma_lead: float
    pitch_design: float
    lead_design: float


def design_deviations(grade_smoothness: int, grade_contact: int, m: float, d1: float,
                      d2: float, b_w: float, alpha_k: float, gamma: float) -> Tolerances:
    """Design values of the pitch and lead deviations ([GOST1643], assumption):

    .. math::
        σ_p = \\sqrt{(2 f_{pb1}/6)^2 + (2 f_{pb2}/6)^2}, \\qquad e_p = γ σ_p

        σ_l = \\sqrt{(F_{β1}/6)^2 + (F_{β2}/6)^2 + (f_x \\sin α_k/6)^2
              + (f_y \\cos α_k/6)^2}, \\qquad e_l = γ σ_l

    (±f_pb is a field of width 2f_pb; F_β, f_x, f_y are total tolerances.  f_x lies in the
    plane of the axes and acts on the contact normal through sin α_k, f_y through cos α_k,
    as for the mesh misalignment of involute gears.)

    Parameters: grades k_p, k_k; m, d1, d2, b_w [mm]; α_k [rad]; γ risk parameter
    (normal quantile; Korotkin's example 2.17).  Returns :class:`Tolerances` [µm].
    """
    p1, p2 = f_pb(grade_smoothness, m, d1), f_pb(grade_smoothness, m, d2)
    fb = f_beta(grade_contact, b_w)
    fx, fy = F_X_OVER_F_BETA * fb, F_Y_OVER_F_BETA * fb
    s = SIGMA_PER_FIELD
    sigma_p = math.hypot(2.0 * p1 * s, 2.0 * p2 * s)
    sigma_l = math.sqrt((fb * s) ** 2 * 2 + (fx * math.sin(alpha_k) * s) ** 2
                        + (fy * math.cos(alpha_k) * s) ** 2)
    return Tolerances(p1, p2, fb, fb, fx, fy, sigma_p, sigma_l, gamma * sigma_p,
                      gamma * sigma_l)


def misalignment_lead(theta: float, b_w: float) -> float:
    """Lead mismatch over the face from a misalignment angle θ [rad]: θ·b_w, in µm
    (b_w in mm).  Positive: the face end where the contact points enter (b = 0) closes
    first ([GOST1643]: gap_i += θ·b_w·(b_i − b_ref))."""
    return theta * b_w * 1000.0


def lead_gap(lead: float, b: float) -> float:
    """Gap of a contact point at b (fraction of b_w) for a lead mismatch ``lead`` [µm] over
    the face: lead·b (a linear gap; its constant part does not change the load sharing)."""
    return lead * b


def relief_gap(relief: float, t: float) -> float:
    """Gap from the lengthwise crowning with end relief Δ [µm] (Korotkin's input Δ):
    parabolic, Δ·(2t)², zero at mid-face and Δ at both face ends (assumed shape)."""
    return relief * (2.0 * t) ** 2
