"""Cylindrical interference fits in the elastic range ([DIN7190-1]; thick-walled cylinders of
Lamé, [Roark]).

Diameter ratios Q_A = d_F/D_aA (hub) and Q_I = D_iI/d_F (hollow shaft).  With the effective
interference U_w = U − 0.8·(Rz_A + Rz_I) (smoothing of the roughness peaks, [DIN7190-1]) the
joint pressure is

    p = (U_w/d_F) / [ (1/E_A)·((1 + Q_A²)/(1 − Q_A²) + ν_A) + (1/E_I)·((1 + Q_I²)/(1 − Q_I²) − ν_I) ]

The joint transmits the torque T = π/2·d_F²·l_F·μ·p and the axial force F = π·d_F·l_F·μ·p
([DIN7190-1]).  Stresses are Lamé's: at the hub bore σ_t = p·(1 + Q_A²)/(1 − Q_A²), σ_r = −p;
in a solid shaft σ_t = σ_r = −p; at the bore of a hollow shaft σ_t = −2·p/(1 − Q_I²),
σ_r = 0; the equivalent stress is von Mises' of the plane stress ([Roark]).

Permissible joint pressure (:data:`PRESSURE_LIMITS`): by default DIN 7190-1's, from the
distortion-energy hypothesis with the difference of the principal stresses at the bore,
p_zul,A = R_eA·(1 − Q_A²)/(√3·S_P) for the hub, 2·R_eI/(√3·S_P) for a solid shaft and
R_eI·(1 − Q_I²)/(√3·S_P) for a hollow one ([DIN7190-1]; printed as eqs. (8) to (10) of
[WHZPressfit]); or the exact limit of the plane-stress von Mises stress above
(``"von Mises"``), which allows √3/√(3 + Q_A⁴) of the DIN pressure at the hub (1 for a thick
hub, 0.866 for a thin one) and √3/2 = 0.866 of it in the shaft: the stricter of the two.

Units: lengths mm, interference µm (converted to mm inside), stresses and moduli MPa, forces N,
torques N·mm.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass

SMOOTHING = 0.8
"""Share of the roughness depths Rz that is smoothed away on joining ([DIN7190-1])."""
CLEARANCE_SHARE = 0.001
"""Joining clearance of a shrink fit, Δs ≈ 0.001·d_F ([DIN7190-1], assembly)."""


def smoothing(rz_shaft: float, rz_hub: float) -> float:
    """Loss of interference by smoothing, 0.8·(Rz_I + Rz_A) [µm].

    >>> smoothing(4.0, 6.0)
    8.0
    """
    return SMOOTHING * (rz_shaft + rz_hub)


def compliance(d: float, D_a: float, D_i: float, E_A: float, nu_A: float, E_I: float,
               nu_I: float) -> float:
    """The relative interference per unit joint pressure, ξ/p [1/MPa] (the bracket above).

    For equal materials and a solid shaft it is 2/(E·(1 − Q_A²)):

    >>> round(compliance(50.0, 80.0, 0.0, 210e3, 0.3, 210e3, 0.3) * 210e3, 6)
    3.282051
    """
    Q_A, Q_I = d / D_a, D_i / d
    hub = ((1 + Q_A ** 2) / (1 - Q_A ** 2) + nu_A) / E_A
    shaft = ((1 + Q_I ** 2) / (1 - Q_I ** 2) - nu_I) / E_I
    return hub + shaft


def pressure(U_w: float, d: float, C: float) -> float:
    """Joint pressure p [MPa] from the effective interference U_w [µm] (0 when it is not
    positive: the parts do not grip)."""
    return max(U_w, 0.0) * 1e-3 / d / C


def interference_for(p: float, d: float, C: float) -> float:
    """Effective interference [µm] that gives the joint pressure ``p`` [MPa]."""
    return p * d * C * 1e3


def torque(p: float, d: float, l: float, mu: float) -> float:
    """Transmittable torque T = π/2·d²·l·μ·p [N·mm]."""
    return 0.5 * math.pi * d * d * l * mu * p


def axial_force(p: float, d: float, l: float, mu: float) -> float:
    """Transmittable axial force F = π·d·l·μ·p [N] (μ the slip coefficient), or the press-in
    force F_e = π·d·l·μ_e·p_max (μ_e the press-in coefficient; [DIN7190-1], [WHZPressfit]
    eq. (15))."""
    return math.pi * d * l * mu * p


def required_pressure(T: float, F_ax: float, d: float, l: float, mu: float,
                      S_R: float) -> float:
    """Least joint pressure [MPa] that carries the torque T [N·mm] and the axial force F_ax
    [N] together with the slip safety S_R: the resultant of the circumferential force 2T/d and
    F_ax must not exceed π·d·l·μ·p/S_R ([DIN7190-1])."""
    return S_R * math.hypot(2.0 * T / d, F_ax) / (math.pi * d * l * mu)


@dataclass(frozen=True)
class Stresses:
    """Lamé stresses [MPa] at the joint pressure ``p``."""

    sigma_t_hub: float       # hoop stress at the hub bore
    sigma_t_hub_outer: float
    sigma_v_hub: float       # von Mises at the hub bore
    sigma_t_shaft: float     # hoop stress at the shaft's inner-most point (bore or axis)
    sigma_v_shaft: float


def von_mises(s1: float, s2: float) -> float:
    """Plane-stress von Mises stress of two principal stresses."""
    return math.sqrt(s1 * s1 - s1 * s2 + s2 * s2)


def stresses(p: float, d: float, D_a: float, D_i: float) -> Stresses:
    """Lamé stresses of hub and shaft at joint pressure p [MPa].

    >>> s = stresses(38.4615, 40.0, 60.0, 20.0)
    >>> round(s.sigma_t_hub, 2)
    100.0
    """
    Q_A, Q_I = d / D_a, D_i / d
    st_hub = p * (1 + Q_A ** 2) / (1 - Q_A ** 2)
    st_out = 2.0 * p * Q_A ** 2 / (1 - Q_A ** 2)
    if D_i > 0:
        st_shaft = -2.0 * p / (1 - Q_I ** 2)
        sv_shaft = abs(st_shaft)
    else:
        st_shaft = -p
        sv_shaft = p
    return Stresses(st_hub, st_out, von_mises(st_hub, -p), st_shaft, sv_shaft)


PRESSURE_LIMITS = ("DIN 7190-1", "von Mises")
"""The models of the permissible joint pressure (spec key ``fit.pressure_limit``)."""


def hub_pressure_limit_din(R_e: float, d: float, D_a: float, S_P: float) -> float:
    """Permissible joint pressure of the hub [MPa], p_zul,A = R_eA·(1 − Q_A²)/(√3·S_P),
    Q_A = d_F/D_aA ([DIN7190-1]; [WHZPressfit] eq. (8)).

    >>> round(hub_pressure_limit_din(355.0, 60.0, 120.0, 1.0), 2)
    153.72
    """
    Q = d / D_a
    return R_e / S_P * (1 - Q ** 2) / math.sqrt(3.0)


def shaft_pressure_limit_din(R_e: float, d: float, D_i: float, S_P: float) -> float:
    """Permissible joint pressure of the shaft [MPa]: solid, 2·R_eI/(√3·S_P); hollow,
    R_eI·(1 − Q_I²)/(√3·S_P), Q_I = D_iI/d_F ([DIN7190-1]; [WHZPressfit] eqs. (9), (10))."""
    if D_i <= 0:
        return 2.0 * R_e / (math.sqrt(3.0) * S_P)
    Q = D_i / d
    return R_e / S_P * (1 - Q ** 2) / math.sqrt(3.0)


def hub_pressure_limit_von_mises(R_e: float, d: float, D_a: float, S_P: float) -> float:
    """Joint pressure [MPa] at which the plane-stress von Mises stress at the hub bore
    reaches R_e/S_P: R_e/S_P·(1 − Q_A²)/√(3 + Q_A⁴) ([Roark])."""
    Q = d / D_a
    return R_e / S_P * (1 - Q ** 2) / math.sqrt(3 + Q ** 4)


def shaft_pressure_limit_von_mises(R_e: float, d: float, D_i: float, S_P: float) -> float:
    """Joint pressure [MPa] at which the shaft reaches R_e/S_P (solid: σ_v = p; hollow: the
    bore, σ_v = 2p/(1 − Q_I²)) ([Roark])."""
    if D_i <= 0:
        return R_e / S_P
    Q = D_i / d
    return R_e / S_P * (1 - Q ** 2) / 2.0


def pressure_limits(model: str, R_eA: float, R_eI: float, d: float, D_a: float, D_i: float,
                    S_P: float) -> tuple[float, float]:
    """Permissible joint pressures (hub, shaft) [MPa] by ``model`` (:data:`PRESSURE_LIMITS`).

    >>> hub, shaft = pressure_limits("DIN 7190-1", 355.0, 355.0, 60.0, 120.0, 30.0, 1.0)
    >>> round(hub, 2), round(shaft, 2)
    (153.72, 153.72)
    """
    if model == "von Mises":
        return (hub_pressure_limit_von_mises(R_eA, d, D_a, S_P),
                shaft_pressure_limit_von_mises(R_eI, d, D_i, S_P))
    return hub_pressure_limit_din(R_eA, d, D_a, S_P), shaft_pressure_limit_din(R_eI, d, D_i, S_P)


def shrink_temperature(U_max: float, d: float, alpha: float, clearance: float,
                       room: float) -> float:
    """Hub temperature [°C] for slipping it on a shaft at ``room`` °C: the bore must grow by
    the largest interference U_max [µm] plus the joining clearance [mm] ([DIN7190-1])."""
    return room + (max(U_max, 0.0) * 1e-3 + clearance) / (alpha * d)
