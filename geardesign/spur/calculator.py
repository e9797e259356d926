"""``kind = "spur"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

This module only maps spec keys to the pure functions of :mod:`geometry`,
:mod:`kinematics` and :mod:`checks`, and their results to report rows.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.result import Result, Section, check
from geardesign.core.spec import ValidatedSpec
from geardesign.spur import internal as I
from geardesign.spur import sources as S
from geardesign.spur.checks import ADVICE_FACE_MAX, LOAD_INPUTS, geometry_checks
from geardesign.spur.geometry import (
    BasicRack,
    GeometryError,
    PairGeometry,
    PairInput,
    pair_geometry,
    shift_sum_for_center_distance,
)
from geardesign.spur.kinematics import balanced_shift_split, sliding_at_ends, velocities

X_AGREE = 1e-3  # |x1 + x2 − x_Σ(a_w)| accepted when all three are given
X_SUM_RANGE = (-2.0, 4.0)  # x1 + x2 reachable with each shift in −1…2 (the spec's range)
X_DIFF_RANGE = (-3.0, 3.0)  # x2 − x1 reachable likewise (internal pairs)


def _fmt(x: float) -> str:
    return f"{x:.4f}".rstrip("0").rstrip(".")


def pair_input_from_spec(spec: ValidatedSpec) -> tuple[PairInput, str]:
    """Build the :class:`PairInput` of a spec, resolving the shifts.

    Without ``center_distance`` the shifts are x1, x2 (0 when absent, echoed as assumed).
    With it, x_Σ follows from a_w (GOST 16532-70, reverse task) and is split: x1 or x2
    given, or ``shift_split`` ("sliding": equal specific sliding at the roots, the default;
    "equal": x1 = x2).  Returns the input and a word for how the shifts were obtained.
    """
    g, r = spec.data["gear"], spec.data["rack"]
    rack = BasicRack(math.radians(g["pressure_angle"]), r["addendum_coef"], r["clearance_coef"],
                     r["root_radius_coef"])
    beta = math.radians(g["helix_angle"])
    m, z1, z2, b = g["module"], g["z1"], g["z2"], g["face_width"]
    a_w = g["center_distance"]
    x1, x2, split = g["x1"], g["x2"], g["shift_split"]

    if a_w is None:
        if split is not None:
            raise InputError.at("gear.shift_split", split,
                                "applies only with gear.center_distance; remove it or give "
                                "center_distance")
        for key in ("x1", "x2"):
            if g[key] is None:
                g[key] = 0.0
                spec.assumed.append(f"gear.{key}")
        return PairInput(m, z1, z2, g["x1"], g["x2"], beta, b, rack), "given"

    try:
        x_sum, _ = shift_sum_for_center_distance(a_w, m, z1, z2, rack.alpha_n, beta)
    except GeometryError as exc:
        a = 0.5 * m * (z1 + z2) / math.cos(beta)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"smaller than possible: must exceed (d_b1 + d_b2)/2 = {_fmt(exc.limit)} mm, where "
            f"the base circles touch (x1 + x2 = 0 gives a_w = {_fmt(a)} mm)") from None
    if not X_SUM_RANGE[0] <= x_sum <= X_SUM_RANGE[1]:
        a = 0.5 * m * (z1 + z2) / math.cos(beta)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"needs x1 + x2 = {x_sum:.3f}, outside what two shifts of −1…2 can give "
            f"({X_SUM_RANGE[0]:g}…{X_SUM_RANGE[1]:g}); choose a_w nearer to a = {_fmt(a)} mm")
    if x1 is not None and x2 is not None:
        if split is not None:
            raise InputError.at("gear.shift_split", split,
                                "applies only when x1 or x2 is left out; remove it")
        if abs(x1 + x2 - x_sum) > X_AGREE:
            raise InputError(Problem(
                "gear.x1 + gear.x2", f"does not match center_distance = {_fmt(a_w)} mm, which "
                f"needs x1 + x2 = {x_sum:.4f}; give x1 or x2 only and the other follows",
                x1 + x2))
        return PairInput(m, z1, z2, x1, x_sum - x1, beta, b, rack), "x1 given, x2 = x_Σ − x1"
    if x1 is not None or x2 is not None:
        if split is not None:
            raise InputError.at("gear.shift_split", split,
                                "applies only when neither x1 nor x2 is given; remove it")
        if x1 is not None:
            return PairInput(m, z1, z2, x1, x_sum - x1, beta, b, rack), "x1 given, x2 = x_Σ − x1"
        return PairInput(m, z1, z2, x_sum - x2, x2, beta, b, rack), "x2 given, x1 = x_Σ − x2"
    if split == "equal":
        return PairInput(m, z1, z2, x_sum / 2, x_sum / 2, beta, b, rack), "equal split"
    base = PairInput(m, z1, z2, 0.0, 0.0, beta, b, rack)
    try:
        x1 = balanced_shift_split(base, x_sum)
    except GeometryError:
        raise InputError.at(
            "gear.center_distance", a_w,
            f"no split of x1 + x2 = {x_sum:.4f} balances the specific sliding with a valid "
            f"geometry; give x1 (or x2) explicitly") from None
    return PairInput(m, z1, z2, x1, x_sum - x1, beta, b, rack), "equal specific sliding"


#: Keys of internal pairs only: their defaults are not echoed for an external pair.
INTERNAL_ONLY = ("gear.internal", "gear.cutter_shift", "gear.internal_tip_shortening")


def _given(spec: ValidatedSpec, path: str) -> bool:
    """Whether the spec gave ``path`` itself (not a default)."""
    table, key = path.split(".")
    return path not in spec.assumed and (spec.data.get(table) or {}).get(key) is not None


def internal_input_from_spec(spec: ValidatedSpec) -> tuple[I.InternalPairInput, str]:
    """The :class:`~geardesign.spur.internal.InternalPairInput` of a spec with
    ``gear.internal = true``, resolving the shifts (GOST 19274-73 sign).

    Without ``center_distance`` the shifts are x1, x2 (0 when absent, echoed as assumed).
    With it, x2 − x1 follows from a_w (:func:`~geardesign.spur.internal.
    shift_difference_for_center_distance`); x1 or x2 given, the other follows; neither, x1 = 0
    (assumed).  Rules across keys are input errors naming the key."""
    g, r = spec.data["gear"], spec.data["rack"]
    rack = BasicRack(math.radians(g["pressure_angle"]), r["addendum_coef"], r["clearance_coef"],
                     r["root_radius_coef"])
    beta = math.radians(g["helix_angle"])
    m, z1, z2, b = g["module"], g["z1"], g["z2"], g["face_width"]
    n_min = I.MIN_TEETH_DIFFERENCE
    if z2 - z1 < n_min:
        raise InputError.at("gear.z2", z2, f"an internal gear needs at least {n_min} teeth more "
                            f"than the pinion (gear.z1 = {z1}): with fewer the pair cannot run "
                            f"(tip interference); use z2 >= {z1 + n_min}")
    if _given(spec, "gear.tip_shortening"):
        raise InputError.at("gear.tip_shortening", g["tip_shortening"],
                            "applies to external pairs (the Δy shortening of GOST 16532-70); the "
                            "tip of an internal gear is set by gear.internal_tip_shortening")
    if g["shift_split"] is not None:
        raise InputError.at("gear.shift_split", g["shift_split"],
                            "applies to external pairs only; for an internal pair give x1 or "
                            "x2 and the other follows from center_distance")
    cutter = None
    z0 = g["cutter_teeth"]
    if z0 is not None:
        if z0 + n_min > z2:
            raise InputError.at("gear.cutter_teeth", z0,
                                f"a shaper cuts an internal gear only with fewer teeth: at most "
                                f"{z2 - n_min} for the {z2}-tooth internal gear (gear.z2; the "
                                f"same rule as for the pinion)")
        cutter = I.ShaperCutter(z0, g["cutter_shift"], g["cutter_tip_radius_coef"])
    else:
        for key in ("cutter_shift", "cutter_tip_radius_coef"):
            if _given(spec, f"gear.{key}"):
                raise InputError.at(f"gear.{key}", g[key],
                                    "applies only with gear.cutter_teeth (the shaper cutter); "
                                    f"give it or remove {key}")
    for path in ("gear.tip_shortening",) + (("gear.cutter_shift",) if cutter is None else ()):
        _drop_unused_defaults(spec, (path,))

    def make(x1: float, x2: float) -> I.InternalPairInput:
        return I.InternalPairInput(m, z1, z2, x1, x2, beta, b, rack,
                                   k2=g["internal_tip_shortening"], cutter=cutter)

    a_w, x1, x2 = g["center_distance"], g["x1"], g["x2"]
    if a_w is None:
        for key in ("x1", "x2"):
            if g[key] is None:
                g[key] = 0.0
                spec.assumed.append(f"gear.{key}")
        return make(g["x1"], g["x2"]), "given"
    try:
        x_diff, _ = I.shift_difference_for_center_distance(a_w, m, z1, z2, rack.alpha_n, beta)
    except GeometryError as exc:
        a = 0.5 * m * (z2 - z1) / math.cos(beta)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"smaller than possible for an internal pair: must exceed (d_b2 − d_b1)/2 = "
            f"{_fmt(exc.limit)} mm, where the base circles touch (x2 − x1 = 0 gives a_w = "
            f"{_fmt(a)} mm)") from None
    lo, hi = X_DIFF_RANGE
    if not lo <= x_diff <= hi:
        a = 0.5 * m * (z2 - z1) / math.cos(beta)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"needs x2 − x1 = {x_diff:.3f}, outside what two shifts of −1…2 can give "
            f"({lo:g}…{hi:g}); choose a_w nearer to a = {_fmt(a)} mm")
    if x1 is not None and x2 is not None:
        if abs(x2 - x1 - x_diff) > X_AGREE:
            raise InputError(Problem(
                "gear.x2 − gear.x1", f"does not match center_distance = {_fmt(a_w)} mm, which "
                f"needs x2 − x1 = {x_diff:.4f} (internal pair); give x1 or x2 only and the "
                f"other follows", x2 - x1))
        return make(x1, x1 + x_diff), "x1 given, x2 = x1 + x_d"
    if x2 is not None:
        return make(x2 - x_diff, x2), "x2 given, x1 = x2 − x_d"
    if x1 is None:
        g["x1"] = 0.0
        spec.assumed.append("gear.x1")
    return make(g["x1"], g["x1"] + x_diff), "x1 given, x2 = x1 + x_d"


def _solve_internal(spec: ValidatedSpec) -> tuple[I.InternalPairGeometry, str]:
    p, how = internal_input_from_spec(spec)
    try:
        return I.internal_pair_geometry(p), how
    except GeometryError as exc:
        if exc.code == "INV_ALPHA_TW":
            raise InputError(Problem(
                "gear.x2 − gear.x1",
                f"too negative for an internal pair: {exc}, no working pressure angle exists; "
                f"x2 − x1 (GOST 19274-73 sign) must be > {exc.limit:.4f}", p.x2 - p.x1)) \
                from None
        if exc.code == "RING_TIP_INSIDE_BASE":
            raise InputError.at(
                "gear.x2", p.x2,
                f"the tip circle of the internal gear (d_a2 = {exc.value:.4f} mm) lies inside "
                f"its base circle (d_b2 = {exc.limit:.4f} mm): no involute at its tips; "
                f"increase x2 (GOST 19274-73 sign) or gear.internal_tip_shortening") from None
        if exc.code == "CUTTER_TIP":
            raise InputError.at("gear.cutter_teeth", p.cutter.z0,
                                f"{exc}; use another cutter") from None
        raise InputError.at(
            "gear.x1", p.x1,
            f"the tip circle of the pinion (d_a = {exc.value:.4f} mm) lies inside its base "
            f"circle (d_b = {exc.limit:.4f} mm): no involute flank; increase x1 or z1") \
            from None


def solve_geometry(spec: ValidatedSpec) -> tuple[PairGeometry, str]:
    """Pair geometry of a spec; impossible geometry becomes a one-line input error.  An
    internal pair (``gear.internal``) gives an
    :class:`~geardesign.spur.internal.InternalPairGeometry`."""
    gear = spec.data["gear"]
    if gear.get("internal"):
        return _solve_internal(spec)
    for path in INTERNAL_ONLY[1:]:
        if _given(spec, path):
            raise InputError.at(path, gear[path.split(".")[1]],
                                "applies to internal pairs only; set gear.internal = true or "
                                "remove it")
    for key in ("cutter_teeth", "cutter_tip_radius_coef"):
        if gear.get(key) is not None:
            raise InputError.at(f"gear.{key}", gear[key], "applies to internal pairs only; set "
                                "gear.internal = true or remove it")
    _drop_unused_defaults(spec, INTERNAL_ONLY)
    p, how = pair_input_from_spec(spec)
    if not spec.data["gear"].get("tip_shortening", True):
        from dataclasses import replace

        p = replace(p, tip_shortening=False)
    try:
        return pair_geometry(p), how
    except GeometryError as exc:
        if exc.code == "INV_ALPHA_TW":
            raise InputError(Problem(
                "gear.x1 + gear.x2",
                f"too negative: {exc}, no working pressure angle exists; x1 + x2 must be "
                f"> {exc.limit:.4f}", p.x1 + p.x2)) from None
        i = 1 if exc.code.endswith("_1") else 2
        x = p.x1 if i == 1 else p.x2
        key = f"gear.x{i}" if how == "given" or f"x{i} given" in how else "gear.center_distance"
        value = x if key.endswith(f"x{i}") else spec.data["gear"]["center_distance"]
        raise InputError.at(
            key, value,
            f"the tip circle of gear {i} (d_a = {exc.value:.4f} mm) lies inside its base circle "
            f"(d_b = {exc.limit:.4f} mm): no involute flank; increase x{i} or z{i}") from None


# ----------------------------------------------------------------------------- rows


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
    :class:`~geardesign.spur.internal.InternalPairGeometry`), in the spur report and in
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


def _strength_inputs(spec: ValidatedSpec, gear: dict):
    """Materials, duty and setting of the strength calculation, or ``None`` for a
    geometry-only spec.  Missing pieces are input errors naming the key; every
    independent one is reported in the same round (:class:`Problems`)."""
    from geardesign.materials.gear_steel import resolve
    from geardesign.spur.strength.rating import Setting

    d = spec.data
    load, mat = d["load"], d["material"]
    torque_given = load is not None and (load["torque1"] is not None or load["power"] is not None)
    if mat is None:
        if torque_given:
            raise InputError(Problem("material", "missing table [material.pinion] and "
                                     "[material.wheel]: required with load.torque1 or load.power "
                                     "for the strength calculation"))
        return None
    from geardesign.spur.strength.iso6336.spec import ISO_NAME, chosen

    problems = Problems()
    # the GOST 21354-87 chart of K_Hβ: the GOST rating and the design mode's sizing read it,
    # the ISO 6336 rating does not (K_Hβ by method C from f_sh and f_ma)
    if gear["bearing_scheme"] is None and (d["design"] is not None
                                           or chosen(d["options"]) != [ISO_NAME]):
        where = "design" if d["design"] is not None else "gear"
        why = ("the design mode sizes the pair with the GOST 21354-87 K_Hβ" if d["design"]
               is not None else "the GOST 21354-87 rating")
        problems.add(Problem(f"{where}.bearing_scheme", f"missing; required for {why}: "
                             "1…7 as in the GOST 21354-87 chart (see geardesign template "
                             "spur)"))
    duty = problems.stage(_duty, spec, load, torque_given)
    mats = tuple(problems.stage(lambda who=who: resolve(mat[who], f"material.{who}"))
                 for who in ("pinion", "wheel"))
    problems.raise_all()
    setting = Setting(gear["accuracy_grade"], gear["tip_relief"], gear["bearing_scheme"],
                      (mat["pinion"]["roughness_Ra"], mat["wheel"]["roughness_Ra"]),
                      dict(d["factors"] or {}), d["options"]["contact_model"],
                      d["options"]["crowning"])
    from geardesign.spur.strength.iso6336.spec import prepare

    prepare(spec)
    return mats, duty, setting


def _duty(spec: ValidatedSpec, load: dict | None, torque_given: bool):
    """The duty of the strength calculation from [load] (torque or power, life, regime or
    spectrum, peak torque); input errors name the key."""
    from geardesign.spur.loads import torque_from_power
    from geardesign.spur.strength.rating import Duty, Life

    if load is None:
        raise InputError(Problem("load", "missing table [load] (speed1, torque1, life_hours): "
                                 "required with [material]"))
    problems = Problems()
    if load["torque1"] is not None and load["power"] is not None:
        problems.add(Problem("load.power", "give torque1 or power, not both", load["power"]))
    if not torque_given:
        problems.add(Problem("load.torque1", "missing; required with [material]: the nominal "
                             "pinion torque in N·m (or load.power in kW)"))
    if load["life_hours"] is None:
        problems.add(Problem("load.life_hours", "missing; required with [material]: the "
                             "required life in hours"))
    blocks = problems.stage(_blocks, load)
    problems.raise_all()
    T1 = load["torque1"] if load["torque1"] is not None else torque_from_power(load["power"],
                                                                               load["speed1"])
    if load["peak_torque1"] is not None and load["peak_torque1"] < T1:
        raise InputError.at("load.peak_torque1", load["peak_torque1"],
                            f"smaller than the nominal torque T1 = {_fmt(T1)} N·m; give the "
                            f"largest short-time torque")
    regime = load["regime"]
    if regime is None and not blocks:
        regime = "0"
        load["regime"] = "0"
        spec.assumed.append("load.regime")
    life = Life(load["life_hours"], (load["meshes_pinion"], load["meshes_wheel"]),
                regime if not blocks else None, blocks)
    return Duty(T1, load["speed1"], load["application_factor"], load["peak_torque1"],
                load["reverse_torque_ratio"], life)


def _blocks(load: dict) -> tuple:
    """The load spectrum of [[load.spectrum]] as blocks (empty without one)."""
    from geardesign.spur.loads import Block

    if not load["spectrum"]:
        return ()
    problems = Problems()
    if load["regime"] is not None:
        problems.add(Problem("load.regime", "give a regime or a spectrum, not both",
                             load["regime"]))
    total = sum(b["time_share"] for b in load["spectrum"])
    if abs(total - 1.0) > 1e-6:
        problems.add(Problem("load.spectrum", f"the time shares add up to {total:.6g}; they "
                             "must add up to 1", load["spectrum"]))

    def largest_block() -> None:
        if max(b["torque_ratio"] for b in load["spectrum"]) < 1.0 - 1e-9:
            raise InputError.at("load.spectrum", load["spectrum"], "no block has torque_ratio "
                                "= 1: torque1 must be the torque of the largest long-acting "
                                "block")

    problems.stage(largest_block)
    problems.raise_all()
    return tuple(Block(b["torque_ratio"], b["time_share"], b["speed_ratio"])
                 for b in load["spectrum"])


_SECTIONS = {"forces": "Loads and forces", "life": "Life and load cycles",
             "factors": "Load factors", "contact": "Contact fatigue",
             "bending": "Bending fatigue", "static": "Peak (static) load"}


#: Defaults that only the strength calculation uses: not echoed for a geometry-only spec.
STRENGTH_ONLY = ("gear.accuracy_grade", "gear.tip_relief", "load.application_factor",
                 "load.meshes_pinion", "load.meshes_wheel", "load.reverse_torque_ratio",
                 "options.method", "options.contact_model")


def _drop_unused_defaults(spec: ValidatedSpec, paths: tuple[str, ...]) -> None:
    """Remove assumed defaults that the calculation did not use from the inputs echo."""
    for path in paths:
        if path in spec.assumed:
            spec.assumed.remove(path)
            table, key = path.split(".")
            if spec.data.get(table) is not None:
                spec.data[table].pop(key, None)


def add_strength(res: Result, geom: PairGeometry, spec: ValidatedSpec, inputs) -> None:
    """Rate the pair by every method the spec names (``options.method`` or
    ``options.methods``), each under its own sections."""
    from geardesign.spur.strength.iso6336.spec import ISO_NAME, chosen

    names = chosen(spec.data["options"])
    rated = {}
    if "GOST 21354-87" in names:
        rated["GOST 21354-87"] = _add_gost_strength(res, geom, spec, inputs)
    else:   # the mesh forces (shafts, bearings, a drive) whatever the method
        from geardesign.spur.strength.rating import Rating, put_forces

        forces = Rating()
        put_forces(forces, geom, inputs[1])
        for row in forces.rows:
            res.section(row.section, _SECTIONS[row.section]).add(
                row.key, row.value, row.unit, row.symbol, row.name, row.source)
    if ISO_NAME in names:
        from geardesign.spur.strength.iso6336.report import add_iso_strength

        rated[ISO_NAME] = add_iso_strength(res, geom, spec, inputs)
    _add_method_checks(res, spec, rated)


def _add_method_checks(res: Result, spec: ValidatedSpec, rated: dict) -> None:
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


def _add_gost_strength(res: Result, geom: PairGeometry, spec: ValidatedSpec, inputs) -> dict:
    """Rate the pair to GOST 21354-87 (``inputs`` from :func:`_strength_inputs`); add rows
    and checks; the rating's value record."""
    from geardesign.materials.gear_steel import data_used
    from geardesign.spur.checks import strength_checks
    from geardesign.spur.strength import method

    mats, duty, setting = inputs
    rating = method("GOST 21354-87").rate(geom, mats, duty, setting)
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
    if (contact_fails or bending_fails) and not getattr(geom, "internal", False):
        from dataclasses import replace

        from geardesign.spur.checks import (face_advice_limit, least_passing,
                                            reconciled_widths)
        from geardesign.spur.geometry import pair_geometry

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
    res.checks.extend(strength_checks(v, mats, geom.inp.beta > 0, setting.grade,
                                      duty.T_peak is not None,
                                      None if internal else geom.inp.b_w, b_contact,
                                      b_bending, geom.a_w, k_contact, face_limit))
    from geardesign.spur.methods_differ import GOST, advised

    gov = 1 if v["sigma_HP1"] <= v["sigma_HP2"] else 2
    return {**v, "advice": advised(
        GOST, b_contact or b_bending, None if k_contact is None else k_contact * geom.a_w,
        v[f"sigma_Hlim{gov}"] * v["sigma_H"] / v["sigma_HP"] if contact_fails else None)}


def ratable(g) -> bool:
    """Whether a pair (an internal pair in particular) has the geometry a strength rating needs: a continuous
    transverse mesh (ε_α >= 1, which the contact-ratio factors of both methods presume),
    both active limits before the tangency points and teeth that are not pointed."""
    return (g.eps_alpha >= 1.0 and g.g1.rho_p > 0.0 and g.g2.rho_p > 0.0
            and g.g1.s_an > 0.0 and g.g2.s_an > 0.0)


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """The checks of :func:`compute` that need no computed geometry, run on a spec whose
    schema problems are already reported (:func:`geardesign.core.registry.load_data`):
    the pair's own rules and the strength inputs, each left out when it reads a wrong key."""
    d = spec.data
    if (d["design"] is None) == (d["gear"] is None):
        return   # both or neither: the schema's problem says to give one
    from geardesign.spur.strength.iso6336.spec import unused_tables

    problems.stage(unused_tables, spec)
    if d["gear"] is not None:
        problems.stage(solve_geometry, spec)
    problems.stage(_strength_inputs, spec, d["gear"] if d["gear"] is not None else d["design"])


def _contact_ratio_domain(geom, spec: ValidatedSpec, gear: dict) -> None:
    """Refuse a pair whose tip circles do not overlap on the line of action: ε_α <= 0 is
    outside the domain of every formula that uses it (Z_ε, Y_ε, K_Hα of GOST 21354-87 and
    ISO 6336 take ε_α > 0; ε_α = g_α/p_bt of GOST 16532-70 table 1 item 4 is a length ratio).
    The input to change is the tooth height (``rack.addendum_coef``) or the shifts."""
    if geom.eps_alpha > 0.0:
        return
    rack = spec.data.get("rack") or {}
    shifts = ", ".join(f"gear.{k} = {gear[k]:.3g}" for k in ("x1", "x2")
                       if isinstance(gear.get(k), (int, float)))
    raise InputError.at(
        "rack.addendum_coef", rack.get("addendum_coef", 1.0),
        f"gives with {shifts or 'the shifts'} a transverse contact ratio ε_α = "
        f"{geom.eps_alpha:.3f} <= 0: the tip circles do not overlap on the line of action; "
        "increase rack.addendum_coef (tooth height) or reduce the profile shifts")


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.spur import CALCULATOR
    from geardesign.spur.strength.iso6336.spec import unused_tables

    if spec.data["design"] is not None:
        from geardesign.spur.design import design_pair

        unused_tables(spec)
        geom, how, gear, notes, variants = design_pair(spec)
        strength = _strength_inputs(spec, gear)
    else:   # the geometry and the strength inputs are checked independently: one report
        gear = spec.data["gear"]
        problems = Problems()
        problems.stage(unused_tables, spec)
        solved = problems.stage(solve_geometry, spec)
        strength = problems.stage(_strength_inputs, spec, gear)
        problems.raise_all()
        geom, how = solved
        notes = variants = None
    _contact_ratio_domain(geom, spec, gear)
    if strength is None:
        _drop_unused_defaults(spec, STRENGTH_ONLY)
    if spec.data.get("accuracy") is not None:
        from geardesign.spur.drawing import assume_expansion

        assume_expansion(spec)
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

    sl = sliding_at_ends(geom)
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
    load = spec.data["load"]
    if load is not None:
        v = velocities(geom, load["speed1"])
        same = " (same sense as the pinion: internal pair)" if internal else ""
        k.add("n2", v.n2, "min^-1", "n2", "wheel speed" + same, S.G16532)
        k.add("omega1", v.omega1, "rad/s", "ω1", "pinion angular velocity", S.SLIDING)
        k.add("omega2", v.omega2, "rad/s", "ω2", "wheel angular velocity" + same, S.SLIDING)
        k.add("v", v.v, "m/s", "v", "pitch-line velocity (at d_w1)", S.SLIDING)
        k.add("v_s_A", v.v_s_A, "m/s", "v_s(A)", "sliding velocity at A (approach)", S.SLIDING)
        k.add("v_s_E", v.v_s_E, "m/s", "v_s(E)", "sliding velocity at E (recess)", S.SLIDING)

    res.checks.extend(geometry_checks(geom, sl, gear["allow_undercut"]))
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
    from geardesign.spur.strength.iso6336.spec import ISO_NAME

    opts = spec.data.get("options") or {}
    iso = ISO_NAME in (opts.get("methods") or [opts.get("method")])
    if strength is not None and (internal or iso) and not ratable(geom):
        res.checks.append(check(
            "STRENGTH_NOT_RATED", False, "error",
            f"the strength was not rated: this {'internal ' if internal else ''}pair cannot "
            f"mesh as computed (ε_α "
            "< 1, a tip beyond the mate's tangency point, or a pointed tooth; see the failed "
            "geometry checks); correct the geometry first", "",
            None, None, S.G19274 if internal else "[ISO6336-2]"))
    elif strength is not None:
        add_strength(res, geom, spec, strength)
    return res
