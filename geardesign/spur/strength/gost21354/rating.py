"""Rating of an external pair to GOST 21354-87: every factor, stress, allowable and
safety factor, computed from the pure functions of :mod:`.formulas` or taken from the
spec where the designer overrides it.

:func:`rate` returns a :class:`GostRating` record (forces, life, load factors, contact,
bending, peak load: frozen section records, per-gear fields as (pinion, wheel) pairs); the
report rows come from the fields' metadata (:func:`geardesign.spur.strength.common.rows`).
It is written with :mod:`geardesign.core.xp`: the calculator rates one pair with numbers,
the sweep kernel (:mod:`geardesign.spur.kernel`) many candidates with numpy arrays through
the same function.

An internal pair (:class:`geardesign.gears.internal.InternalPairGeometry`, whose attribute
``internal`` is true) is rated by the same function: σ_H then uses (u − 1), the internal
gear's tooth form factor is :func:`.formulas.y_fs_internal`, and the reduced radius of
curvature of the informative contact rows is ρ1ρ2/(ρ2 − ρ1).
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core import xp
from geardesign.core.records import dataclass
from geardesign.materials.gear_steel import GearMaterial
from geardesign.gears.geometry import PairGeometry
from geardesign.spur.loads import cycles, equivalent_cycles, mesh_forces
from geardesign.spur.strength.common import Duty, Given, Life  # noqa: F401
from geardesign.spur.strength.gost21354 import formulas as G
from geardesign.spur.strength.gost21354 import tables as T
from geardesign.spur.strength.gost21354.record import (  # noqa: F401
    POPOV, SRC, Bending, Contact, Factors, Forces, GostRating, LifeCycles, Static)

@dataclass(frozen=True)
class Setting:
    grade: int = 8
    tip_relief: bool = False
    scheme: int = 5
    Ra: tuple[float, float] = (1.25, 1.25)
    overrides: dict = field(default_factory=dict)
    contact_model: str = "hertz"
    crowning: float | None = None


# ----------------------------------------------------------------------------- rating


def _when(cond, value):
    """``value`` where ``cond`` holds: for a number ``value`` or ``None`` (no row); for an
    array of candidates the array (its other elements carry no meaning)."""
    if xp.scalar(cond):
        return value() if cond else None
    return value()


def _any(cond) -> bool:
    return bool(cond) if xp.scalar(cond) else bool(cond.any())


def forces(g: PairGeometry, duty: Duty) -> Forces:
    """Torques and mesh forces of a pair ([GOST21354] §2; the same statics as
    [ISO6336-1] §5.1), the same for every strength method: F_tH = 2000·T1/d1 [N] and
    v = π·d1·n1/60000 [m/s] besides the forces at d_w1 (:func:`..loads.mesh_forces`)."""
    f = mesh_forces(g, duty.T1)
    return Forces(T1=duty.T1, T2=duty.T1 * g.u, F_t=f.F_t, F_r=f.F_r, F_a=f.F_a, F_n=f.F_n,
                  beta_w=xp.degrees(f.beta_w), M_a1=f.M_a1, M_a2=f.M_a2,
                  F_tH=2000.0 * duty.T1 / g.g1.d, v_H=math.pi * g.g1.d * duty.n1 / 60000.0)


def life_cycles(duty: Duty, mats, u):
    """Load cycles N_K and the equivalent contact and bending cycles N_HE, N_FE of pinion and
    wheel (lists of two; ``u`` a number or an array of candidates): by the GOST regime's
    equivalence factors μ_H, μ_F or by the spectrum's sum ([GOST21354]; :mod:`...loads`)."""
    life = duty.life
    n = (duty.n1, duty.n1 / u)
    N_K = [cycles(n[i], life.c[i], life.L_h) for i in range(2)]
    N_HE, N_FE = [], []
    for i, mat in enumerate(mats):
        if life.blocks:
            N_HE.append(equivalent_cycles(n[i], life.c[i], life.L_h, life.blocks, 3.0))
            N_FE.append(equivalent_cycles(n[i], life.c[i], life.L_h, life.blocks, mat.q_F))
        else:
            N_HE.append(T.MU_H[life.regime] * N_K[i])
            N_FE.append(T.MU_F[mat.q_F][life.regime] * N_K[i])
    return N_K, N_HE, N_FE


def _life(duty: Duty, mats, u) -> LifeCycles:
    life = duty.life
    N_K, N_HE, N_FE = life_cycles(duty, mats, u)
    regime = None if life.blocks else life.regime
    return LifeCycles(
        regime=regime, q_F=tuple(m.q_F for m in mats),
        how="spectrum" if life.blocks else f"regime {life.regime}",
        mu_H=None if life.blocks else T.MU_H[regime],
        mu_F=None if life.blocks else tuple(T.MU_F[m.q_F][regime] for m in mats),
        damage_sum=("single slope: exponent q_H/2 = 3 (contact) and q_F (bending) for every "
                    "block, no second slope beyond the base number") if life.blocks else None,
        N_K=tuple(N_K), N_HE=tuple(N_HE), N_FE=tuple(N_FE))


def _informative_contact(g: PairGeometry, F_n, sigma_H, m1: GearMaterial, m2: GearMaterial,
                         s: Setting) -> dict:
    """The nonlinear (n = 0.7) contact model and a crowned flank (Popov et al. 2017), at
    the pitch point, in the normal section (ρ_n = ρ_t/cos β_b)."""
    from geardesign.spur.strength import contact_models as C

    if not (s.contact_model == "popov_n07" or s.crowning):
        return {}
    p = g.inp
    rho = [0.5 * gear.d_w * xp.sin(g.alpha_tw) / xp.cos(g.beta_b) for gear in (g.g1, g.g2)]
    if getattr(g, "internal", False):
        rho_w = rho[0] * rho[1] / (rho[1] - rho[0])
    else:
        rho_w = rho[0] * rho[1] / (rho[0] + rho[1])
    b_line = p.b_w / xp.cos(g.beta_b)
    mats = (m1.E, m1.nu, m2.E, m2.nu)
    out = {"rho_w": rho_w}
    if s.contact_model == "popov_n07":
        ratio = C.popov_line(F_n, b_line, rho_w, *mats)[1] / C.hertz_line(F_n, b_line, rho_w,
                                                                          *mats)[1]
        out["sigma_H_n07"] = sigma_H * ratio
    if s.crowning:
        alpha = C.crowning_ellipse_ratio(rho_w, p.b_w, s.crowning)
        _, bK, smax = C.popov_point(F_n, rho_w, alpha, *mats)
        out.update(crowning_alpha=alpha, b_K=bK, sigma_max_crowned=smax)
    return out


def rate(g: PairGeometry, mats: tuple[GearMaterial, GearMaterial], duty: Duty,
         s: Setting) -> GostRating:
    """Rate the pair: contact and bending fatigue, peak loads (GOST 21354-87).

    ``g`` a pair geometry of numbers, or of numpy arrays of candidates (the sweep kernel's
    view of :func:`geardesign.gears.geometry.pair_core`); materials, duty and setting are
    shared by all candidates."""
    given = Given(s.overrides)
    p = g.inp
    helical = p.beta > 0.0
    internal = getattr(g, "internal", False)
    u = g.u
    m1, m2 = mats
    gears = (g.g1, g.g2)
    eps_a = g.eps_alpha
    eps_b = xp.where(helical, g.eps_beta, 0.0)

    fo = forces(g, duty)
    F_tH, v = fo.F_tH, fo.v_H
    life = _life(duty, mats, u)

    # ------------------------------------------------------------------ load factors
    K_A = duty.K_A
    soft_pair = min(m1.HB, m2.HB) <= 350.0   # the softer gear runs in
    spur_form = "spur_relieved" if s.tip_relief else "spur"
    hardness = "soft" if soft_pair else "hard"
    delta_H = xp.where(helical, T.DELTA_H[(hardness, "helical")], T.DELTA_H[(hardness, spur_form)])
    delta_F = xp.where(helical, T.DELTA_F["helical"], T.DELTA_F[spur_form])
    grade = s.grade
    g_0, w_max = G.pitch_factors(grade, p.m_n)
    w_Hv = G.specific_dynamic_force(delta_H, g_0, w_max, v, g.a_w, u)
    w_Fv = G.specific_dynamic_force(delta_F, g_0, w_max, v, g.a_w, u)
    K_Hv = given("K_Hv", lambda: G.k_v(w_Hv, p.b_w, F_tH, K_A))
    K_Fv = given("K_Fv", lambda: G.k_v(w_Fv, p.b_w, F_tH, K_A))
    psi_bd = p.b_w / g.g1.d
    K0_Hb = G.k_h_beta(s.scheme, psi_bd, False)
    K_Hb = given("K_Hbeta", lambda: G.k_h_beta(s.scheme, psi_bd, soft_pair))
    h_eff = xp.where(helical, 2.0 * p.m_n, 2.0 * p.m_n / eps_a)
    N_F = G.n_f(p.b_w, h_eff)
    K_Fb = given("K_Fbeta", lambda: K0_Hb ** N_F)
    Z_eps = given("Z_eps", lambda: G.z_eps(eps_a, eps_b))
    Y_eps = given("Y_eps", lambda: G.y_eps(eps_a, eps_b))
    cos3 = xp.cos(p.beta) ** 3
    z_v = (g.g1.z / cos3, g.g2.z / cos3)
    a_alpha = 0.2 if soft_pair else 0.3
    hel = None
    if _any(helical):
        c_gamma = G.mesh_stiffness(z_v[0], z_v[1], p.x1, p.x2) * (0.75 * eps_a + 0.25)
        f_pb = xp.hypot(*(G.base_pitch_deviation(p.m_n, gear.d, grade) for gear in gears))
        hel = dict(c_gamma=c_gamma, f_pb=f_pb,
                   K_Halpha_max=G.k_h_alpha_max(eps_a, g.eps_beta, Z_eps),
                   K_Falpha_max=1.0 / Y_eps)

    def k_alpha(a_al, F_t, K_A_, K_v, K_b, cap):
        """K_α of the helical candidates within its limits, and whether capped."""
        k = G.k_alpha(eps_a, g.eps_beta, hel["c_gamma"], p.b_w, hel["f_pb"], a_al, F_t, K_A_,
                      K_v, K_b)
        k, capped = G.limited(k, cap)
        return xp.where(helical, k, 1.0), capped

    capped = {}
    for key, a_al, K_v, K_b, cap in (("H", a_alpha, K_Hv, K_Hb, "K_Halpha_max"),
                                     ("F", 0.4, K_Fv, K_Fb, "K_Falpha_max")):
        if s.overrides.get(f"K_{key}alpha") is not None or hel is None:
            capped[key] = (given(f"K_{key}alpha", 1.0), None)
        else:
            capped[key] = k_alpha(a_al, F_tH, K_A, K_v, K_b, hel[cap])
    (K_Ha, cap_H), (K_Fa, cap_F) = capped["H"], capped["F"]
    K_H = K_A * K_Hv * K_Hb * K_Ha
    K_F = K_A * K_Fv * K_Fb * K_Fa
    factors = Factors(
        helical=helical, soft_pair=soft_pair, grade=grade, scheme=s.scheme, b_h=p.b_w / h_eff,
        form=(("helical" if helical else spur_form) if xp.scalar(helical) else None),
        K_A=K_A, w_Hv=w_Hv, delta_H=delta_H, delta_F=delta_F,
        g_0=g_0, w_max=w_max, w_Fv=w_Fv,
        K_Hv=K_Hv, K_Fv=K_Fv, psi_bd=psi_bd, K0_Hbeta=K0_Hb, K_Hbeta=K_Hb,
        K_Hw=_when(soft_pair and K0_Hb > 1.0, lambda: (K_Hb - 1.0) / (K0_Hb - 1.0))
        if xp.scalar(K0_Hb) else None,
        N_F=N_F, K_Fbeta=K_Fb, K_Halpha=K_Ha, K_Falpha=K_Fa,
        K_Halpha_capped=_when(helical, lambda: cap_H) if cap_H is not None else None,
        K_Falpha_capped=_when(helical, lambda: cap_F) if cap_F is not None else None,
        K_H=K_H, K_F=K_F,
        **({k: _when(helical, lambda x=x: x) for k, x in hel.items()} if hel else {}))

    # ------------------------------------------------------------------ contact
    Z_E = given("Z_E", lambda: G.z_e(m1.E, m1.nu, m2.E, m2.nu))
    Z_H = given("Z_H", lambda: G.z_h(g.beta_b, g.alpha_t, g.alpha_tw))
    sigma_H = G.sigma_h(Z_E, Z_H, Z_eps, F_tH, K_H, u, p.b_w, g.g1.d, internal)
    N_HE, N_FE = life.N_HE, life.N_FE
    NHG = given.pair("N_HG", lambda i: G.n_hg(mats[i].HB))
    ZNmax = given.pair("Z_Nmax", lambda i: mats[i].Z_N_max)
    ZN = given.pair("Z_N", lambda i: G.z_n(NHG[i], N_HE[i], ZNmax[i]))
    ZR = given.pair("Z_R", lambda i: G.z_r(s.Ra[i]))
    z_v_of = {soft: G.z_v(v, soft) for soft in {m.soft for m in mats}}
    ZV = given.pair("Z_v", lambda i: z_v_of[mats[i].soft])
    ZX = given.pair("Z_X", lambda i: G.z_x(gears[i].d))
    limit_H = [G.contact_limit(mats[i].sigma_Hlim, ZN[i], ZR[i], ZV[i], ZX[i]) for i in range(2)]
    sigma_HP = tuple(limit_H[i] / mats[i].S_H for i in range(2))
    pair_rule = helical & (g.eps_beta >= 1.0)
    contact = Contact(
        internal=internal, pair_rule=pair_rule, Ra=tuple(s.Ra),
        Z_N_max_material=(m1.Z_N_max, m2.Z_N_max),
        Z_E=Z_E, Z_H=Z_H, Z_eps=Z_eps, sigma_H=sigma_H,
        **_informative_contact(g, fo.F_n * K_H, sigma_H, m1, m2, s),
        sigma_Hlim=(m1.sigma_Hlim, m2.sigma_Hlim), S_H_min=(m1.S_H, m2.S_H), N_HG=NHG,
        Z_Nmax=ZNmax, q_H=tuple(xp.where(N_HE[i] <= NHG[i], 6.0, 20.0) for i in range(2)),
        Z_N=ZN, Z_R=ZR, Z_v=ZV, Z_X=ZX, sigma_HP_gear=sigma_HP,
        S_H=tuple(limit_H[i] / sigma_H for i in range(2)),
        sigma_HP=G.sigma_hp_pair(sigma_HP[0], sigma_HP[1], pair_rule))

    # ------------------------------------------------------------------ bending
    Y_beta = given("Y_beta", lambda: xp.where(helical, G.y_beta(g.eps_beta, p.beta), 1.0))
    Y_delta = given("Y_delta", lambda: G.y_delta(p.m_n))
    N_FG = given("N_FG", G.N_FG)
    Y_R = given("Y_R", 1.0)
    YFS = given.pair("Y_FS", lambda i: G.y_fs_internal(gears[i].x) if internal and i == 1
                     else G.y_fs(z_v[i], gears[i].x))
    sF = tuple(G.sigma_f(F_tH, K_F, p.b_w, p.m_n, YFS[i], Y_beta, Y_eps) for i in range(2))
    YN = given.pair("Y_N", lambda i: G.y_n(N_FE[i], mats[i].q_F, N_FG))
    YX = given.pair("Y_X", lambda i: G.y_x(gears[i].d))
    YA = given.pair("Y_A", lambda i: G.y_a(mats[i].gamma_A, duty.reverse(i)))
    limit_F = [G.bending_limit(mats[i].sigma_Flim, YN[i], Y_delta, Y_R, YX[i], YA[i])
               for i in range(2)]
    bending = Bending(
        internal=internal, q_F_=tuple(m.q_F for m in mats),
        Y_beta=Y_beta, Y_eps=Y_eps, Y_delta=Y_delta, N_FG=N_FG, Y_R=Y_R, z_v=z_v, Y_FS=YFS,
        sigma_F=sF, sigma_Flim=(m1.sigma_Flim, m2.sigma_Flim), S_F_min=(m1.S_F, m2.S_F),
        q_F=(float(m1.q_F), float(m2.q_F)), Y_N=YN, Y_X=YX, Y_A=YA,
        sigma_FP=tuple(limit_F[i] / mats[i].S_F for i in range(2)),
        S_F=tuple(limit_F[i] / sF[i] for i in range(2)))

    # ------------------------------------------------------------------ peak load
    static = None
    if duty.T_peak is not None:
        Tm, ratio = duty.T_peak, duty.T_peak / duty.T1
        K_Hb_max = G.peak_factor(K_Hb, duty.T1, Tm)
        K_Fb_max = G.peak_factor(K_Fb, duty.T1, Tm)
        peak = []
        # K_Hα, K_Fα at the peak torque: the same formula at the peak load with K_A = K_v = 1
        # (the peak torque is an actual torque); a given factor is scaled by peak_factor
        for key, K, a_al, K_b, cap in (("K_Halpha", K_Ha, a_alpha, K_Hb_max, "K_Halpha_max"),
                                       ("K_Falpha", K_Fa, 0.4, K_Fb_max, "K_Falpha_max")):
            if s.overrides.get(key) is not None:
                peak.append(xp.where(helical, G.peak_factor(K, 1.0, ratio), 1.0))
            elif hel is None:
                peak.append(1.0)
            else:
                peak.append(k_alpha(a_al, F_tH * ratio, 1.0, 1.0, K_b, hel[cap])[0])
        K_Hmax, K_Fmax = K_Hb_max * peak[0], K_Fb_max * peak[1]
        S_FSt = given("S_FSt", G.S_FST)
        static = Static(
            T_peak=Tm, K_Hmax=K_Hmax, K_Fmax=K_Fmax, S_FSt=S_FSt,
            sigma_Hmax=G.sigma_h_max(sigma_H, duty.T1, Tm, K_H, K_Hmax),
            sigma_HPmax=(m1.sigma_HPmax, m2.sigma_HPmax),
            sigma_Fmax=tuple(G.sigma_f_max(sF[i], duty.T1, Tm, K_F, K_Fmax) for i in range(2)),
            Y_z=(m1.Y_z, m2.Y_z),
            sigma_FPmax=tuple(G.sigma_fp_max(mats[i].sigma_FSt, YX[i], mats[i].Y_z, S_FSt)
                              for i in range(2)))

    from_spec = frozenset(key.format(k=i + 1) for i, m in enumerate(mats)
                          for what, key in SPEC_KEYS if what in m.given)
    return GostRating(forces=fo, life=life, factors=factors, contact=contact, bending=bending,
                      static=static, given=frozenset(given.used), from_spec=from_spec,
                      materials=tuple(mats))


SPEC_KEYS = (("sigma_Hlim", "sigma_Hlim{k}"), ("sigma_Flim", "sigma_Flim{k}"),
             ("S_F", "S_F{k}_min"), ("sigma_HPmax", "sigma_HPmax{k}"))
"""Material values that the spec may give (``GearMaterial.given``) and their report keys:
their rows name the source "spec"."""
