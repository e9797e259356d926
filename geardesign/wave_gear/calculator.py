"""``kind = "wave_gear"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

Maps the spec to :mod:`.rim` (K_zh) and :mod:`.flexwheel` (kinematics, stress, endurance).
Eqs. (9)-(10) of the paper (shift corrections α_x of a0) are illegible and are not used:
α_x = 1 is reported as such.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problems
from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.wave_gear import flexwheel as F
from geardesign.wave_gear import rim as R
from geardesign.wave_gear import sources as S

FULL = 2.25           # full tooth height of the GOST 13755 rack, × m (for α_h)
H_REC = (2.5, 3.0)    # recommended H0/m ([Tkachenko2017])
H_MIN = 1.5           # H0/m below which the rim is rejected ([IvanovWave])
W0_RANGE = (0.8, 1.3)  # w0/m ([IvanovWave])
U_RANGE = (60.0, 320.0)  # usual single-stage ratio ([IvanovWave])
T_AXIAL = 1e5         # N·m: large wave gears, axial fixation (Strelnikov)
TAU_RATIO = 0.58      # τ_-1 = 0.58 σ_-1 (von Mises) when not given


def _f(x: float, digits: int = 3) -> str:
    text = f"{x:.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def _rigid_teeth(spec: ValidatedSpec) -> int:
    """z_b (default z_g + U): z_b − z_g a positive multiple of the waves."""
    g = spec.data["gear"]
    z, U, z_b = g["flex_teeth"], g["waves"], g["rigid_teeth"]
    if z_b is None:
        z_b = z + U
        g["rigid_teeth"] = z_b
        spec.assumed.append("gear.rigid_teeth")
    dz = z_b - z
    if dz <= 0 or dz % U:
        raise InputError.at("gear.rigid_teeth", z_b,
                            f"z_b − z_g = {dz} must be a positive multiple of the number of "
                            f"waves U = {U}; use rigid_teeth = {z + U} (or {z + 2 * U})")
    return z_b


def _shift(spec: ValidatedSpec) -> tuple[float, str]:
    """The shift of the flexible wheel and how it was found: given, or by the rule of
    eq. (7) (default) or eq. (8) from the teeth."""
    g = spec.data["gear"]
    if g["shift"] is not None and g["shift_rule"] is not None:
        raise InputError.at("gear.shift_rule", g["shift_rule"],
                            "applies only when gear.shift is not given; remove one of them")
    if g["shift"] is not None:
        return g["shift"], "given"
    if g["shift_rule"] is None:
        g["shift_rule"] = "eq7"
        spec.assumed.append("gear.shift_rule")
    how = "eq. (7)" if g["shift_rule"] == "eq7" else "eq. (8)"
    return R.shift_rule(g["flex_teeth"], g["shift_rule"]), how


_RACK_KEYS = ("root_radius_coef", "pressure_angle", "clearance_coef", "addendum_coef")


def _rack(spec: ValidatedSpec):
    """The basic rack's tooth space; a fillet that does not fit is reported on the rack key
    the spec gives (the fillet radius first), with the values it was found from."""
    rk = spec.data["rack"]
    try:
        return R.rack_space(math.radians(rk["pressure_angle"]), rk["addendum_coef"],
                            rk["clearance_coef"], rk["root_radius_coef"])
    except ValueError as exc:
        key = next((k for k in _RACK_KEYS if f"rack.{k}" not in spec.assumed), _RACK_KEYS[0])
        if key == "root_radius_coef":
            raise InputError.at("rack.root_radius_coef", rk[key],
                                f"too large: {exc}; reduce it") from None
        fillet = ("the default, not in the spec" if "rack.root_radius_coef" in spec.assumed
                  else "rack.root_radius_coef")
        raise InputError.at(f"rack.{key}", rk[key],
                            f"too large for the root fillet: {exc} (ρ_f* from {fillet}); "
                            f"reduce rack.{key} or give a smaller rack.root_radius_coef"
                            ) from None


def _root_circle(spec: ValidatedSpec, x: float, how: str) -> None:
    g, rk = spec.data["gear"], spec.data["rack"]
    if F.root_radius(g["module"], g["flex_teeth"], x, rk["addendum_coef"],
                     rk["clearance_coef"]) > 0:
        return
    if how == "given":
        raise InputError.at("gear.shift", x, "gives a root circle of zero radius; increase it")
    raise InputError.at("gear.flex_teeth", g["flex_teeth"],
                        f"gives with the shift x = {x:.4g} (derived from gear.flex_teeth by "
                        f"{how}) a root circle of zero radius: give gear.shift")


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.wave_gear import CALCULATOR

    g, rk, mat = spec.data["gear"], spec.data["rack"], spec.data["material"]
    m, z, U, H0 = g["module"], g["flex_teeth"], g["waves"], g["rim_thickness"]

    # ------------------------------------------------------------ rules across keys
    problems = Problems()
    z_b = problems.stage(_rigid_teeth, spec)
    shift = problems.stage(_shift, spec)
    w0 = g["radial_deflection"]
    if w0 is None:
        w0 = m
        g["radial_deflection"] = w0
        spec.assumed.append("gear.radial_deflection")
    rack = problems.stage(_rack, spec)
    if shift is not Problems.FAILED:
        problems.stage(_root_circle, spec, *shift)
    problems.raise_all()
    x, how = shift
    r_f = F.root_radius(m, z, x, rk["addendum_coef"], rk["clearance_coef"])

    res = CALCULATOR.new_result(spec)

    # ------------------------------------------------------------ kinematics and geometry
    u_rigid_fixed, u_flex_fixed = F.ratios(z, z_b)
    r_m = r_f + 0.5 * H0
    geo = res.section("geometry", "Kinematics and geometry")
    geo.add("z_b", z_b, "-", "z_b", "teeth of the rigid wheel", S.WAVE)
    geo.add("u_rigid_fixed", u_rigid_fixed, "-", "u_h,g",
            "ratio, rigid wheel fixed (output on the flexible wheel, reversed)", S.WAVE)
    geo.add("u_flex_fixed", u_flex_fixed, "-", "u_h,b",
            "ratio, flexible wheel fixed (output on the rigid wheel)", S.WAVE)
    geo.add("d", m * z, "mm", "d_g", "reference diameter of the flexible wheel", S.WAVE)
    geo.add("x", x, "-", "x_g", f"profile shift of the flexible wheel ({how})", S.TK_EQ7_8)
    geo.add("x_eq7", R.shift_rule(z, "eq7"), "-", "x(7)", "shift by eq. (7), 2.15 + 0.009·z_g",
            S.TK_EQ7_8)
    geo.add("x_eq8", R.shift_rule(z, "eq8"), "-", "x(8)", "shift by eq. (8), 0.022·z_g",
            S.TK_EQ7_8)
    geo.add("d_f", 2.0 * r_f, "mm", "d_f", "root diameter of the flexible wheel", S.WAVE)
    geo.add("r_m", r_m, "mm", "r_m", "mid-surface radius of the rim under the teeth", S.RING)
    geo.add("H0_m", H0 / m, "-", "H0/m", "relative rim thickness", S.TK_REC)
    geo.add("w0", w0, "mm", "w0", "radial deflection at the major axis", S.RING)
    geo.add("w0_m", w0 / m, "-", "w0/m", "relative radial deflection", S.RING)
    geo.add("H0_rec_min", H_REC[0] * m, "mm", "H0,rec,min", "recommended rim thickness, lower",
            S.TK_REC)
    geo.add("H0_rec_max", H_REC[1] * m, "mm", "H0,rec,max", "recommended rim thickness, upper",
            S.TK_REC)

    # ------------------------------------------------------------ stiffness factor
    h_eff = g["effective_tooth_height"]
    nu = H0 / m
    a0 = R.mean_cube(nu, rack, h_eff)
    a0_full = R.mean_cube(nu, rack, FULL)
    K_zh = 1.0 / a0
    K_sigma = mat["K_sigma"]
    K0 = K_zh * K_sigma
    st = res.section("rim", "Toothed rim: stress-increase factor")
    st.add("a0", a0, "-", "a0", "mean of (H0/(H0 + h))³ over a pitch, h <= h_eff", S.TK_EQ4_5)
    st.add("a0_full", a0_full, "-", "a0(2.25m)", "the same with the full tooth height",
           S.TK_EQ4_5)
    st.add("alpha_h", a0 / a0_full, "-", "α_h", "height correction a0(h)/a0(2.25m)", S.TK_EQ6)
    st.add("alpha_x", 1.0, "-", "α_x", "shift correction (eqs. (9)-(10) illegible: not "
           "applied)", S.TK_EQ6)
    st.add("K_zh_full", 1.0 / a0_full, "-", "K_zh(2.25m)", "stiffness factor with full teeth",
           S.TK_EQ4_5)
    st.add("K_zh", K_zh, "-", "K_zh", "stiffness factor 1/a0 (h = effective height)",
           S.TK_HEFF)
    st.add("K_sigma", K_sigma, "-", "K_σ", "effective concentration factor (input)", S.TK_EQ1)
    st.add("K0", K0, "-", "K_0", "stress-increase factor K_zh·K_σ", S.TK_EQ1)
    st.add("K_zh_rec_min", R.stiffness_factor(H_REC[0], rack, h_eff), "-", "K_zh(2.5m)",
           "stiffness factor at the recommended H0 = 2.5·m", S.TK_REC)
    st.add("K_zh_rec_max", R.stiffness_factor(H_REC[1], rack, h_eff), "-", "K_zh(3m)",
           "stiffness factor at the recommended H0 = 3·m", S.TK_REC)

    # ------------------------------------------------------------ stresses, endurance
    E = mat["elastic_modulus"]
    C_gen = spec.data["generator"]["shape_factor"]
    sigma_smooth = F.smooth_ring_stress(E, w0, H0, r_m, C_gen)
    sigma_a = K0 * sigma_smooth
    tau_m1 = mat["tau_m1"]
    tau_from_sigma = tau_m1 is None
    if tau_from_sigma:
        tau_m1 = TAU_RATIO * mat["sigma_m1"]
    load = spec.data["load"]
    tau = None
    if load is not None and g["shell_thickness"] is not None:
        tau = F.shell_shear(load["output_torque"], r_m, g["shell_thickness"])
    if tau is not None:
        tau_a, tau_m = (tau, 0.0) if load["reversing"] else (0.0, tau)
        end = F.endurance(mat["sigma_m1"], sigma_a, tau_m1, tau_a, tau_m, mat["psi_tau"])
    else:
        end = F.endurance(mat["sigma_m1"], sigma_a)
    ss = res.section("strength", "Stresses and endurance")
    ss.add("sigma_smooth", sigma_smooth, "MPa", "σ_0", "bending stress of a smooth rim, "
           "C_gen·E·w0·H0/r_m²", S.RING)
    ss.add("sigma_a", sigma_a, "MPa", "σ_a", "bending stress amplitude in the tooth spaces, "
           "K_0·σ_0", S.TK_EQ1)
    if tau is not None:
        ss.add("tau", tau, "MPa", "τ", "torsional shear in the shell, T2/(2π r_m² δ)", S.RING)
        ss.add("tau_m1", tau_m1, "MPa", "τ_-1", "torsional endurance limit"
               + (" (0.58·σ_-1)" if tau_from_sigma else ""), S.FATIGUE)
        ss.add("s_tau", end.s_tau, "-", "s_τ", "safety factor in torsion", S.FATIGUE)
    ss.add("s_sigma", end.s_sigma, "-", "s_σ", "safety factor in bending, σ_-1/σ_a", S.FATIGUE)
    ss.add("s", end.s, "-", "s", "fatigue safety factor", S.FATIGUE)
    if load is not None and load["input_speed"] is not None:
        n_h = load["input_speed"]
        ss.add("f_load", U * n_h / 60.0, "Hz", "f", "bending cycles per second, U·n_h/60",
               S.WAVE)
        if load["life"] is not None:
            ss.add("N_cycles", U * n_h * 60.0 * load["life"], "-", "N",
                   "bending cycles in the life, U·n_h·60·L_h", S.WAVE)

    # ------------------------------------------------------------ checks
    out = res.checks
    out.append(check(
        "RIM_THICKNESS", nu >= H_MIN, "error",
        f"rim thickness H0 = {_f(H0)} mm is only {_f(nu, 2)}·m: the teeth dominate the rim "
        f"stiffness (K_zh = {K_zh:.2f}); use H0 >= {_f(H_MIN * m)} mm, preferably "
        f"{_f(H_REC[0] * m)}...{_f(H_REC[1] * m)} mm",
        f"H0/m = {_f(nu, 2)} >= {H_MIN}", nu, H_MIN, S.TK_REC))
    if nu >= H_MIN:
        out.append(check(
            "RIM_THICKNESS_LOW", nu >= H_REC[0], "warning",
            f"H0/m = {_f(nu, 2)} < {H_REC[0]}: K_zh rises steeply below 2.5...3 (here "
            f"{K_zh:.3f}); prefer H0 = {_f(H_REC[0] * m)}...{_f(H_REC[1] * m)} mm",
            f"H0/m = {_f(nu, 2)} >= {H_REC[0]}", nu, H_REC[0], S.TK_REC))
    out.append(check(
        "DEFLECTION", W0_RANGE[0] <= w0 / m <= W0_RANGE[1], "warning",
        f"w0/m = {_f(w0 / m, 3)} outside {W0_RANGE[0]}...{W0_RANGE[1]}: too little deflection "
        f"risks ratcheting, too much raises the bending stress; the paper's wheels have w0 = m",
        f"w0/m = {_f(w0 / m, 3)} within {W0_RANGE[0]}...{W0_RANGE[1]}", w0 / m,
        W0_RANGE[1] if w0 / m > W0_RANGE[1] else W0_RANGE[0], S.PRACTICE))
    u = abs(u_rigid_fixed)
    out.append(check(
        "RATIO_RANGE", U_RANGE[0] <= u <= U_RANGE[1], "warning",
        f"ratio {u:.1f} outside the usual single-stage range {U_RANGE[0]:.0f}...{U_RANGE[1]:.0f}: "
        f"{'a thick rim for the diameter, high stress' if u < U_RANGE[0] else 'very thin teeth'}; "
        f"check the tooth numbers",
        f"ratio {u:.1f} within {U_RANGE[0]:.0f}...{U_RANGE[1]:.0f}", u,
        U_RANGE[0] if u < U_RANGE[0] else U_RANGE[1], S.PRACTICE))
    s_req = mat["required_safety"]
    # bending alone: σ_a ∝ w0, so s_σ = s_req needs w0 <= w0·s_σ/s_req or σ_-1 >= s_req·σ_a
    w0_ok = w0 * end.s_sigma / s_req
    thinner = (f"reduce the rim thickness (H0/m = {_f(nu, 2)}) towards {_f(H_REC[0] * m)} mm, "
               if nu > H_REC[0] else "")
    out.append(check(
        "FLEX_ENDURANCE", end.s >= s_req, "error",
        f"fatigue safety factor of the flexible wheel s = {end.s:.2f} < s_min = {_f(s_req, 2)} "
        f"(σ_a = {sigma_a:.0f} MPa against σ_-1 = {_f(mat['sigma_m1'], 1)} MPa): reduce the "
        f"radial deflection to w0 <= {w0_ok:.3f} mm, {thinner}increase the wheel diameter "
        f"(σ ∝ 1/r_m²) or use a steel with σ_-1 >= {s_req * sigma_a:.0f} MPa",
        f"fatigue safety factor s = {end.s:.2f} >= s_min = {_f(s_req, 2)}", end.s, s_req,
        S.FATIGUE))
    if load is not None:
        T2 = load["output_torque"]
        out.append(check(
            "AXIAL_FIXATION", T2 <= T_AXIAL, "warning",
            f"output torque {T2:.0f} N·m: in large wave gears the skewed generator discs "
            f"screw into the flexible wheel and load its fastening axially; fix the generator "
            f"and the flexible wheel axially without play and lubricate the disc contact",
            f"output torque {T2:.0f} N·m <= {T_AXIAL:.0f} N·m (axial forces small)", T2,
            T_AXIAL, S.STRELNIKOV))
    return res
