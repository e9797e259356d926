"""``kind = "connection"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

inputs → solve → report: :mod:`.inputs` reads the spec (every input rule), :mod:`.solve`
computes one record per connection type, and this module turns the record into report rows
and the checks with their advice.
"""

from __future__ import annotations

import math

from geardesign.connection import inputs as I
from geardesign.connection import solve
from geardesign.connection import sources as S
from geardesign.connection.inputs import fmt as _f
from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec

SHRINK_TEMPERATURE_MAX = 350.0
"""Highest hub temperature for shrinking steel hubs without changing their heat treatment
(design practice, [DIN7190-1] assembly notes)."""


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.connection import CALCULATOR

    data = spec.data
    # the connection's own rules first: a wrong load (reported by the schema) does not
    # hide them
    if data.get("key") is not None:
        k = I.key(data)
        res, ld = CALCULATOR.new_result(spec), I.load(data)
        r = solve.key(k, ld)
        _key_report(res, k, ld, r)
        fraction = max([r.tau / r.tau_allow] + [fl.p / fl.p_allow for fl in r.flanks])
        what = "the key uses {:.2g} % of its capacity (pressure and shear over their limits)"
    elif data.get("spline") is not None:
        s = I.spline(data, spec.assumed)
        res, ld = CALCULATOR.new_result(spec), I.load(data)
        r = solve.spline(s, ld)
        _spline_report(res, s, ld, r)
        fraction = r.p / r.p_allow
        what = "the spline uses {:.2g} % of its capacity (flank pressure over its limit)"
    else:
        f = I.fit(data)
        res, ld = CALCULATOR.new_result(spec), I.load(data)
        r = solve.fit(f, ld)
        _fit_report(res, f, ld, r)
        fraction = 1.0 / r.S_slip if r.S_slip > 0.0 else math.inf   # no grip: no slip warning
        what = "the torque is {:.2g} % of what the fit transmits before it slips"
    from geardesign.core.units_guard import given, light_load

    res.checks.extend(light_load("UNITS_LOAD", fraction, what.format(100 * fraction),
                                 given(data["load"], {"torque": "N·m"}, "load"), S.PRACTICE))
    return res


# --------------------------------------------------------------------------- key


KEY_LENGTH_RATIO = 1.5
"""A parallel key longer than 1.5·d carries little more: the torsion of the shaft loads
its end near the torque input ([Ivanov] ch. 6, [Dunaev] ch. 6: hub length (0.8 ... 1.5)·d,
the key 5 ... 10 mm shorter than the hub); the same bound as ``SPLINE_LENGTH``."""


def key_length_limit(k: I.KeyInput) -> float:
    """The longest key the advice proposes: 1.5·d, and not longer than the hub."""
    limit = KEY_LENGTH_RATIO * k.d
    return limit if k.hub_length is None else min(limit, k.hub_length)


def _key_advice(r: solve.KeySolution, k: I.KeyInput, ld: I.Load) -> tuple[str, tuple]:
    """What the failed pressure and shear checks advise, and its fix: the standard key length
    that passes, within :func:`key_length_limit`; beyond it two keys, re-rated; beyond
    them a spline or an interference fit."""
    from dataclasses import replace

    limit = key_length_limit(k)
    bound = (f"the {_f(limit)} mm a key may have ({KEY_LENGTH_RATIO:g}·d = "
             f"{_f(KEY_LENGTH_RATIO * k.d)} mm"
             + (f", hub {_f(k.hub_length)} mm)" if k.hub_length is not None else ")"))
    if math.isfinite(r.l_std) and r.l_std <= limit:
        return (f"use a key of at least {_f(r.l_min, 1)} mm, i.e. the standard length "
                f"{_f(r.l_std)} mm (key.length = {_f(r.l_std)})"), (("key.length", r.l_std),)
    single = f"a single key would need {_f(r.l_min, 1)} mm, beyond {bound}"
    if k.count == 1:
        r2 = solve.key(replace(k, count=2), ld)
        if math.isfinite(r2.l_std) and r2.l_std <= limit:
            fix = (("key.count", 2), ("key.length", r2.l_std))
            return (f"{single}; use two keys of the standard length {_f(r2.l_std)} mm "
                    f"(key.count = 2, key.length = {_f(r2.l_std)}; re-rated, they pass)"), fix
    return (f"{single}{'' if k.count == 1 else ' with two keys'}; use a spline or an "
            f"interference fit (kind = \"connection\" with [spline] or [fit]), or a larger "
            f"shaft"), ()


def _key_report(res: Result, k: I.KeyInput, ld: I.Load, r: solve.KeySolution) -> None:
    method = S.KEY_DIN if k.din else S.KEY_GOST
    res.methods = ["GOST 23360-78, DIN 6885-1", "DIN 6892 method C" if k.din else
                   "GOST practice (Ivanov, Dunaev)"]
    geo = res.section("geometry", "Key")
    geo.add("b", k.b, "mm", "b", "key width", k.source)
    geo.add("h", k.h, "mm", "h", "key height", k.source)
    geo.add("t1", k.t1, "mm", "t1", "keyway depth in the shaft", k.source)
    if k.t2 is not None:
        geo.add("t2", k.t2, "mm", "t2", "keyway depth in the hub", k.source)
    geo.add("l_p", r.l_p, "mm", "l_p", f"bearing length (form {k.form})", S.KEY_GOST)
    geo.add("n_eff", r.n_eff, "-", "n·φ", "load-carrying key count (two keys carry 1.5×)",
            S.KEY_SHARE)

    st = res.section("strength", "Pressure and shear")
    st.add("T_d", ld.T_d / 1e3, "N·m", "K_A·T", "design torque", S.KEY_GOST)
    hub = r.flanks[0]
    st.add("k_hub", hub.k, "mm", "k = h − t1", "engaged height on the hub side", method)
    st.add("p_hub", hub.p, "MPa", "p", "bearing pressure, hub side", method)
    if k.din:
        shaft = r.flanks[1]
        st.add("k_shaft", shaft.k, "mm", "t1", "engaged height on the shaft side", S.KEY_DIN)
        st.add("p_shaft", shaft.p, "MPa", "p", "bearing pressure, shaft side", S.KEY_DIN)
        for fl in r.flanks:
            st.add(f"p_zul_{fl.side}", fl.p_allow, "MPa", "p_zul",
                   f"permissible pressure, {fl.side}", r.allow_source)
    else:
        st.add("p_allow", hub.p_allow, "MPa", "[σ]см", f"permissible bearing pressure "
               f"({k.hub_material.replace('_', '-')} hub)", r.allow_source)
    st.add("tau", r.tau, "MPa", "τ", "shear stress of the key", S.KEY_GOST)
    st.add("tau_allow", r.tau_allow, "MPa", "[τ]", "permissible shear stress", r.tau_source)
    for fl in r.flanks:
        st.add(f"S_{fl.side}", fl.p_allow / fl.p, "-", f"S_{fl.side}",
               f"pressure safety, {fl.side} (permissible/actual)", method)

    ds = res.section("design", "Key length that passes")
    ds.add("l_p_min", r.l_p_min, "mm", "l_p,min", "least bearing length", S.KEY_GOST)
    ds.add("l_min", r.l_min, "mm", "l_min", f"least key length (form {k.form})", S.KEY_GOST)
    ds.add("l_std", r.l_std, "mm", "l_std", "shortest standard length that passes",
           S.KEY_LENGTHS)

    advice, fix = _key_advice(r, k, ld)
    for fl in r.flanks:
        where = "on the key" if fl.side == "key" else f"on the {fl.side} side"
        res.checks.append(check(
            fl.code, fl.p <= fl.p_allow, "error",
            f"bearing pressure {where} p = {fl.p:.1f} MPa exceeds {fl.p_allow:.1f} MPa: "
            f"{advice}",
            f"bearing pressure {where} p = {fl.p:.1f} MPa <= {fl.p_allow:.1f} MPa",
            fl.p, fl.p_allow, method, fix))
    res.checks.append(check(
        "KEY_SHEAR", r.tau <= r.tau_allow, "error",
        f"key shear τ = {r.tau:.1f} MPa exceeds {r.tau_allow:.1f} MPa: {advice}",
        f"key shear τ = {r.tau:.1f} MPa <= {r.tau_allow:.1f} MPa", r.tau, r.tau_allow,
        S.KEY_GOST, fix))
    L_hub = k.hub_length
    l_ratio = KEY_LENGTH_RATIO * k.d
    res.checks.append(check(
        "KEY_LENGTH_RATIO", k.l <= l_ratio + 1e-9, "warning",
        f"key length {_f(k.l)} mm > {KEY_LENGTH_RATIO:g}·d = {_f(l_ratio)} mm: the part beyond "
        f"carries little (shaft torsion loads the key's end), so the pressure is understated; "
        f"use two keys, a spline or an interference fit",
        f"key length {_f(k.l)} mm <= {KEY_LENGTH_RATIO:g}·d = {_f(l_ratio)} mm", k.l, l_ratio,
        S.KEY_PRACTICE))
    if L_hub is not None:
        shortest = (f"the shortest standard key that passes ({_f(r.l_std)} mm) is longer "
                    f"than the hub ({_f(L_hub)} mm)" if math.isfinite(r.l_std) else
                    f"no standard key length of this section passes (not even the longest), "
                    f"so none fits the {_f(L_hub)} mm hub")
        res.checks.append(check(
            "KEY_HUB_LENGTH", r.l_std <= L_hub, "warning",
            f"{shortest}: use two keys (key.count = 2), a longer hub or a spline",
            f"a standard key of {_f(r.l_std)} mm passes and fits the {_f(L_hub)} mm hub",
            r.l_std if math.isfinite(r.l_std) else None, L_hub, S.KEY_LENGTHS))


# --------------------------------------------------------------------------- spline


def _spline_report(res: Result, s: I.SplineInput, ld: I.Load,
                   r: solve.SplineSolution) -> None:
    res.methods = ["GOST 6033-80 (Ivanov)" if s.gost else "DIN 5480, DIN 5466"]
    method = S.SPLINE_GOST if s.gost else S.SPLINE_DIN
    g = r.g
    geo = res.section("geometry", "Spline geometry")
    geo.add("d_B", g.d_B, "mm", "d_B", "reference (nominal) diameter", s.source)
    geo.add("m", g.m, "mm", "m", "module", s.source)
    geo.add("z", g.z, "-", "z", "number of teeth", s.source)
    geo.add("d", g.d, "mm", "d = m·z", "pitch diameter", S.SPLINE_GEOM)
    geo.add("x", g.x, "-", "x", "profile shift coefficient", S.SPLINE_GEOM)
    geo.add("d_a1", g.d_a1, "mm", "d_a1", "tip diameter, shaft", S.SPLINE_GEOM)
    geo.add("d_a2", g.d_a2, "mm", "d_a2", "tip diameter, hub", S.SPLINE_GEOM)
    geo.add("h_w", g.h_w, "mm", "h_w", "bearing tooth height", method)
    geo.add("d_m", g.d_m, "mm", "d_m", "mean diameter of the bearing flank", method)

    st = res.section("strength", "Flank pressure")
    st.add("T_d", ld.T_d / 1e3, "N·m", "K_A·T", "design torque", method)
    st.add("p", r.p, "MPa", "p", "mean flank pressure 2T/(d_m·z·h_w·l·ψ)", method)
    st.add("p_allow", r.p_allow, "MPa", "[p]", f"permissible pressure ({s.use}, "
           f"{s.hardness}, {s.conditions})", r.allow_source)
    st.add("S_p", r.p_allow / r.p, "-", "S_p", "pressure safety (permissible/actual)", method)
    ds = res.section("design", "Length that passes")
    ds.add("l_min", r.l_min, "mm", "l_min", "least engaged length", method)
    res.checks.append(check(
        "SPLINE_PRESSURE", r.p <= r.p_allow, "error",
        f"flank pressure p = {r.p:.1f} MPa exceeds {r.p_allow:.1f} MPa: lengthen the hub to at "
        f"least {_f(r.l_min, 1)} mm, use a larger spline"
        + (" or hardened teeth" if s.hardness == "soft" else ""),
        f"flank pressure p = {r.p:.1f} MPa <= {r.p_allow:.1f} MPa", r.p, r.p_allow, method))
    res.checks.append(check(
        "SPLINE_LENGTH", s.l <= 1.5 * s.d_B, "warning",
        f"engaged length {_f(s.l)} mm exceeds 1.5·d_B = {_f(1.5 * s.d_B)} mm: the load does not "
        f"spread over such a length (torsional wind-up); use a larger diameter",
        f"engaged length {_f(s.l)} mm <= 1.5·d_B", s.l, 1.5 * s.d_B, S.PRACTICE))


# --------------------------------------------------------------------------- fit


def _fit_report(res: Result, f: I.FitInput, ld: I.Load, r: solve.FitSolution) -> None:
    res.methods = ["DIN 7190-1 (elastic)", "ISO 286" if f.fit_name else "interference given",
                   f"permissible joint pressure: {f.pressure_limit}"]
    limit = S.PRESSURE_LIMIT[f.pressure_limit]
    geo = res.section("interference", "Interference")
    if f.fit_name:
        geo.add("U_min", f.U_min, "µm", "U_min", f"smallest interference ({f.fit_name})",
                f.source)
        geo.add("U_max", f.U_max, "µm", "U_max", f"largest interference ({f.fit_name})",
                f.source)
    geo.add("Q_A", r.Q_A, "-", "Q_A", "hub diameter ratio d_F/D_aA", S.LAME)
    geo.add("Q_I", r.Q_I, "-", "Q_I", "shaft diameter ratio D_iI/d_F", S.LAME)
    geo.add("smoothing", r.smoothing, "µm", "0.8·ΣRz", "interference lost by smoothing",
            S.SMOOTHING)
    geo.add("U_w_min", r.U_w_min, "µm", "U_w,min", "effective smallest interference",
            S.SMOOTHING)
    geo.add("U_w_max", r.U_w_max, "µm", "U_w,max", "effective largest interference",
            S.SMOOTHING)

    cap = res.section("capacity", "Joint pressure and transmittable load")
    cap.add("p_min", r.p_min, "MPa", "p_min", "joint pressure at the smallest interference",
            S.LAME)
    cap.add("p_max", r.p_max, "MPa", "p_max", "joint pressure at the largest interference",
            S.LAME)
    cap.add("mu", f.mu, "-", "μ", f"coefficient of friction ({f.joining}, {f.surface})",
            f.mu_source)
    cap.add("T_slip", r.T_slip / 1e3, "N·m", "T_slip", "transmittable torque at p_min "
            "(π/2·d²·l·μ·p)", S.SLIP)
    cap.add("F_slip", r.F_slip, "N", "F_slip",
            "transmittable axial force at p_min (π·d·l·μ·p)", S.SLIP)
    cap.add("T_d", ld.T_d / 1e3, "N·m", "K_A·T", "design torque", S.SLIP)
    cap.add("S_slip", r.S_slip, "-", "S_R", "safety against slip at the smallest interference",
            S.SLIP)
    cap.add("p_req", r.p_req, "MPa", "p_req", f"joint pressure needed for S_R = {_f(f.S_R)}",
            S.SLIP)
    cap.add("U_req", r.U_req, "µm", "U_req", "least interference needed (with smoothing)",
            S.SLIP)

    s = r.stress
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
    st.add("pressure_limit", f.pressure_limit, "-", "model", "model of the permissible joint "
           "pressure", limit)
    st.add("p_perm_hub", r.p_perm_hub, "MPa", "p_zul,A", "joint pressure at which the hub "
           "yields", limit)
    st.add("p_perm_shaft", r.p_perm_shaft, "MPa", "p_zul,I", "joint pressure at which the "
           "shaft yields", limit)
    st.add("S_P_hub", r.S_P_hub, "-", "S_P,A", "safety against yield, hub (p_zul,A/p_max)",
           limit)
    st.add("S_P_shaft", r.S_P_shaft, "-", "S_P,I", "safety against yield, shaft "
           "(p_zul,I/p_max)", limit)
    st.add("U_perm", r.U_perm, "µm", "U_perm", f"largest interference for S_P = {_f(f.S_P)} "
           f"(with smoothing)", limit)

    asm = res.section("assembly", "Assembly")
    asm.add("mu_press_in", f.mu_e, "-", "μ_e", f"coefficient of friction for pressing in "
            f"({f.surface})", f.mu_e_source)
    asm.add("F_press", r.F_press, "N", "F_e", "press-in force at the largest interference "
            "(π·d·l·μ_e·p_max)", S.ASSEMBLY)
    asm.add("clearance", f.clearance, "mm", "Δs", "joining clearance", S.ASSEMBLY)
    asm.add("theta_hub", r.theta, "°C", "ϑ_A", "hub temperature for shrinking on", S.ASSEMBLY)

    window = (f"the fit must lie between {_f(r.U_req, 1)} µm (slip) and {_f(r.U_perm, 1)} µm "
              f"(yield)" if r.U_req <= r.U_perm else
              f"no interference satisfies both slip ({_f(r.U_req, 1)} µm needed) and yield "
              f"({_f(r.U_perm, 1)} µm allowed): lengthen the joint, enlarge the hub or use a "
              f"stronger material")
    res.checks.append(check(
        "FIT_SLIP", r.S_slip >= f.S_R, "error",
        f"the joint slips: safety {r.S_slip:.2f} < {_f(f.S_R)} at the smallest interference; "
        f"raise the smallest interference to {_f(r.U_req, 1)} µm or more (a tighter fit)"
        + (", use degreased (dry) joint faces" if f.surface == "oiled" else "")
        + f" or lengthen the joint; {window}",
        f"safety against slip {r.S_slip:.2f} >= {_f(f.S_R)}", r.S_slip, f.S_R, S.SLIP))
    for code, part, S_p in (("FIT_HUB_YIELD", "hub", r.S_P_hub),
                            ("FIT_SHAFT_YIELD", "shaft", r.S_P_shaft)):
        res.checks.append(check(
            code, S_p >= f.S_P, "error",
            f"the {part} yields at the largest interference: safety {S_p:.2f} < {_f(f.S_P)} "
            f"({f.pressure_limit}); "
            f"keep the largest interference below {_f(r.U_perm, 1)} µm (a looser fit) or use "
            f"a stronger material (a thicker wall hardly helps: the stress at the bore follows "
            f"the interference)",
            f"{part} safety against yield {S_p:.2f} >= {_f(f.S_P)} ({f.pressure_limit})",
            S_p if math.isfinite(S_p) else None, f.S_P, limit))
    if f.joining == "shrink":
        res.checks.append(check(
            "FIT_SHRINK_TEMPERATURE", r.theta <= SHRINK_TEMPERATURE_MAX, "warning",
            f"the hub must be heated to {r.theta:.0f} °C, above {SHRINK_TEMPERATURE_MAX:.0f} °C: "
            f"it may lose its heat treatment; cool the shaft as well, or use a looser fit",
            f"hub temperature for shrinking {r.theta:.0f} °C <= "
            f"{SHRINK_TEMPERATURE_MAX:.0f} °C", r.theta, SHRINK_TEMPERATURE_MAX, S.ASSEMBLY))
