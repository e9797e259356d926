"""The GOST 21354-87 rating record: :class:`GostRating`, frozen, one frozen section record
per part (forces, life, load factors, contact, bending, peak load), each reported value a
field with its report metadata (unit, symbol, name, source:
:func:`geardesign.spur.strength.common.q`), a per-gear value a (pinion, wheel) pair.
:func:`.rating.rate` fills it; :func:`geardesign.spur.strength.common.rows` reports it.
"""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.spur.strength.common import Record, opt, q

SRC = "GOST 21354-87"
SRC_TABLE = "GOST 21354-87 (table)"
SRC_ZPCIL = "GOST 21354-87 (ZPCIL)"
SRC_CHART = "GOST 21354-87 chart (ZPCIL fit)"
POPOV = "Popov et al. 2017"


# ----------------------------------------------------------------------------- records


@dataclass(frozen=True, kw_only=True)
class Forces(Record):
    """Torques and mesh forces ([GOST21354] §2; the statics of [ISO6336-1] §5.1)."""

    SECTION = "forces"
    T1: float = q("N·m", "T1", "pinion torque (nominal)", "spec")
    T2: float = q("N·m", "T2", "wheel torque (no mesh loss)", SRC)
    F_t: float = q("N", "F_t", "tangential force at d_w1", "[GOST21354]")
    F_r: float = q("N", "F_r", "radial force", "[GOST21354]")
    F_a: float = q("N", "F_a", "axial force", "[GOST21354]")
    F_n: float = q("N", "F_n", "normal force", "[GOST21354]")
    beta_w: float = q("deg", "β_w", "helix angle at d_w", "[GOST21354]")
    M_a1: float = q("N·m", "M_a1", "moment of F_a on the pinion shaft (F_a·d_w1/2)", "statics")
    M_a2: float = q("N·m", "M_a2", "moment of F_a on the wheel shaft (F_a·d_w2/2)", "statics")
    F_tH: float = q("N", "F_tH", "tangential force at d1 (for σ_H, σ_F)", SRC_ZPCIL)
    v_H: float = q("m/s", "v", "circumferential velocity at d1 (for K_v, Z_v)", SRC_ZPCIL)


@dataclass(frozen=True, kw_only=True)
class LifeCycles(Record):
    """Load cycles and equivalent cycles per gear (by a regime or a spectrum)."""

    SECTION = "life"
    regime: str | None = None
    q_F: tuple[int, int] = (6, 6)
    how: str = ""
    mu_H: float | None = opt("-", "μ_H", "equivalence factor, contact, regime {regime}",
                             SRC_TABLE)
    mu_F: tuple | None = opt("-", "μ_F{k}", "equivalence factor, bending (q_F = {q_F}), "
                             "regime {regime}", SRC_TABLE, gear=True)
    damage_sum: str | None = opt(None, "Σ", "variant of the equivalent-cycle sum", SRC)
    N_K: tuple = q("-", "N_K{k}", "load cycles in the required life, {who}", SRC, gear=True)
    N_HE: tuple = q("-", "N_HE{k}", "equivalent contact cycles ({how}), {who}", SRC,
                    gear=True, group="E")
    N_FE: tuple = q("-", "N_FE{k}", "equivalent bending cycles ({how}, q_F = {q_F}), {who}",
                    SRC, gear=True, group="E")


def _k_hbeta_name(c) -> str:
    return "face load factor, contact" + (
        " (after running-in: softer gear ≤ 350 HB)" if c["soft_pair"]
        else " (no running-in: both gears > 350 HB)")


def _k_alpha_name(which: str):
    return lambda c: f"transverse load factor, {which}" + ("" if c["helical"] else
                                                          " (spur: 1)")


def _k_alpha_source(c) -> str:
    return SRC_ZPCIL if c["helical"] else SRC


@dataclass(frozen=True, kw_only=True)
class Factors(Record):
    """Load factors: application, dynamic, face and transverse load factors."""

    SECTION = "factors"
    helical: object = False
    soft_pair: bool = False
    form: str | None = None
    grade: int = 8
    scheme: int = 5
    b_h: float = 0.0
    K_A: float = q("-", "K_A", "application factor", "spec")
    w_Hv: float = q("N/mm", "w_Hv", "specific dynamic force, contact", SRC_TABLE)
    delta_H: float = q("-", "δ_H", "tooth form/hardness factor of w_Hv ({form})", SRC_TABLE)
    delta_F: float = q("-", "δ_F", "tooth form factor of w_Fv ({form})", SRC_TABLE)
    g_0: float = q("-", "g_0", "pitch deviation factor (grade {grade})", SRC_TABLE)
    w_max: float = q("N/mm", "w_max", "upper limit of w_v (grade {grade})", SRC_TABLE)
    w_Fv: float = q("N/mm", "w_Fv", "specific dynamic force, bending", SRC_TABLE)
    K_v_variant: str = q(None, "K_v", "variant of K_v = 1 + w_v·b_w/(F_t·K_A)", SRC,
                         default="F_t/b_w as computed (no 150 N/mm floor)")
    K_Hv: float = q("-", "K_Hv", "dynamic factor, contact", SRC)
    K_Fv: float = q("-", "K_Fv", "dynamic factor, bending", SRC)
    psi_bd: float = q("-", "ψ_bd", "face width ratio b_w/d1 (read in the K_Hβ chart)", SRC)
    K0_Hbeta: float = q("-", "K⁰_Hβ", "face load factor before running-in (scheme {scheme})",
                        SRC_CHART)
    K_Hbeta: float = q("-", "K_Hβ", _k_hbeta_name, SRC_CHART)
    K_Hw: float | None = opt("-", "K_Hw", "running-in factor (K_Hβ − 1)/(K⁰_Hβ − 1)", SRC)
    N_F: float = q("-", "N_F", "exponent of K_Fβ = (K⁰_Hβ)^N_F (b/h = {b_h:.3f})", SRC_ZPCIL)
    K_Fbeta: float = q("-", "K_Fβ", "face load factor, bending (K⁰_Hβ^N_F, before running-in)",
                       SRC_ZPCIL)
    c_gamma: float | None = opt("N/(mm·µm)", "c_γ", "mesh stiffness", SRC_ZPCIL)
    f_pb: float | None = opt("µm", "f_pb", "equivalent base pitch deviation",
                             "GOST 1643-81 (ZPCIL fit)")
    K_Halpha_max: float | None = opt("-", "K_Hα,max", "upper limit of K_Hα (the factor is "
                                     "never below 1)", SRC_ZPCIL)
    K_Falpha_max: float | None = opt("-", "K_Fα,max", "upper limit of K_Fα = 1/Y_ε "
                                     "(K_Fα·Y_ε ≤ 1)", SRC)
    K_Halpha: float = q("-", "K_Hα", _k_alpha_name("contact"), _k_alpha_source)
    K_Falpha: float = q("-", "K_Fα", _k_alpha_name("bending"), _k_alpha_source)
    K_Halpha_capped: bool | None = opt(None, "K_Hα at cap", "K_Hα limited by its upper limit",
                                       SRC)
    K_Falpha_capped: bool | None = opt(None, "K_Fα at cap", "K_Fα limited by its upper limit",
                                       SRC)
    K_H: float = q("-", "K_H", "load factor, contact K_A·K_Hv·K_Hβ·K_Hα", SRC)
    K_F: float = q("-", "K_F", "load factor, bending K_A·K_Fv·K_Fβ·K_Fα", SRC)


def _z_nmax_name(c) -> str:
    kind = "hardened surface" if c["Z_N_max_material"] < 2.6 else "homogeneous structure"
    return f"upper limit of Z_N ({kind}), {c['who']}"


@dataclass(frozen=True, kw_only=True)
class Contact(Record):
    """Contact fatigue: stress, allowables and safety factors per gear."""

    SECTION = "contact"
    internal: bool = False
    pair_rule: object = False
    Ra: tuple[float, float] = (1.25, 1.25)
    Z_N_max_material: tuple[float, float] = (2.6, 2.6)
    Z_E: float = q("MPa^0.5", "Z_E", "elasticity factor", SRC)
    Z_H: float = q("-", "Z_H", "zone factor", SRC)
    Z_eps: float = q("-", "Z_ε", "contact ratio factor", SRC)
    sigma_H: float = q("MPa", "σ_H", lambda c: "contact stress" + (
        " (internal pair, u − 1)" if c["internal"] else ""), SRC)
    rho_w: float | None = opt("mm", "ρ_w", "reduced radius of curvature at the pitch point",
                              "Hertz")
    sigma_H_n07: float | None = opt("MPa", "σ_H(n=0.7)", "contact stress with the n = 0.7 "
                                    "deformation law (informative)", POPOV + " (9)")
    crowning_alpha: float | None = opt("-", "α", "contact ellipse axis ratio b0/b_K", POPOV)
    b_K: float | None = opt("mm", "b_K", "half-length of the contact ellipse (must stay below "
                            "b_w/2)", POPOV + " (20)")
    sigma_max_crowned: float | None = opt("MPa", "σ_max", "contact stress of the crowned "
                                          "flank, n = 0.7 (informative)", POPOV + " (21)")
    sigma_Hlim: tuple = q("MPa", "σ_Hlim{k}", "contact endurance limit, {who}", "material",
                          gear=True, group="G")
    S_H_min: tuple = q("-", "S_Hmin{k}", "required contact safety factor, {who}", SRC_TABLE,
                       key="S_H{k}_min", gear=True, group="G")
    N_HG: tuple = q("-", "N_HG{k}", "base number of contact cycles, {who}", SRC, gear=True,
                    group="G")
    Z_Nmax: tuple = q("-", "Z_Nmax{k}", _z_nmax_name, SRC, gear=True, group="G")
    q_H: tuple = q("-", "q_H{k}", "exponent of the contact fatigue curve in use, {who}", SRC,
                   gear=True, group="G")
    Z_N: tuple = q("-", "Z_N{k}", "life factor, contact, {who}", SRC, gear=True, group="G")
    Z_R: tuple = q("-", "Z_R{k}", "roughness factor (Ra = {Ra:g} µm), {who}", SRC_TABLE,
                   gear=True, group="G")
    Z_v: tuple = q("-", "Z_v{k}", "velocity factor, {who}", SRC, gear=True, group="G")
    Z_X: tuple = q("-", "Z_X{k}", "size factor, contact, {who}", SRC, gear=True, group="G")
    sigma_HP_gear: tuple = q("MPa", "σ_HP{k}", "allowable contact stress, {who}", SRC,
                             key="sigma_HP{k}", gear=True, group="G")
    S_H: tuple = q("-", "S_H{k}", "contact safety factor σ_Hlim·Z_N·Z_R·Z_v·Z_X/σ_H, {who}",
                   SRC, gear=True, group="G")
    sigma_HP: float = q("MPa", "σ_HP", lambda c: "allowable contact stress of the pair" + (
        " 0.45(σ_HP1 + σ_HP2), ≤ 1.25σ_HPmin" if c["pair_rule"] else " (the smaller)"), SRC)


def _y_fs_name(c) -> str:
    if c["internal"] and c["k"] == 2:
        return "tooth form factor, internal gear (rack limit, approximate)"
    return f"tooth form factor, {c['who']}"


@dataclass(frozen=True, kw_only=True)
class Bending(Record):
    """Bending fatigue: root stress, allowables and safety factors per gear."""

    SECTION = "bending"
    internal: bool = False
    q_F_: tuple[int, int] = (6, 6)
    Y_beta: float = q("-", "Y_β", "helix factor", SRC)
    Y_eps: float = q("-", "Y_ε", "contact ratio factor, bending", SRC)
    Y_delta: float = q("-", "Y_δ", "notch sensitivity factor", SRC)
    N_FG: float = q("-", "N_FG", "base number of bending cycles (Y_N = 1 beyond it: the "
                    "standard's variant)", SRC)
    Y_R: float = q("-", "Y_R", "root surface factor", SRC)
    z_v: tuple = q("-", "z_v{k}", "virtual number of teeth z/cos³β, {who}", SRC, gear=True,
                   group="G")
    Y_FS: tuple = q("-", "Y_FS{k}", _y_fs_name, lambda c: SRC + (
        " (rack limit)" if c["internal"] and c["k"] == 2 else ""), gear=True, group="G")
    sigma_F: tuple = q("MPa", "σ_F{k}", "root bending stress, {who}", SRC, gear=True,
                       group="G")
    sigma_Flim: tuple = q("MPa", "σ_Flim{k}", "bending endurance limit, {who}", "material",
                          gear=True, group="G")
    S_F_min: tuple = q("-", "S_Fmin{k}", "required bending safety factor, {who}", SRC_TABLE,
                       key="S_F{k}_min", gear=True, group="G")
    q_F: tuple = q("-", "q_F{k}", "exponent of the bending fatigue curve, {who}", SRC,
                   gear=True, group="G")
    Y_N: tuple = q("-", "Y_N{k}", "life factor, bending (q_F = {q_F_}), {who}", SRC, gear=True,
                   group="G")
    Y_X: tuple = q("-", "Y_X{k}", "size factor, bending, {who}", SRC, gear=True, group="G")
    Y_A: tuple = q("-", "Y_A{k}", "reversed-load factor, {who}", SRC, gear=True, group="G")
    sigma_FP: tuple = q("MPa", "σ_FP{k}", "allowable bending stress, {who}", SRC, gear=True,
                        group="G")
    S_F: tuple = q("-", "S_F{k}", "bending safety factor σ_Flim·Y_N·Y_δ·Y_R·Y_X·Y_A/σ_F, {who}",
                   SRC, gear=True, group="G")


@dataclass(frozen=True, kw_only=True)
class Static(Record):
    """Peak (static) load: stresses at the peak torque and their limits."""

    SECTION = "static"
    T_peak: float = q("N·m", "T_max", "peak pinion torque (an actual torque: K_A does not "
                      "enter the peak stresses)", "spec")
    K_Hmax: float = q("-", "K_Hmax", "load factor at the peak torque, contact (K_v = 1, no "
                      "K_A)", SRC_ZPCIL)
    K_Fmax: float = q("-", "K_Fmax", "load factor at the peak torque, bending (K_v = 1, no "
                      "K_A)", SRC_ZPCIL)
    S_FSt: float = q("-", "S_FSt", "safety factor against the static bending limit", SRC)
    sigma_Hmax: float = q("MPa", "σ_Hmax", "contact stress at the peak torque", SRC_ZPCIL)
    sigma_HPmax: tuple = q("MPa", "σ_HPmax{k}", "allowable peak contact stress, {who}",
                           SRC_TABLE, gear=True)
    sigma_Fmax: tuple = q("MPa", "σ_Fmax{k}", "bending stress at the peak torque, {who}",
                          SRC_ZPCIL, gear=True, group="G")
    Y_z: tuple = q("-", "Y_z{k}", "blank factor (forging 1, rolled 0.9, casting 0.8), {who}",
                   SRC, gear=True, group="G")
    sigma_FPmax: tuple = q("MPa", "σ_FPmax{k}", "allowable peak bending stress, {who}", SRC,
                           gear=True, group="G")


@dataclass(frozen=True, kw_only=True)
class GostRating(Record):
    """A GOST 21354-87 rating: the section records, the keys of the factors the designer
    gave (``given``) and of the material values taken from the spec (``from_spec``), and
    the pair's materials (pinion, wheel) that its checks judge (hardness ranges and
    difference)."""

    method = "GOST 21354-87"
    forces: Forces
    life: LifeCycles
    factors: Factors
    contact: Contact
    bending: Bending
    static: Static | None = None
    given: frozenset = frozenset()
    from_spec: frozenset = frozenset()
    materials: tuple = ()
