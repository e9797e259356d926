"""The whole worm-pair analysis on plain data: geometry -> speeds, friction, efficiency,
forces -> strength of the wheel, stiffness of the worm -> thermal balance.

This module only composes the pure functions of :mod:`.kinematics`, :mod:`.strength`,
:mod:`.thermal` and :mod:`.tables` (each with its formula and source); it holds no
formula of its own except unit bookkeeping (cycle counts N = 60·n2·L_h).
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core.errors import InputError
from geardesign.core.records import dataclass
from geardesign.worm import tables
from geardesign.worm.geometry import WormPairGeometry
from geardesign.worm.kinematics import (
    Friction,
    Loads,
    Speeds,
    friction,
    is_self_locking,
    loads,
    mesh_efficiency,
    reverse_efficiency,
    speeds,
)
from geardesign.worm.strength import (
    Allowables,
    SpectrumFactors,
    allowables,
    bending_stress,
    contact_stress,
    dynamic_factor,
    load_concentration_factor,
    required_center_distance,
    spectrum_factors,
    worm_deflection,
)
from geardesign.worm.thermal import Thermal, housing_area, oil_temperature

DEFAULT_SPAN_RATIO = 0.9
"""Worm bearing span l ≈ 0.9·d2 when not given ([Chernavsky])."""


@dataclass(frozen=True)
class WheelProps:
    """Wheel material as used: library values with the spec's overrides applied."""

    name: str
    group: str
    sigma_B: float | None
    sigma_T: float | None
    sigma_bu: float | None
    v_s_max: float
    sigma_HP: float | None = None   # given allowable, replaces the computed one
    sigma_FP: float | None = None
    #: where the values come from: the library row's source, and the values the spec gave
    source: str = "given in the spec"
    given: tuple = ()               # the keys of [wheel] the spec gave over the library row


@dataclass(frozen=True)
class Operation:
    T2: float                     # [N·m]
    n1: float                     # [min^-1]
    T_peak: float | None = None   # [N·m], None: T2
    life: float = 20000.0         # [h]
    reversing: bool = False
    spectrum: tuple = ((1.0, 1.0),)   # ((T_i/T2, t_i/t), ...)


@dataclass(frozen=True)
class Options:
    hardened: bool = True
    elastic_modulus: float = 2.1e5
    bearing_span: float | None = None
    deflection_limit: float = 0.01
    friction_level: str = "mean"
    friction_coefficient: float | None = None
    friction_factor: float | None = None
    bearing_efficiency: float = 0.96
    profile_angle: float = math.radians(20.0)
    cv_law: str = "power"
    K_HL_max: float = 1.15
    sigma_H0: float | None = None
    bending_formula: str = "dunaev"
    dynamic_factor: float | None = None
    ambient: float = 20.0
    oil_limit: float = 90.0
    heat_transfer: float = 13.0
    housing_area: float | None = None
    base_share: float = 0.3
    fan: bool = False
    fan_speed: float | None = None
    fan_share: float = 0.35


@dataclass(frozen=True)
class Analysis:
    g: WormPairGeometry
    s: Speeds
    fr: Friction
    eta_m: float
    eta: float
    eta_reverse: float
    self_locking: bool
    ld: Loads
    theta: float
    sf: SpectrumFactors
    K_beta: float
    K_v: float
    K: float
    N: float
    N_HE: float
    N_FE: float
    allow: Allowables
    sigma_HP: float
    sigma_FP: float
    sigma_H: float
    a_w_req: float | None
    T_peak: float
    sigma_Hmax: float
    z_v2: float
    Y_F: float
    sigma_F: float
    sigma_Fmax: float
    span: float
    I_eq: float
    f: float
    f_lim: float
    th: Thermal
    extras: dict = field(default_factory=dict)


def efficiency(g: WormPairGeometry, n1: float, w: WheelProps, o: Options) -> tuple:
    """Speeds, friction, mesh efficiency η_m = tan γ_w/tan(γ_w + ρ') and the overall
    efficiency η = η_b·η_m at the worm speed n1 [min⁻¹] (:mod:`.kinematics`): independent
    of the torque."""
    s = speeds(g, n1)
    fr = friction(s.v_s, w.group, o.friction_level, o.friction_coefficient, o.friction_factor)
    eta_m = mesh_efficiency(g.gamma_w, fr.rho)
    return s, fr, eta_m, o.bearing_efficiency * eta_m


def analyse(g: WormPairGeometry, op: Operation, w: WheelProps, o: Options) -> Analysis:
    """Evaluate a worm pair of known geometry under the operating data ``op``."""
    s, fr, eta_m, eta = efficiency(g, op.n1, w, o)
    ld = loads(g, s, op.T2, eta, o.profile_angle)
    p = g.inp
    theta = tables.theta(p.q, p.z1)
    sf = spectrum_factors(list(op.spectrum))
    K_beta = load_concentration_factor(p.z2, theta, sf.X)
    K_v = o.dynamic_factor if o.dynamic_factor is not None else dynamic_factor(s.v2)
    K = K_beta * K_v
    N = 60.0 * s.n2 * op.life
    al = allowables(w.group, o.hardened, s.v_s, sf.K_HE * N, sf.K_FE * N, op.reversing,
                    w.sigma_B, w.sigma_T, w.sigma_bu, o.cv_law, o.K_HL_max, o.sigma_H0)
    sigma_HP = w.sigma_HP if w.sigma_HP is not None else al.sigma_HP
    if sigma_HP <= 0.0:
        # [σ]_H = σ_H0 − k·v_s of groups II and III leaves its domain (no allowable stress)
        raise InputError.at(
            "load.speed1", op.n1,
            f"gives the sliding speed v_s = {s.v_s:.2f} m/s, at which [σ]_H = σ_H0 − k·v_s = "
            f"{sigma_HP:.1f} MPa: a group {w.group} wheel cannot run this fast; lower the speed "
            "or choose a group I bronze (wheel.material)")
    sigma_FP = w.sigma_FP if w.sigma_FP is not None else al.sigma_FP
    sigma_H = contact_stress(op.T2, K, p.q, p.z2, g.a_w)
    a_w_req = (required_center_distance(op.T2, K, p.q, p.z2, sigma_HP) if sigma_HP > 0
               else None)
    T_peak = op.T_peak if op.T_peak is not None else op.T2
    z_v2 = p.z2 / math.cos(g.gamma_w) ** 3
    Y_F = tables.form_factor(z_v2)
    sigma_F = bending_stress(ld.F_t2, K, Y_F, g.gamma_w, p.m, p.q, p.x, g.b2, o.bending_formula)
    span = o.bearing_span if o.bearing_span is not None else DEFAULT_SPAN_RATIO * g.d2
    f, I_eq = worm_deflection(ld.F_t1, ld.F_r, span, o.elastic_modulus, g.d_f1, g.d_a1)
    area = o.housing_area if o.housing_area is not None else housing_area(g.a_w)
    K_T_fan = (tables.fan_heat_transfer(o.fan_speed if o.fan_speed is not None else op.n1)
               if o.fan else None)
    th = oil_temperature(ld.P1, eta, o.ambient, o.heat_transfer, area, o.base_share, K_T_fan,
                         o.fan_share)
    return Analysis(
        g=g, s=s, fr=fr, eta_m=eta_m, eta=eta, eta_reverse=reverse_efficiency(g.gamma_w, fr.rho),
        self_locking=is_self_locking(g.gamma_w, fr.rho), ld=ld, theta=theta, sf=sf,
        K_beta=K_beta, K_v=K_v, K=K, N=N, N_HE=sf.K_HE * N, N_FE=sf.K_FE * N, allow=al,
        sigma_HP=sigma_HP, sigma_FP=sigma_FP, sigma_H=sigma_H, a_w_req=a_w_req, T_peak=T_peak,
        sigma_Hmax=sigma_H * math.sqrt(T_peak / op.T2), z_v2=z_v2, Y_F=Y_F, sigma_F=sigma_F,
        sigma_Fmax=sigma_F * T_peak / op.T2, span=span, I_eq=I_eq, f=f,
        f_lim=o.deflection_limit * p.m, th=th,
    )
