"""Rating of an external pair to GOST 21354-87: every factor, stress, allowable and
safety factor, computed from the pure functions of :mod:`.gost21354` or taken from the
spec where the designer overrides it.

An internal pair (:class:`geardesign.spur.internal.InternalPairGeometry`, whose attribute
``internal`` is true) is rated by the same function: σ_H then uses (u − 1), the internal
gear's tooth form factor is :func:`.gost21354.y_fs_internal`, and the reduced radius of
curvature of the informative contact rows is ρ1ρ2/(ρ2 − ρ1).

The result is a list of :class:`Value` rows (grouped by section) so that the report and
the JSON carry each quantity with its symbol, unit, source and whether it was given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from geardesign.materials.gear_steel import GearMaterial
from geardesign.spur.geometry import PairGeometry
from geardesign.spur.loads import Block, cycles, equivalent_cycles, mesh_forces
from geardesign.spur.strength import gost21354 as G
from geardesign.spur.strength import tables as T

SRC = "GOST 21354-87"
SRC_TABLE = "GOST 21354-87 (table)"
SRC_ZPCIL = "GOST 21354-87 (ZPCIL)"


@dataclass(frozen=True)
class Life:
    """Required life and loading history."""

    L_h: float
    c: tuple[int, int] = (1, 1)
    regime: str | None = "0"
    blocks: tuple[Block, ...] = ()


@dataclass(frozen=True)
class Duty:
    T1: float               # nominal (largest long-acting) pinion torque, N·m
    n1: float               # pinion speed, min^-1
    K_A: float = 1.0
    T_peak: float | None = None
    reverse_ratio: float = 0.0
    life: Life = field(default_factory=lambda: Life(1.0))
    reverse_ratios: tuple[float, float] | None = None
    """Reversed torque ratio per gear (pinion, wheel) when they differ, e.g. a planet
    loaded on both flanks (1.0) meshing a sun loaded on one (0.0); ``None``: both gears
    take ``reverse_ratio``."""


@dataclass(frozen=True)
class Setting:
    grade: int = 8
    tip_relief: bool = False
    scheme: int = 5
    Ra: tuple[float, float] = (1.25, 1.25)
    overrides: dict = field(default_factory=dict)
    contact_model: str = "hertz"
    crowning: float | None = None


@dataclass(frozen=True)
class Value:
    section: str
    key: str
    value: float | str
    unit: str | None
    symbol: str
    name: str
    source: str


@dataclass
class Rating:
    rows: list[Value] = field(default_factory=list)
    v: dict = field(default_factory=dict)       # key -> value, for checks and tests

    def put(self, section: str, key: str, value, unit, symbol: str, name: str,
            source: str) -> float:
        self.rows.append(Value(section, key, value, unit, symbol, name, source))
        self.v[key] = value
        return value


def _factor(r: Rating, s: Setting, section: str, key: str, computed, symbol: str, name: str,
            source: str, unit: str = "-") -> float:
    """A factor that the designer may override in ``[factors]``."""
    if key in s.overrides and s.overrides[key] is not None:
        return r.put(section, key, s.overrides[key], unit, symbol, name + " (given)", "spec")
    value = computed() if callable(computed) else computed
    return r.put(section, key, value, unit, symbol, name, source)


def _given(s: Setting, key: str, computed) -> float:
    """The value of a factor: the spec's ``[factors]`` entry if given, else computed."""
    given = s.overrides.get(key)
    return given if given is not None else computed()


def _informative_contact(r: Rating, g: PairGeometry, F_n: float, sigma_H: float,
                         m1: GearMaterial, m2: GearMaterial, s: Setting) -> None:
    """Rows of the nonlinear (n = 0.7) contact model and of a crowned flank (Popov et al.
    2017), at the pitch point, in the normal section (ρ_n = ρ_t/cos β_b)."""
    from geardesign.spur.strength import contact_models as C

    p = g.inp
    rho = [0.5 * gear.d_w * math.sin(g.alpha_tw) / math.cos(g.beta_b) for gear in (g.g1, g.g2)]
    if getattr(g, "internal", False):
        rho_w = rho[0] * rho[1] / (rho[1] - rho[0])
    else:
        rho_w = rho[0] * rho[1] / (rho[0] + rho[1])
    b_line = p.b_w / math.cos(g.beta_b)
    mats = (m1.E, m1.nu, m2.E, m2.nu)
    src = "Popov et al. 2017"
    r.put("contact", "rho_w", rho_w, "mm", "ρ_w", "reduced radius of curvature at the pitch point",
          "Hertz")
    if s.contact_model == "popov_n07":
        ratio = C.popov_line(F_n, b_line, rho_w, *mats)[1] / C.hertz_line(F_n, b_line, rho_w, *mats)[1]
        r.put("contact", "sigma_H_n07", sigma_H * ratio, "MPa", "σ_H(n=0.7)",
              "contact stress with the n = 0.7 deformation law (informative)", src + " (9)")
    if s.crowning:
        alpha = C.crowning_ellipse_ratio(rho_w, p.b_w, s.crowning)
        b0, bK, smax = C.popov_point(F_n, rho_w, alpha, *mats)
        r.put("contact", "crowning_alpha", alpha, "-", "α", "contact ellipse axis ratio b0/b_K",
              src)
        r.put("contact", "b_K", bK, "mm", "b_K", "half-length of the contact ellipse "
              "(must stay below b_w/2)", src + " (20)")
        r.put("contact", "sigma_max_crowned", smax, "MPa", "σ_max",
              "contact stress of the crowned flank, n = 0.7 (informative)", src + " (21)")


def put_forces(r: Rating, g: PairGeometry, duty: Duty):
    """The ``forces`` rows of a pair: torques and mesh forces ([GOST21354] §2; the same
    statics as [ISO6336-1] §5.1), the same for every strength method.  Returns the mesh
    forces, F_tH = 2000·T1/d1 [N] and v = π·d1·n1/60000 [m/s]."""
    u = g.u
    f = mesh_forces(g, duty.T1)
    r.put("forces", "T1", duty.T1, "N·m", "T1", "pinion torque (nominal)", "spec")
    r.put("forces", "T2", duty.T1 * u, "N·m", "T2", "wheel torque (no mesh loss)", SRC)
    r.put("forces", "F_t", f.F_t, "N", "F_t", "tangential force at d_w1", "[GOST21354]")
    r.put("forces", "F_r", f.F_r, "N", "F_r", "radial force", "[GOST21354]")
    r.put("forces", "F_a", f.F_a, "N", "F_a", "axial force", "[GOST21354]")
    r.put("forces", "F_n", f.F_n, "N", "F_n", "normal force", "[GOST21354]")
    r.put("forces", "beta_w", math.degrees(f.beta_w), "deg", "β_w", "helix angle at d_w",
          "[GOST21354]")
    r.put("forces", "M_a1", f.M_a1, "N·m", "M_a1", "moment of F_a on the pinion shaft (F_a·d_w1/2)",
          "statics")
    r.put("forces", "M_a2", f.M_a2, "N·m", "M_a2", "moment of F_a on the wheel shaft (F_a·d_w2/2)",
          "statics")
    F_tH = 2000.0 * duty.T1 / g.g1.d
    r.put("forces", "F_tH", F_tH, "N", "F_tH", "tangential force at d1 (for σ_H, σ_F)",
          SRC_ZPCIL)
    v = math.pi * g.g1.d * duty.n1 / 60000.0
    r.put("forces", "v_H", v, "m/s", "v", "circumferential velocity at d1 (for K_v, Z_v)",
          SRC_ZPCIL)
    return f, F_tH, v


def life_cycles(duty: Duty, mats, u):
    """Load cycles N_K and the equivalent contact and bending cycles N_HE, N_FE of pinion and
    wheel (lists of two; ``u`` a number or an array of candidates): by the GOST regime's
    equivalence factors μ_H, μ_F or by the spectrum's sum ([GOST21354]; :mod:`..loads`)."""
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


def rate(g: PairGeometry, mats: tuple[GearMaterial, GearMaterial], duty: Duty,
         s: Setting) -> Rating:
    """Rate the pair: contact and bending fatigue, peak loads (GOST 21354-87)."""
    r = Rating()
    p = g.inp
    helical = p.beta > 0.0
    internal = getattr(g, "internal", False)
    u = g.u
    m1, m2 = mats
    gears = (g.g1, g.g2)

    # ------------------------------------------------------------------ forces, speeds
    f, F_tH, v = put_forces(r, g, duty)

    # ------------------------------------------------------------------ life
    life = duty.life
    N_K, N_HE, N_FE = life_cycles(duty, mats, u)
    how = "spectrum" if life.blocks else f"regime {life.regime}"
    if not life.blocks:
        r.put("life", "mu_H", T.MU_H[life.regime], "-", "μ_H",
              f"equivalence factor, contact, regime {life.regime}", SRC_TABLE)
        for i, mat in enumerate(mats):
            r.put("life", f"mu_F{i + 1}", T.MU_F[mat.q_F][life.regime], "-", f"μ_F{i + 1}",
                  f"equivalence factor, bending (q_F = {mat.q_F}), regime {life.regime}",
                  SRC_TABLE)
    else:
        r.put("life", "damage_sum", "single slope: exponent q_H/2 = 3 (contact) and q_F "
              "(bending) for every block, no second slope beyond the base number", None, "Σ",
              "variant of the equivalent-cycle sum", SRC)
    for i in range(2):
        who = ("pinion", "wheel")[i]
        r.put("life", f"N_K{i + 1}", N_K[i], "-", f"N_K{i + 1}",
              f"load cycles in the required life, {who}", SRC)
    for i in range(2):
        who = ("pinion", "wheel")[i]
        r.put("life", f"N_HE{i + 1}", N_HE[i], "-", f"N_HE{i + 1}",
              f"equivalent contact cycles ({how}), {who}", SRC)
        r.put("life", f"N_FE{i + 1}", N_FE[i], "-", f"N_FE{i + 1}",
              f"equivalent bending cycles ({how}, q_F = {mats[i].q_F}), {who}", SRC)

    # ------------------------------------------------------------------ load factors
    K_A = duty.K_A
    r.put("factors", "K_A", K_A, "-", "K_A", "application factor", "spec")
    soft_pair = min(m1.HB, m2.HB) <= 350.0   # the softer gear runs in
    form = "helical" if helical else ("spur_relieved" if s.tip_relief else "spur")
    grade = s.grade
    w_Hv = G.dynamic_load(T.DELTA_H[("soft" if soft_pair else "hard", form)], grade, p.m_n, v,
                          g.a_w, u)
    w_Fv = G.dynamic_load(T.DELTA_F[form], grade, p.m_n, v, g.a_w, u)
    r.put("factors", "w_Hv", w_Hv, "N/mm", "w_Hv", "specific dynamic force, contact", SRC_TABLE)
    j = G.module_class(p.m_n)
    r.put("factors", "delta_H", T.DELTA_H[("soft" if soft_pair else "hard", form)], "-", "δ_H",
          f"tooth form/hardness factor of w_Hv ({form})", SRC_TABLE)
    r.put("factors", "delta_F", T.DELTA_F[form], "-", "δ_F",
          f"tooth form factor of w_Fv ({form})", SRC_TABLE)
    r.put("factors", "g_0", float(T.G0[grade][j]), "-", "g_0",
          f"pitch deviation factor (grade {grade})", SRC_TABLE)
    r.put("factors", "w_max", float(T.W_MAX[grade][j]), "N/mm", "w_max",
          f"upper limit of w_v (grade {grade})", SRC_TABLE)
    r.put("factors", "w_Fv", w_Fv, "N/mm", "w_Fv", "specific dynamic force, bending", SRC_TABLE)
    r.put("factors", "K_v_variant", "F_t/b_w as computed (no 150 N/mm floor)", None, "K_v",
          "variant of K_v = 1 + w_v·b_w/(F_t·K_A)", SRC)
    K_Hv = _factor(r, s, "factors", "K_Hv", lambda: G.k_v(w_Hv, p.b_w, F_tH, K_A), "K_Hv",
                   "dynamic factor, contact", SRC)
    K_Fv = _factor(r, s, "factors", "K_Fv", lambda: G.k_v(w_Fv, p.b_w, F_tH, K_A), "K_Fv",
                   "dynamic factor, bending", SRC)
    psi_bd = p.b_w / g.g1.d
    r.put("factors", "psi_bd", psi_bd, "-", "ψ_bd", "face width ratio b_w/d1 (read in the "
          "K_Hβ chart)", SRC)
    K0_Hb = r.put("factors", "K0_Hbeta", G.k_h_beta(s.scheme, psi_bd, False), "-", "K⁰_Hβ",
                  f"face load factor before running-in (scheme {s.scheme})",
                  "GOST 21354-87 chart (ZPCIL fit)")
    K_Hb = _factor(r, s, "factors", "K_Hbeta", lambda: G.k_h_beta(s.scheme, psi_bd, soft_pair),
                   "K_Hβ", "face load factor, contact" + (" (after running-in: softer gear "
                   "≤ 350 HB)" if soft_pair else " (no running-in: both gears > 350 HB)"),
                   "GOST 21354-87 chart (ZPCIL fit)")
    if soft_pair and K0_Hb > 1.0:
        r.put("factors", "K_Hw", (K_Hb - 1.0) / (K0_Hb - 1.0), "-", "K_Hw",
              "running-in factor (K_Hβ − 1)/(K⁰_Hβ − 1)", SRC)
    h_eff = 2.0 * p.m_n if helical else 2.0 * p.m_n / g.eps_alpha
    N_F = r.put("factors", "N_F", G.n_f(p.b_w, h_eff), "-", "N_F",
                f"exponent of K_Fβ = (K⁰_Hβ)^N_F (b/h = {p.b_w / h_eff:.3f})", SRC_ZPCIL)
    K_Fb = _factor(r, s, "factors", "K_Fbeta", lambda: K0_Hb ** N_F, "K_Fβ",
                   "face load factor, bending (K⁰_Hβ^N_F, before running-in)", SRC_ZPCIL)
    Z_eps = _given(s, "Z_eps", lambda: G.z_eps(g.eps_alpha, g.eps_beta if helical else 0.0))
    Y_eps = _given(s, "Y_eps", lambda: G.y_eps(g.eps_alpha, g.eps_beta if helical else 0.0))
    if helical:
        z_v = [gear.z / math.cos(p.beta) ** 3 for gear in gears]
        c_gamma = G.mesh_stiffness(z_v[0], z_v[1], p.x1, p.x2) * (0.75 * g.eps_alpha + 0.25)
        f_pb = math.hypot(*(G.base_pitch_deviation(p.m_n, gear.d, grade) for gear in gears))
        a_alpha = 0.2 if soft_pair else 0.3
        K_Ha_max = G.k_h_alpha_max(g.eps_alpha, g.eps_beta, Z_eps)
        K_Fa_max = 1.0 / Y_eps
        capped = {}

        def kha() -> float:
            k = G.k_alpha(g.eps_alpha, g.eps_beta, c_gamma, p.b_w, f_pb, a_alpha, F_tH, K_A,
                          K_Hv, K_Hb)
            k, capped["H"] = G.limited(k, K_Ha_max)
            return k

        def kfa() -> float:
            k = G.k_alpha(g.eps_alpha, g.eps_beta, c_gamma, p.b_w, f_pb, 0.4, F_tH, K_A, K_Fv,
                          K_Fb)
            k, capped["F"] = G.limited(k, K_Fa_max)
            return k

        r.put("factors", "c_gamma", c_gamma, "N/(mm·µm)", "c_γ", "mesh stiffness", SRC_ZPCIL)
        r.put("factors", "f_pb", f_pb, "µm", "f_pb", "equivalent base pitch deviation",
              "GOST 1643-81 (ZPCIL fit)")
        r.put("factors", "K_Halpha_max", K_Ha_max, "-", "K_Hα,max",
              "upper limit of K_Hα (the factor is never below 1)", SRC_ZPCIL)
        r.put("factors", "K_Falpha_max", K_Fa_max, "-", "K_Fα,max",
              "upper limit of K_Fα = 1/Y_ε (K_Fα·Y_ε ≤ 1)", SRC)
        K_Ha = _factor(r, s, "factors", "K_Halpha", kha, "K_Hα", "transverse load factor, contact",
                       SRC_ZPCIL)
        K_Fa = _factor(r, s, "factors", "K_Falpha", kfa, "K_Fα", "transverse load factor, bending",
                       SRC_ZPCIL)
        for key in ("H", "F"):
            if key in capped:
                r.put("factors", f"K_{key}alpha_capped", "yes" if capped[key] else "no", None,
                      f"K_{key}α at cap", f"K_{key}α limited by its upper limit", SRC)
    else:
        K_Ha = _factor(r, s, "factors", "K_Halpha", 1.0, "K_Hα",
                       "transverse load factor, contact (spur: 1)", SRC)
        K_Fa = _factor(r, s, "factors", "K_Falpha", 1.0, "K_Fα",
                       "transverse load factor, bending (spur: 1)", SRC)
    def peak_alpha(K_Hb_max: float, K_Fb_max: float, ratio: float) -> tuple[float, float]:
        """K_Hα and K_Fα at the peak torque: the same formula at the peak load with
        K_A = K_v = 1 (the peak torque is an actual torque); a given factor is scaled
        by :func:`.gost21354.peak_factor`."""
        if not helical:
            return 1.0, 1.0
        out = []
        for key, K, a_al, K_b, cap in (("K_Halpha", K_Ha, a_alpha, K_Hb_max, K_Ha_max),
                                       ("K_Falpha", K_Fa, 0.4, K_Fb_max, K_Fa_max)):
            if s.overrides.get(key) is not None:
                out.append(G.peak_factor(K, 1.0, ratio))
            else:
                k = G.k_alpha(g.eps_alpha, g.eps_beta, c_gamma, p.b_w, f_pb, a_al,
                              F_tH * ratio, 1.0, 1.0, K_b)
                out.append(G.limited(k, cap)[0])
        return out[0], out[1]

    K_H = r.put("factors", "K_H", K_A * K_Hv * K_Hb * K_Ha, "-", "K_H",
                "load factor, contact K_A·K_Hv·K_Hβ·K_Hα", SRC)
    K_F = r.put("factors", "K_F", K_A * K_Fv * K_Fb * K_Fa, "-", "K_F",
                "load factor, bending K_A·K_Fv·K_Fβ·K_Fα", SRC)

    # ------------------------------------------------------------------ contact
    Z_E = _factor(r, s, "contact", "Z_E", lambda: G.z_e(m1.E, m1.nu, m2.E, m2.nu), "Z_E",
                  "elasticity factor", SRC, unit="MPa^0.5")
    Z_H = _factor(r, s, "contact", "Z_H", lambda: G.z_h(g.beta_b, g.alpha_t, g.alpha_tw), "Z_H",
                  "zone factor", SRC)
    _factor(r, s, "contact", "Z_eps", Z_eps, "Z_ε", "contact ratio factor", SRC)
    sigma_H = r.put("contact", "sigma_H",
                    G.sigma_h(Z_E, Z_H, Z_eps, F_tH, K_H, u, p.b_w, g.g1.d, internal), "MPa",
                    "σ_H", "contact stress" + (" (internal pair, u − 1)" if internal else ""),
                    SRC)
    if s.contact_model == "popov_n07" or s.crowning:
        _informative_contact(r, g, f.F_n * K_H, sigma_H, m1, m2, s)
    sigma_HP = []
    for i, mat in enumerate(mats):
        k, who = i + 1, ("pinion", "wheel")[i]
        r.put("contact", f"sigma_Hlim{k}", mat.sigma_Hlim, "MPa", f"σ_Hlim{k}",
              f"contact endurance limit, {who}", "material" if "sigma_Hlim" not in mat.given
              else "spec")
        r.put("contact", f"S_H{k}_min", mat.S_H, "-", f"S_Hmin{k}",
              f"required contact safety factor, {who}", SRC_TABLE)
        NHG = _factor(r, s, "contact", f"N_HG{k}", lambda: G.n_hg(mat.HB), f"N_HG{k}",
                      f"base number of contact cycles, {who}", SRC)
        ZNmax = _factor(r, s, "contact", f"Z_Nmax{k}", mat.Z_N_max, f"Z_Nmax{k}",
                        f"upper limit of Z_N ({'hardened surface' if mat.Z_N_max < 2.6 else 'homogeneous structure'}), {who}", SRC)
        r.put("contact", f"q_H{k}", 6.0 if N_HE[i] <= NHG else 20.0, "-", f"q_H{k}",
              f"exponent of the contact fatigue curve in use, {who}", SRC)
        ZN = _factor(r, s, "contact", f"Z_N{k}", lambda: G.z_n(NHG, N_HE[i], ZNmax), f"Z_N{k}",
                     f"life factor, contact, {who}", SRC)
        ZR = _factor(r, s, "contact", f"Z_R{k}", lambda: G.z_r(s.Ra[i]), f"Z_R{k}",
                     f"roughness factor (Ra = {s.Ra[i]:g} µm), {who}", SRC_TABLE)
        ZV = _factor(r, s, "contact", f"Z_v{k}", lambda: G.z_v(v, mat.soft), f"Z_v{k}",
                     f"velocity factor, {who}", SRC)
        ZX = _factor(r, s, "contact", f"Z_X{k}", lambda: G.z_x(gears[i].d), f"Z_X{k}",
                     f"size factor, contact, {who}", SRC)
        limit = mat.sigma_Hlim * ZN * ZR * ZV * ZX
        sigma_HP.append(r.put("contact", f"sigma_HP{k}", limit / mat.S_H, "MPa", f"σ_HP{k}",
                              f"allowable contact stress, {who}", SRC))
        r.put("contact", f"S_H{k}", limit / sigma_H, "-", f"S_H{k}",
              f"contact safety factor σ_Hlim·Z_N·Z_R·Z_v·Z_X/σ_H, {who}", SRC)
    pair_rule = helical and g.eps_beta >= 1.0
    r.put("contact", "sigma_HP", G.sigma_hp_pair(sigma_HP[0], sigma_HP[1], pair_rule), "MPa",
          "σ_HP", "allowable contact stress of the pair" +
          (" 0.45(σ_HP1 + σ_HP2), ≤ 1.25σ_HPmin" if pair_rule else " (the smaller)"), SRC)

    # ------------------------------------------------------------------ bending
    Y_beta = _factor(r, s, "bending", "Y_beta",
                     lambda: G.y_beta(g.eps_beta, p.beta) if helical else 1.0, "Y_β",
                     "helix factor", SRC)
    _factor(r, s, "bending", "Y_eps", Y_eps, "Y_ε", "contact ratio factor, bending", SRC)
    Y_delta = _factor(r, s, "bending", "Y_delta", lambda: G.y_delta(p.m_n), "Y_δ",
                      "notch sensitivity factor", SRC)
    N_FG = _factor(r, s, "bending", "N_FG", G.N_FG, "N_FG", "base number of bending cycles "
                   "(Y_N = 1 beyond it: the standard's variant)", SRC)
    Y_R = _factor(r, s, "bending", "Y_R", 1.0, "Y_R", "root surface factor", SRC)
    for i, mat in enumerate(mats):
        k, who, gear = i + 1, ("pinion", "wheel")[i], gears[i]
        zv = gear.z / math.cos(p.beta) ** 3
        r.put("bending", f"z_v{k}", zv, "-", f"z_v{k}", f"virtual number of teeth z/cos³β, {who}",
              SRC)
        if internal and k == 2:
            YFS = _factor(r, s, "bending", "Y_FS2", lambda: G.y_fs_internal(gear.x), "Y_FS2",
                          "tooth form factor, internal gear (rack limit, approximate)",
                          SRC + " (rack limit)")
        else:
            YFS = _factor(r, s, "bending", f"Y_FS{k}", lambda: G.y_fs(zv, gear.x), f"Y_FS{k}",
                          f"tooth form factor, {who}", SRC)
        sF = r.put("bending", f"sigma_F{k}",
                   G.sigma_f(F_tH, K_F, p.b_w, p.m_n, YFS, Y_beta, Y_eps), "MPa", f"σ_F{k}",
                   f"root bending stress, {who}", SRC)
        r.put("bending", f"sigma_Flim{k}", mat.sigma_Flim, "MPa", f"σ_Flim{k}",
              f"bending endurance limit, {who}",
              "spec" if "sigma_Flim" in mat.given else "material")
        r.put("bending", f"S_F{k}_min", mat.S_F, "-", f"S_Fmin{k}",
              f"required bending safety factor, {who}",
              "spec" if "S_F" in mat.given else SRC_TABLE)
        r.put("bending", f"q_F{k}", float(mat.q_F), "-", f"q_F{k}",
              f"exponent of the bending fatigue curve, {who}", SRC)
        YN = _factor(r, s, "bending", f"Y_N{k}", lambda: G.y_n(N_FE[i], mat.q_F, N_FG),
                     f"Y_N{k}", f"life factor, bending (q_F = {mat.q_F}), {who}", SRC)
        YX = _factor(r, s, "bending", f"Y_X{k}", lambda: G.y_x(gear.d), f"Y_X{k}",
                     f"size factor, bending, {who}", SRC)
        rev = duty.reverse_ratio if duty.reverse_ratios is None else duty.reverse_ratios[i]
        YA = _factor(r, s, "bending", f"Y_A{k}", lambda: G.y_a(mat.gamma_A, rev), f"Y_A{k}",
                     f"reversed-load factor, {who}", SRC)
        limit = mat.sigma_Flim * YN * Y_delta * Y_R * YX * YA
        r.put("bending", f"sigma_FP{k}", limit / mat.S_F, "MPa", f"σ_FP{k}",
              f"allowable bending stress, {who}", SRC)
        r.put("bending", f"S_F{k}", limit / sF, "-", f"S_F{k}",
              f"bending safety factor σ_Flim·Y_N·Y_δ·Y_R·Y_X·Y_A/σ_F, {who}", SRC)

    # ------------------------------------------------------------------ peak load
    if duty.T_peak is not None:
        Tm = duty.T_peak
        K_Hb_max = G.peak_factor(K_Hb, duty.T1, Tm)
        K_Fb_max = G.peak_factor(K_Fb, duty.T1, Tm)
        K_Ha_pk, K_Fa_pk = peak_alpha(K_Hb_max, K_Fb_max, Tm / duty.T1)
        K_Hmax = K_Hb_max * K_Ha_pk
        K_Fmax = K_Fb_max * K_Fa_pk
        r.put("static", "T_peak", Tm, "N·m", "T_max", "peak pinion torque (an actual torque: "
              "K_A does not enter the peak stresses)", "spec")
        r.put("static", "K_Hmax", K_Hmax, "-", "K_Hmax", "load factor at the peak torque, "
              "contact (K_v = 1, no K_A)", SRC_ZPCIL)
        r.put("static", "K_Fmax", K_Fmax, "-", "K_Fmax", "load factor at the peak torque, "
              "bending (K_v = 1, no K_A)", SRC_ZPCIL)
        S_FSt = _factor(r, s, "static", "S_FSt", G.S_FST, "S_FSt",
                        "safety factor against the static bending limit", SRC)
        r.put("static", "sigma_Hmax", G.sigma_h_max(sigma_H, duty.T1, Tm, K_H, K_Hmax),
              "MPa", "σ_Hmax", "contact stress at the peak torque", SRC_ZPCIL)
        for i, mat in enumerate(mats):
            k, who = i + 1, ("pinion", "wheel")[i]
            r.put("static", f"sigma_HPmax{k}", mat.sigma_HPmax, "MPa", f"σ_HPmax{k}",
                  f"allowable peak contact stress, {who}",
                  "spec" if "sigma_HPmax" in mat.given else SRC_TABLE)
        for i, mat in enumerate(mats):
            k, who = i + 1, ("pinion", "wheel")[i]
            r.put("static", f"sigma_Fmax{k}",
                  G.sigma_f_max(r.v[f"sigma_F{k}"], duty.T1, Tm, K_F, K_Fmax), "MPa",
                  f"σ_Fmax{k}", f"bending stress at the peak torque, {who}", SRC_ZPCIL)
            r.put("static", f"Y_z{k}", mat.Y_z, "-", f"Y_z{k}",
                  f"blank factor (forging 1, rolled 0.9, casting 0.8), {who}", SRC)
            r.put("static", f"sigma_FPmax{k}",
                  G.sigma_fp_max(mat.sigma_FSt, r.v[f"Y_X{k}"], mat.Y_z, S_FSt), "MPa",
                  f"σ_FPmax{k}", f"allowable peak bending stress, {who}", SRC)
    return r
