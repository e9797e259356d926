"""Rating of a gear pair to ISO 6336:2019 method B: every factor, stress, permissible stress
and safety factor, from the part modules or from ``[iso_factors]`` where the designer gives
it.

:func:`rate` has the signature of the GOST rating (``rate(geometry, materials, duty,
setting)``) plus the ISO inputs :class:`~.setting.IsoSetting`; without them the defaults of
:func:`~.setting.default_setting` apply (a calculator that only knows the GOST inputs, e.g.
the planetary meshes, still gets an ISO rating).  It returns the frozen record
:class:`~.record.IsoRating` of declared sections, whose rows (the sections ``iso6336_*``, so
that both methods' results stay apart in one report) come from its fields' metadata through
:func:`geardesign.spur.strength.common.rows`; nothing is written while computing.  The load
factors, pitting and bending are written with :mod:`geardesign.core.xp`: the calculator
rates one pair with numbers, the sweep kernel (:mod:`geardesign.spur.kernel`) a chunk of
external candidates with numpy arrays through the same function (scuffing, the peak torque
and a spectrum: one pair only).  The checks are :mod:`.checks`.
"""

from __future__ import annotations

import math

from geardesign.core import xp
from geardesign.spur.strength.common import Given
from geardesign.spur.strength.iso6336 import part1 as P1
from geardesign.spur.strength.iso6336 import part2 as P2
from geardesign.spur.strength.iso6336 import part3 as P3
from geardesign.spur.strength.iso6336 import part5 as P5
from geardesign.spur.strength.iso6336 import tables as T
from geardesign.spur.strength.iso6336.checks import (  # noqa: F401
    WHO, checks, passes)
from geardesign.spur.strength.iso6336.record import (  # noqa: F401
    S1328, SECTIONS, Bending, Contact, Factors, IsoRating, Materials, Static)
from geardesign.spur.strength.iso6336.scuffing import scuffing, scuffing_checks  # noqa: F401
from geardesign.spur.strength.iso6336.setting import (  # noqa: F401
    IsoGear, IsoSetting, ScuffingSetting, default_setting)
from geardesign.spur.tolerances import iso1328

NAME = "ISO 6336:2019"

Z_BIG = 100000
"""Teeth of the rack that stands in for an internal gear in the form-factor calculation."""


def _materials(mats, iso: IsoSetting, N_L: tuple) -> Materials:
    """ISO material data of both gears ([ISO6336-5]: type, quality, hardness on the line's
    scale, σ_Hlim and σ_Flim of the line unless the spec gives them)."""
    from geardesign.materials.gear_steel import data_used, iso_type

    c: dict = {k: [] for k in ("material", "material_source", "type", "quality", "hardness",
                               "sigma_Hlim", "sigma_Flim", "mat_src", "type_how", "clamped",
                               "scale", "srcH", "srcF")}
    for mat, ig in zip(mats, iso.gears):
        typ = ig.material or P5.type_from_treatment(mat.treatment, mat.label)
        line = P5.limits(typ, ig.quality, P5.hardness_on_scale(T.MATERIAL_LINES[typ]["scale"],
                                                                mat.HB, mat.HV))
        if ig.sigma_Hlim is not None:
            sH, srcH = ig.sigma_Hlim, "spec"
        elif "sigma_Hlim" in mat.given:
            sH, srcH = mat.sigma_Hlim, "spec ([material])"
        else:
            sH, srcH = line.sigma_Hlim, "[ISO6336-5]"
        sF, srcF = ((ig.sigma_Flim, "spec") if ig.sigma_Flim is not None
                    else (line.sigma_Flim, "[ISO6336-5]"))
        how = ("" if ig.material else " (from the grade's library row)"
               if iso_type(getattr(mat, "grade", None), mat.treatment)
               else " (from the heat treatment)")
        for key, x in (("material", mat.label), ("material_source", data_used(mat)),
                       ("type", typ), ("quality", ig.quality), ("hardness", line.hardness),
                       ("sigma_Hlim", sH), ("sigma_Flim", sF),
                       ("mat_src", "library" if getattr(mat, "grade", None) else "spec"),
                       ("type_how", how), ("clamped", line.clamped), ("scale", line.scale),
                       ("srcH", srcH), ("srcF", srcF)):
            c[key].append(x)
    return Materials(N_L=N_L, **{k: tuple(x) for k, x in c.items()})


def rate(g, mats, duty, setting, iso: IsoSetting | None = None) -> IsoRating:
    """Rate the pair to ISO 6336:2019 (method B; K_Hβ by method C): the frozen
    :class:`~geardesign.spur.strength.iso6336.record.IsoRating` of every value."""
    iso = iso or default_setting(setting)
    given = Given(iso.overrides, float)
    p = g.inp
    internal = bool(getattr(g, "internal", False))
    helical = p.beta > 0.0
    gears = (g.g1, g.g2)
    d1, b, m_n, u = g.g1.d, p.b_w, p.m_n, g.u
    a_n = p.rack.alpha_n
    A = iso.grade if iso.grade is not None else setting.grade
    F_t = 2000.0 * duty.T1 / d1
    v = math.pi * d1 * duty.n1 / 60000.0
    K_A, K_g = duty.K_A, iso.K_gamma

    # ------------------------------------------------------------------ materials, life
    n = (duty.n1, duty.n1 / u)
    N_L = tuple(60.0 * n[i] * duty.life.c[i] * duty.life.L_h for i in range(2))
    M = _materials(mats, iso, N_L)
    sHlim, sFlim, types = M.sigma_Hlim, M.sigma_Flim, M.type

    # ------------------------------------------------------------------ forces, accuracy
    line_load = K_A * K_g * F_t / b
    tol = iso1328.rating_deviations(g.g1.d, g.g2.d, m_n, b, g.alpha_t, A, iso.tolerance_standard)
    S_tol = S1328 if iso.tolerance_standard == iso1328.STANDARD else "[ISO1328-1-1995]"
    for key in ("f_pb", "f_falpha", "F_beta", "C_a", "f_sh", "f_ma"):
        if getattr(iso, key) is not None:       # a deviation the designer gives
            given.used.add(key)
    f_pb = iso.f_pb if iso.f_pb is not None else tol["f_pb"]
    f_fa = iso.f_falpha if iso.f_falpha is not None else tol["f_falpha"]
    F_beta = iso.F_beta if iso.F_beta is not None else tol["F_beta"]
    f_Hb = tol["f_Hbeta"]
    ranges = [None, None]
    for i, gear in enumerate(gears):
        if not xp.scalar(gear.d, m_n, b):
            break       # candidates of a sweep: the range is the re-check's warning
        outside = iso1328.outside_validity(gear.d, m_n, b, iso.tolerance_standard)
        if outside:
            ranges[i] = _range_words(iso.tolerance_standard, abs(gear.d), m_n, b, outside)

    # ------------------------------------------------------------------ stiffness
    cb = xp.cos(g.beta_b)
    virtual = cb * cb * xp.cos(p.beta)
    z_n1 = p.z1 / virtual
    z_n2_signed = (-p.z2 if internal else p.z2) / virtual
    z_n2 = None if internal else z_n2_signed
    x2 = -p.x2 if internal else p.x2      # ISO 21771 sign for an internal gear
    # the standard's pinion is the gear with fewer teeth (a sun larger than its planet)
    if z_n2 is None:
        stiff = (z_n1, p.x1, z_n2, x2)
    else:
        swap = z_n2 < z_n1
        stiff = (xp.where(swap, z_n2, z_n1), xp.where(swap, x2, p.x1),
                 xp.where(swap, z_n1, z_n2), xp.where(swap, p.x1, x2))
    c_th = given("c_th", lambda: P1.theoretical_single_stiffness(*stiff[::2], *stiff[1::2]))
    racks = (p.rack, getattr(p, "rack2", p.rack))
    h_fPs = [rk.h_a + rk.c for rk in racks]
    h_fP = h_fPs[0]
    C_B = P1.basic_rack_factor(h_fPs[0], h_fPs[1], a_n)
    C_R = xp.minimum(*(P1.blank_factor(ig.web_ratio, (ig.rim_thickness or m_n) / m_n)
                       for ig in iso.gears))
    c_p = given("c_prime", lambda: P1.single_stiffness(c_th, C_R, C_B, p.beta, line_load))
    c_ga = given("c_gamma_alpha", lambda: P1.mesh_stiffness_alpha(c_p, g.eps_alpha))
    c_gb = P1.mesh_stiffness_beta(c_ga)

    # ------------------------------------------------------------------ running-in
    y_a = P1.pair_mean(*(P1.running_in_alpha(f_pb, types[i], sHlim[i], v) for i in range(2)))
    y_f = P1.pair_mean(*(P1.running_in_alpha(f_fa, types[i], sHlim[i], v) for i in range(2)))
    C_a = iso.C_a if iso.C_a is not None else \
        P1.pair_mean(*(P1.tip_relief_running_in(s) for s in sHlim))

    # ------------------------------------------------------------------ dynamic factor
    m1 = P1.gear_mass(g.g1.d_a, g.g1.d_f, g.g1.d_b, iso.gears[0].inner_diameter)
    m2 = None if internal else P1.gear_mass(g.g2.d_a, g.g2.d_f, g.g2.d_b,
                                            iso.gears[1].inner_diameter)
    n_m = iso.meshes
    m_red = P1.reduced_mass(m1, m2, *n_m)
    n_E1 = P1.resonance_speed(p.z1, c_ga, m_red)
    N = duty.n1 / n_E1
    N_S = P1.lower_resonance_limit(line_load)
    # running-in removes at most the deviation itself (160/σ_Hlim·f_pb exceeds f_pb for
    # σ_Hlim < 160 MPa): the effective deviations are not negative
    K_v_calc, rng = P1.dynamic_factor(N, N_S, c_p, xp.maximum(f_pb - y_a, 0.0),
                                      xp.maximum(f_fa - y_f, 0.0), C_a, line_load, g.eps_gamma)
    K_v = given("K_v", K_v_calc)

    # ------------------------------------------------------------------ face load factors
    F_m_b = F_t * K_A * K_g * K_v / b
    f_sh = iso.f_sh if iso.f_sh is not None else P1.shaft_deflection(
        F_m_b, b, d1, iso.K_prime, iso.shaft_span, iso.pinion_offset, iso.shaft_diameter)
    # f_ma = 1.0·f_Hβ for gears without provision for adjustment ([ISO6336-1] 7.6.2.4; the
    # same rule in DIN 3990-1 §3.4.2.4); the helix modification acts through B2
    f_ma = iso.f_ma if iso.f_ma is not None else f_Hb
    F_bx = P1.initial_misalignment(f_sh, f_ma, iso.modification, F_m_b, f_Hb)
    y_b = P1.pair_mean(*(P1.running_in_beta(F_bx, types[i], sHlim[i], v) for i in range(2)))
    F_by = F_bx - y_b
    K_Hb = given("K_Hbeta", lambda: P1.face_load_factor(F_by, c_gb, F_m_b))
    b_h = xp.minimum(b / g.g1.h, b / g.g2.h)
    K_Fb = given("K_Fbeta", lambda: P1.face_load_factor_bending(K_Hb, b_h))

    # ------------------------------------------------------------------ transverse load factors
    Z_eps = given("Z_eps", lambda: P2.z_eps(g.eps_alpha, g.eps_beta, helical))
    F_tH_b = F_t * K_A * K_g * K_v * K_Hb / b
    f_eff = xp.maximum(xp.maximum(f_pb, f_fa) - y_a, 0.0)
    K_alpha = P1.transverse_load_factor(g.eps_gamma, c_ga, f_eff, F_tH_b)
    KHa_max = P1.transverse_limit_contact(g.eps_gamma, g.eps_alpha, Z_eps)
    KFa_max = P1.transverse_limit_bending(g.eps_gamma, g.eps_alpha)
    K_Ha = given("K_Halpha", lambda: P1.limited(K_alpha, KHa_max)[0])
    K_Fa = given("K_Falpha", lambda: P1.limited(K_alpha, KFa_max)[0])
    factors = Factors(
        tol_src=S_tol, internal=internal, C_a_given=iso.C_a is not None,
        f_sh_given=iso.f_sh is not None, f_ma_given=iso.f_ma is not None,
        modification=iso.modification, b_h=b_h,
        shared=next((f" ({WHO[i]} shared by {n_m[i]} meshes: m1·m2/(n2·m1 + n1·m2))"
                     for i in range(2) if n_m[i] > 1), ""),
        F_t=F_t, v_t=v, K_A=K_A, K_gamma=K_g if K_g != 1.0 else None, w=line_load,
        grade=float(A), tolerance_standard=iso.tolerance_standard, f_pb=f_pb, f_falpha=f_fa,
        F_beta=F_beta, tolerance_range=tuple(ranges), z_n1=z_n1, z_n2=z_n2_signed, c_th=c_th,
        C_B=C_B, C_R=C_R, C_M=P1.C_M, c_prime=c_p, c_gamma_alpha=c_ga, c_gamma_beta=c_gb,
        y_alpha=y_a, y_f=y_f, C_a=C_a, m_red=m_red, n_E1=n_E1, N=N, N_S=N_S, K_v_range=rng,
        K_v=K_v, f_sh=f_sh, f_Hbeta=f_Hb, f_ma=f_ma, F_betax=F_bx, y_beta=y_b, F_betay=F_by,
        K_Hbeta=K_Hb, N_F=P1.n_f(b_h), K_Fbeta=K_Fb, Z_eps=Z_eps, K_Halpha_max=KHa_max,
        K_Falpha_max=KFa_max, K_Halpha=K_Ha, K_Falpha=K_Fa)

    # ------------------------------------------------------------------ pitting
    contact = _contact(given, g, mats, duty, setting, iso, M, factors)

    # ------------------------------------------------------------------ bending
    Y_beta = given("Y_beta", lambda: xp.where(helical, P3.y_beta(g.eps_beta, p.beta), 1.0))
    eps_an = g.eps_alpha / (cb * cb)
    Y_DT = given("Y_DT", lambda: P3.y_dt(eps_an, A))
    B: dict = {k: [] for k in ("form_internal", "tangent", "s_Fn", "h_Fe", "rho_F", "alpha_Fen",
                               "q_s", "Y_F", "Y_S", "Y_B", "sigma_F0", "sigma_F", "Y_NT",
                               "rho_prime", "Y_deltarelT", "Rz_root", "Y_RrelT", "Y_X", "rev",
                               "Y_M", "sigma_FG", "sigma_FP", "S_F", "form_how")}
    form_internal_name = ""
    Y_S_form = []
    for i in range(2):
        gr = gears[i]
        tf, form = None, None
        if internal and i == 1 and getattr(p, "cutter", None) is not None:
            # the internal gear's fillet as its shaper cutter generates it
            c = p.cutter
            rho_a0 = c.rho_a0 if c.rho_a0 is not None else racks[1].rho_f
            tf = P3.internal_tooth_form(p.z2, x2, m_n, a_n, p.beta, g.beta_b, gr.d, gr.d_a,
                                        gr.d_f, g.eps_alpha, c.z0, c.x0, rho_a0 * m_n)
            how = f" (internal gear cut by the shaper z0 = {c.z0}, 60° tangent)"
            if tf is not None:
                form = f"shaper z0 = {c.z0}"
                form_internal_name = "internal gear's Y_F, Y_S: fillet of the shaper cutter"
        if internal and i == 1 and tf is None:
            # no shaper given: the internal gear as the rack it tends to (z → ∞, own addendum)
            d_rack = Z_BIG * g.m_t
            tf = P3.tooth_form(Z_BIG, x2, m_n, a_n, p.beta, g.beta_b, d_rack,
                               d_rack + (gr.d - gr.d_a), g.eps_alpha, h_fPs[1] * m_n,
                               racks[1].rho_f * m_n, iso.protuberance * m_n)
            how = " (internal gear without a shaper: rack approximation, conservative)"
            form = "rack"
            form_internal_name = ("internal gear's Y_F, Y_S: the rack it tends to (no shaper "
                                  "given)")
        elif not (internal and i == 1):
            tf = P3.tooth_form(gr.z, gr.x, m_n, a_n, p.beta, g.beta_b, gr.d, gr.d_a, g.eps_alpha,
                               h_fP * m_n, p.rack.rho_f * m_n, iso.protuberance * m_n)
            how = ""
        k = i + 1
        Y_S_form.append(tf.Y_S)
        YF, YS = given(f"Y_F{k}", tf.Y_F), given(f"Y_S{k}", tf.Y_S)
        YB = given(f"Y_B{k}", lambda: P3.y_b(iso.gears[i].rim_thickness, gr.h, m_n,
                                            internal and i == 1))
        sF0 = P3.nominal_root_stress(F_t, b, m_n, YF, YS, Y_beta, YB, Y_DT)
        sF = P3.root_stress(sF0, K_A, K_g, K_v, K_Fb, K_Fa)
        N_st, N_ref = P3.reference_cycles_bending(types[i])
        YNT = given(f"Y_NT{k}", lambda: P3.y_nt(types[i], N_L[i], iso.optimum))
        sigma_02 = mats[i].sigma_T
        rp = P3.rho_prime(types[i], 3.4 * mats[i].HB, sigma_02)
        Yd_st = P3.y_delta_rel_static(types[i], YS, sigma_02)
        Yd = given(f"Y_deltarelT{k}", lambda: P2.interpolated(P3.y_delta_rel(tf.q_s, rp), N_L[i],
                                                              N_st, N_ref, Yd_st))
        Rz_root = iso.gears[i].Rz_root
        YR = given(f"Y_RrelT{k}", lambda: P2.interpolated(P3.y_r_rel(types[i], Rz_root), N_L[i],
                                                          N_st, N_ref))
        YX = given(f"Y_X{k}", lambda: P2.interpolated(P3.y_x(types[i], m_n), N_L[i], N_st,
                                                      N_ref))
        rev = duty.reverse(i)
        YM = given(f"Y_M{k}", lambda: P3.y_m(rev))
        G = sFlim[i] * P3.Y_ST * YNT * Yd * YR * YX * YM
        tangent = "60°" if internal and i == 1 and how.startswith(" (internal gear cut") \
            else "30°"
        for key, x in (("form_internal", form), ("tangent", tangent), ("s_Fn", tf.s_Fn),
                       ("h_Fe", tf.h_Fe), ("rho_F", tf.rho_F),
                       ("alpha_Fen", xp.degrees(tf.alpha_Fen)), ("q_s", tf.q_s), ("Y_F", YF),
                       ("Y_S", YS), ("Y_B", YB), ("sigma_F0", sF0), ("sigma_F", sF),
                       ("Y_NT", YNT), ("rho_prime", rp), ("Y_deltarelT", Yd),
                       ("Rz_root", Rz_root), ("Y_RrelT", YR), ("Y_X", YX), ("rev", rev),
                       ("Y_M", YM), ("sigma_FG", G), ("sigma_FP", G / iso.S_Fmin),
                       ("S_F", G / sF), ("form_how", how)):
            B[key].append(x)
    bending = Bending(Y_beta=Y_beta, Y_DT=Y_DT, S_Fmin=iso.S_Fmin,
                      S_Fmin_src="spec" if iso.S_Fmin != 1.4 else "spec default",
                      form_internal_name=form_internal_name,
                      **{key: tuple(x) for key, x in B.items()})

    # ------------------------------------------------------------------ scuffing
    scuff = None
    if iso.scuffing is not None:
        scuff = scuffing(given, g, mats, setting, iso, types, F_t, v, K_A,
                         K_g * K_v * K_Hb * K_Ha, c_ga, C_a)

    # ------------------------------------------------------------------ static (peak torque)
    static = None
    if duty.T_peak is not None:
        static = _static(duty, types, sHlim, sFlim, mats, contact, bending, Y_S_form)

    # ------------------------------------------------------------------ load spectrum
    spectrum = None
    if duty.life.blocks:
        from geardesign.spur.strength.iso6336.spectrum import spectrum as miner

        spectrum = miner(g, duty, types, sHlim, sFlim, contact, bending, iso)
    return IsoRating(materials=M, factors=factors, contact=contact, bending=bending,
                     scuffing=scuff, static=static, spectrum=spectrum,
                     given=frozenset(given.used))


def _contact(given: Given, g, mats, duty, setting, iso: IsoSetting, M: Materials,
             f: Factors) -> Contact:
    """Pitting ([ISO6336-2]): σ_H per gear from σ_H0 and the load factors ``f``, the
    pitting stress limits σ_HG and the safety factors S_H = σ_HG/σ_H."""
    p = g.inp
    internal = bool(getattr(g, "internal", False))
    helical = p.beta > 0.0
    types, sHlim, N_L, v = M.type, M.sigma_Hlim, M.N_L, f.v_t
    Z_H = given("Z_H", lambda: P2.z_h(g.beta_b, g.alpha_t, g.alpha_tw))
    m_1, m_2 = mats
    Z_E = given("Z_E", lambda: P2.z_e(m_1.E, m_1.nu, m_2.E, m_2.nu))
    Z_b = given("Z_beta", lambda: P2.z_beta(p.beta))
    ZB, ZD, M1, M2 = P2.single_pair_factors(g.alpha_tw, (g.g1.d_a, g.g2.d_a),
                                            (g.g1.d_b, g.g2.d_b), (p.z1, p.z2), g.eps_alpha,
                                            g.eps_beta, helical, internal)
    Z_BD = (given("Z_B", ZB), given("Z_D", ZD))
    sH0 = P2.nominal_contact_stress(Z_H, Z_E, f.Z_eps, Z_b, f.F_t, g.g1.d, p.b_w, g.u, internal)
    sH = tuple(P2.contact_stress(Z_BD[i], sH0, f.K_A, iso.K_gamma, f.K_v, f.K_Hbeta,
                                 f.K_Halpha) for i in range(2))
    s_min = min(sHlim)
    Z_L = given("Z_L", lambda: P2.z_l(s_min, iso.nu40))
    Z_v = given("Z_v", lambda: P2.z_v(s_min, v))
    Rz = tuple(iso.gears[i].Rz_flank if iso.gears[i].Rz_flank is not None
               else 6.0 * setting.Ra[i] for i in range(2))
    rho = P2.rho_red(g.g1.d_b, g.g2.d_b, g.alpha_tw, internal)
    Z_R = given("Z_R", lambda: P2.z_r(s_min, Rz[0], Rz[1], rho))
    hard = [t in T.SURFACE_HARDENED for t in types]
    G: dict = {k: [] for k in ("N_ref", "soft_vs_hard", "Z_NT", "Z_W", "Z_X", "ZLvR",
                               "sigma_HG", "sigma_HP", "S_H")}
    for i in range(2):
        k = i + 1
        soft_vs_hard = hard[1 - i] and not hard[i] and types[i] not in T.CAST_IRON_GREY
        ZW_ref = P2.z_w(mats[i].HB, Rz[1 - i], Rz[i], rho, v, iso.nu40) if soft_vs_hard else 1.0
        N_st, N_ref = P2.reference_cycles_contact(types[i], iso.limited_pitting)
        ZNT = given(f"Z_NT{k}", lambda: P2.z_nt(types[i], N_L[i], iso.limited_pitting,
                                                 iso.optimum))
        infl = [P2.interpolated(ref, N_L[i], N_st, N_ref) for ref in (Z_L, Z_v, Z_R)]
        ZW = given(f"Z_W{k}", lambda: P2.interpolated(ZW_ref, N_L[i], N_st, N_ref))
        ZX = given(f"Z_X{k}", lambda: P2.z_x(types[i], p.m_n))
        ZLvR = infl[0] * infl[1] * infl[2]
        Glim = sHlim[i] * ZNT * infl[0] * infl[1] * infl[2] * ZW * ZX
        for key, x in (("N_ref", N_ref), ("soft_vs_hard", soft_vs_hard), ("Z_NT", ZNT),
                       ("Z_W", ZW), ("Z_X", ZX),
                       # a row of one pair (not of a sweep) below the reference cycles
                       ("ZLvR", ZLvR if xp.scalar(N_L[i]) and N_L[i] < N_ref else None),
                       ("sigma_HG", Glim), ("sigma_HP", Glim / iso.S_Hmin),
                       ("S_H", P2.safety(Glim, sH[i]))):
            G[key].append(x)
    return Contact(
        internal=internal, nu40=iso.nu40,
        Rz_given=tuple(ig.Rz_flank is not None for ig in iso.gears),
        S_Hmin_src="spec" if iso.S_Hmin != 1.0 else "spec default",
        Z_H=Z_H, Z_E=Z_E, Z_beta=Z_b, M1=M1, M2=None if internal else M2,
        Z_B=Z_BD[0], Z_D=Z_BD[1], sigma_H0=sH0, sigma_H=sH, Z_L=Z_L, Z_v=Z_v, rho_red=rho,
        Rz_flank=Rz, Z_R=Z_R, S_Hmin=iso.S_Hmin, **{key: tuple(x) for key, x in G.items()})


def _static(duty, types, sHlim, sFlim, mats, contact: Contact, bending: Bending,
            Y_S_form: tuple) -> Static:
    """Static strength at the peak torque (an actual torque: K_A = 1, the other load
    factors as at the nominal torque): σ_H ∝ √T, σ_F ∝ T against the limits at the static
    point of the S-N curves ([ISO6336-2] §10, [ISO6336-3] §12); ``Y_S_form`` the stress
    correction factors of the tooth forms (a given Y_S does not enter Y_δrelT,st)."""
    ratio = duty.T_peak / duty.T1
    K_A = duty.K_A
    S: dict = {k: [] for k in ("sigma_Hst", "sigma_HGst", "S_Hst", "ZNT_st", "sigma_Fst",
                               "Y_deltarelTst", "sigma_FGst", "S_Fst", "YNT_st")}
    for i in range(2):
        s = contact.sigma_H[i] * math.sqrt(ratio / K_A)
        sf = bending.sigma_F[i] * ratio / K_A
        ZNT_st, Gs, YNT_st, Yd_st, Gf = P3.static_limits(types[i], sHlim[i], sFlim[i],
                                                         Y_S_form[i], mats[i].sigma_T)
        for key, x in (("sigma_Hst", s), ("sigma_HGst", Gs), ("S_Hst", Gs / s),
                       ("ZNT_st", ZNT_st), ("sigma_Fst", sf), ("Y_deltarelTst", Yd_st),
                       ("sigma_FGst", Gf), ("S_Fst", Gf / sf), ("YNT_st", YNT_st)):
            S[key].append(x)
    return Static(T_peak=duty.T_peak, **{key: tuple(x) for key, x in S.items()})


def _range_words(standard: str, d: float, m_n: float, b: float, outside: list) -> str:
    """The sizes of a gear outside the range of ``standard`` (ISO 1328-1), for the warning."""
    rng = iso1328.validity(standard)
    names = " and ".join(iso1328.SIZE_NAMES[key].split(" d")[0] for key, *_ in outside)
    return (f"d = {d:.6g} mm, m_n = {m_n:.6g} mm, b = {b:.6g} mm: the {names} "
            + ("lie" if len(outside) > 1 else "lies")
            + f" outside the range of {standard} ({rng['d'][0]:g} ≤ d ≤ {rng['d'][1]:g}, "
              f"{rng['m_n'][0]:g} ≤ m_n ≤ {rng['m_n'][1]:g}, {rng['b'][0]:g} ≤ b ≤ "
              f"{rng['b'][1]:g} mm); {iso1328.beyond_range_words(standard)}")
