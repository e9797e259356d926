"""The dynamic factor K_v and the transverse load factor K_Hα = K_Fα of a bevel pair by
[ISO10300-1] method B, from the single pitch deviation and the pair's geometry, or as given.

Method B of [ISO10300-1] is the method B of [ISO6336-1] applied to the virtual cylindrical
gear pair (face width b_v = b, tangential force F_vmt = F_mt without hypoid offset) with
the bevel gear's own mesh stiffness, reduced mass and resonance ranges; the formulas that
the two standards share are the ``spur`` functions, called (running-in allowance y_α, the
reduced mass, the resonance speed, the constants c_v1 … c_v7, the K_v of each range, the
K_Hα before its limits).  The single pitch deviation f_pt of each member is an input: the
tolerance formulas of [ISO17485] (f_pt from the accuracy grade, the module and the tolerance
diameter) were not reachable to check, so the deviation of the drawing (or of the
measurement) is given, in µm.

Checked against [ISOTR10300-30] sample 1 (f_pt = 12 / 26 µm, case-hardened steel,
ρ = 7.86·10⁻⁶ kg/mm³): K_v = 1.020, K_Hα = 1.161 as printed (tests/test_bevel_load.py).
Forces [N], lengths [mm], deviations [µm], stiffness [N/(mm·µm)], masses [kg/mm].
"""

from __future__ import annotations

import math

from geardesign.bevel.geometry import Geometry
from geardesign.bevel.inputs import Inputs
from geardesign.core.records import dataclass
from geardesign.spur.strength.iso6336 import part1 as P1

C_PRIME = 14.0
"""Single stiffness of a bevel pair c' [N/(mm·µm)] at a line load of at least 100 N/mm.
[ISO10300-1] method B (K_v), c' = 14·C_F."""

C_GAMMA = 20.0
"""Mesh stiffness of a bevel pair c_γ [N/(mm·µm)] at a line load of at least 100 N/mm.
[ISO10300-1] method B (K_v, K_Hα), c_γ = 20·C_F."""

LINE_LOAD_REF = 100.0
"""Line load F_vmt K_A/b_v,eff [N/mm] at and above which the stiffness has its full value
(C_F = 1).  [ISO10300-1] method B (correction factor C_F)."""

N_SUB = 0.75
"""Upper end of the subcritical range of the resonance ratio N.  [ISO10300-1] method B."""

N_MAIN = 1.25
"""Upper end of the main resonance range; supercritical from N = 1.5 on, linear between.
[ISO10300-1] method B."""

K_V_ASSUMED = 1.1
"""K_v when neither the factor nor the pitch deviations are given (the spec default before
method B; a pair of average accuracy at moderate speed)."""

K_HALPHA_ASSUMED = 1.0
"""K_Hα when neither the factor nor the pitch deviations are given."""


@dataclass(frozen=True)
class MethodB:
    """The intermediate values of method B."""

    f_pt: float           # single pitch deviation, the larger of the pair [µm]
    y_alpha: float        # running-in allowance [µm]
    f_p_eff: float        # effective pitch deviation f_pt − y_α [µm]
    line_load: float      # F_vmt K_A/b_v [N/mm]
    C_F: float            # stiffness correction for a light line load
    c_prime: float        # single stiffness c' [N/(mm·µm)]
    c_gamma: float        # mesh stiffness c_γ [N/(mm·µm)]
    m_red: float          # reduced mass per face width [kg/mm]
    n_E1: float           # resonance speed of the pinion [min⁻¹]
    N: float              # resonance ratio n1/n_E1
    range: str            # "subcritical", "main resonance", "intermediate", "supercritical"
    K_Halpha_max: float   # upper limit of K_Hα


@dataclass(frozen=True)
class LoadFactors:
    """K_v and K_Hα = K_Fα of the pair with where each comes from ("given": the spec's
    value; "method B": [ISO10300-1] method B; "assumed": neither given nor computable)."""

    K_v: float
    K_v_src: str
    K_Halpha: float
    K_Halpha_src: str
    method_b: MethodB | None


def stiffness(line_load_eff: float) -> tuple[float, float, float]:
    """(C_F, c', c_γ): the single and mesh stiffness of a bevel pair, reduced for a light
    line load.

    .. math:: C_F = \\min\\Big(1, \\frac{F_{vmt} K_A/b_{v,eff}}{100}\\Big),\\quad
              c' = 14 C_F,\\quad c_γ = 20 C_F

    line load F_vmt K_A/b_v,eff [N/mm]; stiffness [N/(mm·µm)].  [ISO10300-1] method B.

    >>> stiffness(50.0)
    (0.5, 7.0, 10.0)
    """
    C_F = min(1.0, line_load_eff / LINE_LOAD_REF)
    return C_F, C_PRIME * C_F, C_GAMMA * C_F


def member_mass(d_m: float, alpha_n: float, rho: float) -> float:
    """Mass per face width of one member reduced to the line of action [kg/mm]:

    .. math:: m^* = \\frac{π}{8} ρ \\frac{d_m^2}{\\cos^2 α_n}

    d_m the mean pitch diameter [mm], ρ [kg/mm³].  [ISO10300-1] method B (the reduced mass
    of the pair by [ISO6336-1], :func:`geardesign.spur.strength.iso6336.part1.reduced_mass`).
    """
    return math.pi / 8.0 * rho * d_m * d_m / math.cos(alpha_n) ** 2


def dynamic_factor(N: float, c_prime: float, f_p_eff: float, line_load: float,
                   eps_vg: float) -> tuple[float, str]:
    """K_v by method B and its resonance range: with B_p = c' f_p,eff/(F_vmt K_A/b_v),

    .. math::
        K_v = N\\,[(c_{v1} + c_{v2}) B_p + c_{v3}] + 1 \\;(N \\le 0.75),\\quad
        (c_{v1} + c_{v2}) B_p + c_{v4} + 1 \\;(0.75 < N \\le 1.25),

    .. math::
        (c_{v5} + c_{v6}) B_p + c_{v7} \\;(N \\ge 1.5), \\text{ linear between 1.25 and 1.5}

    The [ISO6336-1] form (:func:`geardesign.spur.strength.iso6336.part1.dynamic_factor`,
    called) with the pitch deviation in both deviation terms (B_f = B_p), no tip relief
    (B_k = 1) and the bevel ranges; c_v1 … c_v7 by ε_vγ (the same table).  [ISO10300-1]
    method B; [ISOTR10300-30] sample 1 (N = 0.038, K_v = 1.020).
    """
    K, rng = P1.dynamic_factor(N, N_SUB, c_prime, f_p_eff, f_p_eff, 0.0, line_load, eps_vg,
                               N_main=N_MAIN)
    return float(K), str(rng)


def transverse_factor(eps_vg: float, eps_va: float, Z_LS: float, c_gamma: float,
                      f_p_eff: float, F_mtH_b: float) -> tuple[float, float]:
    """K_Hα = K_Fα by method B and its upper limit:

    .. math::
        K_{Hα} = \\frac{ε_{vγ}}{2}\\Big(0.9 + 0.4 \\frac{c_γ (f_{pt} - y_α)}{F_{mtH}/b_v}\\Big)
        \\;(ε_{vγ} \\le 2),\\quad
        0.9 + 0.4 \\sqrt{\\frac{2(ε_{vγ} - 1)}{ε_{vγ}}}
        \\frac{c_γ (f_{pt} - y_α)}{F_{mtH}/b_v}
        \\;(ε_{vγ} > 2)

    F_mtH = F_vmt K_A K_v K_Hβ [N]; within 1 ≤ K_Hα ≤ ε_vγ/(ε_vα Z_LS²) (the [ISO6336-1]
    limit with the bevel load sharing factor Z_LS in place of Z_ε: not checked by a
    published case).  The [ISO6336-1] formulas, called
    (:func:`~geardesign.spur.strength.iso6336.part1.transverse_load_factor`,
    :func:`~geardesign.spur.strength.iso6336.part1.limited`).  [ISO10300-1] method B;
    [ISOTR10300-30] sample 1 (K_Hα = 1.161).
    """
    k = float(P1.transverse_load_factor(eps_vg, c_gamma, f_p_eff, F_mtH_b))
    k_max = P1.transverse_limit_contact(eps_vg, eps_va, Z_LS)
    return float(P1.limited(k, k_max)[0]), k_max


def load_factors(inp: Inputs, g: Geometry, F_mt: float, v_mt: float) -> LoadFactors:
    """K_v and K_Hα of the pair: each as given, else by method B when the pitch deviations
    are given (``[accuracy]``), else assumed (:data:`K_V_ASSUMED`, :data:`K_HALPHA_ASSUMED`).

    Method B ([ISO10300-1]): f_pt the larger of the pair's single pitch deviations; the
    running-in allowance y_α of [ISO6336-1] by the material type (the mean of the members'
    values for their σ_Hlim); the reduced mass m_red = m1* m2*/(m1* + m2*)
    (:func:`member_mass`); n_E1 = 30 000/(π z1)·√(c_γ/m_red), N = n1/n_E1; line load
    F_vmt K_A/b_v with F_vmt = F_mt (no offset) and b_v = b; K_Hβ = 1.5·K_Hβ-be as in the
    rating.  F_mt [N], v_mt [m/s] at the mean cone.
    """
    from geardesign.bevel.rating import MOUNTING_FACTOR, load_sharing

    ld, acc, mt = inp.load, inp.accuracy, inp.material
    if acc is None or (ld.K_v is not None and ld.K_alpha is not None):
        return LoadFactors(
            K_V_ASSUMED if ld.K_v is None else ld.K_v, "assumed" if ld.K_v is None else "given",
            K_HALPHA_ASSUMED if ld.K_alpha is None else ld.K_alpha,
            "assumed" if ld.K_alpha is None else "given", None)
    f_pt = max(acc.f_pt)
    y_a = float(P1.pair_mean(*(P1.running_in_alpha(f_pt, mt.type, s, v_mt)
                               for s in mt.sigma_Hlim)))
    f_eff = f_pt - y_a
    C_F, c_p, c_g = stiffness(F_mt * ld.K_A / g.b_eff)
    m_red = P1.reduced_mass(*(member_mass(m.d_m, g.alpha_n, acc.rho) for m in g.members))
    n_E1 = float(P1.resonance_speed(g.pinion.z, c_g, m_red))
    N = ld.n1 / n_E1
    line_load = F_mt * ld.K_A / g.b
    if ld.K_v is None:
        K_v, rng = dynamic_factor(N, c_p, f_eff, line_load, g.eps_vg)
        src_v = "method B"
    else:
        K_v, rng, src_v = ld.K_v, "", "given"
    K_Hb = 1.5 * MOUNTING_FACTOR[ld.mounting]
    Z_LS = load_sharing(g)[0]
    K_a, K_max = transverse_factor(g.eps_vg, g.eps_va, Z_LS, c_g, f_eff,
                                   F_mt * ld.K_A * K_v * K_Hb / g.b)
    if ld.K_alpha is None:
        src_a = "method B"
    else:
        K_a, src_a = ld.K_alpha, "given"
    return LoadFactors(K_v, src_v, K_a, src_a,
                       MethodB(f_pt, y_a, f_eff, line_load, C_F, c_p, c_g, m_red, n_E1, N,
                               rng, K_max))
