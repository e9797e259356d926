"""The solved rim (:class:`~geardesign.epicycle_rim.solve.Solution`) as report rows and
checks; nothing is computed here."""

from __future__ import annotations

import math

from geardesign.core.result import Result, check
from geardesign.epicycle_rim import checks as C
from geardesign.epicycle_rim import sources as S
from geardesign.epicycle_rim.fatigue_inputs import Fatigue
from geardesign.epicycle_rim.inputs import Inputs
from geardesign.epicycle_rim.solve import FatigueResult, Geometry, ResonanceResult, Solution

FLOQUET_TOL = 1e-6


def geometry_rows(res: Result, g: Geometry) -> None:
    sec = res.section("geometry", "Ring and planets")
    sec.add("d", g.d, "mm", "d", "reference diameter of the ring", S.KINEMATICS)
    sec.add("pitch_angle", g.pitch_angle, "deg", "φ_w", "angular pitch of the ring",
            S.B + " (3)")
    sec.add("angles", list(g.angles), "deg", "ψ", "planet angles on the carrier", S.B + " (4)")
    sec.add("delta_m", g.delta_m, "-", "δ/m", "rim thickness over module", S.ISO6336_3)
    sec.add("Y_B", g.Y_B if g.Y_B == g.Y_B else None, "-", "Y_B", "ISO 6336-3 rim thickness "
            "factor, internal gear (null: outside δ/m > 1.75)", S.ISO6336_3)
    sec.add("m_B", g.m_B, "-", "m_B", "backup ratio δ/h", S.ISO6336_3)
    sec.add("K_B", g.K_B, "-", "K_B", "AGMA rim thickness factor", S.ISO6336_3)
    sec.add("failure_mode", g.failure_mode, None, "", "likely fatigue failure mode "
            "(δ > h: tooth breakage, else rim fracture)", S.A)
    res.checks.append(C.rim_thickness_check(g.delta_m, g.Y_B, g.m_B, g.K_B))
    p = g.planets
    if p is None:
        return
    sec.add("coaxiality", p.coaxiality, "-", "z_r − z_s − 2z_p", "coaxiality (0 without "
            "profile shifts)", S.KINEMATICS)
    sec.add("assembly_index", list(p.assembly_index), "-", "(z_s + z_r)θ/360", "assembly "
            "indices (integers needed)", S.ASSEMBLY)
    sec.add("assembly_step", p.assembly_step, "deg", "Δθ", "step of assemblable planet angles",
            S.ASSEMBLY)
    sec.add("a_w", p.a_w, "mm", "a_w", "sun-planet centre distance (GOST 13755 rack)",
            "GOST 16532-70")
    sec.add("d_a_planet", p.d_a_planet, "mm", "d_a,p", "tip diameter of a planet",
            "GOST 16532-70")
    sec.add("spacing_min", p.spacing_min, "deg", "Δψ_min", "smallest angle between "
            "neighbouring planets", S.ASSEMBLY)
    sec.add("spacing_limit", p.spacing_limit, "deg", "Δψ_lim", "least angle for clear tip "
            "circles", S.ASSEMBLY)
    res.checks.append(C.assembly_check(list(p.assembly_index), list(p.nearest),
                                       p.assembly_step))
    res.checks.append(C.spacing_check(p.spacing_min, p.spacing_limit))
    if p.coaxiality != 0:
        res.checks.append(C.coaxiality_warning(p.coaxiality))


# ----------------------------------------------------------------------------- fatigue


def _stress_rows(res: Result, f: Fatigue, r: FatigueResult) -> None:
    ld, model = f.load, f.options.mean_stress_model
    est = ld.estimate
    st = res.section("stress", "Stresses at the fillets")
    if ld.bending_stress is not None:
        st.add("sigma_F", ld.bending_stress, "MPa", "σ_F",
               "root bending stress (GOST 21354-87, given)", S.GOST21354)
    st.add("sigma_Fn", ld.sigma_Fn, "MPa", "σ_Fn", "nominal tooth bending stress σ_F/Y_F", S.A)
    if est is not None:
        st.add("F_t", est.F_t, "N", "F_t", "tangential mesh force per planet", S.ROARK)
        st.add("F_r", est.F_r, "N", "F_r", "radial mesh force per planet", S.ROARK)
        st.add("R_m", est.R_m, "mm", "R_m", "mean radius of the rim", S.ROARK)
    st.add("hoop_loaded", ld.hoop_loaded, "MPa", "σ_t,load",
           "rim hoop stress under the loaded tooth" + (" (thin-ring estimate)" if est else ""),
           S.ROARK if est else S.A)
    st.add("hoop_between", ld.hoop_between, "MPa", "σ_t,betw",
           "rim hoop stress midway between loaded teeth" + (" (thin-ring estimate)"
                                                            if est else ""),
           S.ROARK if est else S.A)
    st.add("sigma_eq_tension", r.stresses.eq_tension, "MPa", "σ_eq,t",
           "Huber-Mises stress, tension-side fillet of the loaded tooth", S.A + " (3)")
    st.add("sigma_eq_compression", r.stresses.eq_compression, "MPa", "σ_eq,c",
           "Huber-Mises stress, compression-side fillet of the loaded tooth (signed)",
           S.A + " (3)")
    st.add("K_c", ld.load_sharing, "-", "K_c", "load-sharing factor between planets",
           S.A + " (1)")
    for s in f.stages:
        st.add(f"mu_F_{s.name}", s.mu_F, "-", f"μ_F ({s.name})",
               f"loading-mode factor, {s.name} ({s.how})", S.A + " (2)")
    for case in r.cases:
        c = case.cycle
        tag = f"{c.fillet}_{c.stage}"
        who = f"{c.fillet} fillet, {c.stage}"
        st.add(f"sigma_max_{tag}", c.s_max, "MPa", "σ_max", f"maximum stress, {who}",
               S.A + " (1)")
        st.add(f"sigma_min_{tag}", c.s_min, "MPa", "σ_min", f"minimum stress, {who}",
               S.A + " (1)")
        st.add(f"R_{tag}", c.R, "-", "R", f"stress ratio σ_min/σ_max, {who}", S.A)
        st.add(f"sigma_m_{tag}", c.s_m, "MPa", "σ_m", f"mean stress, {who}", S.A)
        st.add(f"sigma_a_{tag}", c.s_a, "MPa", "σ_a", f"stress amplitude, {who}", S.A)
        st.add(f"sigma_eq_{tag}", case.sigma_eq, "MPa", "σ_-1eq",
               f"equivalent symmetric amplitude ({model}), {who}", S.A + " (8)")
    st.add("governing_fillet", r.governing.fillet, None, "", "governing fillet (largest "
           "σ_-1eq)", S.A)
    st.add("governing_stage", r.governing.stage, None, "", "governing stage", S.A)
    st.add("sigma_eq_max", r.sigma_eq_max, "MPa", "σ_-1eq,max", "governing equivalent "
           "amplitude", S.A)
    for alt, eq in r.by_model:
        st.add(f"sigma_eq_{alt}", eq, "MPa", f"σ_-1eq ({alt})", f"governing case by the {alt} "
               f"diagram", S.A + " (4), (8); " + S.GOST25504)


def _endurance_rows(res: Result, f: Fatigue, r: FatigueResult) -> None:
    pe, o = r.part, f.options
    en = res.section("endurance", "Endurance limit of the rim (GOST 25.504-82)")
    en.add("K1", pe.K1, "-", "K1", "blank-size factor", S.A + " (9)")
    en.add("alpha_sigma", pe.alpha, "-", "α_σ",
           "theoretical SCF of the fillet" + (" (given)" if o.stress_concentration else ""),
           S.A + " (12)")
    en.add("dalpha_drho", pe.alpha_slope, "1/mm", "|∂α_σ/∂ρ|", "slope of the SCF in ρ",
           S.A + " (15)")
    en.add("G", pe.gradient, "1/mm", "G", "relative stress gradient"
           + (" (given)" if o.stress_gradient else ""), S.GOST25504)
    en.add("L", pe.perimeter, "mm", "L", "perimeter of the working section", S.A)
    en.add("theta", pe.theta, "-", "θ", "similarity criterion (L/G)/(L0/G0)", S.GOST25504)
    en.add("nu_sigma", pe.nu, "-", "ν_σ", "material sensitivity", S.GOST25504)
    en.add("K_sigma_K_dsigma", pe.k_ratio, "-", "K_σ/K_dσ", "effective SCF over size factor",
           S.A + " (11)")
    en.add("K_F", pe.K_F, "-", "K_F", "roughness factor", S.GOST25504)
    en.add("K_V", pe.K_V, "-", "K_V", "surface hardening factor", S.GOST25504)
    en.add("K_A", pe.K_A, "-", "K_A", "anisotropy factor", S.GOST25504)
    en.add("K", pe.K, "-", "K", "total reduction factor", S.A + " (10)")
    en.add("sigma_m1D", pe.sigma_m1D, "MPa", "σ_-1D", "median endurance limit of the rim",
           S.A + " (9)")
    en.add("psi_sigma", r.psi, "-", "ψ_σ", "mean-stress sensitivity of the material",
           S.GOST25504)
    en.add("psi_sigmaD", r.psi_D, "-", "ψ_σD", "mean-stress sensitivity of the part ψ_σ/K",
           S.GOST25504)
    en.add("v_sigma_max", pe.v_max, "-", "v_σmax", "variation of the failure stress",
           S.GOST25504)
    en.add("v_sigma_m1", f.material.scatter, "-", "v_σ-1",
           "variation of σ_-1 between heats", S.GOST25504)
    en.add("v_alpha_sigma", pe.v_alpha, "-", "v_ασ", "variation of the SCF", S.A + " (15)")
    en.add("v_sigma_m1D_eq14", pe.v_computed, "-", "v_σ-1D (14)",
           "variation of the part endurance limit by eq. (14)", S.A + " (14)")
    en.add("v_sigma_m1D", pe.v, "-", "v_σ-1D", "variation of the part endurance limit used"
           + (" (given)" if o.scatter_total else ""), S.A + " (14)")
    en.add("P_table", [p * 100.0 for p in r.probabilities], "%", "P", "probabilities of "
           "non-failure", S.A + " Table 2")
    en.add("z_P", list(r.z_P), "-", "z_P", "normal quantiles", S.A + " (13)")
    en.add("xi_P", [1.0 - z * pe.v for z in r.z_P], "-", "ξ(P)", "relative endurance limit "
           "1 − z_P·v", S.A + " (16)")
    en.add("sigma_m1D_P", list(r.sigma_m1D_P), "MPa", "σ_-1D(P)", "endurance limit of the rim "
           "at P", S.A + " (13)")


def _life_rows(res: Result, r: FatigueResult, gov: str) -> None:
    lf = res.section("life", "Probability of non-failure and life")
    for case in r.cases:
        c = case.cycle
        tag = f"{c.fillet}_{c.stage}"
        lf.add(f"n_{tag}", case.n, "-", "n", f"safety factor σ_-1D/σ_-1eq, {c.fillet} fillet, "
               f"{c.stage}", S.GOST25504)
        lf.add(f"P_{tag}", case.P * 100.0, "%", "P", f"probability of non-failure, {c.fillet} "
               f"fillet, {c.stage}", S.GOST25504)
    lf.add("n", r.part.sigma_m1D / r.sigma_eq_max, "-", "n", f"safety factor, governing case "
           f"({gov})", S.GOST25504)
    lf.add("P", r.P * 100.0, "%", "P", "probability of non-failure, governing case",
           S.GOST25504)
    lf.add("m", r.m_slope, "-", "m", "slope of the S-N curve of the rim", S.GOST25504)
    lf.add("lg_N_P", list(r.lg_N_P), "-", "lg N_P", "life of the governing case at P (∞ shown "
           "as —)", S.A + " (21)")
    lf.add("N_P", [(10.0 ** x if x > -300.0 else 0.0) if math.isfinite(x) else math.inf
                   for x in r.lg_N_P], "cycles",
           "N_P", "cycles to failure of the governing case at P", S.A + " (21)")
    if r.cycles_per_km is not None:
        lf.add("cycles_per_km", r.cycles_per_km, "1/km", "n_km", "stress cycles of a fillet "
               "per km", S.KINEMATICS)
        for fillet, lives in r.life_km:
            lf.add(f"life_km_{fillet}", list(lives), "km", "L_km", f"life of the {fillet} "
                   f"fillet at P (Miner over the stages; ∞ shown as —)", S.MINER)


def _advice_text(r: FatigueResult) -> str:
    a = r.advice
    if a is None:
        return ""
    parts = []
    if a.K_V is not None:
        parts.append(f"harden the fillets to K_V >= {math.ceil(a.K_V * 100) / 100:.2f} "
                     f"(induction hardening, nitriding or roller burnishing give 2-2.5)")
    if a.rho is not None:
        parts.insert(0, f"increase the fillet radius to ρ >= "
                     f"{math.ceil(a.rho * 1000) / 1000:.3f} mm (e.g. cut the "
                     f"ring with a shaper cutter of more teeth)")
    parts.append("or thicken the rim / reduce the load")
    return ", ".join(parts)


def _fatigue_checks(res: Result, f: Fatigue, r: FatigueResult, gov: str) -> None:
    ck, pe, o, mat = res.checks, r.part, f.options, f.material
    wd, wm = r.worst_domain, r.worst_max
    ck.append(C.domain_check(abs(wd.s_m) + wd.s_a, mat.sigma_u, f"{wd.fillet} fillet, "
                             f"{wd.stage}"))
    ck.extend(C.yield_checks(wm.s_max, mat.sigma_y, f"{wm.fillet} fillet, {wm.stage}"))
    if r.sigma_eq_max == r.sigma_eq_max:
        advice = _advice_text(r)
        ck.append(C.endurance_check(r.sigma_eq_max, pe.sigma_m1D, gov, advice))
        ck.append(C.probability_check(r.P, r.P_required, gov, advice))
    if r.lg_N_min is not None:
        al, be = o.slgn_alpha, o.slgn_beta
        ck.append(check(
            "SN_SCATTER_DOMAIN", False, "error",
            f"the S-N scatter model gives less than one cycle (lg N_P = {r.lg_N_min:.3g}): "
            f"S_lgN = 10^(α + β·lg σ̄) = {r.s_lgn:.3g} decades at σ̄ = "
            f"{r.sigma_eq_max / pe.sigma_m1D:.3g}, where the scatter of steels is 0.05...1; "
            f"check fatigue.slgn_alpha = {al:g} and fatigue.slgn_beta = {be:g}", "", r.s_lgn,
            1.0, S.A + " (17)-(21)"))
    ck.append(C.range_warning("ENDURANCE_RATIO", mat.sigma_m1 / mat.sigma_u,
                              *C.ENDURANCE_RATIO, "σ_-1/σ_u",
                              "check the material data", S.PRACTICE))
    ck.append(C.range_warning("LOAD_SHARING", f.load.load_sharing, *C.LOAD_SHARING, "K_c",
                              "unusual load-sharing factor; check it", S.PRACTICE))
    if f.load.form_factor is not None:
        ck.append(C.range_warning("FORM_FACTOR", f.load.form_factor, *C.FORM_FACTOR, "Y_F",
                                  "unusual tooth form factor; check it", S.PRACTICE))
    for code, value, what in (("SCATTER_MATERIAL", mat.scatter, "v_σ-1"),
                              ("SCATTER_TOTAL", pe.v, "v_σ-1D")):
        ck.append(C.range_warning(code, value, *C.SCATTER_RANGE, what,
                                  "unusual coefficient of variation; check it", S.PRACTICE))
    if f.fillet.roughness < C.RZ_MIN:
        ck.append(C.range_warning("ROUGHNESS", f.fillet.roughness, C.RZ_MIN, 320.0, "Rz [µm]",
                                  "below the range of the roughness factor", S.GOST25504))
    if f.load.estimate is not None:
        ck.append(C.hoop_estimate_warning(f.load.hoop_loaded, f.load.hoop_between))


def fatigue_rows(res: Result, f: Fatigue, r: FatigueResult) -> None:
    gov = f"{r.governing.fillet} fillet, {r.governing.stage}"
    _stress_rows(res, f, r)
    _endurance_rows(res, f, r)
    _life_rows(res, r, gov)
    _fatigue_checks(res, f, r, gov)


# ----------------------------------------------------------------------------- resonance


def _band_rows(sec, r: ResonanceResult, orders) -> None:
    for n, b, bs in zip(orders, r.bands, r.series):
        sec.add(f"a_n{n}", [b.a_lo, b.a_hi], "-", f"a (n = {n})", f"instability region {n} "
                f"along b = μa/2 (exact characteristic values)", S.MATHIEU)
        sec.add(f"Omega_ratio_n{n}", [b.ratio_lo, b.ratio_hi], "-", f"Ω/k0 (n = {n})",
                f"excitation over natural frequency, region {n}", S.B + " (6)")
        if bs is not None:
            sec.add(f"a_series_n{n}", [bs.a_lo, bs.a_hi], "-", f"a (series, n = {n})",
                    f"region {n} by paper B's series (8)", S.MATHIEU_SERIES)
    if r.linear is not None:
        sec.add("a_linear_n1", [r.linear.a_lo, r.linear.a_hi], "-", "a (1 ± b)", "region 1 by "
                "the two-term harmonic balance", S.B + " (7)")


def _order_rows(sec, inp: Inputs, r: ResonanceResult) -> None:
    if inp.resonance.stiffness_model == "stepwise":
        for o in r.orders:
            ob = o.band
            sec.add(f"mesh_ratio_stepwise_n{ob.order}",
                    None if ob.mesh_lo is None else [ob.mesh_lo, ob.mesh_hi], "-",
                    f"f_m/k0 (n = {ob.order})", "unstable mesh-frequency ratio, stepwise "
                    "stiffness (null: narrower than the search)", S.FLOQUET)
    k0s = inp.resonance.natural_frequencies
    sec.add("k0", list(k0s), "Hz", "k0", "natural frequencies of the ring", S.B)
    for o in r.orders:
        ob, n = o.band, o.band.order
        sec.add(f"Omega_n{n}", list(o.omega), "Hz", f"Ω (a = {n * n})", f"excitation "
                f"frequency of resonance {n}, 2k0/n", S.B + " (10)")
        sec.add(f"f_mesh_n{n}", list(o.f_mesh), "Hz", f"f_m (a = {n * n})", f"mesh frequency "
                f"at resonance {n}, Ω/h", S.KINEMATICS)
        if ob.mesh_lo is not None:
            sec.add(f"f_mesh_band_n{n}", [[ob.mesh_lo * k, ob.mesh_hi * k] for k in k0s], "Hz",
                    f"f_m band (n = {n})", f"unstable mesh-frequency band of resonance {n} "
                    f"per k0", S.B + " (6)")
        if o.V is None:
            continue
        sec.add(f"V_n{n}", list(o.V), "km/h", f"V (a = {n * n})", f"vehicle speed at "
                f"resonance {n}", S.KINEMATICS)
        if o.V_band is not None:
            sec.add(f"V_band_n{n}", [list(v) for v in o.V_band], "km/h", f"V band (n = {n})",
                    f"vehicle speeds of the unstable band of resonance {n} per k0",
                    S.KINEMATICS)


def resonance_rows(res: Result, inp: Inputs, r: ResonanceResult) -> None:
    rz = inp.resonance
    p, exc, orders = r.pulsation, r.excitation, rz.orders
    sec = res.section("resonance", "Parametric resonance of the ring")
    sec.add("phases", list(r.phases), "-", "γ", f"ring-planet mesh phases, fractions of a "
            f"pitch ({rz.phase_model} model)", S.PHASING if rz.phase_model == "actual" else S.B)
    sec.add("N_min", p.n_min, "-", "N_Σ,min", "least number of tooth pairs in contact", S.B)
    sec.add("N_max", p.n_max, "-", "N_Σ,max", "largest number of tooth pairs in contact", S.B)
    sec.add("N_mean", p.mean, "-", "N̄_Σ", "mean number of pairs, n_p·ε_α", S.B)
    sec.add("mu", p.mu, "-", "μ", "pulsation depth c_a/c_m = (N_max − N_min)/(2N̄)",
            S.B + " (2)")
    sec.add("mu_h", list(p.mu_h), "-", "μ_h", "harmonic amplitudes of the stiffness over its "
            "mean, h = 1, 2, …", S.B)
    sec.add("h", exc.h, "-", "h", "dominant harmonic of the mesh frequency (excitation Ω = "
            "h·f_m)", S.B)
    sec.add("mu_used", exc.mu, "-", "μ", f"pulsation depth in the Mathieu equation "
            f"({exc.depth_definition})", S.B + " (5)")
    _band_rows(sec, r, orders)
    _order_rows(sec, inp, r)
    v_range = inp.vehicle.speed_range if inp.vehicle is not None else None
    if v_range is not None:
        res.checks.append(C.resonance_check(list(r.hits), len(r.hits), list(v_range)))
    for key, values in r.chart:
        name = ("b grid (q of Mathieu's equation)" if key == "b" else
                f"characteristic value {key[0]}_{key[1:]}(b)")
        sec.add(f"chart_{key}", list(values), "-", key, f"Ince-Strutt chart: {name}",
                S.MATHIEU)
    if exc.mu > 0.0:
        grid = dict(r.chart)["b"]
        sec.add("chart_line_a", [2.0 * q / exc.mu for q in grid], "-", "a = 2b/μ",
                "Ince-Strutt chart: working line b = μa/2", S.B + " (6)")
    if r.floquet is not None:
        for n, fb in zip(orders, r.floquet):
            sec.add(f"a_floquet_n{n}", None if fb is None else list(fb), "-",
                    f"a (Floquet, n = {n})", f"region {n} located by numerical integration "
                    f"(null: too narrow to bracket)", S.FLOQUET)
        sec.add("floquet_max_dev", r.floquet_dev, "-", "max |Δa|", "largest difference between "
                "the Floquet and the characteristic-value boundaries", S.FLOQUET)
        res.checks.append(C.floquet_check_result(r.floquet_dev, FLOQUET_TOL))
    if r.actual is not None:
        res.checks.append(C.phase_model_warning(exc.mu, r.actual.mu, r.actual.h))


def report(res: Result, inp: Inputs, sol: Solution) -> Result:
    """Fill ``res`` (the calculator's result echoing the spec) with the rows and checks."""
    geometry_rows(res, sol.geometry)
    if sol.fatigue is not None:
        fatigue_rows(res, inp.fatigue, sol.fatigue)
    if sol.resonance is not None:
        resonance_rows(res, inp, sol.resonance)
    return res

