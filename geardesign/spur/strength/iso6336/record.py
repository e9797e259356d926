"""The ISO 6336 rating record: :class:`IsoRating`, frozen, made of frozen section records
(materials, load factors, pitting, bending, static; scuffing in :mod:`.scuffing`, the load
spectrum in :mod:`.spectrum`), declared here as the GOST 21354 record is: each reported
value a field carrying its report metadata (unit, symbol, name, source clause,
:func:`geardesign.spur.strength.common.q`), a per-gear value a (pinion, wheel) pair.  The
report rows come from that metadata through the one
:func:`geardesign.spur.strength.common.rows` of both methods; the values by key through
:func:`geardesign.spur.strength.common.values`.

Which values a rating holds depends on its inputs (an optional field is ``None``: no row),
and several names read the inputs (ν40, R_z, the resonance range): those inputs are fields
of the section without metadata (the names' context).  A field the designer gave under
``[iso_factors]`` (or a deviation given under ``[iso]``) is listed in
:attr:`IsoRating.given`: its row reads "(given)" with the source "spec".
"""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.spur.strength.common import Record, opt, q

S1, S2, S3 = "[ISO6336-1]", "[ISO6336-2]", "[ISO6336-3]"
S5, S6, S1328 = "[ISO6336-5]", "[ISO6336-6]", "[ISO1328-1]"
S21 = "[ISO6336-21]"

SECTIONS = {"iso6336_materials": "ISO 6336: materials", "iso6336_factors": "ISO 6336: load factors",
            "iso6336_contact": "ISO 6336: pitting", "iso6336_bending": "ISO 6336: tooth bending",
            "iso6336_static": "ISO 6336: static (peak torque)",
            "iso6336_scuffing": "ISO/TS 6336-21: scuffing (integral temperature)",
            "iso6336_spectrum": "ISO 6336: load spectrum (Miner)"}
"""Report sections of an ISO 6336 rating (key → title), in report order."""


def _g(unit, symbol, name, source, group: str | None = None, **kw):
    """A per-gear reported field (a (pinion, wheel) pair, keys ``…1``, ``…2``)."""
    return q(unit, symbol, name, source, gear=True, group=group, **kw)


def _hardness_name(c) -> str:
    return ("surface hardness on the line's scale"
            + (" (clamped to its range)" if c["clamped"] else "") + f", {c['who']}")


@dataclass(frozen=True, kw_only=True)
class Materials(Record):
    """ISO 6336-5 material data per gear ([ISO6336-5] §5, the lines of Figures 1…16) and
    the load cycles of the required life N_L = 60·n·c·L_h ([ISO6336-2] §10)."""

    SECTION = "iso6336_materials"
    mat_src: tuple = ("spec", "spec")
    type_how: tuple = ("", "")
    clamped: tuple = (False, False)
    scale: tuple = ("HB", "HB")
    srcH: tuple = (S5, S5)
    srcF: tuple = (S5, S5)
    material: tuple = _g(None, "mat{k}", "material, {who}", "{mat_src}", "M")
    material_source: tuple = _g(None, "src{k}", "data used, {who}", "{mat_src}", "M",
                                key="material{k}_source")
    type: tuple = _g(None, "type{k}", "material type, {who}{type_how}", S5, "M")
    quality: tuple = _g(None, "grade{k}", "material quality grade, {who}", S5, "M")
    hardness: tuple = _g("{scale}", "H{k}", _hardness_name, S5, "M")
    sigma_Hlim: tuple = _g("MPa", "σ_Hlim{k}", "endurance limit for contact, {who}", "{srcH}",
                           "M")
    sigma_Flim: tuple = _g("MPa", "σ_Flim{k}", "endurance limit for bending (σ_FE = "
                           "Y_ST·σ_Flim), {who}", "{srcF}", "M")
    N_L: tuple = _g("-", "N_L{k}", "load cycles in the required life, {who}", S2)


def _given_name(computed: str, given: str, flag: str):
    """A name that reads ``given`` when the input ``flag`` is given (the row then adds
    "(given)"), else ``computed``."""
    return lambda c: given if c[flag] else computed


@dataclass(frozen=True, kw_only=True)
class Factors(Record):
    """Load factors ([ISO6336-1]): forces, flank deviations ([ISO1328-1]), mesh stiffness
    (§9), running-in (§8.3), dynamic factor K_v (method B, §6.5), face load factors K_Hβ
    (method C, §7.6) and K_Fβ (§7.7), transverse load factors K_Hα, K_Fα (§8.3) with the
    contact ratio factor Z_ε of their limit ([ISO6336-2] §6.3; reported under pitting)."""

    SECTION = "iso6336_factors"
    tol_src: str = S1328
    internal: bool = False
    shared: str = ""
    C_a_given: bool = False
    f_sh_given: bool = False
    f_ma_given: bool = False
    modification: str = "none"
    b_h: float = 0.0
    F_t: float = q("N", "F_t", "nominal tangential force at the reference circle", S1)
    v_t: float = q("m/s", "v", "circumferential velocity at the reference circle", S1,
                   key="v")
    K_A: float = q("-", "K_A", "application factor", "spec")
    K_gamma: float | None = opt("-", "K_γ", "mesh load factor (load sharing)", S1)
    w: float = q("N/mm", "K_A F_t/b", "line load", S1)
    grade: float = q("-", "A", "flank tolerance class", S1328)
    tolerance_standard: str = q(None, "", "edition of ISO 1328-1 of the flank tolerances",
                                "spec")
    f_pb: float = q("µm", "f_pb", "transverse base pitch deviation (larger of the pair, "
                    "f_pT·cos α_t)", "{tol_src}")
    f_falpha: float = q("µm", "f_fα", "profile form deviation (larger of the pair)",
                        "{tol_src}")
    F_beta: float = q("µm", "F_β", "total helix deviation (larger of the pair)", "{tol_src}")
    tolerance_range: tuple = _g(None, "", "ISO 1328-1 tolerances outside the edition's range, "
                                "{who}", "{tol_src}", default=(None, None))
    z_n1: float = q("-", "z_n1", "virtual number of teeth z/(cos²β_b cos β), pinion", S1)
    z_n2: float = q("-", "z_n2", lambda c: "virtual number of teeth z/(cos²β_b cos β), wheel"
                    + (" (internal gear: negative; infinite in c'_th)" if c["internal"]
                       else ""), S1)
    c_th: float = q("N/(mm·µm)", "c'_th", "theoretical single stiffness (gear with fewer "
                    "teeth as the pinion)", S1)
    C_B: float = q("-", "C_B", "basic rack factor", S1)
    C_R: float = q("-", "C_R", "gear blank factor", S1)
    C_M: float = q("-", "C_M", "correction factor of the single stiffness", S1)
    c_prime: float = q("N/(mm·µm)", "c'", "single stiffness", S1)
    c_gamma_alpha: float = q("N/(mm·µm)", "c_γα", "mesh stiffness (K_v, K_Hα)", S1)
    c_gamma_beta: float = q("N/(mm·µm)", "c_γβ", "mesh stiffness (K_Hβ)", S1)
    y_alpha: float = q("µm", "y_α", "running-in allowance of f_pb", S1)
    y_f: float = q("µm", "y_f", "running-in allowance of f_fα", S1)
    C_a: float = q("µm", _given_name("C_ay", "C_a", "C_a_given"),
                   _given_name("tip relief from running-in (no tip relief given)",
                               "tip relief", "C_a_given"), S1)
    m_red: float = q("kg/mm", "m_red", lambda c: "reduced mass per face width"
                     + (" (internal gear rigid)" if c["internal"] else "") + c["shared"], S1)
    n_E1: float = q("min^-1", "n_E1", "resonance speed of the pinion", S1)
    N: float = q("-", "N", "resonance ratio n1/n_E1", S1)
    N_S: float = q("-", "N_S", "lower limit of the main resonance range", S1)
    K_v_range: str = q(None, "range", "resonance range of K_v", S1)
    K_v: float = q("-", "K_v", "dynamic factor (method B)", S1)
    f_sh: float = q("µm", "f_sh", _given_name("misalignment from the pinion shaft deflection",
                                              "misalignment from shaft deflection",
                                              "f_sh_given"), S1)
    f_Hbeta: float = q("µm", "f_Hβ", "helix slope deviation (larger of the pair)", "{tol_src}")
    f_ma: float = q("µm", "f_ma", _given_name("mesh misalignment from manufacturing (= f_Hβ, "
                                              "no adjustment)",
                                              "mesh misalignment from manufacturing",
                                              "f_ma_given"), S1)
    F_betax: float = q("µm", "F_βx", "initial equivalent misalignment (helix: {modification})",
                       S1)
    y_beta: float = q("µm", "y_β", "running-in allowance of F_βx", S1)
    F_betay: float = q("µm", "F_βy", "effective equivalent misalignment", S1)
    K_Hbeta: float = q("-", "K_Hβ", "face load factor, contact (method C)", S1)
    N_F: float = q("-", "N_F", "exponent of K_Fβ (b/h = {b_h:.3f}, at least 3)", S1)
    K_Fbeta: float = q("-", "K_Fβ", "face load factor, bending", S1)
    Z_eps: float = q("-", "Z_ε", "contact ratio factor", S2, section="iso6336_contact")
    K_Halpha_max: float = q("-", "K_Hα,max", "upper limit of K_Hα: ε_γ/(ε_α Z_ε²)", S1)
    K_Falpha_max: float = q("-", "K_Fα,max", "upper limit of K_Fα: ε_γ/(0.25ε_α + 0.75)", S1)
    K_Halpha: float = q("-", "K_Hα", "transverse load factor, contact", S1)
    K_Falpha: float = q("-", "K_Fα", "transverse load factor, bending", S1)


@dataclass(frozen=True, kw_only=True)
class Contact(Record):
    """Pitting ([ISO6336-2]): the contact stress σ_H (§5, eq. 1–4), its factors, the pitting
    stress limit σ_HG = σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X (§5, eq. 5) and S_H = σ_HG/σ_H."""

    SECTION = "iso6336_contact"
    internal: bool = False
    nu40: float = 220.0
    Rz_given: tuple = (False, False)
    S_Hmin_src: str = "spec default"
    N_ref: tuple = (0.0, 0.0)
    soft_vs_hard: tuple = (False, False)
    Z_H: float = q("-", "Z_H", "zone factor", S2)
    Z_E: float = q("MPa^0.5", "Z_E", "elasticity factor", S2)
    Z_beta: float = q("-", "Z_β", "helix angle factor", S2)
    M1: float = q("-", "M1", "auxiliary of Z_B", S2)
    M2: float | None = opt("-", "M2", "auxiliary of Z_D", S2)
    Z_B: float = q("-", "Z_B", "single pair tooth contact factor, pinion", S2)
    Z_D: float = q("-", "Z_D", lambda c: "single pair tooth contact factor, wheel"
                   + (" (internal gear: 1)" if c["internal"] else ""), S2)
    sigma_H0: float = q("MPa", "σ_H0", "nominal contact stress", S2)
    sigma_H: tuple = _g("MPa", "σ_H{k}", "contact stress, {who}", S2)
    Z_L: float = q("-", "Z_L", "lubricant factor (ν40 = {nu40:g} mm²/s)", S2)
    Z_v: float = q("-", "Z_v", "velocity factor", S2)
    rho_red: float = q("mm", "ρ_red", "relative radius of curvature at the pitch point", S2)
    Rz_flank: tuple = _g("µm", "R_zH{k}", lambda c: "flank roughness"
                         + ("" if c["Rz_given"] else " (6·Ra)") + f", {c['who']}",
                         lambda c: "spec" if c["Rz_given"] else S2)
    Z_R: float = q("-", "Z_R", "roughness factor", S2)
    S_Hmin: float = q("-", "S_Hmin", "required safety factor, pitting", "{S_Hmin_src}")
    Z_NT: tuple = _g("-", "Z_NT{k}", "life factor, contact (reference {N_ref:.0e} cycles), "
                     "{who}", S2, "G")
    Z_W: tuple = _g("-", "Z_W{k}", lambda c: "work hardening factor"
                    + (" (through-hardened against a surface-hardened mate)"
                       if c["soft_vs_hard"] else "") + f", {c['who']}", S2, "G")
    Z_X: tuple = _g("-", "Z_X{k}", "size factor, contact, {who}", S2, "G")
    ZLvR: tuple = _g("-", "Z_LvR{k}", "Z_L·Z_v·Z_R at N_L (interpolated towards 1 at the "
                     "static point), {who}", S2, "G", default=(None, None))
    sigma_HG: tuple = _g("MPa", "σ_HG{k}", "pitting stress limit σ_Hlim Z_NT Z_L Z_v Z_R Z_W "
                         "Z_X, {who}", S2, "G")
    sigma_HP: tuple = _g("MPa", "σ_HP{k}", "permissible contact stress σ_HG/S_Hmin, {who}",
                         S2, "G")
    S_H: tuple = _g("-", "S_H{k}", "safety factor for pitting σ_HG/σ_H, {who}", S2, "G")


@dataclass(frozen=True, kw_only=True)
class Bending(Record):
    """Tooth bending ([ISO6336-3]): the tooth form by method B (§6), the root stress
    σ_F = σ_F0 K_A K_γ K_v K_Fβ K_Fα (§5, eq. 1–3), the root stress limit
    σ_FG = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X Y_M (§5, eq. 4) and S_F = σ_FG/σ_F."""

    SECTION = "iso6336_bending"
    S_Fmin_src: str = "spec default"
    form_how: tuple = ("", "")
    tangent: tuple = ("30°", "30°")
    rho_prime: tuple = (0.0, 0.0)
    Rz_root: tuple = (10.0, 10.0)
    rev: tuple = (0.0, 0.0)
    form_internal_name: str = ""
    Y_beta: float = q("-", "Y_β", "helix angle factor", S3)
    Y_DT: float = q("-", "Y_DT", "deep tooth factor", S3)
    S_Fmin: float = q("-", "S_Fmin", "required safety factor, bending", "{S_Fmin_src}")
    form_internal: tuple = _g(None, "", "{form_internal_name}", S3, "B", key="form_internal",
                              default=(None, None))
    s_Fn: tuple = _g("mm", "s_Fn{k}", "root chord at the {tangent} tangents, {who}", S3, "B")
    h_Fe: tuple = _g("mm", "h_Fe{k}", "bending moment arm, {who}", S3, "B")
    rho_F: tuple = _g("mm", "ρ_F{k}", "root fillet radius, {who}", S3, "B")
    alpha_Fen: tuple = _g("deg", "α_Fen{k}", "load direction angle at the outer single contact "
                          "point, {who}", S3, "B")
    q_s: tuple = _g("-", "q_s{k}", "notch parameter, {who}", S3, "B")
    Y_F: tuple = _g("-", "Y_F{k}", "tooth form factor{form_how}, {who}", S3, "B")
    Y_S: tuple = _g("-", "Y_S{k}", "stress correction factor, {who}", S3, "B")
    Y_B: tuple = _g("-", "Y_B{k}", "rim thickness factor, {who}", S3, "B")
    sigma_F0: tuple = _g("MPa", "σ_F0{k}", "nominal tooth root stress, {who}", S3, "B")
    sigma_F: tuple = _g("MPa", "σ_F{k}", "tooth root stress, {who}", S3, "B")
    Y_NT: tuple = _g("-", "Y_NT{k}", "life factor, bending, {who}", S3, "B")
    Y_deltarelT: tuple = _g("-", "Y_δrelT{k}", "relative notch sensitivity factor (ρ' = "
                            "{rho_prime:.4f} mm), {who}", S3, "B")
    Y_RrelT: tuple = _g("-", "Y_RrelT{k}", "relative surface factor (R_z = {Rz_root:g} µm), "
                        "{who}", S3, "B")
    Y_X: tuple = _g("-", "Y_X{k}", "size factor, bending, {who}", S3, "B")
    Y_M: tuple = _g("-", "Y_M{k}", "mean stress influence factor (T_rev/T = {rev:g}), {who}",
                    S3, "B")
    sigma_FG: tuple = _g("MPa", "σ_FG{k}", "tooth root stress limit σ_Flim Y_ST Y_NT Y_δrelT "
                         "Y_RrelT Y_X Y_M, {who}", S3, "B")
    sigma_FP: tuple = _g("MPa", "σ_FP{k}", "permissible tooth root stress σ_FG/S_Fmin, {who}",
                         S3, "B")
    S_F: tuple = _g("-", "S_F{k}", "safety factor for bending σ_FG/σ_F, {who}", S3, "B")


@dataclass(frozen=True, kw_only=True)
class Static(Record):
    """Static strength at the peak torque ([ISO6336-2] and [ISO6336-3], the life factors
    at the static point of their S-N curves)."""

    SECTION = "iso6336_static"
    ZNT_st: tuple = (1.0, 1.0)
    YNT_st: tuple = (1.0, 1.0)
    T_peak: float = q("N·m", "T_max", "peak pinion torque (an actual torque: K_A = 1; the "
                      "other load factors as at the nominal torque)", "spec")
    sigma_Hst: tuple = _g("MPa", "σ_H,st{k}", "contact stress at the peak torque, {who}", S2,
                          "H")
    sigma_HGst: tuple = _g("MPa", "σ_HG,st{k}", "static pitting limit σ_Hlim·Z_NT,st (Z_NT,st "
                           "= {ZNT_st:g}; Z_L Z_v Z_R Z_X = 1), {who}", S2, "H")
    S_Hst: tuple = _g("-", "S_H,st{k}", "static safety factor, pitting, {who}", S2, "H")
    sigma_Fst: tuple = _g("MPa", "σ_F,st{k}", "root stress at the peak torque, {who}", S3, "F")
    Y_deltarelTst: tuple = _g("-", "Y_δrelT,st{k}", "relative notch sensitivity factor, "
                              "static, {who}", S3, "F")
    sigma_FGst: tuple = _g("MPa", "σ_FG,st{k}", "static root stress limit σ_Flim·Y_ST·Y_NT,st·"
                           "Y_δrelT,st (Y_NT,st = {YNT_st:g}; Y_RrelT = Y_X = 1), {who}", S3, "F")
    S_Fst: tuple = _g("-", "S_F,st{k}", "static safety factor, bending, {who}", S3, "F")


@dataclass(frozen=True, kw_only=True)
class IsoRating(Record):
    """An ISO 6336:2019 rating: one frozen section record per report section (``None``
    when the rating has none: scuffing without its inputs, static without a peak torque,
    spectrum without load blocks); ``given``: the keys of the values the designer gave.
    :attr:`v` its values by key, :attr:`rows` its rows."""

    method = "ISO 6336:2019"
    materials: Materials
    factors: Factors
    contact: Contact
    bending: Bending
    scuffing: object = None
    static: Static | None = None
    spectrum: object = None
    given: frozenset = frozenset()
