"""Vectorised evaluation of many external spur/helical pairs at once: the pair geometry,
the geometric checks and the GOST 21354-87 or ISO 6336:2019 fatigue rating, for numpy
arrays of candidates (one call per chunk).

No formula is written here: the geometry is :func:`geardesign.spur.geometry.pair_core` and
the GOST 21354-87 rating is :func:`geardesign.spur.strength.gost21354.rating.rate` itself,
called on a view of the candidates' arrays (:func:`pair_view`): its formulas are written
with :mod:`geardesign.core.xp`, so one function rates one pair or a chunk.  This module
keeps only what is array-specific: the view, the check flags and the chunk's columns;
``tests/test_sweep_kernel.py`` guards kernel == calculator on 10 000 random pairs
(1e-9 relative).

ISO 6336:2019 (:func:`evaluate` of a :class:`Fixed` with ``method = ISO_NAME``) strings the
functions of :mod:`geardesign.spur.strength.iso6336` (parts 1, 2, 3, 5 and ISO 1328-1) in
the order of :func:`geardesign.spur.strength.iso6336.rating.rate`, with the ``[iso]`` and
``[iso_factors]`` inputs of the spec; pairs that the calculator does not rate by ISO
(:func:`geardesign.spur.calculator.ratable`: ε_α < 1, an active limit beyond the tangency
point, a pointed tooth) fail ``STRENGTH_NOT_RATED``.  No load spectrum, no scuffing (a sweep
refuses those with ISO).

Scope: external pairs, the fatigue rating (contact and bending, life by GOST regime or by a
load spectrum) with the ``[factors]`` overrides of the spec, and the error checks of
:func:`geardesign.spur.checks.geometry_checks` (contact ratio, undercut, pointed tip,
interference, root diameter, radial clearance).  Not here: the peak-torque (static)
checks (the kernel rates without the peak torque), the span: a sweep re-rates the variants
it reports with the scalar calculator (``geardesign sweep --emit-spec``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from types import SimpleNamespace

import numpy as np

from geardesign.spur.geometry import BasicRack, pair_core
from geardesign.spur.strength.common import values
from geardesign.spur.strength.gost21354.rating import rate as gost_rate
from geardesign.spur.strength.verdict import verdict

INPUTS = ("m_n", "z1", "z2", "x1", "x2", "beta", "b_w")
"""The candidate arrays :func:`evaluate` takes (beta in rad)."""


@dataclass(frozen=True)
class Fixed:
    """What all candidates of a chunk share: the rack, the tip rule, the materials, the duty
    and the GOST setting (as the scalar calculator builds them from the spec)."""

    rack: BasicRack
    mats: tuple
    duty: object
    setting: object
    tip_shortening: bool = True
    method: str = "GOST 21354-87"
    iso: object = None          # IsoSetting of an ISO 6336 sweep


def fixed_from_spec(spec) -> Fixed:
    """The :class:`Fixed` data of a validated spur spec (materials, load, setting)."""
    from geardesign.spur.calculator import _strength_inputs, pair_input_from_spec

    from geardesign.spur.strength.iso6336.spec import ISO_NAME, chosen, iso_setting

    p, _ = pair_input_from_spec(spec)
    mats, duty, setting = _strength_inputs(spec, spec.data["gear"])
    tip = spec.data["gear"].get("tip_shortening", True)
    if chosen(spec.data["options"]) == [ISO_NAME]:
        return Fixed(p.rack, mats, duty, setting, tip, ISO_NAME, iso_setting(spec))
    return Fixed(p.rack, mats, duty, setting, tip)


def _given(s, key: str, computed):
    """The spec's ``[factors]`` value of ``key`` where given (as the scalar rating's
    ``_factor``), else the computed one."""
    v = s.overrides.get(key)
    if v is None:
        return computed
    return np.full(np.shape(computed), float(v)) if np.ndim(computed) else float(v)


def evaluate(c: dict, f: Fixed) -> dict:
    """Geometry, checks and GOST 21354-87 fatigue rating of the candidates ``c`` (arrays of
    equal length, keys :data:`INPUTS`).  Returns a dict of arrays: the geometry of
    :func:`pair_core`, the factors and stresses under the keys of the scalar rating
    (``K_Hv``, ``sigma_H``, ``S_H1``, ``sigma_F2``, ...), the check flags ``ok_<CODE>``,
    ``valid`` (a pair exists) and ``passed`` (valid and every error check passed)."""
    arrays = {k: np.asarray(c[k], dtype=float) for k in INPUTS}
    n = len(arrays["m_n"])
    with np.errstate(all="ignore"):
        out = _evaluate(arrays, f) if f.iso is None else _evaluate_iso(arrays, f)
    return {k: (np.broadcast_to(v, (n,)) if np.ndim(v) == 0 else v) for k, v in out.items()}


GOST_COLUMNS = ("F_tH", "v_H", "w_Hv", "w_Fv", "K_Hv", "K_Fv", "psi_bd", "K0_Hbeta", "K_Hbeta",
                "K_Fbeta", "K_Halpha", "K_Falpha", "K_H", "K_F", "Z_eps", "Y_eps", "Z_E", "Z_H",
                "sigma_H", "sigma_HP1", "sigma_HP2", "S_H1", "S_H2", "Z_N1", "Z_N2", "Z_v1",
                "Z_v2", "Z_X1", "Z_X2", "Y_beta", "Y_delta", "Y_FS1", "Y_FS2", "sigma_F1",
                "sigma_F2", "sigma_FP1", "sigma_FP2", "S_F1", "S_F2", "sigma_HP")
"""The rating's values a chunk returns as columns (the sweep copies each column of each
chunk: the rating's other values stay in the record)."""


def pair_view(g: dict, rack=None):
    """The pair geometry of :func:`pair_core`'s arrays as the rating reads it
    (``inp``, ``g1``, ``g2`` and the pair values, as :class:`~geardesign.spur.geometry.PairGeometry`)."""
    inp = SimpleNamespace(m_n=g["m_n"], b_w=g["b_w"], beta=g["beta"], x1=g["x1"], x2=g["x2"],
                          rack=rack)
    gears = [SimpleNamespace(**{k: g[k + i] for k in ("z", "x", "d", "d_b", "d_w", "d_a", "d_f",
                                                       "h", "rho_p", "s_an")})
             for i in "12"]
    return SimpleNamespace(inp=inp, g1=gears[0], g2=gears[1], **{
        k: g[k] for k in ("u", "a_w", "alpha_t", "beta_b", "alpha_tw", "eps_alpha", "eps_beta",
                          "eps_gamma")})


def _evaluate(c: dict, f: Fixed) -> dict:
    m_n, z1, z2, x1, x2, beta, b_w = (c[k] for k in INPUTS)
    g = pair_core(m_n, z1, z2, x1, x2, beta, b_w, f.rack, f.tip_shortening)
    out = dict(g)
    g.update(m_n=m_n, b_w=b_w, beta=beta)
    # the static (peak-torque) checks are the re-check's (module docstring)
    rating = gost_rate(pair_view(g), f.mats, replace(f.duty, T_peak=None), f.setting)
    v = values(rating)
    out.update((k, v[k]) for k in GOST_COLUMNS)
    judged = verdict(rating)
    ok = {"CONTACT_FATIGUE": judged.contact_passes}
    ok["BENDING_FATIGUE_PINION"], ok["BENDING_FATIGUE_WHEEL"] = judged.bending_ok
    out["margin"] = judged.margin
    del rating, v, judged      # the chunk's peak memory: the record's other values go now

    # ------------------------------------------------------------------ checks
    ok = {**_geometry_ok(g, beta > 0.0), **ok}
    valid = np.asarray(g["valid"], dtype=bool) & np.isfinite(out["sigma_H"])
    return _flags(out, ok, valid)


def _geometry_ok(g: dict, helical) -> dict:
    """The error checks of :func:`geardesign.spur.checks.geometry_checks` as flags."""
    ok = {}
    eps_cont = np.where(helical, g["eps_gamma"], g["eps_alpha"])
    ok["CONTACT_RATIO"] = eps_cont >= 1.0
    for k in "12":
        who = "PINION" if k == "1" else "WHEEL"
        ok["UNDERCUT_" + who] = g["x" + k] >= g["x_min" + k] - 1e-9
        ok["POINTED_TIP_" + who] = g["s_an" + k] > 0.0
        ok["INTERFERENCE_" + who] = \
            (g["rho_p" + k] > 0.0) & (g["rho_p" + k] >= g["rho_l" + k] - 1e-9)
        ok["ROOT_DIAMETER_" + who] = g["d_f" + k] > 0.0
    ok["ROOT_CLEARANCE"] = np.minimum(g["c_12"], g["c_21"]) >= -1e-9
    # a pair whose teeth interfere has no contact ratio to rely on (checks.py)
    ok["CONTACT_RATIO"] &= ok["INTERFERENCE_PINION"] & ok["INTERFERENCE_WHEEL"]
    return ok


def _flags(out: dict, ok: dict, valid) -> dict:
    """``ok_<CODE>`` (the check passed on a valid candidate), ``valid`` and ``passed``."""
    passed = valid.copy()
    for code, flag in ok.items():
        out["ok_" + code] = flag & valid
        passed &= flag
    out["valid"] = valid
    out["passed"] = passed
    return out


# ----------------------------------------------------------------------------- ISO 6336


def _evaluate_iso(c: dict, f: Fixed) -> dict:
    """ISO 6336:2019 rating of the candidates: :func:`iso6336.rating.rate` step by step
    (method B; K_Hβ by method C), external pairs, no spectrum, no scuffing."""
    from geardesign.core import xp
    from geardesign.spur.strength.iso6336 import part1 as P1
    from geardesign.spur.strength.iso6336 import part2 as P2
    from geardesign.spur.strength.iso6336 import part3 as P3
    from geardesign.spur.strength.iso6336 import rating as IR
    from geardesign.spur.strength.iso6336 import tables as IT
    from geardesign.spur.tolerances import iso1328

    m_n, z1, z2, x1, x2, beta, b = (c[k] for k in INPUTS)
    g = pair_core(m_n, z1, z2, x1, x2, beta, b, f.rack, f.tip_shortening)
    out = dict(g)
    iso, duty, setting, mats = f.iso, f.duty, f.setting, f.mats
    rack = f.rack
    helical = beta > 0.0
    d1, u = g["d1"], g["u"]
    eps_a, eps_b, eps_g = g["eps_alpha"], g["eps_beta"], g["eps_gamma"]
    a_n = rack.alpha_n
    A = iso.grade if iso.grade is not None else setting.grade
    F_t = 2000.0 * duty.T1 / d1
    v = math.pi * d1 * duty.n1 / 60000.0
    K_A, K_g = duty.K_A, iso.K_gamma

    def given(key, computed):
        return _given(iso, key, computed)

    # ------------------------------------------------------------------ materials, life
    M = [IR._material(i, mats[i], iso.gears[i], IR.Writer({})) for i in range(2)]
    sHlim = [m["sigma_Hlim"] for m in M]
    types = [m["type"] for m in M]
    n = (duty.n1, duty.n1 / u)
    N_L = [60.0 * n[i] * duty.life.c[i] * duty.life.L_h for i in range(2)]
    line_load = K_A * K_g * F_t / b
    out.update(F_t=F_t, v=v, w=line_load, N_L1=N_L[0], N_L2=N_L[1], K_A=K_A, grade=float(A),
               C_M=P1.C_M)
    for i in range(2):
        k = str(i + 1)
        out.update({"sigma_Hlim" + k: sHlim[i], "sigma_Flim" + k: M[i]["sigma_Flim"]})

    # ------------------------------------------------------------------ accuracy
    tol = iso1328.rating_deviations(g["d1"], g["d2"], m_n, b, g["alpha_t"], A,
                                    iso.tolerance_standard)
    f_pb = iso.f_pb if iso.f_pb is not None else tol["f_pb"]
    f_fa = iso.f_falpha if iso.f_falpha is not None else tol["f_falpha"]
    F_beta = iso.F_beta if iso.F_beta is not None else tol["F_beta"]
    f_Hb = tol["f_Hbeta"]

    # ------------------------------------------------------------------ stiffness
    cb = np.cos(g["beta_b"])
    z_n1 = z1 / (cb * cb * np.cos(beta))
    z_n2 = z2 / (cb * cb * np.cos(beta))
    swap = z_n2 < z_n1          # the standard's pinion: the gear with fewer teeth
    c_th = given("c_th", P1.theoretical_single_stiffness(
        np.where(swap, z_n2, z_n1), np.where(swap, z_n1, z_n2),
        np.where(swap, x2, x1), np.where(swap, x1, x2)))
    h_fP = rack.h_a + rack.c
    C_B = P1.basic_rack_factor(h_fP, h_fP, a_n)
    C_R = xp.minimum(*(P1.blank_factor(ig.web_ratio, (ig.rim_thickness or m_n) / m_n)
                       for ig in iso.gears))
    c_p = given("c_prime", P1.single_stiffness(c_th, C_R, C_B, beta, line_load))
    c_ga = given("c_gamma_alpha", P1.mesh_stiffness_alpha(c_p, eps_a))
    c_gb = P1.mesh_stiffness_beta(c_ga)

    # ------------------------------------------------------------------ running-in
    y_a = P1.pair_mean(*(P1.running_in_alpha(f_pb, types[i], sHlim[i], v) for i in range(2)))
    y_f = P1.pair_mean(*(P1.running_in_alpha(f_fa, types[i], sHlim[i], v) for i in range(2)))
    C_a = iso.C_a if iso.C_a is not None else \
        P1.pair_mean(*(P1.tip_relief_running_in(s_) for s_ in sHlim))

    # ------------------------------------------------------------------ dynamic factor
    m1 = P1.gear_mass(g["d_a1"], g["d_f1"], g["d_b1"], iso.gears[0].inner_diameter)
    m2 = P1.gear_mass(g["d_a2"], g["d_f2"], g["d_b2"], iso.gears[1].inner_diameter)
    m_red = P1.reduced_mass(m1, m2, *iso.meshes)
    n_E1 = P1.resonance_speed(z1, c_ga, m_red)
    N = duty.n1 / n_E1
    N_S = P1.lower_resonance_limit(line_load)
    K_v_calc, _ = P1.dynamic_factor(N, N_S, c_p, np.maximum(f_pb - y_a, 0.0),
                                    np.maximum(f_fa - y_f, 0.0), C_a, line_load, eps_g)
    K_v = given("K_v", K_v_calc)

    # ------------------------------------------------------------------ face load factors
    F_m_b = F_t * K_A * K_g * K_v / b
    f_sh = iso.f_sh if iso.f_sh is not None else P1.shaft_deflection(
        F_m_b, b, d1, iso.K_prime, iso.shaft_span, iso.pinion_offset, iso.shaft_diameter)
    f_ma = iso.f_ma if iso.f_ma is not None else f_Hb
    F_bx = P1.initial_misalignment(f_sh, f_ma, iso.modification, F_m_b, f_Hb)
    y_b = P1.pair_mean(*(P1.running_in_beta(F_bx, types[i], sHlim[i], v) for i in range(2)))
    F_by = F_bx - y_b
    K_Hb = given("K_Hbeta", P1.face_load_factor(F_by, c_gb, F_m_b))
    b_h = np.minimum(b / g["h1"], b / g["h2"])
    K_Fb = given("K_Fbeta", P1.face_load_factor_bending(K_Hb, b_h))

    # ------------------------------------------------------------------ transverse load factors
    Z_eps = given("Z_eps", P2.z_eps(eps_a, eps_b, helical))
    F_tH_b = F_t * K_A * K_g * K_v * K_Hb / b
    f_eff = np.maximum(np.maximum(f_pb, f_fa) - y_a, 0.0)
    K_alpha = P1.transverse_load_factor(eps_g, c_ga, f_eff, F_tH_b)
    KHa_max = P1.transverse_limit_contact(eps_g, eps_a, Z_eps)
    KFa_max = P1.transverse_limit_bending(eps_g, eps_a)
    K_Ha = given("K_Halpha", P1.limited(K_alpha, KHa_max)[0])
    K_Fa = given("K_Falpha", P1.limited(K_alpha, KFa_max)[0])
    out.update(f_pb=f_pb, f_falpha=f_fa, F_beta=F_beta, f_Hbeta=f_Hb, c_th=c_th, C_B=C_B,
               C_R=C_R, c_prime=c_p, c_gamma_alpha=c_ga, c_gamma_beta=c_gb, y_alpha=y_a,
               y_f=y_f, C_a=C_a, m_red=m_red, n_E1=n_E1, N=N, N_S=N_S, K_v=K_v, f_sh=f_sh,
               f_ma=f_ma, F_betax=F_bx, y_beta=y_b, F_betay=F_by, K_Hbeta=K_Hb,
               N_F=P1.n_f(b_h), K_Fbeta=K_Fb, K_Halpha_max=KHa_max, K_Falpha_max=KFa_max,
               K_Halpha=K_Ha, K_Falpha=K_Fa, Z_eps=Z_eps)

    # ------------------------------------------------------------------ pitting
    Z_H = given("Z_H", P2.z_h(g["beta_b"], g["alpha_t"], g["alpha_tw"]))
    mt1, mt2 = mats
    Z_E = given("Z_E", P2.z_e(mt1.E, mt1.nu, mt2.E, mt2.nu))
    Z_b = given("Z_beta", P2.z_beta(beta))
    ZB, ZD, M1, M2 = P2.single_pair_factors(g["alpha_tw"], (g["d_a1"], g["d_a2"]),
                                            (g["d_b1"], g["d_b2"]), (z1, z2), eps_a, eps_b,
                                            helical)
    Z_BD = [given("Z_B", ZB), given("Z_D", ZD)]
    sH0 = P2.nominal_contact_stress(Z_H, Z_E, Z_eps, Z_b, F_t, d1, b, u)
    sH = [P2.contact_stress(Z_BD[i], sH0, K_A, K_g, K_v, K_Hb, K_Ha) for i in range(2)]
    s_min = min(sHlim)
    Z_L = given("Z_L", P2.z_l(s_min, iso.nu40))
    Z_v = given("Z_v", P2.z_v(s_min, v))
    Rz = [iso.gears[i].Rz_flank if iso.gears[i].Rz_flank is not None
          else 6.0 * setting.Ra[i] for i in range(2)]
    rho = P2.rho_red(g["d_b1"], g["d_b2"], g["alpha_tw"])
    Z_R = given("Z_R", P2.z_r(s_min, Rz[0], Rz[1], rho))
    out.update(Z_H=Z_H, Z_E=Z_E, Z_beta=Z_b, M1=M1, M2=M2, Z_B=Z_BD[0], Z_D=Z_BD[1],
               sigma_H0=sH0, sigma_H1=sH[0], sigma_H2=sH[1], Z_L=Z_L, Z_v=Z_v, rho_red=rho,
               Z_R=Z_R, S_Hmin=iso.S_Hmin)
    hard = [t in IT.SURFACE_HARDENED for t in types]
    for i in range(2):
        k = str(i + 1)
        soft_vs_hard = hard[1 - i] and not hard[i] and types[i] not in IT.CAST_IRON_GREY
        ZW_ref = P2.z_w(mats[i].HB, Rz[1 - i], Rz[i], rho, v, iso.nu40) if soft_vs_hard else 1.0
        N_st, N_ref = P2.reference_cycles_contact(types[i], iso.limited_pitting)
        ZNT = given("Z_NT" + k, P2.z_nt(types[i], N_L[i], iso.limited_pitting, iso.optimum))
        infl = [P2.interpolated(ref, N_L[i], N_st, N_ref) for ref in (Z_L, Z_v, Z_R)]
        ZW = given("Z_W" + k, P2.interpolated(ZW_ref, N_L[i], N_st, N_ref))
        ZX = given("Z_X" + k, P2.z_x(types[i], m_n))
        G = sHlim[i] * ZNT * infl[0] * infl[1] * infl[2] * ZW * ZX
        out.update({"Z_NT" + k: ZNT, "Z_W" + k: ZW, "Z_X" + k: ZX, "sigma_HG" + k: G,
                    "sigma_HP" + k: G / iso.S_Hmin, "S_H" + k: P2.safety(G, sH[i])})

    # ------------------------------------------------------------------ bending
    Y_beta = given("Y_beta", np.where(helical, P3.y_beta(eps_b, beta), 1.0))
    Y_DT = given("Y_DT", P3.y_dt(eps_a / (cb * cb), A))
    out.update(Y_beta=Y_beta, Y_DT=Y_DT, S_Fmin=iso.S_Fmin)
    for i in range(2):
        k = str(i + 1)
        tf = P3.tooth_form(g["z" + k], g["x" + k], m_n, a_n, beta, g["beta_b"], g["d" + k],
                           g["d_a" + k], eps_a, h_fP * m_n, rack.rho_f * m_n,
                           iso.protuberance * m_n)
        YF = given("Y_F" + k, tf.Y_F)
        YS = given("Y_S" + k, tf.Y_S)
        YB = given("Y_B" + k, P3.y_b(iso.gears[i].rim_thickness, g["h" + k], m_n))
        sF0 = P3.nominal_root_stress(F_t, b, m_n, YF, YS, Y_beta, YB, Y_DT)
        sF = P3.root_stress(sF0, K_A, K_g, K_v, K_Fb, K_Fa)
        N_st, N_ref = P3.reference_cycles_bending(types[i])
        YNT = given("Y_NT" + k, P3.y_nt(types[i], N_L[i], iso.optimum))
        sigma_02 = mats[i].sigma_T
        rp = P3.rho_prime(types[i], 3.4 * mats[i].HB, sigma_02)
        Yd_st = P3.y_delta_rel_static(types[i], YS, sigma_02)
        Yd = given("Y_deltarelT" + k,
                   P2.interpolated(P3.y_delta_rel(tf.q_s, rp), N_L[i], N_st, N_ref, Yd_st))
        YR = given("Y_RrelT" + k, P2.interpolated(P3.y_r_rel(types[i], iso.gears[i].Rz_root),
                                                 N_L[i], N_st, N_ref))
        YX = given("Y_X" + k, P2.interpolated(P3.y_x(types[i], m_n), N_L[i], N_st, N_ref))
        rev = duty.reverse_ratio if duty.reverse_ratios is None else duty.reverse_ratios[i]
        YM = given("Y_M" + k, P3.y_m(rev))
        G = M[i]["sigma_Flim"] * P3.Y_ST * YNT * Yd * YR * YX * YM
        out.update({"s_Fn" + k: tf.s_Fn, "h_Fe" + k: tf.h_Fe, "rho_F" + k: tf.rho_F,
                    "alpha_Fen" + k: np.degrees(tf.alpha_Fen), "q_s" + k: tf.q_s,
                    "Y_F" + k: YF, "Y_S" + k: YS, "Y_B" + k: YB, "sigma_F0" + k: sF0,
                    "sigma_F" + k: sF, "Y_NT" + k: YNT, "Y_deltarelT" + k: Yd,
                    "Y_RrelT" + k: YR, "Y_X" + k: YX, "Y_M" + k: YM, "sigma_FG" + k: G,
                    "sigma_FP" + k: G / iso.S_Fmin, "S_F" + k: G / sF})

    # ------------------------------------------------------------------ checks
    ok = _geometry_ok(g, helical)
    # the calculator rates by ISO only a pair that can mesh as computed (calculator.ratable)
    ratable = ((eps_a >= 1.0) & (g["rho_p1"] > 0.0) & (g["rho_p2"] > 0.0)
               & (g["s_an1"] > 0.0) & (g["s_an2"] > 0.0))
    ok["STRENGTH_NOT_RATED"] = ratable
    judged = verdict(out)
    for i, who in enumerate(("PINION", "WHEEL")):
        ok["ISO_PITTING_" + who] = ratable & judged.contact_ok[i]
        ok["ISO_BENDING_" + who] = ratable & judged.bending_ok[i]
    # the sweep's columns: the larger contact stress and the smaller permissible one
    out["sigma_H"] = np.maximum(sH[0], sH[1])
    out["sigma_HP"] = np.minimum(out["sigma_HP1"], out["sigma_HP2"])
    out["margin"] = judged.margin
    valid = np.asarray(g["valid"], dtype=bool) & _iso_inputs_fit(g, iso)
    return _flags(out, ok, valid)


def _iso_inputs_fit(g: dict, iso) -> np.ndarray:
    """Candidates whose gears take the ``[iso.pinion]``/``[iso.wheel]`` body data (bore
    inside the root circle, rim within the domain of Y_B and the body): the conditions of
    :func:`geardesign.spur.strength.iso6336.spec.gear_checks`, which the calculator refuses
    as input errors."""
    from geardesign.spur.strength.iso6336.part3 import y_b_domain

    ok = np.ones(np.shape(g["d_f1"]), dtype=bool)
    for i, ig in enumerate(iso.gears):
        k = str(i + 1)
        ok &= ig.inner_diameter < g["d_f" + k]
        if ig.rim_thickness is not None:
            ok &= ig.rim_thickness > y_b_domain(ig.rim_thickness, g["h" + k], None)
            ok &= 2.0 * ig.rim_thickness <= g["d_f" + k] - ig.inner_diameter
    return ok
