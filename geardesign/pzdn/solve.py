"""The PZDN solved: ``solve(inputs) -> Solution``, pure (no rows, no spec, the inputs
unchanged), from the functions of :mod:`.spring`, :mod:`.coupling`, :mod:`.regression`
and (start-up) :mod:`.solve_startup`.  :mod:`.report` turns the record into rows and
checks.

The coupling gear is solved by the spur calculator's typed interface
(:func:`geardesign.pzdn.coupling.rate`: :func:`geardesign.spur.solve.solve` on the spur
inputs of the coupling table), whose record is kept whole; an input problem of the gear is
reported against the pzdn keys.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.pzdn import spring as SP
from geardesign.pzdn import tables
from geardesign.pzdn.inputs import Coupling, Inputs, Motor, Regression
from geardesign.pzdn.solve_startup import StartupResult, solve_startup
from geardesign.pzdn.spring_inputs import Spring

# ----------------------------------------------------------------------------- springs


@dataclass(frozen=True)
class SpringResult:
    """A spring designed, and its state at the largest wind-up."""

    spring: Spring
    design: SP.SpringDesign
    k_actual: float              # curvature factor with the actual index D/d
    C_slot: tuple[float, float] | None   # stiffness with the finger at the slot ends
    arm_target: float | None     # finger arm for the target stiffness (NaN: unreachable)
    phi_full: float              # largest wind-up at the finger [rad]
    phi_full_body: float         # its share taken by the coils [rad]
    D_wound: float               # mean coil diameter there [mm]
    p_wound: float | None        # pitch there, body held at H [mm]
    pitch_needed: float | None   # pitch that keeps the coils clear [mm]
    phi_touch: float | None      # coil wind-up at which the coils touch [rad]
    H_wound: float | None        # body length there, free ends [mm]
    T_limit: float | None        # torque at the stop angle [N·m]
    sigma_limit: float | None    # bending stress there [MPa]


def _spring(r: Spring) -> SpringResult:
    s = SP.design(r.inp)
    C_slot = arm = None
    if r.slot_arms is not None:
        L2 = SP.leg_length(s.inp.leg2_arm, s.D, s.inp.leg_model) if s.inp.leg2_arm else 0.0
        C_slot = tuple(SP.stiffness(s.inp.E, s.J, s.L + SP.leg_length(a, s.D, s.inp.leg_model)
                                    + L2) / 1000.0 for a in r.slot_arms)
    if r.target_stiffness is not None:
        L2 = SP.leg_length(s.inp.leg2_arm, s.D, s.inp.leg_model) if s.inp.leg2_arm else 0.0
        L_need = s.inp.E * s.J / (r.target_stiffness * 1000.0) - s.L - L2
        a = SP.arm_for_leg_length(L_need, s.D, s.inp.leg_model) if L_need > 0 else math.nan
        arm = a if math.isfinite(a) and a > s.D / 2.0 else math.nan
    phi_full = max(x for x in (s.phi_T, s.inp.phi_design, s.inp.phi_stop) if x is not None)
    body = phi_full * s.L / (s.L + s.L_leg)
    p_w = need = touch = H_w = None
    if r.ends_fixed_axially:
        if s.i > 1.0:
            p_w = SP.wound_pitch(s.H, s.d, s.i, body)
            need = s.d + s.d * body / (2 * math.pi * (s.i - 1.0))
            touch = SP.touching_angle(s.H, s.d, s.i)
    else:
        H_w = max(s.H, SP.free_body_length(s.d, s.i, body))
    T_lim = sigma_lim = None
    if s.inp.phi_stop is not None:
        T_lim = s.C_finger * s.inp.phi_stop
        sigma_lim = SP.bending_stress(T_lim * 1000.0, s.k, s.d)
    return SpringResult(r, s, SP.curvature_factor(s.c_actual, s.inp.curvature), C_slot, arm,
                        phi_full, body, SP.wound_diameter(s.D, s.i, body), p_w, need, touch,
                        H_w, T_lim, sigma_lim)


# ----------------------------------------------------------------------------- motor


@dataclass(frozen=True)
class MotorResult:
    omega: float                 # [rad/s]
    T_nominal: float | None      # [N·m]
    t_windup: float              # [s]


def _motor(mo: Motor) -> MotorResult:
    omega = math.pi * mo.speed / 30.0
    Tn = None
    if mo.nominal_torque is not None or mo.power is not None:
        Tn = mo.nominal_torque if mo.nominal_torque is not None else mo.power * 1000.0 / omega
    return MotorResult(omega, Tn, mo.breakaway_time * mo.windup_factor)


# ----------------------------------------------------------------------------- coupling gear


@dataclass(frozen=True)
class CouplingResult:
    """Load sharing and module estimate of the coupling gear, and its spur rating."""

    u: float
    T1: float                    # pinion torque per mesh [N·m]
    T1_peak: float | None
    Y_F: tuple[float, float]
    sigma_FP: tuple[float, float]    # σ_Flim/S_F [MPa]
    weak: int                    # 0 pinion, 1 wheel
    K_Fbeta: float
    K_Fbeta_given: bool
    m_est: float                 # [mm]
    module: float                # [mm]
    face_width: float            # [mm]
    spur: object                 # the spur record (geardesign.spur.solve.Record)


def _coupling(c: Coupling) -> CouplingResult:
    from geardesign.pzdn import coupling as CG
    from geardesign.spur.strength import gost21354 as G
    from geardesign.spur.strength import tables as GT

    g, mats = c.table, c.materials
    u = g["z2"] / g["z1"]
    T1 = CG.pinion_torque(g["torque"], g["torque_on"], g["planets"], u)
    T1_peak = (CG.pinion_torque(g["peak_torque"], g["torque_on"], g["planets"], u)
               if g["peak_torque"] is not None else None)
    f = g["factors"] or {}
    Y_F = (f.get("Y_FS1") or G.y_fs(g["z1"], g["x1"]), f.get("Y_FS2") or G.y_fs(g["z2"], g["x2"]))
    sFP = (mats[0].sigma_Flim / mats[0].S_F, mats[1].sigma_Flim / mats[1].S_F)
    weak = CG.weaker_gear(Y_F, sFP)
    K_Fb = f.get("K_Fbeta") or G.k_h_beta(g["bearing_scheme"], g["psi_bd"],
                                          min(m.HB for m in mats) <= 350.0)
    T_est = T1_peak if T1_peak is not None else T1
    m_est = CG.module_estimate(T_est, K_Fb, Y_F[weak], g["psi_bd"], g["z1"], sFP[weak])
    module = g["module"] if g["module"] is not None else CG.round_module(m_est, GT.MODULES_1)
    b = g["face_width"] if g["face_width"] is not None else g["psi_bd"] * module * g["z1"]
    # the spur calculator rates the gear: its typed inputs, solved once
    spur = CG.rate(CG.spur_inputs(CG.spur_spec(g, module, b, T1, T1_peak)))
    return CouplingResult(u, T1, T1_peak, Y_F, sFP, weak, K_Fb, f.get("K_Fbeta") is not None,
                          m_est, module, b, spur)


# ----------------------------------------------------------------------------- regression


@dataclass(frozen=True)
class RegressionResult:
    machine: str
    C_zero: float
    T1_zero: float
    J1_zero: float
    point: object                # regression.RegressionPoint at C
    fitted: tuple[float, float]  # C range treated as fitted [N·m/rad]
    without: object | None       # the point of the drive alone
    sweep: tuple


def _regression(rg: Regression) -> RegressionResult:
    from geardesign.pzdn import regression as R

    reg = tables.regression("ko2")
    p = R.evaluate(rg.C, reg, rg.T_ref_12, rg.T_ref_23)
    p0 = None
    if rg.drive_stiffness is not None and rg.pzdn_stiffness is not None:
        p0 = R.evaluate(rg.drive_stiffness, reg, rg.T_ref_12, rg.T_ref_23)
    pts = tuple(R.evaluate(c, reg, rg.T_ref_12, rg.T_ref_23) for c in rg.sweep)
    return RegressionResult(reg["machine"], reg["C_zero"], reg["T1_zero"], reg["J1_zero"], p,
                            R.fitted_range(reg), p0, pts)


# ----------------------------------------------------------------------------- entry


@dataclass(frozen=True)
class Solution:
    motor: MotorResult | None
    springs: tuple[SpringResult, ...]
    C_series: float | None       # all springs in series (two or more springs) [N·m/rad]
    C_parallel: float | None     # all springs in parallel [N·m/rad]
    coupling: CouplingResult | None
    startup: StartupResult | None
    regression: RegressionResult | None


def solve(inp: Inputs) -> Solution:
    """Solve the PZDN for typed inputs (:func:`geardesign.pzdn.inputs.read`)."""
    springs = tuple(_spring(s) for s in inp.springs)
    fingers = [r.design.C_finger for r in springs]
    several = len(springs) > 1
    finger_C = {r.spring.name: r.design.C_finger for r in springs}
    return Solution(
        _motor(inp.motor) if inp.motor is not None else None, springs,
        1.0 / sum(1.0 / c for c in fingers) if several else None,
        sum(fingers) if several else None,
        _coupling(inp.coupling) if inp.coupling is not None else None,
        solve_startup(inp.startup, finger_C) if inp.startup is not None else None,
        _regression(inp.regression) if inp.regression is not None else None)
