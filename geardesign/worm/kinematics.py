"""Kinematics, friction, efficiency, self-locking and forces of a worm pair.

Pure functions.  Speeds in min⁻¹ and m/s, angles in rad, torques in N·m, powers in kW,
forces in N.  [Dunaev]; [Ivanov].
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.worm import tables
from geardesign.worm.geometry import WormPairGeometry


@dataclass(frozen=True)
class Speeds:
    n1: float        # worm speed [min^-1]
    n2: float        # wheel speed [min^-1]
    omega1: float    # [rad/s]
    omega2: float    # [rad/s]
    v1: float        # worm peripheral speed on d_w1 [m/s]
    v2: float        # wheel peripheral speed on d2 [m/s]
    v_s: float       # sliding speed [m/s]


def speeds(g: WormPairGeometry, n1: float) -> Speeds:
    """Speeds of the pair.

    .. math:: v_1 = \\frac{π d_{w1} n_1}{60000}, \\quad v_s = \\frac{v_1}{\\cos γ_w},
              \\quad n_2 = n_1/u, \\quad v_2 = \\frac{π d_2 n_2}{60000}

    [Dunaev] (d in mm, n in min⁻¹, v in m/s).
    """
    n2 = n1 / g.u
    v1 = math.pi * g.d_w1 * n1 / 60000.0
    return Speeds(n1, n2, math.pi * n1 / 30.0, math.pi * n2 / 30.0, v1,
                  math.pi * g.d2 * n2 / 60000.0, v1 / math.cos(g.gamma_w))


def estimated_sliding_speed(n1: float, T2: float) -> float:
    """Sliding speed before the size is known (Dunaev & Lelikov):
    v_s ≈ 4.5·10⁻⁴·n1·T2^(1/3) [m/s], n1 in min⁻¹, T2 in N·m ([Dunaev];
    Pascal program ``Vs := 4.5*n1*T2^(1/3)/10000``)."""
    return 4.5e-4 * n1 * T2 ** (1.0 / 3.0)


@dataclass(frozen=True)
class Friction:
    f_table: float       # f' from the table (tin bronze), before the material factor
    material_factor: float
    f: float             # reduced friction coefficient used
    rho: float           # reduced friction angle [rad]
    given: bool          # f given in the spec (table not used)


def friction(v_s: float, group: str, level: str = "mean", coefficient: float | None = None,
             material_factor: float | None = None) -> Friction:
    """Reduced friction coefficient f' and angle ρ' = arctan f'.

    f' = k_mat·f'_table(v_s) with the table of [Ivanov] (tin bronze on a hardened
    ground worm) interpolated linearly on v_s, at its low end, middle (default) or high
    end, and k_mat = 1.0 for tin bronzes, 1.4 for tin-free bronzes, brass and cast iron
    (the textbooks' "+30 ... 50 %").  A given ``coefficient`` replaces the table.
    """
    f_tab = tables.friction_coefficient(v_s, level)
    k = tables.friction_material_factor(group) if material_factor is None else material_factor
    f = coefficient if coefficient is not None else k * f_tab
    return Friction(f_tab, k, f, math.atan(f), coefficient is not None)


def mesh_efficiency(gamma_w: float, rho: float) -> float:
    """Mesh efficiency with the worm driving, η_m = tan γ_w / tan(γ_w + ρ')
    ([Dunaev]; Pascal program; DIN 3975 form with ρ_z).

    Example: without friction (ρ' = 0) the mesh loses nothing (identity):

    >>> mesh_efficiency(0.2, 0.0)
    1.0
    """
    return math.tan(gamma_w) / math.tan(gamma_w + rho)


def reverse_efficiency(gamma_w: float, rho: float) -> float:
    """Mesh efficiency with the wheel driving, η' = tan(γ_w − ρ') / tan γ_w; 0 when the
    pair is self-locking (γ_w <= ρ'), where no motion is transmitted backwards
    ([Dunaev])."""
    if gamma_w <= rho:
        return 0.0
    return math.tan(gamma_w - rho) / math.tan(gamma_w)


def is_self_locking(gamma_w: float, rho: float) -> bool:
    """The wheel cannot drive the worm: γ_w <= ρ' ([Dunaev]).

    Example: a lead angle below the friction angle locks:

    >>> is_self_locking(0.05, 0.06), is_self_locking(0.2, 0.06)
    (True, False)
    """
    return gamma_w <= rho


@dataclass(frozen=True)
class Loads:
    T1: float      # worm torque [N·m]
    T2: float      # wheel torque [N·m]
    P1: float      # input power [kW]
    P2: float      # output power [kW]
    P_loss: float  # power lost [kW]
    F_t1: float    # worm tangential force = wheel axial force [N]
    F_t2: float    # wheel tangential force = worm axial force [N]
    F_r: float     # radial force [N]


def loads(g: WormPairGeometry, s: Speeds, T2: float, eta: float, alpha: float) -> Loads:
    """Torques, powers and mesh forces.

    .. math:: T_1 = \\frac{T_2}{u η}, \\; P_2 = T_2 ω_2, \\; P_1 = P_2/η,
              \\; F_{t2} = F_{a1} = \\frac{2000 T_2}{d_2}, \\;
              F_{t1} = F_{a2} = \\frac{2000 T_1}{d_{w1}}, \\; F_r = F_{t2} \\tan α

    with the overall efficiency η and the basic profile angle α ([Dunaev]; Chernavsky; Dunaev &
    Lelikov).
    """
    T1 = T2 / (g.u * eta)
    P2 = T2 * s.omega2 / 1000.0
    P1 = P2 / eta
    F_t2 = 2000.0 * T2 / g.d2
    return Loads(T1, T2, P1, P2, P1 - P2, 2000.0 * T1 / g.d_w1, F_t2, F_t2 * math.tan(alpha))
