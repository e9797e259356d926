"""``kind = "spur"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

This module only maps spec keys to the pure functions of :mod:`geometry`,
:mod:`kinematics` and :mod:`checks`, and their results to report rows.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem
from geardesign.core.result import Result, Section
from geardesign.core.spec import ValidatedSpec
from geardesign.spur import sources as S
from geardesign.spur.checks import geometry_checks
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


def solve_geometry(spec: ValidatedSpec) -> tuple[PairGeometry, str]:
    """Pair geometry of a spec; impossible geometry becomes a one-line input error."""
    p, how = pair_input_from_spec(spec)
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
    """Report rows of the pair geometry (also used by calculators that reuse this pair)."""
    p = g.inp
    g1, g2 = g.gears
    sec = res.section("geometry", "Geometry")
    sec.add("u", g.u, "-", "u", "gear ratio z2/z1", S.G16532)
    sec.add("m_t", g.m_t, "mm", "m_t", "transverse module", S.G16532)
    sec.add("alpha_t", g.alpha_t, "rad", "α_t", "transverse pressure angle", S.G16532)
    sec.add("beta_b", g.beta_b, "rad", "β_b", "base helix angle", S.G16532)
    sec.add("x_sum", g.x_sum, "-", "x_Σ", "sum of profile shift coefficients", S.G16532)
    _pair(sec, "x", (p.x1, p.x2), "-", "x", "profile shift coefficient", S.G16532)
    sec.add("shift_source", how, None, "", "how the shifts were obtained", S.G16532)
    sec.add("alpha_tw", g.alpha_tw, "rad", "α_tw", "working transverse pressure angle",
            S.G16532)
    sec.add("a", g.a, "mm", "a", "reference centre distance", S.G16532)
    sec.add("a_w", g.a_w, "mm", "a_w", "working centre distance", S.G16532)
    sec.add("y", g.y, "-", "y", "centre distance modification coefficient", S.G16532)
    sec.add("delta_y", g.dy, "-", "Δy", "tip shortening coefficient (x_Σ − y)", S.G16532)
    _pair(sec, "d", (g1.d, g2.d), "mm", "d", "reference diameter", S.G16532)
    _pair(sec, "d_b", (g1.d_b, g2.d_b), "mm", "d_b", "base diameter", S.G16532)
    _pair(sec, "d_w", (g1.d_w, g2.d_w), "mm", "d_w", "working pitch diameter", S.G16532)
    _pair(sec, "d_a", (g1.d_a, g2.d_a), "mm", "d_a", "tip diameter", S.G16532)
    _pair(sec, "d_f", (g1.d_f, g2.d_f), "mm", "d_f", "root diameter", S.G16532)
    _pair(sec, "h", (g1.h, g2.h), "mm", "h", "tooth depth", S.G16532)
    sec.add("c_12", g.c_12, "mm", "c_12", "radial clearance, pinion tip to wheel root", S.G16532)
    sec.add("c_21", g.c_21, "mm", "c_21", "radial clearance, wheel tip to pinion root", S.G16532)
    sec.add("p_bt", g.p_bt, "mm", "p_bt", "transverse base pitch", S.G16532)
    sec.add("p_bn", g.p_bn, "mm", "p_bn", "normal base pitch", S.G16532)
    sec.add("g_alpha", g.g_alpha, "mm", "g_α", "length of the active line of action",
            S.G16532)
    sec.add("eps_alpha", g.eps_alpha, "-", "ε_α", "transverse contact ratio", S.G16532)
    sec.add("eps_beta", g.eps_beta, "-", "ε_β", "overlap ratio", S.G16532)
    sec.add("eps_gamma", g.eps_gamma, "-", "ε_γ", "total contact ratio", S.G16532)
    sec.add("psi_bd", p.b_w / g1.d_w, "-", "ψ_bd", "face width ratio b_w/d_w1", S.PRACTICE)

    q = res.section("quality", "Meshing quality")
    _pair(q, "x_min", (g1.x_min, g2.x_min), "-", "x_min", "least shift without undercut",
          S.G16532)
    _pair(q, "alpha_a", (g1.alpha_a, g2.alpha_a), "rad", "α_a", "pressure angle at the tip",
          S.G16532)
    _pair(q, "rho_a", (g1.rho_a, g2.rho_a), "mm", "ρ_a", "radius of curvature at the tip",
          S.G16532)
    _pair(q, "rho_p", (g1.rho_p, g2.rho_p), "mm", "ρ_p",
          "radius of curvature at the lower point of active profile", S.G16532)
    _pair(q, "rho_l", (g1.rho_l, g2.rho_l), "mm", "ρ_l",
          "radius of curvature at the form point (end of the generated involute)",
          S.G16532)
    _pair(q, "d_p", (g1.d_p, g2.d_p), "mm", "d_p", "diameter of the lower point of active profile",
          S.G16532)
    _pair(q, "d_l", (g1.d_l, g2.d_l), "mm", "d_l", "form circle diameter", S.G16532)
    q.add("g_w", g.g_w, "mm", "g_w", "line of action N1N2 = a_w·sin α_tw", S.G16532)

    t = res.section("thickness", "Tooth thickness and measurement")
    _pair(t, "s_n", (g1.s_n, g2.s_n), "mm", "s_n", "normal tooth thickness at the reference circle",
          S.G16532)
    _pair(t, "s_an", (g1.s_an, g2.s_an), "mm", "s_an", "normal tooth thickness at the tip",
          S.G16532)
    _pair(t, "k", (g1.k, g2.k), "-", "k", "number of teeth spanned", S.G16532_SPAN)
    _pair(t, "W", (g1.W, g2.W), "mm", "W", "base tangent length (span) over k teeth",
          S.G16532_SPAN)
    _pair(t, "d_W", (g1.d_W, g2.d_W), "mm", "d_W", "diameter of the calliper contact",
          S.G16532_SPAN)


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.spur import CALCULATOR

    geom, how = solve_geometry(spec)
    res = CALCULATOR.new_result(spec)
    add_geometry_rows(res, geom, how)

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
        k.add("n2", v.n2, "min^-1", "n2", "wheel speed", S.G16532)
        k.add("omega1", v.omega1, "rad/s", "ω1", "pinion angular velocity", S.SLIDING)
        k.add("omega2", v.omega2, "rad/s", "ω2", "wheel angular velocity", S.SLIDING)
        k.add("v", v.v, "m/s", "v", "pitch-line velocity (at d_w1)", S.SLIDING)
        k.add("v_s_A", v.v_s_A, "m/s", "v_s(A)", "sliding velocity at A (approach)", S.SLIDING)
        k.add("v_s_E", v.v_s_E, "m/s", "v_s(E)", "sliding velocity at E (recess)", S.SLIDING)

    res.checks.extend(geometry_checks(geom, sl, spec.data["gear"]["allow_undercut"]))
    return res
