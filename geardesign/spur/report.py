"""Report of a solved spur pair: the record of :func:`geardesign.spur.solve.solve` as rows
of a :class:`~geardesign.core.result.Result` and its checks (with the face-width advice
found by re-rating).  A row function computes nothing beyond formatting: every value comes
from the record.
"""

from __future__ import annotations

import math

from geardesign.core.result import Result, Section, check
from geardesign.gears import internal as I
from geardesign.spur import sources as S
from geardesign.spur.checks import ADVICE_FACE_MAX, LOAD_INPUTS, geometry_checks
from geardesign.gears.geometry import PairGeometry
from geardesign.spur.solve import GOST, ISO, Record

def _pair(sec: Section, key: str, values: tuple, unit: str, symbol: str, name: str,
          source: str) -> None:
    for i, v in enumerate(values):
        who = ("pinion", "wheel")[i]
        sec.add(f"{key}{i + 1}", v, unit, f"{symbol}{i + 1}", f"{name}, {who}", source)


def add_geometry_rows(res: Result, g: PairGeometry, how: str) -> None:
    """Report rows of the pair geometry (also used by calculators that reuse this pair).
    An internal pair (``g.internal``) reports x2 − x1 instead of x1 + x2, the shift of the
    internal gear in both signs, and its tip and cutting interference."""
    p = g.inp
    g1, g2 = g.gears
    internal = getattr(g, "internal", False)
    src = S.G19274 if internal else S.G16532
    sec = res.section("geometry", "Geometry" + (" (internal pair)" if internal else ""))
    if internal:
        sec.add("internal", True, None, "", "internal pair: gear 2 is an internal gear", src)
        sec.add("convention", "GOST 19274-73 (z2 > 0, x2 > 0 away from the axis)", None, "",
                "sign convention of the internal gear (as given)", src)
    sec.add("u", g.u, "-", "u", "gear ratio z2/z1", src)
    sec.add("m_t", g.m_t, "mm", "m_t", "transverse module", src)
    sec.add("alpha_t", g.alpha_t, "rad", "α_t", "transverse pressure angle", src)
    sec.add("beta_b", g.beta_b, "rad", "β_b", "base helix angle", src)
    if internal:
        sec.add("x_diff", g.x_diff, "-", "x_d", "shift difference x2 − x1 (GOST sign)", src)
        sec.add("x1", p.x1, "-", "x1", "profile shift coefficient, pinion", src)
        sec.add("x2", p.x2, "-", "x2", "profile shift coefficient, internal gear "
                "(GOST 19274-73 sign)", src)
        sec.add("x2_iso", I.x_to_iso(p.x2), "-", "x2,ISO",
                "profile shift coefficient, internal gear (ISO 21771 sign)", src)
        sec.add("k_tip2", p.k2, "-", "k2", "tip shortening coefficient of the internal gear", src)
    else:
        sec.add("x_sum", g.x_sum, "-", "x_Σ", "sum of profile shift coefficients", src)
        _pair(sec, "x", (p.x1, p.x2), "-", "x", "profile shift coefficient", src)
    sec.add("shift_source", how, None, "", "how the shifts were obtained", src)
    sec.add("alpha_tw", g.alpha_tw, "rad", "α_tw", "working transverse pressure angle", src)
    sec.add("a", g.a, "mm", "a", "reference centre distance"
            + (" m_t(z2 − z1)/2" if internal else ""), src)
    sec.add("a_w", g.a_w, "mm", "a_w", "working centre distance", src)
    sec.add("y", g.y, "-", "y", "centre distance modification coefficient", src)
    sec.add("delta_y", g.dy, "-", "Δy", "x_d − y (not applied to the tips of an internal pair)"
            if internal else "tip shortening coefficient (x_Σ − y)", src)
    _pair(sec, "d", (g1.d, g2.d), "mm", "d", "reference diameter", src)
    _pair(sec, "d_b", (g1.d_b, g2.d_b), "mm", "d_b", "base diameter", src)
    _pair(sec, "d_w", (g1.d_w, g2.d_w), "mm", "d_w", "working pitch diameter", src)
    if internal:
        sec.add("d_a1", g1.d_a, "mm", "d_a1", "tip diameter, pinion", src)
        sec.add("d_a2", g2.d_a, "mm", "d_a2", "tip diameter, internal gear: "
                "d2 − 2(h_a* − x2 − k2)m_n", src)
    else:
        _pair(sec, "d_a", (g1.d_a, g2.d_a), "mm", "d_a", "tip diameter", src)
    _pair(sec, "d_f", (g1.d_f, g2.d_f), "mm", "d_f", "root diameter", src)
    _pair(sec, "h", (g1.h, g2.h), "mm", "h", "tooth depth", src)
    sec.add("c_12", g.c_12, "mm", "c_12", "radial clearance, pinion tip to wheel root", src)
    sec.add("c_21", g.c_21, "mm", "c_21", "radial clearance, wheel tip to pinion root", src)
    sec.add("p_bt", g.p_bt, "mm", "p_bt", "transverse base pitch", src)
    sec.add("p_bn", g.p_bn, "mm", "p_bn", "normal base pitch", src)
    sec.add("g_alpha", g.g_alpha, "mm", "g_α", "length of the active line of action", src)
    sec.add("eps_alpha", g.eps_alpha, "-", "ε_α", "transverse contact ratio"
            + (" (internal mesh)" if internal else ""), src)
    sec.add("eps_beta", g.eps_beta, "-", "ε_β", "overlap ratio", src)
    sec.add("eps_gamma", g.eps_gamma, "-", "ε_γ", "total contact ratio", src)
    sec.add("psi_bd", p.b_w / g1.d_w, "-", "ψ_bd", "face width ratio b_w/d_w1", S.PRACTICE)

    q = res.section("quality", "Meshing quality")
    if internal:   # no undercut of an internal gear
        q.add("x_min1", g1.x_min, "-", "x_min1", "least shift without undercut, pinion",
              S.G16532)
    else:
        _pair(q, "x_min", (g1.x_min, g2.x_min), "-", "x_min", "least shift without undercut",
              S.G16532)
    _pair(q, "alpha_a", (g1.alpha_a, g2.alpha_a), "rad", "α_a", "pressure angle at the tip",
          src)
    _pair(q, "rho_a", (g1.rho_a, g2.rho_a), "mm", "ρ_a", "radius of curvature at the tip",
          src)
    _pair(q, "rho_p", (g1.rho_p, g2.rho_p), "mm", "ρ_p",
          "radius of curvature at the " + ("active limit of the profile" if internal else
                                           "lower point of active profile"), src)
    _pair(q, "rho_l", (g1.rho_l, g2.rho_l), "mm", "ρ_l",
          "radius of curvature at the form point (end of the generated involute)", src)
    _pair(q, "d_p", (g1.d_p, g2.d_p), "mm", "d_p", "diameter of the " + (
        "active limit of the profile (internal gear: its outer end)" if internal else
        "lower point of active profile"), src)
    _pair(q, "d_l", (g1.d_l, g2.d_l), "mm", "d_l", "form circle diameter", src)
    q.add("g_w", g.g_w, "mm", "g_w", "line of action N1N2 = a_w·sin α_tw", src)
    if internal:
        internal_rows(q, g)

    t = res.section("thickness", "Tooth thickness and measurement")
    _pair(t, "s_n", (g1.s_n, g2.s_n), "mm", "s_n", "normal tooth thickness at the reference circle",
          src)
    _pair(t, "s_an", (g1.s_an, g2.s_an), "mm", "s_an", "normal tooth thickness at the tip",
          src)
    span = S.G19274 if internal else S.G16532_SPAN
    _pair(t, "k", (g1.k, g2.k), "-", "k", "number of teeth (internal gear: spaces) spanned",
          span)
    _pair(t, "W", (g1.W, g2.W), "mm", "W", "base tangent length (span) over k teeth", span)
    _pair(t, "d_W", (g1.d_W, g2.d_W), "mm", "d_W", "diameter of the calliper contact", span)


def internal_rows(sec: Section, g) -> None:
    """Rows of an internal mesh's tip and cutting interference (an
    :class:`~geardesign.gears.internal.InternalPairGeometry`), in the spur report and in
    every planet–ring mesh of the planetary report."""
    if g.delta_tip is not None:
        sec.add("delta_tip", g.delta_tip, "-", "δ", "tip interference measure (≥ 0: none)",
                S.G19274_MEMORY)
    if g.cutting is not None:
        cg = g.cutting
        sec.add("alpha_tw0", cg.alpha_tw0, "rad", "α_tw0", "cutting pressure angle (shaper)",
                S.G19274)
        sec.add("a_w0", cg.a_w0, "mm", "a_w0", "cutting centre distance (shaper)", S.G19274)
        sec.add("d_a0", cg.d_a0, "mm", "d_a0", "shaper tip diameter (at the ring root)",
                S.G19274)
        if math.isfinite(cg.delta0):
            sec.add("delta_cut", cg.delta0, "-", "δ_0",
                    "cutting tip interference measure (≥ 0: none)", S.G19274_MEMORY)


_SECTIONS = {"forces": "Loads and forces", "life": "Life and load cycles",
             "factors": "Load factors", "contact": "Contact fatigue",
             "bending": "Bending fatigue", "static": "Peak (static) load"}


def add_strength(res: Result, record) -> None:
    """Rows and checks of every method the pair was rated by (``record.ratings``), each
    under its own sections; the mesh forces alone when GOST 21354-87 is not among them."""
    spec, geom, st = record.inputs.spec, record.geometry, record.inputs.strength
    rated = {}
    if GOST in record.ratings:
        rated[GOST] = _add_gost_strength(res, geom, spec, st, record.ratings[GOST])
    elif record.forces is not None:   # the mesh forces (shafts, bearings, a drive)
        for row in record.forces.rows:
            res.section(row.section, _SECTIONS[row.section]).add(
                row.key, row.value, row.unit, row.symbol, row.name, row.source)
    if ISO in record.ratings:
        from geardesign.spur.strength.iso6336.report import add_iso_strength

        rated[ISO] = add_iso_strength(res, geom, spec, st, rating=record.ratings[ISO],
                                      iso=record.inputs.iso)
    _add_method_checks(res, spec, rated)


def _add_method_checks(res: Result, spec, rated: dict) -> None:
    """The checks over the methods' ratings (``rated``: method → value record): a load
    that looks like a unit slip (the lightest of the methods' readings) and, with both
    methods, the factors in which they differ most."""
    from geardesign.core.units_guard import given
    from geardesign.spur.checks import contact_load_fraction, light_load_checks

    if rated:
        v = min(rated.values(), key=lambda x: contact_load_fraction(x)[0])
        res.checks.extend(light_load_checks(v, given(spec.data["load"], LOAD_INPUTS, "load")))
    if len(rated) == 2:
        from geardesign.spur.methods_differ import methods_differ

        res.checks.extend(methods_differ(rated, spec))


def _add_gost_strength(res: Result, geom: PairGeometry, spec, inputs, rating) -> dict:
    """Rows and checks of the pair's GOST 21354-87 ``rating`` (``inputs``: materials,
    duty, setting), the face-width and scale advice found by re-rating a failing pair; the
    rating's value record."""
    from geardesign.materials.gear_steel import data_used
    from geardesign.spur.strength.checks import rating_checks
    from geardesign.spur.strength import method

    mats, duty, setting = inputs
    res.methods.append("GOST 21354-87")
    sec = res.section("materials", "Materials")
    for k, m in enumerate(mats, 1):
        sec.add(f"material{k}", m.label, None, f"mat{k}", ("pinion", "wheel")[k - 1],
                "library" if not m.given else "library + spec")
        sec.add(f"material{k}_source", data_used(m), None, f"src{k}",
                f"data used, {('pinion', 'wheel')[k - 1]}", "library" if m.grade else "spec")
        sec.add(f"HB{k}", m.HB, "HB", f"HB{k}", "surface hardness in HB (converted)",
                "GOST 21354-87 (ZPCIL fit)")
        if m.sigma_T is not None:
            sec.add(f"sigma_T{k}", m.sigma_T, "MPa", f"σ_T{k}", "yield strength of the blank",
                    "spec" if "sigma_T" in m.given else "library")
    for row in rating.rows:
        res.section(row.section, _SECTIONS[row.section]).add(
            row.key, row.value, row.unit, row.symbol, row.name, row.source)
    v = rating.v
    b_contact = b_bending = k_contact = None
    face_limit = ADVICE_FACE_MAX
    contact_fails = v["sigma_H"] > v["sigma_HP"] * (1 + 1e-12)
    bending_fails = any(v[f"S_F{k}"] < v[f"S_F{k}_min"] * (1 - 1e-12) for k in (1, 2))
    from geardesign.core.rerating import rerating

    if (contact_fails or bending_fails) and not getattr(geom, "internal", False) \
            and not rerating():   # a candidate's re-rating reads the verdicts only
        from dataclasses import replace

        from geardesign.spur.checks import (face_advice_limit, least_passing,
                                            reconciled_widths)
        from geardesign.gears.geometry import pair_geometry

        rate = method("GOST 21354-87").rate
        inp = geom.inp
        face_limit = face_advice_limit(inp.b_w, geom.g1.d_w)

        def rerate(b: float) -> dict:
            return rate(pair_geometry(replace(inp, b_w=b)), mats, duty, setting).v

        def rescale(k: float) -> dict:   # the pair scaled: a_w, module, face width ∝ k
            return rate(pair_geometry(replace(inp, m_n=k * inp.m_n, b_w=k * inp.b_w)), mats,
                        duty, setting).v

        def contact_ok(x: dict) -> bool:
            return x["sigma_H"] <= x["sigma_HP"] * (1 + 1e-12)

        if contact_fails:
            b_contact = least_passing(rerate, inp.b_w, contact_ok, face_limit)
            k_contact = least_passing(rescale, 1.0, contact_ok, 4.0)
        if bending_fails:
            b_bending = least_passing(
                rerate, inp.b_w,
                lambda x: all(x[f"S_F{k}"] >= x[f"S_F{k}_min"] * (1 - 1e-12) for k in (1, 2)),
                face_limit)
        b_contact, b_bending = reconciled_widths(b_contact, b_bending)
    internal = getattr(geom, "internal", False)   # no re-rated advice for an internal pair
    res.checks.extend(rating_checks(rating, found={
        "b": (None if internal else geom.inp.b_w, b_contact, b_bending),
        "k": (geom.a_w, k_contact, None), "face_limit": face_limit}))
    from geardesign.spur.methods_differ import GOST, advised

    gov = 1 if v["sigma_HP1"] <= v["sigma_HP2"] else 2
    return {**v, "advice": advised(
        GOST, b_contact or b_bending, None if k_contact is None else k_contact * geom.a_w,
        v[f"sigma_Hlim{gov}"] * v["sigma_H"] / v["sigma_HP"] if contact_fails else None)}



def report(record: Record) -> Result:
    """The report of a solved pair: the inputs echoed (from the spec the inputs were read
    from), geometry, drawing data, kinematics, each method's rating, and the checks with
    advice.  ``record.inputs.spec`` must be set (:func:`geardesign.spur.inputs.from_spec`,
    :func:`geardesign.load`)."""
    from geardesign.spur import CALCULATOR

    inp = record.inputs
    spec = inp.spec
    if spec is None:
        raise ValueError("the report echoes the spec the inputs were read from: build the "
                         "inputs with geardesign.load() or spur.inputs.from_tables()")
    geom, how, sl = record.geometry, inp.how, record.sliding
    notes = inp.design.notes if inp.design is not None else None
    variants = inp.design.variants if inp.design is not None else None
    strength = inp.strength
    internal = getattr(geom, "internal", False)
    res = CALCULATOR.new_result(spec)
    if internal:
        res.methods.append("GOST 19274-73")
    res.pair_geometry = geom  # for --profile and --plot (geardesign.spur.export)
    if notes is not None:
        sec = res.section("design", "Design proposal")
        for row in notes:
            sec.add(*row)
        from geardesign.core.result import DataTable

        res.tables.append(DataTable("design_variants", "Design variants rated (passing first, "
                                    "by centre distance, then reserve)", [
            ("rank", "rank", "-"), ("a_w", "a_w", "mm"), ("m_n", "m_n", "mm"),
            ("z1", "z1", "-"), ("z2", "z2", "-"), ("beta", "β", "deg"), ("b_w", "b_w", "mm"),
            ("x1", "x1", "-"), ("x2", "x2", "-"), ("S_H", "S_H", "-"), ("S_F1", "S_F1", "-"),
            ("S_F2", "S_F2", "-"), ("margin", "reserve", "-"), ("mass", "mass", "kg"),
            ("passes", "passes", None)], variants))
    add_geometry_rows(res, geom, how)
    if spec.data.get("accuracy") is not None or spec.data.get("drawing") is not None:
        from geardesign.spur.drawing import add_drawing

        add_drawing(res, geom, spec)

    k = res.section("kinematics", "Kinematics and sliding")
    k.add("theta1_A", sl.theta1_A, "-", "ϑ1(A)", "specific sliding, pinion root (start of action)",
          S.SLIDING)
    k.add("theta2_A", sl.theta2_A, "-", "ϑ2(A)", "specific sliding, wheel tip (start of action)",
          S.SLIDING)
    k.add("theta1_E", sl.theta1_E, "-", "ϑ1(E)", "specific sliding, pinion tip (end of action)",
          S.SLIDING)
    k.add("theta2_E", sl.theta2_E, "-", "ϑ2(E)", "specific sliding, wheel root (end of action)",
          S.SLIDING)
    k.add("sigma12_A", sl.sigma12_A, "-", "σ12(A)", "relative sliding at A (Dobrov)", S.DOBROV)
    k.add("sigma12_E", sl.sigma12_E, "-", "σ12(E)", "relative sliding at E (Dobrov)", S.DOBROV)
    if record.velocities is not None:
        v = record.velocities
        same = " (same sense as the pinion: internal pair)" if internal else ""
        k.add("n2", v.n2, "min^-1", "n2", "wheel speed" + same, S.G16532)
        k.add("omega1", v.omega1, "rad/s", "ω1", "pinion angular velocity", S.SLIDING)
        k.add("omega2", v.omega2, "rad/s", "ω2", "wheel angular velocity" + same, S.SLIDING)
        k.add("v", v.v, "m/s", "v", "pitch-line velocity (at d_w1)", S.SLIDING)
        k.add("v_s_A", v.v_s_A, "m/s", "v_s(A)", "sliding velocity at A (approach)", S.SLIDING)
        k.add("v_s_E", v.v_s_E, "m/s", "v_s(E)", "sliding velocity at E (recess)", S.SLIDING)

    res.checks.extend(geometry_checks(geom, sl, inp.allow_undercut))
    if notes is not None:
        from geardesign.spur.design import first_estimate_check

        res.checks.append(first_estimate_check(notes, spec.data["design"]["psi_ba"]))
    m_n = geom.inp.m_n
    if m_n < 0.1:
        res.checks.append(check(
            "UNITS_MODULE", False, "warning",
            f"module = {m_n:g} mm is below 0.1 mm (instrument gears start there): "
            f"check the units (module is in mm)", "", m_n, 0.1, "plausibility"))
    beta = math.degrees(geom.inp.beta)
    if 0.0 < beta < 1.0:
        res.checks.append(check(
            "UNITS_ANGLE", False, "warning",
            f"helix_angle = {beta:.6g}° is below 1°: check the units (degrees; {beta:.6g} rad "
            f"would be {math.degrees(beta):.2f}°)", "", beta, 1.0, "plausibility"))
    if strength is not None and not record.rated:
        res.checks.append(check(
            "STRENGTH_NOT_RATED", False, "error",
            f"the strength was not rated: this {'internal ' if internal else ''}pair cannot "
            f"mesh as computed (ε_α "
            "< 1, a tip beyond the mate's tangency point, or a pointed tooth; see the failed "
            "geometry checks); correct the geometry first", "",
            None, None, S.G19274 if internal else "[ISO6336-2]"))
    elif strength is not None:
        add_strength(res, record)
    return res

from geardesign.core.modules import callable_module  # noqa: E402

callable_module(__name__, "report")   # spur.report(record)
