"""The report of a Novikov pair: the solved record (:mod:`geardesign.novikov.solve`) turned
into report rows and checks.  Computes nothing: every number comes from the record; the
forces, the deviations and the allowables are reported from their fields' metadata by the
strength ratings' one :func:`geardesign.spur.strength.common.rows`."""

from __future__ import annotations

import math

from geardesign.core.result import Result, check
from geardesign.novikov import sources as S
from geardesign.novikov.checks import (
    ContinuityData,
    continuity_checks,
    module_checks,
    proportion_checks,
    psi_check,
    stress_check,
)
from geardesign.novikov.engagement import Engagement, PointStress
from geardesign.novikov.factors import Y_A
from geardesign.novikov.geometry import PairGeometry, phase_step
from geardesign.novikov.inputs import Inputs
from geardesign.novikov.rack import STANDARD, module_range, module_series
from geardesign.novikov.solve import MIN_WIDTH_POINTS, Solution
from geardesign.spur.strength.common import add_rows

TITLES = {"forces": "Forces", "deviations": "Stiffness and deviations (error model)",
          "allowables": "Allowable stresses and safety (GOST 21354-87 scheme)"}
"""Sections of the records' rows (:func:`geardesign.spur.strength.common.rows`)."""


def _where(at: PointStress | None, b_w: float) -> str:
    if at is None:
        return "no load"
    gear = "pinion" if at.j == 1 else "wheel"
    return (f"phase {at.k}, tooth {at.zub}, j = {at.j} ({gear} addendum), b = {at.b:.6f}·b_w "
            f"= {at.b * b_w:.1f} mm")


def _table1_formula(i: int, zub: int, j: int) -> str:
    if i == 0:
        return "−(1 − ε_q)/ε_β"
    k = zub - 2
    if j == 1:
        return "0" if k == 0 else f"{k}/ε_β"
    return "ε_q/ε_β" if k == 0 else f"({k} + ε_q)/ε_β"


def _critical_rows(sec, prefix: str, name: str, at: PointStress | None, b_w: float,
                   source: str) -> None:
    """Where a critical stress occurs: phase, tooth, line, position, force, ψ, error case."""
    if at is None:
        return
    sec.add(f"{prefix}_phase", at.k, "-", "k", f"{name}: phase", source)
    sec.add(f"{prefix}_zub", at.zub, "-", "zub", f"{name}: tooth pair (Table 1)", source)
    sec.add(f"{prefix}_j", at.j, "-", "j", f"{name}: line (1 pinion, 2 wheel addendum)", source)
    sec.add(f"{prefix}_b", at.b, "-", "b", f"{name}: position, fraction of b_w", source)
    sec.add(f"{prefix}_b_mm", at.b * b_w, "mm", "b·b_w",
            f"{name}: distance from the entry face end", source)
    sec.add(f"{prefix}_force", at.F, "N", "F", f"{name}: force at the point", S.SHARING)
    sec.add(f"{prefix}_psi", at.psi, "-", "ψ", f"{name}: ψ = a/b_w", S.ELLIPSE)
    sec.add(f"{prefix}_case", at.case, None, "", f"{name}: error case", S.ERROR_MODEL)


def _geometry_rows(res: Result, g: PairGeometry, how: str) -> None:
    p, r = g.inp, g.inp.rack
    src = S.RACK if r.name == STANDARD else "spec (custom rack)"
    sec = res.section("geometry", "Geometry")
    sec.add("rack", r.name, None, "", "basic rack" + ("" if r.verified else
            " (values not verified against a standard)"), src)
    sec.add("alpha_k", r.alpha_k, "rad", "α_k", "profile angle at the contact point", src)
    sec.add("lk_star", r.lk_star, "-", "l_k*", "active addendum path along the chord / m", src)
    sec.add("eps_q", r.eps_q, "-", "ε_q", "phase coefficient of axial overlap (rack constant)",
            src)
    sec.add("h_a_star", r.h_a, "-", "h_a*", "addendum coefficient", src)
    sec.add("h_f_star", r.h_f, "-", "h_f*", "dedendum coefficient", src)
    sec.add("beta", p.beta, "rad", "β", f"helix angle ({how})", S.GEOM)
    sec.add("u", g.u, "-", "u", "gear ratio z2/z1", S.GEOM)
    sec.add("a_w", g.a_w, "mm", "a_w", "centre distance m(z1 + z2)/(2cos β)", S.GEOM)
    for i, (d, da, df, zv) in enumerate(((g.d1, g.d_a1, g.d_f1, g.z_v1),
                                         (g.d2, g.d_a2, g.d_f2, g.z_v2)), start=1):
        who = ("pinion", "wheel")[i - 1]
        sec.add(f"d{i}", d, "mm", f"d{i}", f"reference diameter, {who}", S.GEOM)
        sec.add(f"d_a{i}", da, "mm", f"d_a{i}", f"tip diameter, {who}", S.RACK)
        sec.add(f"d_f{i}", df, "mm", f"d_f{i}", f"root diameter, {who}", S.RACK)
        sec.add(f"z_v{i}", zv, "-", f"z_v{i}", f"virtual number of teeth z/cos³β, {who}", S.GEOM)
    sec.add("p_t", g.p_t, "mm", "p_t", "transverse pitch", S.GEOM)
    sec.add("p_x", g.p_x, "mm", "p_x", "axial pitch π·m/sin β", S.GEOM)
    sec.add("eps_beta", g.eps_beta, "-", "ε_β", "axial overlap ratio b_w/p_x", S.GEOM)
    sec.add("l_k", g.l_k, "mm", "l_k", "active addendum path l_k*·m", S.RACK)
    sec.add("rho_p", g.rho_p, "mm", "ρ_p", "reduced lengthwise radius of curvature", S.RHO_P)
    sec.add("psi_bd", p.b_w / g.d1, "-", "b_w/d1", "face width ratio", S.PRACTICE)


def report(res: Result, inp: Inputs, sol: Solution, load: dict) -> None:
    """Rows and checks of a solved pair into ``res``; ``load`` is the spec's [load] table
    (the inputs the unit guard names)."""
    pair, g, eng = inp.pair, sol.g, sol.eng
    rack, b_w, m = pair.rack, pair.b_w, pair.m
    _geometry_rows(res, g, inp.how)
    _engagement_rows(res, inp, sol)
    add_rows(res, sol.forces, TITLES)
    add_rows(res, sol.stiffness, TITLES)
    _phase_rows(res, eng, b_w)
    _strength_rows(res, sol, b_w)
    add_rows(res, sol.allow, TITLES)
    al = sol.allow
    FP, share_F, share_H = al.sigma_FP, sol.share_F, sol.share_H
    cov, widths = sol.cov, sol.widths
    res.checks.extend(continuity_checks(ContinuityData(
        b_w, g.p_x, g.eps_beta, rack.delta, widths[0], widths[1], cov.n_min, cov.n_max,
        math.degrees(pair.beta))))
    res.checks.append(stress_check("SIGMA_H", eng.sigma_H.value, al.sigma_HP, "σ_Hmax",
                                   _where(eng.sigma_H.at, b_w), share_H, S.CONTACT))
    res.checks.append(stress_check("SIGMA_F_PINION", eng.sigma_F1.value, FP[0], "σ_F1max",
                                   _where(eng.sigma_F1.at, b_w), share_F, S.BENDING))
    res.checks.append(stress_check("SIGMA_F_WHEEL", eng.sigma_F2.value, FP[1], "σ_F2max",
                                   _where(eng.sigma_F2.at, b_w), share_F, S.BENDING))
    res.checks.extend(_units_checks(eng, FP, load))
    res.checks.append(_psi_check(eng))
    res.checks.append(check(
        "EDGE_LOADING", eng.min_active >= 2, "warning",
        f"in some phase only {eng.min_active} point carries the whole load (the deviations "
        f"lift the others off): improve the accuracy grades or widen the face",
        f"at least {eng.min_active} loaded points in every phase and error case",
        eng.min_active, 2, S.SHARING))
    res.checks.extend(module_checks(m, module_series(),
                                    module_range() if rack.name == STANDARD else None))
    res.checks.extend(proportion_checks(pair.z1, g.z_v1, b_w, g.d1, pair.x1, pair.x2,
                                        inp.pinion.hardness, inp.wheel.hardness,
                                        sol.hardness_diff_min_HB))
    if rack.name != STANDARD:
        res.checks.append(check(
            "RACK_CUSTOM", False, "warning",
            "custom rack: Korotkin's factor tables (K_W, K_F, K_H, Y_v) were fitted for the "
            f"{STANDARD} rack; check that they apply", "", None, None, S.KOROTKIN))
    res.checks.append(check(
        "ALLOWABLES_SOURCE", True, "info", "",
        "allowable stresses from the GOST 21354-87 scheme for ≤ 350 HB (σ_Hlim = 2·HB + 70, "
        "σ_Flim = 1.75·HB): GOST 30224-96 for Novikov gears was not available; the verdict on "
        "σ_H, an effective stress of formula (4), is provisional", None, None, S.G21354))
    if al.N[0] is None:
        res.checks.append(check(
            "LIFE_FACTORS", True, "info", "",
            "no load.speed1 and load.life: Z_N = Y_N = 1 (life at the base number of cycles)",
            None, None, S.G21354))
    res.checks.append(check(
        "DEVIATIONS_SHARE", True, "info", "",
        f"deviations ({inp.error_model}) and misalignment cause {share_F:.0%} of σ_Fmax "
        f"({eng.ideal_F.value:.1f} → {eng.sigma_F.value:.1f} MPa) and {share_H:.0%} of σ_Hmax "
        f"({eng.ideal_H.value:.1f} → {eng.sigma_H.value:.1f} MPa); tooth stiffness c_p = "
        f"{sol.stiffness.c_p:.0f} N/µm is an assumption", share_H, None, S.ERROR_MODEL))


def _psi_check(eng: Engagement):
    crit = []
    for name, c in (("σ_F", eng.sigma_F), ("σ_H", eng.sigma_H)):
        if c.at is not None and c.at.psi_clamped:
            crit.append(name)
    return psi_check(eng.clamped, eng.evaluations, eng.psi_min, eng.psi_max, crit)


def _phase_rows(res: Result, eng: Engagement, b_w: float) -> None:
    """Per-phase arrays (one list per phase; ``None`` for a phase without a point in the
    face, which happens only when the contact is interrupted)."""
    sec = res.section("phases", "Phases (per point: envelope over the error cases)")
    env = eng.envelopes

    def per_point(get):
        return [[get(e) for e in r] if r else None for r in env]

    sec.add("phase", [k + 1 for k in range(len(env))], "-", "k", "phase", S.PHASES)
    sec.add("n_points", [len(r) for r in env], "-", "n", "theoretical points in the face",
            S.TABLE1)
    sec.add("i", per_point(lambda e: e.point.i), "-", "i", "point (Table 1)", S.TABLE1)
    sec.add("zub", per_point(lambda e: e.point.zub), "-", "zub", "tooth pair", S.TABLE1)
    sec.add("j", per_point(lambda e: e.point.j), "-", "j", "line of action", S.TABLE1)
    sec.add("b", per_point(lambda e: e.point.b), "-", "b", "position, fraction of b_w",
            S.PHASES)
    sec.add("b_mm", per_point(lambda e: e.point.b * b_w), "mm", "b·b_w",
            "distance from the entry face end", S.PHASES)
    sec.add("F_ideal", per_point(lambda e: e.F_ideal), "N", "F_0", "force, ideal pair",
            S.SHARING)
    sec.add("F_max", per_point(lambda e: e.F_max), "N", "F", "force, worst error case",
            S.SHARING)
    sec.add("sigma_F", per_point(lambda e: e.sigma_F), "MPa", "σ_F",
            "phase bending stress (worst case)", S.BENDING)
    sec.add("sigma_H", per_point(lambda e: e.sigma_H), "MPa", "σ_H",
            "phase contact stress (worst case)", S.CONTACT)
    sec.add("psi", per_point(lambda e: e.psi_at_H), "-", "ψ", "ψ = a/b_w in the case of σ_H",
            S.ELLIPSE)

    view = res.section("phase_map", "Contact points per phase: tooth/line@b·b_w in mm "
                       "(value) and σ_F/σ_H in MPa (name)")
    width = len(str(len(env)))
    for k, r in enumerate(env, start=1):
        where = " ".join(f"{e.point.zub}/{e.point.j}@{e.point.b * b_w:.1f}" for e in r)
        stresses = ", ".join(f"{e.sigma_F:.0f}/{e.sigma_H:.0f}" for e in r)
        view.add(f"k{k:0{width}d}", where or "no point", None, f"k = {k}",
                 f"σ_F/σ_H: {stresses}" if r else "contact interrupted", S.TABLE1)


def _units_checks(eng, FP, load: dict) -> list:
    """``UNITS_LOAD`` when the teeth carry less than 1 % of their bending capacity
    (max σ_Fmax/σ_FP, nearly proportional to the load, [Korotkin2017]), as a torque typed
    in N·m where kN·m was meant does (:mod:`geardesign.core.units_guard`)."""
    from geardesign.core.units_guard import given, light_load

    fraction = max(eng.sigma_F1.value / FP[0], eng.sigma_F2.value / FP[1])
    what = (f"the teeth carry {100 * fraction:.2g} % of their bending capacity (σ_Fmax = "
            f"{max(eng.sigma_F1.value, eng.sigma_F2.value):.3g} MPa against σ_FP = "
            f"{min(FP):.0f} MPa)")
    return light_load("UNITS_LOAD", fraction, what, given(load, {"torque2": "N·m"}, "load"),
                      S.BENDING)


def _engagement_rows(res: Result, inp: Inputs, sol: Solution) -> None:
    """Table 1, the phases and the cyclogram criteria."""
    g, cov, points = sol.g, sol.cov, sol.points
    counts = [len(r) for r in sol.rows]
    widths = list(sol.widths)
    e = res.section("engagement", "Engagement (Table 1, phases, cyclogram)")
    e.add("delta_q", inp.pair.rack.delta, "-", "δ", "distance of ε_q to the nearest integer",
          S.CYCLOGRAM)
    e.add("n_min", cov.n_min, "-", "n_min", "least number of points in contact", S.CYCLOGRAM)
    e.add("n_max", cov.n_max, "-", "n_max", "greatest number of points in contact", S.CYCLOGRAM)
    e.add("fraction_n_max", cov.fraction_max, "-", "", "fraction of the cycle with n_max points",
          S.CYCLOGRAM)
    e.add("b_w_min", widths, "mm", "b_w,min(n)",
          f"least face width for n = 1…{MIN_WIDTH_POINTS} points at every instant", S.CYCLOGRAM)
    e.add("b_w_min_px", [w / g.p_x for w in widths], "-", "b_w,min(n)/p_x",
          "the same in axial pitches", S.CYCLOGRAM)
    e.add("phases", inp.phases, "-", "f_z", "phases per axial pitch", S.PHASES)
    e.add("db", phase_step(g.eps_beta, inp.phases), "-", "Δb", "phase step p_x/(b_w·f_z)",
          S.PHASES)
    e.add("points_per_phase_min", min(counts), "-", "n_k,min", "least points in a phase (counted)",
          S.TABLE1)
    e.add("points_per_phase_max", max(counts), "-", "n_k,max",
          "greatest points in a phase (counted)", S.TABLE1)
    e.add("teeth", list(sol.teeth), "-", "zub", "tooth pairs in engagement over one axial pitch",
          S.TABLE1)
    e.add("table1_i", [p.i for p in points], "-", "i", "Table 1: serial number of the point",
          S.TABLE1)
    e.add("table1_zub", [p.zub for p in points], "-", "zub", "Table 1: tooth pair", S.TABLE1)
    e.add("table1_j", [p.j for p in points], "-", "j", "Table 1: line (1 pinion, 2 wheel "
          "addendum)", S.TABLE1)
    e.add("table1_b", [p.b1 for p in points], "-", "b_i", "Table 1: position in phase 1, "
          "fraction of b_w", S.TABLE1)
    e.add("table1_formula", [_table1_formula(p.i, p.zub, p.j) for p in points], None, "",
          "Table 1: b_i formula", S.TABLE1)


def _strength_rows(res: Result, sol: Solution, b_w: float) -> None:
    eng = sol.eng
    s = res.section("strength", "Phase stresses (critical values)")
    s.add("Y_v1", sol.Y_v1, "-", "Y_v1", "3-D tooth form factor, pinion", S.YV)
    s.add("Y_v2", sol.Y_v2, "-", "Y_v2", "3-D tooth form factor, wheel", S.YV)
    s.add("Y_a", Y_A, "-", "Y_a", "patch load distribution factor (exponent unreadable: 1)",
          S.BENDING)
    s.add("sigma_F_max", eng.sigma_F.value, "MPa", "σ_Fmax", "critical bending stress",
          S.BENDING)
    _critical_rows(s, "sigma_F", "σ_Fmax", eng.sigma_F.at, b_w, S.BENDING)
    s.add("sigma_F1_max", eng.sigma_F1.value, "MPa", "σ_F1max",
          "critical bending stress, pinion (j = 1 points)", S.BENDING)
    s.add("sigma_F2_max", eng.sigma_F2.value, "MPa", "σ_F2max",
          "critical bending stress, wheel (j = 2 points)", S.BENDING)
    s.add("sigma_H_max", eng.sigma_H.value, "MPa", "σ_Hmax", "critical contact stress",
          S.CONTACT)
    _critical_rows(s, "sigma_H", "σ_Hmax", eng.sigma_H.at, b_w, S.CONTACT)
    s.add("sigma_F_max_ideal", eng.ideal_F.value, "MPa", "σ_Fmax,0",
          "critical bending stress of the ideal pair (no deviations, θ = 0)", S.BENDING)
    s.add("sigma_H_max_ideal", eng.ideal_H.value, "MPa", "σ_Hmax,0",
          "critical contact stress of the ideal pair", S.CONTACT)
    s.add("share_F_deviations", sol.share_F, "-", "1 − σ_F,0/σ_F", "part of σ_Fmax caused by "
          "the deviations and θ", S.ERROR_MODEL)
    s.add("share_H_deviations", sol.share_H, "-", "1 − σ_H,0/σ_H", "part of σ_Hmax caused by "
          "the deviations and θ", S.ERROR_MODEL)
