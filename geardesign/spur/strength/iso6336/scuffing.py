"""Scuffing by the integral temperature method ([ISO6336-21], ISO/TS 6336-21:2017 =
ISO/TR 13989-2:2000): the record :class:`Scuffing` (its fields with their report metadata),
:func:`scuffing` that fills it for one pair, and :func:`scuffing_checks`.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.core.result import Check, check
from geardesign.spur.strength.common import Record, q
from geardesign.spur.strength.iso6336 import part21 as P21
from geardesign.spur.strength.iso6336 import tables as T

S21 = "[ISO6336-21]"


@dataclass(frozen=True, kw_only=True)
class Scuffing(Record):
    """The scuffing rating of a pair ([ISO6336-21] §5–§6): the oil, the factors, the
    integral temperature Θ_int = Θ_M + C_2 Θ_flaint, the integral scuffing temperature
    Θ_intS of the oil's FZG load stage and the safety factors S_intS = Θ_intS/Θ_int and
    S_SL."""

    SECTION = "iso6336_scuffing"
    nu100_given: bool = False
    density15: float = 890.0
    lubricant: str = ""
    lubrication: str = ""
    meshes: int = 1
    structure: str = ""
    structure_how: str = ""
    B_M: float = T.B_M_STEEL
    branch: str = ""
    driving: str = "pinion"
    ef_ea: float = 1.0
    C_a_used: float = 0.0
    Ra: float = 0.0
    S_Smin_src: str = "spec default"
    scuffing_method: str = q(None, "", "method", S21)
    fzg_load_stage: float = q("-", "FZG", "FZG A/8.3/90 failure load stage of the oil "
                              "(ISO 14635-1)", "spec")
    theta_oil: float = q("°C", "Θ_oil", "oil temperature", "spec")
    nu100: float = q("mm^2/s", "ν100", lambda c: "kinematic viscosity at 100 °C"
                     + ("" if c["nu100_given"] else " (from ν40 with VI 95)"),
                     lambda c: "spec" if c["nu100_given"] else "ASTM D2270")
    nu_oil: float = q("mm^2/s", "ν_oil", "kinematic viscosity at the oil temperature "
                      "(Ubbelohde–Walther)", "ASTM D341")
    eta_oil: float = q("mPa·s", "η_oil", "dynamic viscosity at the oil temperature (ρ15 = "
                       "{density15:g} kg/m³, expansion " + f"{T.OIL_EXPANSION:g}/K)", S21)
    X_L: float = q("-", "X_L", lambda c: f"lubricant factor ({c['lubricant'].replace('_', ' ')} "
                   "oil)", S21)
    X_S: float = q("-", "X_S", "lubrication factor ({lubrication} lubrication)", S21)
    X_mp: float = q("-", "X_mp", lambda c: f"multiple mesh factor ({c['meshes']} mesh"
                    f"{'es' if c['meshes'] > 1 else ''})", S21)
    X_WrelT: float = q("-", "X_WrelT", lambda c: "relative welding factor ("
                       f"{c['structure'].replace('_', ' ')}){c['structure_how']}", S21)
    K_Bgamma: float = q("-", "K_Bγ", "helical load factor", S21)
    w_Bt: float = q("N/mm", "w_Bt", "transverse unit load K_A K_γ K_v K_Hβ K_Hα F_t/b", S21)
    rho_E1: float = q("mm", "ρ_E1", "radius of curvature of the pinion at its tip", S21)
    rho_E2: float = q("mm", "ρ_E2", "radius of curvature of the wheel at the pinion tip", S21)
    eps_1: float = q("-", "ε_1", "addendum contact ratio, pinion", S21)
    eps_2: float = q("-", "ε_2", "addendum contact ratio, wheel", S21)
    X_M: float = q("K·N^-0.75·s^0.5·m^-0.5·mm", "X_M", "flash factor (B_M = {B_M:g} "
                   "N/(mm·s^½·K))", S21)
    X_alphabeta: float = q("-", "X_αβ", "angle factor", S21)
    X_BE: float = q("-", "X_BE", "geometry factor at the pinion tip", S21)
    X_eps: float = q("-", "X_ε", "contact ratio factor ({branch})", S21)
    X_eps_branch: str = q(None, "X_ε branch", "branch of the X_ε table (the scuffing advice)",
                          S21, row=False)
    nu40_scuffing: float = q("mm^2/s", "ν40", "kinematic viscosity at 40 °C (the scuffing "
                             "advice)", "spec", row=False)
    X_Q: float = q("-", "X_Q", "approach factor (driving: {driving}, ε_f/ε_a = {ef_ea:.3f})",
                   S21)
    C_eff: float = q("µm", "C_eff", "optimal tip relief K_A F_t/(b c_γ)", S21)
    X_Ca: float = q("-", "X_Ca", "tip relief factor (C_a = {C_a_used:.3g} µm)", S21)
    X_E: float = q("-", "X_E", "running-in factor (well run in)", S21)
    rho_redC: float = q("mm", "ρ_redC", "relative radius of curvature at the pitch point "
                        "(normal section)", S21)
    v_sumC: float = q("m/s", "v_ΣC", "sum of the tangential velocities at the pitch point "
                      "(operating pitch circle)", S21)
    X_R: float = q("-", "X_R", "roughness factor (Ra = {Ra:g} µm, mean of the flanks)", S21)
    mu_mC: float = q("-", "μ_mC", "mean coefficient of friction", S21)
    theta_flaE: float = q("K", "Θ_flaE", "flash temperature at the pinion tip", S21)
    theta_flaint: float = q("K", "Θ_flaint", "mean flash temperature Θ_flaE·X_ε", S21)
    theta_M: float = q("°C", "Θ_M", "bulk temperature Θ_oil + C_1 X_mp X_S Θ_flaint", S21)
    theta_int: float = q("°C", "Θ_int", "integral temperature Θ_M + C_2 Θ_flaint", S21)
    T_1T: float = q("N·m", "T_1T", "pinion torque of the FZG load stage", "[ISO14635-1]")
    theta_MT: float = q("°C", "Θ_MT", "bulk temperature of the test gears", S21)
    theta_flaintT: float = q("K", "Θ_flaintT", "mean flash temperature of the test gears", S21)
    theta_intS: float = q("°C", "Θ_intS", "integral scuffing temperature Θ_MT + C_2 X_WrelT "
                          "Θ_flaintT", S21)
    S_Smin: float = q("-", "S_Smin", "required safety factor, scuffing", "{S_Smin_src}")
    S_intS: float = q("-", "S_intS", "safety factor for scuffing Θ_intS/Θ_int", S21)
    S_SL: float = q("-", "S_SL", "safety factor for scuffing referred to the load (Θ_intS − "
                    "Θ_oil)/(Θ_int − Θ_oil)", S21)


def scuffing(given, g, mats, setting, iso, types, F_t: float, v: float, K_A: float,
             K_rest: float, c_ga: float, C_a: float) -> Scuffing:
    """Scuffing of one pair by the integral temperature method ([ISO6336-21] §5, §6):
    ``given`` the ``[iso_factors]`` overrides (:class:`~..common.Given`), ``F_t`` [N] and
    ``v`` [m/s] at the reference circle, ``K_rest`` = K_γ K_v K_Hβ K_Hα, ``c_ga`` the mesh
    stiffness [N/(mm·µm)], ``C_a`` the tip relief [µm]."""
    from geardesign.materials.lubricants import nu100_from_vi, viscosity_at

    sc, p = iso.scuffing, g.inp
    internal = bool(getattr(g, "internal", False))
    b, u, a = p.b_w, g.u, g.a_w
    a_wt, a_t = g.alpha_tw, g.alpha_t
    nu100 = sc.nu100 if sc.nu100 is not None else nu100_from_vi(iso.nu40, 95.0)
    nu_oil = viscosity_at(sc.oil_temperature, iso.nu40, nu100)
    eta = given("eta_oil", lambda: nu_oil * P21.oil_density(sc.density15, sc.oil_temperature)
                / 1000.0)
    X_L, X_S = T.SCUFFING_X_L[sc.lubricant], T.SCUFFING_X_S[sc.lubrication]
    X_mp = P21.multiple_mesh_factor(sc.meshes)
    if sc.structure is not None:
        structure, how = sc.structure, " (given)"
    else:
        structure = min((T.SCUFFING_STRUCTURE[t] for t in types),
                        key=lambda k: T.SCUFFING_X_WRELT[k])
        how = " (from the material types)"
    X_W = given("X_WrelT", T.SCUFFING_X_WRELT[structure])
    # load
    K_Bg = given("K_Bgamma", lambda: P21.helical_load_factor(g.eps_alpha + g.eps_beta))
    w_Bt = K_A * K_rest * F_t / b
    # geometry at the pinion tip E
    rho_E1 = 0.5 * math.sqrt(g.g1.d_a ** 2 - g.g1.d_b ** 2)
    path = a * math.sin(a_wt)
    rho_E2 = rho_E1 + path if internal else path - rho_E1
    eps_1 = p.z1 / (2.0 * math.pi) * (2.0 * rho_E1 / g.g1.d_b - math.tan(a_wt))
    eps_2 = g.eps_alpha - eps_1
    E_r = 2.0 / sum((1.0 - m.nu ** 2) / m.E for m in mats)
    X_M = given("X_M", lambda: P21.flash_factor(E_r, sc.B_M))
    X_ab = given("X_alphabeta", lambda: P21.angle_factor(a_wt, p.rack.alpha_n, a_t, p.beta))
    X_BE = given("X_BE", lambda: P21.geometry_factor_tip(rho_E1, rho_E2, u, internal))
    X_eps_c, branch = P21.contact_ratio_factor(eps_1, eps_2)
    X_eps = given("X_eps", X_eps_c)
    e_f, e_a = (eps_2, eps_1) if sc.driving == "pinion" else (eps_1, eps_2)
    X_Q = given("X_Q", lambda: P21.approach_factor(e_f, e_a))
    C_eff = K_A * F_t / (b * c_ga)
    X_Ca = given("X_Ca", lambda: P21.tip_relief_factor(C_a, C_eff, max(eps_1, eps_2)))
    X_E = given("X_E", 1.0)
    # friction
    k_u = (u - 1.0) if internal else (u + 1.0)
    rho_C = u / k_u ** 2 * path / math.cos(g.beta_b)
    v_sum = P21.sum_velocity_pitch(v * g.g1.d_w / g.g1.d, a_wt)
    Ra = 0.5 * (setting.Ra[0] + setting.Ra[1])
    X_R = P21.roughness_factor(Ra, rho_C)
    mu = given("mu_mC", lambda: P21.mean_friction(w_Bt * K_Bg, v_sum, rho_C, eta, X_R, X_L))
    # temperatures
    th_E = P21.flash_temperature_tip(mu, X_M, X_BE, X_ab, w_Bt * K_Bg, v, a, X_E, X_Q, X_Ca)
    th_fl = th_E * X_eps
    th_M = P21.bulk_temperature(sc.oil_temperature, th_fl, X_S, X_mp)
    th_int = th_M + P21.C_2 * th_fl
    th_S, th_MT, th_flT = P21.integral_scuffing_temperature(sc.fzg_load_stage, iso.nu40, X_L,
                                                             X_W)
    return Scuffing(
        nu100_given=sc.nu100 is not None, density15=sc.density15, lubricant=sc.lubricant,
        lubrication=sc.lubrication, meshes=sc.meshes, structure=structure,
        structure_how=how, B_M=sc.B_M, branch=branch, driving=sc.driving, ef_ea=e_f / e_a,
        C_a_used=min(C_a, C_eff), Ra=Ra,
        S_Smin_src="spec" if sc.S_Smin != 1.8 else "spec default",
        scuffing_method="integral temperature method (ISO/TS 6336-21:2017 = ISO/TR "
                        "13989-2:2000)",
        fzg_load_stage=float(sc.fzg_load_stage), theta_oil=sc.oil_temperature, nu100=nu100,
        nu_oil=nu_oil, eta_oil=eta, X_L=X_L, X_S=X_S, X_mp=X_mp, X_WrelT=X_W, K_Bgamma=K_Bg,
        w_Bt=w_Bt, rho_E1=rho_E1, rho_E2=rho_E2, eps_1=eps_1, eps_2=eps_2, X_M=X_M,
        X_alphabeta=X_ab, X_BE=X_BE, X_eps=X_eps,
        X_eps_branch=branch if "X_eps" not in iso.overrides else "",
        nu40_scuffing=iso.nu40, X_Q=X_Q, C_eff=C_eff, X_Ca=X_Ca, X_E=X_E, rho_redC=rho_C,
        v_sumC=v_sum, X_R=X_R, mu_mC=mu, theta_flaE=th_E, theta_flaint=th_fl, theta_M=th_M,
        theta_int=th_int, T_1T=P21.fzg_torque(sc.fzg_load_stage), theta_MT=th_MT,
        theta_flaintT=th_flT, theta_intS=th_S, S_Smin=sc.S_Smin, S_intS=th_S / th_int,
        # 0 when the oil alone is at the scuffing temperature (no load is safe)
        S_SL=max(0.0, th_S - sc.oil_temperature) / (th_int - sc.oil_temperature))


OIL_TEMPERATURE_REACHABLE = 40.0
"""Lowest oil temperature [°C] the scuffing advice proposes (what an oil cooler reaches in
practice); below it the advice names only the oil and the geometry."""


def scuffing_checks(v: dict) -> list[Check]:
    """S_intS ≥ S_Smin ([ISO6336-21]) with advice: the FZG load stage of an oil that passes,
    or how far to lower the oil temperature (Θ_int moves with Θ_oil nearly one to one)."""
    S, need = v["S_intS"], v["S_Smin"]
    th_int, th_S = v["theta_int"], v["theta_intS"]
    ok = S >= need * (1 - 1e-12)
    advice = []
    if not ok:
        target = need * th_int
        nu40 = v["nu40_scuffing"]
        stage = next((k for k in sorted(T.FZG_TORQUE) if P21.integral_scuffing_temperature(
            k, nu40, v["X_L"], v["X_WrelT"])[0] >= target), None)
        if stage is not None:
            advice.append(f"use an oil of FZG load stage {stage} or higher (Θ_intS >= "
                          f"{target:.0f} °C)")
        drop = math.ceil(th_int - th_S / need)   # whole kelvins, on the safe side
        if v["theta_oil"] - drop >= OIL_TEMPERATURE_REACHABLE:
            advice.append(f"lower the oil temperature by at least {drop:d} K, to "
                          f"{v['theta_oil'] - drop:g} °C (cooling)")
        advice.append("reduce the sliding at the tips (smaller module with more teeth, tip "
                      "relief, balanced profile shifts) or the flank roughness")
    out = [check("ISO_SCUFFING", ok, "error",
                 f"ISO/TS 6336-21 scuffing: S_intS = {S:.2f} < S_Smin = {need:.2f} "
                 f"(Θ_int = {th_int:.0f} °C, Θ_intS = {th_S:.0f} °C): " + ", or ".join(advice),
                 f"ISO/TS 6336-21 scuffing: S_intS = {S:.2f} >= {need:.2f} (Θ_int = "
                 f"{th_int:.0f} °C)", S, need, S21)]
    if "(nearest)" in v.get("X_eps_branch", ""):
        out.append(check("ISO_SCUFFING_CONTACT_RATIO", False, "warning",
                         f"ISO/TS 6336-21: ε_α = {v['eps_1'] + v['eps_2']:.2f} with ε_1 = "
                         f"{v['eps_1']:.2f}, ε_2 = {v['eps_2']:.2f} lies outside the table of "
                         f"X_ε; the nearest branch was used: give X_eps under [iso_factors] "
                         f"for a closer rating", "", None, None, S21))
    return out
