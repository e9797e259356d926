"""The GOST 21354 route of a bevel pair: the stresses of the virtual spur pair ([GOST21354],
the functions of ``spur.strength.gost21354``, called) divided by the bevel factors θ_H, θ_F
of the handbook method ([Dunaev] §2.6; [Ivanov] ch. 4).

Life factors are 1 (long-life limits as given): the permissible stresses are σ_Hlim and
Y_ST·σ_Flim = 2·σ_Flim.  Stresses [MPa], forces [N], lengths [mm].
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from geardesign.bevel.geometry import Geometry
from geardesign.bevel.inputs import Inputs
from geardesign.bevel.rating import MOUNTING_FACTOR, Y_ST
from geardesign.core.records import dataclass
from geardesign.spur.strength import gost21354 as G

if TYPE_CHECKING:
    from geardesign.bevel.rating import Forces

THETA = {  # (θ_H, θ_F) = (a_H + b_H·u, a_F + b_F·u) for circular teeth
    "both_soft": ((1.22, 0.21), (0.94, 0.08)),
    "one_hard": ((1.13, 0.13), (0.85, 0.043)),
    "both_hard": ((0.81, 0.15), (0.65, 0.11)),
}
"""Bevel factors of circular teeth θ_H, θ_F against the pair's hardness (soft: up to
350 HB; one hard: the pinion): [Dunaev] §2.6, table 2.6, written without the table at hand.
The independent program [ConeGear] (``Unit2.pas``, TPer.PzubKon1 and TPer.PrSigF) carries
the same table in every coefficient but one: θ_H of a hard pinion on a soft wheel, 1.23 +
0.13u there against 1.13 + 0.13u here, a misprint in one of the two that the handbook would
settle (tests/test_bevel_published_gost.py; the report's METHOD_UNVERIFIED warning names
it).  No published worked example checks the table; straight teeth:
:data:`THETA_STRAIGHT`."""

THETA_STRAIGHT = 0.85
"""θ_H = θ_F = 0.85 for straight bevel teeth ([Dunaev] §2.6; [Ivanov] ch. 4; the same in
[ConeGear]).  [CourseBevelUA] takes 1 for contact and 0.85 for bending in its design
formulas: another handbook's choice, not followed here."""


@dataclass(frozen=True)
class GostMember:
    z_vn: float
    Y_FS: float
    sigma_F: float
    S_H: float
    S_F: float


@dataclass(frozen=True)
class GostRating:
    """[GOST21354] on the virtual spur pair with θ_H, θ_F ([Dunaev] §2.6)."""

    theta_H: float
    theta_F: float
    K_H: float
    K_F: float
    Z_E: float
    Z_H: float
    sigma_H: float
    pinion: GostMember
    wheel: GostMember


def theta_factors(spiral: bool, hardness: str, u: float) -> tuple[float, float]:
    """θ_H, θ_F: the load capacity of a bevel pair over that of its virtual spur pair.

    .. math:: θ = a + b\\,u \\text{ (circular teeth, :data:`THETA`)},\\quad θ = 0.85
              \\text{ (straight teeth)}

    [Dunaev] §2.6 table 2.6; [Ivanov] ch. 4; [ConeGear] (one coefficient disputed, see
    :data:`THETA`).

    >>> theta_factors(True, "both_hard", 2.0)
    (1.11, 0.87)
    """
    if not spiral:
        return THETA_STRAIGHT, THETA_STRAIGHT
    (aH, bH), (aF, bF) = THETA[hardness]
    return round(aH + bH * u, 10), round(aF + bF * u, 10)


def gost_rating(inp: Inputs, g: Geometry, f: Forces) -> GostRating:
    """σ_H and σ_F through the virtual spur pair ([GOST21354] formulas, called):

    .. math::
        σ_H = Z_E Z_H \\sqrt{\\frac{F_{mt} K_H (u_v + 1)}{θ_H\\, b\\, d_{v1} u_v}},\\quad
        σ_F = \\frac{F_{mt} K_F}{θ_F\\, b\\, m_{nm}} Y_{FS}(z_{vn}, x)

    K_H = K_F = K_A K_v K_Hβ K_Hα (K_Hβ as :func:`iso_rating`), Z_H of the spur pair
    (α_n, β = 0: the circular-teeth gain is in θ_H), Z_ε = 1, z_vn = z/(cos δ cos³β_m);
    at Σ = 90° (u_v + 1)/(d_v1 u_v) = √(u² + 1)/(u d_m1), the handbook form.
    [Dunaev] §2.6; [GOST21354].  Compared with the independent program [ConeGear]: σ_F the
    same but for its rounded constant 2.7 (−0.74 % at b = 0.285 R_e), σ_H 9.0 % below its
    constant 32 200 (tests/test_bevel_published_gost.py).
    """
    ld, mt, p = inp.load, inp.material, inp.pair
    th_H, th_F = theta_factors(p.spiral, mt.hardness, g.u)
    K = ld.K_A * ld.K_v * 1.5 * MOUNTING_FACTOR[ld.mounting] * ld.K_alpha
    Z_E = G.z_e(mt.E, mt.nu, mt.E, mt.nu)
    Z_H = G.z_h(0.0, g.alpha_n, g.alpha_n)
    s_H = G.sigma_h(Z_E, Z_H, 1.0, f.F_mt, K, g.u_v, th_H * g.b, g.pinion.d_v)
    members = []
    for i, m in enumerate(g.members):
        z_vn = m.z / (math.cos(m.delta) * math.cos(g.beta_m) ** 3)
        Y = G.y_fs(z_vn, m.x)
        s_F = G.sigma_f(f.F_mt, K, th_F * g.b, g.m_nm, Y, 1.0, 1.0)
        members.append(GostMember(z_vn, Y, s_F, mt.sigma_Hlim[i] / s_H,
                                  Y_ST * mt.sigma_Flim[i] / s_F))
    return GostRating(th_H, th_F, K, K, Z_E, Z_H, s_H, *members)
