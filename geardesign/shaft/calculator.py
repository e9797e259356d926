"""``kind = "shaft"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

:mod:`.inputs` turns the spec into plain data, :func:`.solve.analyse` computes, and this
module writes the rows, the tables and the checks (with advice).
"""

from __future__ import annotations

import math
from dataclasses import replace

from geardesign.core.errors import InputError, Problems
from geardesign.core.result import DataTable, Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.shaft import inputs as IN
from geardesign.shaft import sources as S
from geardesign.shaft import strength as ST
from geardesign.shaft.solve import ARCMIN, ShaftResult, analyse


def model(spec: ValidatedSpec) -> dict:
    """The plain data of :func:`.solve.analyse` read from the spec (every input rule): the
    method's defaults, the steps, the material, the loads and the supports are checked
    independently, and every problem is reported at once."""
    problems = Problems()
    problems.stage(IN.resolve_defaults, spec)
    steps = problems.stage(IN.steps, spec)
    rows = spec.data["step"]
    d_max = problems.stage(lambda: max(s["diameter"] for s in rows))
    how = problems.stage(IN.method, spec)
    mat = (problems.stage(IN.material, spec.data["material"], how, d_max)
           if how is not Problems.FAILED else Problems.FAILED)
    length = problems.stage(lambda: sum(s["length"] for s in rows))
    length = None if length is Problems.FAILED else length
    loads = problems.stage(IN.loads, spec, length)
    supports = problems.stage(IN.supports, spec, length)
    problems.raise_all()
    mat, origin = mat
    return dict(steps=steps, loads=loads, supports=supports, material=mat,
                options=IN.options(spec), origin=origin)


def compute(spec: ValidatedSpec) -> Result:
    m = model(spec)
    r = analyse(m["steps"], m["loads"], m["supports"], m["material"], m["options"])
    return report(spec, m, r)


def report(spec: ValidatedSpec, m: dict, r: ShaftResult) -> Result:
    """Rows, tables and checks of an analysed shaft (``m`` from :func:`model`)."""
    from geardesign.shaft import CALCULATOR

    model_ = m
    mat, origin, steps = m["material"], m["origin"], m["steps"]
    loads, supports, opt = m["loads"], m["supports"], m["options"]
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
    res.checks.extend(_checks(r, lim, opt.speed, loads, supports, origin, steps, mat.sigma_B,
                              din, mat.din.d_eff if din else 0.0, scale))
    res.checks.extend(_units_checks(r, spec))
    return res


def _units_checks(r: ShaftResult, spec: ValidatedSpec) -> list:
    """``UNITS_LOAD`` when the peak loads use less than 1 % of the static strength
    (1/S_T: the stresses are proportional to the loads), as loads typed in N and N·m where
    kN and kN·m were meant do (:mod:`geardesign.core.units_guard`); the hints name the
    largest loads given."""
    from geardesign.core.units_guard import given, light_load

    cs = r.critical_static
    if cs is None or not cs.S_static > 0.0 or not math.isfinite(cs.S_static):
        return []
    fraction = 1.0 / cs.S_static
    inputs = []
    for i, ld in enumerate(spec.data.get("load") or []):
        inputs += given(ld, {"Fy": "N", "Fz": "N", "Fx": "N", "torque": "N·m", "moment_y": "N·m",
                             "moment_z": "N·m"}, f"load[{i}]")
    inputs.sort(key=lambda x: -abs(x[1]))
    what = (f"the peak loads use {100 * fraction:.2g} % of the static strength (S_T = "
            f"{cs.S_static:.4g} at {cs.label})")
    return light_load("UNITS_LOAD", fraction, what, inputs[:2], S.VON_MISES)


MAX_SCALE = 3.0      # the largest scale of the diameters the advice looks at


def scaled_steps(steps: list, k: float) -> list:
    """The steps with every diameter, bore and fillet radius times ``k`` (lengths kept)."""
    def times(v):
        return None if v is None else v * k

    return [replace(s, diameter=s.diameter * k, bore=s.bore * k, fillet=s.fillet * k,
                    groove_depth=times(s.groove_depth), groove_radius=times(s.groove_radius),
                    groove_width=times(s.groove_width), cross_bore=times(s.cross_bore))
            for s in steps]


def scale_to_pass(spec: ValidatedSpec, m: dict, which: str, S_req: float) -> float | None:
    """The least factor k (rounded up to 0.01) by which every step's diameter, bore and
    fillet radius must grow for the shaft's lowest safety ``which`` ("S": fatigue,
    "S_static": static) to reach ``S_req``, found by analysing the scaled shaft again (its
    size, notch and, by DIN 743, material factors change with the diameters; the bending
    moments of a shaft on more than two supports too).  None when k = ``MAX_SCALE`` does not
    reach it.  The nominal stresses fall as 1/k³, so k = (S_req/S)^(1/3) is the first
    guess; the guess is repeated from the safety it reaches (at most 12 analyses, and 5 to
    check the rounding)."""
    steps, loads, supports, opt = m["steps"], m["loads"], m["supports"], m["options"]
    d_max = max(st.diameter for st in steps)

    def lowest(k: float) -> float:
        try:
            mat = IN.material(spec.data["material"], opt.method, d_max * k)[0] \
                if opt.method == "DIN743" else m["material"]
            r = analyse(scaled_steps(steps, k), loads, supports, mat, opt)
        except InputError:
            return 0.0
        worst = r.critical if which == "S" else r.critical_static
        if worst is None:
            return math.inf
        return worst.S if which == "S" else worst.S_static

    k, S = 1.0, lowest(1.0)
    for _ in range(12):
        if S >= S_req:
            break
        step = (S_req / S) ** (1.0 / 3.0) if S > 0 else 1.25
        k = min(MAX_SCALE, k * max(step, 1.01))
        S = lowest(k)
        if S < S_req and k >= MAX_SCALE:
            return None
    else:
        return None
    k_up = math.ceil(k * 100.0 - 1e-9) / 100.0
    for _ in range(5):                   # rounding up keeps it passing; make sure
        if k_up > MAX_SCALE:
            return None
        if lowest(k_up) >= S_req:
            break
        k_up += 0.01
    return k_up


def _din_range_checks(r: ShaftResult, d_eff: float) -> list:
    """Warnings where DIN 743's formulas are used outside their range."""
    from geardesign.shaft.din743 import tables as din_tables

    out = []
    sh = din_tables()["shoulder"]
    if any(s.outside_table for s in r.sections):
        where = ", ".join(s.label for s in r.sections if s.outside_table)
        out.append(check(
            "FILLET_TABLE_RANGE", False, "warning",
            f"the shoulder or round groove at {where} lies outside the range of the DIN 743-2 "
            f"formula for α "
            f"(r/t >= {sh['r_t_min']:g}, d/D <= {sh['d_D_max']:g}): the formula is used "
            f"beyond it; enlarge the fillet or check α against a handbook",
            "", None, None, S.DIN_NOTCH))
    d_eff_max = din_tables()["K_1"]["d_eff_max"]
    if d_eff > d_eff_max:
        out.append(check(
            "FACTOR_TABLE_RANGE", False, "warning",
            f"the blank diameter d_eff = {d_eff:g} mm is above the {d_eff_max:g} mm of the "
            f"DIN 743 technological size factor K_1: its last value is used; give the "
            f"blank's own sigma_B and sigma_T", "", None, None, S.DIN_K1))
    return out


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


def _support_table(r: ShaftResult) -> DataTable:
    t = DataTable("supports", "Supports: reactions (force on the shaft) and slopes", [
        ("name", "support", None), ("x", "x", "mm"), ("R_y", "R_y", "N"), ("R_z", "R_z", "N"),
        ("R", "R", "N"), ("R_x", "R_x", "N"), ("w", "w", "mm"),
        ("slope", "θ", "arcmin")])
    for p in r.supports:
        t.rows.append({"name": p.name, "x": p.x, "R_y": p.R_y, "R_z": p.R_z,
                       "R": math.hypot(p.R_y, p.R_z), "R_x": p.R_x, "w": p.w,
                       "slope": p.slope / ARCMIN})
    return t


def _load_table(r: ShaftResult) -> DataTable:
    t = DataTable("loads", "Loads: deflection and slope", [
        ("name", "load", None), ("x", "x", "mm"), ("w_y", "w_y", "mm"), ("w_z", "w_z", "mm"),
        ("w", "w", "mm"), ("slope", "θ", "arcmin")])
    for p in r.loads:
        t.rows.append({"name": p.name, "x": p.x, "w_y": p.w_y, "w_z": p.w_z, "w": p.w,
                       "slope": p.slope / ARCMIN})
    return t


def _din_fatigue_table(r: ShaftResult) -> DataTable:
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


def _section_tables(r: ShaftResult, din: bool = False) -> list[DataTable]:
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


def _val(v: float) -> float | None:
    """A check value: None where the quantity is unbounded (an unloaded shaft has an
    infinite safety), so that the check passes without an infinite number."""
    return v if math.isfinite(v) else None


def _fmt(v: float) -> str:
    return "∞" if math.isinf(v) else f"{v:.2f}"


def _scale_advice(k: float | None, sec, what: str, notches: bool = False) -> str:
    """The advice to grow the shaft: every diameter (bores, fillet radii; with ``notches``
    the grooves' depth, radius and width and the cross-bores) times ``k``."""
    if k is None:
        return (f"even {MAX_SCALE:g} times the diameters do not reach {what}: use a stronger "
                f"steel or reduce the load")
    also = (" (the grooves' depth, radius and width and the cross-bores' diameter scale "
            "with them)" if notches else "")
    return (f"scale every step's diameter (and bore and fillet radius) by {k:.2f}, which "
            f"reaches {what} (analysed again){also}: at {sec.label} (x = {sec.x:g} mm) from "
            f"{sec.d:g} to {math.ceil(sec.d * k * 10.0 - 1e-9) / 10.0:g} mm; choose the "
            f"bearings and hubs for the new seats")


def _checks(r: ShaftResult, lim: dict, speed: float, loads, supports, origin, steps,
            mat_sigma_B: float, din: bool = False, d_eff: float = 0.0,
            scale: dict | None = None) -> list:
    out = []
    scale = scale or {}
    c = r.critical
    if c is not None:
        S_req = lim["S_min"]
        notches = any(st.groove_depth is not None or st.cross_bore is not None
                      for st in steps)
        advice = _scale_advice(scale.get("S"), c, f"[S] = {S_req:g}", notches)
        if c.fillet_r is not None and c.concentrator == "fillet":
            r_big = min(c.fillet_t / 2.0, 0.05 * c.d) if c.fillet_t else c.fillet_r
            if r_big > c.fillet_r:
                advice += (f", or enlarge the fillet radius from {c.fillet_r:g} to about "
                           f"{r_big:.1f} mm (t/r = 2)")
        elif c.concentrator == "keyway" and c.keyway_cutter == "end_mill":
            advice += ", or cut the keyway with a disc cutter"
        elif c.concentrator == "press fit":
            advice += ", or relieve the hub edge (groove, thinner hub end)"
        elif c.concentrator == "round groove":
            advice += ", or give the groove a larger radius"
        elif c.concentrator == "ring groove":
            advice += ", or give the groove a larger root radius"
        elif c.concentrator == "cross-bore":
            advice += ", or make the hole smaller"
        out.append(check(
            "FATIGUE", c.S >= S_req, "error",
            f"fatigue safety S = {_fmt(c.S)} < [S] = {S_req:g} at {c.label} (x = {c.x:g} mm, "
            f"{c.concentrator}): {advice}",
            f"fatigue safety S = {_fmt(c.S)} >= [S] = {S_req:g} (lowest at {c.label}, "
            f"x = {c.x:g} mm)", _val(c.S), S_req, S.DIN_FATIGUE if din else S.FATIGUE))
        cs = r.critical_static
        S_req = lim["S_static_min"]
        out.append(check(
            "STATIC_STRENGTH", cs.S_static >= S_req, "error",
            f"static safety at the peak load S_T = {_fmt(cs.S_static)} < [S_T] = {S_req:g} at "
            f"{cs.label} (x = {cs.x:g} mm): "
            f"{_scale_advice(scale.get('S_static'), cs, f'[S_T] = {S_req:g}', notches)}, "
            f"or use a steel of higher yield strength",
            f"static safety at the peak load S_T = {_fmt(cs.S_static)} >= [S_T] = {S_req:g} "
            f"(lowest at {cs.label})", _val(cs.S_static), S_req,
            S.DIN_STATIC if din else S.VON_MISES))
    margin = lim["critical_speed_margin"]
    ratio = r.n_cr / speed
    out.append(check(
        "CRITICAL_SPEED", ratio >= margin, "error",
        f"first bending critical speed n_cr = {r.n_cr:.0f} min^-1 is only {ratio:.2f} times "
        f"the speed {speed:g} min^-1 (at least {margin:g} required): stiffen the shaft "
        f"(larger diameters, shorter span, bearings closer to heavy parts)",
        f"first bending critical speed n_cr = {r.n_cr:.0f} min^-1 = {ratio:.1f}·n",
        _val(ratio), margin, S.PRACTICE))
    tilt = ST.tables()["tilt"]
    for sp, p in zip(supports, r.supports):
        if sp.type not in tilt:
            continue
        lo, hi, name = tilt[sp.type]["min"], tilt[sp.type]["max"], tilt[sp.type]["name"]
        a = p.slope / ARCMIN
        sev = "warning" if a <= hi else "error"
        out.append(check(
            "BEARING_TILT", a <= lo, sev,
            f"slope at bearing {p.name} (x = {p.x:g} mm) {a:.2f}′ exceeds "
            f"{'the permissible ' + format(hi, 'g') if a > hi else 'the lower limit ' + format(lo, 'g')}′ "
            f"of a {name} ({lo:g}…{hi:g}′): stiffen the shaft between the bearings or use a "
            f"bearing that tolerates tilt",
            f"slope at bearing {p.name} {a:.2f}′ <= {lo:g}′ ({name})", a, lo, S.TILT))
    for ld, p in zip(loads, r.loads):
        if ld.module is None:
            continue
        limit = 0.01 * ld.module
        out.append(check(
            "GEAR_DEFLECTION", p.w <= limit, "warning",
            f"deflection at {p.name} (x = {p.x:g} mm) {p.w * 1000:.1f} µm exceeds 0.01·m = "
            f"{limit * 1000:.1f} µm: stiffen the shaft or bring the bearings closer",
            f"deflection at {p.name} {p.w * 1000:.1f} µm <= 0.01·m = {limit * 1000:.1f} µm",
            p.w, limit, S.GEAR_SEAT))
    if din:
        out.extend(_din_range_checks(r, d_eff))
        return out
    if any(s.outside_table for s in r.sections):
        where = ", ".join(s.label for s in r.sections if s.outside_table)
        out.append(check(
            "FILLET_TABLE_RANGE", False, "warning",
            f"t/r or r/d of the fillet at {where} lies outside the table (t/r above 5 or r/d "
            f"below 0.01): the nearest row is used and may understate K_σ; enlarge the fillet",
            "", None, None, S.TABLES))
    big = [s for s in r.sections if s.d > ST.TABLE_D_MAX]
    high = ST.tables()["fillet"]["sigma_B"][-1]
    if big or mat_sigma_B > high:
        why = []
        if mat_sigma_B > high:
            why.append(f"σ_B = {mat_sigma_B:g} MPa is above the tables' {high:g} MPa "
                       f"(K_σ, K_τ grow with σ_B)")
        if big:
            why.append(f"d = {max(s.d for s in big):g} mm is above the tables' "
                       f"{ST.TABLE_D_MAX:g} mm (K_d falls, K_σ/K_d of a fit grows with d)")
        out.append(check(
            "FACTOR_TABLE_RANGE", False, "warning",
            "; ".join(why) + ": the last column is used and may understate the concentration; "
            "check the factors against a handbook for this size and strength", "",
            None, None, S.TABLES))
    if origin.get("blank"):
        d_max = max(s.diameter for s in steps)
        blank = origin["blank"]
        out.append(check(
            "BLANK_SIZE", d_max <= blank, "warning",
            f"the largest diameter {d_max:g} mm exceeds the blank size {blank:g} mm for which "
            f"the properties of steel {origin['grade']} at {origin['HB']:g} HB hold: give "
            f"the blank's own sigma_B and sigma_T",
            f"blank properties of steel {origin['grade']} hold up to {blank:g} mm",
            d_max, blank, S.MATERIAL) if blank > 0 else check(
            "BLANK_SIZE", True, "info", "", f"properties of steel {origin['grade']} hold for "
            f"any blank size", None, None, S.MATERIAL))
    return out
