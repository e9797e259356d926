"""Dynamics of a Geneva-indexed spindle block (barrel) of a multi-spindle automatic: [RotaryDevices].

The distributing (cam) shaft carries the Geneva crank and turns at ω_r; the cross turns the
barrel through a gear with ratio i = z/n_pos (the barrel turns 2π/n_pos per index while the
cross turns 2π/z), so the barrel speed is ω_b = u3(φ)·ω_r with u3 = i·ω2/ω1.  During indexing
the spindles keep turning at their working speed ω_sh.rab and, carried round with the barrel,
roll on the central gear: ω_sh = ω_sh.rab + s·u_p·ω_b with u_p = 1 + z_ts/z_sh and s = +1
(barrel and spindles turn the same way), −1 (opposite) or 0 (spindle drive declutched).

Everything is reduced to the distributing shaft (one degree of freedom, rigid links).  The
seed's ratios are u1 = ω_r/ω_d, u2 = ω_r/ω_sh.rab, u3 = ω_b/ω_k (ω_k = ω_r, the crank is on
the distributing shaft).  SI units inside (kg·m², rad/s, N·m, W).
"""

from __future__ import annotations

from geardesign.core.records import dataclass


@dataclass(frozen=True)
class SpindleBlock:
    """Data of the indexed spindle block (SI units)."""

    J_b: float          # barrel with cross and intermediate gears, without spindles [kg·m²]
    M_tr: float         # friction moment resisting the barrel rotation [N·m]
    eta_b: float        # efficiency motor -> barrel
    i_kb: float         # barrel turn per cross turn, z/n_pos
    n_sh: int = 0       # number of spindles
    J_sh: float = 0.0   # one spindle with workpiece [kg·m²]
    m_sh: float = 0.0   # one spindle's mass [kg]
    R_b: float = 0.0    # spindle axis to barrel axis [m]
    u_p: float = 0.0    # signed planetary ratio s·(1 + z_ts/z_sh)
    w_rab: float = 0.0  # spindle working speed [rad/s]
    eta_sh: float = 1.0  # efficiency motor -> spindle (planetary motion through the cross)
    J_d: float = 0.0    # motor rotor [kg·m²]
    w_d: float = 0.0    # motor speed [rad/s] (0: no motor reduction)
    J_r: float = 0.0    # distributing shaft with crank and worm wheel [kg·m²]
    M_x: float = 0.0    # idle moment reduced to the distributing shaft [N·m]


def planetary_ratio(z_central: int, z_spindle: int, direction: str) -> float:
    """Signed u_p: s·(1 + z_ts/z_sh), s = +1 "same", −1 "opposite", 0 "declutched".

    A spindle gear z_sh rolling on the fixed central gear z_ts while the barrel turns by
    ω_b turns by (1 + z_ts/z_sh)·ω_b relative to the frame (planetary kinematics, external
    mesh; the paper prints u_p = 1 + z_ts/z_sh, index order reconstructed).
    """
    s = {"same": 1.0, "opposite": -1.0, "declutched": 0.0}[direction]
    return s * (1.0 + z_central / z_spindle)


@dataclass(frozen=True)
class InertiaCoefficients:
    """J_p(φ) = B1 + B2·u3² + B12·u3 ([RotaryDevices] eq. (2)) [kg·m²]."""

    B1: float
    B2: float
    B12: float


def inertia_coefficients(s: SpindleBlock, w_r: float) -> InertiaCoefficients:
    """Coefficients of the reduced moment of inertia, [RotaryDevices] eq. (2):

    .. math::
        B_1 = J_d/u_1^2 + n_{sh} J_{sh}/u_2^2 + J_r,\\quad
        B_2 = J_{b.pr} = J_b + n_{sh} J_{sh} u_p^2 + n_{sh} m_{sh} R_b^2,\\quad
        B_{12} = 2 n_{sh} J_{sh} u_p / u_2

    with u1 = ω_r/ω_d and u2 = ω_r/ω_sh.rab (so J_d/u1² = J_d·(ω_d/ω_r)²: the motor rotor
    reduced to the slow shaft), u_p signed (:func:`planetary_ratio`).  They follow from the
    kinetic energy T = ½J_dω_d² + ½J_rω_r² + ½J_bω_b² + n_sh[½m_sh(R_bω_b)² + ½J_shω_sh²]
    with ω_sh = ω_sh.rab + u_p·ω_b.  B1 is constant and does not enter the dynamic moment.

    Parameters: the spindle block ``s``, distributing-shaft speed w_r [rad/s].
    Reference: [RotaryDevices] eq. (2) (reconstructed from the fragments, [RotaryDevices] eq. (2)).
    """
    B1 = s.J_r
    if s.w_d > 0.0:
        B1 += s.J_d * (s.w_d / w_r) ** 2
    B1 += s.n_sh * s.J_sh * (s.w_rab / w_r) ** 2
    B2 = s.J_b + s.n_sh * s.J_sh * s.u_p ** 2 + s.n_sh * s.m_sh * s.R_b ** 2
    B12 = 2.0 * s.n_sh * s.J_sh * s.u_p * s.w_rab / w_r
    return InertiaCoefficients(B1, B2, B12)


@dataclass(frozen=True)
class DrivePoint:
    """The drive at one crank angle (SI units; powers in W)."""

    u3: float       # ω_b/ω_r
    du3: float      # du3/dφ
    J_p: float      # reduced moment of inertia [kg·m²]
    dJ_p: float     # dJ_p/dφ [kg·m²/rad]
    M_d: float      # driving moment on the distributing shaft (efficiencies 1) [N·m]
    N_d: float      # M_d·ω_r [W]
    N_b: float      # power to the barrel (orbit + friction), efficiency applied [W]
    N_sh: float     # power to the spindles' own rotation, efficiency applied [W]
    N: float        # motor power N_b + N_sh + M_x·ω_r [W]
    w_sh: float     # spindle speed during indexing [rad/s]


def with_efficiency(power: float, eta: float) -> float:
    """Motor power for a power ``power`` delivered through a drive of efficiency η.

    Power taken by the load is divided by η (the motor supplies the losses); power given
    back by the load (negative, e.g. spindles braked by the planetary motion) is
    multiplied by η (the losses reduce what returns).  The paper divides every term by η;
    for negative terms that would make the losses return energy ([RotaryDevices]).
    """
    return power / eta if power >= 0.0 else power * eta


def drive_point(s: SpindleBlock, B: InertiaCoefficients, w_r: float, omega_ratio: float,
                eps_ratio: float) -> DrivePoint:
    """Moments and powers at one crank angle, distributing shaft at constant speed ω_r.

    Lagrange form, [RotaryDevices] eqs. (1) and (3), first approximation (ω_r constant):

    .. math::
        M_d = M_c + \\frac{ω_r^2}{2} \\frac{dJ_p}{dφ},\\quad
        \\frac{dJ_p}{dφ} = (2 B_2 u_3 + B_{12}) \\frac{du_3}{dφ},\\quad
        M_c = M_x + ΣM_{tr}·u_3,\\quad N_d = M_d ω_r

    with u3 = i·ω2/ω1 and du3/dφ = i·ε2/ω1².  Direct power form (the paper's power balance
    printed before eq. (1)), with efficiencies:

    .. math::
        N_b = \\frac{(J_b + n_{sh} m_{sh} R_b^2) ε_b ω_b + ΣM_{tr} ω_b}{η_b},\\quad
        N_{sh} = \\frac{n_{sh} J_{sh} u_p ε_b (ω_{sh.rab} + u_p ω_b)}{η_{sh}}

    (negative parts multiplied by η instead, :func:`with_efficiency`).  With all η = 1,
    N_b + N_sh + M_x ω_r = N_d identically (the two forms are the same physics).

    Parameters: spindle block ``s``, coefficients ``B``, w_r [rad/s], ω2/ω1 and ε2/ω1² of
    the Geneva mechanism at the angle.  Reference: [RotaryDevices] eqs. (1)-(3), [RotaryDevices].
    """
    u3 = s.i_kb * omega_ratio
    du3 = s.i_kb * eps_ratio
    J_p = B.B1 + B.B2 * u3 * u3 + B.B12 * u3
    dJ_p = (2.0 * B.B2 * u3 + B.B12) * du3
    M_d = s.M_x + s.M_tr * u3 + 0.5 * w_r * w_r * dJ_p
    w_b = u3 * w_r
    e_b = du3 * w_r * w_r
    w_sh = s.w_rab + s.u_p * w_b
    N_b_raw = (s.J_b + s.n_sh * s.m_sh * s.R_b ** 2) * e_b * w_b + s.M_tr * w_b
    N_sh_raw = s.n_sh * s.J_sh * s.u_p * e_b * w_sh
    N_b = with_efficiency(N_b_raw, s.eta_b)
    N_sh = with_efficiency(N_sh_raw, s.eta_sh)
    return DrivePoint(u3=u3, du3=du3, J_p=J_p, dJ_p=dJ_p, M_d=M_d, N_d=M_d * w_r, N_b=N_b,
                      N_sh=N_sh, N=N_b + N_sh + s.M_x * w_r, w_sh=w_sh)
