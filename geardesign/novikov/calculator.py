"""``kind = "novikov"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

This module maps spec keys to the pure functions of :mod:`geometry`, :mod:`deviations`,
:mod:`engagement` and the shared GOST 21354-87 allowables, applies the rules that involve several keys, and
turns the results into report rows and checks.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem
from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.materials.novikov import steel
from geardesign.materials.gear_steel import treatment_limits
from geardesign.spur.strength import gost21354 as G21354
from geardesign.novikov import deviations as dev
from geardesign.novikov import sources as S
from geardesign.novikov.checks import (
    ContinuityData,
    continuity_checks,
    module_checks,
    proportion_checks,
    psi_check,
    stress_check,
)
from geardesign.novikov.engagement import Engagement, MeshData, PointStress, run_phases
from geardesign.novikov.factors import Y_A, y_v
from geardesign.novikov.geometry import (
    GeometryError,
    NovikovPair,
    PairGeometry,
    coverage,
    engaged_teeth,
    helix_for_center_distance,
    min_face_width,
    pair_geometry,
    phase_points,
    phase_step,
    table1_points,
)
from geardesign.novikov.rack import (
    STANDARD,
    NovikovRack,
    module_range,
    module_series,
    standard_rack,
)
from geardesign.novikov.stress import ellipse_coefficient, reduced_modulus

SHIFT_SUM_TOL = 1e-9
RACK_KEYS = ("profile_angle", "lk_star", "eps_q", "addendum_coef", "dedendum_coef")
MIN_WIDTH_POINTS = 6
"""Least face widths are reported for 1 … 6 simultaneous points."""
EPS_BETA_MAX = 8.0
"""Scope of the phase analysis: Korotkin's Table 1 lists tooth pairs up to ε_β ≈ 5; beyond
ε_β = 8 the loop would also be slow (the work grows with ε_β²·f_z)."""


def _fmt(x: float) -> str:
    return f"{x:.4f}".rstrip("0").rstrip(".")


# ----------------------------------------------------------------------------- inputs


def rack_from_spec(spec: ValidatedSpec) -> NovikovRack:
    """The basic rack: GOST 15023-76 from ``racks.toml``, or a custom rack whose five
    constants must all be given."""
    r = spec.data["rack"]
    if r["name"] == STANDARD:
        for key in RACK_KEYS:
            if r[key] is not None:
                raise InputError.at(
                    f"rack.{key}", r[key],
                    f'applies only to rack.name = "custom" (the {STANDARD} values are data); '
                    f'remove it or set rack.name = "custom"')
        return standard_rack()
    missing = [k for k in RACK_KEYS if r[k] is None]
    if missing:
        raise InputError([Problem(f"rack.{k}", 'missing; required for rack.name = "custom"')
                          for k in missing])
    return NovikovRack("custom", math.radians(r["profile_angle"]), r["lk_star"], r["eps_q"],
                       r["addendum_coef"], r["dedendum_coef"], verified=False)


def pair_from_spec(spec: ValidatedSpec, rack: NovikovRack) -> tuple[NovikovPair, str]:
    """The pair of a spec; the helix angle is given or follows from the centre distance."""
    g = spec.data["gear"]
    m, z1, z2 = g["module"], g["z1"], g["z2"]
    beta_deg, a_w = g["helix_angle"], g["center_distance"]
    if abs(g["x1"] + g["x2"]) > SHIFT_SUM_TOL:
        raise InputError(Problem(
            "gear.x1 + gear.x2", f"must be 0: a Novikov pair works at the standard centre "
            f"distance m(z1 + z2)/(2cos β); use x2 = {-g['x1']:g}", g["x1"] + g["x2"]))
    if beta_deg is None and a_w is None:
        raise InputError(Problem("gear.helix_angle", "missing; required: give gear.helix_angle "
                                 "or gear.center_distance (β then follows from it)"))
    if beta_deg is not None and a_w is not None:
        raise InputError.at("gear.center_distance", a_w,
                            "give either gear.helix_angle or gear.center_distance, not both")
    if a_w is not None:
        a0 = 0.5 * m * (z1 + z2)
        a45 = a0 / math.cos(math.radians(45.0))
        try:
            beta = helix_for_center_distance(a_w, m, z1, z2)
        except GeometryError:
            beta = None
        if beta is None or beta >= math.radians(45.0):
            raise InputError.at(
                "gear.center_distance", a_w,
                f"gives no helix angle in 0…45°: must be > m(z1 + z2)/2 = {_fmt(a0)} mm and "
                f"< m(z1 + z2)/(2cos 45°) = {_fmt(a45)} mm")
        how = "from the centre distance"
    else:
        beta = math.radians(beta_deg)
        how = "given"
    return NovikovPair(m, z1, z2, beta, g["face_width"], g["x1"], g["x2"], rack), how


def explicit_errors(spec: ValidatedSpec, teeth: list[int]) -> tuple[dict[int, float], float]:
    """Per-tooth gaps and lead of ``error_model = "explicit"``; the other models must not
    give them."""
    acc = spec.data["accuracy"]
    model = acc["error_model"]
    if model != "explicit":
        for key in ("pitch_errors", "lead_error"):
            if acc[key] is not None:
                raise InputError.at(
                    f"accuracy.{key}", acc[key],
                    f'applies only with accuracy.error_model = "explicit"; remove it or set '
                    f'error_model = "explicit"')
        return {}, 0.0
    n = len(teeth)
    pe = acc["pitch_errors"]
    if pe is None:
        raise InputError(Problem(
            "accuracy.pitch_errors", f'missing; required with accuracy.error_model = "explicit": '
            f"{n} values in µm, one per tooth pair in engagement (pairs {teeth[0]}…{teeth[-1]} "
            f"of Korotkin's Table 1)"))
    if len(pe) != n:
        raise InputError.at(
            "accuracy.pitch_errors", pe,
            f"needs {n} values, one per tooth pair in engagement (pairs {teeth[0]}…{teeth[-1]} "
            f"of Korotkin's Table 1), got {len(pe)}")
    if acc["lead_error"] is None:
        acc["lead_error"] = 0.0
        spec.assumed.append("accuracy.lead_error")
    return dict(zip(teeth, pe)), acc["lead_error"]


def cycles(spec: ValidatedSpec, u: float) -> tuple[float | None, float | None]:
    """Numbers of load cycles N_K = 60·n·L_h of pinion and wheel (one contact of each
    flank region per revolution), or None without speed and life."""
    load = spec.data["load"]
    n1, life = load["speed1"], load["life"]
    if life is not None and n1 is None:
        raise InputError.at("load.life", life,
                            "needs load.speed1 (the number of cycles is 60·n1·L_h); give "
                            "speed1 or remove life")
    if life is None:
        return None, None
    N1 = 60.0 * n1 * life
    return N1, N1 / u


# ----------------------------------------------------------------------------- rows


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


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.novikov import CALCULATOR

    rack = rack_from_spec(spec)
    pair, how = pair_from_spec(spec, rack)
    g = pair_geometry(pair)
    if g.eps_beta > EPS_BETA_MAX:
        b_max = EPS_BETA_MAX * g.p_x
        raise InputError.at(
            "gear.face_width", pair.b_w,
            f"gives ε_β = {g.eps_beta:.4f} > {EPS_BETA_MAX:g}, beyond the scope of the phase "
            f"analysis (Korotkin's Table 1 covers ε_β up to about 5); make the face width at "
            f"most {math.floor(b_max * 100) / 100:.2f} mm or reduce the helix angle")
    acc, load, ana, mat = (spec.data["accuracy"], spec.data["load"], spec.data["analysis"],
                           spec.data["material"])
    phases = ana["phases"]
    points = table1_points(g.eps_beta, rack.eps_q)
    rows = phase_points(points, g.eps_beta, phases)
    teeth = engaged_teeth(rows)
    pitch_errors, lead_error = explicit_errors(spec, teeth)
    N1, N2 = cycles(spec, g.u)

    res = CALCULATOR.new_result(spec)
    _geometry_rows(res, g, how)
    b_w, m = pair.b_w, pair.m

    # -- engagement: Table 1, phases, cyclogram criteria
    delta = rack.delta
    cov = coverage(g.eps_beta, delta)
    counts = [len(r) for r in rows]
    widths = [min_face_width(n, g.p_x, delta) for n in range(1, MIN_WIDTH_POINTS + 1)]
    e = res.section("engagement", "Engagement (Table 1, phases, cyclogram)")
    e.add("delta_q", delta, "-", "δ", "distance of ε_q to the nearest integer", S.CYCLOGRAM)
    e.add("n_min", cov.n_min, "-", "n_min", "least number of points in contact", S.CYCLOGRAM)
    e.add("n_max", cov.n_max, "-", "n_max", "greatest number of points in contact", S.CYCLOGRAM)
    e.add("fraction_n_max", cov.fraction_max, "-", "", "fraction of the cycle with n_max points",
          S.CYCLOGRAM)
    e.add("b_w_min", widths, "mm", "b_w,min(n)",
          f"least face width for n = 1…{MIN_WIDTH_POINTS} points at every instant", S.CYCLOGRAM)
    e.add("b_w_min_px", [w / g.p_x for w in widths], "-", "b_w,min(n)/p_x",
          "the same in axial pitches", S.CYCLOGRAM)
    e.add("phases", phases, "-", "f_z", "phases per axial pitch", S.PHASES)
    e.add("db", phase_step(g.eps_beta, phases), "-", "Δb", "phase step p_x/(b_w·f_z)", S.PHASES)
    e.add("points_per_phase_min", min(counts), "-", "n_k,min", "least points in a phase (counted)",
          S.TABLE1)
    e.add("points_per_phase_max", max(counts), "-", "n_k,max",
          "greatest points in a phase (counted)", S.TABLE1)
    e.add("teeth", teeth, "-", "zub", "tooth pairs in engagement over one axial pitch", S.TABLE1)
    e.add("table1_i", [p.i for p in points], "-", "i", "Table 1: serial number of the point",
          S.TABLE1)
    e.add("table1_zub", [p.zub for p in points], "-", "zub", "Table 1: tooth pair", S.TABLE1)
    e.add("table1_j", [p.j for p in points], "-", "j", "Table 1: line (1 pinion, 2 wheel "
          "addendum)", S.TABLE1)
    e.add("table1_b", [p.b1 for p in points], "-", "b_i", "Table 1: position in phase 1, "
          "fraction of b_w", S.TABLE1)
    e.add("table1_formula", [_table1_formula(p.i, p.zub, p.j) for p in points], None, "",
          "Table 1: b_i formula", S.TABLE1)

    # -- forces
    K_A = load["application_factor"]
    T2 = load["torque2"]
    F_t = 2000.0 * T2 / g.d2
    F_sum = F_t * K_A
    f = res.section("forces", "Forces")
    f.add("F_t", F_t, "N", "F_tΣ", "total tangential force 2000·T2/d2", S.KOROTKIN)
    f.add("F_t_design", F_sum, "N", "K_A·F_tΣ", "design tangential force", S.KOROTKIN)
    f.add("F_a", F_sum * math.tan(pair.beta), "N", "F_a", "axial force F_t·tan β", S.FORCES)
    f.add("F_r", F_sum * math.tan(rack.alpha_k) / math.cos(pair.beta), "N", "F_r",
          "radial force F_t·tan α_k/cos β", S.FORCES)
    f.add("F_n", F_sum / (math.cos(rack.alpha_k) * math.cos(pair.beta)), "N", "F_n",
          "normal force F_t/(cos α_k·cos β)", S.FORCES)

    # -- stiffness and deviations
    st = steel()
    k_a = ellipse_coefficient(g.rho_p, g.l_k, rack.alpha_k, reduced_modulus(st.E, st.nu))
    F_ref = F_sum / (2.0 * g.eps_beta)
    a_ref = k_a * math.sqrt(F_ref)
    L_eff = 2.0 * a_ref + 2.0 * (rack.h_a + rack.h_f) * m
    c_p = ana["point_stiffness"] or ana["mesh_stiffness"] * L_eff
    d = res.section("deviations", "Stiffness and deviations (error model)")
    d.add("a_ref", a_ref, "mm", "a_ref", "contact-patch semi-axis at the mean load per point "
          "F_t/(2ε_β)", S.ELLIPSE)
    d.add("L_eff", L_eff, "mm", "L_eff", "effective length 2a_ref + 2h of a point's stiffness",
          S.COMPLIANCE)
    d.add("c_p", c_p, "N/µm", "c_p", "stiffness of one contact point at mid-face" +
          (" (given)" if ana["point_stiffness"] else " c'·L_eff"), S.COMPLIANCE)
    d.add("W_ref", F_ref / c_p, "µm", "W_ref", "deflection at mid-face under the mean load "
          "per point", S.COMPLIANCE)
    model = acc["error_model"]
    theta = math.radians(acc["misalignment"])
    theta_lead = dev.misalignment_lead(theta, b_w)
    relief = acc["end_relief"] * 1000.0
    d.add("error_model", model, None, "", "error model", S.ERROR_MODEL)
    d.add("theta_lead", theta_lead, "µm", "θ·b_w", "lead mismatch from the misalignment",
          S.ERROR_MODEL)
    d.add("relief", relief, "µm", "Δ", "end relief (parabolic crowning)", S.ERROR_MODEL)
    tol = dev.design_deviations(acc["grade_smoothness"], acc["grade_contact"], m, g.d1, g.d2,
                                b_w, rack.alpha_k, acc["risk"])
    if model == "grades":
        d.add("f_pb1", tol.f_pb1, "µm", "f_pb1", "pitch deviation limit ±, pinion (k_p)",
              S.TOLERANCES)
        d.add("f_pb2", tol.f_pb2, "µm", "f_pb2", "pitch deviation limit ±, wheel (k_p)",
              S.TOLERANCES)
        d.add("F_beta", tol.F_beta1, "µm", "F_β", "tooth direction tolerance, each gear (k_k)",
              S.TOLERANCES)
        d.add("f_x", tol.f_x, "µm", "f_x", "axis parallelism tolerance (= F_β, unverified)",
              S.TOLERANCES)
        d.add("f_y", tol.f_y, "µm", "f_y", "axis skew tolerance (= 0.5·F_β, unverified)",
              S.TOLERANCES)
        d.add("sigma_pitch", tol.sigma_pitch, "µm", "σ_p", "standard deviation of the pitch gap",
              S.ERROR_MODEL)
        d.add("sigma_lead", tol.sigma_lead, "µm", "σ_l", "standard deviation of the lead mismatch",
              S.ERROR_MODEL)
        d.add("e_p", tol.pitch_design, "µm", "e_p = γσ_p", "design pitch gap (the study tooth "
              "leads by it)", S.ERROR_MODEL)
        d.add("e_l", tol.lead_design, "µm", "e_l = γσ_l", "design lead mismatch (both signs)",
              S.ERROR_MODEL)
    elif model == "explicit":
        d.add("pitch_errors", [pitch_errors[z] for z in teeth], "µm", "δu",
              "given gaps of the tooth pairs", S.ERROR_MODEL)
        d.add("lead_error", lead_error, "µm", "f_kβ", "given lead mismatch", S.ERROR_MODEL)

    # -- phase loop
    Y_v1, Y_v2 = y_v(g.z_v1, pair.x1), y_v(g.z_v2, pair.x2)
    mesh = MeshData(F_sum, m, b_w, rack.alpha_k, g.l_k, g.rho_p, k_a, c_p, Y_v1, Y_v2, relief)
    eng = run_phases(rows, mesh, model, theta_lead, tol.lead_design, tol.pitch_design,
                     pitch_errors, lead_error)
    _phase_rows(res, eng, b_w)

    # -- strength
    s = res.section("strength", "Phase stresses (critical values)")
    s.add("Y_v1", Y_v1, "-", "Y_v1", "3-D tooth form factor, pinion", S.YV)
    s.add("Y_v2", Y_v2, "-", "Y_v2", "3-D tooth form factor, wheel", S.YV)
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
    share_F = 1.0 - eng.ideal_F.value / eng.sigma_F.value if eng.sigma_F.value > 0 else 0.0
    share_H = 1.0 - eng.ideal_H.value / eng.sigma_H.value if eng.sigma_H.value > 0 else 0.0
    s.add("sigma_F_max_ideal", eng.ideal_F.value, "MPa", "σ_Fmax,0",
          "critical bending stress of the ideal pair (no deviations, θ = 0)", S.BENDING)
    s.add("sigma_H_max_ideal", eng.ideal_H.value, "MPa", "σ_Hmax,0",
          "critical contact stress of the ideal pair", S.CONTACT)
    s.add("share_F_deviations", share_F, "-", "1 − σ_F,0/σ_F", "part of σ_Fmax caused by the "
          "deviations and θ", S.ERROR_MODEL)
    s.add("share_H_deviations", share_H, "-", "1 − σ_H,0/σ_H", "part of σ_Hmax caused by the "
          "deviations and θ", S.ERROR_MODEL)

    # -- allowables (GOST 21354-87 pieces)
    HB1, HB2 = mat["pinion"]["hardness"], mat["wheel"]["hardness"]
    al = res.section("allowables", "Allowable stresses and safety (GOST 21354-87 scheme)")
    base = [treatment_limits("improved", hb) for hb in (HB1, HB2)]
    lim_H = [mat[w]["sigma_Hlim"] or base[i].sigma_Hlim for i, w in enumerate(("pinion", "wheel"))]
    lim_F = [mat[w]["sigma_Flim"] or base[i].sigma_Flim for i, w in enumerate(("pinion", "wheel"))]
    NHG = [G21354.n_hg(HB1), G21354.n_hg(HB2)]
    ZN = [G21354.z_n(NHG[i], N, base[i].Z_N_max) if N is not None else 1.0
          for i, N in enumerate((N1, N2))]
    YN = [G21354.y_n(N, base[i].q_F) if N is not None else 1.0 for i, N in enumerate((N1, N2))]
    YA = G21354.y_a(base[0].gamma_A, 1.0 if load["reversing"] else 0.0)
    S_Hmin, S_Fmin = base[0].S_H, base[0].S_F
    # σ_HP = σ_Hlim·Z_N/S_H and σ_FP = σ_Flim·Y_N·Y_A/S_F (Z_R, Z_v, Z_X, Y_R, Y_X, Y_δ = 1)
    HP = [lim_H[i] * ZN[i] / S_Hmin for i in range(2)]
    FP = [lim_F[i] * YN[i] * YA / S_Fmin for i in range(2)]
    if N1 is not None:
        al.add("N_K1", N1, "-", "N_K1", "load cycles, pinion 60·n1·L_h", S.G21354)
        al.add("N_K2", N2, "-", "N_K2", "load cycles, wheel", S.G21354)
    for i in range(2):
        who, k = ("pinion", "wheel")[i], i + 1
        al.add(f"sigma_Hlim{k}", lim_H[i], "MPa", f"σ_Hlim{k}", f"contact endurance limit, {who}"
               + (" (given)" if mat[who]["sigma_Hlim"] else " 2·HB + 70"), S.G21354)
        al.add(f"N_HG{k}", NHG[i], "-", f"N_HG{k}", f"base cycles for contact, {who}", S.G21354)
        al.add(f"Z_N{k}", ZN[i], "-", f"Z_N{k}", f"life factor for contact, {who}", S.G21354)
        al.add(f"sigma_HP{k}", HP[i], "MPa", f"σ_HP{k}", f"allowable contact stress, {who}",
               S.G21354)
    al.add("S_H_min", S_Hmin, "-", "S_Hmin", "least safety factor for contact",
           S.G21354)
    sigma_HP = min(HP)
    al.add("sigma_HP", sigma_HP, "MPa", "σ_HP", "allowable contact stress of the pair (lower)",
           S.G21354)
    for i in range(2):
        who, k = ("pinion", "wheel")[i], i + 1
        al.add(f"sigma_Flim{k}", lim_F[i], "MPa", f"σ_Flim{k}", f"bending endurance limit, {who}"
               + (" (given)" if mat[who]["sigma_Flim"] else " 1.75·HB"), S.G21354)
        al.add(f"Y_N{k}", YN[i], "-", f"Y_N{k}", f"life factor for bending, {who}", S.G21354)
        al.add(f"sigma_FP{k}", FP[i], "MPa", f"σ_FP{k}", f"allowable bending stress, {who}",
               S.G21354)
    al.add("Y_A", YA, "-", "Y_A", "reversing load factor", S.G21354)
    al.add("S_F_min", S_Fmin, "-", "S_Fmin", "least safety factor for bending", S.G21354)
    S_H = (min(lim_H[i] * ZN[i] for i in range(2)) / eng.sigma_H.value
           if eng.sigma_H.value > 0 else math.inf)
    S_F = [lim_F[i] * YN[i] * YA / v if v > 0 else math.inf
           for i, v in enumerate((eng.sigma_F1.value, eng.sigma_F2.value))]
    al.add("S_H", S_H, "-", "S_H", "safety factor for contact σ_Hlim·Z_N/σ_Hmax", S.G21354)
    al.add("S_F1", S_F[0], "-", "S_F1", "safety factor for bending, pinion", S.G21354)
    al.add("S_F2", S_F[1], "-", "S_F2", "safety factor for bending, wheel", S.G21354)

    # -- checks
    res.checks.extend(continuity_checks(ContinuityData(
        b_w, g.p_x, g.eps_beta, delta, widths[0], widths[1], cov.n_min, cov.n_max,
        math.degrees(pair.beta))))
    res.checks.append(stress_check("SIGMA_H", eng.sigma_H.value, sigma_HP, "σ_Hmax",
                                   _where(eng.sigma_H.at, b_w), share_H, S.CONTACT))
    res.checks.append(stress_check("SIGMA_F_PINION", eng.sigma_F1.value, FP[0], "σ_F1max",
                                   _where(eng.sigma_F1.at, b_w), share_F, S.BENDING))
    res.checks.append(stress_check("SIGMA_F_WHEEL", eng.sigma_F2.value, FP[1], "σ_F2max",
                                   _where(eng.sigma_F2.at, b_w), share_F, S.BENDING))
    res.checks.extend(_units_checks(eng, FP, spec))
    res.checks.append(_psi_check(eng))
    res.checks.append(check(
        "EDGE_LOADING", eng.min_active >= 2, "warning",
        f"in some phase only {eng.min_active} point carries the whole load (the deviations "
        f"lift the others off): improve the accuracy grades or widen the face",
        f"at least {eng.min_active} loaded points in every phase and error case",
        eng.min_active, 2, S.SHARING))
    res.checks.extend(module_checks(m, module_series(),
                                    module_range() if rack.name == STANDARD else None))
    res.checks.extend(proportion_checks(pair.z1, g.z_v1, b_w, g.d1, pair.x1, pair.x2, HB1, HB2,
                                        st.hardness_diff_min_HB))
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
    if N1 is None:
        res.checks.append(check(
            "LIFE_FACTORS", True, "info", "",
            "no load.speed1 and load.life: Z_N = Y_N = 1 (life at the base number of cycles)",
            None, None, S.G21354))
    res.checks.append(check(
        "DEVIATIONS_SHARE", True, "info", "",
        f"deviations ({model}) and misalignment cause {share_F:.0%} of σ_Fmax "
        f"({eng.ideal_F.value:.1f} → {eng.sigma_F.value:.1f} MPa) and {share_H:.0%} of σ_Hmax "
        f"({eng.ideal_H.value:.1f} → {eng.sigma_H.value:.1f} MPa); tooth stiffness c_p = "
        f"{c_p:.0f} N/µm is an assumption", share_H, None, S.ERROR_MODEL))
    return res


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


def _units_checks(eng, FP, spec: ValidatedSpec) -> list:
    """``UNITS_LOAD`` when the teeth carry less than 1 % of their bending capacity
    (max σ_Fmax/σ_FP, nearly proportional to the load, [Korotkin2017]), as a torque typed
    in N·m where kN·m was meant does (:mod:`geardesign.core.units_guard`)."""
    from geardesign.core.units_guard import given, light_load

    fraction = max(eng.sigma_F1.value / FP[0], eng.sigma_F2.value / FP[1])
    what = (f"the teeth carry {100 * fraction:.2g} % of their bending capacity (σ_Fmax = "
            f"{max(eng.sigma_F1.value, eng.sigma_F2.value):.3g} MPa against σ_FP = "
            f"{min(FP):.0f} MPa)")
    return light_load("UNITS_LOAD", fraction, what,
                      given(spec.data["load"], {"torque2": "N·m"}, "load"), S.BENDING)
