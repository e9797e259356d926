"""The solved PZDN (:class:`~geardesign.pzdn.solve.Solution`) as a
:class:`~geardesign.core.result.Result`: the motor, the springs (:mod:`.report_spring`),
the coupling gear, the start-up (:mod:`.report_startup`) and the regression; nothing is
computed here."""

from __future__ import annotations

from geardesign.core.result import Result, check
from geardesign.pzdn import sources as S
from geardesign.pzdn.inputs import Inputs, Regression
from geardesign.pzdn.report_spring import spring_checks, spring_rows
from geardesign.pzdn.report_startup import startup_rows
from geardesign.pzdn.solve import CouplingResult, MotorResult, RegressionResult, Solution
from geardesign.pzdn.spring_inputs import fmt as _fmt


def _motor_rows(res: Result, mo: MotorResult, given_torque: bool) -> None:
    sec = res.section("motor", "Motor")
    sec.add("omega", mo.omega, "rad/s", "ω", "angular speed π·n/30", S.THESIS_A)
    if mo.T_nominal is not None:
        sec.add("T_nominal", mo.T_nominal, "N·m", "T_c", "nominal torque P/ω",
                "spec" if given_torque else S.THESIS_A)
    sec.add("t_windup", mo.t_windup, "s", "t",
            "spring wind-up time = motor start time factor·t1", S.THESIS_A + " eq. (14)")


def _springs_rows(res: Result, sol: Solution) -> None:
    springs = sol.springs
    sec = res.section("springs", "Springs together")
    sec.add("names", [r.spring.name for r in springs], None, "", "springs", "spec")
    sec.add("C", [r.design.C for r in springs], "N·m/rad", "C_i", "stiffnesses of the coils",
            S.THESIS_B + " eq. (11)")
    sec.add("C_finger", [r.design.C_finger for r in springs], "N·m/rad", "C_f,i",
            "stiffnesses at the fingers", S.THESIS_B)
    sec.add("C_series", sol.C_series, "N·m/rad", "C_series", "all springs in series", S.SERIES)
    sec.add("C_parallel", sol.C_parallel, "N·m/rad", "C_parallel",
            "all springs in parallel", "statics")


def _coupling_rows(res: Result, g: dict, est: CouplingResult) -> None:
    sec = res.section("coupling_gear", "Coupling gear: load sharing and module estimate")
    sec.add("u", est.u, "-", "u", "gear ratio z2/z1", "geometry")
    sec.add("T1_mesh", est.T1, "N·m", "T1", f"pinion torque per mesh (torque on the "
            f"{g['torque_on']} over {g['planets']} meshes)", S.TEXTBOOK_GEAR)
    if est.T1_peak is not None:
        sec.add("T1_mesh_peak", est.T1_peak, "N·m", "T1max", "peak pinion torque per mesh",
                S.TEXTBOOK_GEAR)
    sec.add("Y_F1", est.Y_F[0], "-", "Y_F1", "form factor, pinion (estimate)",
            "spec" if (g["factors"] or {}).get("Y_FS1") else S.SPUR)
    sec.add("Y_F2", est.Y_F[1], "-", "Y_F2", "form factor, wheel (estimate)",
            "spec" if (g["factors"] or {}).get("Y_FS2") else S.SPUR)
    sec.add("sigma_FP1_est", est.sigma_FP[0], "MPa", "[σ]_F1", "σ_Flim/S_F, pinion (estimate)",
            S.SPUR)
    sec.add("sigma_FP2_est", est.sigma_FP[1], "MPa", "[σ]_F2", "σ_Flim/S_F, wheel (estimate)",
            S.SPUR)
    sec.add("weaker", ("pinion", "wheel")[est.weak], None, "", "weaker gear in bending "
            "(larger Y_F/[σ]_F)", S.TEXTBOOK_GEAR)
    sec.add("K_Fbeta_est", est.K_Fbeta, "-", "K_Fβ", "face load factor of the estimate"
            + ("" if est.K_Fbeta_given else " (chart K_Hβ, conservative)"),
            "spec" if est.K_Fbeta_given else S.SPUR)
    sec.add("m_est", est.m_est, "mm", "m_est",
            "module estimate 1.4·∛(K_Fβ·T1·Y_F/(ψ_bd·z1²·[σ]_F))", S.TEXTBOOK_GEAR)
    sec.add("m", est.module, "mm", "m", "module used",
            "spec" if g["module"] is not None else "GOST 9563-60 (rounded up)")
    sec.add("b_w", est.face_width, "mm", "b_w", "face width used",
            "spec" if g["face_width"] is not None else "ψ_bd·m·z1")
    from geardesign.pzdn.coupling import spur_report

    spur = spur_report(est.spur)
    res.methods.extend(m for m in spur.methods if m not in res.methods)
    # the spur calculator's own report is nested under this one; the main figures are
    # read from its record (not recomputed)
    res.parts.append(("coupling_gear_rating", "Coupling gear: the spur calculator's report",
                      spur))
    v = est.spur.values
    for key, unit, sym, name in (
            ("sigma_H", "MPa", "σ_H", "contact stress"),
            ("sigma_HP", "MPa", "σ_HP", "allowable contact stress of the pair"),
            ("sigma_F1", "MPa", "σ_F1", "root bending stress, pinion"),
            ("sigma_FP1", "MPa", "σ_FP1", "allowable bending stress, pinion"),
            ("sigma_F2", "MPa", "σ_F2", "root bending stress, wheel"),
            ("sigma_FP2", "MPa", "σ_FP2", "allowable bending stress, wheel"),
            ("S_H2", "-", "S_H2", "contact safety factor, wheel"),
            ("S_F1", "-", "S_F1", "bending safety factor, pinion"),
            ("S_F2", "-", "S_F2", "bending safety factor, wheel")):
        if key in v:
            sec.add(key, v[key], unit, sym, name + " (from the spur report)",
                    f"spur calculator ({g['method']})")
    from geardesign.core.units_guard import given, lifted

    res.checks.extend(lifted(spur, "UNITS_LOAD", given(
        g, {"torque": "N·m", "peak_torque": "N·m"}, "coupling_gear"), "the coupling gear"))
    failed = [c.code for c in spur.failed]
    if "sigma_H" in v and "sigma_HP" in v:      # GOST 21354-87: one σ_H of the pair
        passed = (f"coupling gear passes every check of the spur calculator (σ_H = "
                  f"{v['sigma_H']:.0f} MPa <= σ_HP = {v['sigma_HP']:.0f} MPa)")
    else:                                       # ISO 6336: safety factors per gear
        passed = (f"coupling gear passes every check of the spur calculator ({g['method']}: "
                  f"S_H = {min(v['S_H1'], v['S_H2']):.2f}, "
                  f"S_F = {min(v['S_F1'], v['S_F2']):.2f})")
    res.checks.append(check(
        "COUPLING_GEAR", not failed, "error",
        f"coupling gear fails {', '.join(failed)} of the spur calculator: see its report below "
        f"for what to change (module, face width, materials)",
        passed, None, None, f"spur calculator ({g['method']})"))
    res.checks.append(check(
        "GEAR_MODULE", est.module >= est.m_est - 1e-9, "warning",
        f"coupling gear: module {_fmt(est.module)} mm below the bending estimate "
        f"{est.m_est:.2f} mm (the full GOST 21354-87 rating decides)",
        f"coupling gear: module {_fmt(est.module)} mm >= estimate {est.m_est:.2f} mm",
        est.module, est.m_est, S.TEXTBOOK_GEAR))


# =============================================================================== regression


def _regression_rows(res: Result, rg: Regression, r: RegressionResult) -> None:
    C, how, p = rg.C, rg.how, r.point
    E = S.THESIS_E
    sec = res.section("regression", f"Regression of the {r.machine} drive")
    sec.add("C12", C, "N·m/rad", "C12", "link stiffness"
            + (" 1/C = 1/C_M + 1/C_belt" if how == S.SERIES else ""), how)
    sec.add("T12max", p.T12max, "N·m", "T12max", "maximum moment, line 1-2", E + " eq. (1)")
    sec.add("T23max", p.T23max, "N·m", "T23max", "maximum moment, line 2-3", E + " eq. (2)")
    sec.add("k12", p.k12, "-", "k12", "T12max/T_ref12", E)
    sec.add("k23", p.k23, "-", "k23", "T23max/T_ref23", E)
    lo, hi = r.fitted
    sec.add("fitted_range", [lo, hi], "N·m/rad", "C range", "range treated as fitted "
            "(C0 ± 50 %, assumed: the thesis gives the centre only)", E)
    if r.without is not None:
        p0 = r.without
        cmp = res.section("regression_comparison", "With and without the PZDN (regression)")
        cmp.add("C_without", rg.drive_stiffness, "N·m/rad", "C12", "drive alone", "spec")
        cmp.add("T12max_without", p0.T12max, "N·m", "T12max", "line 1-2 without the PZDN",
                E + " eq. (1)")
        cmp.add("T23max_without", p0.T23max, "N·m", "T23max", "line 2-3 without the PZDN",
                E + " eq. (2)")
        cmp.add("k23_without", p0.k23, "-", "k23", "k23 without the PZDN", E)
        cmp.add("change_T23", 100.0 * (p.T23max / p0.T23max - 1.0), "%", "ΔT23",
                "change of T23max by the PZDN", E)
        cmp.add("change_T12", 100.0 * (p.T12max / p0.T12max - 1.0), "%", "ΔT12",
                "change of T12max by the PZDN", E)
    if rg.sweep:
        pts = r.sweep
        sw = res.section("regression_sweep", "Regression over the stiffness")
        sw.add("C12", list(rg.sweep), "N·m/rad", "C12", "link stiffness", "spec")
        sw.add("T12max", [q.T12max for q in pts], "N·m", "T12max", "line 1-2", E + " eq. (1)")
        sw.add("T23max", [q.T23max for q in pts], "N·m", "T23max", "line 2-3", E + " eq. (2)")
        sw.add("k12", [q.k12 for q in pts], "-", "k12", "T12max/T_ref12", E)
        sw.add("k23", [q.k23 for q in pts], "-", "k23", "T23max/T_ref23", E)
        outside = [c for c in rg.sweep if not lo <= c <= hi]
        if outside:
            res.checks.append(check(
                "REGRESSION_SWEEP_RANGE", False, "warning",
                f"{len(outside)} of {len(rg.sweep)} sweep stiffnesses lie outside "
                f"{lo:g}…{hi:g} N·m/rad: those values are extrapolated", "", None, None, E))
    res.checks.append(check(
        "REGRESSION_RANGE", lo <= C <= hi, "warning",
        f"C12 = {C:.4g} N·m/rad lies outside {lo:g}…{hi:g} N·m/rad around the centre "
        f"C0 = {r.C_zero:g} of the fitted design: the regression is extrapolated there "
        f"(the thesis itself uses it at 24.7 N·m/rad); use the start-up model ([startup]) "
        f"for a soft PZDN", f"C12 = {C:.4g} N·m/rad within {lo:g}…{hi:g} N·m/rad", C,
        lo if C < lo else hi, E))
    res.checks.append(check(
        "REGRESSION_MACHINE", False, "info",
        f"the regression belongs to the {r.machine} drive at T1 = {r.T1_zero:g} N·m, "
        f"J1 = {r.J1_zero:g} kg·m²; for another drive use the start-up model",
        "", None, None, E))


def report(res: Result, inp: Inputs, sol: Solution, methods: tuple) -> Result:
    """Fill ``res`` (the calculator's result echoing the spec) with the rows and checks;
    ``methods``: the calculator's methods (the spring methods are named when there are
    springs)."""
    res.methods = [methods[0]] + (list(methods[1:]) if sol.springs else [])
    if inp.startup is not None and inp.startup.method != "closed_form":
        res.methods.append(S.METHOD_EXACT if inp.startup.motor.model == "constant"
                           else S.METHOD_ODE)
    if sol.motor is not None:
        _motor_rows(res, sol.motor, inp.motor.nominal_torque is not None)
    for sr in sol.springs:
        spring_rows(res, sr)
        spring_checks(res, sr)
    if len(sol.springs) > 1:
        _springs_rows(res, sol)
    if sol.coupling is not None:
        _coupling_rows(res, inp.coupling.table, sol.coupling)
    if sol.startup is not None:
        startup_rows(res, inp.startup, sol.startup)
    if sol.regression is not None:
        _regression_rows(res, inp.regression, sol.regression)
    return res
