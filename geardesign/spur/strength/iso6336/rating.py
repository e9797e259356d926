"""Rating of a gear pair to ISO 6336:2019 method B: every factor, stress, permissible stress
and safety factor, from the part modules or from ``[iso_factors]`` where the designer gives
it; the checks that judge the result.

:func:`rate` has the signature of the GOST rating (``rate(geometry, materials, duty,
setting)``) plus the ISO inputs :class:`IsoSetting`; without them the defaults of
:func:`default_setting` apply (a calculator that only knows the GOST inputs, e.g. the
planetary meshes, still gets an ISO rating).  It returns the frozen record
:class:`~geardesign.spur.strength.iso6336.record.IsoRating`, whose rows (the sections
``iso6336_*``, so that both methods' results stay apart in one report) come from its fields'
metadata through :func:`geardesign.spur.strength.common.rows`.  The load factors, pitting
and bending are written with :mod:`geardesign.core.xp`: the calculator rates one pair with
numbers, the sweep kernel (:mod:`geardesign.spur.kernel`) a chunk of external candidates
with numpy arrays through the same function (scuffing, the peak torque and a spectrum: one
pair only).
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core import xp
from geardesign.core.records import dataclass
from geardesign.core.result import Check, check
from geardesign.spur.strength.iso6336 import part1 as P1
from geardesign.spur.strength.iso6336 import part2 as P2
from geardesign.spur.strength.iso6336 import part3 as P3
from geardesign.spur.strength.iso6336 import part5 as P5
from geardesign.spur.strength.iso6336 import part21 as P21
from geardesign.spur.strength.iso6336 import tables as T
from geardesign.spur.strength.iso6336.record import SECTIONS, IsoRating, Writer  # noqa: F401
from geardesign.spur.strength.verdict import verdict
from geardesign.spur.tolerances import iso1328

NAME = "ISO 6336:2019"
S1, S2, S3 = "[ISO6336-1]", "[ISO6336-2]", "[ISO6336-3]"
S5, S6, S1328 = "[ISO6336-5]", "[ISO6336-6]", "[ISO1328-1]"
S21 = "[ISO6336-21]"
WHO = ("pinion", "wheel")

Z_BIG = 100000
"""Teeth of the rack that stands in for an internal gear in the form-factor calculation."""


@dataclass(frozen=True)
class IsoGear:
    """ISO inputs of one gear."""

    material: str | None = None       # ISO 6336-5 type; None: from the heat treatment
    quality: str = "MQ"
    sigma_Hlim: float | None = None
    sigma_Flim: float | None = None
    Rz_flank: float | None = None     # µm; None: 6·Ra of the flank
    Rz_root: float = 10.0             # µm
    inner_diameter: float = 0.0       # bore of the gear body, mm
    rim_thickness: float | None = None  # s_R below the root, mm; None: solid
    web_ratio: float | None = None    # b_s/b of a web gear; None: solid


@dataclass(frozen=True)
class ScuffingSetting:
    """Oil and lubrication of the scuffing rating (ISO/TS 6336-21)."""

    fzg_load_stage: int                # FZG A/8.3/90 failure load stage of the oil, 1..14
    oil_temperature: float             # °C, before the mesh (sump or injection)
    nu100: float | None = None         # mm²/s; None: from ν40 with VI 95
    density15: float = 890.0           # kg/m³
    lubricant: str = "mineral"         # key of tables.SCUFFING_X_L
    lubrication: str = "dip"           # key of tables.SCUFFING_X_S
    meshes: int = 1                    # gears the pinion meshes with (X_mp)
    driving: str = "pinion"
    structure: str | None = None       # key of tables.SCUFFING_X_WRELT; None: from the types
    B_M: float = T.B_M_STEEL           # N/(mm·s^½·K)
    S_Smin: float = 1.8


@dataclass(frozen=True)
class IsoSetting:
    """ISO 6336 inputs of a pair beyond the GOST setting."""

    grade: int | None = None           # ISO 1328-1 flank tolerance class; None: the spec's grade
    tolerance_standard: str = iso1328.STANDARD   # edition of ISO 1328-1 of the tolerances
    nu40: float = 220.0                # mm²/s
    C_a: float | None = None           # tip relief, µm; None: C_ay from running-in
    modification: str = "none"
    f_ma: float | None = None          # µm
    f_sh: float | None = None          # µm
    K_prime: float = 0.0
    shaft_span: float | None = None
    pinion_offset: float = 0.0
    shaft_diameter: float | None = None
    f_pb: float | None = None          # µm
    f_falpha: float | None = None      # µm
    F_beta: float | None = None        # µm
    S_Hmin: float = 1.0
    S_Fmin: float = 1.4
    limited_pitting: bool = False
    optimum: bool = False
    protuberance: float = 0.0          # s_pr/m_n
    K_gamma: float = 1.0
    # meshes of this kind each gear carries, for the reduced mass: (n_P, 1) for a sun that is
    # gear 1 of a sun–planet mesh with n_P planets ([ISO6336-1] 6.5.9, planetary gears)
    meshes: tuple[int, int] = (1, 1)
    gears: tuple[IsoGear, IsoGear] = (IsoGear(), IsoGear())
    scuffing: ScuffingSetting | None = None
    overrides: dict = field(default_factory=dict)


def default_setting(setting) -> IsoSetting:
    """The ISO inputs a caller that has only the GOST setting gets: its accuracy grade,
    every other ISO input at its default."""
    return IsoSetting(grade=setting.grade)


def _material(i: int, mat, ig: IsoGear, R: Writer) -> dict:
    """ISO material data of gear ``i`` (type, σ_Hlim, σ_Flim and their sources)."""
    k, who = i + 1, WHO[i]
    typ = ig.material or P5.type_from_treatment(mat.treatment, mat.label)
    line = P5.limits(typ, ig.quality, P5.hardness_on_scale(T.MATERIAL_LINES[typ]["scale"],
                                                            mat.HB, mat.HV))
    sec = "iso6336_materials"
    from geardesign.materials.gear_steel import data_used, iso_type

    R.put(sec, f"material{k}", mat.label, None, f"mat{k}", f"material, {who}",
          "library" if getattr(mat, "grade", None) else "spec")
    R.put(sec, f"material{k}_source", data_used(mat), None, f"src{k}", f"data used, {who}",
          "library" if getattr(mat, "grade", None) else "spec")
    how = ("" if ig.material else " (from the grade's library row)"
           if iso_type(getattr(mat, "grade", None), mat.treatment) else " (from the heat treatment)")
    R.put(sec, f"type{k}", typ, None, f"type{k}", f"material type, {who}{how}", S5)
    R.put(sec, f"quality{k}", ig.quality, None, f"grade{k}", f"material quality grade, {who}", S5)
    R.put(sec, f"hardness{k}", line.hardness, line.scale, f"H{k}",
          f"surface hardness on the line's scale{' (clamped to its range)' if line.clamped else ''}, {who}",
          S5)
    if ig.sigma_Hlim is not None:
        sH, srcH = ig.sigma_Hlim, "spec"
    elif "sigma_Hlim" in mat.given:
        sH, srcH = mat.sigma_Hlim, "spec ([material])"
    else:
        sH, srcH = line.sigma_Hlim, S5
    if ig.sigma_Flim is not None:
        sF, srcF = ig.sigma_Flim, "spec"
    else:
        sF, srcF = line.sigma_Flim, S5
    R.put(sec, f"sigma_Hlim{k}", sH, "MPa", f"σ_Hlim{k}", f"endurance limit for contact, {who}", srcH)
    R.put(sec, f"sigma_Flim{k}", sF, "MPa", f"σ_Flim{k}", f"endurance limit for bending "
          f"(σ_FE = Y_ST·σ_Flim), {who}", srcF)
    return {"type": typ, "sigma_Hlim": sH, "sigma_Flim": sF, "clamped": line.clamped,
            "range": T.MATERIAL_LINES[typ]["range"], "scale": line.scale}


def rate(g, mats, duty, setting, iso: IsoSetting | None = None) -> IsoRating:
    """Rate the pair to ISO 6336:2019 (method B; K_Hβ by method C): the frozen
    :class:`~geardesign.spur.strength.iso6336.record.IsoRating` of every value."""
    iso = iso or default_setting(setting)
    R = Writer(iso.overrides)
    p = g.inp
    internal = bool(getattr(g, "internal", False))
    helical = p.beta > 0.0
    gears = (g.g1, g.g2)
    z = (p.z1, p.z2)
    d1, b, m_n, u = g.g1.d, p.b_w, p.m_n, g.u
    a_n = p.rack.alpha_n
    A = iso.grade if iso.grade is not None else setting.grade
    F_t = 2000.0 * duty.T1 / d1
    v = math.pi * d1 * duty.n1 / 60000.0
    K_A, K_g = duty.K_A, iso.K_gamma
    F = "iso6336_factors"

    # ------------------------------------------------------------------ materials, life
    M = [_material(i, mats[i], iso.gears[i], R) for i in range(2)]
    sHlim = [m["sigma_Hlim"] for m in M]
    n = (duty.n1, duty.n1 / u)
    N_L = [60.0 * n[i] * duty.life.c[i] * duty.life.L_h for i in range(2)]
    for i in range(2):
        R.put("iso6336_materials", f"N_L{i + 1}", N_L[i], "-", f"N_L{i + 1}",
              f"load cycles in the required life, {WHO[i]}", S2)

    # ------------------------------------------------------------------ forces, accuracy
    R.put(F, "F_t", F_t, "N", "F_t", "nominal tangential force at the reference circle", S1)
    R.put(F, "v", v, "m/s", "v", "circumferential velocity at the reference circle", S1)
    R.put(F, "K_A", K_A, "-", "K_A", "application factor", "spec")
    if K_g != 1.0:
        R.put(F, "K_gamma", K_g, "-", "K_γ", "mesh load factor (load sharing)", S1)
    line_load = K_A * K_g * F_t / b
    R.put(F, "w", line_load, "N/mm", "K_A F_t/b", "line load", S1)
    R.put(F, "grade", float(A), "-", "A", "flank tolerance class", S1328)
    R.put(F, "tolerance_standard", iso.tolerance_standard, None, "",
          "edition of ISO 1328-1 of the flank tolerances", "spec")
    tol = iso1328.rating_deviations(g.g1.d, g.g2.d, m_n, b, g.alpha_t, A, iso.tolerance_standard)
    S_tol = S1328 if iso.tolerance_standard == iso1328.STANDARD else "[ISO1328-1-1995]"
    f_pb = R.put(F, "f_pb", iso.f_pb if iso.f_pb is not None else tol["f_pb"], "µm", "f_pb",
                 "transverse base pitch deviation (larger of the pair, f_pT·cos α_t)"
                 + (" (given)" if iso.f_pb is not None else ""),
                 "spec" if iso.f_pb is not None else S_tol)
    f_fa = R.put(F, "f_falpha", iso.f_falpha if iso.f_falpha is not None else tol["f_falpha"],
                 "µm", "f_fα", "profile form deviation (larger of the pair)"
                 + (" (given)" if iso.f_falpha is not None else ""),
                 "spec" if iso.f_falpha is not None else S_tol)
    R.put(F, "F_beta", iso.F_beta if iso.F_beta is not None else tol["F_beta"], "µm", "F_β",
          "total helix deviation (larger of the pair)"
          + (" (given)" if iso.F_beta is not None else ""),
          "spec" if iso.F_beta is not None else S_tol)
    f_Hb = tol["f_Hbeta"]
    for k, (gear, who) in enumerate(zip(gears, WHO), 1):
        if not xp.scalar(gear.d, m_n, b):
            break       # candidates of a sweep: the range is the re-check's warning
        outside = iso1328.outside_validity(gear.d, m_n, b, iso.tolerance_standard)
        if outside:
            R.put(F, f"tolerance_range{k}", _range_words(iso.tolerance_standard, abs(gear.d),
                                                         m_n, b, outside), None, "",
                  f"ISO 1328-1 tolerances outside the edition's range, {who}", S_tol)

    # ------------------------------------------------------------------ stiffness
    cb = xp.cos(g.beta_b)
    virtual = cb * cb * xp.cos(p.beta)
    z_n1 = p.z1 / virtual
    z_n2_signed = (-p.z2 if internal else p.z2) / virtual
    z_n2 = None if internal else z_n2_signed
    R.put(F, "z_n1", z_n1, "-", "z_n1", "virtual number of teeth z/(cos²β_b cos β), pinion", S1)
    R.put(F, "z_n2", z_n2_signed, "-", "z_n2",
          "virtual number of teeth z/(cos²β_b cos β), wheel"
          + (" (internal gear: negative; infinite in c'_th)" if internal else ""), S1)
    x2 = -p.x2 if internal else p.x2      # ISO 21771 sign for an internal gear
    # the standard's pinion is the gear with fewer teeth (a sun larger than its planet)
    if z_n2 is None:
        stiff = (z_n1, p.x1, z_n2, x2)
    else:
        swap = z_n2 < z_n1
        stiff = (xp.where(swap, z_n2, z_n1), xp.where(swap, x2, p.x1),
                 xp.where(swap, z_n1, z_n2), xp.where(swap, p.x1, x2))
    c_th = R.factor(F, "c_th", lambda: P1.theoretical_single_stiffness(*stiff[::2], *stiff[1::2]),
                    "N/(mm·µm)", "c'_th", "theoretical single stiffness (gear with fewer "
                    "teeth as the pinion)", S1)
    racks = (p.rack, getattr(p, "rack2", p.rack))
    h_fPs = [rk.h_a + rk.c for rk in racks]
    h_fP = h_fPs[0]
    C_B = R.put(F, "C_B", P1.basic_rack_factor(h_fPs[0], h_fPs[1], a_n), "-", "C_B",
                "basic rack factor", S1)
    C_R = R.put(F, "C_R", xp.minimum(*(P1.blank_factor(ig.web_ratio,
                                                       (ig.rim_thickness or m_n) / m_n)
                                      for ig in iso.gears)), "-", "C_R", "gear blank factor", S1)
    R.put(F, "C_M", P1.C_M, "-", "C_M", "correction factor of the single stiffness", S1)
    c_p = R.factor(F, "c_prime", lambda: P1.single_stiffness(c_th, C_R, C_B, p.beta, line_load),
                   "N/(mm·µm)", "c'", "single stiffness", S1)
    c_ga = R.factor(F, "c_gamma_alpha", lambda: P1.mesh_stiffness_alpha(c_p, g.eps_alpha),
                    "N/(mm·µm)", "c_γα", "mesh stiffness (K_v, K_Hα)", S1)
    c_gb = R.put(F, "c_gamma_beta", P1.mesh_stiffness_beta(c_ga), "N/(mm·µm)", "c_γβ",
                 "mesh stiffness (K_Hβ)", S1)

    # ------------------------------------------------------------------ running-in
    types = [m["type"] for m in M]
    y_a = R.put(F, "y_alpha", P1.pair_mean(*(P1.running_in_alpha(f_pb, types[i], sHlim[i], v)
                                             for i in range(2))),
                "µm", "y_α", "running-in allowance of f_pb", S1)
    y_f = R.put(F, "y_f", P1.pair_mean(*(P1.running_in_alpha(f_fa, types[i], sHlim[i], v)
                                         for i in range(2))),
                "µm", "y_f", "running-in allowance of f_fα", S1)
    if iso.C_a is not None:
        C_a = R.put(F, "C_a", iso.C_a, "µm", "C_a", "tip relief (given)", "spec")
    else:
        C_a = R.put(F, "C_a", P1.pair_mean(*(P1.tip_relief_running_in(s) for s in sHlim)),
                    "µm", "C_ay", "tip relief from running-in (no tip relief given)", S1)

    # ------------------------------------------------------------------ dynamic factor
    m1 = P1.gear_mass(g.g1.d_a, g.g1.d_f, g.g1.d_b, iso.gears[0].inner_diameter)
    m2 = None if internal else P1.gear_mass(g.g2.d_a, g.g2.d_f, g.g2.d_b,
                                            iso.gears[1].inner_diameter)
    n_m = iso.meshes
    shared = next((f" ({WHO[i]} shared by {n_m[i]} meshes: m1·m2/(n2·m1 + n1·m2))"
                   for i in range(2) if n_m[i] > 1), "")
    m_red = R.put(F, "m_red", P1.reduced_mass(m1, m2, *n_m), "kg/mm", "m_red",
                  "reduced mass per face width" + (" (internal gear rigid)" if internal else "")
                  + shared, S1)
    n_E1 = R.put(F, "n_E1", P1.resonance_speed(p.z1, c_ga, m_red), "min^-1", "n_E1",
                 "resonance speed of the pinion", S1)
    N = R.put(F, "N", duty.n1 / n_E1, "-", "N", "resonance ratio n1/n_E1", S1)
    N_S = R.put(F, "N_S", P1.lower_resonance_limit(line_load), "-", "N_S",
                "lower limit of the main resonance range", S1)
    # running-in removes at most the deviation itself (160/σ_Hlim·f_pb exceeds f_pb for
    # σ_Hlim < 160 MPa): the effective deviations are not negative
    K_v_calc, rng = P1.dynamic_factor(N, N_S, c_p, xp.maximum(f_pb - y_a, 0.0),
                                      xp.maximum(f_fa - y_f, 0.0),
                                      C_a, line_load,
                                      g.eps_gamma)
    R.put(F, "K_v_range", rng, None, "range", "resonance range of K_v", S1)
    K_v = R.factor(F, "K_v", K_v_calc, "-", "K_v", "dynamic factor (method B)", S1)

    # ------------------------------------------------------------------ face load factors
    F_m_b = F_t * K_A * K_g * K_v / b
    if iso.f_sh is not None:
        f_sh = R.put(F, "f_sh", iso.f_sh, "µm", "f_sh", "misalignment from shaft deflection "
                     "(given)", "spec")
    else:
        f_sh = R.put(F, "f_sh", P1.shaft_deflection(F_m_b, b, d1, iso.K_prime, iso.shaft_span,
                                                    iso.pinion_offset, iso.shaft_diameter),
                     "µm", "f_sh", "misalignment from the pinion shaft deflection", S1)
    R.put(F, "f_Hbeta", f_Hb, "µm", "f_Hβ", "helix slope deviation (larger of the pair)", S_tol)
    # f_ma = 1.0·f_Hβ for gears without provision for adjustment ([ISO6336-1] 7.6.2.4; the
    # same rule in DIN 3990-1 §3.4.2.4); the helix modification acts through B2
    f_ma = R.put(F, "f_ma", iso.f_ma if iso.f_ma is not None else f_Hb, "µm", "f_ma",
                 "mesh misalignment from manufacturing" + (" (given)" if iso.f_ma is not None
                                                           else " (= f_Hβ, no adjustment)"),
                 "spec" if iso.f_ma is not None else S1)
    F_bx = R.put(F, "F_betax", P1.initial_misalignment(f_sh, f_ma, iso.modification, F_m_b, f_Hb),
                 "µm", "F_βx", f"initial equivalent misalignment (helix: {iso.modification})", S1)
    y_b = R.put(F, "y_beta", P1.pair_mean(*(P1.running_in_beta(F_bx, types[i], sHlim[i], v)
                                            for i in range(2))),
                "µm", "y_β", "running-in allowance of F_βx", S1)
    F_by = R.put(F, "F_betay", F_bx - y_b, "µm", "F_βy", "effective equivalent misalignment", S1)
    K_Hb = R.factor(F, "K_Hbeta", lambda: P1.face_load_factor(F_by, c_gb, F_m_b), "-", "K_Hβ",
                    "face load factor, contact (method C)", S1)
    b_h = xp.minimum(b / g.g1.h, b / g.g2.h)
    R.put(F, "N_F", P1.n_f(b_h), "-", "N_F", f"exponent of K_Fβ (b/h = {_num(b_h, '.3f')}, at "
          "least 3)", S1)
    K_Fb = R.factor(F, "K_Fbeta", lambda: P1.face_load_factor_bending(K_Hb, b_h), "-", "K_Fβ",
                    "face load factor, bending", S1)

    # ------------------------------------------------------------------ transverse load factors
    Z_eps = R.factor("iso6336_contact", "Z_eps", lambda: P2.z_eps(g.eps_alpha, g.eps_beta, helical),
                     "-", "Z_ε", "contact ratio factor", S2)
    F_tH_b = F_t * K_A * K_g * K_v * K_Hb / b
    f_eff = xp.maximum(xp.maximum(f_pb, f_fa) - y_a, 0.0)
    K_alpha = P1.transverse_load_factor(g.eps_gamma, c_ga, f_eff, F_tH_b)
    KHa_max = R.put(F, "K_Halpha_max", P1.transverse_limit_contact(g.eps_gamma, g.eps_alpha, Z_eps),
                    "-", "K_Hα,max", "upper limit of K_Hα: ε_γ/(ε_α Z_ε²)", S1)
    KFa_max = R.put(F, "K_Falpha_max", P1.transverse_limit_bending(g.eps_gamma, g.eps_alpha),
                    "-", "K_Fα,max", "upper limit of K_Fα: ε_γ/(0.25ε_α + 0.75)", S1)
    K_Ha = R.factor(F, "K_Halpha", lambda: P1.limited(K_alpha, KHa_max)[0], "-", "K_Hα",
                    "transverse load factor, contact", S1)
    K_Fa = R.factor(F, "K_Falpha", lambda: P1.limited(K_alpha, KFa_max)[0], "-", "K_Fα",
                    "transverse load factor, bending", S1)

    # ------------------------------------------------------------------ pitting
    C = "iso6336_contact"
    Z_H = R.factor(C, "Z_H", lambda: P2.z_h(g.beta_b, g.alpha_t, g.alpha_tw), "-", "Z_H",
                   "zone factor", S2)
    m_1, m_2 = mats
    Z_E = R.factor(C, "Z_E", lambda: P2.z_e(m_1.E, m_1.nu, m_2.E, m_2.nu), "MPa^0.5", "Z_E",
                   "elasticity factor", S2)
    Z_b = R.factor(C, "Z_beta", lambda: P2.z_beta(p.beta), "-", "Z_β", "helix angle factor", S2)
    ZB, ZD, M1, M2 = P2.single_pair_factors(g.alpha_tw, (g.g1.d_a, g.g2.d_a),
                                            (g.g1.d_b, g.g2.d_b), z, g.eps_alpha, g.eps_beta,
                                            helical, internal)
    R.put(C, "M1", M1, "-", "M1", "auxiliary of Z_B", S2)
    if not internal:
        R.put(C, "M2", M2, "-", "M2", "auxiliary of Z_D", S2)
    Z_BD = [R.factor(C, "Z_B", ZB, "-", "Z_B", "single pair tooth contact factor, pinion", S2),
            R.factor(C, "Z_D", ZD, "-", "Z_D", "single pair tooth contact factor, wheel"
                     + (" (internal gear: 1)" if internal else ""), S2)]
    sH0 = R.put(C, "sigma_H0", P2.nominal_contact_stress(Z_H, Z_E, Z_eps, Z_b, F_t, d1, b, u,
                                                         internal),
                "MPa", "σ_H0", "nominal contact stress", S2)
    sH = [R.put(C, f"sigma_H{k}", P2.contact_stress(Z_BD[k - 1], sH0, K_A, K_g, K_v, K_Hb, K_Ha),
                "MPa", f"σ_H{k}", f"contact stress, {WHO[k - 1]}", S2) for k in (1, 2)]
    s_min = min(sHlim)
    Z_L = R.factor(C, "Z_L", lambda: P2.z_l(s_min, iso.nu40), "-", "Z_L",
                   f"lubricant factor (ν40 = {iso.nu40:g} mm²/s)", S2)
    Z_v = R.factor(C, "Z_v", lambda: P2.z_v(s_min, v), "-", "Z_v", "velocity factor", S2)
    Rz = [iso.gears[i].Rz_flank if iso.gears[i].Rz_flank is not None
          else 6.0 * setting.Ra[i] for i in range(2)]
    rho = P2.rho_red(g.g1.d_b, g.g2.d_b, g.alpha_tw, internal)
    R.put(C, "rho_red", rho, "mm", "ρ_red", "relative radius of curvature at the pitch point", S2)
    for i in range(2):
        R.put(C, f"Rz_flank{i + 1}", Rz[i], "µm", f"R_zH{i + 1}", "flank roughness"
              + ("" if iso.gears[i].Rz_flank is not None else " (6·Ra)") + f", {WHO[i]}",
              "spec" if iso.gears[i].Rz_flank is not None else S2)
    Z_R = R.factor(C, "Z_R", lambda: P2.z_r(s_min, Rz[0], Rz[1], rho), "-", "Z_R",
                   "roughness factor", S2)
    hard = [t in T.SURFACE_HARDENED for t in types]
    R.put(C, "S_Hmin", iso.S_Hmin, "-", "S_Hmin", "required safety factor, pitting",
          "spec" if iso.S_Hmin != 1.0 else "spec default")
    sHG = []
    for i in range(2):
        k, who = i + 1, WHO[i]
        soft_vs_hard = hard[1 - i] and not hard[i] and types[i] not in T.CAST_IRON_GREY
        ZW_ref = P2.z_w(mats[i].HB, Rz[1 - i], Rz[i], rho, v, iso.nu40) if soft_vs_hard else 1.0
        N_st, N_ref = P2.reference_cycles_contact(types[i], iso.limited_pitting)
        ZNT = R.factor(C, f"Z_NT{k}", lambda: P2.z_nt(types[i], N_L[i], iso.limited_pitting,
                                                       iso.optimum),
                       "-", f"Z_NT{k}", f"life factor, contact (reference {N_ref:.0e} cycles), {who}",
                       S2)
        infl = {}
        for key, ref, name in (("Z_L", Z_L, "lubricant"), ("Z_v", Z_v, "velocity"),
                               ("Z_R", Z_R, "roughness")):
            infl[key] = P2.interpolated(ref, N_L[i], N_st, N_ref)
        ZW = R.factor(C, f"Z_W{k}", lambda: P2.interpolated(ZW_ref, N_L[i], N_st, N_ref), "-",
                      f"Z_W{k}", "work hardening factor" + (" (through-hardened against a "
                                                            "surface-hardened mate)"
                                                            if soft_vs_hard else "") + f", {who}",
                      S2)
        ZX = R.factor(C, f"Z_X{k}", lambda: P2.z_x(types[i], m_n), "-", f"Z_X{k}",
                      f"size factor, contact, {who}", S2)
        if xp.scalar(N_L[i]) and N_L[i] < N_ref:    # a row of one pair (not of a sweep)
            R.put(C, f"ZLvR{k}", infl["Z_L"] * infl["Z_v"] * infl["Z_R"], "-", f"Z_LvR{k}",
                  f"Z_L·Z_v·Z_R at N_L (interpolated towards 1 at the static point), {who}", S2)
        G = sHlim[i] * ZNT * infl["Z_L"] * infl["Z_v"] * infl["Z_R"] * ZW * ZX
        sHG.append(R.put(C, f"sigma_HG{k}", G, "MPa", f"σ_HG{k}",
                         f"pitting stress limit σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X, {who}", S2))
        R.put(C, f"sigma_HP{k}", G / iso.S_Hmin, "MPa", f"σ_HP{k}",
              f"permissible contact stress σ_HG/S_Hmin, {who}", S2)
        R.put(C, f"S_H{k}", P2.safety(G, sH[i]), "-", f"S_H{k}",
              f"safety factor for pitting σ_HG/σ_H, {who}", S2)

    # ------------------------------------------------------------------ bending
    B = "iso6336_bending"
    Y_beta = R.factor(B, "Y_beta", lambda: xp.where(helical, P3.y_beta(g.eps_beta, p.beta), 1.0),
                      "-", "Y_β", "helix angle factor", S3)
    eps_an = g.eps_alpha / (cb * cb)
    Y_DT = R.factor(B, "Y_DT", lambda: P3.y_dt(eps_an, A), "-", "Y_DT", "deep tooth factor", S3)
    R.put(B, "S_Fmin", iso.S_Fmin, "-", "S_Fmin", "required safety factor, bending",
          "spec" if iso.S_Fmin != 1.4 else "spec default")
    forms = []
    for i in range(2):
        k, who, gr = i + 1, WHO[i], gears[i]
        tf = None
        if internal and i == 1 and getattr(p, "cutter", None) is not None:
            # the internal gear's fillet as its shaper cutter generates it
            c = p.cutter
            rho_a0 = c.rho_a0 if c.rho_a0 is not None else racks[1].rho_f
            tf = P3.internal_tooth_form(p.z2, x2, m_n, a_n, p.beta, g.beta_b, gr.d, gr.d_a,
                                        gr.d_f, g.eps_alpha, c.z0, c.x0, rho_a0 * m_n)
            how = f" (internal gear cut by the shaper z0 = {c.z0}, 60° tangent)"
            if tf is not None:
                R.put(B, "form_internal", f"shaper z0 = {c.z0}", None, "",
                      "internal gear's Y_F, Y_S: fillet of the shaper cutter", S3)
        if internal and i == 1 and tf is None:
            # no shaper given: the internal gear as the rack it tends to (z → ∞, own addendum)
            d_rack = Z_BIG * g.m_t
            tf = P3.tooth_form(Z_BIG, x2, m_n, a_n, p.beta, g.beta_b, d_rack,
                               d_rack + (gr.d - gr.d_a), g.eps_alpha, h_fPs[1] * m_n,
                               racks[1].rho_f * m_n, iso.protuberance * m_n)
            how = " (internal gear without a shaper: rack approximation, conservative)"
            R.put(B, "form_internal", "rack", None, "",
                  "internal gear's Y_F, Y_S: the rack it tends to (no shaper given)", S3)
        elif not (internal and i == 1):
            tf = P3.tooth_form(gr.z, gr.x, m_n, a_n, p.beta, g.beta_b, gr.d, gr.d_a, g.eps_alpha,
                               h_fP * m_n, p.rack.rho_f * m_n, iso.protuberance * m_n)
            how = ""
        forms.append(tf)
        tangent = "60°" if internal and i == 1 and how.startswith(" (internal gear cut") else "30°"
        R.put(B, f"s_Fn{k}", tf.s_Fn, "mm", f"s_Fn{k}", f"root chord at the {tangent} tangents, "
              f"{who}", S3)
        R.put(B, f"h_Fe{k}", tf.h_Fe, "mm", f"h_Fe{k}", f"bending moment arm, {who}", S3)
        R.put(B, f"rho_F{k}", tf.rho_F, "mm", f"ρ_F{k}", f"root fillet radius, {who}", S3)
        R.put(B, f"alpha_Fen{k}", xp.degrees(tf.alpha_Fen), "deg", f"α_Fen{k}",
              f"load direction angle at the outer single contact point, {who}", S3)
        R.put(B, f"q_s{k}", tf.q_s, "-", f"q_s{k}", f"notch parameter, {who}", S3)
        YF = R.factor(B, f"Y_F{k}", tf.Y_F, "-", f"Y_F{k}", f"tooth form factor{how}, {who}", S3)
        YS = R.factor(B, f"Y_S{k}", tf.Y_S, "-", f"Y_S{k}", f"stress correction factor, {who}", S3)
        YB = R.factor(B, f"Y_B{k}", lambda: P3.y_b(iso.gears[i].rim_thickness, gr.h, m_n,
                                                  internal and i == 1),
                      "-", f"Y_B{k}", f"rim thickness factor, {who}", S3)
        sF0 = R.put(B, f"sigma_F0{k}", P3.nominal_root_stress(F_t, b, m_n, YF, YS, Y_beta, YB, Y_DT),
                    "MPa", f"σ_F0{k}", f"nominal tooth root stress, {who}", S3)
        sF = R.put(B, f"sigma_F{k}", P3.root_stress(sF0, K_A, K_g, K_v, K_Fb, K_Fa), "MPa",
                   f"σ_F{k}", f"tooth root stress, {who}", S3)
        N_st, N_ref = P3.reference_cycles_bending(types[i])
        YNT = R.factor(B, f"Y_NT{k}", lambda: P3.y_nt(types[i], N_L[i], iso.optimum), "-",
                       f"Y_NT{k}", f"life factor, bending, {who}", S3)
        sigma_02 = mats[i].sigma_T
        rp = P3.rho_prime(types[i], 3.4 * mats[i].HB, sigma_02)
        Yd_st = P3.y_delta_rel_static(types[i], YS, sigma_02)
        Yd = R.factor(B, f"Y_deltarelT{k}",
                      lambda: P2.interpolated(P3.y_delta_rel(tf.q_s, rp), N_L[i], N_st, N_ref, Yd_st),
                      "-", f"Y_δrelT{k}", f"relative notch sensitivity factor (ρ' = {rp:.4f} mm), {who}",
                      S3)
        Rz_root = iso.gears[i].Rz_root
        YR = R.factor(B, f"Y_RrelT{k}", lambda: P2.interpolated(P3.y_r_rel(types[i], Rz_root),
                                                               N_L[i], N_st, N_ref),
                      "-", f"Y_RrelT{k}", f"relative surface factor (R_z = {Rz_root:g} µm), {who}", S3)
        YX = R.factor(B, f"Y_X{k}", lambda: P2.interpolated(P3.y_x(types[i], m_n), N_L[i], N_st,
                                                           N_ref),
                      "-", f"Y_X{k}", f"size factor, bending, {who}", S3)
        rev = duty.reverse_ratio if duty.reverse_ratios is None else duty.reverse_ratios[i]
        YM = R.factor(B, f"Y_M{k}", lambda: P3.y_m(rev), "-", f"Y_M{k}",
                      f"mean stress influence factor (T_rev/T = {rev:g}), {who}", S3)
        G = M[i]["sigma_Flim"] * P3.Y_ST * YNT * Yd * YR * YX * YM
        R.put(B, f"sigma_FG{k}", G, "MPa", f"σ_FG{k}",
              f"tooth root stress limit σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X Y_M, {who}", S3)
        R.put(B, f"sigma_FP{k}", G / iso.S_Fmin, "MPa", f"σ_FP{k}",
              f"permissible tooth root stress σ_FG/S_Fmin, {who}", S3)
        R.put(B, f"S_F{k}", G / sF, "-", f"S_F{k}", f"safety factor for bending σ_FG/σ_F, {who}", S3)

    # ------------------------------------------------------------------ scuffing
    if iso.scuffing is not None:
        _scuffing(R, g, mats, setting, iso, types, F_t, v, K_A, K_g * K_v * K_Hb * K_Ha,
                  c_ga, C_a)

    # ------------------------------------------------------------------ static (peak torque)
    if duty.T_peak is not None:
        St = "iso6336_static"
        ratio = duty.T_peak / duty.T1
        R.put(St, "T_peak", duty.T_peak, "N·m", "T_max", "peak pinion torque (an actual torque: "
              "K_A = 1; the other load factors as at the nominal torque)", "spec")
        for i in range(2):
            k, who = i + 1, WHO[i]
            s = sH[i] * math.sqrt(ratio / K_A)
            R.put(St, f"sigma_Hst{k}", s, "MPa", f"σ_H,st{k}", f"contact stress at the peak "
                  f"torque, {who}", S2)
            pts = T.ZNT_CURVES[T.ZNT_GROUP[types[i]]]
            ZW_st = 1.0
            Gs = sHlim[i] * pts[0][1] * ZW_st
            R.put(St, f"sigma_HGst{k}", Gs, "MPa", f"σ_HG,st{k}", "static pitting limit "
                  f"σ_Hlim·Z_NT,st (Z_NT,st = {pts[0][1]:g}; Z_L Z_v Z_R Z_X = 1), {who}", S2)
            R.put(St, f"S_Hst{k}", Gs / s, "-", f"S_H,st{k}", f"static safety factor, pitting, "
                  f"{who}", S2)
        for i in range(2):
            k, who = i + 1, WHO[i]
            s = R.v[f"sigma_F{k}"] * ratio / K_A
            R.put(St, f"sigma_Fst{k}", s, "MPa", f"σ_F,st{k}", f"root stress at the peak torque, "
                  f"{who}", S3)
            pts = T.YNT_CURVES[T.YNT_GROUP[types[i]]]
            Yd_st = P3.y_delta_rel_static(types[i], forms[i].Y_S, mats[i].sigma_T)
            Gs = M[i]["sigma_Flim"] * P3.Y_ST * pts[0][1] * Yd_st
            R.put(St, f"Y_deltarelTst{k}", Yd_st, "-", f"Y_δrelT,st{k}",
                  f"relative notch sensitivity factor, static, {who}", S3)
            R.put(St, f"sigma_FGst{k}", Gs, "MPa", f"σ_FG,st{k}", "static root stress limit "
                  f"σ_Flim·Y_ST·Y_NT,st·Y_δrelT,st (Y_NT,st = {pts[0][1]:g}; Y_RrelT = Y_X = 1), "
                  f"{who}", S3)
            R.put(St, f"S_Fst{k}", Gs / s, "-", f"S_F,st{k}", f"static safety factor, bending, "
                  f"{who}", S3)

    # ------------------------------------------------------------------ load spectrum
    if duty.life.blocks:
        _spectrum(R, g, duty, types, sHlim, M, N_L, iso)
    return R.record()


def _scuffing(R: Writer, g, mats, setting, iso: IsoSetting, types, F_t: float, v: float,
              K_A: float, K_rest: float, c_ga: float, C_a: float) -> None:
    """Scuffing by the integral temperature method ([ISO6336-21]): the factors, Θ_int,
    Θ_intS and the safety factors, in the section ``iso6336_scuffing``."""
    from geardesign.materials.lubricants import nu100_from_vi, viscosity_at

    sc, p, Sc = iso.scuffing, g.inp, "iso6336_scuffing"
    internal = bool(getattr(g, "internal", False))
    b, u, a = p.b_w, g.u, g.a_w
    a_wt, a_t = g.alpha_tw, g.alpha_t
    R.put(Sc, "scuffing_method", "integral temperature method (ISO/TS 6336-21:2017 = ISO/TR "
          "13989-2:2000)", None, "", "method", S21)
    # oil
    R.put(Sc, "fzg_load_stage", float(sc.fzg_load_stage), "-", "FZG", "FZG A/8.3/90 failure "
          "load stage of the oil (ISO 14635-1)", "spec")
    R.put(Sc, "theta_oil", sc.oil_temperature, "°C", "Θ_oil", "oil temperature", "spec")
    nu100 = sc.nu100 if sc.nu100 is not None else nu100_from_vi(iso.nu40, 95.0)
    R.put(Sc, "nu100", nu100, "mm^2/s", "ν100", "kinematic viscosity at 100 °C"
          + ("" if sc.nu100 is not None else " (from ν40 with VI 95)"),
          "spec" if sc.nu100 is not None else "ASTM D2270")
    nu_oil = viscosity_at(sc.oil_temperature, iso.nu40, nu100)
    R.put(Sc, "nu_oil", nu_oil, "mm^2/s", "ν_oil", "kinematic viscosity at the oil "
          "temperature (Ubbelohde–Walther)", "ASTM D341")
    eta = R.factor(Sc, "eta_oil", lambda: nu_oil * P21.oil_density(sc.density15, sc.oil_temperature)
                   / 1000.0, "mPa·s", "η_oil", f"dynamic viscosity at the oil temperature "
                   f"(ρ15 = {sc.density15:g} kg/m³, expansion {T.OIL_EXPANSION:g}/K)", S21)
    X_L = R.put(Sc, "X_L", T.SCUFFING_X_L[sc.lubricant], "-", "X_L",
                f"lubricant factor ({sc.lubricant.replace('_', ' ')} oil)", S21)
    X_S = R.put(Sc, "X_S", T.SCUFFING_X_S[sc.lubrication], "-", "X_S",
                f"lubrication factor ({sc.lubrication} lubrication)", S21)
    X_mp = R.put(Sc, "X_mp", P21.multiple_mesh_factor(sc.meshes), "-", "X_mp",
                 f"multiple mesh factor ({sc.meshes} mesh{'es' if sc.meshes > 1 else ''})", S21)
    if sc.structure is not None:
        structure, how = sc.structure, " (given)"
    else:
        structure = min((T.SCUFFING_STRUCTURE[t] for t in types),
                        key=lambda k: T.SCUFFING_X_WRELT[k])
        how = " (from the material types)"
    X_W = R.factor(Sc, "X_WrelT", T.SCUFFING_X_WRELT[structure], "-", "X_WrelT",
                   f"relative welding factor ({structure.replace('_', ' ')}){how}", S21)
    # load
    eps_g = g.eps_alpha + g.eps_beta
    K_Bg = R.factor(Sc, "K_Bgamma", lambda: P21.helical_load_factor(eps_g), "-", "K_Bγ",
                    "helical load factor", S21)
    w_Bt = R.put(Sc, "w_Bt", K_A * K_rest * F_t / b, "N/mm", "w_Bt",
                 "transverse unit load K_A K_γ K_v K_Hβ K_Hα F_t/b", S21)
    # geometry at the pinion tip E
    rho_E1 = 0.5 * math.sqrt(g.g1.d_a ** 2 - g.g1.d_b ** 2)
    path = a * math.sin(a_wt)
    rho_E2 = rho_E1 + path if internal else path - rho_E1
    R.put(Sc, "rho_E1", rho_E1, "mm", "ρ_E1", "radius of curvature of the pinion at its tip", S21)
    R.put(Sc, "rho_E2", rho_E2, "mm", "ρ_E2", "radius of curvature of the wheel at the pinion "
          "tip", S21)
    tan_wt = math.tan(a_wt)
    eps_1 = p.z1 / (2.0 * math.pi) * (2.0 * rho_E1 / g.g1.d_b - tan_wt)
    eps_2 = g.eps_alpha - eps_1
    R.put(Sc, "eps_1", eps_1, "-", "ε_1", "addendum contact ratio, pinion", S21)
    R.put(Sc, "eps_2", eps_2, "-", "ε_2", "addendum contact ratio, wheel", S21)
    E_r = 2.0 / sum((1.0 - m.nu ** 2) / m.E for m in mats)
    X_M = R.factor(Sc, "X_M", lambda: P21.flash_factor(E_r, sc.B_M), "K·N^-0.75·s^0.5·m^-0.5·mm",
                   "X_M", f"flash factor (B_M = {sc.B_M:g} N/(mm·s^½·K))", S21)
    X_ab = R.factor(Sc, "X_alphabeta", lambda: P21.angle_factor(a_wt, p.rack.alpha_n, a_t, p.beta),
                    "-", "X_αβ", "angle factor", S21)
    X_BE = R.factor(Sc, "X_BE", lambda: P21.geometry_factor_tip(rho_E1, rho_E2, u, internal), "-",
                    "X_BE", "geometry factor at the pinion tip", S21)
    X_eps_c, branch = P21.contact_ratio_factor(eps_1, eps_2)
    X_eps = R.factor(Sc, "X_eps", X_eps_c, "-", "X_ε", f"contact ratio factor ({branch})", S21)
    R.put(Sc, "X_eps_branch", branch if "X_eps" not in iso.overrides else "", None, "X_ε branch",
          "branch of the X_ε table (the scuffing advice)", S21, row=False)
    R.put(Sc, "nu40_scuffing", iso.nu40, "mm^2/s", "ν40", "kinematic viscosity at 40 °C (the "
          "scuffing advice)", "spec", row=False)
    e_f, e_a = (eps_2, eps_1) if sc.driving == "pinion" else (eps_1, eps_2)
    X_Q = R.factor(Sc, "X_Q", lambda: P21.approach_factor(e_f, e_a), "-", "X_Q",
                   f"approach factor (driving: {sc.driving}, ε_f/ε_a = {e_f / e_a:.3f})", S21)
    C_eff = R.put(Sc, "C_eff", K_A * F_t / (b * c_ga), "µm", "C_eff",
                  "optimal tip relief K_A F_t/(b c_γ)", S21)
    X_Ca = R.factor(Sc, "X_Ca", lambda: P21.tip_relief_factor(C_a, C_eff, max(eps_1, eps_2)), "-",
                    "X_Ca", f"tip relief factor (C_a = {min(C_a, C_eff):.3g} µm)", S21)
    X_E = R.factor(Sc, "X_E", 1.0, "-", "X_E", "running-in factor (well run in)", S21)
    # friction
    k_u = (u - 1.0) if internal else (u + 1.0)
    rho_C = R.put(Sc, "rho_redC", u / k_u ** 2 * path / math.cos(g.beta_b), "mm", "ρ_redC",
                  "relative radius of curvature at the pitch point (normal section)", S21)
    v_sum = R.put(Sc, "v_sumC", P21.sum_velocity_pitch(v * g.g1.d_w / g.g1.d, a_wt), "m/s",
                  "v_ΣC", "sum of the tangential velocities at the pitch point (operating "
                  "pitch circle)", S21)
    Ra = 0.5 * (setting.Ra[0] + setting.Ra[1])
    X_R = R.put(Sc, "X_R", P21.roughness_factor(Ra, rho_C), "-", "X_R",
                f"roughness factor (Ra = {Ra:g} µm, mean of the flanks)", S21)
    mu = R.factor(Sc, "mu_mC", lambda: P21.mean_friction(w_Bt * K_Bg, v_sum, rho_C, eta, X_R, X_L),
                  "-", "μ_mC", "mean coefficient of friction", S21)
    # temperatures
    th_E = R.put(Sc, "theta_flaE", P21.flash_temperature_tip(mu, X_M, X_BE, X_ab, w_Bt * K_Bg, v,
                                                           a, X_E, X_Q, X_Ca),
                 "K", "Θ_flaE", "flash temperature at the pinion tip", S21)
    th_fl = R.put(Sc, "theta_flaint", th_E * X_eps, "K", "Θ_flaint", "mean flash temperature "
                  "Θ_flaE·X_ε", S21)
    th_M = R.put(Sc, "theta_M", P21.bulk_temperature(sc.oil_temperature, th_fl, X_S, X_mp), "°C",
                 "Θ_M", "bulk temperature Θ_oil + C_1 X_mp X_S Θ_flaint", S21)
    th_int = R.put(Sc, "theta_int", th_M + P21.C_2 * th_fl, "°C", "Θ_int",
                   "integral temperature Θ_M + C_2 Θ_flaint", S21)
    th_S, th_MT, th_flT = P21.integral_scuffing_temperature(sc.fzg_load_stage, iso.nu40, X_L, X_W)
    R.put(Sc, "T_1T", P21.fzg_torque(sc.fzg_load_stage), "N·m", "T_1T",
          "pinion torque of the FZG load stage", "[ISO14635-1]")
    R.put(Sc, "theta_MT", th_MT, "°C", "Θ_MT", "bulk temperature of the test gears", S21)
    R.put(Sc, "theta_flaintT", th_flT, "K", "Θ_flaintT", "mean flash temperature of the test "
          "gears", S21)
    R.put(Sc, "theta_intS", th_S, "°C", "Θ_intS", "integral scuffing temperature "
          "Θ_MT + C_2 X_WrelT Θ_flaintT", S21)
    R.put(Sc, "S_Smin", sc.S_Smin, "-", "S_Smin", "required safety factor, scuffing",
          "spec" if sc.S_Smin != 1.8 else "spec default")
    R.put(Sc, "S_intS", th_S / th_int, "-", "S_intS", "safety factor for scuffing "
          "Θ_intS/Θ_int", S21)
    # 0 when the oil alone is at the scuffing temperature (no load is safe)
    R.put(Sc, "S_SL", max(0.0, th_S - sc.oil_temperature) / (th_int - sc.oil_temperature), "-",
          "S_SL", "safety factor for scuffing referred to the load (Θ_intS − Θ_oil)/(Θ_int − "
          "Θ_oil)", S21)


def _spectrum(R: Writer, g, duty, types, sHlim, M, N_L, iso: IsoSetting) -> None:
    """Miner's damage sums and the safety factors of the spectrum.  Each block's stress is the
    nominal one scaled with its torque (σ_H ∝ √T, σ_F ∝ T; the load factors kept at their
    nominal-torque values)."""
    from geardesign.spur.strength.iso6336 import part6 as P6

    v, Sp = R.v, "iso6336_spectrum"
    life = duty.life
    R.put(Sp, "method", "Palmgren–Miner on the S-N curves of parts 2 and 3; block stresses "
          "scaled from the nominal torque", None, "Σn/N", "damage accumulation", S6)
    for i in range(2):
        k, who = i + 1, WHO[i]
        n_i = [60.0 * (duty.n1 / (1.0 if i == 0 else g.u)) * blk.speed_ratio * life.c[i]
               * life.L_h * blk.time_share for blk in life.blocks]
        N_st, N_ref = P2.reference_cycles_contact(types[i], iso.limited_pitting)
        fixed = v[f"Z_W{k}"] * v[f"Z_X{k}"]
        infl = v["Z_L"] * v["Z_v"] * v["Z_R"]

        def s_HG(N: float, i=i, N_st=N_st, N_ref=N_ref, fixed=fixed, infl=infl) -> float:
            return sHlim[i] * P2.z_nt(types[i], N, iso.limited_pitting, iso.optimum) * \
                P2.interpolated(infl, N, N_st, N_ref) * fixed

        sH = [v[f"sigma_H{k}"] * math.sqrt(blk.torque_ratio) for blk in life.blocks]
        D = P6.damage(sH, n_i, s_HG)
        S = P6.spectrum_safety(sH, n_i, s_HG)
        R.put(Sp, f"D_H{k}", D, "-", f"D_H{k}", f"damage sum, pitting (stresses as computed), {who}", S6)
        R.put(Sp, f"S_Hspec{k}", S, "-", f"S_H,spec{k}", f"safety factor for pitting of the "
              f"spectrum (D = 1 at S·σ_Hi), {who}", S6)
        Nb_st, Nb_ref = P3.reference_cycles_bending(types[i])
        Ybase = M[i]["sigma_Flim"] * P3.Y_ST * v[f"Y_M{k}"]
        refs = (v[f"Y_deltarelT{k}"], v[f"Y_RrelT{k}"], v[f"Y_X{k}"])
        Yd_st = P3.y_delta_rel_static(types[i], v[f"Y_S{k}"], None)

        def s_FG(N: float, i=i, Ybase=Ybase, refs=refs, Yd_st=Yd_st, a=Nb_st, r=Nb_ref) -> float:
            return Ybase * P3.y_nt(types[i], N, iso.optimum) * \
                P2.interpolated(refs[0], N, a, r, Yd_st) * P2.interpolated(refs[1], N, a, r) * \
                P2.interpolated(refs[2], N, a, r)

        sF = [v[f"sigma_F{k}"] * blk.torque_ratio for blk in life.blocks]
        D = P6.damage(sF, n_i, s_FG)
        S = P6.spectrum_safety(sF, n_i, s_FG)
        R.put(Sp, f"D_F{k}", D, "-", f"D_F{k}", f"damage sum, bending (stresses as computed), {who}", S6)
        R.put(Sp, f"S_Fspec{k}", S, "-", f"S_F,spec{k}", f"safety factor for bending of the "
              f"spectrum (D = 1 at S·σ_Fi), {who}", S6)


def _num(x, spec: str) -> str:
    """``x`` formatted for a row's name; a sweep's array of candidates reads "per candidate"."""
    return format(x, spec) if xp.scalar(x) else "per candidate"


# ----------------------------------------------------------------------------- checks


def _pct(x: float) -> str:
    return f"{100 * x:.0f} %" if x <= 3.0 else "more than 300 % (far from passing: check the " \
                                                 "inputs and their units)"


def _range_words(standard: str, d: float, m_n: float, b: float, outside: list) -> str:
    """The sizes of a gear outside the range of ``standard`` (ISO 1328-1), for the warning."""
    rng = iso1328.validity(standard)
    names = " and ".join(iso1328.SIZE_NAMES[key].split(" d")[0] for key, *_ in outside)
    return (f"d = {d:.6g} mm, m_n = {m_n:.6g} mm, b = {b:.6g} mm: the {names} "
            + ("lie" if len(outside) > 1 else "lies")
            + f" outside the range of {standard} ({rng['d'][0]:g} ≤ d ≤ {rng['d'][1]:g}, "
              f"{rng['m_n'][0]:g} ≤ m_n ≤ {rng['m_n'][1]:g}, {rng['b'][0]:g} ≤ b ≤ "
              f"{rng['b'][1]:g} mm); {iso1328.beyond_range_words(standard)}")


def checks(v: dict, members: tuple[str, str] = WHO, spectrum: bool = False,
           peak: bool = False, internal: bool = False, clamped: tuple = (),
           found: dict | None = None) -> list[Check]:
    """Checks of an ISO 6336 rating ``v``: S_H ≥ S_Hmin and S_F ≥ S_Fmin per gear (of the
    spectrum when one is given), the static safety factors at the peak torque, and notes.

    The advice names the face width and the scale of the pair (centre distance, module and
    face width in proportion) that pass, when ``found`` carries them (``{"b": (b_w,
    b_pitting, b_bending), "k": (a_w, k_pitting, k_bending), "face_limit": the largest
    face width tried as a multiple of b_w}``, found by re-rating); else
    it follows the scaling of the formulas at the present load factors: σ_H ∝ 1/√b and
    ∝ a^(-3/2) at a fixed ratio b/a; σ_F ∝ 1/(b m_n)."""
    found = found or {}

    def by_rerating(kind: int) -> str | None:
        parts = []
        if "k" in found and found["k"][kind] is not None:
            a_w, k = found["k"][0], found["k"][kind]
            parts.append(f"increase the centre distance to at least {k * a_w:.1f} mm "
                         f"(+{100 * (k - 1):.0f} %, module and face width in proportion)")
        if "b" in found and found["b"][kind] is not None:
            from geardesign.spur.checks import face_width_up

            b_w, b = found["b"][0], face_width_up(found["b"][kind])
            parts.append(f"the face width to at least {b:g} mm (+{100 * (b / b_w - 1):.0f} %: "
                         f"set gear.face_width = {b:g})")
        if not parts:
            return None
        text = " or ".join(parts) + " (found by re-rating)"
        if "b" in found and found["b"][kind] is None:
            from geardesign.spur.checks import face_width_beyond

            text += "; " + face_width_beyond(found["b"][0], found["face_limit"])
        return text

    def face_fix(kind: int) -> tuple:
        from geardesign.spur.checks import face_width_fix

        b = found.get("b")
        return face_width_fix(b[0], b[kind]) if b else ()

    out: list[Check] = []
    S_Hmin, S_Fmin = v["S_Hmin"], v["S_Fmin"]
    judged = verdict(v)
    for k in (1, 2):
        who, up = members[k - 1], members[k - 1].upper()
        key = f"S_Hspec{k}" if spectrum else f"S_H{k}"
        S = v[key]
        r = S_Hmin / S
        out.append(check(
            f"ISO_PITTING_{up}", judged.contact_ok[k - 1], "error",
            f"ISO 6336 pitting, {who}: S_H{k} = {S:.2f} < S_Hmin = {S_Hmin:.2f}"
            + (" (load spectrum)" if spectrum else "") + ": "
            + (by_rerating(1) or f"increase the centre distance by {_pct(r ** (2 / 3) - 1)} "
               f"(module and face width in proportion), or the face width by {_pct(r * r - 1)} "
               f"(at the present load factors)")
            + f", or use a {who} material with σ_Hlim at least {v[f'sigma_Hlim{k}'] * r:.0f} MPa",
            f"ISO 6336 pitting, {who}: S_H{k} = {S:.2f} >= {S_Hmin:.2f}", S, S_Hmin, S2,
            face_fix(1)))
    for k in (1, 2):
        who, up = members[k - 1], members[k - 1].upper()
        key = f"S_Fspec{k}" if spectrum else f"S_F{k}"
        S = v[key]
        r = S_Fmin / S
        out.append(check(
            f"ISO_BENDING_{up}", judged.bending_ok[k - 1], "error",
            f"ISO 6336 tooth bending, {who}: S_F{k} = {S:.2f} < S_Fmin = {S_Fmin:.2f}"
            + (" (load spectrum)" if spectrum else "") + f": increase the module by "
            f"{_pct(r - 1)} (same centre distance, fewer teeth), or "
            + (by_rerating(2) or f"the face width by {_pct(r - 1)} (at the present load "
                                 f"factors)")
            + f", or use a {who} material with σ_Flim at least {v[f'sigma_Flim{k}'] * r:.0f} MPa",
            f"ISO 6336 tooth bending, {who}: S_F{k} = {S:.2f} >= {S_Fmin:.2f}", S, S_Fmin, S3,
            face_fix(2)))
    if peak:
        for kind, sym, need, src in (("PITTING", "S_Hst", S_Hmin, S2), ("BENDING", "S_Fst", S_Fmin, S3)):
            for k in (1, 2):
                who, up = members[k - 1], members[k - 1].upper()
                S = v[f"{sym}{k}"]
                expo = 2.0 if kind == "PITTING" else 1.0
                out.append(check(
                    f"ISO_STATIC_{kind}_{up}", S >= need * (1 - 1e-12), "error",
                    f"ISO 6336 static {kind.lower()}, {who}: {sym}{k} = {S:.2f} < {need:.2f} at "
                    f"the peak torque: limit the peak torque to "
                    f"{v['T_peak'] * (S / need) ** expo:.0f} N·m (e.g. a slip coupling), or "
                    f"enlarge the gears",
                    f"ISO 6336 static {kind.lower()}, {who}: {sym}{k} = {S:.2f} >= {need:.2f}",
                    S, need, src))
    if "S_intS" in v:
        out.extend(scuffing_checks(v))
    if internal and v.get("form_internal", "rack") == "rack":
        out.append(check("ISO_INTERNAL_FORM_FACTOR", False, "info",
                         "ISO 6336: the internal gear's Y_F and Y_S are those of the rack it "
                         "tends to (conservative); give the shaper cutter that cuts it "
                         "(cutter teeth) for the standard's internal-gear method", "",
                         None, None, S3))
    for k in (1, 2):
        if f"tolerance_range{k}" in v:
            out.append(check(
                f"ISO_TOLERANCE_RANGE_{members[k - 1].upper()}", False, "warning",
                f"ISO 6336: the {members[k - 1]}'s flank tolerances (f_pb, f_fα, f_Hβ, F_β "
                f"of K_v, K_Hα, K_Hβ): {v[f'tolerance_range{k}']}; give the measured "
                f"deviations (iso.f_pb, iso.f_falpha, iso.F_beta, iso.f_ma) for a rating "
                f"within the standard", "", None, None,
                "[ISO1328-1-1995]" if v.get("tolerance_standard") == iso1328.STANDARD_1995
                else S1328))
    for k, (lo, hi, scale) in clamped:
        out.append(check(f"ISO_HARDNESS_RANGE_{members[k - 1].upper()}", False, "warning",
                         f"ISO 6336-5: the {members[k - 1]} hardness lies outside the material "
                         f"line's range {lo:g}…{hi:g} {scale}; σ_Hlim and σ_Flim were taken at "
                         f"the nearer end: give sigma_Hlim and sigma_Flim under [iso.{WHO[k - 1]}]",
                         "", None, None, S5))
    return out


OIL_TEMPERATURE_REACHABLE = 40.0
"""Lowest oil temperature [°C] the scuffing advice proposes (what an oil cooler reaches in
practice); below it the advice names only the oil and the geometry."""


def scuffing_checks(v: dict) -> list[Check]:
    """S_intS ≥ S_Smin ([ISO6336-21]) with advice: the FZG load stage of an oil that passes,
    or how far to lower the oil temperature (Θ_int moves with Θ_oil nearly one to one)."""
    S, need = v["S_intS"], v["S_Smin"]
    th_int, th_S = v["theta_int"], v["theta_intS"]
    ok = S >= need * (1 - 1e-12)
    advice = []
    if not ok:
        from geardesign.spur.strength.iso6336 import part21 as P21

        target = need * th_int
        nu40 = v["nu40_scuffing"]
        stage = next((k for k in sorted(T.FZG_TORQUE) if P21.integral_scuffing_temperature(
            k, nu40, v["X_L"], v["X_WrelT"])[0] >= target), None)
        if stage is not None:
            advice.append(f"use an oil of FZG load stage {stage} or higher (Θ_intS >= "
                          f"{target:.0f} °C)")
        drop = math.ceil(th_int - th_S / need)   # whole kelvins, on the safe side
        if v["theta_oil"] - drop >= OIL_TEMPERATURE_REACHABLE:
            advice.append(f"lower the oil temperature by at least {drop:d} K, to "
                          f"{v['theta_oil'] - drop:g} °C (cooling)")
        advice.append("reduce the sliding at the tips (smaller module with more teeth, tip "
                      "relief, balanced profile shifts) or the flank roughness")
    out = [check("ISO_SCUFFING", ok, "error",
                 f"ISO/TS 6336-21 scuffing: S_intS = {S:.2f} < S_Smin = {need:.2f} "
                 f"(Θ_int = {th_int:.0f} °C, Θ_intS = {th_S:.0f} °C): " + ", or ".join(advice),
                 f"ISO/TS 6336-21 scuffing: S_intS = {S:.2f} >= {need:.2f} (Θ_int = "
                 f"{th_int:.0f} °C)", S, need, S21)]
    if "(nearest)" in v.get("X_eps_branch", ""):
        out.append(check("ISO_SCUFFING_CONTACT_RATIO", False, "warning",
                         f"ISO/TS 6336-21: ε_α = {v['eps_1'] + v['eps_2']:.2f} with ε_1 = "
                         f"{v['eps_1']:.2f}, ε_2 = {v['eps_2']:.2f} lies outside the table of "
                         f"X_ε; the nearest branch was used: give X_eps under [iso_factors] "
                         f"for a closer rating", "", None, None, S21))
    return out


def passes(v: dict, kind: str) -> bool:
    """Whether a rating ``v`` passes pitting (``"H"``) or bending (``"F"``) on both gears
    (:func:`geardesign.spur.strength.verdict.verdict`)."""
    judged = verdict(v)
    return bool(judged.contact_passes if kind == "H" else judged.bending_passes)


def rating_checks(rating: IsoRating, internal: bool = False, members=WHO,
                  found: dict | None = None) -> list[Check]:
    """:func:`checks` of a finished rating (what a calculator calls)."""
    v = rating.v
    clamped = []
    for k in (1, 2):
        row = next(r for r in rating.rows if r.key == f"hardness{k}")
        typ = v[f"type{k}"]
        line = T.MATERIAL_LINES[typ]
        if "clamped" in row.name:
            clamped.append((k, (*line["range"], line["scale"])))
    return checks(v, members, "S_Hspec1" in v, "S_Hst1" in v, internal, tuple(clamped), found)
