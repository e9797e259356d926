"""``kind = "epicycle_rim"``: from a validated spec to a
:class:`~geardesign.core.result.Result`.

This module maps spec keys to the pure functions of :mod:`.stress`, :mod:`.endurance`,
:mod:`.mesh`, :mod:`.mathieu`, :mod:`.resonance` and :mod:`.rim`, their results to report
rows, and applies the rules that involve several keys (:class:`InputError`, exit 2).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from geardesign.core.errors import InputError, Problem
from geardesign.core.result import Result, check
from geardesign.core.spec import Field, ValidatedSpec
from geardesign.epicycle_rim import checks as C
from geardesign.epicycle_rim import endurance as E
from geardesign.epicycle_rim import mathieu as M
from geardesign.epicycle_rim import mesh
from geardesign.epicycle_rim import resonance as R
from geardesign.epicycle_rim import rim
from geardesign.epicycle_rim import sources as S
from geardesign.epicycle_rim import stress as ST
from geardesign.epicycle_rim.spec import FATIGUE, FATIGUE_TABLES
from geardesign.epicycle_rim.tables import mode_K_FE

_NAME = re.compile(r"^[a-z][a-z0-9_]*$")
FLOQUET_TOL = 1e-6


def _fmt(x: float) -> str:
    return f"{x:.4f}".rstrip("0").rstrip(".")


def _assume(spec: ValidatedSpec, table: str, key: str, value) -> None:
    spec.data[table][key] = value
    spec.assumed.append(f"{table}.{key}")


# ----------------------------------------------------------------------------- input rules


def _check_tables(spec: ValidatedSpec) -> tuple[bool, bool]:
    d = spec.data
    given = [t for t in FATIGUE_TABLES if d.get(t) is not None]
    fatigue = bool(given)
    if fatigue:
        for t in FATIGUE_TABLES:
            if d.get(t) is None:
                what = "[[stage]] tables" if t == "stage" else f"table [{t}]"
                raise InputError(Problem(
                    t, f"missing {what}: the fatigue analysis (started by "
                    f"[{given[0]}]) needs [fillet], [material], [load] and [[stage]]"))
    elif d.get("fatigue") is not None:
        raise InputError(Problem(
            "fatigue", "applies to the fatigue analysis, which needs [fillet], [material], "
            "[load] and [[stage]]; remove [fatigue] or add them"))
    resonance = d.get("resonance") is not None
    if not fatigue and not resonance:
        raise InputError(Problem(
            "", "nothing to compute: give the fatigue tables ([fillet], [material], [load], "
            "[[stage]]) or [resonance], or both"))
    return fatigue, resonance


def _ring_and_planets(spec: ValidatedSpec) -> list[float]:
    """Resolve the defaults of [ring] and [planets]; return the planet angles [deg]."""
    ring, pl = spec.data["ring"], spec.data["planets"]
    if ring["tooth_height"] is None:
        _assume(spec, "ring", "tooth_height", 2.25 * ring["module"])
    n = pl["count"]
    if (pl["z_sun"] is None) != (pl["z_planet"] is None):
        key = "planets.z_planet" if pl["z_planet"] is None else "planets.z_sun"
        raise InputError(Problem(key, "missing: give both z_sun and z_planet (or neither)"))
    if pl["z_sun"] is not None:
        delta = ring["z"] - pl["z_sun"] - 2 * pl["z_planet"]
        if abs(delta) > 2:
            raise InputError(Problem(
                "ring.z", f"does not fit the planets: z_sun + 2·z_planet = "
                f"{pl['z_sun'] + 2 * pl['z_planet']} (coaxial trains need z_r = z_s + 2·z_p, "
                f"±2 with profile shifts)", ring["z"]))
    if pl["angles"] is not None and pl["shifts"] is not None:
        raise InputError(Problem("planets.shifts", "give planets.angles or planets.shifts, "
                                 "not both", pl["shifts"]))
    if pl["angles"] is not None:
        if len(pl["angles"]) != n:
            raise InputError(Problem("planets.angles", f"must list {n} angles (planets.count "
                                     f"= {n})", pl["angles"]))
        return list(pl["angles"])
    if pl["shifts"] is not None:
        k = pl["shifts"]
        if len(k) != n:
            raise InputError(Problem("planets.shifts", f"must list {n} shifts (planets.count "
                                     f"= {n})", k))
        if abs(sum(k)) > 1e-9:
            raise InputError(Problem("planets.shifts", f"must sum to 0 (the spacings add up "
                                     f"to 360°); the sum is {sum(k):.6g}", k))
        return mesh.angles_from_shifts(n, k, ring["z"])
    return [360.0 * i / n for i in range(n)]


@dataclass
class Material:
    sigma_u: float
    sigma_y: float
    sigma_m1: float
    source: str


def _material(spec: ValidatedSpec) -> Material:
    from geardesign.materials.fatigue_steel import grade

    m = spec.data["material"]
    source = "given"
    if m["grade"] is not None:
        lib = grade(m["grade"])
        source = f"{m['grade']}: {lib['source']}"
        for key in ("sigma_u", "sigma_y", "sigma_m1"):
            if m[key] is None:
                _assume(spec, "material", key, lib[key])
    for key, what in (("sigma_u", "ultimate strength"), ("sigma_y", "yield strength"),
                      ("sigma_m1", "endurance limit")):
        if m[key] is None:
            raise InputError(Problem(f"material.{key}", f"missing: give the {what} or a "
                                     f"material.grade"))
    if m["sigma_y"] >= m["sigma_u"]:
        raise InputError(Problem("material.sigma_y", f"must be below sigma_u = "
                                 f"{_fmt(m['sigma_u'])} MPa", m["sigma_y"]))
    if m["sigma_m1"] >= m["sigma_u"]:
        raise InputError(Problem("material.sigma_m1", f"must be below sigma_u = "
                                 f"{_fmt(m['sigma_u'])} MPa", m["sigma_m1"]))
    if E.sensitivity_nu(m["sigma_u"]) <= 0.0:
        raise InputError(Problem("material.sigma_u", "must be < 1475 MPa: the sensitivity "
                                 "ν_σ = 0.211 − 0.000143·σ_u of GOST 25.504-82 is <= 0 above",
                                 m["sigma_u"]))
    return Material(m["sigma_u"], m["sigma_y"], m["sigma_m1"], source)


def _nominal_bending(load: dict) -> float:
    sF, YF, sFn = load["bending_stress"], load["form_factor"], load["nominal_bending_stress"]
    if sFn is not None:
        if sF is not None or YF is not None:
            raise InputError(Problem("load.nominal_bending_stress", "give either "
                                     "nominal_bending_stress or bending_stress with "
                                     "form_factor, not both", sFn))
        return sFn
    if sF is None or YF is None:
        key = "load.form_factor" if sF is not None else "load.bending_stress"
        raise InputError(Problem(key, "missing: give bending_stress with form_factor, or "
                                 "nominal_bending_stress"))
    return ST.nominal_bending_stress(sF, YF)


def _hoop(spec: ValidatedSpec) -> tuple[float, float, ST.HoopEstimate | None]:
    load, ring, pl = spec.data["load"], spec.data["ring"], spec.data["planets"]
    if load["hoop_source"] == "given":
        for key in ("hoop_stress_loaded", "hoop_stress_between"):
            if load[key] is None:
                raise InputError(Problem(f"load.{key}", 'missing: give both hoop stresses, '
                                         'or hoop_source = "thin_ring" with ring_torque'))
        if load["pressure_angle"] is not None:
            raise InputError(Problem("load.pressure_angle", 'applies only with hoop_source = '
                                     '"thin_ring"; remove it', load["pressure_angle"]))
        return load["hoop_stress_loaded"], load["hoop_stress_between"], None
    for key in ("hoop_stress_loaded", "hoop_stress_between"):
        if load[key] is not None:
            raise InputError(Problem(f"load.{key}", 'not used with hoop_source = "thin_ring" '
                                     '(the estimate replaces it); remove it', load[key]))
    if load["ring_torque"] is None:
        raise InputError(Problem("load.ring_torque", 'missing: hoop_source = "thin_ring" '
                                 'needs the ring torque'))
    if load["pressure_angle"] is None:
        _assume(spec, "load", "pressure_angle", 20.0)
    h = ST.thin_ring_hoop_stress(load["ring_torque"], ring["module"], ring["z"], pl["count"],
                                 ring["face_width"], ring["rim_thickness"],
                                 math.radians(load["pressure_angle"]))
    return h.hoop_loaded, h.hoop_between, h


@dataclass(frozen=True)
class Stage:
    name: str
    tension_fillet: str
    mu_F: float
    how: str
    share: float | None


def _stages(spec: ValidatedSpec) -> list[Stage]:
    q_F = spec.data["load"]["fatigue_exponent"]
    out, names = [], set()
    for i, s in enumerate(spec.data["stage"]):
        key = f"stage[{i}]"
        if not _NAME.match(s["name"]):
            raise InputError(Problem(f"{key}.name", "must be a lower-case name of letters, "
                                     "digits and _ starting with a letter (it names the "
                                     "result keys), e.g. \"ed_braking\"", s["name"]))
        if s["name"] in names:
            raise InputError(Problem(f"{key}.name", "used twice; stage names must differ",
                                     s["name"]))
        names.add(s["name"])
        given = [k for k in ("mu_F", "mode", "torque_levels") if s[k] is not None]
        if len(given) != 1:
            raise InputError(Problem(
                key, "give exactly one of mu_F, mode, or torque_levels with time_fractions"
                + (f" (given: {', '.join(given)})" if given else "")))
        if s["time_fractions"] is not None and s["torque_levels"] is None:
            raise InputError(Problem(f"{key}.time_fractions", "applies only with "
                                     "torque_levels", s["time_fractions"]))
        if s["mu_F"] is not None:
            mu, how = s["mu_F"], "given"
        elif s["mode"] is not None:
            mu = ST.mode_factor_from_table(mode_K_FE(s["mode"], q_F), q_F)
            how = f"GOST 21354-87 mode {s['mode']}"
        else:
            t = s["time_fractions"]
            if t is None or len(t) != len(s["torque_levels"]):
                raise InputError(Problem(f"{key}.time_fractions", f"must list one duration "
                                         f"per torque level ({len(s['torque_levels'])})", t)
                                 if t is not None else
                                 Problem(f"{key}.time_fractions", "missing: give the duration "
                                         "of each torque level"))
            mu = ST.loading_mode_factor(s["torque_levels"], t, q_F)
            how = "torque spectrum"
        out.append(Stage(s["name"], s["tension_fillet"], mu, how, s["distance_share"]))
    shares = [s.share for s in out if s.share is not None]
    if sum(shares) > 1.0 + 1e-9:
        raise InputError(Problem("stage.distance_share", f"the shares sum to "
                                 f"{sum(shares):.4g}; they must not exceed 1", shares))
    return out


def _fatigue_options(spec: ValidatedSpec) -> dict:
    if spec.data.get("fatigue") is None:
        spec.data["fatigue"] = {}
        for f in FATIGUE.fields:
            if isinstance(f, Field):
                spec.data["fatigue"][f.key] = f.default
                if f.default is not None:
                    spec.assumed.append(f"fatigue.{f.key}")
    fo = spec.data["fatigue"]
    if fo["stress_gradient"] is None and fo["concentrator_depth"] is None:
        raise InputError(Problem("fatigue.concentrator_depth", "missing: give the depth of "
                                 "the concentrator t, or the stress_gradient G directly"))
    if fo["stress_gradient"] is not None and fo["concentrator_depth"] is not None:
        raise InputError(Problem("fatigue.concentrator_depth", "not used when "
                                 "stress_gradient is given; remove one of them",
                                 fo["concentrator_depth"]))
    return fo


# ----------------------------------------------------------------------------- fatigue


def _advice(spec: ValidatedSpec, mat: Material, fo: dict, pe: E.PartEndurance,
            sigma_eq: float, P_req: float) -> str:
    """What to change when the rim fails: the fillet radius and the hardening factor that
    reach the required probability (other inputs held)."""
    fl = spec.data["fillet"]
    u = E.normal_quantile(P_req)
    v, va = pe.v, fo["stress_scatter"]
    denom = 1.0 - u * u * v * v
    parts = []
    if denom > 0.0:
        n_req = (1.0 + math.sqrt(1.0 - denom * (1.0 - u * u * va * va))) / denom
        kv = fl["hardening_factor"] * n_req * sigma_eq / pe.sigma_m1D
        parts.append(f"harden the fillets to K_V >= {math.ceil(kv * 100) / 100:.2f} "
                     f"(induction hardening, nitriding "
                     f"or roller burnishing give 2-2.5)")
    if fo["stress_concentration"] is None and fo["stress_gradient"] is None:
        def prob(rho: float) -> float:
            p = _part(spec, mat, fo, rho)
            return E.probability_of_non_failure(sigma_eq, p.sigma_m1D, p.v, va)

        lo, hi = fl["radius"], 0.5 * fl["root_chord"] * 0.999
        if prob(hi) >= P_req:
            for _ in range(50):
                mid = 0.5 * (lo + hi)
                if prob(mid) >= P_req:
                    hi = mid
                else:
                    lo = mid
            parts.insert(0, f"increase the fillet radius to ρ >= "
                         f"{math.ceil(hi * 1000) / 1000:.3f} mm (e.g. cut the "
                         f"ring with a shaper cutter of more teeth)")
    parts.append("or thicken the rim / reduce the load")
    return ", ".join(parts)


def _part(spec: ValidatedSpec, mat: Material, fo: dict, rho: float | None = None
          ) -> E.PartEndurance:
    fl, ring, m = spec.data["fillet"], spec.data["ring"], spec.data["material"]
    return E.part_endurance(
        sigma_u=mat.sigma_u, sigma_m1=mat.sigma_m1, d0=m["specimen_diameter"],
        blank_size=m["blank_size"], root_chord=fl["root_chord"],
        fillet_radius=fl["radius"] if rho is None else rho,
        radius_tol=fl["radius_tolerance"], rim_thickness=ring["rim_thickness"],
        perimeter=fo["stressed_perimeter"], Rz=fl["roughness"], K_V=fl["hardening_factor"],
        v_material=m["scatter"], alpha=fo["stress_concentration"],
        gradient=fo["stress_gradient"], depth=fo["concentrator_depth"],
        K_A=m["anisotropy_factor"], v_override=fo["scatter_total"])


def _fatigue(spec: ValidatedSpec, res: Result, pl_count: int, vehicle: dict | None,
             prepared: tuple) -> None:
    mat, stages, fo, sFn, hoop_l, hoop_b, est = prepared
    d = spec.data
    load, fl = d["load"], d["fillet"]
    model = fo["mean_stress_model"]

    pe = _part(spec, mat, fo)
    psi = ST.psi_sigma(mat.sigma_u)
    psi_D = psi / pe.K

    # -- stresses and cycles
    rs = ST.rim_stresses(sFn, hoop_l, hoop_b)
    st = res.section("stress", "Stresses at the fillets")
    if load["bending_stress"] is not None:
        st.add("sigma_F", load["bending_stress"], "MPa", "σ_F",
               "root bending stress (GOST 21354-87, given)", S.GOST21354)
    st.add("sigma_Fn", sFn, "MPa", "σ_Fn", "nominal tooth bending stress σ_F/Y_F", S.A)
    if est is not None:
        st.add("F_t", est.F_t, "N", "F_t", "tangential mesh force per planet", S.ROARK)
        st.add("F_r", est.F_r, "N", "F_r", "radial mesh force per planet", S.ROARK)
        st.add("R_m", est.R_m, "mm", "R_m", "mean radius of the rim", S.ROARK)
    st.add("hoop_loaded", hoop_l, "MPa", "σ_t,load",
           "rim hoop stress under the loaded tooth" + (" (thin-ring estimate)" if est else ""),
           S.ROARK if est else S.A)
    st.add("hoop_between", hoop_b, "MPa", "σ_t,betw",
           "rim hoop stress midway between loaded teeth" + (" (thin-ring estimate)"
                                                            if est else ""),
           S.ROARK if est else S.A)
    st.add("sigma_eq_tension", rs.eq_tension, "MPa", "σ_eq,t",
           "Huber-Mises stress, tension-side fillet of the loaded tooth", S.A + " (3)")
    st.add("sigma_eq_compression", rs.eq_compression, "MPa", "σ_eq,c",
           "Huber-Mises stress, compression-side fillet of the loaded tooth (signed)",
           S.A + " (3)")
    st.add("K_c", load["load_sharing"], "-", "K_c", "load-sharing factor between planets",
           S.A + " (1)")

    cases = []
    for s in stages:
        st.add(f"mu_F_{s.name}", s.mu_F, "-", f"μ_F ({s.name})",
               f"loading-mode factor, {s.name} ({s.how})", S.A + " (2)")
        for c in ST.fillet_cycles(rs, load["load_sharing"], s.name, s.mu_F, s.tension_fillet):
            cases.append(c)
    rows = []
    for c in cases:
        eq = ST.equivalent_amplitude(c.s_a, c.s_m, mat.sigma_u, model, psi_D)
        rows.append((c, eq))
        tag = f"{c.fillet}_{c.stage}"
        who = f"{c.fillet} fillet, {c.stage}"
        st.add(f"sigma_max_{tag}", c.s_max, "MPa", "σ_max", f"maximum stress, {who}",
               S.A + " (1)")
        st.add(f"sigma_min_{tag}", c.s_min, "MPa", "σ_min", f"minimum stress, {who}",
               S.A + " (1)")
        st.add(f"R_{tag}", c.R, "-", "R", f"stress ratio σ_min/σ_max, {who}", S.A)
        st.add(f"sigma_m_{tag}", c.s_m, "MPa", "σ_m", f"mean stress, {who}", S.A)
        st.add(f"sigma_a_{tag}", c.s_a, "MPa", "σ_a", f"stress amplitude, {who}", S.A)
        st.add(f"sigma_eq_{tag}", eq, "MPa", "σ_-1eq",
               f"equivalent symmetric amplitude ({model}), {who}", S.A + " (8)")

    valid = [(c, e) for c, e in rows if not math.isnan(e)]
    worst_dom = max(rows, key=lambda r: abs(r[0].s_m) + r[0].s_a)[0]
    worst_max = max(rows, key=lambda r: r[0].s_max)[0]
    gov_c, gov_eq = max(valid, key=lambda r: r[1]) if valid else (worst_dom, math.nan)
    gov = f"{gov_c.fillet} fillet, {gov_c.stage}"
    st.add("governing_fillet", gov_c.fillet, None, "", "governing fillet (largest σ_-1eq)", S.A)
    st.add("governing_stage", gov_c.stage, None, "", "governing stage", S.A)
    st.add("sigma_eq_max", gov_eq, "MPa", "σ_-1eq,max", "governing equivalent amplitude", S.A)
    for alt in ST.MEAN_STRESS_MODELS:
        st.add(f"sigma_eq_{alt}", ST.equivalent_amplitude(gov_c.s_a, gov_c.s_m, mat.sigma_u,
                                                          alt, psi_D),
               "MPa", f"σ_-1eq ({alt})", f"governing case by the {alt} diagram",
               S.A + " (4), (8); " + S.GOST25504)

    # -- endurance limit of the part
    en = res.section("endurance", "Endurance limit of the rim (GOST 25.504-82)")
    en.add("K1", pe.K1, "-", "K1", "blank-size factor", S.A + " (9)")
    en.add("alpha_sigma", pe.alpha, "-", "α_σ",
           "theoretical SCF of the fillet" + (" (given)" if fo["stress_concentration"]
                                              else ""), S.A + " (12)")
    en.add("dalpha_drho", pe.alpha_slope, "1/mm", "|∂α_σ/∂ρ|", "slope of the SCF in ρ",
           S.A + " (15)")
    en.add("G", pe.gradient, "1/mm", "G", "relative stress gradient"
           + (" (given)" if fo["stress_gradient"] else ""), S.GOST25504)
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
    en.add("psi_sigma", psi, "-", "ψ_σ", "mean-stress sensitivity of the material",
           S.GOST25504)
    en.add("psi_sigmaD", psi_D, "-", "ψ_σD", "mean-stress sensitivity of the part ψ_σ/K",
           S.GOST25504)
    en.add("v_sigma_max", pe.v_max, "-", "v_σmax", "variation of the failure stress",
           S.GOST25504)
    en.add("v_sigma_m1", d["material"]["scatter"], "-", "v_σ-1",
           "variation of σ_-1 between heats", S.GOST25504)
    en.add("v_alpha_sigma", pe.v_alpha, "-", "v_ασ", "variation of the SCF", S.A + " (15)")
    en.add("v_sigma_m1D_eq14", pe.v_computed, "-", "v_σ-1D (14)",
           "variation of the part endurance limit by eq. (14)", S.A + " (14)")
    en.add("v_sigma_m1D", pe.v, "-", "v_σ-1D", "variation of the part endurance limit used"
           + (" (given)" if fo["scatter_total"] else ""), S.A + " (14)")

    probs = [p / 100.0 for p in fo["probabilities"]]
    for P in probs + [fo["required_probability"] / 100.0]:
        if 1.0 - E.normal_quantile(P) * pe.v <= 0.0:
            key = ("fatigue.probabilities" if P in probs else "fatigue.required_probability")
            pmax = 100.0 * E.normal_cdf(1.0 / pe.v)
            raise InputError(Problem(key, f"P = {P * 100:g} % makes σ_-1D(P) = σ_-1D·(1 − z_P·v)"
                                     f" <= 0 with v = {pe.v:.4g}; use P < {pmax:.2f} %",
                                     fo["probabilities"] if P in probs
                                     else fo["required_probability"]))
    zs = [E.normal_quantile(P) for P in probs]
    en.add("P_table", [p * 100.0 for p in probs], "%", "P", "probabilities of non-failure",
           S.A + " Table 2")
    en.add("z_P", zs, "-", "z_P", "normal quantiles", S.A + " (13)")
    en.add("xi_P", [1.0 - z * pe.v for z in zs], "-", "ξ(P)", "relative endurance limit "
           "1 − z_P·v", S.A + " (16)")
    en.add("sigma_m1D_P", [E.quantile_endurance(pe.sigma_m1D, pe.v, P) for P in probs],
           "MPa", "σ_-1D(P)", "endurance limit of the rim at P", S.A + " (13)")

    # -- probability and life
    lf = res.section("life", "Probability of non-failure and life")
    va = fo["stress_scatter"]
    for c, eq in rows:
        tag = f"{c.fillet}_{c.stage}"
        n = pe.sigma_m1D / eq if not math.isnan(eq) else math.nan
        P = E.probability_of_non_failure(eq, pe.sigma_m1D, pe.v, va) if n == n else math.nan
        lf.add(f"n_{tag}", n, "-", "n", f"safety factor σ_-1D/σ_-1eq, {c.fillet} fillet, "
               f"{c.stage}", S.GOST25504)
        lf.add(f"P_{tag}", P * 100.0, "%", "P", f"probability of non-failure, {c.fillet} "
               f"fillet, {c.stage}", S.GOST25504)
    P_gov = (E.probability_of_non_failure(gov_eq, pe.sigma_m1D, pe.v, va)
             if gov_eq == gov_eq else math.nan)
    lf.add("n", pe.sigma_m1D / gov_eq, "-", "n", f"safety factor, governing case ({gov})",
           S.GOST25504)
    lf.add("P", P_gov * 100.0, "%", "P", f"probability of non-failure, governing case",
           S.GOST25504)
    m_slope = E.sn_slope(mat.sigma_u, pe.K)
    lf.add("m", m_slope, "-", "m", "slope of the S-N curve of the rim", S.GOST25504)
    NG, al, be = fo["knee_cycles"], fo["slgn_alpha"], fo["slgn_beta"]

    def lgN(eq: float, P: float) -> float:
        if eq != eq:
            return math.nan
        return E.lg_life(eq, pe.sigma_m1D, pe.v, P, m_slope, NG, al, be)

    lg_gov = [lgN(gov_eq, P) for P in probs]
    lf.add("lg_N_P", lg_gov, "-", "lg N_P", "life of the governing case at P (∞ shown as —)",
           S.A + " (21)")
    lf.add("N_P", [(10.0 ** x if x > -300.0 else 0.0) if math.isfinite(x) else math.inf
                   for x in lg_gov], "cycles",
           "N_P", "cycles to failure of the governing case at P", S.A + " (21)")

    if vehicle is not None and all(s.share is not None for s in stages):
        per_km = pl_count * vehicle["carrier_ratio"] * 1e6 / (2.0 * math.pi
                                                             * vehicle["wheel_radius"])
        lf.add("cycles_per_km", per_km, "1/km", "n_km", "stress cycles of a fillet per km",
               S.KINEMATICS)
        for fillet in ST.FILLETS:
            lives = []
            for P in probs:
                dmg = 0.0
                for c, eq in rows:
                    if c.fillet != fillet:
                        continue
                    share = next(s.share for s in stages if s.name == c.stage)
                    x = lgN(eq, P)
                    if x != x:
                        dmg = math.nan
                    elif math.isfinite(x):
                        # lg N_P < -300: no cycle at all (10**x underflows); the scatter
                        # check below says which coefficients put the model there
                        dmg += share * per_km * 10.0 ** -x if x > -300.0 else math.inf
                lives.append(math.inf if dmg == 0.0 else (math.nan if dmg != dmg
                                                          else 1.0 / dmg))
            lf.add(f"life_km_{fillet}", lives, "km", "L_km", f"life of the {fillet} fillet at P "
                   f"(Miner over the stages; ∞ shown as —)", S.MINER)

    # -- checks
    P_req = fo["required_probability"] / 100.0
    ck = res.checks
    ck.append(C.domain_check(abs(worst_dom.s_m) + worst_dom.s_a, mat.sigma_u,
                             f"{worst_dom.fillet} fillet, {worst_dom.stage}"))
    ck.extend(C.yield_checks(worst_max.s_max, mat.sigma_y,
                             f"{worst_max.fillet} fillet, {worst_max.stage}"))
    if gov_eq == gov_eq:
        fails = P_gov < P_req or gov_eq > pe.sigma_m1D
        advice = _advice(spec, mat, fo, pe, gov_eq, P_req) if fails else ""
        ck.append(C.endurance_check(gov_eq, pe.sigma_m1D, gov, advice))
        ck.append(C.probability_check(P_gov, P_req, gov, advice))
    below_one = [x for x in lg_gov if x < 0.0]
    if below_one:
        sb = gov_eq / pe.sigma_m1D
        s_lgn = 10.0 ** min(al + be * math.log10(sb), 300.0)
        ck.append(check(
            "SN_SCATTER_DOMAIN", False, "error",
            f"the S-N scatter model gives less than one cycle (lg N_P = {min(below_one):.3g}): "
            f"S_lgN = 10^(α + β·lg σ̄) = {s_lgn:.3g} decades at σ̄ = {sb:.3g}, where the scatter "
            f"of steels is 0.05...1; check fatigue.slgn_alpha = {al:g} and fatigue.slgn_beta "
            f"= {be:g}", "", s_lgn, 1.0, S.A + " (17)-(21)"))
    ck.append(C.range_warning("ENDURANCE_RATIO", mat.sigma_m1 / mat.sigma_u,
                              *C.ENDURANCE_RATIO, "σ_-1/σ_u",
                              "check the material data", S.PRACTICE))
    ck.append(C.range_warning("LOAD_SHARING", load["load_sharing"], *C.LOAD_SHARING, "K_c",
                              "unusual load-sharing factor; check it", S.PRACTICE))
    if load["form_factor"] is not None:
        ck.append(C.range_warning("FORM_FACTOR", load["form_factor"], *C.FORM_FACTOR, "Y_F",
                                  "unusual tooth form factor; check it", S.PRACTICE))
    for code, value, what in (("SCATTER_MATERIAL", d["material"]["scatter"], "v_σ-1"),
                              ("SCATTER_TOTAL", pe.v, "v_σ-1D")):
        ck.append(C.range_warning(code, value, *C.SCATTER_RANGE, what,
                                  "unusual coefficient of variation; check it", S.PRACTICE))
    if fl["roughness"] < C.RZ_MIN:
        ck.append(C.range_warning("ROUGHNESS", fl["roughness"], C.RZ_MIN, 320.0, "Rz [µm]",
                                  "below the range of the roughness factor", S.GOST25504))
    if est is not None:
        ck.append(C.hoop_estimate_warning(hoop_l, hoop_b))


# ----------------------------------------------------------------------------- resonance


@dataclass(frozen=True)
class ResonancePrep:
    phases: list
    pulsation: mesh.Pulsation
    exc: R.Excitation
    orders: list
    bands: list


def _prepare_resonance(spec: ValidatedSpec, angles: list[float]) -> ResonancePrep:
    d = spec.data
    rz, ring, pl = d["resonance"], d["ring"], d["planets"]
    eps = pl["contact_ratio"]
    if eps is None:
        raise InputError(Problem("planets.contact_ratio", "missing: [resonance] needs the "
                                 "transverse contact ratio of the ring-planet mesh"))
    phases = mesh.mesh_phases(angles, ring["z"], rz["phase_model"])
    p = mesh.pulsation(phases, eps, rz["harmonics"])
    exc = R.excitation(p, rz["depth"])
    orders = sorted(set(rz["orders"]))
    bands = [M.band_exact(n, exc.mu) for n in orders]
    if rz["chart_b_max"] is None:
        _assume(spec, "resonance", "chart_b_max",
                max(0.5, 1.25 * 0.5 * exc.mu * max(b.a_hi for b in bands)))
    return ResonancePrep(phases, p, exc, orders, bands)


def _resonance(spec: ValidatedSpec, res: Result, angles: list[float], vehicle: dict | None,
               prep: ResonancePrep) -> None:
    d = spec.data
    rz = d["resonance"]
    ring, pl = d["ring"], d["planets"]
    eps = pl["contact_ratio"]
    z = ring["z"]
    phases, p, exc, orders, bands = prep.phases, prep.pulsation, prep.exc, prep.orders, prep.bands
    sec = res.section("resonance", "Parametric resonance of the ring")
    sec.add("phases", list(phases), "-", "γ", f"ring-planet mesh phases, fractions of a pitch "
            f"({rz['phase_model']} model)", S.PHASING if rz["phase_model"] == "actual" else S.B)
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

    for n, b in zip(orders, bands):
        sec.add(f"a_n{n}", [b.a_lo, b.a_hi], "-", f"a (n = {n})", f"instability region {n} "
                f"along b = μa/2 (exact characteristic values)", S.MATHIEU)
        sec.add(f"Omega_ratio_n{n}", [b.ratio_lo, b.ratio_hi], "-", f"Ω/k0 (n = {n})",
                f"excitation over natural frequency, region {n}", S.B + " (6)")
        if n in M.SERIES_ORDERS:
            bs = M.band_series(n, exc.mu)
            sec.add(f"a_series_n{n}", [bs.a_lo, bs.a_hi], "-", f"a (series, n = {n})",
                    f"region {n} by paper B's series (8)", S.MATHIEU_SERIES)
    if 1 in orders:
        bl = M.band_linear(exc.mu)
        sec.add("a_linear_n1", [bl.a_lo, bl.a_hi], "-", "a (1 ± b)", "region 1 by the "
                "two-term harmonic balance", S.B + " (7)")

    if rz["stiffness_model"] == "stepwise":
        used = R.order_bands(p, exc, orders, "stepwise")
        for ob in used:
            sec.add(f"mesh_ratio_stepwise_n{ob.order}",
                    None if ob.mesh_lo is None else [ob.mesh_lo, ob.mesh_hi], "-",
                    f"f_m/k0 (n = {ob.order})", f"unstable mesh-frequency ratio, stepwise "
                    f"stiffness (null: narrower than the search)", S.FLOQUET)
    else:
        used = R.order_bands(p, exc, orders, "sinusoid")

    k0s = rz["natural_frequencies"]
    sec.add("k0", list(k0s), "Hz", "k0", "natural frequencies of the ring", S.B)
    hits, n_hits = [], 0
    v_range = vehicle["speed_range"] if vehicle is not None else None
    for ob in used:
        n = ob.order
        omega = [R.resonance_frequency(k, n) for k in k0s]
        f_m = [o / exc.h for o in omega]
        sec.add(f"Omega_n{n}", omega, "Hz", f"Ω (a = {n * n})", f"excitation frequency of "
                f"resonance {n}, 2k0/n", S.B + " (10)")
        sec.add(f"f_mesh_n{n}", f_m, "Hz", f"f_m (a = {n * n})", f"mesh frequency at "
                f"resonance {n}, Ω/h", S.KINEMATICS)
        if ob.mesh_lo is not None:
            sec.add(f"f_mesh_band_n{n}", [[ob.mesh_lo * k, ob.mesh_hi * k] for k in k0s], "Hz",
                    f"f_m band (n = {n})", f"unstable mesh-frequency band of resonance {n} "
                    f"per k0", S.B + " (6)")
        if vehicle is None:
            continue
        V = [R.speed_from_mesh_frequency(f, z, vehicle["wheel_radius"],
                                         vehicle["carrier_ratio"]) for f in f_m]
        sec.add(f"V_n{n}", V, "km/h", f"V (a = {n * n})", f"vehicle speed at resonance {n}",
                S.KINEMATICS)
        if ob.mesh_lo is not None:
            Vb = [[R.speed_from_mesh_frequency(ob.mesh_lo * k, z, vehicle["wheel_radius"],
                                               vehicle["carrier_ratio"]),
                   R.speed_from_mesh_frequency(ob.mesh_hi * k, z, vehicle["wheel_radius"],
                                               vehicle["carrier_ratio"])] for k in k0s]
            sec.add(f"V_band_n{n}", Vb, "km/h", f"V band (n = {n})", f"vehicle speeds of the "
                    f"unstable band of resonance {n} per k0", S.KINEMATICS)
        else:
            continue  # no unstable band found (narrower than the search): no resonance
        if v_range is not None:
            for k, (lo, hi) in zip(k0s, Vb):
                if hi > lo and R.overlaps(lo, hi, v_range[0], v_range[1]):
                    n_hits += 1
                    hits.append(f"n = {n}, k0 = {k:g} Hz at {lo:.1f}…{hi:.1f} km/h")
    if v_range is not None:
        res.checks.append(C.resonance_check(hits, n_hits, v_range))

    # -- Ince-Strutt chart as data
    chart = M.stability_chart(max(orders), rz["chart_b_max"], rz["chart_points"])
    for key, values in chart.items():
        name = ("b grid (q of Mathieu's equation)" if key == "b" else
                f"characteristic value {key[0]}_{key[1:]}(b)")
        sec.add(f"chart_{key}", values, "-", key, f"Ince-Strutt chart: {name}", S.MATHIEU)
    if exc.mu > 0.0:
        sec.add("chart_line_a", [2.0 * q / exc.mu for q in chart["b"]], "-", "a = 2b/μ",
                "Ince-Strutt chart: working line b = μa/2", S.B + " (6)")

    if rz["floquet_check"]:
        devs = []
        for n, b in zip(orders, bands):
            fb = M.floquet_band(n, exc.mu, b)
            sec.add(f"a_floquet_n{n}", None if fb is None else list(fb), "-",
                    f"a (Floquet, n = {n})", f"region {n} located by numerical integration "
                    f"(null: too narrow to bracket)", S.FLOQUET)
            if fb is not None:
                devs.append(max(abs(fb[0] - b.a_lo), abs(fb[1] - b.a_hi)))
        dev = max(devs, default=0.0)
        sec.add("floquet_max_dev", dev, "-", "max |Δa|", "largest difference between the "
                "Floquet and the characteristic-value boundaries", S.FLOQUET)
        res.checks.append(C.floquet_check_result(dev, FLOQUET_TOL))

    if rz["phase_model"] == "paper":
        pa = mesh.pulsation(mesh.mesh_phases(angles, z, "actual"), eps, rz["harmonics"])
        ea = R.excitation(pa, rz["depth"])
        res.checks.append(C.phase_model_warning(exc.mu, ea.mu, ea.h))


# ----------------------------------------------------------------------------- geometry


def _geometry(spec: ValidatedSpec, res: Result, angles: list[float]) -> None:
    from geardesign.spur.geometry import BasicRack, GeometryError, PairInput, pair_geometry

    ring, pl = spec.data["ring"], spec.data["planets"]
    m, z, delta, h = ring["module"], ring["z"], ring["rim_thickness"], ring["tooth_height"]
    g = res.section("geometry", "Ring and planets")
    g.add("d", m * z, "mm", "d", "reference diameter of the ring", S.KINEMATICS)
    g.add("pitch_angle", 360.0 / z, "deg", "φ_w", "angular pitch of the ring", S.B + " (3)")
    g.add("angles", list(angles), "deg", "ψ", "planet angles on the carrier", S.B + " (4)")
    m_B = rim.backup_ratio(delta, h)
    Y_B = rim.rim_factor_iso_internal(delta, m)
    K_B = rim.rim_factor_agma(m_B)
    g.add("delta_m", delta / m, "-", "δ/m", "rim thickness over module", S.ISO6336_3)
    g.add("Y_B", Y_B if Y_B == Y_B else None, "-", "Y_B", "ISO 6336-3 rim thickness factor, "
          "internal gear (null: outside δ/m > 1.75)", S.ISO6336_3)
    g.add("m_B", m_B, "-", "m_B", "backup ratio δ/h", S.ISO6336_3)
    g.add("K_B", K_B, "-", "K_B", "AGMA rim thickness factor", S.ISO6336_3)
    g.add("failure_mode", rim.failure_mode(delta, h), None, "", "likely fatigue failure mode "
          "(δ > h: tooth breakage, else rim fracture)", S.A)
    res.checks.append(C.rim_thickness_check(delta / m, Y_B, m_B, K_B))

    if pl["z_sun"] is None:
        return
    zs, zp = pl["z_sun"], pl["z_planet"]
    dz = z - zs - 2 * zp
    g.add("coaxiality", dz, "-", "z_r − z_s − 2z_p", "coaxiality (0 without profile shifts)",
          S.KINEMATICS)
    rel = [a - angles[0] for a in angles]
    idx = [mesh.assembly_index(a, zs, z) for a in rel]
    step = mesh.assembly_step(zs, z)
    g.add("assembly_index", idx, "-", "(z_s + z_r)θ/360", "assembly indices (integers "
          "needed)", S.ASSEMBLY)
    g.add("assembly_step", step, "deg", "Δθ", "step of assemblable planet angles",
          S.ASSEMBLY)
    try:
        pg = pair_geometry(PairInput(m, zs, zp, pl["x_sun"], pl["x_planet"], 0.0,
                                     ring["face_width"], BasicRack(math.radians(20.0))))
    except GeometryError as exc:
        raise InputError(Problem("planets.x_planet", f"no sun-planet pair with these shifts "
                                 f"({exc}); check x_sun and x_planet", pl["x_planet"])) from None
    limit = mesh.spacing_limit(pg.g2.d_a, pg.a_w)
    gap = mesh.min_spacing(angles)
    g.add("a_w", pg.a_w, "mm", "a_w", "sun-planet centre distance (GOST 13755 rack)",
          "GOST 16532-70")
    g.add("d_a_planet", pg.g2.d_a, "mm", "d_a,p", "tip diameter of a planet", "GOST 16532-70")
    g.add("spacing_min", gap, "deg", "Δψ_min", "smallest angle between neighbouring planets",
          S.ASSEMBLY)
    g.add("spacing_limit", limit, "deg", "Δψ_lim", "least angle for clear tip circles",
          S.ASSEMBLY)
    res.checks.append(C.assembly_check(idx, mesh.nearest_assemblable(rel, zs, z), step))
    res.checks.append(C.spacing_check(gap, limit))
    if dz != 0:
        res.checks.append(C.coaxiality_warning(dz))


# ----------------------------------------------------------------------------- entry


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.epicycle_rim import CALCULATOR

    fatigue, resonance = _check_tables(spec)
    angles = _ring_and_planets(spec)
    d = spec.data
    vehicle = d.get("vehicle")
    if vehicle is not None and vehicle["speed_range"] is not None:
        lo, hi = vehicle["speed_range"]
        if not lo < hi:
            raise InputError(Problem("vehicle.speed_range", "must be [lowest, highest] with "
                                     "lowest < highest", vehicle["speed_range"]))
    prepared = None
    if fatigue:
        fl = d["fillet"]
        if fl["radius"] >= 0.5 * fl["root_chord"]:
            raise InputError(Problem("fillet.radius", f"must be less than half the root chord "
                                     f"S/2 = {_fmt(0.5 * fl['root_chord'])} mm", fl["radius"]))
        mat = _material(spec)
        sFn = _nominal_bending(d["load"])
        hoop_l, hoop_b, est = _hoop(spec)
        stages = _stages(spec)
        fo = _fatigue_options(spec)
        if fo["stressed_perimeter"] is None:
            _assume(spec, "fatigue", "stressed_perimeter", 2.0 * d["ring"]["face_width"])
        prepared = (mat, stages, fo, sFn, hoop_l, hoop_b, est)
    prep_r = _prepare_resonance(spec, angles) if resonance else None
    res = CALCULATOR.new_result(spec)
    _geometry(spec, res, angles)
    if fatigue:
        _fatigue(spec, res, d["planets"]["count"], vehicle, prepared)
    if resonance:
        _resonance(spec, res, angles, vehicle, prep_r)
    return res
