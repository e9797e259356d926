"""record -> Result: the rows and the checks of a solved bevel pair (nothing computed here
but the comparisons of the checks)."""

from __future__ import annotations

from geardesign.bevel import sources as S
from geardesign.bevel import solve
from geardesign.bevel.solve import Solution
from geardesign.core.result import Result, check

POINTED_TIP = 0.3
"""Least tip thickness over the module, s_a >= 0.3·m ([GOST16532] quality checks, as for
cylindrical gears; [GOST19624] table 1 note)."""

FACE_RECOMMENDED = 1.0 / 3.0
"""Recommended largest face width over the outer cone distance ([ISO23509] §5)."""

EPS_MIN = 1.1
"""Least transverse contact ratio of straight teeth (design practice)."""

MEMBERS = ("pinion", "wheel")


def geometry_rows(res: Result, sol: Solution) -> None:
    g = sol.geometry
    src = S.GEOM_SPIRAL if g.spiral else S.GEOM_STRAIGHT
    sec = res.section("geometry", "Cones and modules")
    sec.add("u", g.u, "-", "u", "gear ratio z2/z1", S.CONE)
    sec.add("m_te", g.m_te, "mm", "m_te", "outer transverse module", src)
    sec.add("m_tm", g.m_tm, "mm", "m_tm", "mean transverse module", src)
    sec.add("m_nm", g.m_nm, "mm", "m_nm", "mean normal module", src)
    sec.add("R_e", g.R_e, "mm", "R_e", "outer cone distance", S.CONE)
    sec.add("R_m", g.R_m, "mm", "R_m", "mean cone distance", S.CONE)
    sec.add("b_over_R_e", g.b / g.R_e, "-", "b/R_e", "face width ratio", S.CONE)
    for name, m in zip(MEMBERS, g.members):
        i = "1" if name == "pinion" else "2"
        sec.add(f"delta{i}", m.delta, "rad", f"δ{i}", f"pitch cone angle, {name}", S.CONE)
        sec.add(f"theta_a{i}", m.theta_a, "rad", f"θ_a{i}", f"addendum angle, {name}", src)
        sec.add(f"theta_f{i}", m.theta_f, "rad", f"θ_f{i}", f"dedendum angle, {name}", src)
        sec.add(f"delta_a{i}", m.delta_a, "rad", f"δ_a{i}", f"face cone angle, {name}", src)
        sec.add(f"delta_f{i}", m.delta_f, "rad", f"δ_f{i}", f"root cone angle, {name}", src)
        sec.add(f"d_e{i}", m.d_e, "mm", f"d_e{i}", f"outer reference diameter, {name}", src)
        sec.add(f"d_m{i}", m.d_m, "mm", f"d_m{i}", f"mean reference diameter, {name}", src)
        sec.add(f"h_ae{i}", m.h_ae, "mm", f"h_ae{i}", f"outer addendum, {name}", src)
        sec.add(f"h_fe{i}", m.h_fe, "mm", f"h_fe{i}", f"outer dedendum, {name}", src)
        sec.add(f"d_ae{i}", m.d_ae, "mm", f"d_ae{i}", f"outer tip diameter, {name}", src)
        sec.add(f"d_fe{i}", m.d_fe, "mm", f"d_fe{i}", f"outer root diameter, {name}", src)
        sec.add(f"d_am{i}", m.d_am, "mm", f"d_am{i}", f"mean tip diameter, {name}", src)
        sec.add(f"d_fm{i}", m.d_fm, "mm", f"d_fm{i}", f"mean root diameter, {name}", src)
        sec.add(f"B{i}", m.B, "mm", f"B{i}", f"apex to the outer tip circle plane, {name}",
                src)
        where = "mean normal" if g.spiral else "outer transverse"
        sec.add(f"s{i}", m.s_e, "mm", f"s{i}", f"{where} circular tooth thickness, {name}",
                src)
        sec.add(f"s_c{i}", m.s_c, "mm", f"s̄{i}", f"{where} chordal tooth thickness, {name}",
                src)
        sec.add(f"h_c{i}", m.h_c, "mm", f"h̄_a{i}", f"chordal height, {name}", src)

    v = res.section("virtual", "Virtual cylindrical gears (mean section)")
    v.add("alpha_vt", g.alpha_vt, "rad", "α_vt", "transverse pressure angle", S.VIRTUAL)
    v.add("beta_vb", g.beta_vb, "rad", "β_vb", "base spiral angle", S.VIRTUAL)
    v.add("u_v", g.u_v, "-", "u_v", "virtual gear ratio", S.VIRTUAL)
    v.add("a_v", g.a_v, "mm", "a_v", "virtual centre distance", S.VIRTUAL)
    for name, m in zip(MEMBERS, g.members):
        i = "1" if name == "pinion" else "2"
        v.add(f"z_v{i}", m.z_v, "-", f"z_v{i}", f"virtual number of teeth, {name}", S.VIRTUAL)
        v.add(f"z_vn{i}", m.z_vn, "-", f"z_vn{i}", f"virtual number of teeth (normal), {name}",
              S.VIRTUAL)
        v.add(f"d_v{i}", m.d_v, "mm", f"d_v{i}", f"reference diameter, {name}", S.VIRTUAL)
        v.add(f"d_va{i}", m.d_va, "mm", f"d_va{i}", f"tip diameter, {name}", S.VIRTUAL)
        v.add(f"d_vb{i}", m.d_vb, "mm", f"d_vb{i}", f"base diameter, {name}", S.VIRTUAL)
        v.add(f"x_min{i}", m.x_min, "-", f"x_min{i}", f"least shift without undercut, {name}",
              S.UNDERCUT)
        v.add(f"s_am{i}", m.s_am, "mm", f"s_am{i}", f"tip thickness (mean, normal), {name}",
              S.UNDERCUT)
        if not g.spiral:
            v.add(f"s_ae{i}", m.s_ae, "mm", f"s_ae{i}", f"tip thickness (outer), {name}",
                  S.UNDERCUT)
    v.add("g_va", g.g_va, "mm", "g_vα", "length of action", S.CONTACT_RATIO)
    v.add("eps_va", g.eps_va, "-", "ε_vα", "transverse contact ratio", S.CONTACT_RATIO)
    v.add("eps_vb", g.eps_vb, "-", "ε_vβ", "face contact ratio", S.CONTACT_RATIO)
    v.add("eps_vg", g.eps_vg, "-", "ε_vγ", "total contact ratio", S.CONTACT_RATIO)


def force_rows(res: Result, sol: Solution) -> None:
    f = sol.forces
    sec = res.section("forces", "Forces on the shafts (mean cone)")
    sec.add("F_mt", f.F_mt, "N", "F_mt", "tangential force", S.FORCES)
    sec.add("T2", f.T2 / 1e3, "N·m", "T2", "wheel torque (no losses)", S.FORCES)
    sec.add("v_mt", f.v_mt, "m/s", "v_mt", "pitch line speed, mean cone", S.FORCES)
    for name, m in zip(MEMBERS, (f.pinion, f.wheel)):
        i = "1" if name == "pinion" else "2"
        sec.add(f"F_a{i}", m.F_a, "N", f"F_a{i}", f"axial force, {name} (+: away from the "
                f"apex)", S.FORCES)
        sec.add(f"F_r{i}", m.F_r, "N", f"F_r{i}", f"radial force, {name} (+: toward its "
                f"axis)", S.FORCES)


def iso_rows(res: Result, sol: Solution) -> None:
    r = sol.iso
    sec = res.section("iso10300", "ISO 10300 method B1")
    for key, val, sym, name, src in (
            ("K_Hbeta_be", r.K_Hbeta_be, "K_Hβ-be", "mounting factor", S.ISO_K),
            ("K_Hbeta", r.K_Hbeta, "K_Hβ", "face load factor, contact", S.ISO_K),
            ("K_Fbeta", r.K_Fbeta, "K_Fβ", "face load factor, bending", S.ISO_K),
            ("Z_E", r.Z_E, "Z_E", "elasticity factor", S.ISO_H),
            ("Z_H", r.Z_H, "Z_H", "zone factor", S.ISO_H),
            ("Z_MB", r.Z_MB, "Z_M-B", "mid-zone factor", S.ISO_H),
            ("Z_LS", r.Z_LS, "Z_LS", "load sharing factor", S.ISO_H),
            ("Z_beta", r.Z_beta, "Z_β", "spiral angle factor", S.ISO_H),
            ("Z_K", r.Z_K, "Z_K", "bevel gear factor", S.ISO_H),
            ("Y_LS", r.Y_LS, "Y_LS", "load sharing factor, bending", S.ISO_F)):
        sec.add(key, val, "-" if key != "Z_E" else "√MPa", sym, name, src)
    sec.add("b_eH", r.b_eH, "mm", "b_eH", "effective face width (0.85·b)", S.ISO_H)
    sec.add("sigma_H0", r.sigma_H0, "MPa", "σ_H0", "nominal contact stress", S.ISO_H)
    sec.add("sigma_H", r.sigma_H, "MPa", "σ_H", "contact stress", S.ISO_H)
    for name, m in zip(MEMBERS, (r.pinion, r.wheel)):
        i = "1" if name == "pinion" else "2"
        sec.add(f"Y_F{i}", m.Y_F, "-", f"Y_F{i}", f"tooth form factor, {name}", S.TOOTH_FORM)
        sec.add(f"Y_S{i}", m.Y_S, "-", f"Y_S{i}", f"stress correction factor, {name}",
                S.TOOTH_FORM)
        sec.add(f"sigma_F{i}", m.sigma_F, "MPa", f"σ_F{i}", f"root stress, {name}", S.ISO_F)
        sec.add(f"S_H{i}", m.S_H, "-", f"S_H{i}", f"pitting safety, {name}", S.ISO_H)
        sec.add(f"S_F{i}", m.S_F, "-", f"S_F{i}", f"bending safety, {name}", S.ISO_F)


def gost_rows(res: Result, sol: Solution) -> None:
    r = sol.gost
    sec = res.section("gost21354", "GOST 21354 via the virtual spur pair")
    sec.add("theta_H", r.theta_H, "-", "θ_H", "bevel factor, contact", S.GOST)
    sec.add("theta_F", r.theta_F, "-", "θ_F", "bevel factor, bending", S.GOST)
    sec.add("K_H", r.K_H, "-", "K_H", "load factor, contact", S.GOST)
    sec.add("K_F", r.K_F, "-", "K_F", "load factor, bending", S.GOST)
    sec.add("Z_E", r.Z_E, "√MPa", "Z_E", "elasticity factor", S.GOST)
    sec.add("Z_H", r.Z_H, "-", "Z_H", "zone factor", S.GOST)
    sec.add("sigma_H", r.sigma_H, "MPa", "σ_H", "contact stress", S.GOST)
    for name, m in zip(MEMBERS, (r.pinion, r.wheel)):
        i = "1" if name == "pinion" else "2"
        sec.add(f"z_vn{i}", m.z_vn, "-", f"z_vn{i}", f"virtual spur teeth, {name}", S.GOST)
        sec.add(f"Y_FS{i}", m.Y_FS, "-", f"Y_FS{i}", f"tooth form factor, {name}", S.GOST)
        sec.add(f"sigma_F{i}", m.sigma_F, "MPa", f"σ_F{i}", f"root stress, {name}", S.GOST)
        sec.add(f"S_H{i}", m.S_H, "-", f"S_H{i}", f"pitting safety, {name}", S.GOST)
        sec.add(f"S_F{i}", m.S_F, "-", f"S_F{i}", f"bending safety, {name}", S.GOST)


def checks(res: Result, sol: Solution) -> None:
    g, rt = sol.geometry, sol.inputs.rating
    for name, m in zip(MEMBERS, g.members):
        res.checks.append(check(
            "UNDERCUT", m.x >= m.x_min - 1e-9, "error",
            f"the {name} is undercut: x = {m.x:.3f} < x_min = {m.x_min:.3f} on its virtual "
            f"gear (z_v = {m.z_v:.1f}); raise pair.x1, or use more pinion teeth",
            f"{name}: no undercut (x = {m.x:.3f} >= {m.x_min:.3f})", m.x, m.x_min,
            S.UNDERCUT))
        for where, s_a, mod in (("mean", m.s_am, g.m_nm), ("outer", m.s_ae, g.m_te)):
            if where == "outer" and g.spiral:
                continue
            res.checks.append(check(
                "POINTED_TIP", s_a >= POINTED_TIP * mod, "warning",
                f"the {name}'s tip is {'pointed' if s_a <= 0 else 'thin'} at the {where} "
                f"section: s_a = {s_a:.3f} mm < {POINTED_TIP:g}·m = {POINTED_TIP * mod:.3f} mm; "
                f"reduce pair.x1 or pair.xt1",
                f"{name} tip thickness at the {where} section {s_a:.3f} mm >= "
                f"{POINTED_TIP:g}·m", s_a, POINTED_TIP * mod, S.UNDERCUT))
    ratio = g.b / g.R_e
    res.checks.append(check(
        "FACE_WIDTH", ratio <= FACE_RECOMMENDED + 1e-9, "warning",
        f"face width b = {g.b:g} mm is {ratio:.3f}·R_e, over R_e/3: the inner end carries "
        f"little and is hard to cut; use b <= {g.R_e / 3:.1f} mm",
        f"face width b/R_e = {ratio:.3f} <= 1/3", ratio, FACE_RECOMMENDED, S.CONE))
    res.checks.append(check(
        "CONTACT_RATIO", g.eps_vg >= EPS_MIN, "error",
        f"total contact ratio ε_vγ = {g.eps_vg:.3f} < {EPS_MIN:g}: the mesh is not continuous; "
        f"reduce the module with more teeth, or use spiral teeth",
        f"total contact ratio ε_vγ = {g.eps_vg:.3f} >= {EPS_MIN:g}", g.eps_vg, EPS_MIN,
        S.CONTACT_RATIO))
    rated = solve.ratable(g)
    res.checks.append(check(
        "STRENGTH_NOT_RATED", rated, "error",
        "the strength is not rated: the pair does not mesh as computed (ε_vα < 1, an "
        "undercut or a pointed tooth, see the checks above); fix the geometry first",
        "the pair meshes as computed: strength rated", None, None, S.VIRTUAL))
    for label, r, sH, sF in (("ISO 10300", sol.iso, S.ISO_H, S.ISO_F),
                             ("GOST 21354", sol.gost, S.GOST, S.GOST)):
        if r is None:
            continue
        tag = "ISO" if r is sol.iso else "GOST"
        for name, m in zip(MEMBERS, (r.pinion, r.wheel)):
            res.checks.append(check(
                f"{tag}_PITTING", m.S_H >= rt.S_Hmin, "error",
                f"{label}: pitting safety of the {name} S_H = {m.S_H:.3f} < {rt.S_Hmin:g}; "
                f"widen the face, raise the module or use harder flanks",
                f"{label}: pitting safety of the {name} S_H = {m.S_H:.3f} >= {rt.S_Hmin:g}",
                m.S_H, rt.S_Hmin, sH))
            res.checks.append(check(
                f"{tag}_BENDING", m.S_F >= rt.S_Fmin, "error",
                f"{label}: bending safety of the {name} S_F = {m.S_F:.3f} < {rt.S_Fmin:g}; "
                f"raise the module or use a stronger material",
                f"{label}: bending safety of the {name} S_F = {m.S_F:.3f} >= {rt.S_Fmin:g}",
                m.S_F, rt.S_Fmin, sF))


def report(res: Result, sol: Solution) -> Result:
    """Fill ``res`` with the rows and checks of ``sol``."""
    geometry_rows(res, sol)
    force_rows(res, sol)
    if sol.iso is not None:
        iso_rows(res, sol)
    if sol.gost is not None:
        gost_rows(res, sol)
    checks(res, sol)
    return res
