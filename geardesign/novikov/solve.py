"""A Novikov pair computed from its typed inputs (:class:`~geardesign.novikov.inputs.Inputs`)
into one frozen record: geometry, engagement, forces, stiffness and deviations, the phase
loop and the GOST 21354-87 allowables.  Pure: no spec, no report rows (those are
:mod:`geardesign.novikov.report`'s).  Formulas in :mod:`.geometry`, :mod:`.deviations`,
:mod:`.engagement`, :mod:`.stress`, :mod:`.factors`."""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.materials.gear_steel import treatment_limits
from geardesign.materials.novikov import steel
from geardesign.novikov import deviations as dev
from geardesign.novikov.engagement import Engagement, MeshData, run_phases
from geardesign.novikov.factors import y_v
from geardesign.novikov.geometry import (
    Coverage,
    PairGeometry,
    PhasePoint,
    TheoreticalPoint,
    coverage,
    engaged_teeth,
    min_face_width,
    pair_geometry,
    phase_points,
    table1_points,
)
from geardesign.novikov.inputs import Inputs
from geardesign.novikov.stress import ellipse_coefficient, reduced_modulus
from geardesign.spur.strength import gost21354 as G21354

MIN_WIDTH_POINTS = 6
"""Least face widths are reported for 1 … 6 simultaneous points."""


@dataclass(frozen=True)
class Forces:
    """Forces on the pair [N] ([Korotkin2017]; the components by the helix and α_k)."""

    F_t: float          # total tangential force 2000·T2/d2
    F_sum: float        # design tangential force K_A·F_t
    F_a: float
    F_r: float
    F_n: float


@dataclass(frozen=True)
class Stiffness:
    """Contact patch, point stiffness and the deviations of the error model."""

    k_a: float          # ellipse coefficient
    F_ref: float        # mean load per point F_t/(2ε_β) [N]
    a_ref: float        # [mm]
    L_eff: float        # [mm]
    c_p: float          # [N/µm]
    theta_lead: float   # [µm]
    relief: float       # [µm]
    tol: dev.Tolerances


@dataclass(frozen=True)
class Allowables:
    """GOST 21354-87 allowables and safety factors (index 0 pinion, 1 wheel)."""

    N: tuple            # load cycles (None, None) without speed and life
    lim_H: tuple
    lim_F: tuple
    N_HG: tuple
    Z_N: tuple
    Y_N: tuple
    Y_A: float
    S_Hmin: float
    S_Fmin: float
    sigma_HP_each: tuple
    sigma_FP: tuple
    sigma_HP: float
    S_H: float
    S_F: tuple


@dataclass(frozen=True)
class Solution:
    """Everything the report shows of one Novikov pair."""

    g: PairGeometry
    cov: Coverage
    points: tuple[TheoreticalPoint, ...]
    rows: tuple[tuple[PhasePoint, ...], ...]
    teeth: tuple[int, ...]
    widths: tuple[float, ...]     # least face width for 1 … MIN_WIDTH_POINTS points [mm]
    forces: Forces
    stiffness: Stiffness
    Y_v1: float
    Y_v2: float
    eng: Engagement
    share_F: float                # part of σ_Fmax caused by the deviations
    share_H: float
    allow: Allowables
    hardness_diff_min_HB: float


def cycles(inp: Inputs, u: float) -> tuple[float | None, float | None]:
    """Numbers of load cycles N_K = 60·n·L_h of pinion and wheel (one contact of each
    flank region per revolution), or None without speed and life ([GOST21354])."""
    if inp.life is None:
        return None, None
    N1 = 60.0 * inp.speed1 * inp.life
    return N1, N1 / u


def allowables(inp: Inputs, u: float, sigma_H: float, sigma_F: tuple[float, float]
               ) -> Allowables:
    """σ_HP = σ_Hlim·Z_N/S_H and σ_FP = σ_Flim·Y_N·Y_A/S_F (Z_R, Z_v, Z_X, Y_R, Y_X, Y_δ = 1)
    for through-hardened steel ≤ 350 HB ([GOST21354]); the safety factors against the
    critical phase stresses."""
    N = cycles(inp, u)
    mats = (inp.pinion, inp.wheel)
    base = [treatment_limits("improved", m.hardness) for m in mats]
    lim_H = tuple(m.sigma_Hlim or base[i].sigma_Hlim for i, m in enumerate(mats))
    lim_F = tuple(m.sigma_Flim or base[i].sigma_Flim for i, m in enumerate(mats))
    NHG = tuple(G21354.n_hg(m.hardness) for m in mats)
    ZN = tuple(G21354.z_n(NHG[i], n, base[i].Z_N_max) if n is not None else 1.0
               for i, n in enumerate(N))
    YN = tuple(G21354.y_n(n, base[i].q_F) if n is not None else 1.0 for i, n in enumerate(N))
    YA = G21354.y_a(base[0].gamma_A, 1.0 if inp.reversing else 0.0)
    S_Hmin, S_Fmin = base[0].S_H, base[0].S_F
    HP = tuple(lim_H[i] * ZN[i] / S_Hmin for i in range(2))
    FP = tuple(lim_F[i] * YN[i] * YA / S_Fmin for i in range(2))
    S_H = min(lim_H[i] * ZN[i] for i in range(2)) / sigma_H if sigma_H > 0 else math.inf
    S_F = tuple(lim_F[i] * YN[i] * YA / v if v > 0 else math.inf
                for i, v in enumerate(sigma_F))
    return Allowables(N, lim_H, lim_F, NHG, ZN, YN, YA, S_Hmin, S_Fmin, HP, FP, min(HP), S_H,
                      S_F)


def solve(inp: Inputs) -> Solution:
    """The pair analysed by Korotkin's NOVGOST-17 algorithm ([Korotkin2017]): Table 1 and
    the phases, the cyclogram criteria ([Matyushenko2017]), load sharing under the error
    model, the critical phase stresses and their allowables."""
    pair = inp.pair
    rack, b_w, m = pair.rack, pair.b_w, pair.m
    g = pair_geometry(pair)
    points = table1_points(g.eps_beta, rack.eps_q)
    rows = phase_points(points, g.eps_beta, inp.phases)
    teeth = engaged_teeth(rows)
    delta = rack.delta
    cov = coverage(g.eps_beta, delta)
    widths = tuple(min_face_width(n, g.p_x, delta) for n in range(1, MIN_WIDTH_POINTS + 1))

    F_t = 2000.0 * inp.torque2 / g.d2
    F_sum = F_t * inp.application_factor
    forces = Forces(F_t, F_sum, F_sum * math.tan(pair.beta),
                    F_sum * math.tan(rack.alpha_k) / math.cos(pair.beta),
                    F_sum / (math.cos(rack.alpha_k) * math.cos(pair.beta)))

    st = steel()
    k_a = ellipse_coefficient(g.rho_p, g.l_k, rack.alpha_k, reduced_modulus(st.E, st.nu))
    F_ref = F_sum / (2.0 * g.eps_beta)
    a_ref = k_a * math.sqrt(F_ref)
    L_eff = 2.0 * a_ref + 2.0 * (rack.h_a + rack.h_f) * m
    c_p = inp.point_stiffness or inp.mesh_stiffness * L_eff
    theta_lead = dev.misalignment_lead(inp.misalignment, b_w)
    relief = inp.end_relief * 1000.0
    tol = dev.design_deviations(inp.grade_smoothness, inp.grade_contact, m, g.d1, g.d2, b_w,
                                rack.alpha_k, inp.risk)
    stiff = Stiffness(k_a, F_ref, a_ref, L_eff, c_p, theta_lead, relief, tol)

    Y_v1, Y_v2 = y_v(g.z_v1, pair.x1), y_v(g.z_v2, pair.x2)
    mesh = MeshData(F_sum, m, b_w, rack.alpha_k, g.l_k, g.rho_p, k_a, c_p, Y_v1, Y_v2, relief)
    eng = run_phases(rows, mesh, inp.error_model, theta_lead, tol.lead_design,
                     tol.pitch_design, inp.pitch_errors, inp.lead_error)
    share_F = 1.0 - eng.ideal_F.value / eng.sigma_F.value if eng.sigma_F.value > 0 else 0.0
    share_H = 1.0 - eng.ideal_H.value / eng.sigma_H.value if eng.sigma_H.value > 0 else 0.0
    allow = allowables(inp, g.u, eng.sigma_H.value, (eng.sigma_F1.value, eng.sigma_F2.value))
    return Solution(g, cov, tuple(points), tuple(tuple(r) for r in rows), tuple(teeth),
                    widths, forces, stiff, Y_v1, Y_v2, eng, share_F, share_H, allow,
                    st.hardness_diff_min_HB)
