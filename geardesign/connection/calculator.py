"""``kind = "connection"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

Maps the spec (N·m, mm, µm) to the pure functions of :mod:`.key`, :mod:`.spline` and
:mod:`.fit` (N·mm inside), their results to report rows, and the checks with advice.
"""

from __future__ import annotations

import math
import re

from geardesign.connection import fit as F
from geardesign.connection import iso286
from geardesign.connection import key as K
from geardesign.connection import sources as S
from geardesign.connection import spline as SP
from geardesign.connection import tables
from geardesign.core.errors import InputError, Problem
from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec

SHRINK_TEMPERATURE_MAX = 350.0
"""Highest hub temperature for shrinking steel hubs without changing their heat treatment
(design practice, [DIN7190-1] assembly notes)."""


def _f(x: float, digits: int = 3) -> str:
    text = f"{x:.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.connection import CALCULATOR

    res = CALCULATOR.new_result(spec)
    data = spec.data
    if data.get("key") is not None:
        _key(res, data)
    elif data.get("spline") is not None:
        _spline(res, data)
    else:
        _fit(res, data)
    return res


# --------------------------------------------------------------------------- key


def _key_section(k: dict) -> tuple[float, float, float, float | None, str]:
    """b, h, t1, t2 and the source of the key section (table row or the spec)."""
    given = [n for n in ("width", "height", "shaft_depth") if k[n] is not None]
    if given and len(given) < 3:
        missing = [n for n in ("width", "height", "shaft_depth") if k[n] is None]
        raise InputError(Problem(
            "key." + missing[0], "missing; a key not from the table needs key.width, "
            "key.height and key.shaft_depth together"))
    d = k["shaft_diameter"]
    if given:
        b, h, t1 = k["width"], k["height"], k["shaft_depth"]
        if t1 >= h:
            raise InputError.at("key.shaft_depth", t1, f"must be less than the key height "
                                f"key.height = {_f(h)} mm (the key must stand out into the hub)")
        return b, h, t1, None, "spec (key not from the table)"
    size = tables.key_for_diameter(d)
    if size is None:
        first, last = tables.key_sizes()[0], tables.key_sizes()[-1]
        raise InputError.at("key.shaft_diameter", d, f"outside the key table of GOST 23360-78 "
                            f"/ DIN 6885-1 (over {_f(first.d_over)} up to {_f(last.d_to)} mm); "
                            f"give key.width, key.height and key.shaft_depth for another key")
    return size.b, size.h, size.t1, size.t2, f"{S.KEY_TABLE} (keys.csv row {size.row})"


def _key(res: Result, data: dict) -> None:
    k, ld = data["key"], data["load"]
    T = ld["torque"] * 1e3
    KA = ld["application_factor"]
    Td = T * KA
    d, l, form, n = k["shaft_diameter"], k["length"], k["form"], k["count"]
    din = k["standard"] == "DIN 6885-1"
    b, h, t1, t2, src = _key_section(k)
    l_p = K.bearing_length(l, b, form)
    if l_p <= 0:
        raise InputError.at("key.length", l, f"must be longer than the key width b = {_f(b)} mm "
                            f"(form {form}: bearing length l_p = {_f(l_p)} mm)")
    lengths = tables.key_lengths()
    L_hub = k["hub_length"]
    if L_hub is not None and l > L_hub:
        fits = [v for v in lengths if v <= L_hub]
        hint = (f"use a standard key of at most {_f(fits[-1])} mm or a longer hub" if fits
                else "use a longer hub")
        raise InputError.at("key.length", l, f"longer than the hub (key.hub_length = "
                            f"{_f(L_hub)} mm): {hint}")
    n_eff = float(tables.toml()["key_share"][str(n)])
    res.methods = ["GOST 23360-78, DIN 6885-1", "DIN 6892 method C" if din else
                   "GOST practice (Ivanov, Dunaev)"]

    geo = res.section("geometry", "Key")
    geo.add("b", b, "mm", "b", "key width", src)
    geo.add("h", h, "mm", "h", "key height", src)
    geo.add("t1", t1, "mm", "t1", "keyway depth in the shaft", src)
    if t2 is not None:
        geo.add("t2", t2, "mm", "t2", "keyway depth in the hub", src)
    geo.add("l_p", l_p, "mm", "l_p", f"bearing length (form {form})", S.KEY_GOST)
    geo.add("n_eff", n_eff, "-", "n·φ", "load-carrying key count (two keys carry 1.5×)",
            S.KEY_SHARE)

    st = res.section("strength", "Pressure and shear")
    st.add("T_d", Td / 1e3, "N·m", "K_A·T", "design torque", S.KEY_GOST)
    k_hub = h - t1
    p_hub = K.pressure(Td, d, l_p, k_hub, n_eff)
    tau = K.shear(Td, d, b, l_p, n_eff)
    st.add("k_hub", k_hub, "mm", "k = h − t1", "engaged height on the hub side",
           S.KEY_DIN if din else S.KEY_GOST)
    st.add("p_hub", p_hub, "MPa", "p", "bearing pressure, hub side",
           S.KEY_DIN if din else S.KEY_GOST)
    cases = []   # (code, side, p, p_allow, k, source)
    if din:
        tb = tables.toml()["key_din"]
        need = {"shaft_strength": "the shaft yield strength R_e",
                "hub_strength": "the hub strength (R_e of steel, R_m of cast iron)",
                "key_strength": "the key yield strength R_e"}
        if k["allowable_pressure"] is None or k["allowable_shear"] is None:
            for name, what in need.items():
                if k[name] is None:
                    raise InputError(Problem("key." + name, f"missing; DIN 6892 method C needs "
                                             f"{what} (MPa), or give key.allowable_pressure "
                                             f"and key.allowable_shear"))
        fS, fH = tb["support_factor"], k["hardness_factor"]
        k_shaft = t1
        p_shaft = K.pressure(Td, d, l_p, k_shaft, n_eff)
        st.add("k_shaft", k_shaft, "mm", "t1", "engaged height on the shaft side", S.KEY_DIN)
        st.add("p_shaft", p_shaft, "MPa", "p", "bearing pressure, shaft side", S.KEY_DIN)
        over = k["allowable_pressure"]
        p_allow_hub = over if over is not None else fS[k["hub_material"]] * fH * k["hub_strength"]
        p_allow_shaft = over if over is not None else fS["steel"] * fH * k["shaft_strength"]
        p_allow_key = over if over is not None else fS["steel"] * fH * k["key_strength"]
        src_allow = "spec" if over is not None else S.KEY_ALLOW_DIN
        st.add("p_zul_hub", p_allow_hub, "MPa", "p_zul", "permissible pressure, hub", src_allow)
        st.add("p_zul_shaft", p_allow_shaft, "MPa", "p_zul", "permissible pressure, shaft",
               src_allow)
        st.add("p_zul_key", p_allow_key, "MPa", "p_zul", "permissible pressure, key", src_allow)
        cases = [("KEY_PRESSURE_HUB", "hub", p_hub, p_allow_hub, k_hub),
                 ("KEY_PRESSURE_SHAFT", "shaft", p_shaft, p_allow_shaft, k_shaft),
                 ("KEY_PRESSURE_KEY", "key", max(p_hub, p_shaft), p_allow_key,
                  min(k_hub, k_shaft))]
        tau_allow = (k["allowable_shear"] if k["allowable_shear"] is not None
                     else tb["shear_factor"] * k["key_strength"])
        tau_src = "spec" if k["allowable_shear"] is not None else S.KEY_ALLOW_DIN
    else:
        tb = tables.toml()["key_gost"]
        over = k["allowable_pressure"]
        p_allow = over if over is not None else tb["pressure"][k["hub_material"]]
        st.add("p_allow", p_allow, "MPa", "[σ]см", f"permissible bearing pressure "
               f"({k['hub_material'].replace('_', '-')} hub)",
               "spec" if over is not None else S.KEY_ALLOW_GOST)
        cases = [("KEY_PRESSURE", "hub", p_hub, p_allow, k_hub)]
        tau_allow = k["allowable_shear"] if k["allowable_shear"] is not None else tb["shear"]
        tau_src = "spec" if k["allowable_shear"] is not None else S.KEY_ALLOW_GOST
    st.add("tau", tau, "MPa", "τ", "shear stress of the key", S.KEY_GOST)
    st.add("tau_allow", tau_allow, "MPa", "[τ]", "permissible shear stress", tau_src)
    for code, side, p, pa, _ in cases:
        st.add(f"S_{side}", pa / p, "-", f"S_{side}", f"pressure safety, {side} "
               "(permissible/actual)", S.KEY_DIN if din else S.KEY_GOST)

    # the shortest key that passes every pressure and the shear
    lp_req = max([K.required_bearing_length(Td, d, kk, pa, n_eff) for *_, pa, kk in cases]
                 + [2.0 * Td / (d * b * tau_allow * n_eff)])
    l_req = K.length_for(lp_req, b, form)
    l_std = K.standard_length(l_req, tables.key_lengths())
    ds = res.section("design", "Key length that passes")
    ds.add("l_p_min", lp_req, "mm", "l_p,min", "least bearing length", S.KEY_GOST)
    ds.add("l_min", l_req, "mm", "l_min", f"least key length (form {form})", S.KEY_GOST)
    ds.add("l_std", l_std, "mm", "l_std", "shortest standard length that passes",
           S.KEY_LENGTHS)

    advice = _key_advice(l_std, l_req, L_hub, n)
    for code, side, p, pa, _ in cases:
        where = "on the key" if side == "key" else f"on the {side} side"
        res.checks.append(check(
            code, p <= pa, "error",
            f"bearing pressure {where} p = {p:.1f} MPa exceeds {pa:.1f} MPa: {advice}",
            f"bearing pressure {where} p = {p:.1f} MPa <= {pa:.1f} MPa",
            p, pa, S.KEY_DIN if din else S.KEY_GOST))
    res.checks.append(check(
        "KEY_SHEAR", tau <= tau_allow, "error",
        f"key shear τ = {tau:.1f} MPa exceeds {tau_allow:.1f} MPa: {advice}",
        f"key shear τ = {tau:.1f} MPa <= {tau_allow:.1f} MPa", tau, tau_allow, S.KEY_GOST))
    if L_hub is not None:
        res.checks.append(check(
            "KEY_HUB_LENGTH", l_std <= L_hub, "warning",
            f"the shortest standard key that passes ({_f(l_std)} mm) is longer than the hub "
            f"({_f(L_hub)} mm): use two keys (key.count = 2), a longer hub or a spline",
            f"a standard key of {_f(l_std)} mm passes and fits the {_f(L_hub)} mm hub",
            l_std if math.isfinite(l_std) else None, L_hub, S.KEY_LENGTHS))


def _key_advice(l_std: float, l_req: float, L_hub: float | None, n: int) -> str:
    if math.isfinite(l_std) and (L_hub is None or l_std <= L_hub):
        return f"use a key of at least {_f(l_req, 1)} mm, i.e. the standard length {_f(l_std)} mm"
    more = "two keys (key.count = 2), " if n == 1 else ""
    return (f"a single key would need {_f(l_req, 1)} mm; use {more}a longer hub, a spline or an "
            f"interference fit")


# --------------------------------------------------------------------------- spline

_DESIGNATION = re.compile(
    r"^\s*(?:[WN]\s*)?(\d+(?:\.\d+)?)\s*[x×]\s*(\d+(?:\.\d+)?)\s*[x×]\s*(\d+)\s*$")


def _spline_size(s: dict) -> tuple[float, float, int, str]:
    numbers = [n for n in ("reference_diameter", "module", "teeth") if s[n] is not None]
    if s["designation"] is not None:
        if numbers:
            raise InputError(Problem("spline." + numbers[0], "give either spline.designation "
                                     "or the numbers (reference_diameter, module, teeth), not "
                                     "both", s[numbers[0]]))
        m = _DESIGNATION.match(s["designation"])
        if not m:
            raise InputError.at("spline.designation", s["designation"],
                                'must read d_B x m x z, e.g. "W 40x2x18"')
        d_B, mod, z = float(m.group(1)), float(m.group(2)), int(m.group(3))
        if not (0 < d_B <= 1000 and 0 < mod <= 20 and 6 <= z <= 200):
            raise InputError.at("spline.designation", s["designation"],
                                "d_B must lie in 0...1000 mm, m in 0...20 mm and z in 6...200")
        row = tables.spline_size(d_B, mod)
        src = f"{S.SPLINE_GEOM}" + (f"; splines.csv row {row.row}" if row and row.z == z else "")
        return d_B, mod, z, src
    for n in ("reference_diameter", "module"):
        if s[n] is None:
            raise InputError(Problem("spline." + n, 'missing; give spline.designation (e.g. '
                                     '"W 40x2x18") or spline.reference_diameter and '
                                     'spline.module'))
    d_B, mod = s["reference_diameter"], s["module"]
    if s["teeth"] is not None:
        return d_B, mod, s["teeth"], S.SPLINE_GEOM
    row = tables.spline_size(d_B, mod)
    if row is None:
        raise InputError.at("spline.module", mod, f"the series table has no spline "
                            f"{_f(d_B)} x {_f(mod)}; give spline.teeth")
    return d_B, mod, row.z, f"{S.SPLINE_GEOM}; splines.csv row {row.row}"


def _spline(res: Result, data: dict) -> None:
    s, ld = data["spline"], data["load"]
    T = ld["torque"] * 1e3
    KA = ld["application_factor"]
    gost = s["standard"] == "GOST 6033-80"
    d_B, m, z, src = _spline_size(s)
    g = SP.geometry(d_B, m, z, "GOST" if gost else "DIN")
    lo, hi = SP.X_RANGE
    if not lo - 1e-9 <= g.x <= hi + 1e-9:
        ok = [zz for zz in range(6, 201)
              if lo - 1e-9 <= (d_B - m * zz - 1.1 * m) / (2 * m) <= hi + 1e-9]
        hint = (f"use z = {ok[0]}" + (f" or {ok[-1]}" if ok[-1] != ok[0] else "")) if ok else \
            "change the module"
        raise InputError.at("spline.teeth" if s["designation"] is None else
                            "spline.designation", z if s["designation"] is None else
                            s["designation"],
                            f"z = {z} on d_B = {_f(d_B)} mm with m = {_f(m)} mm gives the profile "
                            f"shift x = {g.x:.3f}, outside {lo}...{hi} of DIN 5480: {hint}")
    use, hard, cond = s["use"], s["hardness"], s["conditions"]
    table = tables.toml()["spline_pressure"][use]
    if s["allowable_pressure"] is None and hard not in table:
        raise InputError.at("spline.hardness", hard, "a hub sliding under load needs hardened "
                            'teeth (spline.hardness = "hardened") or give '
                            "spline.allowable_pressure")
    p_allow = (s["allowable_pressure"] if s["allowable_pressure"] is not None
               else table[hard][cond])
    res.methods = ["GOST 6033-80 (Ivanov)" if gost else "DIN 5480, DIN 5466"]
    method_src = S.SPLINE_GOST if gost else S.SPLINE_DIN

    geo = res.section("geometry", "Spline geometry")
    geo.add("d_B", d_B, "mm", "d_B", "reference (nominal) diameter", src)
    geo.add("m", m, "mm", "m", "module", src)
    geo.add("z", z, "-", "z", "number of teeth", src)
    geo.add("d", g.d, "mm", "d = m·z", "pitch diameter", S.SPLINE_GEOM)
    geo.add("x", g.x, "-", "x", "profile shift coefficient", S.SPLINE_GEOM)
    geo.add("d_a1", g.d_a1, "mm", "d_a1", "tip diameter, shaft", S.SPLINE_GEOM)
    geo.add("d_a2", g.d_a2, "mm", "d_a2", "tip diameter, hub", S.SPLINE_GEOM)
    geo.add("h_w", g.h_w, "mm", "h_w", "bearing tooth height", method_src)
    geo.add("d_m", g.d_m, "mm", "d_m", "mean diameter of the bearing flank", method_src)

    l, psi = s["length"], s["load_factor"]
    p = SP.pressure(T * KA, g.d_m, z, g.h_w, l, psi)
    st = res.section("strength", "Flank pressure")
    st.add("T_d", T * KA / 1e3, "N·m", "K_A·T", "design torque", method_src)
    st.add("p", p, "MPa", "p", "mean flank pressure 2T/(d_m·z·h_w·l·ψ)", method_src)
    st.add("p_allow", p_allow, "MPa", "[p]", f"permissible pressure ({use}, {hard}, {cond})",
           "spec" if s["allowable_pressure"] is not None else S.SPLINE_ALLOW)
    st.add("S_p", p_allow / p, "-", "S_p", "pressure safety (permissible/actual)", method_src)
    l_req = SP.required_length(T * KA, g.d_m, z, g.h_w, psi, p_allow)
    ds = res.section("design", "Length that passes")
    ds.add("l_min", l_req, "mm", "l_min", "least engaged length", method_src)
    res.checks.append(check(
        "SPLINE_PRESSURE", p <= p_allow, "error",
        f"flank pressure p = {p:.1f} MPa exceeds {p_allow:.1f} MPa: lengthen the hub to at "
        f"least {_f(l_req, 1)} mm, use a larger spline"
        + (" or hardened teeth" if hard == "soft" else ""),
        f"flank pressure p = {p:.1f} MPa <= {p_allow:.1f} MPa", p, p_allow, method_src))
    res.checks.append(check(
        "SPLINE_LENGTH", l <= 1.5 * d_B, "warning",
        f"engaged length {_f(l)} mm exceeds 1.5·d_B = {_f(1.5 * d_B)} mm: the load does not "
        f"spread over such a length (torsional wind-up); use a larger diameter",
        f"engaged length {_f(l)} mm <= 1.5·d_B", l, 1.5 * d_B, S.PRACTICE))


# --------------------------------------------------------------------------- fit


def _fit_interference(f: dict) -> tuple[float, float, str, str]:
    """Smallest and largest interference [µm], the fit name and the source."""
    d = f["diameter"]
    given = [n for n in ("interference_min", "interference_max") if f[n] is not None]
    if f["fit"] is not None:
        if given:
            raise InputError(Problem("fit." + given[0], "give either fit.fit or the "
                                     "interferences, not both", f[given[0]]))
        try:
            ft = iso286.fit(f["fit"], d)
        except iso286.FitError as exc:
            raise InputError.at("fit.fit", f["fit"], str(exc)) from None
        return ft.U_min, ft.U_max, ft.name, f"{S.ISO286}, iso286.csv row {ft.row}"
    if len(given) < 2:
        missing = [n for n in ("interference_min", "interference_max") if f[n] is None]
        raise InputError(Problem("fit." + missing[0], 'missing; give fit.fit (e.g. "H7/s6") '
                                 "or fit.interference_min and fit.interference_max (µm)"))
    if f["interference_min"] > f["interference_max"]:
        raise InputError.at("fit.interference_min", f["interference_min"],
                            f"must not exceed fit.interference_max = "
                            f"{_f(f['interference_max'])} µm")
    return f["interference_min"], f["interference_max"], "", "spec"


def _fit(res: Result, data: dict) -> None:
    f, ld = data["fit"], data["load"]
    T = ld["torque"] * 1e3
    KA = ld["application_factor"]
    F_ax = ld["axial_force"]
    d, D_a, D_i, l = f["diameter"], f["hub_outer_diameter"], f["shaft_bore"], f["length"]
    if D_a <= d:
        raise InputError.at("fit.hub_outer_diameter", D_a, f"must be larger than the joint "
                            f"diameter fit.diameter = {_f(d)} mm (the hub needs a wall)")
    if D_i >= d:
        raise InputError.at("fit.shaft_bore", D_i, f"must be smaller than the joint diameter "
                            f"fit.diameter = {_f(d)} mm (0 for a solid shaft)")
    U_min, U_max, name, u_src = _fit_interference(f)
    if U_max <= 0:
        what = f'"{name}" gives' if name else "the interferences give"
        raise InputError.at("fit.fit" if name else "fit.interference_max",
                            name or U_max, f"{what} no interference at {_f(d)} mm (largest "
                            f"{_f(U_max, 1)} µm): a clearance or transition fit transmits "
                            f"nothing by friction; choose an interference fit such as H7/s6")
    res.methods = ["DIN 7190-1 (elastic)", "ISO 286" if name else "interference given"]
    E_A, nu_A, E_I, nu_I = (f["hub_modulus"], f["hub_poisson"], f["shaft_modulus"],
                            f["shaft_poisson"])
    loss = F.smoothing(f["rz_shaft"], f["rz_hub"])
    Uw_min, Uw_max = U_min - loss, U_max - loss
    C = F.compliance(d, D_a, D_i, E_A, nu_A, E_I, nu_I)
    p_min, p_max = F.pressure(Uw_min, d, C), F.pressure(Uw_max, d, C)
    mu_src = "spec" if f["friction"] is not None else S.FRICTION
    mu = (f["friction"] if f["friction"] is not None else
          tables.toml()["friction"][f["hub_material"]][f["joining"]][f["surface"]])

    geo = res.section("interference", "Interference")
    if name:
        geo.add("U_min", U_min, "µm", "U_min", f"smallest interference ({name})", u_src)
        geo.add("U_max", U_max, "µm", "U_max", f"largest interference ({name})", u_src)
    geo.add("Q_A", d / D_a, "-", "Q_A", "hub diameter ratio d_F/D_aA", S.LAME)
    geo.add("Q_I", D_i / d, "-", "Q_I", "shaft diameter ratio D_iI/d_F", S.LAME)
    geo.add("smoothing", loss, "µm", "0.8·ΣRz", "interference lost by smoothing", S.SMOOTHING)
    geo.add("U_w_min", Uw_min, "µm", "U_w,min", "effective smallest interference", S.SMOOTHING)
    geo.add("U_w_max", Uw_max, "µm", "U_w,max", "effective largest interference", S.SMOOTHING)

    T_d = T * KA
    cap = res.section("capacity", "Joint pressure and transmittable load")
    cap.add("p_min", p_min, "MPa", "p_min", "joint pressure at the smallest interference", S.LAME)
    cap.add("p_max", p_max, "MPa", "p_max", "joint pressure at the largest interference", S.LAME)
    cap.add("mu", mu, "-", "μ", f"coefficient of friction ({f['joining']}, {f['surface']})",
            mu_src)
    T_min = F.torque(p_min, d, l, mu)
    cap.add("T_slip", T_min / 1e3, "N·m", "T_slip", "transmittable torque at p_min "
            "(π/2·d²·l·μ·p)", S.SLIP)
    cap.add("F_slip", F.axial_force(p_min, d, l, mu), "N", "F_slip",
            "transmittable axial force at p_min (π·d·l·μ·p)", S.SLIP)
    F_res = math.hypot(2.0 * T_d / d, F_ax * KA)
    S_slip = F.axial_force(p_min, d, l, mu) / F_res
    cap.add("T_d", T_d / 1e3, "N·m", "K_A·T", "design torque", S.SLIP)
    cap.add("S_slip", S_slip, "-", "S_R", "safety against slip at the smallest interference",
            S.SLIP)
    p_req = F.required_pressure(T_d, F_ax * KA, d, l, mu, f["slip_safety"])
    U_req = F.interference_for(p_req, d, C) + loss
    cap.add("p_req", p_req, "MPa", "p_req", f"joint pressure needed for S_R = "
            f"{_f(f['slip_safety'])}", S.SLIP)
    cap.add("U_req", U_req, "µm", "U_req", "least interference needed (with smoothing)", S.SLIP)

    s = F.stresses(p_max, d, D_a, D_i)
    st = res.section("stress", "Stresses at the largest interference")
    st.add("sigma_t_hub", s.sigma_t_hub, "MPa", "σ_t,Ai", "hoop stress at the hub bore", S.LAME)
    st.add("sigma_t_hub_outer", s.sigma_t_hub_outer, "MPa", "σ_t,Aa",
           "hoop stress at the hub outside", S.LAME)
    st.add("sigma_v_hub", s.sigma_v_hub, "MPa", "σ_v,A", "von Mises stress at the hub bore",
           S.VON_MISES)
    st.add("sigma_t_shaft", s.sigma_t_shaft, "MPa", "σ_t,I", "hoop stress of the shaft "
           "(bore of a hollow shaft, else the whole section)", S.LAME)
    st.add("sigma_v_shaft", s.sigma_v_shaft, "MPa", "σ_v,I", "von Mises stress of the shaft",
           S.VON_MISES)
    S_hub = f["hub_yield"] / s.sigma_v_hub if s.sigma_v_hub > 0 else math.inf
    S_shaft = f["shaft_yield"] / s.sigma_v_shaft if s.sigma_v_shaft > 0 else math.inf
    st.add("S_P_hub", S_hub, "-", "S_P,A", "safety against yield, hub", S.VON_MISES)
    st.add("S_P_shaft", S_shaft, "-", "S_P,I", "safety against yield, shaft", S.VON_MISES)
    p_lim = min(F.hub_pressure_limit(f["hub_yield"], d, D_a, f["yield_safety"]),
                F.shaft_pressure_limit(f["shaft_yield"], d, D_i, f["yield_safety"]))
    U_perm = F.interference_for(p_lim, d, C) + loss
    st.add("U_perm", U_perm, "µm", "U_perm", f"largest interference for S_P = "
           f"{_f(f['yield_safety'])} (with smoothing)", S.VON_MISES)

    asm = res.section("assembly", "Assembly")
    F_press = F.axial_force(p_max, d, l, mu)
    asm.add("F_press", F_press, "N", "F_e", "press-in force at the largest interference",
            S.ASSEMBLY)
    clearance = (f["joining_clearance"] if f["joining_clearance"] is not None
                 else F.CLEARANCE_SHARE * d)
    theta = F.shrink_temperature(U_max, d, f["hub_expansion"], clearance,
                                 f["room_temperature"])
    asm.add("clearance", clearance, "mm", "Δs", "joining clearance", S.ASSEMBLY)
    asm.add("theta_hub", theta, "°C", "ϑ_A", "hub temperature for shrinking on", S.ASSEMBLY)

    window = (f"the fit must lie between {_f(U_req, 1)} µm (slip) and {_f(U_perm, 1)} µm "
              f"(yield)" if U_req <= U_perm else
              f"no interference satisfies both slip ({_f(U_req, 1)} µm needed) and yield "
              f"({_f(U_perm, 1)} µm allowed): lengthen the joint, enlarge the hub or use a "
              f"stronger material")
    res.checks.append(check(
        "FIT_SLIP", S_slip >= f["slip_safety"], "error",
        f"the joint slips: safety {S_slip:.2f} < {_f(f['slip_safety'])} at the smallest "
        f"interference; raise the smallest interference to {_f(U_req, 1)} µm or more (a "
        f"tighter fit)"
        + (", use degreased (dry) joint faces" if f["surface"] == "oiled" else "")
        + f" or lengthen the joint; {window}",
        f"safety against slip {S_slip:.2f} >= {_f(f['slip_safety'])}", S_slip,
        f["slip_safety"], S.SLIP))
    for code, part, S_p in (("FIT_HUB_YIELD", "hub", S_hub), ("FIT_SHAFT_YIELD", "shaft",
                                                                S_shaft)):
        res.checks.append(check(
            code, S_p >= f["yield_safety"], "error",
            f"the {part} yields at the largest interference: safety {S_p:.2f} < "
            f"{_f(f['yield_safety'])}; keep the largest interference below {_f(U_perm, 1)} µm "
            f"(a looser fit) or use a stronger material (a thicker wall hardly helps: the "
            f"stress at the bore follows the interference)",
            f"{part} safety against yield {S_p:.2f} >= {_f(f['yield_safety'])}",
            S_p if math.isfinite(S_p) else None, f["yield_safety"], S.VON_MISES))
    if f["joining"] == "shrink":
        res.checks.append(check(
            "FIT_SHRINK_TEMPERATURE", theta <= SHRINK_TEMPERATURE_MAX, "warning",
            f"the hub must be heated to {theta:.0f} °C, above {SHRINK_TEMPERATURE_MAX:.0f} °C: "
            f"it may lose its heat treatment; cool the shaft as well, or use a looser fit",
            f"hub temperature for shrinking {theta:.0f} °C <= {SHRINK_TEMPERATURE_MAX:.0f} °C",
            theta, SHRINK_TEMPERATURE_MAX, S.ASSEMBLY))
