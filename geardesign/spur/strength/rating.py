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
    f = mesh_forces(g, duty.T1)
    r.put("forces", "T1", duty.T1, "N*m", "T1", "pinion torque (nominal)", "spec")
    r.put("forces", "T2", duty.T1 * u, "N*m", "T2", "wheel torque (no mesh loss)", SRC)
    r.put("forces", "F_t", f.F_t, "N", "F_t", "tangential force at d_w1", "method note §8.4")
    r.put("forces", "F_r", f.F_r, "N", "F_r", "radial force", "method note §8.4")
    r.put("forces", "F_a", f.F_a, "N", "F_a", "axial force", "method note §8.4")
    r.put("forces", "F_n", f.F_n, "N", "F_n", "normal force", "method note §8.4")
    r.put("forces", "beta_w", math.degrees(f.beta_w), "deg", "β_w", "helix angle at d_w",
          "method note §8.4")
    r.put("forces", "M_a1", f.M_a1, "N*m", "M_a1", "moment of F_a on the pinion shaft (F_a·d_w1/2)",
          "statics")
    r.put("forces", "M_a2", f.M_a2, "N*m", "M_a2", "moment of F_a on the wheel shaft (F_a·d_w2/2)",
          "statics")
    F_tH = 2000.0 * duty.T1 / g.g1.d
    r.put("forces", "F_tH", F_tH, "N", "F_tH", "tangential force at d1 (for σ_H, σ_F)",
          SRC_ZPCIL)
    v = math.pi * g.g1.d * duty.n1 / 60000.0
    r.put("forces", "v_H", v, "m/s", "v", "circumferential velocity at d1 (for K_v, Z_v)",
          SRC_ZPCIL)

    # ------------------------------------------------------------------ life
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
    how = "spectrum" if life.blocks else f"regime {life.regime}"
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
    r.put("factors", "w_Fv", w_Fv, "N/mm", "w_Fv", "specific dynamic force, bending", SRC_TABLE)
    K_Hv = _factor(r, s, "factors", "K_Hv", lambda: G.k_v(w_Hv, p.b_w, F_tH, K_A), "K_Hv",
                   "dynamic factor, contact", SRC)
    K_Fv = _factor(r, s, "factors", "K_Fv", lambda: G.k_v(w_Fv, p.b_w, F_tH, K_A), "K_Fv",
                   "dynamic factor, bending", SRC)
    psi_bd = p.b_w / g.g1.d
    K_Hb = _factor(r, s, "factors", "K_Hbeta", lambda: G.k_h_beta(s.scheme, psi_bd, soft_pair),
                   "K_Hβ", f"face load factor, contact (scheme {s.scheme}, ψ_bd = {psi_bd:.3f})",
                   "GOST 21354-87 chart (ZPCIL fit)")
    h_eff = 2.0 * p.m_n if helical else 2.0 * p.m_n / g.eps_alpha
    K_Fb = _factor(r, s, "factors", "K_Fbeta", lambda: G.k_f_beta(K_Hb, p.b_w, h_eff), "K_Fβ",
                   "face load factor, bending (K_Hβ^N_F)", SRC_ZPCIL)
    Z_eps = G.z_eps(g.eps_alpha, g.eps_beta if helical else 0.0)
    if helical:
        z_v = [gear.z / math.cos(p.beta) ** 3 for gear in gears]
        c_gamma = G.mesh_stiffness(z_v[0], z_v[1], p.x1, p.x2) * (0.75 * g.eps_alpha + 0.25)
        f_pb = math.hypot(*(G.base_pitch_deviation(p.m_n, gear.d, grade) for gear in gears))
        a_alpha = 0.2 if soft_pair else 0.3

        def kha() -> float:
            k = G.k_alpha(g.eps_alpha, g.eps_beta, c_gamma, p.b_w, f_pb, a_alpha, F_tH, K_A,
                          K_Hv, K_Hb)
            return min(k, G.k_h_alpha_max(g.eps_alpha, g.eps_beta, Z_eps))

        def kfa() -> float:
            k = G.k_alpha(g.eps_alpha, g.eps_beta, c_gamma, p.b_w, f_pb, 0.4, F_tH, K_A, K_Fv,
                          K_Fb)
            return min(k, G.k_f_alpha_max(g.eps_alpha, g.eps_beta))

        r.put("factors", "c_gamma", c_gamma, "N/(mm*um)", "c_γ", "mesh stiffness", SRC_ZPCIL)
        r.put("factors", "f_pb", f_pb, "um", "f_pb", "equivalent base pitch deviation",
              "GOST 1643-81 (ZPCIL fit)")
        K_Ha = _factor(r, s, "factors", "K_Halpha", kha, "K_Hα", "transverse load factor, contact",
                       SRC_ZPCIL)
        K_Fa = _factor(r, s, "factors", "K_Falpha", kfa, "K_Fα", "transverse load factor, bending",
                       SRC_ZPCIL)
    else:
        K_Ha = _factor(r, s, "factors", "K_Halpha", 1.0, "K_Hα",
                       "transverse load factor, contact (spur: 1)", SRC)
        K_Fa = _factor(r, s, "factors", "K_Falpha", 1.0, "K_Fα",
                       "transverse load factor, bending (spur: 1)", SRC)
    K_H = r.put("factors", "K_H", K_A * K_Hv * K_Hb * K_Ha, "-", "K_H",
                "load factor, contact K_A·K_Hv·K_Hβ·K_Hα", SRC)
    K_F = r.put("factors", "K_F", K_A * K_Fv * K_Fb * K_Fa, "-", "K_F",
                "load factor, bending K_A·K_Fv·K_Fβ·K_Fα", SRC)

    # ------------------------------------------------------------------ contact
    Z_E = _factor(r, s, "contact", "Z_E", lambda: G.z_e(m1.E, m1.nu, m2.E, m2.nu), "Z_E",
                  "elasticity factor", SRC, unit="MPa^0.5")
    Z_H = r.put("contact", "Z_H", G.z_h(g.beta_b, g.alpha_t, g.alpha_tw), "-", "Z_H",
                "zone factor", SRC)
    r.put("contact", "Z_eps", Z_eps, "-", "Z_ε", "contact ratio factor", SRC)
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
        NHG = r.put("contact", f"N_HG{k}", G.n_hg(mat.HB), "-", f"N_HG{k}",
                    f"base number of contact cycles, {who}", SRC)
        ZN = r.put("contact", f"Z_N{k}", G.z_n(NHG, N_HE[i], mat.Z_N_max), "-", f"Z_N{k}",
                   f"life factor, contact, {who}", SRC)
        ZR = _factor(r, s, "contact", f"Z_R{k}", lambda: G.z_r(s.Ra[i]), f"Z_R{k}",
                     f"roughness factor (Ra = {s.Ra[i]:g} µm), {who}", SRC_TABLE)
        ZV = r.put("contact", f"Z_v{k}", G.z_v(v, mat.soft), "-", f"Z_v{k}",
                   f"velocity factor, {who}", SRC)
        ZX = r.put("contact", f"Z_X{k}", G.z_x(gears[i].d), "-", f"Z_X{k}",
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
    Y_beta = r.put("bending", "Y_beta", G.y_beta(g.eps_beta, p.beta) if helical else 1.0, "-",
                   "Y_β", "helix factor", SRC)
    Y_eps = r.put("bending", "Y_eps", G.y_eps(g.eps_alpha, g.eps_beta if helical else 0.0), "-",
                  "Y_ε", "contact ratio factor, bending", SRC)
    Y_delta = r.put("bending", "Y_delta", G.y_delta(p.m_n), "-", "Y_δ",
                    "notch sensitivity factor", SRC)
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
        YN = r.put("bending", f"Y_N{k}", G.y_n(N_FE[i], mat.q_F), "-", f"Y_N{k}",
                   f"life factor, bending (q_F = {mat.q_F}), {who}", SRC)
        YX = r.put("bending", f"Y_X{k}", G.y_x(gear.d), "-", f"Y_X{k}",
                   f"size factor, bending, {who}", SRC)
        rev = duty.reverse_ratio if duty.reverse_ratios is None else duty.reverse_ratios[i]
        YA = r.put("bending", f"Y_A{k}", G.y_a(mat.gamma_A, rev), "-", f"Y_A{k}",
                   f"reversed-load factor, {who}", SRC)
        limit = mat.sigma_Flim * YN * Y_delta * Y_R * YX * YA
        r.put("bending", f"sigma_FP{k}", limit / mat.S_F, "MPa", f"σ_FP{k}",
              f"allowable bending stress, {who}", SRC)
        r.put("bending", f"S_F{k}", limit / sF, "-", f"S_F{k}",
              f"bending safety factor σ_Flim·Y_N·Y_δ·Y_R·Y_X·Y_A/σ_F, {who}", SRC)

    # ------------------------------------------------------------------ peak load
    if duty.T_peak is not None:
        Tm = duty.T_peak
        K_Hmax = K_A * G.peak_factor(K_Hb, duty.T1, Tm) * G.peak_factor(K_Ha, duty.T1, Tm)
        K_Fmax = K_A * G.peak_factor(K_Fb, duty.T1, Tm) * G.peak_factor(K_Fa, duty.T1, Tm)
        r.put("static", "T_peak", Tm, "N*m", "T_max", "peak pinion torque", "spec")
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
            r.put("static", f"sigma_FPmax{k}",
                  G.sigma_fp_max(mat.sigma_FSt, r.v[f"Y_X{k}"], mat.Y_z), "MPa",
                  f"σ_FPmax{k}", f"allowable peak bending stress, {who}", SRC)
    return r
