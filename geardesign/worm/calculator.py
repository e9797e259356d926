"""``kind = "worm"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

This module maps spec keys to the pure functions of :mod:`.geometry`, :mod:`.pair`,
:mod:`.design` and :mod:`.checks`, and their results to report rows.  Rules across keys
raise :class:`~geardesign.core.errors.InputError` naming the key and what is allowed.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.result import Check, Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.materials import worm_wheel
from geardesign.worm import design as D
from geardesign.worm.advice import standard_pair_advice
from geardesign.worm import sources as S
from geardesign.worm.checks import pair_checks
from geardesign.worm.geometry import (
    WormGeometryError,
    WormPairGeometry,
    WormPairInput,
    center_distance,
    pair_geometry,
    shift_for_center_distance,
)
from geardesign.worm.kinematics import estimated_sliding_speed
from geardesign.worm.pair import Analysis, Operation, Options, WheelProps, analyse
from geardesign.worm.spec import GEAR
from geardesign.worm.strength import (
    allowables,
    load_concentration_factor,
    required_center_distance,
    spectrum_factors,
)
from geardesign.worm import tables

X_AGREE = 1e-3       # |x − x(a_w)| accepted when both are given
RATIO_AGREE = 0.04   # |z2/z1 − u|/u accepted when all three are given
SHARE_AGREE = 1e-3   # |Σ t_i/t − 1|
_REQUIRED_IN_CHECK = tuple((k, GEAR.member(k)) for k in ("module", "diameter_factor", "z1", "z2"))


def _fmt(x: float, digits: int = 4) -> str:
    return f"{x:.{digits}f}".rstrip("0").rstrip(".")


# ----------------------------------------------------------------------------- inputs


def wheel_props(spec: ValidatedSpec) -> WheelProps:
    """The wheel material: library values, overridden by the values given."""
    w = spec.data["wheel"]
    name = w["material"]
    if name == "custom":
        if w["group"] is None:
            raise InputError(Problem("wheel.group", 'missing; required with material = "custom": '
                                     'one of "I", "II", "III" (material group)'))
        group, props, v_max = w["group"], {}, worm_wheel.GROUP_V_S_MAX[w["group"]]
        source = "given in the spec (material = \"custom\")"
    else:
        lib = worm_wheel.get(name)
        group = w["group"] or lib.group
        props = {"sigma_B": lib.sigma_B, "sigma_T": lib.sigma_T, "sigma_bu": lib.sigma_bu}
        v_max = lib.v_s_max
        source = f"library row {name}: {lib.source}"
    given = [key for key in ("group", "sigma_B", "sigma_T", "sigma_bu", "v_s_max", "sigma_HP",
                             "sigma_FP") if w[key] is not None]
    for key in ("sigma_B", "sigma_T", "sigma_bu"):
        if w[key] is not None:
            props[key] = w[key]
    if given and name != "custom":
        source += "; given in the spec: " + ", ".join(given)
    need = ("sigma_B", "sigma_T") if group in ("I", "II") else ("sigma_bu",)
    what = {"sigma_B": "tensile", "sigma_T": "yield", "sigma_bu": "bending"}
    problems = [Problem(f"wheel.{k}", f"missing; required for a group {group} wheel "
                        f"({what[k]} strength, MPa)")
                for k in need if props.get(k) is None]
    if problems:
        raise InputError(problems)
    sigma_H0 = spec.data["method"]["sigma_H0"]
    if sigma_H0 is not None and group == "I":
        raise InputError.at("method.sigma_H0", sigma_H0,
                            "applies only to group II and III wheels ([σ]_H = σ_H0 − k·v_s); "
                            "remove it for a group I (tin bronze) wheel")
    return WheelProps(name, group, props.get("sigma_B"), props.get("sigma_T"),
                      props.get("sigma_bu"), w["v_s_max"] if w["v_s_max"] is not None else v_max,
                      w["sigma_HP"], w["sigma_FP"], source, tuple(given))


def operation(spec: ValidatedSpec) -> Operation:
    ld = spec.data["load"]
    spectrum = ((1.0, 1.0),)
    if ld["spectrum"] is not None:
        spectrum = tuple((r["torque_ratio"], r["time_share"]) for r in ld["spectrum"])
        total = sum(s for _, s in spectrum)
        if abs(total - 1.0) > SHARE_AGREE:
            raise InputError(Problem("load.spectrum", f"the time shares add up to "
                                     f"{_fmt(total)}; they must add up to 1"))
    if ld["peak_torque"] is not None and ld["peak_torque"] < ld["torque2"]:
        raise InputError.at("load.peak_torque", ld["peak_torque"],
                            f"smaller than load.torque2 = {_fmt(ld['torque2'])} N·m; the peak "
                            f"must be >= the long-acting torque (or leave it out)")
    return Operation(ld["torque2"], ld["speed1"], ld["peak_torque"], ld["life"], ld["reversing"],
                     spectrum)


def options(spec: ValidatedSpec) -> Options:
    d = spec.data
    fr, me, th, wo = d["friction"], d["method"], d["thermal"], d["worm"]
    if fr["coefficient"] is not None and fr["material_factor"] is not None:
        raise InputError.at("friction.material_factor", fr["material_factor"],
                            "applies only to the table's f'; remove it or remove "
                            "friction.coefficient")
    if th["fan_speed"] is not None and not th["fan"]:
        raise InputError.at("thermal.fan_speed", th["fan_speed"],
                            "applies only with thermal.fan = true; remove it or set fan = true")
    if th["oil_limit"] <= th["ambient"]:
        raise InputError.at("thermal.oil_limit", th["oil_limit"],
                            f"must be above thermal.ambient = {_fmt(th['ambient'])} °C")
    return Options(
        hardened=wo["surface"] == "hardened_ground", elastic_modulus=wo["elastic_modulus"],
        bearing_span=wo["bearing_span"], deflection_limit=wo["deflection_limit"],
        friction_level=fr["level"], friction_coefficient=fr["coefficient"],
        friction_factor=fr["material_factor"], bearing_efficiency=fr["bearing_efficiency"],
        profile_angle=math.radians(d["gear"]["profile_angle"]), cv_law=me["cv_law"],
        K_HL_max=me["K_HL_max"], sigma_H0=me["sigma_H0"], bending_formula=me["bending_formula"],
        dynamic_factor=me["dynamic_factor"], ambient=th["ambient"], oil_limit=th["oil_limit"],
        heat_transfer=th["heat_transfer"], housing_area=th["housing_area"],
        base_share=th["base_share"], fan=th["fan"], fan_speed=th["fan_speed"],
        fan_share=th["fan_share"])


def _pair_input(spec: ValidatedSpec, m: float, q: float, z1: int, z2: int, x: float,
                hardened: bool) -> WormPairInput:
    g, bw = spec.data["gear"], spec.data["basic_worm"]
    if q <= 2.0 * (bw["addendum_coef"] + bw["clearance_coef"]):
        raise InputError.at("gear.diameter_factor", q,
                            f"too small for the basic worm: the root diameter d_f1 = "
                            f"m·(q − 2(h_a* + c*)) must be > 0, so q > "
                            f"{_fmt(2.0 * (bw['addendum_coef'] + bw['clearance_coef']))}")
    return WormPairInput(m, q, z1, z2, x, g["worm_type"], math.radians(g["profile_angle"]),
                         bw["addendum_coef"], bw["clearance_coef"], bw["root_radius_coef"],
                         g["face_width"], g["worm_length"], hardened)


def _check_ratio(g: dict, z1: int, z2: int) -> None:
    u = g["ratio"]
    if u is not None and abs(z2 / z1 - u) / u > RATIO_AGREE:
        raise InputError(Problem("gear.ratio", f"does not match z2/z1 = {z2}/{z1} = "
                                 f"{_fmt(z2 / z1)} (more than 4 % apart); give z1 and z2 or "
                                 f"the ratio, or make them agree", u))


def check_mode_input(spec: ValidatedSpec, hardened: bool) -> tuple[WormPairInput, str]:
    """The pair of a ``mode = "check"`` spec, with the wheel shift resolved."""
    g = spec.data["gear"]
    missing = [(k, f.description, f.rule()) for k, f in _REQUIRED_IN_CHECK if g[k] is None]
    if missing:
        raise InputError([Problem(f"gear.{k}", f'missing; required with mode = "check": '
                                  f"{rule} ({desc})") for k, desc, rule in missing])
    m, q, z1, z2 = g["module"], g["diameter_factor"], g["z1"], g["z2"]
    _check_ratio(g, z1, z2)
    a_w, x = g["center_distance"], g["x"]
    if a_w is None:
        if x is None:
            g["x"] = 0.0
            spec.assumed.append("gear.x")
        return _pair_input(spec, m, q, z1, z2, g["x"], hardened), "given"
    x_a = shift_for_center_distance(a_w, m, q, z2)
    if x is not None:
        if abs(x - x_a) > X_AGREE:
            raise InputError(Problem(
                "gear.x", f"does not match center_distance = {_fmt(a_w)} mm, which needs "
                f"x = {x_a:.4f}; give x or center_distance, not both", x))
        return _pair_input(spec, m, q, z1, z2, x_a, hardened), "from center_distance"
    if abs(x_a) > 1.0:
        lo, hi = center_distance(m, q, z2, -1.0), center_distance(m, q, z2, 1.0)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"needs the wheel shift x = {x_a:.4f}, outside ±1 (GOST 19650-97); with m = "
            f"{_fmt(m)} mm, q = {_fmt(q)}, z2 = {z2} the centre distance must be "
            f"{_fmt(lo)} ... {_fmt(hi)} mm")
    return _pair_input(spec, m, q, z1, z2, x_a, hardened), "from center_distance"


@dataclass(frozen=True)
class DesignResult:
    z1: int
    z2: int
    z_source: str
    q0: float
    q_given: bool
    v_s_est: float
    sigma_HP: float
    K_HL: float | None
    C_v: float | None
    K: float
    K_beta: float
    theta: float
    a_w_req: float
    a_w: float
    rows: str
    m_calc: float
    proposal: D.Proposal


def design_mode_input(spec: ValidatedSpec, w: WheelProps, op: Operation,
                      o: Options) -> tuple[WormPairInput, DesignResult]:
    """Propose a_w, m, q, x for a ``mode = "design"`` spec (:mod:`.design`)."""
    g = spec.data["gear"]
    given = [k for k in ("module", "center_distance", "x") if g[k] is not None]
    if given:
        raise InputError([Problem(f"gear.{k}", 'is proposed by mode = "design"; remove it, or '
                                  'use mode = "check" to check a given pair', g[k])
                          for k in given])
    z1, z2, u = g["z1"], g["z2"], g["ratio"]
    if z1 is not None and z2 is not None:
        _check_ratio(g, z1, z2)
        how = "given"
    elif u is not None and z2 is None:
        z1 = z1 if z1 is not None else D.starts_for_ratio(u)
        z2 = round(u * z1)
        how = "from the ratio"
        if not 10 <= z2 <= 400:
            raise InputError(Problem("gear.ratio", f"gives z2 = round(u·z1) = {z2}, outside "
                                     f"10 ... 400; choose another ratio or z1", u))
    else:
        raise InputError(Problem("gear.ratio", 'missing; with mode = "design" give the ratio '
                                 "(z1 optional) or both z1 and z2"))
    q_given = g["diameter_factor"] is not None
    q0 = g["diameter_factor"] if q_given else D.default_q(z2)
    v_s = estimated_sliding_speed(op.n1, op.T2)
    sf = spectrum_factors(list(op.spectrum))
    N = 60.0 * op.n1 / (z2 / z1) * op.life
    al = allowables(w.group, o.hardened, v_s, sf.K_HE * N, sf.K_FE * N, op.reversing,
                    w.sigma_B, w.sigma_T, w.sigma_bu, o.cv_law, o.K_HL_max, o.sigma_H0)
    sigma_HP = w.sigma_HP if w.sigma_HP is not None else al.sigma_HP
    if sigma_HP <= 0.0:
        raise InputError.at(
            "wheel.material", w.name,
            f"[σ]_H = {sigma_HP:.1f} MPa at the estimated sliding speed {v_s:.2f} m/s: a group "
            f"{w.group} wheel cannot carry this drive; choose a group I bronze")
    theta = tables.theta(q0, z1)
    K_beta = load_concentration_factor(z2, theta, sf.X)
    K = K_beta * (o.dynamic_factor if o.dynamic_factor is not None else 1.0)
    a_req = required_center_distance(op.T2, K, q0, z2, sigma_HP)
    rows = (spec.data["design"] or {}).get("center_distance_rows", "first")
    a_w = D.round_up_center_distance(a_req, rows)
    if a_w is None:
        raise InputError.at("load.torque2", op.T2,
                            f"needs a centre distance of {a_req:.1f} mm ([σ]_H = "
                            f"{sigma_HP:.1f} MPa at the estimated sliding speed {v_s:.2f} m/s), "
                            f"beyond the GOST 2144-76 series (500 mm); use a stronger wheel "
                            f"material or split the drive")
    prop = D.choose_module(a_w, z2, q0, q_given)
    p = _pair_input(spec, prop.m, prop.q, z1, z2, prop.x, o.hardened)
    return p, DesignResult(z1, z2, how, q0, q_given, v_s, sigma_HP, al.K_HL, al.C_v, K, K_beta,
                           theta, a_req, a_w, rows, 2.0 * a_w / (q0 + z2), prop)


def _solve(p: WormPairInput) -> WormPairGeometry:
    try:
        return pair_geometry(p)
    except WormGeometryError as exc:  # pragma: no cover - guarded by the input rules
        raise InputError(Problem("gear", str(exc))) from None


# ----------------------------------------------------------------------------- rows


def add_rows(res: Result, a: Analysis, w: WheelProps, how: str) -> None:
    g, p = a.g, a.g.inp
    sec = res.section("geometry", "Geometry")
    sec.add("u", g.u, "-", "u", "ratio z2/z1", S.G19650)
    sec.add("m", p.m, "mm", "m", "axial module", S.G19650)
    sec.add("q", p.q, "-", "q", "diameter factor", S.G19650)
    sec.add("z1", p.z1, "-", "z1", "worm starts", S.G19650)
    sec.add("z2", p.z2, "-", "z2", "wheel teeth", S.G19650)
    sec.add("x", p.x, "-", "x", "wheel shift coefficient", S.G19650)
    sec.add("shift_source", how, None, "", "how the shift was obtained", S.G19650)
    sec.add("a_w", g.a_w, "mm", "a_w", "centre distance", S.G19650)
    sec.add("d1", g.d1, "mm", "d1", "reference diameter, worm", S.G19650)
    sec.add("d_w1", g.d_w1, "mm", "d_w1", "working diameter, worm", S.G19650)
    sec.add("d_a1", g.d_a1, "mm", "d_a1", "tip diameter, worm", S.G19650)
    sec.add("d_f1", g.d_f1, "mm", "d_f1", "root diameter, worm", S.G19650)
    sec.add("gamma", g.gamma, "rad", "γ", "lead angle on d1", S.G19650)
    sec.add("gamma_w", g.gamma_w, "rad", "γ_w", "lead angle on d_w1", S.G19650)
    sec.add("p_x", g.p_x, "mm", "p_x", "axial pitch", S.G19650)
    sec.add("p_z1", g.p_z1, "mm", "p_z1", "lead of the worm thread", S.G19650)
    sec.add("alpha_x", g.alpha_x, "rad", "α_x", "axial profile angle", S.G19036)
    sec.add("alpha_n", g.alpha_n, "rad", "α_n", "normal profile angle", S.G19036)
    sec.add("m_n", g.m_n, "mm", "m_n", "normal module m·cos γ", S.G19650)
    if g.d_b1 is not None:
        sec.add("gamma_b", g.gamma_b, "rad", "γ_b", "base lead angle (ZI)", S.G19650)
        sec.add("d_b1", g.d_b1, "mm", "d_b1", "base diameter (ZI)", S.G19650)
    sec.add("d2", g.d2, "mm", "d2", "reference diameter, wheel", S.G19650)
    sec.add("d_a2", g.d_a2, "mm", "d_a2", "tip (throat) diameter, wheel", S.G19650)
    sec.add("d_f2", g.d_f2, "mm", "d_f2", "root diameter, wheel", S.G19650)
    sec.add("d_aM2", g.d_aM2_max, "mm", "d_aM2", "largest outside diameter of the wheel (max)",
            S.G19650)
    sec.add("R_throat", g.R_throat, "mm", "R", "throat radius of the wheel rim 0.5·d1 − h_a*·m",
            S.G19650)
    sec.add("b2", g.b2, "mm", "b2", "wheel face width" + ("" if g.b2_given else
                                                          " (largest allowed)"), S.G19650)
    sec.add("b2_max", g.b2_max, "mm", "b2,max", "largest face width", S.G19650)
    sec.add("wrap_angle", g.wrap_angle, "rad", "2δ", "conditional wrap angle", S.G19650)
    sec.add("b1", g.b1, "mm", "b1", "worm thread length" + ("" if g.b1_given else
                                                            " (least required)"), S.G19650)
    sec.add("b1_min", g.b1_min, "mm", "b1,min", "least worm thread length", S.DUNAEV)
    sec.add("c", g.c_radial, "mm", "c", "radial clearance c*·m", S.G19036)
    sec.add("eps_alpha", g.eps_alpha, "-", "ε_α", "contact ratio in the wheel mid-plane "
            "(approximate)", S.TEXTBOOK)
    sec.add("x_min", g.x_min, "-", "x_min", "least shift without undercut in the mid-plane",
            S.G19650)

    t = res.section("control", "Thread thickness and control data (GOST 2.406-76)")
    t.add("s_x1", g.s_x1, "mm", "s_x1", "axial thread thickness on d1", S.G19650)
    t.add("s_n1", g.s_n1, "mm", "s_n1", "normal thread thickness on d1 (chordal thickness)",
          S.G2406)
    t.add("h_a1_chord", g.h_a1_chord, "mm", "h̄_a1", "measuring height of the chordal "
          "thickness", S.G2406)
    t.add("s2", g.s2, "mm", "s2", "wheel tooth thickness on d2", S.G19650)
    t.add("hand", res.inputs["gear"]["hand"], None, "", "hand of the thread",
          S.G2406)
    t.add("worm_type", p.worm_type, None, "", "worm type (GOST 18498-89)", S.G2406)

    k = res.section("kinematics", "Kinematics, friction and efficiency")
    k.add("n2", a.s.n2, "min^-1", "n2", "wheel speed", S.MECHANICS)
    k.add("v1", a.s.v1, "m/s", "v1", "worm peripheral speed on d_w1", S.MECHANICS)
    k.add("v2", a.s.v2, "m/s", "v2", "wheel peripheral speed on d2", S.MECHANICS)
    k.add("v_s", a.s.v_s, "m/s", "v_s", "sliding speed v1/cos γ_w", S.MECHANICS)
    k.add("f_table", a.fr.f_table, "-", "f'_tab", "reduced friction coefficient from the "
          "table (tin bronze)" + (" (not used: f' given)" if a.fr.given else ""), S.FRICTION)
    k.add("k_f", a.fr.material_factor, "-", "k_f", "material factor on the table's f'",
          S.FRICTION)
    k.add("f", a.fr.f, "-", "f'", "reduced friction coefficient used", S.FRICTION)
    k.add("rho", a.fr.rho, "rad", "ρ'", "reduced friction angle", S.FRICTION)
    k.add("eta_m", a.eta_m, "-", "η_m", "mesh efficiency, worm driving", S.TEXTBOOK)
    k.add("eta", a.eta, "-", "η", "overall efficiency (bearings and churning included)",
          S.TEXTBOOK)
    k.add("eta_reverse", a.eta_reverse, "-", "η'", "mesh efficiency, wheel driving "
          "(0 if self-locking)", S.TEXTBOOK)
    k.add("self_locking", a.self_locking, None, "", "self-locking (γ_w <= ρ')", S.TEXTBOOK)

    f = res.section("forces", "Torques, power and forces")
    f.add("T1", a.ld.T1, "N·m", "T1", "worm torque", S.MECHANICS)
    f.add("T2", a.ld.T2, "N·m", "T2", "wheel torque", S.MECHANICS)
    f.add("P1", a.ld.P1, "kW", "P1", "input power", S.MECHANICS)
    f.add("P2", a.ld.P2, "kW", "P2", "output power", S.MECHANICS)
    f.add("P_loss", a.ld.P_loss, "kW", "P_loss", "power lost", S.MECHANICS)
    f.add("F_t1", a.ld.F_t1, "N", "F_t1 = F_a2", "tangential force on the worm = axial force "
          "on the wheel", S.TEXTBOOK)
    f.add("F_t2", a.ld.F_t2, "N", "F_t2 = F_a1", "tangential force on the wheel = axial force "
          "on the worm", S.TEXTBOOK)
    f.add("F_r", a.ld.F_r, "N", "F_r", "radial force F_t2·tan α", S.TEXTBOOK)

    st = res.section("strength", "Strength of the wheel")
    lib_src = "library" if w.name != "custom" else "spec"
    st.add("material", w.name, None, "", "wheel material", lib_src)
    st.add("material_source", w.source, None, "src", "data used, wheel material", lib_src)
    st.add("group", w.group, None, "", "material group", S.TEXTBOOK)
    for key, sym, name in (("sigma_B", "σ_B", "tensile strength"),
                           ("sigma_T", "σ_T", "yield strength"),
                           ("sigma_bu", "σ_bu", "bending strength")):
        if getattr(w, key) is not None:
            st.add(key, getattr(w, key), "MPa", sym, name,
                   "spec" if key in w.given else lib_src)
    st.add("v_s_max", w.v_s_max, "m/s", "v_s,max", "highest sliding speed of the material",
           "spec" if "v_s_max" in w.given else lib_src)
    st.add("theta", a.theta, "-", "θ", "worm deflection coefficient", S.CHERNAVSKY)
    st.add("X", a.sf.X, "-", "X", "load-regime factor", S.CHERNAVSKY)
    st.add("K_beta", a.K_beta, "-", "K_β", "load concentration factor", S.CHERNAVSKY)
    st.add("K_v", a.K_v, "-", "K_v", "dynamic factor", S.TEXTBOOK)
    st.add("K", a.K, "-", "K", "load factor K_β·K_v", S.TEXTBOOK)
    st.add("N", a.N, "-", "N", "load cycles of a wheel tooth 60·n2·L_h", S.TEXTBOOK)
    st.add("N_HE", a.N_HE, "-", "N_HE", "equivalent cycles, contact", S.TEXTBOOK)
    st.add("N_FE", a.N_FE, "-", "N_FE", "equivalent cycles, bending", S.TEXTBOOK)
    if a.allow.K_HL is not None:
        st.add("K_HL", a.allow.K_HL, "-", "K_HL", "life factor, contact", S.TEXTBOOK)
        st.add("C_v", a.allow.C_v, "-", "C_v", "sliding-speed factor", S.DUNAEV)
    if a.allow.sigma_H0 is not None:
        st.add("sigma_H0", a.allow.sigma_H0, "MPa", "σ_H0", "constant of [σ]_H = σ_H0 − k·v_s",
               S.TEXTBOOK)
    st.add("sigma_HP", a.sigma_HP, "MPa", "[σ]_H", "allowable contact stress"
           + (" (given)" if w.sigma_HP is not None else ""), S.TEXTBOOK)
    st.add("sigma_H", a.sigma_H, "MPa", "σ_H", "contact stress", S.CHERNAVSKY)
    st.add("a_w_req", a.a_w_req, "mm", "a_w,req", "least centre distance for σ_H = [σ]_H",
           S.CHERNAVSKY)
    st.add("T_peak", a.T_peak, "N·m", "T_peak", "peak torque on the wheel", S.TEXTBOOK)
    st.add("sigma_Hmax", a.sigma_Hmax, "MPa", "σ_Hmax", "peak contact stress", S.TEXTBOOK)
    st.add("sigma_HP_max", a.allow.sigma_HP_max, "MPa", "[σ]_Hmax", "allowable peak contact "
           "stress", S.TEXTBOOK)
    st.add("z_v2", a.z_v2, "-", "z_v2", "virtual number of wheel teeth z2/cos³γ_w", S.DUNAEV)
    st.add("Y_F2", a.Y_F, "-", "Y_F2", "tooth form factor", S.DUNAEV)
    st.add("K_FL", a.allow.K_FL, "-", "K_FL", "life factor, bending", S.TEXTBOOK)
    st.add("sigma_FP", a.sigma_FP, "MPa", "[σ]_F", "allowable bending stress"
           + (" (given)" if w.sigma_FP is not None else ""), S.TEXTBOOK)
    st.add("sigma_F", a.sigma_F, "MPa", "σ_F", "bending stress", S.DUNAEV)
    st.add("sigma_Fmax", a.sigma_Fmax, "MPa", "σ_Fmax", "peak bending stress", S.TEXTBOOK)
    st.add("sigma_FP_max", a.allow.sigma_FP_max, "MPa", "[σ]_Fmax", "allowable peak bending "
           "stress", S.TEXTBOOK)
    st.add("S_H", a.sigma_HP / a.sigma_H, "-", "[σ]_H/σ_H", "contact reserve", S.TEXTBOOK)
    st.add("S_F", a.sigma_FP / a.sigma_F, "-", "[σ]_F/σ_F", "bending reserve", S.TEXTBOOK)

    sf = res.section("stiffness", "Stiffness of the worm")
    sf.add("span", a.span, "mm", "l", "bearing span of the worm", S.DUNAEV)
    sf.add("I_eq", a.I_eq, "mm^4", "I_eq", "equivalent second moment of area", S.DUNAEV)
    sf.add("f_worm", a.f, "mm", "f", "deflection of the worm at the mesh", S.DUNAEV)
    sf.add("f_limit", a.f_lim, "mm", "f_lim", "allowed deflection", S.DUNAEV)

    th = res.section("thermal", "Thermal balance")
    th.add("heat", a.th.heat, "W", "Φ", "heat generated 1000·(1 − η)·P1", S.THERMAL)
    th.add("area", a.th.area, "m²", "A", "cooling surface of the housing", S.THERMAL)
    if a.th.K_T_fan is not None:
        th.add("K_T_fan", a.th.K_T_fan, "W/(m²·K)", "K_T,fan", "heat-transfer coefficient of "
               "the fan-blown surface", S.THERMAL)
    th.add("t_oil", a.th.t_oil, "°C", "t_oil", "steady oil temperature", S.THERMAL)


def add_design_rows(res: Result, d: DesignResult) -> None:
    sec = res.section("design", "Design proposal")
    sec.add("z_source", d.z_source, None, "", "how z1 and z2 were obtained", S.DUNAEV)
    sec.add("v_s_est", d.v_s_est, "m/s", "v_s,est", "estimated sliding speed "
            "4.5·10⁻⁴·n1·T2^(1/3)", S.DUNAEV)
    if d.K_HL is not None:
        sec.add("K_HL_design", d.K_HL, "-", "K_HL", "life factor used for the design",
                S.TEXTBOOK)
        sec.add("C_v_design", d.C_v, "-", "C_v", "sliding-speed factor at v_s,est", S.DUNAEV)
    sec.add("sigma_HP_design", d.sigma_HP, "MPa", "[σ]_H", "allowable contact stress at "
            "v_s,est", S.TEXTBOOK)
    sec.add("theta_design", d.theta, "-", "θ", "worm deflection coefficient", S.CHERNAVSKY)
    sec.add("K_design", d.K, "-", "K", "load factor used for the design (K_v = 1 unless "
            "given)", S.TEXTBOOK)
    sec.add("q_design", d.q0, "-", "q", "diameter factor used" + ("" if d.q_given else
                                                                    " (smallest first-row q "
                                                                    ">= 0.212·z2)"), S.DUNAEV)
    sec.add("a_w_required", d.a_w_req, "mm", "a_w,req", "required centre distance",
            S.CHERNAVSKY)
    sec.add("a_w_series", d.rows, None, "", "GOST 2144-76 rows used", S.G2144)
    sec.add("a_w_proposed", d.a_w, "mm", "a_w", "proposed standard centre distance", S.G2144)
    sec.add("m_calc", d.m_calc, "mm", "m_calc", "module 2·a_w/(q + z2) before rounding", S.G2144)
    sec.add("standard", d.proposal.standard, None, "", "standard m and q with |x| <= 1 found",
            S.G19672)


def _check_mode_inputs(spec: ValidatedSpec, o) -> None:
    """The pair of the check mode and how its shift was found (no [design] keys); ``None``
    when the options could not be read (their problem is reported)."""
    given = [k for k in spec.data["design"] or {} if f"design.{k}" not in spec.assumed]
    if given:
        raise InputError.at(f"design.{given[0]}", spec.data["design"][given[0]],
                            'applies only with mode = "design"; remove it or set mode = '
                            '"design"')
    return check_mode_input(spec, o.hardened) if o is not Problems.FAILED else None


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.worm import CALCULATOR

    problems = Problems()
    w, op, o = (problems.stage(f, spec) for f in (wheel_props, operation, options))
    if spec.data["mode"] == "design":
        problems.raise_all()    # the design needs the wheel, the duty and the options
        p, dres = design_mode_input(spec, w, op, o)
        how = "design"
    else:
        checked = problems.stage(_check_mode_inputs, spec, o)
        problems.raise_all()
        p, how = checked
        dres = None
    g = _solve(p)
    a = analyse(g, op, w, o)
    res = CALCULATOR.new_result(spec)
    if dres is not None:
        add_design_rows(res, dres)
    add_rows(res, a, w, how)
    locking = spec.data["load"]["self_locking"]
    checks = pair_checks(a, w, o, locking)
    if dres is None:
        x_given = spec.data["gear"]["x"] is not None and "gear.x" not in spec.assumed
        advice = standard_pair_advice(a, checks, op, w, o, locking, x_given)
        if advice is not None:
            checks = pair_checks(a, w, o, locking, advice)
    if dres is not None:
        checks.insert(0, _design_check(dres))
    res.checks.extend(checks)
    res.checks.extend(_units_checks(a, spec))
    return res


def _units_checks(a, spec: ValidatedSpec) -> list[Check]:
    """``UNITS_LOAD`` when the wheel carries less than 1 % of its contact capacity,
    (σ_H/[σ]_H)² (σ_H ∝ √T2, [Dunaev]), as a torque typed in N·m where kN·m was meant
    does (:mod:`geardesign.core.units_guard`)."""
    from geardesign.core.units_guard import given, light_load

    if not a.sigma_HP > 0.0:
        return []
    fraction = (a.sigma_H / a.sigma_HP) ** 2
    what = (f"the wheel carries {100 * fraction:.2g} % of its contact capacity (σ_H = "
            f"{a.sigma_H:.3g} MPa against [σ]_H = {a.sigma_HP:.0f} MPa)")
    return light_load("UNITS_LOAD", fraction, what,
                      given(spec.data["load"], {"torque2": "N·m"}, "load"), S.TEXTBOOK)


def _design_check(d: DesignResult) -> Check:
    p = d.proposal
    return check(
        "DESIGN_STANDARD", p.standard, "warning",
        f"no GOST 19672-74 module and diameter factor give |x| <= 1 at a_w = {_fmt(d.a_w)} mm "
        f"with q = {_fmt(d.q0)}; the module m = {_fmt(p.m)} mm is not standard: leave "
        f"gear.diameter_factor out so that q may change"
        + (', or set design.center_distance_rows = "both"' if d.rows == "first" else ""),
        f"a_w = {_fmt(d.a_w)} mm (required {d.a_w_req:.1f} mm) with standard m = {_fmt(p.m)} "
        f"mm, q = {_fmt(p.q)}, x = {p.x:.4f}", d.a_w, d.a_w_req, S.G2144)
