"""Loads of a gear pair: torque, forces on the teeth and shafts, load cycles and spectra.

Pure functions; torque N·m, force N, speed min⁻¹, lengths mm, time h.
"""

from __future__ import annotations

import math

from geardesign.core import xp
from geardesign.core.records import dataclass
from geardesign.gears.geometry import PairGeometry


def torque_from_power(P: float, n: float) -> float:
    """Torque [N·m] from power P [kW] at speed n [min⁻¹]: T = 30000·P/(π·n) = 9549.3·P/n.

    Example: 10 kW at 1000 min⁻¹ is 9549.3·10/1000 = 95.49 N·m:

    >>> round(torque_from_power(10.0, 1000.0), 2)
    95.49
    """
    return 30000.0 * P / (math.pi * n)


@dataclass(frozen=True)
class Forces:
    """Forces in the mesh at the working pitch circle (N) and the axial-force moments (N·m)
    that each gear puts on its shaft."""

    F_t: float
    F_r: float
    F_a: float
    F_n: float
    beta_w: float
    M_a1: float
    M_a2: float


def mesh_forces(g: PairGeometry, T1: float) -> Forces:
    """Tooth forces from the pinion torque T1 [N·m].

    .. math::
        F_t = 2000 T_1/d_{w1},\\quad F_r = F_t \\tan α_{tw},\\quad
        F_a = F_t \\tan β_w,\\quad F_n = \\frac{F_t}{\\cos α_{tw} \\cos β_b},\\quad
        \\tan β_w = \\tan β\\, d_{w1}/d_1

    Each gear's shaft carries F_t, F_r, F_a (opposite directions on the two shafts) and
    the moment of the axial force M_a = F_a·d_w/2000 [N·m] in the plane of the axes.
    References: [GOST21354]; ISO 6336-1 §5 (force components).
    """
    d_w1 = g.g1.d_w
    F_t = 2000.0 * T1 / d_w1
    tan_beta_w = xp.tan(g.inp.beta) * d_w1 / g.g1.d
    F_a = F_t * tan_beta_w
    beta_w = xp.atan(tan_beta_w)
    return Forces(
        F_t=F_t, F_r=F_t * xp.tan(g.alpha_tw), F_a=F_a,
        F_n=F_t / (xp.cos(g.alpha_tw) * xp.cos(g.beta_b)), beta_w=beta_w,
        M_a1=F_a * d_w1 / 2000.0, M_a2=F_a * g.g2.d_w / 2000.0,
    )


@dataclass(frozen=True)
class Block:
    """One block of a load spectrum: torque T_i/T, time share t_i/L_h, speed n_i/n."""

    torque_ratio: float
    time_share: float
    speed_ratio: float = 1.0


def cycles(n: float, c: int, L_h: float) -> float:
    """Number of load cycles N_K = 60·n·c·L_h (c meshes per revolution).
    GOST 21354-87; [GOST21354].

    Example: 1000 min⁻¹, one mesh per revolution, 10 000 h: N_K = 6·10⁸:

    >>> cycles(1000.0, 1, 10000.0)
    600000000.0
    """
    return 60.0 * n * c * L_h


def equivalent_cycles(n: float, c: int, L_h: float, blocks: tuple[Block, ...],
                      exponent: float) -> float:
    """Equivalent number of cycles of a load spectrum.

    .. math:: N_E = 60\\,c\\,L_h \\sum_i (T_i/T)^{p}\\, n_i\\, t_i

    p = q_H/2 = 3 for contact, p = q_F (6 or 9) for bending; T the largest long-acting
    torque (T_i/T ≤ 1).  References: GOST 21354-87 (equivalent cycles); [GOST21354].
    """
    return 60.0 * c * L_h * sum(b.torque_ratio ** exponent * n * b.speed_ratio * b.time_share
                                for b in blocks)
