"""The start-up of the PZDN (:class:`~geardesign.pzdn.solve_startup.StartupResult`) as
report rows and checks; nothing is computed here but ratios shown in the rows."""

from __future__ import annotations

import math

from geardesign.core.result import Result, check
from geardesign.pzdn import sources as S
from geardesign.pzdn.solve_startup import StartupResult
from geardesign.pzdn.startup_inputs import Startup

AGREEMENT = 0.005          # closed form vs. integration, relative (acceptance of the method)


def _amplitude_rows(c, amp, key: str, words: str) -> None:
    """Mode amplitudes of a stage, one row per quantity and link (modes 1, 2 in a list)."""
    for j, (sym, name, src) in enumerate((
            ("A", "cosine amplitudes (sign-corrected)", S.NOTE_D),
            ("B", "sine amplitudes (sign-corrected)", S.NOTE_D),
            ("D", "mode amplitudes √(A² + B²)", S.THESIS_D + " eq. (26)"))):
        for link, off in (("12", 0), ("13", 3)):
            c.add(f"{sym}{link}_{key}", [a[j + off] for a in amp], "N·m",
                  f"{sym}({link})1, {sym}({link})2", f"{words} {name}, link 1-{link[1]}", src)


def _model_rows(res: Result, si: Startup, r: StartupResult) -> None:
    m, D = r.model, S.THESIS_D
    C, sC, drive = (m.C12, m.C13), r.spring_C, si.drive_C or (None, None)

    sec = res.section("startup_model", "Start-up model (reduced to the motor shaft)")
    for k, unit, name in (("T1", "N·m", "motor starting torque"),
                          ("T2", "N·m", "resisting moment, mass 2"),
                          ("T3", "N·m", "resisting moment, mass 3")):
        sec.add(k, getattr(m, k), unit, k, name, "spec")
    for line, c, spring_c, dc, name in zip(("12", "13"), C, sC, drive, si.spring_names):
        src = "spec" if name is None else f"spring \"{name}\""
        sec.add(f"C{line}_spring", spring_c, "N·m/rad", f"C{line},M",
                f"PZDN spring stiffness of line 1-{line[1]}", src)
        sec.add(f"C{line}", c, "N·m/rad", f"C{line}", f"link stiffness 1-{line[1]} used"
                + (" (spring in series with the drive)" if dc is not None else ""),
                S.SERIES if dc is not None else src)
    sec.add("t_end", si.t_end, "s", "t_end", "duration computed", si.t_end_source)
    Js = m.J1 + m.J2 + m.J3
    sec.add("epsilon", (m.T1 - m.T2 - m.T3) / Js, "rad/s^2", "ε",
            "common angular acceleration (T1 − T2 − T3)/ΣJ", D + " eq. (22)")
    b3, b2 = r.beta3, r.beta2
    sec.add("beta_stage3", list(b3), "1/s", "β1, β2", "natural circular frequencies, all "
            "masses moving", D + " eq. (23)")
    sec.add("f_stage3", [b / (2 * math.pi) for b in b3], "Hz", "f1, f2",
            "natural frequencies, all masses moving", D + " eq. (23)")
    sec.add("beta_stage2", list(b2), "1/s", "β1, β2 (stage 2)",
            "circular frequencies with mass 3 at rest", D + " eq. (15)")
    motor = si.motor
    sec.add("motor_model", motor.model + (f", rise time {motor.rise_time:g} s"
                                          if motor.rise_time > 0 else ""), None, "",
            "motor torque during the start", "spec")


def _closed_form_rows(res: Result, r: StartupResult) -> None:
    m, D, cr = r.model, S.THESIS_D, r.closed_form
    cf, cf_peak = cr.cf, cr.peak
    c = res.section("closed_form", "Closed form (step torque, no damping; corrected "
                    "thesis solution)")
    c.add("order", cf.order, None, "", "break-away order", D)
    c.add("tau1", cf.tau1, "s", "τ1", "stage 1: only mass 1 moves", D + " eq. (12)")
    if cr.stage2_start is not None:
        s2 = cf.stages[1]
        x0, dx0 = cr.stage2_start
        c.add("T12_0", x0[0], "N·m", "T12(0)", "stage 2 start: link torque 1-2",
              D + " eq. (13)")
        c.add("T13_0", x0[1], "N·m", "T13(0)", "stage 2 start: link torque 1-3",
              D + " eq. (13)")
        c.add("dT12_0", dx0[0], "N·m/s", "T12'(0)", "stage 2 start: rate of T12",
              D + " eq. (13)")
        c.add("dT13_0", dx0[1], "N·m/s", "T13'(0)", "stage 2 start: rate of T13",
              D + " eq. (13)")
        c.add("a_stage2", list(s2.a), "N·m", "a12, a13", "stage 2 constant parts",
              D + " eq. (14)")
        c.add("beta2_stage2", [b * b for b in s2.beta], "1/s^2", "β1², β2²",
              "stage 2 squared frequencies", D + " eq. (15)")
        _amplitude_rows(c, cr.amplitudes2, "stage2", "stage 2")
    c.add("tau2", cf.tau2, "s", "τ2", "stage 2 duration (first upward crossing)",
          S.NOTE_D + " step 8")
    c.add("t_break", list(cf.t_break), "s", "t2, t3", "break-away of masses 2, 3 from "
          "switch-on", D)
    if cf.reached_stage3:
        s3 = cf.stages[-1]
        c.add("a_stage3", list(s3.a), "N·m", "a12, a13", "stage 3 constant parts",
              D + " eq. (22)")
        c.add("beta2_stage3", [b * b for b in s3.beta], "1/s^2", "β1², β2²",
              "stage 3 squared frequencies", D + " eq. (23)")
        _amplitude_rows(c, cr.amplitudes3, "stage3", "stage 3")
    c.add("T12max", cf_peak[0], "N·m", "T12max", "peak link torque 1-2 (envelope)",
          D + " eq. (27)")
    c.add("T13max", cf_peak[1], "N·m", "T13max", "peak link torque 1-3 (envelope)",
          D + " eq. (27)")
    c.add("k12", cf_peak[0] / m.T2, "-", "k12", "dynamic load coefficient T12max/T2",
          D + " eq. (28)")
    c.add("k13", cf_peak[1] / m.T3, "-", "k13", "dynamic load coefficient T13max/T3",
          D + " eq. (28)")
    c.add("T12max_t", cr.T12max_t, "N·m", "max T12(t)", "largest T12 within t_end",
          D)
    c.add("T13max_t", cr.T13max_t, "N·m", "max T13(t)", "largest T13 within t_end",
          D)
    c.add("omega_min", list(cr.omega_min), "rad/s", "min ω2, ω3",
          "lowest speeds of masses 2, 3 (negative: runs backwards)", D)


def _ode_rows(res: Result, r: StartupResult) -> None:
    m, D, sim = r.model, S.THESIS_D, r.sim
    src = S.ode(sim)
    o = res.section("ode", "Numerical integration")
    o.add("T12max", sim.T12_max, "N·m", "T12max", "peak link torque 1-2", src)
    o.add("T13max", sim.T13_max, "N·m", "T13max", "peak link torque 1-3", src)
    o.add("t12max", sim.t12_max, "s", "t(T12max)", "time of the peak 1-2", src)
    o.add("t13max", sim.t13_max, "s", "t(T13max)", "time of the peak 1-3", src)
    o.add("k12", sim.T12_max / m.T2, "-", "k12", "dynamic load coefficient T12max/T2",
          D + " eq. (28)")
    o.add("k13", sim.T13_max / m.T3, "-", "k13", "dynamic load coefficient T13max/T3",
          D + " eq. (28)")
    o.add("t_break", [x if x is not None else math.nan for x in sim.t_break], "s",
          "t2, t3", "first break-away of masses 2, 3", src)
    o.add("sticks", list(sim.sticks), "-", "n_stick", "times masses 2, 3 came to rest "
          "again", src)
    o.add("damping", list(sim.c), "N·m*s/rad", "c12, c13", "link damping coefficients",
          "2ζ√(C·J1Jj/(J1+Jj))")
    o.add("final_speeds", list(sim.final_speeds), "rad/s", "ω1, ω2, ω3",
          "speeds at t_end", src)


def _history_rows(res: Result, r: StartupResult) -> None:
    h = res.section("history", "Time histories")
    src = S.ode(r.sim) if r.sim is not None else S.THESIS_D
    for key, val, unit, name in (("t", r.history[0], "s", "time"),
                                 ("T12", r.history[1], "N·m", "link torque 1-2"),
                                 ("T13", r.history[2], "N·m", "link torque 1-3"),
                                 ("omega1", r.history[3], "rad/s", "speed of mass 1"),
                                 ("omega2", r.history[4], "rad/s", "speed of mass 2"),
                                 ("omega3", r.history[5], "rad/s", "speed of mass 3")):
        h.add(key, list(val), unit, key, name, src)


def _checks(res: Result, si: Startup, r: StartupResult) -> None:
    m, D, cr, sim, motor = r.model, S.THESIS_D, r.closed_form, r.sim, si.motor
    cf = cr.cf if cr is not None else None
    T_start = motor.static(0.0) if motor.model != "constant" else m.T1
    res.checks.append(check(
        "STARTUP_TORQUE", T_start > m.T2 + m.T3, "error",
        f"the motor starting torque {T_start:.2f} N·m does not exceed the resisting moments "
        f"T2 + T3 = {m.T2 + m.T3:.2f} N·m: the machine cannot accelerate; use a stronger motor "
        f"or reduce the load", f"starting torque {T_start:.2f} N·m > T2 + T3 = "
        f"{m.T2 + m.T3:.2f} N·m", T_start, m.T2 + m.T3, D))
    broke = (cf.reached_stage3 if cf is not None else True) and (
        sim is None or all(x is not None for x in sim.t_break))
    res.checks.append(check(
        "BREAKAWAY", broke, "error",
        "a driven mass never breaks away within t_end: its link never reaches the resisting "
        "moment; raise T1 or t_end, or check T2, T3", "both driven masses break away",
        None, None, D))
    if cf is not None:
        res.checks.append(check(
            "CLOSED_FORM_BRANCH", cf.order == "2 first", "info",
            f"break-away order \"{cf.order}\": the thesis' solution covers \"mass 2 first\" "
            f"(T2/C12 < T3/C13) only; computed here with the general form",
            "mass 2 breaks away first, as in the thesis", None, None, S.NOTE_D))
        if cf.reached_stage3:
            w = min(cr.omega_min)
            res.checks.append(check(
                "CLOSED_FORM_VALIDITY", w >= -1e-9, "warning",
                f"in the linear solution a driven mass runs backwards (lowest speed {w:.2f} "
                f"rad/s): a real mechanism stops and sticks, so the closed-form peaks "
                f"over-predict; see the integration with stick = true",
                "the driven masses keep turning forwards: the closed form is valid", w, 0.0,
                S.NOTE_D))
    if cf is not None and sim is not None:
        same = (motor.model == "constant" and motor.rise_time == 0.0
                and si.damping_ratio == 0.0 and sim.sticks == [0, 0])
        if same:
            dev = max(abs(sim.T12_max - cr.T12max_t) / cr.T12max_t,
                      abs(sim.T13_max - cr.T13max_t) / cr.T13max_t)
            res.checks.append(check(
                "METHODS_AGREE", dev <= AGREEMENT, "warning",
                f"closed form and integration differ by {100 * dev:.2f} % (> 0.5 %) in the "
                f"peaks within t_end: report it as a bug", f"closed form and integration agree "
                f"within {100 * dev:.3f} % (peaks within t_end)", dev, AGREEMENT, S.ode(sim)))
        else:
            res.checks.append(check(
                "METHODS_AGREE", False, "info",
                "closed form and integration solve different problems here (torque rise, "
                "motor characteristic, damping or sticking masses): their peaks are not "
                "expected to agree", "", None, None, S.ode(sim)))
    if motor.model == "constant" and motor.rise_time == 0.0 and (
            sim is None or si.damping_ratio == 0.0):
        res.checks.append(check(
            "SCALING_INVARIANCE", False, "info",
            "with a step torque and no damping, multiplying C12 and C13 by the same factor only "
            "rescales time: k12 and k13 depend on C12/C13, not on the stiffness level; give "
            "rise_time, a motor characteristic or damping to see the effect of a softer PZDN",
            "", None, None, S.NOTE_D))


def _comparison_rows(res: Result, si: Startup, r: StartupResult) -> None:
    m = r.model
    src_cmp = S.ode(r.sim) if r.sim is not None else S.THESIS_D + " eq. (27)"
    base = r.peaks
    if si.drive_C is not None:
        p0 = r.without
        cmp = res.section("startup_comparison", "With and without the PZDN (start-up)")
        cmp.add("C_without", list(si.drive_C), "N·m/rad", "C12, C13",
                "link stiffnesses without the PZDN (drive alone)", "spec")
        cmp.add("C_with", [m.C12, m.C13], "N·m/rad", "C12, C13",
                "link stiffnesses with the PZDN", S.SERIES)
        cmp.add("Tmax_without", list(p0), "N·m", "T12max, T13max", "peaks without the PZDN",
                src_cmp)
        cmp.add("Tmax_with", list(base), "N·m", "T12max, T13max", "peaks with the PZDN",
                src_cmp)
        cmp.add("k_without", [p0[0] / m.T2, p0[1] / m.T3], "-", "k12, k13",
                "dynamic load coefficients without the PZDN", src_cmp)
        cmp.add("k_with", [base[0] / m.T2, base[1] / m.T3], "-", "k12, k13",
                "dynamic load coefficients with the PZDN", src_cmp)
        change = [100.0 * (b / a - 1.0) for a, b in zip(p0, base)]
        cmp.add("change", change, "%", "ΔT12, ΔT13", "change of the peaks by the PZDN", src_cmp)
        better = all(x <= 0.0 for x in change)
        res.checks.append(check(
            "PZDN_EFFECT", better, "info",
            f"in this model the PZDN does not lower every peak (T12 {change[0]:+.1f} %, T13 "
            f"{change[1]:+.1f} %): try other spring stiffnesses (see the sweep), a torque rise "
            f"time or damping",
            f"the PZDN lowers the peaks: T12 {change[0]:+.1f} %, T13 {change[1]:+.1f} %",
            None, None, src_cmp))
    if si.sweep:
        sw = res.section("startup_sweep", "Stiffness sweep (both links × λ)")
        ks12, ks13, T12s, T13s = [], [], [], []
        for p in r.sweep:
            T12s.append(p[0])
            T13s.append(p[1])
            ks12.append(p[0] / m.T2)
            ks13.append(p[1] / m.T3)
        sw.add("lambda", list(si.sweep), "-", "λ", "stiffness factor", "spec")
        sw.add("C12", [m.C12 * x for x in si.sweep], "N·m/rad", "C12", "link stiffness 1-2",
               "spec")
        sw.add("C13", [m.C13 * x for x in si.sweep], "N·m/rad", "C13", "link stiffness 1-3",
               "spec")
        sw.add("T12max", T12s, "N·m", "T12max", "peak link torque 1-2", src_cmp)
        sw.add("T13max", T13s, "N·m", "T13max", "peak link torque 1-3", src_cmp)
        sw.add("k12", ks12, "-", "k12", "dynamic load coefficient 1-2", src_cmp)
        sw.add("k13", ks13, "-", "k13", "dynamic load coefficient 1-3", src_cmp)


def startup_rows(res: Result, si: Startup, r: StartupResult) -> None:
    """Rows and checks of the start-up."""
    _model_rows(res, si, r)
    if r.closed_form is not None:
        _closed_form_rows(res, r)
    if r.sim is not None:
        _ode_rows(res, r)
    if r.history is not None:
        _history_rows(res, r)
    _checks(res, si, r)
    _comparison_rows(res, si, r)


def write_plot(res: Result, spec, name: str) -> None:
    """Draw the time histories into the file ``startup.plot`` names (inside the spec's
    folder) and say so in the report."""
    from geardesign.core.errors import InputError
    from geardesign.core.io import confined, target_problem
    from geardesign.pzdn.plot import PlotError, write_plot as draw

    try:   # a file the spec names: inside the spec's folder (DESIGN.md, "Spec files")
        path = confined(name, spec.base_dir, spec.base_dir, "the spec's folder")
    except ValueError as exc:
        raise InputError.at("startup.plot", name, str(exc)) from None
    why = target_problem(path, spec.base_dir)
    if why is not None:
        raise InputError.at("startup.plot", name, f"cannot write: {why}")
    try:
        draw(res, path)
    except PlotError as exc:
        raise InputError.at("startup.plot", name, str(exc)) from None
    res.section("history", "Time histories").add("plot_file", str(path), None, "",
                                                  "plot written", "matplotlib")
