"""``kind = "pzdn"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

The spec's tables select what is computed (several may be combined in one spec):
``[[spring]]`` (with ``[motor]`` for the wind-up of method A) sizes the torsion springs;
``[coupling_gear]`` rates the coupling's spur gear with the spur calculator; ``[startup]``
runs the three-mass start-up (closed form and/or numerical integration, a comparison with
the drive without the PZDN and a stiffness sweep); ``[regression]`` evaluates the KO-2
regression.  This module maps spec keys to the pure functions of :mod:`.spring`,
:mod:`.startup`, :mod:`.simulate`, :mod:`.regression` and :mod:`.coupling`, and their
results to report rows and checks.  Inputs are resolved (and every cross-key rule raised as
an :class:`InputError`) before the result is created, so that the echoed inputs carry the
defaults actually used.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from geardesign.core.errors import InputError, Problem
from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.pzdn import sources as S
from geardesign.pzdn import spring as SP
from geardesign.pzdn import tables

TABLES = ("spring", "coupling_gear", "startup", "regression")
AGREEMENT = 0.005          # closed form vs. integration, relative (acceptance of the method)


def _fmt(x: float, digits: int = 4) -> str:
    return f"{x:.{digits}f}".rstrip("0").rstrip(".")


def _assume(spec: ValidatedSpec, table: dict, key: str, path: str, value) -> None:
    """Fill in a default the calculation chose and echo it as assumed."""
    table[key] = value
    if path not in spec.assumed:
        spec.assumed.append(path)


def _drop(spec: ValidatedSpec, table: dict, path: str) -> None:
    """Remove an assumed default that the calculation does not use from the echo."""
    key = path.rsplit(".", 1)[-1]
    if path in spec.assumed:
        spec.assumed.remove(path)
        table.pop(key, None)


# =============================================================================== springs


@dataclass
class ResolvedSpring:
    key: str            # "spring[0]"
    number: int         # 1-based
    name: str
    inp: SP.SpringInput
    tau_allow: float | None
    sigma_source: str
    steel: object | None
    phi_kin: float | None
    phi_req: float | None
    phi_leg_req: float | None
    D_given_outer: bool
    d_in_series: bool = True
    design: SP.SpringDesign | None = None
    phi_full: float = 0.0        # largest wind-up at the finger, rad
    phi_full_body: float = 0.0   # its share taken by the coils, rad
    T_limit: float = math.nan    # torque at the stop angle, N·m
    arm_target: float = math.nan  # finger arm for the target stiffness, mm


def _allowables(sp: dict, key: str, steel, spec: ValidatedSpec):
    """([σ] as a function of d, [τ] as a function of d or None, a word on the source)."""
    lim = tables.limits()
    if sp["sigma_allow"] is not None:
        if sp["sigma_over_tau"] is not None:
            raise InputError.at(f"{key}.sigma_over_tau", sp["sigma_over_tau"],
                                "give sigma_allow or sigma_over_tau (× tau_allow), not both")
        tau = sp["tau_allow"]
        return (lambda d: sp["sigma_allow"]), (lambda d: tau) if tau else None, "spec"
    if sp["tau_allow"] is not None:
        if sp["sigma_over_tau"] is None:
            _assume(spec, sp, "sigma_over_tau", f"{key}.sigma_over_tau",
                    lim["sigma_over_tau_default"])
        r, tau = sp["sigma_over_tau"], sp["tau_allow"]
        return (lambda d: r * tau), (lambda d: tau), "[σ] = [σ]/[τ]·[τ] (thesis eq. (1))"
    if steel is not None:
        from geardesign.materials import spring_steel

        if sp["sigma_over_tau"] is not None:
            r = sp["sigma_over_tau"]
            return (lambda d: r * steel.allowable_shear(d)), steel.allowable_shear, \
                "[σ]/[τ] × library [τ]"
        return (lambda d: spring_steel.bending_allowable(steel, d)), steel.allowable_shear, \
            "library, [τ]/0.577 (Shigley §10-12)"
    raise InputError(Problem(f"{key}.sigma_allow", "missing; give the allowable bending "
                             "stress sigma_allow, or tau_allow (with sigma_over_tau, default "
                             "1.5), or a material from the library"))


def _resolve_spring(spec: ValidatedSpec, j: int, sp: dict, motor: dict | None) -> ResolvedSpring:
    from geardesign.materials import spring_steel

    key = f"spring[{j}]"
    lim = tables.limits()
    name = sp["name"] or f"spring {j + 1}"
    steel = spring_steel.get(sp["material"]) if sp["material"] is not None else None
    if sp["E"] is None:
        E = spring_steel.elastic_modulus(sp["material"]) if steel is not None else None
        _assume(spec, sp, "E", f"{key}.E", E if E is not None else lim["E_default"])
    E = sp["E"]
    sigma_of, tau_of, sigma_source = _allowables(sp, key, steel, spec)
    T = sp["torque"] * 1000.0
    c_in, D_in, d_in = sp["index"], sp["coil_diameter"], sp["wire_diameter"]
    outer = sp["diameter_basis"] == "outer"
    if c_in is None and D_in is None:
        raise InputError(Problem(f"{key}.coil_diameter", "missing; give the coil diameter "
                                 "or the spring index (index), or both"))

    def d_mean(d: float) -> float | None:
        if D_in is None:
            return None
        return D_in - d if outer else D_in

    in_series = True
    if d_in is None:   # d_min with k(c) and [σ](d): fixed point, then the standard series
        d = (32.0 * T / (math.pi * sigma_of(1.0))) ** (1.0 / 3.0)
        for _ in range(60):
            Dm = d_mean(d)
            c = c_in if c_in is not None else (Dm / d if Dm and Dm > d else 4.0)
            d = SP.min_wire_diameter(T, SP.curvature_factor(c, sp["curvature_factor"]),
                                     sigma_of(d))
        d, in_series = SP.standard_wire(d, tables.wire_series())
    else:
        d = d_in
    if D_in is not None:
        D = d_mean(d)
        limit = 2.0 * d if outer else d
        if D_in <= limit:
            what = ("2·d", "an outer") if outer else ("the wire diameter d", "a mean")
            raise InputError.at(f"{key}.coil_diameter", D_in,
                                f"must exceed {what[0]} = {_fmt(limit)} mm ({what[1]} coil "
                                f"diameter up to it leaves no bore); increase it or use a "
                                f"thinner wire")
    else:
        D = c_in * d
    if sp["pitch"] is not None and sp["pitch"] < d:
        raise InputError.at(f"{key}.pitch", sp["pitch"],
                            f"smaller than the wire diameter d = {_fmt(d)} mm: the coils "
                            f"would overlap; give pitch >= d (= d: close-wound)")
    for arm_key in ("leg_arm", "leg2_arm"):
        arm = sp[arm_key]
        if arm is not None and arm <= D / 2.0:
            raise InputError.at(f"{key}.{arm_key}", arm,
                                f"must exceed the coil radius D/2 = {_fmt(D / 2)} mm: the "
                                f"arm is measured from the spring axis to the load point")
    if sp["slot_arms"] is not None:
        lo, hi = sp["slot_arms"]
        if not lo < hi:
            raise InputError.at(f"{key}.slot_arms", sp["slot_arms"],
                                "give [least arm, largest arm] with least < largest")
        if lo <= D / 2.0:
            raise InputError.at(f"{key}.slot_arms", sp["slot_arms"],
                                f"the slot must lie outside the coil: least arm > D/2 = "
                                f"{_fmt(D / 2)} mm")
        if sp["leg_arm"] is not None and not lo <= sp["leg_arm"] <= hi:
            raise InputError.at(f"{key}.leg_arm", sp["leg_arm"],
                                f"the finger must sit in its slot: {_fmt(lo)} … {_fmt(hi)} mm")
    sigma_allow = sigma_of(d)
    # method A: required wind-up angle
    J = SP.second_moment(d)
    L_leg = sum(SP.leg_length(a, D, sp["leg_model"]) for a in (sp["leg_arm"], sp["leg2_arm"])
                if a is not None)
    phi_kin = phi_req = phi_leg = None
    phi_design = math.radians(sp["design_angle"]) if sp["design_angle"] is not None else None
    if motor is not None:
        phi_kin = SP.kinematic_windup(motor["speed"],
                                      motor["breakaway_time"] * motor["windup_factor"])
        phi_leg = SP.twist(T, L_leg, E, J)
        phi_req = phi_kin + phi_leg
        if phi_design is None:
            phi_design = SP.design_angle(phi_req, lim["design_angle_step"])
    if sp["coils"] is None and phi_design is None:
        raise InputError(Problem(f"{key}.coils", "missing; give the number of working coils, "
                                 "or [motor] (or design_angle) to compute it from the wind-up "
                                 "angle (method A)"))
    if sp["pitch"] is None:
        _assume(spec, sp, "pitch", f"{key}.pitch", d + lim["pitch_gap_default"])
    inp = SP.SpringInput(
        T=sp["torque"], E=E, sigma_allow=sigma_allow, d=d, c=c_in, D=D, i=sp["coils"],
        p=sp["pitch"], curvature=sp["curvature_factor"], leg_arm=sp["leg_arm"],
        leg2_arm=sp["leg2_arm"], leg_model=sp["leg_model"], phi_required=phi_req,
        phi_design=phi_design,
        phi_stop=math.radians(sp["stop_angle"]) if sp["stop_angle"] is not None else None)
    tau = tau_of(d) if tau_of is not None else None
    return ResolvedSpring(key, j + 1, name, inp, tau, sigma_source, steel, phi_kin, phi_req,
                          phi_leg, outer, in_series)


def _spring_rows(res: Result, r: ResolvedSpring, sp: dict, assumed: list) -> None:
    s = r.design = SP.design(r.inp)
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
                "spec" if sp["tau_allow"] is not None else "library")
        sec.add("sigma_over_tau", s.inp.sigma_allow / r.tau_allow, "-", "[σ]/[τ]",
                "ratio of the allowables (thesis: 1.25…1.5)", B + " eq. (1)")
    e_src = "spec" if f"{r.key}.E" not in assumed else (
        "library (ODOP)" if r.steel is not None else S.THESIS_B + " (2.15·10⁵ MPa)")
    sec.add("E", s.inp.E, "MPa", "E", "Young's modulus", e_src)
    sec.add("d_min", s.d_min, "mm", "d_min", "least wire diameter 2.17·∛(T·k/[σ])",
            B + " eq. (5)")
    sec.add("d", s.d, "mm", "d", "wire diameter",
            "spec" if sp["wire_diameter"] is not None else S.GOST9389)
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
                "spec" if sp["design_angle"] is not None else A + " (rounded up to 5°)")
        sec.add("i_required", s.i_required, "-", "i_req",
                "working coils for the design angle (φ − φ₁)·E·J/(π·D·T)", A + " eq. (15)")
    sec.add("i", s.i, "-", "i", "working coils",
            "spec" if sp["coils"] is not None else A + " (rounded up)")
    sec.add("p", s.p, "mm", "p", "coil pitch",
            "spec" if f"{r.key}.pitch" not in assumed else A + " (d + 2 mm)")
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
    if sp["slot_arms"] is not None:
        Cs = [SP.stiffness(s.inp.E, s.J, s.L + SP.leg_length(a, s.D, s.inp.leg_model)
                           + (SP.leg_length(s.inp.leg2_arm, s.D, s.inp.leg_model)
                              if s.inp.leg2_arm else 0.0)) / 1000.0 for a in sp["slot_arms"]]
        sec.add("C_slot", Cs, "N·m/rad", "C(l_min), C(l_max)",
                "stiffness with the finger at the ends of the slot", leg_src)
    if sp["target_stiffness"] is not None:
        L2 = SP.leg_length(s.inp.leg2_arm, s.D, s.inp.leg_model) if s.inp.leg2_arm else 0.0
        L_need = s.inp.E * s.J / (sp["target_stiffness"] * 1000.0) - s.L - L2
        arm = SP.arm_for_leg_length(L_need, s.D, s.inp.leg_model) if L_need > 0 else math.nan
        r.arm_target = arm if math.isfinite(arm) and arm > s.D / 2.0 else math.nan
        sec.add("arm_target", r.arm_target, "mm", "l_target",
                "finger arm that gives the target stiffness", leg_src)
    # full wind-up: geometry
    phi_full = max(x for x in (s.phi_T, s.inp.phi_design, s.inp.phi_stop) if x is not None)
    body = phi_full * s.L / (s.L + s.L_leg)
    r.phi_full, r.phi_full_body = phi_full, body
    sec.add("phi_full", phi_full, "rad", "φ_max", "largest wind-up (design torque, design "
            "angle or stop)", "max(φ_T, φ, φ_stop)")
    sec.add("D_wound", SP.wound_diameter(s.D, s.i, body), "mm", "D'",
            "mean coil diameter at the largest wind-up D·i/(i + φ/2π)", S.SHIGLEY)
    sec.add("D_i_wound", SP.wound_diameter(s.D, s.i, body) - s.d, "mm", "D_i'",
            "inner diameter at the largest wind-up", S.SHIGLEY)
    if sp["ends_fixed_axially"]:
        if s.i > 1.0:
            sec.add("p_wound", SP.wound_pitch(s.H, s.d, s.i, body), "mm", "p'",
                    "pitch at the largest wind-up, body held at H", "helix geometry")
            sec.add("phi_touch", SP.touching_angle(s.H, s.d, s.i), "rad", "φ_touch",
                    "coil-body wind-up at which the coils touch", "helix geometry")
    else:
        sec.add("H_wound", max(s.H, SP.free_body_length(s.d, s.i, body)), "mm", "H'",
                "body length at the largest wind-up, free ends d·(i + 1 + φ/2π)", S.SHIGLEY)
    if s.inp.phi_stop is not None:
        T_lim = s.C_finger * s.inp.phi_stop
        r.T_limit = T_lim
        sec.add("phi_stop", s.inp.phi_stop, "rad", "φ_stop", "stop angle of the coupling",
                "spec")
        sec.add("T_limit", T_lim, "N·m", "T_lim", "torque limit of the coupling C_f·φ_stop",
                S.THESIS_A)
        sec.add("sigma_limit", SP.bending_stress(T_lim * 1000.0, s.k, s.d), "MPa", "σ_lim",
                "bending stress at the torque limit", B + " eq. (1)")


def _spring_checks(res: Result, r: ResolvedSpring, sp: dict) -> None:
    s = r.design
    lim = tables.limits()
    n = r.number
    who = f"spring {n}" + (f" ({sp['name']})" if sp["name"] is not None else "")
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
    if sp["index"] is not None and sp["coil_diameter"] is not None:
        mis = abs(c - s.c_design) / s.c_design
        k_act = SP.curvature_factor(c, s.inp.curvature)
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
    if r.tau_allow is not None and (sp["tau_allow"] is not None
                                    or sp["sigma_over_tau"] is not None):
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
        if sp["design_angle"] is not None and r.phi_req is not None:
            out.append(check(
                f"DESIGN_ANGLE_{n}", s.inp.phi_design >= r.phi_req - 1e-12, "warning",
                f"{who}: design angle {sp['design_angle']:g}° is below the required wind-up "
                f"{math.degrees(r.phi_req):.1f}° (motor start + leg): raise it to at least "
                f"{math.ceil(math.degrees(r.phi_req)):g}°",
                f"{who}: design angle >= required wind-up {math.degrees(r.phi_req):.1f}°",
                sp["design_angle"], math.degrees(r.phi_req), S.THESIS_A + " eq. (13)"))
    # coils touching at full wind-up
    if sp["ends_fixed_axially"]:
        if s.i > 1.0:
            p_w = SP.wound_pitch(s.H, s.d, s.i, r.phi_full_body)
            need = s.d + s.d * r.phi_full_body / (2 * math.pi * (s.i - 1.0))
            out.append(check(
                f"COILS_TOUCH_{n}", p_w >= s.d - 1e-9, "error",
                f"{who}: the coils touch before the full wind-up of "
                f"{math.degrees(r.phi_full):.0f}° (pitch there {p_w:.2f} mm < d = {_fmt(s.d)} mm, "
                f"body held at H = {s.H:.1f} mm): increase the pitch to at least {need:.2f} mm, "
                f"or let the body lengthen (ends_fixed_axially = false)",
                f"{who}: coils clear at the full wind-up (pitch {p_w:.2f} mm >= d)", p_w, s.d,
                "helix geometry"))
    if sp["arbor_diameter"] is not None:
        Di = SP.wound_diameter(s.D, s.i, r.phi_full_body) - s.d
        out.append(check(
            f"ARBOR_CLEARANCE_{n}", Di > sp["arbor_diameter"], "error",
            f"{who}: wound up by {math.degrees(r.phi_full):.0f}° the inner diameter shrinks to "
            f"{Di:.2f} mm and grips the {_fmt(sp['arbor_diameter'])} mm arbor: use a thinner "
            f"arbor, a larger coil diameter or more coils",
            f"{who}: inner diameter {Di:.2f} mm at the full wind-up clears the arbor",
            Di, sp["arbor_diameter"], S.SHIGLEY))
    if s.inp.phi_stop is not None:
        T_lim = r.T_limit
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
            f"σ = {SP.bending_stress(T_lim * 1000.0, s.k, s.d):.0f} MPa > [σ]; lower stop_angle "
            f"to at most {math.degrees(s.T_allow / s.C_finger):.1f}° or use a thicker wire",
            f"{who}: σ at the torque limit within [σ] (T_lim <= T_allow = {s.T_allow:.2f} N·m)",
            T_lim, s.T_allow, S.THESIS_B + " eq. (1)"))
    if sp["target_stiffness"] is not None:
        arm = r.arm_target
        slot = sp["slot_arms"]
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
            f"{who}: target stiffness {_fmt(sp['target_stiffness'])} N·m/rad {why}",
            f"{who}: target stiffness {_fmt(sp['target_stiffness'])} N·m/rad with the finger "
            f"at l = {arm:.1f} mm" if math.isfinite(arm) else "", arm if math.isfinite(arm)
            else None, None, S.THESIS_A))


# =============================================================================== coupling gear


def _coupling(spec: ValidatedSpec, g: dict):
    """Module estimate, face width and the spur spec of the coupling gear."""
    from geardesign.materials.gear_steel import resolve
    from geardesign.pzdn import coupling as CG
    from geardesign.spur.strength import gost21354 as G
    from geardesign.spur.strength import tables as GT

    if g["peak_torque"] is not None and g["peak_torque"] < g["torque"]:
        raise InputError.at("coupling_gear.peak_torque", g["peak_torque"],
                            f"smaller than the working torque {_fmt(g['torque'])} N·m; give "
                            f"the largest short-time torque")
    u = g["z2"] / g["z1"]
    T1 = CG.pinion_torque(g["torque"], g["torque_on"], g["planets"], u)
    T1_peak = (CG.pinion_torque(g["peak_torque"], g["torque_on"], g["planets"], u)
               if g["peak_torque"] is not None else None)
    mats = []
    for who in ("pinion", "wheel"):
        m = dict(g[who], root_ground=False, roughness_Ra=1.25)
        mats.append(resolve(m, f"coupling_gear.{who}"))
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
    est = dict(u=u, T1=T1, T1_peak=T1_peak, Y_F=Y_F, sFP=sFP, weak=weak, K_Fb=K_Fb,
               T_est=T_est, m_est=m_est, module=module, b=b,
               K_Fb_given=f.get("K_Fbeta") is not None)
    return est, CG.spur_spec(g, module, b, T1, T1_peak)


def _coupling_rows(res: Result, g: dict, est: dict, spur_spec: dict) -> None:
    from geardesign.pzdn import coupling as CG

    sec = res.section("coupling_gear", "Coupling gear: load sharing and module estimate")
    sec.add("u", est["u"], "-", "u", "gear ratio z2/z1", "geometry")
    sec.add("T1_mesh", est["T1"], "N·m", "T1", f"pinion torque per mesh (torque on the "
            f"{g['torque_on']} over {g['planets']} meshes)", S.TEXTBOOK_GEAR)
    if est["T1_peak"] is not None:
        sec.add("T1_mesh_peak", est["T1_peak"], "N·m", "T1max", "peak pinion torque per mesh",
                S.TEXTBOOK_GEAR)
    sec.add("Y_F1", est["Y_F"][0], "-", "Y_F1", "form factor, pinion (estimate)",
            "spec" if (g["factors"] or {}).get("Y_FS1") else S.SPUR)
    sec.add("Y_F2", est["Y_F"][1], "-", "Y_F2", "form factor, wheel (estimate)",
            "spec" if (g["factors"] or {}).get("Y_FS2") else S.SPUR)
    sec.add("sigma_FP1_est", est["sFP"][0], "MPa", "[σ]_F1", "σ_Flim/S_F, pinion (estimate)",
            S.SPUR)
    sec.add("sigma_FP2_est", est["sFP"][1], "MPa", "[σ]_F2", "σ_Flim/S_F, wheel (estimate)",
            S.SPUR)
    sec.add("weaker", ("pinion", "wheel")[est["weak"]], None, "", "weaker gear in bending "
            "(larger Y_F/[σ]_F)", S.TEXTBOOK_GEAR)
    sec.add("K_Fbeta_est", est["K_Fb"], "-", "K_Fβ", "face load factor of the estimate"
            + ("" if est["K_Fb_given"] else " (chart K_Hβ, conservative)"),
            "spec" if est["K_Fb_given"] else S.SPUR)
    sec.add("m_est", est["m_est"], "mm", "m_est",
            "module estimate 1.4·∛(K_Fβ·T1·Y_F/(ψ_bd·z1²·[σ]_F))", S.TEXTBOOK_GEAR)
    sec.add("m", est["module"], "mm", "m", "module used",
            "spec" if g["module"] is not None else "GOST 9563-60 (rounded up)")
    sec.add("b_w", est["b"], "mm", "b_w", "face width used",
            "spec" if g["face_width"] is not None else "ψ_bd·m·z1")
    spur = CG.rate(spur_spec)
    res.methods.extend(m for m in spur.methods if m not in res.methods)
    # the spur calculator's own report is nested under this one; the main figures are
    # repeated here from it (not recomputed)
    res.parts.append(("coupling_gear_rating", "Coupling gear: the spur calculator's report",
                      spur))
    v = {row.key: row.value for sec_ in spur.sections for row in sec_.rows}
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
        "GEAR_MODULE", est["module"] >= est["m_est"] - 1e-9, "warning",
        f"coupling gear: module {_fmt(est['module'])} mm below the bending estimate "
        f"{est['m_est']:.2f} mm (the full GOST 21354-87 rating decides)",
        f"coupling gear: module {_fmt(est['module'])} mm >= estimate {est['m_est']:.2f} mm",
        est["module"], est["m_est"], S.TEXTBOOK_GEAR))


# =============================================================================== start-up


@dataclass
class StartupInput:
    model: object          # ThreeMass; its C12, C13 are set when the springs are known
    spring_C: tuple        # PZDN spring stiffness of each line, None: from a [[spring]]
    drive_C: tuple | None
    motor: object          # simulate.Motor
    t_end: float
    t_end_source: str
    omega_n: float | None


def _startup_input(spec: ValidatedSpec, st: dict, springs: list) -> StartupInput:
    from geardesign.pzdn.simulate import Motor
    from geardesign.pzdn.startup import ThreeMass

    by_name = {r.name: r for r in springs}
    Cs = []
    for line in ("12", "13"):
        num, ref = st[f"C{line}"], st[f"C{line}_spring"]
        if num is None and ref is None:
            raise InputError(Problem(f"startup.C{line}", f"missing; give the link stiffness "
                                     f"C{line} [N·m/rad], or C{line}_spring, the name of the "
                                     f"[[spring]] that gives it"))
        if num is not None and ref is not None:
            raise InputError.at(f"startup.C{line}_spring", ref, f"give C{line} or "
                                f"C{line}_spring, not both")
        if ref is not None:
            if ref not in by_name:
                names = ", ".join(f'"{n}"' for n in by_name) or "none: add [[spring]] tables"
                raise InputError.at(f"startup.C{line}_spring", ref,
                                    f"no [[spring]] of that name; known: {names}")
            Cs.append(None)
        else:
            Cs.append(num)
    drive = (st["C12_drive"], st["C13_drive"])
    if (drive[0] is None) != (drive[1] is None):
        missing = "C13_drive" if drive[1] is None else "C12_drive"
        raise InputError(Problem(f"startup.{missing}", "missing; give the drive stiffness of "
                                 "both lines (C12_drive and C13_drive) or of neither"))
    method = st["method"]
    if method == "closed_form":
        for k, default in (("rise_time", 0.0), ("damping_ratio", 0.0)):
            if st[k] != default and f"startup.{k}" not in spec.assumed:
                raise InputError.at(f"startup.{k}", st[k], "applies only to the numerical "
                                    "integration: the closed form is for a step torque without "
                                    "damping; use method = \"ode\" or \"both\"")
        if st["motor_model"] != "constant":
            raise InputError.at("startup.motor_model", st["motor_model"],
                                "the closed form needs a constant torque T1; use method = "
                                "\"ode\" or \"both\"")
    mm = st["motor_model"]
    kl = ("kloss_max_torque", "kloss_critical_slip", "synchronous_speed")
    cv = ("curve_speed", "curve_torque")
    for k in kl + cv:
        wanted = "kloss" if k in kl else "curve"
        if st[k] is not None and mm != wanted:
            raise InputError.at(f"startup.{k}", st[k],
                                f"applies only with motor_model = \"{wanted}\"")
    if mm == "kloss":
        for k in kl:
            if st[k] is None:
                raise InputError(Problem(f"startup.{k}", "missing; required with motor_model "
                                         "= \"kloss\" (breakdown torque, critical slip, "
                                         "synchronous speed)"))
        motor = Motor("kloss", st["T1"], st["rise_time"], st["kloss_max_torque"],
                      st["kloss_critical_slip"], math.pi * st["synchronous_speed"] / 30.0)
    elif mm == "curve":
        for k in cv:
            if st[k] is None:
                raise InputError(Problem(f"startup.{k}", "missing; required with motor_model "
                                         "= \"curve\" (speeds and torques of the characteristic)"))
        sp, tq = st["curve_speed"], st["curve_torque"]
        if len(sp) != len(tq):
            raise InputError.at("startup.curve_torque", tq,
                                f"needs one torque per speed: {len(sp)} speeds, {len(tq)} "
                                f"torques")
        if any(b <= a for a, b in zip(sp, sp[1:])):
            raise InputError.at("startup.curve_speed", sp, "the speeds must increase strictly")
        motor = Motor("curve", st["T1"], st["rise_time"],
                      speeds=tuple(math.pi * n / 30.0 for n in sp), torques=tuple(tq))
    else:
        motor = Motor("constant", st["T1"], st["rise_time"])
    if st["plot"] is not None:
        if Path(st["plot"]).suffix.lower() not in (".png", ".svg"):
            raise InputError.at("startup.plot", st["plot"], "the plot file must end in .png "
                                "or .svg")
        if st["history_points"] < 2:
            raise InputError.at("startup.history_points", st["history_points"],
                                "must be at least 2 to draw startup.plot")
    Js = st["J1"] + st["J2"] + st["J3"]
    eps = (st["T1"] - st["T2"] - st["T3"]) / Js
    omega_n = math.pi * st["motor_speed"] / 30.0 if st["motor_speed"] is not None else None
    if st["t_end"] is not None:
        t_end, src = st["t_end"], "spec"
    elif omega_n is None:
        raise InputError(Problem("startup.t_end", "missing; give the duration t_end [s] or "
                                 "motor_speed (the start-up then lasts until the mean speed "
                                 "reaches it)"))
    elif eps <= 0:
        raise InputError.at("startup.T1", st["T1"],
                            f"does not exceed T2 + T3 = {_fmt(st['T2'] + st['T3'])} N·m, so the "
                            f"machine never reaches motor_speed; give t_end to compute the "
                            f"stalled start, or a larger T1")
    else:
        t_end, src = omega_n / eps, "ω_n·ΣJ/(T1 − T2 − T3)"
    if method == "closed_form":   # defaults that only the integration uses: not echoed
        for k in ("rise_time", "damping_ratio", "stick", "motor_model"):
            _drop(spec, st, f"startup.{k}")
    # the link stiffnesses are filled in once the springs are designed
    model = ThreeMass(st["T1"], st["T2"], st["T3"], st["J1"], st["J2"], st["J3"], 1.0, 1.0)
    return StartupInput(model, tuple(Cs), drive if drive[0] is not None else None, motor,
                        t_end, src, omega_n)


def _link(spring_C: float, drive_C: float | None) -> float:
    from geardesign.pzdn.startup import series

    return series(spring_C, drive_C) if drive_C is not None else spring_C


MAX_PERIODS = 5_000
"""Oscillation periods of the stiffest mode over the start-up that the closed form resolves
(50 samples each): the bound on its time and memory (about 0.2 ms a period)."""
MAX_PERIODS_ODE = 500
"""The same bound for the numerical integration (about 3 ms a period at rtol 1e-12)."""


def _run_model(m, si: StartupInput, st: dict, want_cf: bool, want_ode: bool):
    """Closed form and/or integration of one model: (closed form, its peaks, its samples
    over t_end, simulation); None for what was not asked."""
    from geardesign.pzdn import startup as SU

    cf = cf_peak = cf_h = sim = None
    beta = SU.frequencies(SU.stage_matrix(m, True, True)[0])[0]
    periods = si.t_end * beta / (2.0 * math.pi)
    limit = MAX_PERIODS_ODE if want_ode else MAX_PERIODS
    if not periods <= limit:
        raise InputError(Problem(
            "startup", f"the start-up lasts {_fmt(si.t_end)} s and the stiffest mode "
            f"oscillates at {_fmt(beta / (2.0 * math.pi))} Hz: {periods:.3g} periods, more than "
            f"the {limit} that are resolved in bounded time"
            + (" by the integration" if want_ode else "") + "; give a shorter startup.t_end "
            f"or check J1, J2, J3 [kg*m^2] and the link stiffnesses [N·m/rad]"))
    if want_cf:
        cf = SU.solve(m, si.t_end)
        cf_peak = cf.peak()
        cf_h = SU.sample(cf, si.t_end, min(2.0 * math.pi / beta / 50.0, si.t_end / 2000.0))
    if want_ode:
        from geardesign.pzdn.simulate import simulate

        sim = simulate(m, si.motor, si.t_end, st.get("damping_ratio", 0.0),
                       st.get("stick", False))
    return cf, cf_peak, cf_h, sim


def _amplitude_rows(c, stage, key: str, words: str) -> None:
    """Mode amplitudes of a stage, one row per quantity and link (modes 1, 2 in a list)."""
    amp = stage.amplitudes()
    for j, (sym, name, src) in enumerate((
            ("A", "cosine amplitudes (sign-corrected)", S.NOTE_D),
            ("B", "sine amplitudes (sign-corrected)", S.NOTE_D),
            ("D", "mode amplitudes √(A² + B²)", S.THESIS_D + " eq. (26)"))):
        for link, off in (("12", 0), ("13", 3)):
            c.add(f"{sym}{link}_{key}", [a[j + off] for a in amp], "N·m",
                  f"{sym}({link})1, {sym}({link})2", f"{words} {name}, link 1-{link[1]}", src)


def _startup(res: Result, spec: ValidatedSpec, st: dict, si: StartupInput, springs: list):
    from dataclasses import replace

    from geardesign.pzdn import startup as SU

    by_name = {r.name: r for r in springs}
    sC = []
    for line, c in zip(("12", "13"), si.spring_C):
        sC.append(c if c is not None else by_name[st[f"C{line}_spring"]].design.C_finger)
    drive = si.drive_C or (None, None)
    C = (_link(sC[0], drive[0]), _link(sC[1], drive[1]))
    m = replace(si.model, C12=C[0], C13=C[1])
    method = st["method"]
    want_cf, want_ode = method in ("closed_form", "both"), method in ("ode", "both")
    cf, cf_peak, grid, sim = _run_model(m, si, st, want_cf, want_ode)
    D = S.THESIS_D

    sec = res.section("startup_model", "Start-up model (reduced to the motor shaft)")
    for k, unit, name in (("T1", "N·m", "motor starting torque"),
                          ("T2", "N·m", "resisting moment, mass 2"),
                          ("T3", "N·m", "resisting moment, mass 3")):
        sec.add(k, getattr(m, k), unit, k, name, "spec")
    for line, c, spring_c, dc in zip(("12", "13"), C, sC, drive):
        src = "spec" if st[f"C{line}_spring"] is None else f"spring \"{st[f'C{line}_spring']}\""
        sec.add(f"C{line}_spring", spring_c, "N·m/rad", f"C{line},M",
                f"PZDN spring stiffness of line 1-{line[1]}", src)
        sec.add(f"C{line}", c, "N·m/rad", f"C{line}", f"link stiffness 1-{line[1]} used"
                + (" (spring in series with the drive)" if dc is not None else ""),
                S.SERIES if dc is not None else src)
    sec.add("t_end", si.t_end, "s", "t_end", "duration computed", si.t_end_source)
    Js = m.J1 + m.J2 + m.J3
    sec.add("epsilon", (m.T1 - m.T2 - m.T3) / Js, "rad/s^2", "ε",
            "common angular acceleration (T1 − T2 − T3)/ΣJ", D + " eq. (22)")
    b3 = SU.frequencies(SU.stage_matrix(m, True, True)[0])
    b2 = SU.frequencies(SU.stage_matrix(m, True, False)[0])
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

    if cf is not None:
        c = res.section("closed_form", "Closed form (step torque, no damping; corrected "
                        "thesis solution)")
        c.add("order", cf.order, None, "", "break-away order", D)
        c.add("tau1", cf.tau1, "s", "τ1", "stage 1: only mass 1 moves", D + " eq. (12)")
        if cf.order in ("2 first", "3 first"):
            s2 = cf.stages[1]
            x0, dx0 = s2.torques(cf.tau1), s2.rates(cf.tau1)
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
            _amplitude_rows(c, s2, "stage2", "stage 2")
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
            _amplitude_rows(c, s3, "stage3", "stage 3")
        c.add("T12max", cf_peak[0], "N·m", "T12max", "peak link torque 1-2 (envelope)",
              D + " eq. (27)")
        c.add("T13max", cf_peak[1], "N·m", "T13max", "peak link torque 1-3 (envelope)",
              D + " eq. (27)")
        c.add("k12", cf_peak[0] / m.T2, "-", "k12", "dynamic load coefficient T12max/T2",
              D + " eq. (28)")
        c.add("k13", cf_peak[1] / m.T3, "-", "k13", "dynamic load coefficient T13max/T3",
              D + " eq. (28)")
        c.add("T12max_t", max(grid[1]), "N·m", "max T12(t)", "largest T12 within t_end",
              D)
        c.add("T13max_t", max(grid[2]), "N·m", "max T13(t)", "largest T13 within t_end",
              D)
        w2min, w3min = min(grid[4]), min(grid[5])
        c.add("omega_min", [w2min, w3min], "rad/s", "min ω2, ω3",
              "lowest speeds of masses 2, 3 (negative: runs backwards)", D)
    if sim is not None:
        o = res.section("ode", "Numerical integration")
        o.add("T12max", sim.T12_max, "N·m", "T12max", "peak link torque 1-2", S.ODE)
        o.add("T13max", sim.T13_max, "N·m", "T13max", "peak link torque 1-3", S.ODE)
        o.add("t12max", sim.t12_max, "s", "t(T12max)", "time of the peak 1-2", S.ODE)
        o.add("t13max", sim.t13_max, "s", "t(T13max)", "time of the peak 1-3", S.ODE)
        o.add("k12", sim.T12_max / m.T2, "-", "k12", "dynamic load coefficient T12max/T2",
              D + " eq. (28)")
        o.add("k13", sim.T13_max / m.T3, "-", "k13", "dynamic load coefficient T13max/T3",
              D + " eq. (28)")
        o.add("t_break", [x if x is not None else math.nan for x in sim.t_break], "s",
              "t2, t3", "first break-away of masses 2, 3", S.ODE)
        o.add("sticks", list(sim.sticks), "-", "n_stick", "times masses 2, 3 came to rest "
              "again", S.ODE)
        o.add("damping", list(sim.c), "N·m*s/rad", "c12, c13", "link damping coefficients",
              "2ζ√(C·J1Jj/(J1+Jj))")
        o.add("final_speeds", list(sim.final_speeds), "rad/s", "ω1, ω2, ω3",
              "speeds at t_end", S.ODE)
    if st["history_points"] > 0:
        h = res.section("history", "Time histories")
        npts = st["history_points"]
        if sim is not None:
            from geardesign.pzdn.simulate import histories

            t, T12, T13, w1, w2, w3 = histories(sim, m, npts, si.t_end)
            src = S.ODE
        else:
            t, T12, T13, w1, w2, w3 = SU.sample(cf, si.t_end, si.t_end / max(npts - 1, 1))
            src = D
        for key, val, unit, name in (("t", t, "s", "time"), ("T12", T12, "N·m", "link torque 1-2"),
                                     ("T13", T13, "N·m", "link torque 1-3"),
                                     ("omega1", w1, "rad/s", "speed of mass 1"),
                                     ("omega2", w2, "rad/s", "speed of mass 2"),
                                     ("omega3", w3, "rad/s", "speed of mass 3")):
            h.add(key, list(val), unit, key, name, src)

    # ---------------------------------------------------------------- checks
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
            w = min(grid[4] + grid[5])
            res.checks.append(check(
                "CLOSED_FORM_VALIDITY", w >= -1e-9, "warning",
                f"in the linear solution a driven mass runs backwards (lowest speed {w:.2f} "
                f"rad/s): a real mechanism stops and sticks, so the closed-form peaks "
                f"over-predict; see the integration with stick = true",
                "the driven masses keep turning forwards: the closed form is valid", w, 0.0,
                S.NOTE_D))
    if cf is not None and sim is not None:
        same = (motor.model == "constant" and motor.rise_time == 0.0
                and st.get("damping_ratio", 0.0) == 0.0 and sim.sticks == [0, 0])
        if same:
            dev = max(abs(sim.T12_max - max(grid[1])) / max(grid[1]),
                      abs(sim.T13_max - max(grid[2])) / max(grid[2]))
            res.checks.append(check(
                "METHODS_AGREE", dev <= AGREEMENT, "warning",
                f"closed form and integration differ by {100 * dev:.2f} % (> 0.5 %) in the "
                f"peaks within t_end: report it as a bug", f"closed form and integration agree "
                f"within {100 * dev:.3f} % (peaks within t_end)", dev, AGREEMENT, S.ODE))
        else:
            res.checks.append(check(
                "METHODS_AGREE", False, "info",
                "closed form and integration solve different problems here (torque rise, "
                "motor characteristic, damping or sticking masses): their peaks are not "
                "expected to agree", "", None, None, S.ODE))
    if motor.model == "constant" and motor.rise_time == 0.0 and (
            sim is None or st.get("damping_ratio", 0.0) == 0.0):
        res.checks.append(check(
            "SCALING_INVARIANCE", False, "info",
            "with a step torque and no damping, multiplying C12 and C13 by the same factor only "
            "rescales time: k12 and k13 depend on C12/C13, not on the stiffness level; give "
            "rise_time, a motor characteristic or damping to see the effect of a softer PZDN",
            "", None, None, S.NOTE_D))

    # ---------------------------------------------------------------- comparison, sweep
    def peaks(model):
        cf_, cfp, g_, sim_ = _run_model(model, si, st, not want_ode, want_ode)
        if sim_ is not None:
            return sim_.T12_max, sim_.T13_max
        return cfp

    src_cmp = S.ODE if want_ode else D + " eq. (27)"
    base = (sim.T12_max, sim.T13_max) if sim is not None else cf_peak
    if si.drive_C is not None:
        m0 = replace(m, C12=si.drive_C[0], C13=si.drive_C[1])
        p0 = peaks(m0)
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
    if st["sweep"]:
        sw = res.section("startup_sweep", "Stiffness sweep (both links × λ)")
        ks12, ks13, T12s, T13s = [], [], [], []
        for lam in st["sweep"]:
            p = peaks(replace(m, C12=m.C12 * lam, C13=m.C13 * lam))
            T12s.append(p[0])
            T13s.append(p[1])
            ks12.append(p[0] / m.T2)
            ks13.append(p[1] / m.T3)
        sw.add("lambda", list(st["sweep"]), "-", "λ", "stiffness factor", "spec")
        sw.add("C12", [m.C12 * x for x in st["sweep"]], "N·m/rad", "C12", "link stiffness 1-2",
               "spec")
        sw.add("C13", [m.C13 * x for x in st["sweep"]], "N·m/rad", "C13", "link stiffness 1-3",
               "spec")
        sw.add("T12max", T12s, "N·m", "T12max", "peak link torque 1-2", src_cmp)
        sw.add("T13max", T13s, "N·m", "T13max", "peak link torque 1-3", src_cmp)
        sw.add("k12", ks12, "-", "k12", "dynamic load coefficient 1-2", src_cmp)
        sw.add("k13", ks13, "-", "k13", "dynamic load coefficient 1-3", src_cmp)

    if st["plot"] is not None:
        from geardesign.pzdn.plot import PlotError, write_plot

        from geardesign.core.io import confined, target_problem

        try:   # a file the spec names: inside the spec's folder (DESIGN.md, "Spec files")
            path = confined(st["plot"], spec.base_dir, spec.base_dir, "the spec's folder")
        except ValueError as exc:
            raise InputError.at("startup.plot", st["plot"], str(exc)) from None
        why = target_problem(path, spec.base_dir)
        if why is not None:
            raise InputError.at("startup.plot", st["plot"], f"cannot write: {why}")
        try:
            write_plot(res, path)
        except PlotError as exc:
            raise InputError.at("startup.plot", st["plot"], str(exc)) from None
        res.section("history", "Time histories").add("plot_file", str(path), None, "",
                                                      "plot written", "matplotlib")


# =============================================================================== regression


def _regression(res: Result, spec: ValidatedSpec, rg: dict) -> None:
    from geardesign.pzdn import regression as R
    from geardesign.pzdn.startup import series

    reg = tables.regression("ko2")
    if rg["C12"] is not None:
        if rg["pzdn_stiffness"] is not None or rg["drive_stiffness"] is not None:
            raise InputError.at("regression.C12", rg["C12"], "give C12, or pzdn_stiffness (with "
                                "drive_stiffness), not both")
        C, how = rg["C12"], "spec"
    elif rg["pzdn_stiffness"] is not None:
        C = (series(rg["pzdn_stiffness"], rg["drive_stiffness"])
             if rg["drive_stiffness"] is not None else rg["pzdn_stiffness"])
        how = S.SERIES if rg["drive_stiffness"] is not None else "spec"
    else:
        raise InputError(Problem("regression.pzdn_stiffness", "missing; give the PZDN "
                                 "stiffness pzdn_stiffness (and drive_stiffness in series), "
                                 "or the link stiffness C12"))
    E = S.THESIS_E
    p = R.evaluate(C, reg, rg["T_ref_12"], rg["T_ref_23"])
    sec = res.section("regression", f"Regression of the {reg['machine']} drive")
    sec.add("C12", C, "N·m/rad", "C12", "link stiffness"
            + (" 1/C = 1/C_M + 1/C_belt" if how == S.SERIES else ""), how)
    sec.add("T12max", p.T12max, "N·m", "T12max", "maximum moment, line 1-2", E + " eq. (1)")
    sec.add("T23max", p.T23max, "N·m", "T23max", "maximum moment, line 2-3", E + " eq. (2)")
    sec.add("k12", p.k12, "-", "k12", "T12max/T_ref12", E)
    sec.add("k23", p.k23, "-", "k23", "T23max/T_ref23", E)
    lo, hi = R.fitted_range(reg)
    sec.add("fitted_range", [lo, hi], "N·m/rad", "C range", "range treated as fitted "
            "(C0 ± 50 %, assumed: the thesis gives the centre only)", E)
    if rg["drive_stiffness"] is not None and rg["pzdn_stiffness"] is not None:
        p0 = R.evaluate(rg["drive_stiffness"], reg, rg["T_ref_12"], rg["T_ref_23"])
        cmp = res.section("regression_comparison", "With and without the PZDN (regression)")
        cmp.add("C_without", rg["drive_stiffness"], "N·m/rad", "C12", "drive alone", "spec")
        cmp.add("T12max_without", p0.T12max, "N·m", "T12max", "line 1-2 without the PZDN",
                E + " eq. (1)")
        cmp.add("T23max_without", p0.T23max, "N·m", "T23max", "line 2-3 without the PZDN",
                E + " eq. (2)")
        cmp.add("k23_without", p0.k23, "-", "k23", "k23 without the PZDN", E)
        cmp.add("change_T23", 100.0 * (p.T23max / p0.T23max - 1.0), "%", "ΔT23",
                "change of T23max by the PZDN", E)
        cmp.add("change_T12", 100.0 * (p.T12max / p0.T12max - 1.0), "%", "ΔT12",
                "change of T12max by the PZDN", E)
    if rg["sweep"]:
        pts = [R.evaluate(c, reg, rg["T_ref_12"], rg["T_ref_23"]) for c in rg["sweep"]]
        sw = res.section("regression_sweep", "Regression over the stiffness")
        sw.add("C12", list(rg["sweep"]), "N·m/rad", "C12", "link stiffness", "spec")
        sw.add("T12max", [q.T12max for q in pts], "N·m", "T12max", "line 1-2", E + " eq. (1)")
        sw.add("T23max", [q.T23max for q in pts], "N·m", "T23max", "line 2-3", E + " eq. (2)")
        sw.add("k12", [q.k12 for q in pts], "-", "k12", "T12max/T_ref12", E)
        sw.add("k23", [q.k23 for q in pts], "-", "k23", "T23max/T_ref23", E)
        outside = [c for c in rg["sweep"] if not lo <= c <= hi]
        if outside:
            res.checks.append(check(
                "REGRESSION_SWEEP_RANGE", False, "warning",
                f"{len(outside)} of {len(rg['sweep'])} sweep stiffnesses lie outside "
                f"{lo:g}…{hi:g} N·m/rad: those values are extrapolated", "", None, None, E))
    res.checks.append(check(
        "REGRESSION_RANGE", lo <= C <= hi, "warning",
        f"C12 = {C:.4g} N·m/rad lies outside {lo:g}…{hi:g} N·m/rad around the centre "
        f"C0 = {reg['C_zero']:g} of the fitted design: the regression is extrapolated there "
        f"(the thesis itself uses it at 24.7 N·m/rad); use the start-up model ([startup]) "
        f"for a soft PZDN", f"C12 = {C:.4g} N·m/rad within {lo:g}…{hi:g} N·m/rad", C,
        lo if C < lo else hi, E))
    res.checks.append(check(
        "REGRESSION_MACHINE", False, "info",
        f"the regression belongs to the {reg['machine']} drive at T1 = {reg['T1_zero']:g} N·m, "
        f"J1 = {reg['J1_zero']:g} kg·m²; for another drive use the start-up model",
        "", None, None, E))


# =============================================================================== compute


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.pzdn import CALCULATOR

    d = spec.data
    present = [t for t in TABLES if d.get(t) is not None]
    if not present:
        raise InputError(Problem("", "nothing to compute: give [[spring]] tables, "
                                 "[coupling_gear], [startup] or [regression]"))
    if d["motor"] is not None and d["spring"] is None:
        raise InputError(Problem("motor", "applies only with [[spring]] tables (the wind-up "
                                 "angle of method A); remove it or add the springs"))
    springs = []
    if d["spring"] is not None:
        seen: dict = {}
        for j, sp in enumerate(d["spring"]):
            if sp["name"] is not None and sp["name"] in seen:
                raise InputError.at(f"spring[{j}].name", sp["name"],
                                    f"spring[{seen[sp['name']]}] has the same name; give each "
                                    f"spring its own name")
            seen.setdefault(sp["name"], j)
        motor = d["motor"]
        springs = [_resolve_spring(spec, j, sp, motor) for j, sp in enumerate(d["spring"])]
    coupling = None
    if d["coupling_gear"] is not None:
        coupling = _coupling(spec, d["coupling_gear"])
    si = None
    if d["startup"] is not None:
        si = _startup_input(spec, d["startup"], springs)
    work = [dict(sp) for sp in d["spring"] or ()]
    for sp in d["spring"] or ():   # the inputs echo leaves out keys not given (as for tables)
        for k in [k for k, v in sp.items() if v is None]:
            del sp[k]
    res = CALCULATOR.new_result(spec)
    res.methods = [CALCULATOR.methods[0]] + (list(CALCULATOR.methods[1:]) if springs else [])
    if si is not None and d["startup"]["method"] != "closed_form":
        res.methods.append("numerical integration (scipy)")
    if d["motor"] is not None:
        mo = d["motor"]
        sec = res.section("motor", "Motor")
        omega = math.pi * mo["speed"] / 30.0
        sec.add("omega", omega, "rad/s", "ω", "angular speed π·n/30", S.THESIS_A)
        if mo["nominal_torque"] is not None or mo["power"] is not None:
            Tn = mo["nominal_torque"] if mo["nominal_torque"] is not None else \
                mo["power"] * 1000.0 / omega
            sec.add("T_nominal", Tn, "N·m", "T_c", "nominal torque P/ω",
                    "spec" if mo["nominal_torque"] is not None else S.THESIS_A)
        sec.add("t_windup", mo["breakaway_time"] * mo["windup_factor"], "s", "t",
                "spring wind-up time = motor start time factor·t1", S.THESIS_A + " eq. (14)")
    for r, sp in zip(springs, work):
        _spring_rows(res, r, sp, spec.assumed)
        _spring_checks(res, r, sp)
    if len(springs) > 1:
        sec = res.section("springs", "Springs together")
        sec.add("names", [r.name for r in springs], None, "", "springs", "spec")
        sec.add("C", [r.design.C for r in springs], "N·m/rad", "C_i", "stiffnesses of the coils",
                S.THESIS_B + " eq. (11)")
        sec.add("C_finger", [r.design.C_finger for r in springs], "N·m/rad", "C_f,i",
                "stiffnesses at the fingers", S.THESIS_B)
        sec.add("C_series", 1.0 / sum(1.0 / r.design.C_finger for r in springs), "N·m/rad",
                "C_series", "all springs in series", S.SERIES)
        sec.add("C_parallel", sum(r.design.C_finger for r in springs), "N·m/rad", "C_parallel",
                "all springs in parallel", "statics")
    if coupling is not None:
        _coupling_rows(res, d["coupling_gear"], *coupling)
    if si is not None:
        _startup(res, spec, d["startup"], si, springs)
    if d["regression"] is not None:
        _regression(res, spec, d["regression"])
    return res
