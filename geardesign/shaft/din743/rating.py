"""One section of a shaft by DIN 743: the notch (shoulder, round groove, rectangular groove,
V-notch, cross-bore, key seat, press fit, a notch of given β, or none), the material at its
blank size, the stresses -> :class:`Rating` (every factor and both safeties).  Pure
functions on plain data; [DIN743-1], [DIN743-2], [DIN743-3] through :mod:`.part1`,
:mod:`.part2`, :mod:`.part3`."""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.shaft.din743 import part1 as P1
from geardesign.shaft.din743 import part2 as P2
from geardesign.shaft.din743 import part3 as P3


@dataclass(frozen=True)
class Notch:
    """A notch and its notch factors β (tension, bending, torsion) at the section's
    diameter.  ``alpha_*``: the stress concentration factor for γ_F (β where none is
    known); ``circumferential``: a notch around the shaft (γ_F applies); ``roughness``:
    K_F from R_z applies (False where β includes the surface: key seat, press fit);
    ``Rz_B``: β was measured with this roughness [µm], K_F is taken relative to it
    (rectangular groove)."""
    kind: str
    beta_zd: float
    beta_b: float
    beta_t: float
    alpha_zd: float
    alpha_b: float
    alpha_t: float | None = None
    n_b: float | None = None
    n_t: float | None = None
    circumferential: bool = True
    roughness: bool = True
    in_range: bool = True
    Rz_B: float | None = None


@dataclass(frozen=True)
class Material:
    """A steel of [DIN743-3] at the blank diameter d_eff: K_1 of the tensile and the yield
    strength, σ_B(d) = K_1B·σ_B(d_B), σ_S(d) = K_1S·σ_S(d_B) [MPa]."""
    steel: P3.Steel
    d_eff: float
    K_1B: float
    K_1S: float

    @property
    def sigma_B_d(self) -> float:
        return self.K_1B * self.steel.sigma_B

    @property
    def sigma_S_d(self) -> float:
        return self.K_1S * self.steel.sigma_S


def material(steel: P3.Steel, d_eff: float) -> Material:
    """The steel at the blank diameter d_eff [mm] (K_1 of [DIN743-2] eqs. (10)-(14))."""
    return Material(steel, d_eff, P3.K_1(steel.type, d_eff, "B"),
                    P3.K_1(steel.type, d_eff, "S"))


def shoulder(d: float, D: float, r: float, mat: Material, hard_surface: bool) -> Notch:
    """A shoulder from d to D with fillet radius r [mm]: β = α/n ([DIN743-2])."""
    a = {k: P2.alpha_shoulder(d, D, r, k) for k in ("tension", "bending", "torsion")}
    n = {k: P2.support_number(P2.stress_gradient_shoulder(d, D, r, k), mat.sigma_S_d,
                              hard_surface) for k in a}
    b = {k: P2.beta_from_alpha(a[k], n[k]) for k in a}
    return Notch("shoulder", b["tension"], b["bending"], b["torsion"], a["tension"],
                 a["bending"], a["torsion"], min(n["bending"], a["bending"]),
                 min(n["torsion"], a["torsion"]), True, True, P2.shoulder_in_range(d, D, r))


def round_groove(D: float, t: float, r: float, mat: Material, hard_surface: bool) -> Notch:
    """A round groove (umlaufende Rundnut) of depth t and radius r [mm] in a shaft of
    diameter D [mm]; the section is the groove root d = D − 2t: α of [DIN743-2] with the
    round-groove constants, G′ = 2·(1 + φ)/r (tension, bending), 1/r (torsion), β = α/n."""
    d = D - 2.0 * t
    a = {k: P2.alpha_shoulder(d, D, r, k, "round_groove")
         for k in ("tension", "bending", "torsion")}
    n = {k: P2.support_number(P2.stress_gradient_shoulder(d, D, r, k, "round_groove"),
                              mat.sigma_S_d, hard_surface) for k in a}
    b = {k: P2.beta_from_alpha(a[k], n[k]) for k in a}
    return Notch("round groove", b["tension"], b["bending"], b["torsion"], a["tension"],
                 a["bending"], a["torsion"], min(n["bending"], a["bending"]),
                 min(n["torsion"], a["torsion"]), True, True, P2.shoulder_in_range(d, D, r))


def ring_groove(D: float, t: float, m: float, r: float, mat: Material) -> Notch:
    """A rectangular groove (umlaufende Rechtecknut, e.g. for a retaining ring) of depth t,
    width m and root radius r [mm] in a shaft of diameter D [mm]; the section is the groove
    root d = D − 2t: β measured ([DIN743-2] section 4.2.4, :func:`.part2.beta_ring_groove`),
    K_F relative to R_z = 20 µm; γ_F from β (no α is known)."""
    bzd, bb, bt = P2.beta_ring_groove(D - 2.0 * t, t, m, r, mat.sigma_S_d)
    return Notch("ring groove", bzd, bb, bt, bzd, bb,
                 Rz_B=P2.tables()["ring_groove"]["Rz_B"])


def v_notch(D: float, t: float, mat: Material) -> Notch:
    """A V-notch (Spitzkerbe) of depth t [mm] in a shaft of diameter D [mm]; the section is
    the root d = D − 2t: β measured ([DIN743-2] section 4.2.3,
    :func:`.part2.beta_v_notch`), K_F relative to R_z = 20 µm; γ_F from β."""
    bzd, bb, bt = P2.beta_v_notch(D - 2.0 * t, mat.sigma_B_d)
    return Notch("V-notch", bzd, bb, bt, bzd, bb, Rz_B=P2.tables()["v_notch"]["Rz_B"])


def cross_bore(d: float, d_L: float, mat: Material, hard_surface: bool) -> Notch:
    """A cross-bore (Querbohrung) of diameter d_L [mm] through a solid shaft of diameter d
    [mm]: α of [DIN743-2] section 5.2.3, G′ = 2.3/r (+ 2/d in bending and torsion, 1.15/r
    in torsion), β = α/n; not around the shaft (γ_F = 1)."""
    a = dict(zip(("tension", "bending", "torsion"), P2.alpha_cross_bore(d, d_L)))
    n = {k: P2.support_number(P2.stress_gradient_cross_bore(d, d_L, k), mat.sigma_S_d,
                              hard_surface) for k in a}
    b = {k: P2.beta_from_alpha(a[k], n[k]) for k in a}
    return Notch("cross-bore", b["tension"], b["bending"], b["torsion"], a["tension"],
                 a["bending"], a["torsion"], min(n["bending"], a["bending"]),
                 min(n["torsion"], a["torsion"]), circumferential=False)


def measured(kind: str, d: float, mat: Material) -> Notch:
    """A key seat (``"key"``) or a press fit (``"press_fit"``) at diameter d [mm]:
    β from [DIN743-2] table 1 with K_3; tension β_zd = β_σ; K_F = 1."""
    bs, bt = P2.beta_measured(kind, d, mat.sigma_B_d)
    return Notch("key" if kind == "key" else "press fit", bs, bs, bt, bs, bs,
                 circumferential=kind != "key", roughness=False)


def given(beta_sigma: float, beta_tau: float, kind: str = "groove") -> Notch:
    """A circumferential notch whose β are given (e.g. a groove from a handbook)."""
    return Notch(kind, beta_sigma, beta_sigma, beta_tau, beta_sigma, beta_sigma)


def smooth() -> Notch:
    """No notch: β = 1."""
    return Notch("smooth", 1.0, 1.0, 1.0, 1.0, 1.0)


@dataclass(frozen=True)
class Stresses:
    """Nominal stresses of the section [MPa]: amplitude, mean and peak of tension (zd),
    bending (b) and torsion (t)."""
    zda: float = 0.0
    zdm: float = 0.0
    zdmax: float = 0.0
    ba: float = 0.0
    bm: float = 0.0
    bmax: float = 0.0
    ta: float = 0.0
    tm: float = 0.0
    tmax: float = 0.0


@dataclass(frozen=True)
class Rating:
    notch: Notch
    K_2: float
    K_F_sigma: float
    K_F_tau: float
    K_sigma_zd: float
    K_sigma: float
    K_tau: float
    sigma_zdWK: float
    sigma_WK: float
    tau_WK: float
    psi_zd: float
    psi_sigma: float
    psi_tau: float
    sigma_mv: float
    tau_mv: float
    gamma_F: float
    gamma_F_zd: float
    K_2F: float
    K_2F_tau: float
    sigma_zdFK: float
    sigma_FK: float
    tau_FK: float
    sigma_zdADK: float
    sigma_ADK: float
    tau_ADK: float
    S: float            # S_Dauer
    S_static: float     # S_Verform


def rate(notch: Notch, mat: Material, d: float, s: Stresses, Rz: float, K_V: float = 1.0,
         hard_surface: bool = False, hollow: bool = False, load_case: int = 2) -> Rating:
    """Safety against fatigue and against permanent deformation of a section of diameter d
    [mm] with the notch ``notch`` ([DIN743-1]; factors [DIN743-2]; material [DIN743-3])."""
    st = mat.steel
    K2 = P2.K_2(d)
    if notch.roughness and notch.Rz_B is not None:
        KFs, KFt = P2.K_F_relative(Rz, mat.sigma_B_d, notch.Rz_B)
    elif notch.roughness:
        KFs, KFt = P2.K_F(Rz, mat.sigma_B_d)
    else:
        KFs = KFt = 1.0
    K_zd = P1.K_sigma(notch.beta_zd, 1.0, KFs, K_V)
    K_b = P1.K_sigma(notch.beta_b, K2, KFs, K_V)
    K_t = P1.K_sigma(notch.beta_t, K2, KFt, K_V)
    W_zd, W_b, W_t = P3.endurance_limits(st.sigma_B)
    zdWK = P1.fatigue_limit(W_zd, mat.K_1B, K_zd)
    bWK = P1.fatigue_limit(W_b, mat.K_1B, K_b)
    tWK = P1.fatigue_limit(W_t, mat.K_1B, K_t)
    psi_zd = P1.mean_stress_sensitivity(zdWK, mat.K_1B, st.sigma_B)
    psi_b = P1.mean_stress_sensitivity(bWK, mat.K_1B, st.sigma_B)
    psi_t = P1.mean_stress_sensitivity(tWK, mat.K_1B, st.sigma_B)
    g_zd = P1.gamma_F(notch.alpha_zd, notch.circumferential, hard_surface)
    g_b = P1.gamma_F(notch.alpha_b, notch.circumferential, hard_surface)
    K2F_zd = P1.K_2F("tension", hard_surface, hollow)
    K2F_b = P1.K_2F("bending", hard_surface, hollow)
    K2F_t = P1.K_2F("torsion", hard_surface, hollow)
    zdFK = P1.yield_limit(mat.K_1S, K2F_zd, g_zd, st.sigma_S)
    bFK = P1.yield_limit(mat.K_1S, K2F_b, g_b, st.sigma_S)
    tFK = P1.yield_limit(mat.K_1S, K2F_t, 1.0, st.sigma_S, torsion=True)
    mv, tmv = P1.equivalent_mean(s.zdm, s.bm, s.tm)
    zdADK = P1.amplitude_strength(load_case, mv, s.zda, zdFK, zdWK, psi_zd)
    bADK = P1.amplitude_strength(load_case, mv, s.ba, bFK, bWK, psi_b)
    tADK = P1.amplitude_strength(load_case, tmv, s.ta, tFK, tWK, psi_t)
    S = P1.safety(s.zda, s.ba, s.ta, zdADK, bADK, tADK)
    S_static = P1.safety(s.zdmax, s.bmax, s.tmax, zdFK, bFK, tFK)
    return Rating(notch, K2, KFs, KFt, K_zd, K_b, K_t, zdWK, bWK, tWK, psi_zd, psi_b, psi_t,
                  mv, tmv, g_b, g_zd, K2F_b, K2F_t, zdFK, bFK, tFK, zdADK, bADK, tADK, S,
                  S_static)
