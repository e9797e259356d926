"""``kind = "geneva"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

This module maps spec keys to the pure functions of :mod:`.kinematics` and :mod:`.drive`,
and their results to report rows and checks.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.geneva import kinematics as K
from geardesign.geneva import sources as S
from geardesign.geneva.drive import (
    SpindleBlock, drive_point, inertia_coefficients, planetary_ratio)

RPM = math.pi / 30.0  # min^-1 -> rad/s


def _f(x: float, digits: int = 4) -> str:
    text = f"{x:.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def _rules(spec: ValidatedSpec) -> None:
    """Rules across keys, each reported (one run): a dwell must exist; the drive tables
    need [barrel]."""
    problems = Problems()
    problems.stage(_dwell, spec.data["geneva"])
    for table in ("spindles", "drive"):
        if spec.data[table] is not None and spec.data["barrel"] is None:
            problems.add(Problem(
                table, f"[{table}] belongs to the spindle-block drive and needs a [barrel] "
                "table (stations, inertia, efficiency); add it or remove this table"))
    problems.raise_all()


def _dwell(g: dict) -> None:
    """The cross must stand still between indexes (motion share < 1)."""
    internal = g["type"] == "internal"
    z, k = g["slots"], g["pins"]
    share = K.motion_share(z, k, internal)
    if share >= 1.0 - 1e-12:
        if internal:
            k_max = 1
        else:
            k_max = math.ceil(2.0 * z / (z - 2)) - 1
        kind = "internal" if internal else "external"
        raise InputError.at(
            "geneva.pins", k,
            f"no dwell: {k} roller(s) keep the {kind} cross moving {share * 100:.0f} % of a "
            f"crank turn (k·(z {'+' if internal else '−'} 2)/(2z) must be < 1); use pins <= "
            f"{k_max} with {z} slots")


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.geneva import CALCULATOR

    _rules(spec)
    g = spec.data["geneva"]
    internal = g["type"] == "internal"
    z, k, a, d_r = g["slots"], g["pins"], g["center_distance"], g["roller_diameter"]
    n_r = g["crank_speed"]
    w1 = n_r * RPM
    res = CALCULATOR.new_result(spec)

    # ------------------------------------------------------------------ geometry
    geo = K.geometry(z, internal, a, d_r, g["clearance"], g["shaft_diameter"] or 0.0)
    sec = res.section("geometry", "Geometry")
    sec.add("internal", internal, None, "", "internal Geneva (cross turns with the crank)",
            S.GENEVA)
    sec.add("lambda", geo.lam, "-", "λ", "crank ratio R1/a = sin(π/z)", S.GENEVA_GEOM)
    sec.add("R1", geo.R1, "mm", "R1", "crank radius (roller centre)", S.GENEVA_GEOM)
    sec.add("R2", geo.R2, "mm", "R2", "roller-centre radius on the cross at entry",
            S.GENEVA_GEOM)
    sec.add("mouth_radius", geo.mouth_radius, "mm", "R_m",
            "bore of the slotted ring (slot-mouth radius)" if internal else
            "outer radius of the cross (slot-mouth corners)", S.GENEVA_GEOM)
    sec.add("slot_travel", geo.slot_travel, "mm", "h", "travel of the roller centre along the slot",
            S.GENEVA_GEOM)
    sec.add("slot_end_radius", geo.slot_end_radius, "mm", "r_e",
            "radius of the slot end (roller + clearance)", S.GENEVA_GEOM)
    sec.add("slot_depth", geo.slot_depth, "mm", "l_s", "slot depth from the mouth circle",
            S.GENEVA_GEOM)
    sec.add("web", geo.web, "mm", "w", "narrowest web between two adjacent slots",
            S.GENEVA_GEOM)
    sec.add("locking_radius", geo.locking_radius, "mm", "R_l",
            "largest locking-disc radius on the crank", S.GENEVA_GEOM)
    sec.add("max_roller_diameter", geo.max_roller, "mm", "d_r,max",
            "largest roller diameter that fits", S.GENEVA_GEOM)

    # ------------------------------------------------------------------ kinematics
    phi0 = K.half_motion_angle(z, internal)
    share = K.motion_share(z, k, internal)
    T = 60.0 / n_r                      # crank revolution [s]
    t_index = T / k                     # one index cycle [s]
    t_motion = 2.0 * phi0 / w1
    om_max = K.peak_omega_ratio(geo.lam, internal)
    eps_max, phi_eps = K.peak_acceleration(z, internal)
    pow_max, phi_pow = K.peak_power_factor(z, internal)
    jump = K.entry_jump(z)
    kin = res.section("kinematics", "Kinematics (crank at constant speed)")
    kin.add("index_angle", 2.0 * math.pi / z, "rad", "2π/z", "cross index angle", S.GENEVA)
    kin.add("motion_angle", 2.0 * phi0, "rad", "2φ0", "crank angle of the motion", S.GENEVA)
    kin.add("dwell_angle", 2.0 * math.pi / k - 2.0 * phi0, "rad", "φ_d",
            "crank angle of the dwell (locking arc) per index", S.GENEVA)
    kin.add("motion_share", share, "-", "τ", "moving share of the time, k·2φ0/(2π)", S.GENEVA)
    kin.add("omega1", w1, "rad/s", "ω1", "crank angular speed", S.GENEVA)
    kin.add("t_motion", t_motion, "s", "t_m", "motion time per index", S.GENEVA)
    kin.add("t_dwell", t_index - t_motion, "s", "t_d", "dwell time per index", S.GENEVA)
    kin.add("t_cycle", t_index, "s", "t_c", "index cycle time (crank turn / pins)", S.GENEVA)
    kin.add("omega2_max_ratio", om_max, "-", "ω2,max/ω1", "peak speed ratio (at φ = 0)",
            S.GENEVA)
    kin.add("eps2_max_ratio", eps_max, "-", "|ε2|max/ω1²", "peak acceleration factor",
            S.GENEVA)
    kin.add("phi_eps2_max", phi_eps, "rad", "φ(ε2,max)",
            "crank angle of the peak acceleration (before the centre line)", S.GENEVA)
    kin.add("power_max_ratio", pow_max, "-", "|ω2ε2|max/ω1³", "peak power factor", S.GENEVA)
    kin.add("phi_power_max", phi_pow, "rad", "φ(ω2ε2,max)", "crank angle of the peak power",
            S.GENEVA)
    kin.add("eps2_entry_ratio", jump, "-", "ε2,0/ω1²",
            "acceleration jump at entry and exit, tan(π/z)", S.GENEVA)
    kin.add("omega2_max", om_max * w1, "rad/s", "ω2,max", "peak cross speed", S.GENEVA)
    kin.add("eps2_max", eps_max * w1 * w1, "rad/s^2", "ε2,max", "peak cross acceleration",
            S.GENEVA)
    kin.add("eps2_entry", jump * w1 * w1, "rad/s^2", "ε2,0", "acceleration jump at entry",
            S.GENEVA)

    law = K.motion_law(z, internal, g["points"])
    ml = res.section("motion_law", "Motion law (arrays over the crank angle)")
    ml.add("phi", law.phi, "rad", "φ", "crank angle from the line of centres", S.GENEVA)
    ml.add("t", [(p + phi0) / w1 for p in law.phi], "s", "t", "time from entry", S.GENEVA)
    ml.add("psi", law.psi, "rad", "ψ", "cross angle from its middle position", S.GENEVA)
    ml.add("omega2", [u * w1 for u in law.omega], "rad/s", "ω2", "cross angular speed",
           S.GENEVA)
    ml.add("eps2", [e * w1 * w1 for e in law.eps], "rad/s^2", "ε2",
           "cross angular acceleration", S.GENEVA)
    ml.add("omega2_ratio", law.omega, "-", "ω2/ω1", "speed ratio", S.GENEVA)
    ml.add("eps2_ratio", law.eps, "-", "ε2/ω1²", "acceleration factor", S.GENEVA)
    ml.add("power_ratio", [u * e for u, e in zip(law.omega, law.eps)], "-", "ω2ε2/ω1³",
           "dynamic power factor", S.GENEVA)

    # ------------------------------------------------------------------ load on the cross
    load = spec.data["load"]
    if load is not None:
        J2, M_f = load["inertia"], load["friction_torque"]
        rho = [K.roller_radius_on_cross(p, z, a, internal) / 1000.0 for p in law.phi]
        M2 = [J2 * e * w1 * w1 + M_f for e in law.eps]
        M1 = [m * u for m, u in zip(M2, law.omega)]
        F = [m / r for m, r in zip(M2, rho)]
        lam = geo.lam

        def moment2(p: float) -> float:
            return J2 * K.eps_ratio(p, lam, internal) * w1 * w1 + M_f

        M1_max, phi_M1 = K.maximise(
            lambda p: abs(moment2(p) * K.omega_ratio(p, lam, internal)), -phi0, phi0, 2000)
        F_max, phi_F = K.maximise(
            lambda p: abs(moment2(p)) / (K.roller_radius_on_cross(p, z, a, internal) / 1000.0),
            -phi0, phi0, 2000)
        M2_max, _ = K.maximise(lambda p: abs(moment2(p)), -phi0, phi0, 2000)
        ld = res.section("load", "Load on the cross")
        ld.add("M2_max", M2_max, "N·m", "M2,max",
               "largest moment on the cross (J2·ε2 + M_f)", S.DYNAMICS)
        ld.add("M1_max", M1_max, "N·m", "M1,max", "largest crank moment (M2·ω2/ω1)",
               S.DYNAMICS)
        ld.add("phi_M1_max", phi_M1, "rad", "φ(M1,max)", "crank angle of M1,max", S.DYNAMICS)
        ld.add("F_max", F_max, "N", "F_max", "largest roller/slot force (M2/ρ)", S.DYNAMICS)
        ld.add("phi_F_max", phi_F, "rad", "φ(F_max)", "crank angle of F_max", S.DYNAMICS)
        ld.add("M1", M1, "N·m", "M1", "crank moment over the crank angle", S.DYNAMICS)
        ld.add("F", F, "N", "F", "roller/slot force over the crank angle", S.DYNAMICS)

    # ------------------------------------------------------------------ spindle block
    if spec.data["barrel"] is not None:
        _spindle_block(res, spec, law, z, w1)

    res.checks.extend(_checks(spec, geo, z, k, internal, d_r))
    return res


def _spindle_block(res: Result, spec: ValidatedSpec, law: K.MotionLaw, z: int,
                   w1: float) -> None:
    b, sp, dr = spec.data["barrel"], spec.data["spindles"], spec.data["drive"]
    kw = dict(J_b=b["inertia"], M_tr=b["friction_torque"], eta_b=b["efficiency"],
              i_kb=z / b["stations"])
    if sp is not None:
        kw.update(n_sh=sp["count"], J_sh=sp["inertia"], m_sh=sp["mass"],
                  R_b=sp["orbit_radius"] / 1000.0,
                  u_p=planetary_ratio(sp["central_gear_teeth"], sp["spindle_gear_teeth"],
                                      sp["direction"]),
                  w_rab=sp["working_speed"] * RPM, eta_sh=sp["efficiency"])
    if dr is not None:
        kw.update(J_d=dr["motor_inertia"], w_d=dr["motor_speed"] * RPM,
                  J_r=dr["shaft_inertia"], M_x=dr["idle_torque"])
    block = SpindleBlock(**kw)
    B = inertia_coefficients(block, w1)
    pts = [drive_point(block, B, w1, u, e) for u, e in zip(law.omega, law.eps)]
    # the peaks on the tabulated grid are refined on a fine grid of the same law
    lam = K.crank_ratio(z)
    internal = spec.data["geneva"]["type"] == "internal"
    phi0 = K.half_motion_angle(z, internal)

    def at(phi: float):
        return drive_point(block, B, w1, K.omega_ratio(phi, lam, internal),
                           K.eps_ratio(phi, lam, internal))

    N_peak, phi_N = K.maximise(lambda p: at(p).N, -phi0, phi0, steps=2000)
    Md_peak, phi_Md = K.maximise(lambda p: at(p).M_d, -phi0, phi0, steps=2000)
    p_N = at(phi_N)

    sec = res.section("drive", "Spindle-block drive (reduced to the distributing shaft)")
    sec.add("i_kb", block.i_kb, "-", "i", "barrel turn per cross turn, z/n_pos", S.SEED_EQ2)
    sec.add("u_p", block.u_p, "-", "±u_p", "signed planetary ratio of the spindles",
            S.PLANETARY)
    sec.add("B1", B.B1, "kg*m^2", "B1", "constant part of J_p", S.SEED_EQ2)
    sec.add("B2", B.B2, "kg*m^2", "B2 = J_b.pr", "barrel inertia with spindles' orbit and "
            "planetary rotation", S.SEED_EQ2)
    sec.add("B12", B.B12, "kg*m^2", "B12", "coupling of spindle rotation and barrel", S.SEED_EQ2)
    sec.add("omega_b_max", block.i_kb * K.peak_omega_ratio(lam, internal) * w1, "rad/s",
            "ω_b,max", "peak barrel speed", S.SEED_EQ2)
    sec.add("eps_b_max", block.i_kb * K.peak_acceleration(z, internal)[0] * w1 * w1,
            "rad/s^2", "ε_b,max", "peak barrel acceleration", S.SEED_EQ2)
    sec.add("M_d_max", Md_peak, "N·m", "M_d,max",
            "peak driving moment on the distributing shaft (η = 1)", S.SEED_EQ1)
    sec.add("phi_M_d_max", phi_Md, "rad", "φ(M_d,max)", "crank angle of M_d,max", S.SEED_EQ1)
    sec.add("N_max", N_peak / 1000.0, "kW", "N_max", "peak motor power while indexing "
            "(with efficiencies)", S.SEED_POWER)
    sec.add("phi_N_max", phi_N, "rad", "φ(N_max)", "crank angle of N_max", S.SEED_POWER)
    sec.add("N_b_at_max", p_N.N_b / 1000.0, "kW", "N_b", "barrel share of N_max", S.SEED_POWER)
    sec.add("N_sh_at_max", p_N.N_sh / 1000.0, "kW", "N_sh", "spindle share of N_max",
            S.SEED_POWER)
    sec.add("N_d_at_max", p_N.N_d / 1000.0, "kW", "N_d",
            "power on the distributing shaft at that angle (η = 1)", S.SEED_EQ1)
    if block.w_d > 0.0:
        sec.add("M_motor_max", N_peak / block.w_d, "N·m", "M_mot,max",
                "peak motor torque N_max/ω_d", S.SEED_POWER)
    if block.n_sh:
        w_sh = [p.w_sh for p in pts]
        sec.add("n_sh_min", min(w_sh) / RPM, "min^-1", "n_sh,min",
                "lowest spindle speed while indexing", S.PLANETARY)
        sec.add("n_sh_max", max(w_sh) / RPM, "min^-1", "n_sh,max",
                "highest spindle speed while indexing", S.PLANETARY)

    arr = res.section("drive_law", "Spindle-block drive (arrays over the crank angle)")
    arr.add("J_p", [p.J_p for p in pts], "kg*m^2", "J_p", "reduced moment of inertia",
            S.SEED_EQ2)
    arr.add("dJ_p", [p.dJ_p for p in pts], "kg*m^2/rad", "dJ_p/dφ",
            "its derivative", S.SEED_EQ3)
    arr.add("M_d", [p.M_d for p in pts], "N·m", "M_d", "driving moment on the distributing "
            "shaft (η = 1)", S.SEED_EQ1)
    arr.add("N_d", [p.N_d / 1000.0 for p in pts], "kW", "N_d", "power on the distributing "
            "shaft (η = 1)", S.SEED_EQ1)
    arr.add("N_b", [p.N_b / 1000.0 for p in pts], "kW", "N_b", "barrel power (with η_b)",
            S.SEED_POWER)
    arr.add("N_sh", [p.N_sh / 1000.0 for p in pts], "kW", "N_sh", "spindle power (with η_sh)",
            S.SEED_POWER)
    arr.add("N", [p.N / 1000.0 for p in pts], "kW", "N", "motor power", S.SEED_POWER)

    # checks of the drive
    if dr is not None and dr["rated_power"] is not None:
        P = dr["rated_power"]
        remedies = ["lower geneva.crank_speed (the dynamic power grows with its cube)"]
        if sp is not None and sp["direction"] == "same":
            remedies.append("turn the barrel against the spindles")
        if sp is not None and sp["direction"] != "declutched":
            remedies.append("declutch the spindles while indexing")
        if z < 5:
            remedies.append("use 5-6 slots")
        ways = ", ".join(remedies[:-1]) + (" or " if len(remedies) > 1 else "") + remedies[-1]
        res.checks.append(check(
            "MOTOR_POWER", N_peak / 1000.0 <= P, "error",
            f"peak indexing power N_max = {N_peak / 1000.0:.3f} kW exceeds the motor rating "
            f"{_f(P, 3)} kW: use a motor of at least {N_peak / 1000.0:.2f} kW, or {ways}",
            f"peak indexing power N_max = {N_peak / 1000.0:.3f} kW <= rating {_f(P, 3)} kW",
            N_peak / 1000.0, P, S.SEED_POWER))
    if block.n_sh and block.u_p < 0.0:
        n_min = min(p.w_sh for p in pts) / RPM
        n_rab = block.w_rab / RPM
        res.checks.append(check(
            "SPINDLE_SPEED_DROP", n_min >= 0.0, "warning",
            f"turning the barrel against the spindles reverses them while indexing (lowest "
            f"spindle speed {n_min:.0f} min^-1 against {n_rab:.0f} min^-1 at work); an "
            f"overrunning clutch in the spindle drive keeps them turning forward",
            f"turning the barrel against the spindles lowers their speed to {n_min:.0f} "
            f"min^-1 while indexing ({n_rab:.0f} min^-1 at work); an overrunning clutch in "
            f"the spindle drive can keep it", n_min, 0.0, S.PLANETARY))


def _checks(spec: ValidatedSpec, geo: K.GenevaGeometry, z: int, k: int, internal: bool,
            d_r: float) -> list:
    out = []
    out.append(check(
        "SLOTS_MIN", z >= 4, "warning",
        f"a 3-slot cross has extreme accelerations (|ε2|max = "
        f"{K.peak_acceleration(3, internal)[0]:.1f}·ω1²); use 4 slots or more, 5-6 where the "
        f"cycle allows",
        f"z = {z} slots (3 slots give extreme accelerations)", z, 4, S.PRACTICE))
    fits = geo.max_roller > 0.0 and d_r <= geo.max_roller
    if geo.max_roller > 0.0:
        advice = (f"use geneva.roller_diameter <= {geo.max_roller:.2f} mm or a larger "
                  f"geneva.center_distance")
    else:
        advice = "increase geneva.center_distance or reduce the clearance or the cross shaft"
    where = "at the slot mouth" if internal else "at the slot bottom"
    out.append(check(
        "ROLLER_FIT", fits, "error",
        f"the roller d_r = {_f(d_r, 3)} mm does not fit: web between slots {where} "
        f"{geo.web:.2f} mm, locking disc radius {geo.locking_radius:.2f} mm, slot end radius "
        f"{geo.slot_end_radius:.2f} mm; {advice}",
        f"roller d_r = {_f(d_r, 3)} mm fits (largest {geo.max_roller:.2f} mm; web "
        f"{geo.web:.2f} mm)", d_r, geo.max_roller, S.GENEVA_GEOM))
    return out
