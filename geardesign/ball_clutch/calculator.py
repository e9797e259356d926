"""``kind = "ball_clutch"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

This module maps spec keys to the pure functions of :mod:`.clutch`, :mod:`.spring` and
:mod:`.contact` (mm and min⁻¹ in the spec, SI inside), and their results to report rows and
checks.
"""

from __future__ import annotations

import math

from geardesign.ball_clutch import clutch as C
from geardesign.ball_clutch import sources as S
from geardesign.ball_clutch import spring as SP
from geardesign.ball_clutch.contact import ball_contact, effective_modulus
from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.materials import spring_steel

RPM = math.pi / 30.0
MARGIN_WARN = 1.1        # T_lim,min >= 1.1·T (design practice)
SPEED_SENSITIVITY = 0.10  # |T_lim(n)/T_lim(0) − 1| <= 10 % (design practice)
INDEX_RANGE = (4.0, 12.0)  # usual spring index D/d (design practice)
SPEED_POINTS = 41


def _f(x: float, digits: int = 3) -> str:
    text = f"{x:.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


@dataclass(frozen=True)
class SpringData:
    c: float                  # N/mm
    geometric: bool
    d: float | None = None
    D: float | None = None
    n_a: float | None = None
    G: float | None = None
    R_m: float | None = None
    share: float | None = None
    material: str | None = None


def _spring(spec: ValidatedSpec) -> SpringData:
    """The spring's rate and data; rules across the [spring] keys raise InputError."""
    sp = spec.data["spring"]
    geo_keys = ("wire_diameter", "coil_diameter", "active_coils")
    given = [k for k in geo_keys if sp[k] is not None]
    if sp["rate"] is not None:
        if given:
            raise InputError(Problem(
                "spring.rate", "give either the rate or the wire and coil data "
                f"(spring.{', spring.'.join(given)}), not both", sp["rate"]))
        problems = Problems()
        for k in ("free_length", "material", "shear_modulus", "tensile_strength",
                  "allowable_share"):
            if sp[k] is not None:
                problems.at("spring." + k, sp[k], "is used only with the wire data "
                            "(spring.wire_diameter, spring.coil_diameter, spring.active_coils); "
                            "give them instead of spring.rate or remove it")
        problems.raise_all()
        return SpringData(c=sp["rate"], geometric=False)
    if len(given) != len(geo_keys):
        missing = [k for k in geo_keys if sp[k] is None]
        raise InputError(Problem(
            "spring." + missing[0], "missing; the spring needs spring.rate or all of "
            "spring.wire_diameter, spring.coil_diameter and spring.active_coils"))
    d, D, n_a = sp["wire_diameter"], sp["coil_diameter"], sp["active_coils"]
    problems = Problems()
    if D <= 2.0 * d:
        problems.at("spring.coil_diameter", D,
                    f"the mean coil diameter must exceed twice the wire diameter "
                    f"(2·{_f(d)} = {_f(2 * d)} mm): the coils cannot be wound")
    mat = spring_steel.get(sp["material"]) if sp["material"] is not None else None
    G = sp["shear_modulus"] if sp["shear_modulus"] is not None else (mat.G if mat else None)
    if G is None:
        problems.add(Problem(
            "spring.material", "missing; the wire data need spring.material (one of "
            + ", ".join(f'"{n}"' for n in spring_steel.names())
            + ") or spring.shear_modulus"))
    problems.raise_all()
    R_m = sp["tensile_strength"] if sp["tensile_strength"] is not None else (
        mat.tensile_strength(d) if mat else None)
    share = sp["allowable_share"] if sp["allowable_share"] is not None else (
        mat.allowable if mat else None)
    return SpringData(c=SP.rate(G, d, D, n_a), geometric=True, d=d, D=D, n_a=n_a, G=G,
                      R_m=R_m, share=share, material=sp["material"])


def _socket(sa: dict) -> None:
    """The socket depth and radius against the ball (each reported)."""
    d_b, h_s = sa["ball_diameter"], sa["socket_depth"]
    problems = Problems()
    if h_s >= 0.5 * d_b:
        problems.at("safety.socket_depth", h_s,
                    f"must be less than the ball radius d_b/2 = {_f(0.5 * d_b)} mm (the ball "
                    "must stay guided while it leaves the socket)")
    if sa["socket_radius"] is not None and sa["socket_radius"] <= 0.5 * d_b:
        problems.at("safety.socket_radius", sa["socket_radius"],
                    f"must be larger than the ball radius d_b/2 = {_f(0.5 * d_b)} mm (a "
                    "spherical socket holds the ball from outside); omit it for a conical "
                    "socket")
    problems.raise_all()


def _balls_fit(sa: dict) -> None:
    z3, d_b, d5 = sa["balls"], sa["ball_diameter"], sa["ball_circle"]
    pitch = math.pi * d5 / z3
    if pitch <= d_b:
        raise InputError.at("safety.balls", z3,
                            f"{z3} balls of {_f(d_b)} mm do not fit on the {_f(d5)} mm circle "
                            f"(pitch {_f(pitch)} mm); use safety.balls <= "
                            f"{max(1, math.ceil(math.pi * d5 / d_b) - 1)} or a larger "
                            "safety.ball_circle")


def _preload(sa: dict, sp: dict) -> None:
    """The spring preload is given, or designed from safety.limit_torque: one of them."""
    design = sa["limit_torque"] is not None
    if design and sp["preload"] is not None:
        raise InputError(Problem(
            "spring.preload", "give either spring.preload or safety.limit_torque (design "
            "mode: the preload follows), not both", sp["preload"]))
    if not design and sp["preload"] is None:
        raise InputError(Problem(
            "spring.preload", "missing; give spring.preload (mm), or safety.limit_torque to "
            "have the preload designed"))


def _not_self_locking(spec: ValidatedSpec) -> None:
    """Design mode: cot(α2 + ρ) <= f_g means no spring force releases at the target torque
    (the formula of the required force leaves its domain and gives a force <= 0).  The
    frictions named are the spec's, or its defaults (said so)."""
    sa = spec.data["safety"]
    f, f_g = sa["friction"], sa["guide_friction"]
    alpha_free = C.self_locking_angle(f, f_g)
    if math.radians(sa["socket_angle"]) < alpha_free:
        return

    def said(key: str, v: float) -> str:
        return f"{_f(v)}" + (" (the default, not in the spec)"
                             if f"safety.{key}" in spec.assumed else "")

    raise InputError.at(
        "safety.socket_angle", sa["socket_angle"],
        f"must be below {math.degrees(alpha_free):.1f}° with friction f = "
        f"{said('friction', f)} and guide friction f_g = {said('guide_friction', f_g)}: at a "
        "larger angle the balls self-lock (cot(α2 + ρ) <= f_g) and no spring force gives "
        "safety.limit_torque")


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.ball_clutch import CALCULATOR

    op, sa, sp = spec.data["operation"], spec.data["safety"], spec.data["spring"]
    # ------------------------------------------------------------ rules across keys
    design = sa["limit_torque"] is not None
    problems = Problems()
    problems.stage(_socket, sa)
    problems.stage(_balls_fit, sa)
    problems.stage(_preload, sa, sp)
    if design:
        problems.stage(_not_self_locking, spec)
    sd = problems.stage(_spring, spec)
    problems.raise_all()

    T, n = op["torque"], op["speed"]
    w = n * RPM
    z3, d_b, d5 = sa["balls"], sa["ball_diameter"], sa["ball_circle"]
    alpha = math.radians(sa["socket_angle"])
    h_s = sa["socket_depth"]
    f, f_g, spread = sa["friction"], sa["guide_friction"], sa["friction_spread"]

    # ------------------------------------------------------------ safety part
    r0 = 0.5 * d5 / 1000.0
    m = C.ball_mass(d_b / 1000.0, sa["ball_density"]) + sa["extra_mass"]
    F_c = C.centrifugal_force(m, r0, w)
    if design:
        F_pre = C.required_spring_force(sa["limit_torque"], F_c, z3, r0, alpha, f, f_g)
        y0 = F_pre / sd.c
    else:
        y0 = sp["preload"]
        F_pre = sd.c * y0
    band = C.limit_band(F_pre, F_c, z3, r0, alpha, f, f_g, spread)
    band0 = C.limit_band(F_pre, 0.0, z3, r0, alpha, f, f_g, spread)
    T_frictionless = C.limit_torque(F_pre, F_c, z3, r0, alpha)
    alpha_lock = C.self_locking_angle(f * (1 + spread), f_g * (1 + spread))
    w_rel = C.release_speed(F_pre, m, r0)

    res = CALCULATOR.new_result(spec)
    if design:
        ds = res.section("design", "Design from the target limit torque")
        ds.add("F_pre_required", F_pre, "N", "c·y0", "spring force per ball for the target",
               S.FRICTION)
        ds.add("y0_required", y0, "mm", "y0", "spring preload deflection to set", S.SEED_EQ7)

    sec = res.section("safety", "Safety (torque-limiting) part")
    sec.add("r0", r0 * 1000.0, "mm", "r0", "radius of the ball centres", S.SEED_EQ15)
    sec.add("m", m, "kg", "m", "mass moving with one ball", S.CENTRIFUGAL)
    sec.add("omega", w, "rad/s", "ω", "clutch angular speed", S.CENTRIFUGAL)
    sec.add("c", sd.c, "N/mm", "c", "spring rate", S.SPRING)
    sec.add("y0", y0, "mm", "y0", "spring preload deflection", S.SEED_EQ7)
    sec.add("F_pre", F_pre, "N", "c·y0", "spring force on one ball, engaged", S.SEED_EQ7)
    sec.add("F_c", F_c, "N", "m·r0·ω²", "centrifugal force of one ball at speed", S.CENTRIFUGAL)
    sec.add("rho", math.atan(f), "rad", "ρ", "friction angle at the socket", S.FRICTION)
    sec.add("alpha_self_locking", alpha_lock, "rad", "α2,lock",
            "socket angle at which the clutch self-locks (high friction)", S.FRICTION)
    sec.add("T_lim_frictionless", T_frictionless, "N·m", "T_lim,0",
            "limit torque without friction, z3·r0·tan α2·(c·y0 − m·r0·ω²)", S.SEED_EQ15)
    sec.add("T_lim", band.nominal, "N·m", "T_lim", "limit torque at speed, nominal friction",
            S.FRICTION)
    sec.add("T_lim_min", band.low, "N·m", "T_lim,min", "limit torque at speed, low friction",
            S.FRICTION)
    sec.add("T_lim_max", band.high, "N·m", "T_lim,max", "limit torque at speed, high friction",
            S.FRICTION)
    sec.add("T_lim_static", band0.nominal, "N·m", "T_lim(0)", "limit torque at rest, nominal "
            "friction", S.FRICTION)
    sec.add("T_lim_static_min", band0.low, "N·m", "T_lim,min(0)", "limit torque at rest, low "
            "friction", S.FRICTION)
    sec.add("T_lim_static_max", band0.high, "N·m", "T_lim,max(0)", "limit torque at rest, "
            "high friction", S.FRICTION)
    sec.add("ratio", band.nominal / T, "-", "T_lim/T", "limit over rated torque "
            "(1.25...1.5 recommended)", S.PRACTICE)
    sec.add("n_release", w_rel / RPM, "min^-1", "n_c",
            "speed at which the balls leave by centrifugal force alone", S.CENTRIFUGAL)
    if spec.data["inertia"] is not None:
        I1, I3 = spec.data["inertia"]["drive"], spec.data["inertia"]["driven"]
        k_dyn = C.inertia_factor(z3, m, r0, I1, I3)
        sec.add("k_dyn", k_dyn, "-", "k_dyn", "(z3·m·r0² + I1 + I3)/(z3·m·r0² + I3)",
                S.SEED_EQ15)
        sec.add("T_lim_dynamic", k_dyn * band.nominal, "N·m", "T_p",
                "drive torque that releases with a free driven inertia", S.SEED_EQ15)

    # speed dependence (centrifugal term), nominal friction
    n_top = min(1.5 * n, w_rel / RPM) if n > 0 else w_rel / RPM
    speeds = [n_top * i / (SPEED_POINTS - 1) for i in range(SPEED_POINTS)]
    curve = [C.limit_torque(F_pre, C.centrifugal_force(m, r0, s * RPM), z3, r0, alpha, f, f_g)
             for s in speeds]
    sp_sec = res.section("speed", "Limit torque over speed (nominal friction)")
    sp_sec.add("n_grid", speeds, "min^-1", "n", "clutch speed", S.CENTRIFUGAL)
    sp_sec.add("T_lim_curve", curve, "N·m", "T_lim(n)", "limit torque", S.CENTRIFUGAL)

    # ------------------------------------------------------------ forces, contact
    F_t1_rated = F_t1_max = None
    fw = spec.data["freewheel"]
    fo = res.section("forces", "Ball forces")
    _, F_t2 = C.ball_forces(T, 1, 1.0, z3, 2.0 * r0)
    fo.add("F_t2", F_t2, "N", "F_t2", "circumferential force on one safety ball at the rated "
           "torque", S.SEED_EQ1_4)
    if fw is not None:
        d4 = fw["ball_circle"] / 1000.0
        F_t1_rated, _ = C.ball_forces(T, fw["balls"], d4, z3, 2.0 * r0)
        top = band0.high if math.isfinite(band0.high) else math.nan
        F_t1_max, _ = C.ball_forces(top, fw["balls"], d4, z3, 2.0 * r0)
        fo.add("F_t1", F_t1_rated, "N", "F_t1", "circumferential force on one freewheel ball at "
               "the rated torque", S.SEED_EQ1_4)
        fo.add("F_t1_max", F_t1_max, "N", "F_t1,max", "the same at the highest limit torque "
               "(the freewheel must carry it)", S.SEED_EQ1_4)
    T_top = band0.high
    F_n = T_top / (z3 * r0) / math.sin(alpha) if math.isfinite(T_top) else math.nan
    E_star = effective_modulus(sa["elastic_modulus"], sa["poisson"], sa["elastic_modulus"],
                               sa["poisson"])
    if math.isfinite(F_n) and F_n > 0:
        p0, a_c = ball_contact(F_n, d_b, sa["socket_radius"], E_star)
    else:
        p0, a_c = math.nan, math.nan
    fo.add("F_n", F_n, "N", "F_n", "normal force ball/socket at the highest limit torque",
           S.SEED_EQ15)
    fo.add("p0", p0, "MPa", "p0", "peak Hertz contact pressure ball/socket", S.HERTZ)
    fo.add("a", a_c, "mm", "a", "radius of the contact circle", S.HERTZ)

    # ------------------------------------------------------------ spring
    st = SP.spring_state(sd.c, y0, h_s, sp["free_length"],
                         SP.solid_length(sd.n_a, sd.d, sp["ends"]) if sd.geometric else None)
    ss = res.section("spring", "Spring")
    ss.add("F1", st.F_pre, "N", "F1", "force engaged (preload)", S.SEED_EQ7)
    ss.add("F2", st.F_max, "N", "F2", "force with the ball lifted by h_s", S.SEED_EQ7)
    tau = R_m = tau_adm = None
    if sd.geometric:
        Cidx = sd.D / sd.d
        tau = SP.shear_stress(st.F_max, sd.d, sd.D)
        ss.add("C", Cidx, "-", "C", "spring index D/d", S.SPRING)
        ss.add("K_W", SP.wahl_factor(Cidx), "-", "K_W", "Wahl factor", S.SPRING)
        ss.add("n_t", SP.total_coils(sd.n_a, sp["ends"]), "-", "n_t", "total coils",
               S.SPRING_ENDS)
        ss.add("L_s", st.L_solid, "mm", "L_s", "solid length", S.SPRING_ENDS)
        ss.add("L0_min", st.L_free_min, "mm", "L0,min", "least free length (solid length + "
               "y0 + h_s)", S.SPRING_ENDS)
        if st.L_installed is not None:
            ss.add("L1", st.L_installed, "mm", "L1", "length engaged", S.SPRING_ENDS)
            ss.add("L2", st.L_released, "mm", "L2", "length with the ball lifted", S.SPRING_ENDS)
        ss.add("tau_max", tau, "MPa", "τ2", "shear stress at F2 (with K_W)", S.SPRING)
        if sd.R_m is not None:
            R_m = sd.R_m
            ss.add("R_m", R_m, "MPa", "R_m", "tensile strength of the wire", S.MATERIAL)
        if sd.R_m is not None and sd.share is not None:
            tau_adm = sd.share * sd.R_m
            ss.add("tau_adm", tau_adm, "MPa", "[τ]", "allowable shear stress", S.MATERIAL)

    # ------------------------------------------------------------ checks
    out = res.checks
    hi_f, hi_g = f * (1 + spread), f_g * (1 + spread)
    locks = not math.isfinite(band.high)
    out.append(check(
        "SELF_LOCKING", not locks, "error",
        f"the balls never leave their sockets: with α2 = {_f(sa['socket_angle'], 2)}° and "
        f"the high friction (f = {_f(hi_f)}, f_g = {_f(hi_g)}) cot(α2 + ρ) <= f_g; reduce "
        f"safety.socket_angle below {math.degrees(alpha_lock):.1f}° or the friction",
        f"α2 = {_f(sa['socket_angle'], 2)}° < {math.degrees(alpha_lock):.1f}° (self-locking "
        f"at high friction)", sa["socket_angle"], math.degrees(alpha_lock), S.FRICTION))
    out.append(check(
        "CENTRIFUGAL_RELEASE", F_c < F_pre, "error",
        f"at {_f(n, 1)} min^-1 the centrifugal force {F_c:.2f} N of a ball reaches the spring "
        f"force {F_pre:.2f} N: the clutch releases without load above "
        f"{w_rel / RPM:.0f} min^-1; increase the spring preload or rate, use lighter balls or "
        f"a smaller ball circle",
        f"centrifugal force {F_c:.2f} N < spring force {F_pre:.2f} N (release by speed alone "
        f"at {w_rel / RPM:.0f} min^-1)", F_c, F_pre, S.CENTRIFUGAL))
    if not locks and F_c < F_pre:
        drop = 1.0 - band.nominal / band0.nominal
        out.append(check(
            "SPEED_SENSITIVITY", drop <= SPEED_SENSITIVITY, "warning",
            f"the limit torque at {_f(n, 1)} min^-1 is {drop * 100:.1f} % below its value at "
            f"rest ({band.nominal:.2f} against {band0.nominal:.2f} N·m): the centrifugal force "
            f"matters; set the preload for the operating speed or use lighter balls",
            f"the limit torque at speed is within {SPEED_SENSITIVITY * 100:.0f} % of its value "
            f"at rest ({drop * 100:.1f} % lower)", drop, SPEED_SENSITIVITY, S.CENTRIFUGAL))
        out.append(check(
            "LIMIT_ABOVE_RATED", band.low >= T, "error",
            f"the clutch trips at the rated torque: T_lim,min = {band.low:.2f} N·m < T = "
            f"{_f(T)} N·m at low friction; increase the spring preload (y0) or rate, or the "
            f"socket angle",
            f"T_lim,min = {band.low:.2f} N·m >= rated {_f(T)} N·m", band.low, T, S.PRACTICE))
        if band.low >= T:
            out.append(check(
                "LIMIT_MARGIN", band.low >= MARGIN_WARN * T, "warning",
                f"T_lim,min = {band.low:.2f} N·m is less than {MARGIN_WARN}·T = "
                f"{MARGIN_WARN * T:.2f} N·m: nuisance trips are likely; aim at T_lim = "
                f"1.25...1.5·T",
                f"T_lim,min = {band.low:.2f} N·m >= {MARGIN_WARN}·T = {MARGIN_WARN * T:.2f} N·m",
                band.low / T, MARGIN_WARN, S.PRACTICE))
            from geardesign.core.units_guard import given, light_load

            out += light_load(   # a rated torque typed in N·m where kN·m was meant
                "UNITS_LOAD", T / band.low, f"the rated torque is {100 * T / band.low:.2g} % "
                f"of what the clutch holds (T = {_f(T)} N·m against T_lim,min = "
                f"{band.low:.2f} N·m)", given(op, {"torque": "N·m"}, "operation"), S.PRACTICE)
    if math.isfinite(p0):
        p_adm = sa["allowable_contact"]
        out.append(check(
            "BALL_CONTACT", p0 <= p_adm, "error",
            f"contact pressure ball/socket p0 = {p0:.0f} MPa at the highest limit torque "
            f"exceeds {_f(p_adm, 0)} MPa: use larger or more balls, a conforming spherical "
            f"socket (safety.socket_radius) or a lower limit torque",
            f"contact pressure p0 = {p0:.0f} MPa <= {_f(p_adm, 0)} MPa", p0, p_adm, S.ISO76))
    if sd.geometric:
        Cidx = sd.D / sd.d
        why = ("hard to coil, high curvature stress" if Cidx < INDEX_RANGE[0]
               else "prone to tangle and buckle")
        out.append(check(
            "SPRING_INDEX", INDEX_RANGE[0] <= Cidx <= INDEX_RANGE[1], "warning",
            f"spring index D/d = {Cidx:.2f} outside {INDEX_RANGE[0]:.0f}...{INDEX_RANGE[1]:.0f}: "
            f"{why}; change the coil or wire diameter",
            f"spring index D/d = {Cidx:.2f} within {INDEX_RANGE[0]:.0f}...{INDEX_RANGE[1]:.0f}",
            Cidx, INDEX_RANGE[0] if Cidx < INDEX_RANGE[0] else INDEX_RANGE[1], S.PRACTICE))
        if sd.material is not None and sp["tensile_strength"] is None:
            mat = spring_steel.get(sd.material)
            out.append(check(
                "SPRING_WIRE_RANGE", mat.covers(sd.d), "warning",
                f"wire d = {_f(sd.d)} mm is outside the range {_f(mat.d_min)}...{_f(mat.d_max)} "
                f"mm of the strength data of {mat.name}; give spring.tensile_strength",
                f"wire d = {_f(sd.d)} mm within the data range of {mat.name}",
                sd.d, mat.d_max, S.MATERIAL))
        if tau_adm is not None:
            out.append(check(
                "SPRING_STRESS", tau <= tau_adm, "error",
                f"spring shear stress τ = {tau:.0f} MPa with the ball lifted exceeds [τ] = "
                f"{tau_adm:.0f} MPa: use a thicker wire, a smaller coil diameter or a lower "
                f"preload, or a stronger material",
                f"spring shear stress τ = {tau:.0f} MPa <= [τ] = {tau_adm:.0f} MPa",
                tau, tau_adm, S.SPRING))
        if st.L_released is not None:
            out.append(check(
                "SPRING_SOLID", st.L_released > st.L_solid, "error",
                f"the spring goes solid before the ball leaves its socket: length "
                f"{st.L_released:.2f} mm with the ball lifted, solid length {st.L_solid:.2f} mm; "
                f"use a free length of at least {st.L_free_min:.2f} mm or fewer coils",
                f"length with the ball lifted {st.L_released:.2f} mm > solid length "
                f"{st.L_solid:.2f} mm", st.L_released, st.L_solid, S.SPRING_ENDS))
    return res
