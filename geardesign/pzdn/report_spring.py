"""A spring of the PZDN (:class:`~geardesign.pzdn.solve.SpringResult`) as report rows and
checks; nothing is computed here."""

from __future__ import annotations

import math

from geardesign.core.result import Result, check
from geardesign.pzdn import sources as S
from geardesign.pzdn import tables
from geardesign.pzdn.solve import SpringResult
from geardesign.pzdn.spring_inputs import fmt as _fmt


def spring_rows(res: Result, sr: SpringResult) -> None:
    r, s = sr.spring, sr.design
    n = r.number
    A, B = S.THESIS_A, S.THESIS_B
    sec = res.section(f"spring{n}", f"Spring {n}: {r.name}")
    sec.add("name", r.name, None, "", "spring", "spec")
    sec.add("T", s.inp.T, "N·m", "T", "design torque", "spec")
    sec.add("c", s.c_design, "-", "c", "spring index used for k", B + " eq. (3)")
    sec.add("c_actual", s.c_actual, "-", "D/d", "actual index, mean diameter over wire", B)
    sec.add("k", s.k, "-", "k", f"curvature factor ({s.inp.curvature})",
            {"thesis": B + " eq. (2)", "wahl": S.SHIGLEY, "en13906": S.EN13906}[s.inp.curvature])
    sec.add("sigma_allow", s.inp.sigma_allow, "MPa", "[σ]", "allowable bending stress",
            r.sigma_source)
    if r.tau_allow is not None:
        sec.add("tau_allow", r.tau_allow, "MPa", "[τ]", "allowable torsional stress",
                "spec" if r.tau_given else "library")
        sec.add("sigma_over_tau", s.inp.sigma_allow / r.tau_allow, "-", "[σ]/[τ]",
                "ratio of the allowables (thesis: 1.25…1.5)", B + " eq. (1)")
    e_src = "spec" if not r.E_assumed else (
        "library (ODOP)" if r.steel is not None else S.THESIS_B + " (2.15·10⁵ MPa)")
    sec.add("E", s.inp.E, "MPa", "E", "Young's modulus", e_src)
    sec.add("d_min", s.d_min, "mm", "d_min", "least wire diameter 2.17·∛(T·k/[σ])",
            B + " eq. (5)")
    sec.add("d", s.d, "mm", "d", "wire diameter",
            "spec" if r.d_given else S.GOST9389)
    sec.add("D", s.D, "mm", "D", "mean coil diameter", "spec")
    sec.add("D_e", s.D + s.d, "mm", "D_e", "outer coil diameter", "geometry")
    sec.add("D_i", s.D - s.d, "mm", "D_i", "inner coil diameter", "geometry")
    sec.add("W", s.W, "mm^3", "W", "section modulus π·d³/32", B + " eq. (4)")
    sec.add("J", s.J, "mm^4", "J", "second moment of area π·d⁴/64", B + " eq. (8)")
    sec.add("sigma", s.sigma, "MPa", "σ", "bending stress at the design torque T·k/W",
            B + " eq. (1)")
    sec.add("utilisation", s.sigma / s.inp.sigma_allow, "-", "σ/[σ]", "stress utilisation",
            B + " eq. (1)")
    sec.add("T_allow", s.T_allow, "N·m", "T_allow", "torque at which σ = [σ]", B + " eq. (1)")
    if r.phi_kin is not None:
        sec.add("phi_kin", r.phi_kin, "rad", "φ₂", "motor-start wind-up ω·t/2, t = factor·t1",
                A + " eq. (14)")
        sec.add("phi_req", r.phi_req, "rad", "φ_req", "required wind-up angle φ₁ + φ₂",
                A + " eq. (13)")
    if s.inp.phi_design is not None:
        sec.add("phi_design", s.inp.phi_design, "rad", "φ", "design wind-up angle",
                "spec" if r.design_angle is not None else A + " (rounded up to 5°)")
        sec.add("i_required", s.i_required, "-", "i_req",
                "working coils for the design angle (φ − φ₁)·E·J/(π·D·T)", A + " eq. (15)")
    sec.add("i", s.i, "-", "i", "working coils",
            "spec" if r.coils_given else A + " (rounded up)")
    sec.add("p", s.p, "mm", "p", "coil pitch",
            "spec" if not r.pitch_assumed else A + " (d + 2 mm)")
    sec.add("L", s.L, "mm", "L", "wire length of the working coils π·D·i", B + " eq. (7)")
    sec.add("H", s.H, "mm", "H", "working height d + (i − 1)·p", A + " eq. (16)")
    sec.add("C", s.C, "N·m/rad", "C", "stiffness of the coils E·J/L", B + " eq. (11)")
    sec.add("phi_body", s.phi_body, "rad", "φ_c", "twist of the coils at T: T·L/(E·J)",
            B + " eq. (6)")
    leg_src = {"thesis": A + " eq. (7)", "shigley": S.SHIGLEY,
               "en13906_radial": S.EN13906, "en13906_tangential": S.EN13906}[s.inp.leg_model]
    if s.inp.leg_arm is not None or s.inp.leg2_arm is not None:
        if s.inp.leg_arm is not None:
            sec.add("leg_arm", s.inp.leg_arm, "mm", "l", "finger arm of the loaded leg", "spec")
            sec.add("F_leg", s.F_leg, "N", "F", "force on the finger T/l", A + " eq. (8)")
        sec.add("L_leg", s.L_leg, "mm", "L_leg", f"equivalent wire length of the legs "
                f"({s.inp.leg_model})", leg_src)
        sec.add("phi_leg", s.phi_leg, "rad", "φ₁", "leg bending at T", leg_src)
        sec.add("C_finger", s.C_finger, "N·m/rad", "C_f",
                "stiffness at the finger E·J/(L + L_leg)", leg_src)
    sec.add("phi_T", s.phi_T, "rad", "φ_T", "wind-up at the design torque (coils + legs)",
            B + " eq. (6)")
    sec.add("energy", 0.5 * s.inp.T * s.phi_T, "J", "U", "energy stored at the design torque "
            "T·φ/2", S.MECHANICS)
    # finger position: stiffness over the slot and the arm for a target stiffness
    if sr.C_slot is not None:
        sec.add("C_slot", list(sr.C_slot), "N·m/rad", "C(l_min), C(l_max)",
                "stiffness with the finger at the ends of the slot", leg_src)
    if r.target_stiffness is not None:
        sec.add("arm_target", sr.arm_target, "mm", "l_target",
                "finger arm that gives the target stiffness", leg_src)
    # full wind-up: geometry
    sec.add("phi_full", sr.phi_full, "rad", "φ_max", "largest wind-up (design torque, design "
            "angle or stop)", "max(φ_T, φ, φ_stop)")
    sec.add("D_wound", sr.D_wound, "mm", "D'",
            "mean coil diameter at the largest wind-up D·i/(i + φ/2π)", S.SHIGLEY)
    sec.add("D_i_wound", sr.D_wound - s.d, "mm", "D_i'",
            "inner diameter at the largest wind-up", S.SHIGLEY)
    if sr.p_wound is not None:
        sec.add("p_wound", sr.p_wound, "mm", "p'",
                "pitch at the largest wind-up, body held at H", "helix geometry")
        sec.add("phi_touch", sr.phi_touch, "rad", "φ_touch",
                "coil-body wind-up at which the coils touch", "helix geometry")
    if sr.H_wound is not None:
        sec.add("H_wound", sr.H_wound, "mm", "H'",
                "body length at the largest wind-up, free ends d·(i + 1 + φ/2π)", S.SHIGLEY)
    if s.inp.phi_stop is not None:
        sec.add("phi_stop", s.inp.phi_stop, "rad", "φ_stop", "stop angle of the coupling",
                "spec")
        sec.add("T_limit", sr.T_limit, "N·m", "T_lim", "torque limit of the coupling "
                "C_f·φ_stop", S.THESIS_A)
        sec.add("sigma_limit", sr.sigma_limit, "MPa", "σ_lim",
                "bending stress at the torque limit", B + " eq. (1)")


def spring_checks(res: Result, sr: SpringResult) -> None:
    r, s = sr.spring, sr.design
    lim = tables.limits()
    n = r.number
    who = f"spring {n}" + (f" ({r.name})" if r.named else "")
    B = S.THESIS_B
    out = res.checks
    out.append(check(
        f"SPRING_STRESS_{n}", s.sigma <= s.inp.sigma_allow, "error",
        f"{who} overstressed: σ = {s.sigma:.0f} MPa > [σ] = {s.inp.sigma_allow:.0f} MPa at "
        f"T = {_fmt(s.inp.T)} N·m; use a wire of at least d_min = {s.d_min:.2f} mm, a stronger "
        f"material or a smaller design torque",
        f"{who}: σ = {s.sigma:.0f} MPa <= [σ] = {s.inp.sigma_allow:.0f} MPa "
        f"({100 * (1 - s.sigma / s.inp.sigma_allow):.1f} % reserve)",
        s.sigma, s.inp.sigma_allow, B + " eq. (1)"))
    lo, hi = lim["index_allowed"]
    c = s.c_actual
    out.append(check(
        f"SPRING_INDEX_{n}", lo <= c <= hi, "error",
        f"{who}: index D/d = {c:.2f} outside {lo:g}…{hi:g}: "
        + (f"the coil cannot be wound that tight; use D >= {lo * s.d:.1f} mm or a thinner wire"
           if c < lo else f"the coil is too slack to keep its shape; use D <= {hi * s.d:.1f} mm "
                          f"or a thicker wire"),
        f"{who}: index D/d = {c:.2f} within {lo:g}…{hi:g}", c, lo if c < lo else hi, S.EN13906))
    rlo, rhi = lim["index_recommended"]
    if lo <= c <= hi:
        out.append(check(
            f"SPRING_INDEX_RANGE_{n}", rlo <= c <= rhi, "warning",
            f"{who}: index D/d = {c:.2f} outside the thesis' range {rlo:g}…{rhi:g}; "
            f"prefer D = {rlo * s.d:.0f}…{rhi * s.d:.0f} mm for d = {_fmt(s.d)} mm",
            f"{who}: index D/d = {c:.2f} within {rlo:g}…{rhi:g}", c, rhi if c > rhi else rlo,
            B + " eq. (3)"))
    if r.index_and_diameter:
        mis = abs(c - s.c_design) / s.c_design
        k_act = sr.k_actual
        out.append(check(
            f"SPRING_INDEX_MISMATCH_{n}", mis <= lim["index_mismatch"], "warning",
            f"{who}: the given index c = {_fmt(s.c_design, 2)} differs by {100 * mis:.0f} % from "
            f"D/d = {c:.2f}; k was taken with c = {_fmt(s.c_design, 2)} (as the thesis); with "
            f"D/d it is {k_act:.4f} (σ = {s.sigma * k_act / s.k:.0f} MPa): give index = "
            f"{c:.2f} or leave it out",
            f"{who}: index c = {_fmt(s.c_design, 2)} agrees with D/d = {c:.2f}", mis,
            lim["index_mismatch"], S.NOTE_A))
    out.append(check(
        f"SPRING_COILS_{n}", s.i >= lim["coils_min"], "warning",
        f"{who}: only {_fmt(s.i, 2)} working coils (< {lim['coils_min']:g}): the legs dominate "
        f"and the rate is uncertain; use more coils", f"{who}: {_fmt(s.i, 2)} working coils",
        s.i, lim["coils_min"], S.EN13906))
    if not r.d_in_series:
        out.append(check(
            f"WIRE_SERIES_{n}", False, "warning",
            f"{who}: d_min = {s.d_min:.2f} mm is beyond the GOST 9389-75 wire series "
            f"(up to 8 mm); d = {_fmt(s.d)} mm taken: check the availability of bar spring "
            f"steel or give wire_diameter", "", s.d, None, S.GOST9389))
    if r.steel is not None and not r.steel.covers(s.d):
        out.append(check(
            f"MATERIAL_RANGE_{n}", False, "warning",
            f"{who}: d = {_fmt(s.d)} mm outside {r.steel.d_min:g}…{r.steel.d_max:g} mm of "
            f"{r.steel.name}: its strength law is extrapolated", "", s.d, None,
            r.steel.standard))
    if r.tau_allow is not None and r.ratio_set:
        ratio = s.inp.sigma_allow / r.tau_allow
        a, b = lim["sigma_over_tau"]
        out.append(check(
            f"SIGMA_OVER_TAU_{n}", a - 1e-9 <= ratio <= b + 1e-9, "warning",
            f"{who}: [σ]/[τ] = {ratio:.2f} outside the thesis' {a:g}…{b:g}; check the allowables",
            f"{who}: [σ]/[τ] = {ratio:.2f} within {a:g}…{b:g}", ratio, b if ratio > b else a,
            S.THESIS_A + " eq. (1)"))
    if s.inp.phi_design is not None:
        i_req = math.ceil(s.i_required - 1e-9)
        out.append(check(
            f"SPRING_WINDUP_{n}", s.phi_T >= s.inp.phi_design - 1e-12, "warning",
            f"{who} too stiff for the motor wind-up: it turns {math.degrees(s.phi_T):.1f}° at "
            f"T = {_fmt(s.inp.T)} N·m, the design angle is {math.degrees(s.inp.phi_design):.1f}°; "
            f"use at least {i_req} working coils (or a longer finger arm)",
            f"{who}: turns {math.degrees(s.phi_T):.1f}° at the design torque >= design angle "
            f"{math.degrees(s.inp.phi_design):.1f}°", math.degrees(s.phi_T),
            math.degrees(s.inp.phi_design), S.THESIS_A + " eqs. (13)-(15)"))
        if r.design_angle is not None and r.phi_req is not None:
            out.append(check(
                f"DESIGN_ANGLE_{n}", s.inp.phi_design >= r.phi_req - 1e-12, "warning",
                f"{who}: design angle {r.design_angle:g}° is below the required wind-up "
                f"{math.degrees(r.phi_req):.1f}° (motor start + leg): raise it to at least "
                f"{math.ceil(math.degrees(r.phi_req)):g}°",
                f"{who}: design angle >= required wind-up {math.degrees(r.phi_req):.1f}°",
                r.design_angle, math.degrees(r.phi_req), S.THESIS_A + " eq. (13)"))
    # coils touching at full wind-up
    if sr.p_wound is not None:
        p_w, need = sr.p_wound, sr.pitch_needed
        out.append(check(
            f"COILS_TOUCH_{n}", p_w >= s.d - 1e-9, "error",
            f"{who}: the coils touch before the full wind-up of "
            f"{math.degrees(sr.phi_full):.0f}° (pitch there {p_w:.2f} mm < d = {_fmt(s.d)} mm, "
            f"body held at H = {s.H:.1f} mm): increase the pitch to at least {need:.2f} mm, "
            f"or let the body lengthen (ends_fixed_axially = false)",
            f"{who}: coils clear at the full wind-up (pitch {p_w:.2f} mm >= d)", p_w, s.d,
            "helix geometry"))
    if r.arbor_diameter is not None:
        Di = sr.D_wound - s.d
        out.append(check(
            f"ARBOR_CLEARANCE_{n}", Di > r.arbor_diameter, "error",
            f"{who}: wound up by {math.degrees(sr.phi_full):.0f}° the inner diameter shrinks to "
            f"{Di:.2f} mm and grips the {_fmt(r.arbor_diameter)} mm arbor: use a thinner "
            f"arbor, a larger coil diameter or more coils",
            f"{who}: inner diameter {Di:.2f} mm at the full wind-up clears the arbor",
            Di, r.arbor_diameter, S.SHIGLEY))
    if s.inp.phi_stop is not None:
        T_lim = sr.T_limit
        phi_need = s.inp.T / s.C_finger
        out.append(check(
            f"COUPLING_SLIP_{n}", T_lim >= s.inp.T, "error",
            f"{who}: the coupling reaches its stop at T_lim = {T_lim:.2f} N·m, below the working "
            f"torque {_fmt(s.inp.T)} N·m, so it slips in normal running; raise stop_angle to at "
            f"least {math.degrees(phi_need):.1f}° or stiffen the spring (fewer coils, thicker "
            f"wire, shorter finger arm)",
            f"{who}: torque limit {T_lim:.2f} N·m >= working torque {_fmt(s.inp.T)} N·m",
            T_lim, s.inp.T, S.THESIS_A))
        out.append(check(
            f"SPRING_STRESS_AT_LIMIT_{n}", T_lim <= s.T_allow, "error",
            f"{who}: at the torque limit {T_lim:.2f} N·m the coils reach "
            f"σ = {sr.sigma_limit:.0f} MPa > [σ]; lower stop_angle "
            f"to at most {math.degrees(s.T_allow / s.C_finger):.1f}° or use a thicker wire",
            f"{who}: σ at the torque limit within [σ] (T_lim <= T_allow = {s.T_allow:.2f} N·m)",
            T_lim, s.T_allow, S.THESIS_B + " eq. (1)"))
    if r.target_stiffness is not None:
        arm = sr.arm_target
        slot = r.slot_arms
        ok = math.isfinite(arm) and (slot is None or slot[0] <= arm <= slot[1])
        if not math.isfinite(arm):
            why = (f"unreachable: even with the finger at the coil the stiffness is at most "
                   f"{s.C:.3f} N·m/rad (coils alone) — use fewer coils or a thicker wire for a "
                   f"stiffer spring")
        elif slot is not None and not ok:
            why = (f"needs the finger at l = {arm:.1f} mm, outside the slot {slot[0]:g}…"
                   f"{slot[1]:g} mm; lengthen the slot or change the coils")
        else:
            why = ""
        out.append(check(
            f"TARGET_STIFFNESS_{n}", ok, "error",
            f"{who}: target stiffness {_fmt(r.target_stiffness)} N·m/rad {why}",
            f"{who}: target stiffness {_fmt(r.target_stiffness)} N·m/rad with the finger "
            f"at l = {arm:.1f} mm" if math.isfinite(arm) else "", arm if math.isfinite(arm)
            else None, None, S.THESIS_A))
