"""Design mode: propose an external pair for a torque, a ratio and two materials
(GOST 21354-87 design formula, GOST 2185 centre distances, GOST 9563 modules), then leave
the full check to the calculator.

Procedure (GOST 21354-87 design calculation, as in the handbooks):

1. Preliminary allowable contact stress σ_HP = σ_Hlim·Z_N·0.9/S_H per gear (Z_R·Z_v·Z_X
   taken as 0.9, [GOST21354]), the pair value as in the check.
2. K_Hβ from the chart at ψ_bd = ψ_ba(u + 1)/2.
3. a_w = K_a(u + 1)·∛(T1·K_Hβ/(ψ_ba·u·σ_HP²)), rounded up to the GOST 2185 series.
4. For each GOST 9563 module from 0.01·a_w up: z_Σ = ⌊2a_w cos β/m⌋, z1 = round(z_Σ/(u+1))
   (at least z1_min), z2 = z_Σ − z1; helical: β = arccos(m z_Σ/(2a_w)) exactly; spur:
   x_Σ from a_w, split for equal sliding.  b_w = ψ_ba·a_w.
5. The first candidate that passes every error check of the full rating is proposed;
   if none does, the next centre distance of the series is tried (up to six steps).
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem
from geardesign.core.spec import ValidatedSpec
from geardesign.gears.geometry import (
    BasicRack, GeometryError, disc_mass, PairGeometry, PairInput, pair_geometry,
    shift_sum_for_center_distance)
from geardesign.spur.kinematics import balanced_shift_split, sliding_at_ends
from geardesign.spur.loads import cycles, equivalent_cycles
from geardesign.spur.strength import gost21354 as G
from geardesign.spur.strength import tables as T

MODULE_MIN_RATIO = 0.01   # m >= 0.01·a_w (handbook range 0.01…0.02 a_w, hardened up to 0.0315)
MODULE_MAX_RATIO = 0.0315
MAX_RATIO_TOLERANCE = 10.0   # the largest design.ratio_tolerance the spec allows [%]
A_W_STEPS = 6


def _series(which: int) -> list[float]:
    values = list(T.CENTER_DISTANCES_1)
    if which == 2:
        values += list(T.CENTER_DISTANCES_2)
    return sorted(values)


def preliminary_sigma_hp(mats, duty, u: float) -> list[float]:
    """Allowable contact stress of each gear for the design formula (step 1 above)."""
    life = duty.life
    n = (duty.n1, duty.n1 / u)
    out = []
    for i, mat in enumerate(mats):
        if life.blocks:
            N = equivalent_cycles(n[i], life.c[i], life.L_h, life.blocks, 3.0)
        else:
            N = T.MU_H[life.regime] * cycles(n[i], life.c[i], life.L_h)
        out.append(mat.sigma_Hlim * G.z_n(G.n_hg(mat.HB), N, mat.Z_N_max) * 0.9 / mat.S_H)
    return out


def design_pair(spec: ValidatedSpec):
    """Return ``(geometry, how the shifts were set, gear settings, proposal rows)``."""
    from geardesign.spur.spec_inputs import _strength_inputs
    from geardesign.spur.checks import geometry_checks
    from geardesign.spur.strength.checks import rating_checks
    from geardesign.spur.strength import method

    rate = method(spec.data["options"]["method"]).rate

    d = spec.data
    des = dict(d["design"])
    des["allow_undercut"] = False
    if d["material"] is None:
        raise InputError(Problem("material", "missing table [material.pinion] and "
                                 "[material.wheel]: the design mode sizes the pair for them"))
    inputs = _strength_inputs(spec, des)
    mats, duty, setting = inputs
    r = d["rack"]
    rack = BasicRack(math.radians(des["pressure_angle"]), r["addendum_coef"], r["clearance_coef"],
                     r["root_radius_coef"])
    u_req = des["ratio"]
    beta0 = math.radians(des["helix_angle"])
    helical = des["helix_angle"] > 0.0
    psi_ba = des["psi_ba"]

    s1, s2 = preliminary_sigma_hp(mats, duty, u_req)
    sigma_HP = G.sigma_hp_pair(s1, s2, helical)
    soft_pair = min(m.HB for m in mats) <= 350.0
    psi_bd = psi_ba * (u_req + 1.0) / 2.0
    K_Hb = G.k_h_beta(setting.scheme, psi_bd, soft_pair)
    a_est = G.center_distance_estimate(duty.T1 * duty.K_A, u_req, K_Hb, psi_ba, sigma_HP, helical)
    series = [a for a in _series(des["center_distance_series"]) if a >= a_est * (1 - 1e-9)]
    if not series:
        raise InputError.at("design.ratio", u_req,
                            f"the estimated centre distance {a_est:.0f} mm exceeds the GOST 2185 "
                            f"series; split the drive into stages")

    tried = 0
    best = None
    proposal = None
    variants = []
    for a_w in series[:A_W_STEPS]:
        m_lo, m_hi = MODULE_MIN_RATIO * a_w, MODULE_MAX_RATIO * a_w
        modules = [m for m in sorted(T.MODULES_1) if m_lo - 1e-9 <= m <= m_hi + 1e-9]
        for m in modules:
            cand = _candidate(a_w, m, u_req, des, beta0, helical, psi_ba, rack)
            if cand is None:
                continue
            tried += 1
            p, how = cand
            try:
                g = pair_geometry(p)
            except GeometryError:
                continue
            ok = not [c for c in geometry_checks(g, sliding_at_ends(g), False)
                      if not c.passed and c.severity == "error"]
            rating = rate(g, mats, duty, setting)
            checks = rating_checks(rating)
            failed = [c.code for c in checks if not c.passed and c.severity == "error"]
            ok = ok and not failed
            best = (g, how, a_w, m)
            variants.append(_variant(g, a_w, rating.v, mats, ok, how))
            if ok and proposal is None:
                proposal = (g, how, a_w, m)
    if proposal is not None:
        g, how, a_w, m = proposal
        out = _result(g, how, des, a_est, a_w, sigma_HP, K_Hb, u_req, tried, True)
        return (*out, _ranked(variants))
    if best is None:
        raise InputError.at("design.ratio", u_req, _no_pair(series[:A_W_STEPS], u_req, des,
                                                            beta0))
    g, how, a_w, m = best
    return (*_result(g, how, des, a_est, a_w, sigma_HP, K_Hb, u_req, tried, False),
            _ranked(variants))


def _variant(g: PairGeometry, a_w: float, v: dict, mats, ok: bool, how: str) -> dict:
    """One rated candidate of the design search, for the table of variants: its data, the
    safety factors of the rating (GOST: S_H per gear and the pair's σ_HP/σ_H; ISO: S_H, S_F
    per gear) and the smallest reserve."""
    p = g.inp
    if "sigma_HP" in v:                      # GOST 21354-87
        reserve = [v["sigma_HP"] / v["sigma_H"], v["S_F1"] / mats[0].S_F,
                   v["S_F2"] / mats[1].S_F]
        S_H = min(v["S_H1"], v["S_H2"])
    else:                                    # ISO 6336
        reserve = [v["S_H1"] / v["S_Hmin"], v["S_H2"] / v["S_Hmin"],
                   v["S_F1"] / v["S_Fmin"], v["S_F2"] / v["S_Fmin"]]
        S_H = min(v["S_H1"], v["S_H2"])
    return {"a_w": a_w, "m_n": p.m_n, "z1": p.z1, "z2": p.z2, "beta": math.degrees(p.beta),
            "b_w": p.b_w, "x1": p.x1, "x2": p.x2, "S_H": S_H, "S_F1": v["S_F1"],
            "S_F2": v["S_F2"], "margin": min(reserve), "passes": "yes" if ok else "no",
            "mass": disc_mass(g.g1.d, p.b_w) + disc_mass(g.g2.d, p.b_w)}


def _ranked(variants: list) -> list:
    """Every rated candidate, ranked: passing ones first, then by centre distance, then by
    the larger reserve, then by the lighter pair."""
    order = sorted(variants, key=lambda r: (r["passes"] != "yes", r["a_w"], -r["margin"],
                                            r["mass"]))
    for i, r in enumerate(order, 1):
        r["rank"] = i
    return order


def _no_pair(series, u: float, des: dict, beta0: float) -> str:
    """Why no pair fits the ratio, and the change that makes one fit: the most teeth in all
    the module rule leaves (m >= MODULE_MIN_RATIO·a_w, the smallest GOST 9563 module in it,
    over the centre distances tried) give z1 = z1_min the ratio (z_Σ − z1)/z1; when the
    tolerance the rounding then needs is allowed, widen it to that, else the stage cannot
    have this ratio: split it (or lower the ratio)."""
    z_sum = 0
    for a_w in series:
        m = min((m for m in T.MODULES_1 if m >= MODULE_MIN_RATIO * a_w - 1e-9), default=None)
        if m is not None:
            z_sum = max(z_sum, _teeth_sum(a_w, m, beta0))
    z1 = des["z1_min"]
    u_max = (z_sum - z1) / z1 if z_sum > 2 * z1 else 0.0
    need = (u - u_max) / u * 100.0
    head = "no pair of standard module and whole tooth numbers fits this ratio within the tolerance"
    if u_max >= 1.0 and need <= MAX_RATIO_TOLERANCE:
        return (f"{head}: with z1 >= {z1} the module rule (m >= {MODULE_MIN_RATIO:g}·a_w) leaves "
                f"at most {z_sum} teeth in all, u = {u_max:.3f}; widen design.ratio_tolerance "
                f"to {math.ceil(need * 10.0) / 10.0:g} %")
    return (f"{head}: with z1 >= {z1} the module rule (m >= {MODULE_MIN_RATIO:g}·a_w) leaves at "
            f"most {z_sum} teeth in all (u = {u_max:.3f} at most, {need:.1f} % short); split "
            f"the ratio into two stages (a drive spec; its [split] table proposes the stage "
            f"ratios) or lower design.ratio")


def _teeth_sum(a_w: float, m: float, beta: float) -> int:
    """The most teeth in all at centre distance ``a_w``, module ``m`` and helix angle
    ``beta``: z_Σ = ⌊2·a_w·cos β / m⌋ (a_w = m·z_Σ / (2 cos β): the reference centre
    distance of [GOST16532])."""
    return int(math.floor(2.0 * a_w * math.cos(beta) / m + 1e-9))


def _candidate(a_w: float, m: float, u: float, des: dict, beta0: float, helical: bool,
               psi_ba: float, rack: BasicRack):
    z_sum = _teeth_sum(a_w, m, beta0)
    z1 = max(int(round(z_sum / (u + 1.0))), des["z1_min"])
    z2 = z_sum - z1
    if z2 < z1 or abs(z2 / z1 - u) / u * 100.0 > des["ratio_tolerance"]:
        return None
    b_w = float(math.ceil(psi_ba * a_w))
    if helical:
        c = m * z_sum / (2.0 * a_w)
        if c >= 1.0:
            return None
        beta = math.acos(c)
        return PairInput(m, z1, z2, 0.0, 0.0, beta, b_w, rack), "x1 = x2 = 0 (β fitted to a_w)"
    try:
        x_sum, _ = shift_sum_for_center_distance(a_w, m, z1, z2, rack.alpha_n, 0.0)
    except GeometryError:
        return None
    if abs(x_sum) < 1e-9:
        return PairInput(m, z1, z2, 0.0, 0.0, 0.0, b_w, rack), "x1 = x2 = 0"
    base = PairInput(m, z1, z2, 0.0, 0.0, 0.0, b_w, rack)
    try:
        x1 = balanced_shift_split(base, x_sum)
    except GeometryError:
        return None
    return PairInput(m, z1, z2, x1, x_sum - x1, 0.0, b_w, rack), "equal specific sliding"


def _result(g: PairGeometry, how: str, des: dict, a_est: float, a_w: float, sigma_HP: float,
            K_Hb: float, u_req: float, tried: int, ok: bool):
    p = g.inp
    gear = dict(des)
    rows = [
        ("sigma_HP_design", sigma_HP, "MPa", "σ_HP'", "preliminary allowable contact stress "
         "(Z_R·Z_v·Z_X = 0.9)", "GOST 21354-87"),
        ("K_Hbeta_design", K_Hb, "-", "K_Hβ'", "face load factor at ψ_bd = ψ_ba(u+1)/2",
         "GOST 21354-87 chart"),
        ("a_w_estimate", a_est, "mm", "a_w'", "design centre distance K_a(u+1)∛(T1K_Hβ/(ψ_ba u σ_HP²))",
         "GOST 21354-87"),
        ("a_w_proposed", a_w, "mm", "a_w", "proposed centre distance (GOST 2185 series)",
         "GOST 2185-66"),
        ("module_proposed", p.m_n, "mm", "m_n", "proposed module (GOST 9563 series)",
         "GOST 9563-60"),
        ("z1_proposed", p.z1, "-", "z1", "pinion teeth", "design"),
        ("z2_proposed", p.z2, "-", "z2", "wheel teeth", "design"),
        ("helix_angle_proposed", p.beta, "rad", "β", "helix angle", "design"),
        ("face_width_proposed", p.b_w, "mm", "b_w", "face width ψ_ba·a_w", "GOST 2185-66"),
        ("ratio_error", (p.z2 / p.z1 - u_req) / u_req * 100.0, "%", "Δu", "ratio deviation",
         "design"),
        ("candidates", tried, "-", "", "candidate pairs rated", "design"),
        ("proposal_passes", ok, None, "", "the proposal passes every error check", "design"),
    ]
    return g, how, gear, rows


def first_estimate_check(rows: list, psi_ba: float):
    """An ``info`` check of a design-mode report saying what the proposal is: the
    handbook's first estimate ([GOST21354] design formula as applied in [Dunaev]: a_w from
    the formula at a fixed ψ_ba, rounded up to the GOST 2185-66 series, the first GOST 9563
    module that passes), not the lightest pair, and where to find that (``geardesign
    sweep``, which varies the data over ranges, does not round a_w to the series and ranks
    the passing pairs by mass).  ``rows`` are the proposal rows of :func:`design_pair`."""
    from geardesign.core.result import check

    v = {r[0]: r[1] for r in rows}
    return check(
        "DESIGN_FIRST_ESTIMATE", True, "info", "",
        f"the proposal is the handbook's first estimate: the design formula gives a_w' = "
        f"{v['a_w_estimate']:.1f} mm at ψ_ba = {psi_ba:g}, rounded up to {v['a_w_proposed']:g} "
        f"mm of the GOST 2185-66 series, with the first standard module that passes; it is "
        f"not the lightest pair: geardesign sweep varies module, teeth, helix angle and face "
        f"width over ranges (any a_w, ψ_ba within its window) and ranks the passing pairs by "
        f"mass (docs/sweep.md)", v["a_w_proposed"], v["a_w_estimate"], "GOST 21354-87")
