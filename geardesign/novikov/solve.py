"""A Novikov pair computed from its typed inputs (:class:`~geardesign.novikov.inputs.Inputs`)
into one frozen record: geometry, engagement, forces, stiffness and deviations, the phase
loop and the GOST 21354-87 allowables.  Pure: no spec, no report rows (those are
:mod:`geardesign.novikov.report`'s); the forces, the deviations and the allowables are
records whose fields carry their report metadata (unit, symbol, name, source), reported by
the strength ratings' one :func:`geardesign.spur.strength.common.rows`.  Formulas in :mod:`.geometry`, :mod:`.deviations`,
:mod:`.engagement`, :mod:`.stress`, :mod:`.factors`."""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.materials.gear_steel import treatment_limits
from geardesign.materials.novikov import steel
from geardesign.novikov import deviations as dev
from geardesign.novikov import sources as S
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
from geardesign.spur.strength.common import Record, opt, q

MIN_WIDTH_POINTS = 6
"""Least face widths are reported for 1 … 6 simultaneous points."""


@dataclass(frozen=True)
class Forces(Record):
    """Forces on the pair [N] ([Korotkin2017]; the components by the helix and α_k)."""

    SECTION = "forces"
    F_t: float = q("N", "F_tΣ", "total tangential force 2000·T2/d2", S.KOROTKIN)
    F_sum: float = q("N", "K_A·F_tΣ", "design tangential force", S.KOROTKIN, key="F_t_design")
    F_a: float = q("N", "F_a", "axial force F_t·tan β", S.FORCES)
    F_r: float = q("N", "F_r", "radial force F_t·tan α_k/cos β", S.FORCES)
    F_n: float = q("N", "F_n", "normal force F_t/(cos α_k·cos β)", S.FORCES)


def _c_p_name(c) -> str:
    return "stiffness of one contact point at mid-face" + (" (given)" if c["c_p_given"]
                                                           else " c'·L_eff")


@dataclass(frozen=True, kw_only=True)
class Stiffness(Record):
    """Contact patch, point stiffness and the deviations of the error model ([Korotkin2017];
    the tolerances of GOST 1643-81 by the accuracy grades, or the deviations given)."""

    SECTION = "deviations"
    k_a: float                          # ellipse coefficient
    F_ref: float                        # mean load per point F_t/(2ε_β) [N]
    tol: dev.Tolerances
    c_p_given: bool = False
    a_ref: float = q("mm", "a_ref", "contact-patch semi-axis at the mean load per point "
                     "F_t/(2ε_β)", S.ELLIPSE)
    L_eff: float = q("mm", "L_eff", "effective length 2a_ref + 2h of a point's stiffness",
                     S.COMPLIANCE)
    c_p: float = q("N/µm", "c_p", _c_p_name, S.COMPLIANCE)
    W_ref: float = q("µm", "W_ref", "deflection at mid-face under the mean load per point",
                     S.COMPLIANCE)
    error_model: str = q(None, "", "error model", S.ERROR_MODEL)
    theta_lead: float = q("µm", "θ·b_w", "lead mismatch from the misalignment", S.ERROR_MODEL)
    relief: float = q("µm", "Δ", "end relief (parabolic crowning)", S.ERROR_MODEL)
    # the error model "grades": the tolerances and the design deviations
    f_pb1: float | None = opt("µm", "f_pb1", "pitch deviation limit ±, pinion (k_p)",
                              S.TOLERANCES)
    f_pb2: float | None = opt("µm", "f_pb2", "pitch deviation limit ±, wheel (k_p)",
                              S.TOLERANCES)
    F_beta: float | None = opt("µm", "F_β", "tooth direction tolerance, each gear (k_k)",
                               S.TOLERANCES)
    f_x: float | None = opt("µm", "f_x", "axis parallelism tolerance (= F_β, unverified)",
                            S.TOLERANCES)
    f_y: float | None = opt("µm", "f_y", "axis skew tolerance (= 0.5·F_β, unverified)",
                            S.TOLERANCES)
    sigma_pitch: float | None = opt("µm", "σ_p", "standard deviation of the pitch gap",
                                    S.ERROR_MODEL)
    sigma_lead: float | None = opt("µm", "σ_l", "standard deviation of the lead mismatch",
                                   S.ERROR_MODEL)
    e_p: float | None = opt("µm", "e_p = γσ_p", "design pitch gap (the study tooth leads by "
                            "it)", S.ERROR_MODEL)
    e_l: float | None = opt("µm", "e_l = γσ_l", "design lead mismatch (both signs)",
                            S.ERROR_MODEL)
    # the error model "explicit": the deviations given
    pitch_errors: list | None = opt("µm", "δu", "given gaps of the tooth pairs", S.ERROR_MODEL)
    lead_error: float | None = opt("µm", "f_kβ", "given lead mismatch", S.ERROR_MODEL)


def _g(unit, symbol, name, group=None, **kw):
    """A per-gear field of :class:`Allowables` ([GOST21354])."""
    return q(unit, symbol, name, S.G21354, gear=True, group=group, **kw)


@dataclass(frozen=True, kw_only=True)
class Allowables(Record):
    """GOST 21354-87 allowables and safety factors (per-gear values: (pinion, wheel))."""

    SECTION = "allowables"
    H_given: tuple = (False, False)     # σ_Hlim given (else 2·HB + 70)
    F_given: tuple = (False, False)     # σ_Flim given (else 1.75·HB)
    N: tuple = _g("-", "N_K{k}", lambda c: "load cycles, pinion 60·n1·L_h" if c["k"] == 1
                  else "load cycles, wheel", key="N_K{k}")   # (None, None) without life
    lim_H: tuple = _g("MPa", "σ_Hlim{k}", lambda c: f"contact endurance limit, {c['who']}"
                      + (" (given)" if c["H_given"] else " 2·HB + 70"), "H",
                      key="sigma_Hlim{k}")
    N_HG: tuple = _g("-", "N_HG{k}", "base cycles for contact, {who}", "H")
    Z_N: tuple = _g("-", "Z_N{k}", "life factor for contact, {who}", "H")
    sigma_HP_each: tuple = _g("MPa", "σ_HP{k}", "allowable contact stress, {who}", "H",
                              key="sigma_HP{k}")
    S_Hmin: float = q("-", "S_Hmin", "least safety factor for contact", S.G21354,
                      key="S_H_min")
    sigma_HP: float = q("MPa", "σ_HP", "allowable contact stress of the pair (lower)",
                        S.G21354)
    lim_F: tuple = _g("MPa", "σ_Flim{k}", lambda c: f"bending endurance limit, {c['who']}"
                      + (" (given)" if c["F_given"] else " 1.75·HB"), "F",
                      key="sigma_Flim{k}")
    Y_N: tuple = _g("-", "Y_N{k}", "life factor for bending, {who}", "F")
    sigma_FP: tuple = _g("MPa", "σ_FP{k}", "allowable bending stress, {who}", "F")
    Y_A: float = q("-", "Y_A", "reversing load factor", S.G21354)
    S_Fmin: float = q("-", "S_Fmin", "least safety factor for bending", S.G21354,
                      key="S_F_min")
    S_H: float = q("-", "S_H", "safety factor for contact σ_Hlim·Z_N/σ_Hmax", S.G21354)
    S_F: tuple = _g("-", "S_F{k}", "safety factor for bending, {who}")


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
    return Allowables(H_given=tuple(bool(m.sigma_Hlim) for m in mats),
                      F_given=tuple(bool(m.sigma_Flim) for m in mats), N=N, lim_H=lim_H,
                      N_HG=NHG, Z_N=ZN, sigma_HP_each=HP, S_Hmin=S_Hmin, sigma_HP=min(HP),
                      lim_F=lim_F, Y_N=YN, sigma_FP=FP, Y_A=YA, S_Fmin=S_Fmin, S_H=S_H, S_F=S_F)


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
    grades = inp.error_model == "grades"
    explicit = inp.error_model == "explicit"
    stiff = Stiffness(
        k_a=k_a, F_ref=F_ref, tol=tol, c_p_given=bool(inp.point_stiffness), a_ref=a_ref,
        L_eff=L_eff, c_p=c_p, W_ref=F_ref / c_p, error_model=inp.error_model,
        theta_lead=theta_lead, relief=relief,
        **({"f_pb1": tol.f_pb1, "f_pb2": tol.f_pb2, "F_beta": tol.F_beta1, "f_x": tol.f_x,
            "f_y": tol.f_y, "sigma_pitch": tol.sigma_pitch, "sigma_lead": tol.sigma_lead,
            "e_p": tol.pitch_design, "e_l": tol.lead_design} if grades else {}),
        pitch_errors=[inp.pitch_errors[z] for z in teeth] if explicit else None,
        lead_error=inp.lead_error if explicit else None)

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
