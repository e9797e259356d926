"""The report of an analysed shaft: the material, the beam model, the diagrams along the
shaft, the tables of supports, loads and rated places, the critical places and the checks
(:mod:`geardesign.shaft.checks`).  ``m`` is the typed inputs read by
:func:`geardesign.shaft.inputs.model`, ``r`` the record of
:func:`geardesign.shaft.solve.analyse`."""

from __future__ import annotations

import math

from geardesign.core.result import DataTable, Result
from geardesign.core.spec import ValidatedSpec
from geardesign.shaft import sources as S
from geardesign.shaft.checks import shaft_checks, units_checks
from geardesign.shaft.records import ARCMIN, Inputs, ShaftRecord
from geardesign.shaft.scaling import scale_to_pass

def report(spec: ValidatedSpec, m: Inputs, r: ShaftRecord) -> Result:
    """Rows, tables and checks of an analysed shaft (``m`` from :func:`model`)."""
    from geardesign.shaft import CALCULATOR

    model_ = m
    mat, origin, steps = m.material, m.origin or {}, m.steps
    loads, supports, opt = m.loads, m.supports, m.options
    res = CALCULATOR.new_result(spec)
    lim = spec.data["shaft"]

    din = opt.method == "DIN743"
    if din:
        res.methods[:] = [x for x in res.methods if not x.startswith("GOST")] + [S.DIN_METHOD]
        _din_material_rows(res, mat, origin)
    else:
        m = res.section("material", "Material")
        m.add("sigma_B", mat.sigma_B, "MPa", "σ_B", "ultimate tensile strength",
              S.MATERIAL if origin.get("sigma_B") == "grade" else "input")
        m.add("sigma_T", mat.sigma_T, "MPa", "σ_T", "yield strength",
              S.MATERIAL if origin.get("sigma_T") == "grade" else "input")
        m.add("sigma_m1", mat.sigma_m1, "MPa", "σ_-1", "endurance limit, rotating bending",
              {"grade": S.MATERIAL, "given": "input"}.get(origin.get("sigma_m1"), S.ESTIMATE))
        m.add("tau_m1", mat.tau_m1, "MPa", "τ_-1", "endurance limit, torsion",
              {"grade": S.MATERIAL, "given": "input"}.get(origin.get("tau_m1"), S.ESTIMATE))
        m.add("psi_sigma", mat.psi_sigma, "-", "ψ_σ", "mean-stress sensitivity, bending",
              "input" if spec.data["material"]["psi_sigma"] is not None else "[GOST25504]")
        m.add("psi_tau", mat.psi_tau, "-", "ψ_τ", "mean-stress sensitivity, torsion",
              {"grade": S.MATERIAL, "given": "input"}.get(origin.get("psi_tau"), "[GOST25504]"))
        m.add("alloy", mat.alloy, None, "", "alloy steel (size factor in bending)", S.TABLES)

    g = res.section("shaft", "Shaft and beam model")
    g.add("length", r.length, "mm", "L", "length of the shaft", "input")
    g.add("mass", r.mass, "kg", "m", "mass of the shaft", "ρ·ΣA·l")
    g.add("nodes", len(r.x), None, "n", "finite-element nodes", S.FE)
    g.add("omega_cr", r.omega_cr, "rad/s", "ω_cr",
          "first bending natural frequency (eigenvalue, shaft and part masses)", S.EIGEN)
    g.add("n_cr", r.n_cr, "min^-1", "n_cr", "first bending critical speed", S.EIGEN)
    g.add("n_cr_ratio", r.n_cr / opt.speed, "-", "n_cr/n", "critical speed over the speed",
          S.EIGEN)
    w_max = max(r.w)
    g.add("w_max", w_max, "mm", "w_max", "largest deflection", S.FE)
    g.add("x_w_max", r.x[r.w.index(w_max)], "mm", "x(w_max)", "where it occurs", S.FE)

    res.tables.append(_support_table(r))
    res.tables.append(_load_table(r))
    res.tables.extend(_section_tables(r, din))

    dg = res.section("diagrams", "Diagrams along the shaft (arrays over x)")
    dg.add("x", r.x, "mm", "x", "position of the nodes", S.FE)
    dg.add("M_y", r.M_y, "N·m", "M_y", "bending moment, x–y plane (just right of x)", S.FE)
    dg.add("M_z", r.M_z, "N·m", "M_z", "bending moment, x–z plane", S.FE)
    dg.add("M", r.M, "N·m", "M", "resultant bending moment", S.FE)
    dg.add("V_y", r.V_y, "N", "V_y", "shear force, x–y plane", S.FE)
    dg.add("V_z", r.V_z, "N", "V_z", "shear force, x–z plane", S.FE)
    dg.add("T", r.T, "N·m", "T", "torque", S.STATICS)
    dg.add("N", r.N, "N", "N", "axial force (tension +)", S.STATICS)
    dg.add("w_y", r.w_y, "mm", "w_y", "deflection in y", S.FE)
    dg.add("w_z", r.w_z, "mm", "w_z", "deflection in z", S.FE)
    dg.add("w", r.w, "mm", "w", "resultant deflection", S.FE)
    dg.add("slope", r.slope, "rad", "θ", "resultant slope", S.FE)

    c = r.critical
    st = res.section("strength", "Strength: critical sections")
    if c is not None:
        fat = S.DIN_FATIGUE if din else S.FATIGUE
        stat = S.DIN_STATIC if din else S.VON_MISES
        st.add("critical_section", c.label, None, "", "section of the lowest fatigue safety",
               fat)
        st.add("x_critical", c.x, "mm", "x", "its position", fat)
        st.add("S", c.S, "-", "S", "lowest fatigue safety factor", fat)
        st.add("S_min", lim["S_min"], "-", "[S]", "required",
               S.DIN_LIMIT if din else S.FATIGUE_LIMIT)
        cs = r.critical_static
        st.add("critical_section_static", cs.label, None, "",
               "section of the lowest static safety", stat)
        st.add("S_static", cs.S_static, "-", "S_T", "lowest static safety factor (peak load)",
               stat)
        st.add("S_static_min", lim["S_static_min"], "-", "[S_T]", "required",
               S.DIN_LIMIT if din else S.STATIC_LIMIT)
    scale = {}
    if c is not None:
        if c.S < lim["S_min"]:
            scale["S"] = scale_to_pass(spec, model_, "S", lim["S_min"])
        if r.critical_static.S_static < lim["S_static_min"]:
            scale["S_static"] = scale_to_pass(spec, model_, "S_static",
                                              lim["S_static_min"])
    res.checks.extend(shaft_checks(r, lim, opt.speed, loads, supports, origin, steps, mat.sigma_B,
                              din, mat.din.d_eff if din else 0.0, scale))
    res.checks.extend(units_checks(r, spec))
    return res


def _din_material_rows(res: Result, mat, origin: dict) -> None:
    """The material section of the DIN 743 method: the steel at d_B and at d_eff."""
    dm = mat.din
    st = dm.steel
    m = res.section("material", "Material (DIN 743-3)")
    src = S.DIN_STEEL if origin.get("grade") else "input"
    if origin.get("grade"):
        m.add("grade", st.name, None, "", "EN grade of DIN 743-3"
              + (f" (for GOST {origin['gost']})" if origin.get("gost") else ""), S.DIN_STEEL)
    m.add("steel_type", st.type, None, "", "steel type (K_1)", src)
    m.add("sigma_B_dB", st.sigma_B, "MPa", "σ_B(d_B)", "tensile strength at d_B",
          src if origin.get("sigma_B") == "grade" else "input")
    m.add("sigma_S_dB", st.sigma_S, "MPa", "σ_S(d_B)", "yield strength at d_B",
          src if origin.get("sigma_T") == "grade" else "input")
    m.add("d_B", st.d_B, "mm", "d_B", "reference diameter (σ_B)", S.DIN_STEEL)
    m.add("d_eff", dm.d_eff, "mm", "d_eff", "blank diameter at heat treatment",
          "input" if origin.get("d_eff") == "given" else "largest step diameter")
    m.add("K_1B", dm.K_1B, "-", "K_1B(d_eff)", "technological size factor, tensile",
          S.DIN_K1)
    m.add("K_1S", dm.K_1S, "-", "K_1S(d_eff)", "technological size factor, yield",
          S.DIN_K1)
    m.add("sigma_B", dm.sigma_B_d, "MPa", "σ_B(d)", "tensile strength of the blank",
          S.DIN_K1)
    m.add("sigma_T", dm.sigma_S_d, "MPa", "σ_S(d)", "yield strength of the blank", S.DIN_K1)
    m.add("sigma_bW", 0.5 * st.sigma_B, "MPa", "σ_bW(d_B)", "endurance limit, bending",
          S.DIN_STEEL)
    m.add("tau_tW", 0.3 * st.sigma_B, "MPa", "τ_tW(d_B)", "endurance limit, torsion",
          S.DIN_STEEL)


def _support_table(r: ShaftRecord) -> DataTable:
    t = DataTable("supports", "Supports: reactions (force on the shaft) and slopes", [
        ("name", "support", None), ("x", "x", "mm"), ("R_y", "R_y", "N"), ("R_z", "R_z", "N"),
        ("R", "R", "N"), ("R_x", "R_x", "N"), ("w", "w", "mm"),
        ("slope", "θ", "arcmin")])
    for p in r.supports:
        t.rows.append({"name": p.name, "x": p.x, "R_y": p.R_y, "R_z": p.R_z,
                       "R": math.hypot(p.R_y, p.R_z), "R_x": p.R_x, "w": p.w,
                       "slope": p.slope / ARCMIN})
    return t


def _load_table(r: ShaftRecord) -> DataTable:
    t = DataTable("loads", "Loads: deflection and slope", [
        ("name", "load", None), ("x", "x", "mm"), ("w_y", "w_y", "mm"), ("w_z", "w_z", "mm"),
        ("w", "w", "mm"), ("slope", "θ", "arcmin")])
    for p in r.loads:
        t.rows.append({"name": p.name, "x": p.x, "w_y": p.w_y, "w_z": p.w_z, "w": p.w,
                       "slope": p.slope / ARCMIN})
    return t


def _din_fatigue_table(r: ShaftRecord) -> DataTable:
    """Fatigue and static safety of every section by DIN 743 (the governing notch)."""
    f = DataTable("fatigue", "Sections: fatigue and static safety (" + S.DIN_FATIGUE + ")", [
        ("label", "section", None), ("concentrator", "notch", None),
        ("beta_sigma", "β_σ", "-"), ("beta_tau", "β_τ", "-"),
        ("K_2", "K_2", "-"), ("K_F", "K_Fσ", "-"), ("K_sigma", "K_σ", "-"),
        ("K_tau", "K_τ", "-"), ("sigma_WK", "σ_WK", "MPa"), ("tau_WK", "τ_WK", "MPa"),
        ("psi_sigma", "ψ_σK", "-"), ("psi_tau", "ψ_τK", "-"),
        ("sigma_ADK", "σ_ADK", "MPa"), ("tau_ADK", "τ_ADK", "MPa"), ("S", "S", "-"),
        ("sigma_FK", "σ_FK", "MPa"), ("S_static", "S_Verform", "-")])
    for s in r.sections:
        d = s.din
        f.rows.append({"label": s.label, "concentrator": s.concentrator,
                       "beta_sigma": d.notch.beta_b, "beta_tau": d.notch.beta_t,
                       "K_2": d.K_2, "K_F": d.K_F_sigma, "K_sigma": d.K_sigma,
                       "K_tau": d.K_tau, "sigma_WK": d.sigma_WK, "tau_WK": d.tau_WK,
                       "psi_sigma": d.psi_sigma, "psi_tau": d.psi_tau,
                       "sigma_ADK": d.sigma_ADK, "tau_ADK": d.tau_ADK, "S": s.S,
                       "sigma_FK": d.sigma_FK, "S_static": s.S_static})
    return f


def _section_tables(r: ShaftRecord, din: bool = False) -> list[DataTable]:
    t = DataTable("sections", "Sections: loads and stresses (static at the peak load)", [
        ("label", "section", None), ("x", "x", "mm"), ("d", "d", "mm"), ("M", "M", "N·m"),
        ("T", "T", "N·m"), ("N", "N", "N"), ("sigma_a", "σ_a", "MPa"),
        ("sigma_m", "σ_m", "MPa"), ("tau_a", "τ_a", "MPa"), ("tau_m", "τ_m", "MPa"),
        ("sigma_v_peak", "σ_v,peak", "MPa"), ("S_static", "S_T", "-")])
    f = DataTable("fatigue", "Sections: fatigue (" + S.FATIGUE + ")", [
        ("label", "section", None), ("concentrator", "concentrator", None),
        ("K_sigma_Kd", "K_σ/K_dσ", "-"), ("K_tau_Kd", "K_τ/K_dτ", "-"), ("K_F", "K_Fσ", "-"),
        ("K_sigma_D", "K_σD", "-"), ("K_tau_D", "K_τD", "-"), ("S_sigma", "S_σ", "-"),
        ("S_tau", "S_τ", "-"), ("S", "S", "-")])
    for s in r.sections:
        t.rows.append({"label": s.label, "x": s.x, "d": s.d, "M": s.M, "T": s.T, "N": s.N,
                       "sigma_a": s.sigma_a, "sigma_m": s.sigma_m, "tau_a": s.tau_a,
                       "tau_m": s.tau_m, "sigma_v_peak": s.sigma_v_peak,
                       "S_static": s.S_static})
        f.rows.append({"label": s.label, "concentrator": s.concentrator,
                       "K_sigma_Kd": s.ratio_sigma, "K_tau_Kd": s.ratio_tau,
                       "K_F": s.K_F_sigma, "K_sigma_D": s.K_sigma_D, "K_tau_D": s.K_tau_D,
                       "S_sigma": s.S_sigma, "S_tau": s.S_tau, "S": s.S})
    return [t, _din_fatigue_table(r) if din else f]
