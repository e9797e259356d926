"""Static strength of a bevel pair at the peak torque T_max (a short-time actual torque:
the starting torque of the motor, a jam), by both routes.

ISO route ([ISO10300-2], [ISO10300-3], whose life factors are those of [ISO6336-2] and
[ISO6336-3]): the stresses of the method B1 rating scaled to the peak torque with K_A = 1
(σ_H ∝ √T, σ_F ∝ T, the other load factors as at the nominal torque, as the spur ISO rating
does), against the limits at the static point of the S-N curves (Z_NT,st, Y_NT,st,
Y_δrelT,st: :func:`geardesign.spur.strength.iso6336.part3.static_limits`, called) with the
bevel gear factor Z_K of the contact limit.

GOST route ([GOST21354] through the virtual spur pair, [Dunaev] §2.6): σ_Hmax and σ_Fmax of
the spur package (:func:`~geardesign.spur.strength.gost21354.formulas.sigma_h_max`,
:func:`~geardesign.spur.strength.gost21354.formulas.sigma_f_max` with the load factors at
the peak torque, K_A = K_v = 1, :func:`~geardesign.spur.strength.gost21354.formulas.peak_factor`)
against the material's σ_HPmax and σ_FPmax = σ_FSt/S_FSt (Y_z = Y_X = 1: a forged blank,
no size reduction), called likewise.

Stresses [MPa], torques [N·m].
"""

from __future__ import annotations

import math

from geardesign.bevel.inputs import Inputs
from geardesign.bevel.rating import MOUNTING_FACTOR, IsoRating
from geardesign.core.records import dataclass
from geardesign.spur.strength import gost21354 as G
from geardesign.spur.strength.iso6336 import part3 as P3

Y_X_STATIC = 1.0
"""Size factor of the static bending limit of the GOST route (no size reduction)."""

Y_Z_FORGED = 1.0
"""Blank factor Y_z of the static bending limit: a forged or stamped blank ([GOST21354];
0.9 rolled, 0.8 cast are not offered)."""


@dataclass(frozen=True)
class IsoPeakMember:
    sigma_F: float        # root stress at the peak torque
    Y_deltarelT: float    # static relative notch sensitivity factor
    sigma_FG: float       # static root stress limit
    sigma_HG: float       # static contact stress limit
    S_H: float
    S_F: float


@dataclass(frozen=True)
class IsoPeak:
    """Static strength at the peak torque by [ISO10300-2] / [ISO10300-3] limits."""

    T_peak: float         # peak pinion torque [N·m]
    material: str         # ISO 6336-5 material type
    Z_NT: float           # static life factor, contact
    Y_NT: float           # static life factor, bending
    sigma_H: float        # contact stress at the peak torque
    pinion: IsoPeakMember
    wheel: IsoPeakMember


@dataclass(frozen=True)
class GostPeakMember:
    sigma_Fmax: float
    sigma_HPmax: float
    sigma_FPmax: float
    S_H: float            # σ_HPmax/σ_Hmax
    S_F: float            # σ_FPmax/σ_Fmax


@dataclass(frozen=True)
class GostPeak:
    """Peak load by [GOST21354] through the virtual spur pair."""

    T_peak: float
    K_Hmax: float
    K_Fmax: float
    sigma_Hmax: float
    pinion: GostPeakMember
    wheel: GostPeakMember


def iso_peak(inp: Inputs, r: IsoRating) -> IsoPeak:
    """The method B1 stresses at the peak torque and the static limits (module docstring).

    .. math:: σ_{H,st} = σ_H \\sqrt{\\frac{T_{max}}{T_1 K_A}},\\quad
              σ_{F,st} = σ_F \\frac{T_{max}}{T_1 K_A},\\quad
              S_{H,st} = \\frac{σ_{Hlim} Z_{NT,st} Z_K}{σ_{H,st}},\\quad
              S_{F,st} = \\frac{σ_{Flim} Y_{ST} Y_{NT,st} Y_{δrelT,st}}{σ_{F,st}}

    [ISO10300-2], [ISO10300-3] with the life factors of [ISO6336-2] §10, [ISO6336-3] §12.
    """
    ld, mt = inp.load, inp.material
    ratio = ld.T_peak / ld.T1 / ld.K_A
    s_H = r.sigma_H * math.sqrt(ratio)
    members, Z_NT, Y_NT = [], 1.0, 1.0
    for i, m in enumerate((r.pinion, r.wheel)):
        Z_NT, G_H, Y_NT, Y_d, G_F = P3.static_limits(mt.type, mt.sigma_Hlim[i],
                                                      mt.sigma_Flim[i], m.Y_Sa, mt.sigma_02)
        G_H *= r.Z_K
        s_F = m.sigma_F * ratio
        members.append(IsoPeakMember(s_F, Y_d, G_F, G_H, G_H / s_H, G_F / s_F))
    return IsoPeak(ld.T_peak / 1e3, mt.type, Z_NT, Y_NT, s_H, *members)


def gost_peak(inp: Inputs, K_Halpha: float, r) -> GostPeak | None:
    """σ_Hmax, σ_Fmax of the GOST route at the peak torque and the material's peak limits
    (module docstring); None when the material gives no σ_HPmax, σ_FSt.  ``K_Halpha`` the
    pair's K_Hα = K_Fα (given or by method B), ``r`` the
    :class:`~geardesign.bevel.gost_route.GostRating` at the nominal torque.

    .. math:: K_{max} = [(K_{Hβ} - 1) T_1/T_{max} + 1]\\,[(K_{Hα} - 1) T_1/T_{max} + 1],\\quad
              σ_{Hmax} = σ_H \\sqrt{\\frac{T_{max} K_{max}}{T_1 K_H}},\\quad
              σ_{Fmax} = σ_F \\frac{T_{max} K_{max}}{T_1 K_F}

    [GOST21354]; [ZPCIL] ``SIGMAX.h``.
    """
    ld, mt = inp.load, inp.material
    if mt.sigma_HPmax is None or mt.sigma_FSt is None:
        return None
    T, Tm = ld.T1, ld.T_peak
    K_Hb = 1.5 * MOUNTING_FACTOR[ld.mounting]
    K_max = G.peak_factor(K_Hb, T, Tm) * G.peak_factor(K_Halpha, T, Tm)
    s_H = float(G.sigma_h_max(r.sigma_H, T, Tm, r.K_H, K_max))
    members = []
    for i, m in enumerate((r.pinion, r.wheel)):
        s_F = float(G.sigma_f_max(m.sigma_F, T, Tm, r.K_F, K_max))
        lim_F = G.sigma_fp_max(mt.sigma_FSt[i], Y_X_STATIC, Y_Z_FORGED, G.S_FST)
        members.append(GostPeakMember(s_F, mt.sigma_HPmax[i], lim_F,
                                      mt.sigma_HPmax[i] / s_H, lim_F / s_F))
    return GostPeak(Tm / 1e3, K_max, K_max, s_H, *members)
