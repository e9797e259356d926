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


def _member_rows(sec, members, table) -> None:
    """One row per (key, attribute, unit, symbol, name, source) of ``table`` for each member,
    the key and symbol suffixed 1 (pinion) or 2 (wheel)."""
    for i, (who, m) in enumerate(zip(MEMBERS, members), 1):
        for key, attr, unit, sym, name, src in table:
            sec.add(f"{key}{i}", getattr(m, attr), unit, f"{sym}{i}", f"{name}, {who}", src)


def _pair_rows(sec, obj, table) -> None:
    """One row per (key, unit, symbol, name, source) of ``table``, the value ``obj.key``."""
    for key, unit, sym, name, src in table:
        sec.add(key, getattr(obj, key), unit, sym, name, src)


def geometry_rows(res: Result, sol: Solution) -> None:
    g = sol.geometry
    src = S.GEOM_SPIRAL if g.spiral else S.GEOM_STRAIGHT
    sec = res.section("geometry", "Cones and modules")
    _pair_rows(sec, g, (
        ("u", "-", "u", "gear ratio z2/z1", S.CONE),
        ("m_te", "mm", "m_te", "outer transverse module", src),
        ("m_tm", "mm", "m_tm", "mean transverse module", src),
        ("m_nm", "mm", "m_nm", "mean normal module", src),
        ("R_e", "mm", "R_e", "outer cone distance", S.CONE),
        ("R_m", "mm", "R_m", "mean cone distance", S.CONE)))
    sec.add("b_over_R_e", g.b / g.R_e, "-", "b/R_e", "face width ratio", S.CONE)
    where = "mean normal" if g.spiral else "outer transverse"
    _member_rows(sec, g.members, (
        ("delta", "delta", "rad", "δ", "pitch cone angle", S.CONE),
        ("theta_a", "theta_a", "rad", "θ_a", "addendum angle", src),
        ("theta_f", "theta_f", "rad", "θ_f", "dedendum angle", src),
        ("delta_a", "delta_a", "rad", "δ_a", "face cone angle", src),
        ("delta_f", "delta_f", "rad", "δ_f", "root cone angle", src),
        ("d_e", "d_e", "mm", "d_e", "outer reference diameter", src),
        ("d_m", "d_m", "mm", "d_m", "mean reference diameter", src),
        ("h_ae", "h_ae", "mm", "h_ae", "outer addendum", src),
        ("h_fe", "h_fe", "mm", "h_fe", "outer dedendum", src),
        ("d_ae", "d_ae", "mm", "d_ae", "outer tip diameter", src),
        ("d_fe", "d_fe", "mm", "d_fe", "outer root diameter", src),
        ("d_am", "d_am", "mm", "d_am", "mean tip diameter", src),
        ("d_fm", "d_fm", "mm", "d_fm", "mean root diameter", src),
        ("B", "B", "mm", "B", "apex to the outer tip circle plane", src),
        ("b_ax", "b_ax", "mm", "b_ax", "axial length of the face cone", src),
        ("d_ai", "d_ai", "mm", "d_ai", "inner tip diameter", src),
        ("s", "s_e", "mm", "s", f"{where} circular tooth thickness", src),
        ("s_c", "s_c", "mm", "s̄", f"{where} chordal tooth thickness (virtual gear)",
         src + S.CHORD_VIRTUAL),
        ("h_c", "h_c", "mm", "h̄_a", "chordal height (virtual gear, no cos δ)",
         src + S.CHORD_VIRTUAL),
        ("s_cc", "s_cc", "mm", "s̄_c", f"{where} constant chord", src + S.CHORD_CONSTANT),
        ("h_cc", "h_cc", "mm", "h̄_c", "height to the constant chord", src + S.CHORD_CONSTANT),
        ("s_mn", "s_mn", "mm", "s_mn", "mean normal circular tooth thickness", S.CHORD_ISO),
        ("s_mt", "s_mt", "mm", "s_mt", "mean transverse circular tooth thickness",
         S.CHORD_ISO),
        ("d_mn", "d_mn", "mm", "d_mn", "mean normal diameter", S.CHORD_ISO),
        ("s_mnc", "s_mnc", "mm", "s_mnc", "mean normal chordal tooth thickness", S.CHORD_ISO),
        ("h_amc", "h_amc", "mm", "h_amc", "mean chordal addendum (ISO 23509, with cos δ)",
         S.CHORD_ISO)))

    v = res.section("virtual", "Virtual cylindrical gears (mean section)")
    _pair_rows(v, g, (
        ("alpha_vt", "rad", "α_vt", "transverse pressure angle", S.VIRTUAL),
        ("beta_vb", "rad", "β_vb", "base spiral angle", S.VIRTUAL),
        ("u_v", "-", "u_v", "virtual gear ratio", S.VIRTUAL),
        ("a_v", "mm", "a_v", "virtual centre distance", S.VIRTUAL)))
    _member_rows(v, g.members, (
        ("z_v", "z_v", "-", "z_v", "virtual number of teeth", S.VIRTUAL),
        ("z_vn", "z_vn", "-", "z_vn", "virtual number of teeth (normal)", S.VIRTUAL),
        ("d_v", "d_v", "mm", "d_v", "reference diameter", S.VIRTUAL),
        ("d_va", "d_va", "mm", "d_va", "tip diameter", S.VIRTUAL),
        ("d_vb", "d_vb", "mm", "d_vb", "base diameter", S.VIRTUAL),
        ("x_min", "x_min", "-", "x_min", "least shift without undercut", S.UNDERCUT),
        ("s_am", "s_am", "mm", "s_am", "tip thickness (mean, normal)", S.UNDERCUT))
        + (() if g.spiral else
           (("s_ae", "s_ae", "mm", "s_ae", "tip thickness (outer)", S.UNDERCUT),)))
    _pair_rows(v, g, (
        ("g_va", "mm", "g_vα", "length of action", S.CONTACT_RATIO),
        ("eps_va", "-", "ε_vα", "transverse contact ratio", S.CONTACT_RATIO),
        ("eps_vb", "-", "ε_vβ", "face contact ratio", S.CONTACT_RATIO),
        ("eps_vg", "-", "ε_vγ", "total contact ratio", S.CONTACT_RATIO)))


def force_rows(res: Result, sol: Solution) -> None:
    f = sol.forces
    sec = res.section("forces", "Forces on the shafts (mean cone)")
    sec.add("F_mt", f.F_mt, "N", "F_mt", "tangential force", S.FORCES)
    sec.add("T2", f.T2 / 1e3, "N·m", "T2", "wheel torque (no losses)", S.FORCES)
    sec.add("v_mt", f.v_mt, "m/s", "v_mt", "pitch line speed, mean cone", S.FORCES)
    sec.add("v_et", f.v_et, "m/s", "v_et", "pitch line speed, outer cone", S.SPEED_OUTER)
    _member_rows(sec, (f.pinion, f.wheel), (
        ("F_a", "F_a", "N", "F_a", "axial force (+: away from the apex)", S.FORCES),
        ("F_r", "F_r", "N", "F_r", "radial force (+: toward its axis)", S.FORCES)))


def design_rows(res: Result, proposal, sol: Solution) -> None:
    """The proposal of the design mode (:mod:`geardesign.bevel.design`)."""
    g = sol.geometry
    sec = res.section("design", "Design mode: proposed pair")
    which = "mean normal m_nm" if g.spiral else "outer transverse m_te"
    for key, value, unit, sym, name in (
            ("z1_proposed", proposal.z1, "-", "z1", "pinion teeth"),
            ("z2_proposed", proposal.z2, "-", "z2", "wheel teeth"),
            ("module_proposed", proposal.module, "mm", "m", f"module ({which}, GOST 9563 "
             f"first series)"),
            ("face_width_proposed", proposal.face_width, "mm", "b", "face width (K_be·R_e)"),
            ("ratio_deviation", proposal.u_dev, "%", "Δu", "deviation of z2/z1 from the ratio"),
            ("modules_rated", proposal.tried, "-", "", "modules rated")):
        sec.add(key, value, unit, sym, name, S.DESIGN)


def iso_rows(res: Result, sol: Solution) -> None:
    r = sol.iso
    sec = res.section("iso10300", "ISO 10300 method B1")
    _pair_rows(sec, r, (
        ("K_Hbeta_be", "-", "K_Hβ-be", "mounting factor", S.ISO_K),
        ("K_Hbeta", "-", "K_Hβ", "face load factor, contact", S.ISO_K),
        ("K_Fbeta", "-", "K_Fβ", "face load factor, bending", S.ISO_K),
        ("F_n", "N", "F_n", "normal force at the mean point", S.ISO_H),
        ("l_bm", "mm", "l_bm", "length of the middle contact line", S.VIRTUAL),
        ("Z_E", "√MPa", "Z_E", "elasticity factor", S.ISO_H),
        ("Z_MB", "-", "Z_M-B", "mid-zone factor", S.ISO_H),
        ("Z_LS", "-", "Z_LS", "load sharing factor", S.ISO_H),
        ("Z_K", "-", "Z_K", "bevel gear factor (permissible stress)", S.ISO_H),
        ("sigma_H0", "MPa", "σ_H0", "nominal contact stress", S.ISO_H),
        ("sigma_H", "MPa", "σ_H", "contact stress", S.ISO_H),
        ("Y_eps", "-", "Y_ε", "contact ratio factor, bending", S.ISO_F),
        ("Y_BS", "-", "Y_BS", "bevel spiral angle factor", S.ISO_F),
        ("Y_LS", "-", "Y_LS", "load sharing factor, bending", S.ISO_F)))
    _member_rows(sec, (r.pinion, r.wheel), (
        ("Y_Fa", "Y_Fa", "-", "Y_Fa", "tooth form factor (load at the tip)", S.TOOTH_FORM),
        ("Y_Sa", "Y_Sa", "-", "Y_Sa", "stress correction factor (load at the tip)",
         S.TOOTH_FORM),
        ("sigma_F0", "sigma_F0", "MPa", "σ_F0", "nominal root stress", S.ISO_F),
        ("sigma_F", "sigma_F", "MPa", "σ_F", "root stress", S.ISO_F),
        ("S_H", "S_H", "-", "S_H", "pitting safety", S.ISO_H),
        ("S_F", "S_F", "-", "S_F", "bending safety", S.ISO_F)))


def factor_rows(res: Result, sol: Solution) -> None:
    """K_v and K_Hα as used, each marked (given), (method B) or (assumed), and the
    intermediate values of method B when it was used (:mod:`geardesign.bevel.factors`)."""
    lf = sol.factors
    sec = res.section("load_factors", "Load factors K_v, K_Hα (ISO 10300-1)")
    sec.add("K_v", lf.K_v, "-", "K_v", f"dynamic factor ({lf.K_v_src})", S.LOAD_FACTORS)
    sec.add("K_Halpha", lf.K_Halpha, "-", "K_Hα", f"transverse load factor K_Hα = K_Fα "
            f"({lf.K_Halpha_src})", S.LOAD_FACTORS)
    b = lf.method_b
    if b is None:
        return
    for key, value, unit, sym, name in (
            ("f_pt", b.f_pt, "µm", "f_pt", "single pitch deviation (the larger of the pair)"),
            ("y_alpha", b.y_alpha, "µm", "y_α", "running-in allowance"),
            ("f_p_eff", b.f_p_eff, "µm", "f_p,eff", "effective pitch deviation"),
            ("line_load", b.line_load, "N/mm", "F_vmt K_A/b_v", "line load"),
            ("C_F", b.C_F, "-", "C_F", "stiffness correction (light line load)"),
            ("c_prime", b.c_prime, "N/(mm·µm)", "c'", "single stiffness"),
            ("c_gamma", b.c_gamma, "N/(mm·µm)", "c_γ", "mesh stiffness"),
            ("m_red", b.m_red, "kg/mm", "m_red", "reduced mass per face width"),
            ("n_E1", b.n_E1, "min^-1", "n_E1", "resonance speed of the pinion"),
            ("N", b.N, "-", "N", f"resonance ratio n1/n_E1 ({b.range or 'K_v given'})"),
            ("K_Halpha_max", b.K_Halpha_max, "-", "K_Hα,max",
             "upper limit of K_Hα, ε_vγ/(ε_vα Z_LS²)")):
        sec.add(key, value, unit, sym, name, S.LOAD_FACTORS)


def peak_rows(res: Result, sol: Solution) -> None:
    """The static strength at the peak torque (:mod:`geardesign.bevel.peak`)."""
    p = sol.iso_peak
    if p is not None:
        sec = res.section("iso10300_static", "ISO 10300 static strength at the peak torque")
        sec.add("T_peak", p.T_peak, "N·m", "T_max", "peak pinion torque (an actual torque: "
                "K_A = 1)", S.ISO_STATIC)
        sec.add("material_type", p.material, "-", "", "material type (ISO 6336-5)",
                S.ISO_STATIC)
        _pair_rows(sec, p, (
            ("Z_NT", "-", "Z_NT,st", "life factor at the static point, contact", S.ISO_STATIC),
            ("Y_NT", "-", "Y_NT,st", "life factor at the static point, bending", S.ISO_STATIC),
            ("sigma_H", "MPa", "σ_H,st", "contact stress at the peak torque", S.ISO_STATIC)))
        _member_rows(sec, (p.pinion, p.wheel), (
            ("sigma_HG", "sigma_HG", "MPa", "σ_HG,st", "static contact limit σ_Hlim Z_NT,st Z_K",
             S.ISO_STATIC),
            ("S_H", "S_H", "-", "S_H,st", "static pitting safety", S.ISO_STATIC),
            ("sigma_F", "sigma_F", "MPa", "σ_F,st", "root stress at the peak torque",
             S.ISO_STATIC),
            ("Y_deltarelT", "Y_deltarelT", "-", "Y_δrelT,st", "static notch sensitivity factor",
             S.ISO_STATIC),
            ("sigma_FG", "sigma_FG", "MPa", "σ_FG,st", "static root limit σ_Flim Y_ST Y_NT,st "
             "Y_δrelT,st", S.ISO_STATIC),
            ("S_F", "S_F", "-", "S_F,st", "static bending safety", S.ISO_STATIC)))
    q = sol.gost_peak
    if q is not None:
        sec = res.section("gost21354_static", "GOST 21354 peak load")
        sec.add("T_peak", q.T_peak, "N·m", "T_max", "peak pinion torque", S.GOST_STATIC)
        _pair_rows(sec, q, (
            ("K_Hmax", "-", "K_Hmax", "load factor at the peak torque, contact (K_A = K_v = 1)",
             S.GOST_STATIC),
            ("K_Fmax", "-", "K_Fmax", "load factor at the peak torque, bending (K_A = K_v = 1)",
             S.GOST_STATIC),
            ("sigma_Hmax", "MPa", "σ_Hmax", "contact stress at the peak torque",
             S.GOST_STATIC)))
        _member_rows(sec, (q.pinion, q.wheel), (
            ("sigma_HPmax", "sigma_HPmax", "MPa", "σ_HPmax", "allowable peak contact stress",
             S.GOST_STATIC),
            ("sigma_Fmax", "sigma_Fmax", "MPa", "σ_Fmax", "root stress at the peak torque",
             S.GOST_STATIC),
            ("sigma_FPmax", "sigma_FPmax", "MPa", "σ_FPmax", "allowable peak root stress "
             "σ_FSt/S_FSt", S.GOST_STATIC)))


def peak_checks(res: Result, sol: Solution) -> None:
    """The static checks at the peak torque: S_st >= S_min (ISO), σ_max <= σ_Pmax (GOST);
    a GOST route without the material's peak limits is said so."""
    rt, T_max = sol.inputs.rating, sol.inputs.load.T_peak
    if T_max is None:
        return
    lever = "widen the face, raise the module, or limit the peak torque (a slip coupling)"
    p = sol.iso_peak
    for name, m in zip(MEMBERS, (p.pinion, p.wheel) if p is not None else ()):
        for code, S_, need, what in (("ISO_STATIC_PITTING", m.S_H, rt.S_Hmin, "pitting"),
                                     ("ISO_STATIC_BENDING", m.S_F, rt.S_Fmin, "bending")):
            res.checks.append(check(
                code, S_ >= need, "error",
                f"ISO 10300: static {what} safety of the {name} at the peak torque "
                f"{p.T_peak:.0f} N·m is {S_:.3f} < {need:g}; {lever}",
                f"ISO 10300: static {what} safety of the {name} at the peak torque "
                f"{S_:.3f} >= {need:g}", S_, need, S.ISO_STATIC))
    q = sol.gost_peak
    for name, m in zip(MEMBERS, (q.pinion, q.wheel) if q is not None else ()):
        for code, s, lim, what in (("GOST_STATIC_CONTACT", q.sigma_Hmax, m.sigma_HPmax,
                                    "σ_Hmax"),
                                   ("GOST_STATIC_BENDING", m.sigma_Fmax, m.sigma_FPmax,
                                    "σ_Fmax")):
            res.checks.append(check(
                code, s <= lim, "error",
                f"GOST 21354: {what} of the {name} at the peak torque {q.T_peak:.0f} N·m is "
                f"{s:.0f} MPa > {lim:.0f} MPa allowed; {lever}",
                f"GOST 21354: {what} of the {name} at the peak torque {s:.0f} MPa <= "
                f"{lim:.0f} MPa", s, lim, S.GOST_STATIC))
    if sol.gost is not None and q is None:
        res.checks.append(check(
            "GOST_STATIC_NOT_RATED", False, "warning",
            "GOST 21354: the peak load is not checked: give the material's peak limits "
            "material.sigma_HPmax1, sigma_HPmax2, sigma_FSt1, sigma_FSt2 (GOST 21354 table: "
            "σ_HPmax = 2.8·σ_T improved, 44·HRC case-hardened)", "", None, None,
            S.GOST_STATIC))


def gost_rows(res: Result, sol: Solution) -> None:
    r = sol.gost
    sec = res.section("gost21354", "GOST 21354 via the virtual spur pair")
    _pair_rows(sec, r, (
        ("theta_H", "-", "θ_H", "bevel factor, contact", S.GOST),
        ("theta_F", "-", "θ_F", "bevel factor, bending", S.GOST),
        ("K_H", "-", "K_H", "load factor, contact", S.GOST),
        ("K_F", "-", "K_F", "load factor, bending", S.GOST),
        ("Z_E", "√MPa", "Z_E", "elasticity factor", S.GOST),
        ("Z_H", "-", "Z_H", "zone factor", S.GOST),
        ("sigma_H", "MPa", "σ_H", "contact stress", S.GOST)))
    _member_rows(sec, (r.pinion, r.wheel), (
        ("z_vn", "z_vn", "-", "z_vn", "virtual spur teeth", S.GOST),
        ("Y_FS", "Y_FS", "-", "Y_FS", "tooth form factor", S.GOST),
        ("sigma_F", "sigma_F", "MPa", "σ_F", "root stress", S.GOST),
        ("S_H", "S_H", "-", "S_H", "pitting safety", S.GOST),
        ("S_F", "S_F", "-", "S_F", "bending safety", S.GOST)))


def checks(res: Result, sol: Solution) -> None:
    g, rt = sol.geometry, sol.inputs.rating
    done = S.VERIFIED[g.spiral]
    res.checks.append(check(
        "METHOD_UNVERIFIED", False, "warning",
        "not yet checked against a published worked example: " + S.UNVERIFIED[g.spiral]
        + (f"; checked: {done}" if done else "")
        + "; compare these figures with an independent calculation before signing",
        "", None, None, S.PUBLISHED))
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
        "undercut or a pointed tooth, see the checks above); change the geometry as those checks advise",
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


def units_checks(sol: Solution, load: dict | None) -> list:
    """``UNITS_LOAD`` when the pair carries less than 1 % of its contact capacity, as a
    torque typed in N·m where kN·m was meant does: the spur rule
    (:func:`geardesign.spur.strength.checks.contact_load_fraction`, (σ_H0/σ_Hlim)²) on the
    nominal σ_H0 of ISO 10300-2 method B1, or the GOST route's σ_H and K_H; ``load``: the
    spec's ``[load]`` table as given (the inputs the warning names,
    :mod:`geardesign.core.units_guard`)."""
    from geardesign.core.units_guard import given, light_load
    from geardesign.spur.strength.checks import contact_load_fraction

    lim = sol.inputs.material.sigma_Hlim
    if sol.iso is not None:
        v = {"sigma_H0": sol.iso.sigma_H0}
    elif sol.gost is not None:
        v = {"sigma_H": sol.gost.sigma_H, "K_H": sol.gost.K_H}
    else:
        return []
    fraction, what = contact_load_fraction({**v, "sigma_Hlim1": lim[0], "sigma_Hlim2": lim[1]})
    return light_load("UNITS_LOAD", fraction, what,
                      given(load, {"torque": "N·m", "peak_torque": "N·m"}, "load"),
                      S.ISO_H if sol.iso is not None else S.GOST)


def report(res: Result, sol: Solution, load: dict | None = None) -> Result:
    """Fill ``res`` with the rows and checks of ``sol``; ``load``: the spec's ``[load]``
    table as given, for the unit-slip warning (:func:`units_checks`)."""
    geometry_rows(res, sol)
    force_rows(res, sol)
    if sol.iso is not None:
        iso_rows(res, sol)
    if sol.gost is not None:
        gost_rows(res, sol)
    if sol.factors is not None:
        factor_rows(res, sol)
    peak_rows(res, sol)
    checks(res, sol)
    peak_checks(res, sol)
    res.checks.extend(units_checks(sol, load))
    return res
