"""Bevel geometry against published worked examples, each value at its printed precision.

[BevGear2023]: the calculation report of the BevGear program for the spiral bevel example of
[ISO23509] (project item "Gleas FM ISO 23509 page 79"): z = 14/39, d_e2 = 176.893 mm,
b = 25.4 mm, β_m = 35°, Σ = 90°, α = 20°, h_a* = 1, h_f* = 1.25 (c* = 0.25), x_hm1 = 0.505,
uniform clearance.  Its face and root angles come from the cutter (duplex taper, given
θ_a2 = 2.1342°, θ_f2 = 6.4934°) and are not ours to match: the standard-depth cones of
``pair_geometry`` are a different convention (named in docs/bevel.md), so only the
convention-independent quantities are tested.
"""

from __future__ import annotations

import math

import pytest

from geardesign.bevel.geometry import pair_geometry
from geardesign.bevel.inputs import Pair

# (value, tolerance): tolerance = half a unit of the last printed digit unless noted
ISO23509_P79 = {
    # [BevGear2023] section 3 row 20, section 4 rows 21-30
    "u": (2.7857, 0.00005),
    "delta1_deg": (19.7468, 0.00005),
    "delta2_deg": (70.2532, 0.00005),
    "R_m": (81.273, 0.0005),
    # d_m1 printed 54.919 while d_m2·z1/z2 = 152.987·14/39 = 54.918: one unit of the
    # last digit, the report's own rounding
    "d_m1": (54.919, 0.001),
    "d_m2": (152.987, 0.0005),
    "m_mt": (3.9227, 0.00005),
    "m_mn": (3.2133, 0.00005),
    "h_am1": (4.836, 0.0005),
    "h_am2": (1.591, 0.0005),
    "h_fm1": (2.394, 0.0005),
    "h_fm2": (5.639, 0.0005),
    "h_m": (7.230, 0.0005),
    "c": (0.803, 0.0005),
}


def _iso23509_p79():
    return pair_geometry(Pair(
        True, 176.893 / 39, "outer", 14, 39, math.pi / 2, 25.4, math.radians(35.0), "left",
        math.radians(20.0), 1.0, 0.25, 0.3, 0.505, 0.0, "constant_clearance"))


def _ours(g) -> dict[str, float]:
    P, W = g.pinion, g.wheel
    return {
        "u": g.u, "delta1_deg": math.degrees(P.delta), "delta2_deg": math.degrees(W.delta),
        "R_m": g.R_m, "d_m1": P.d_m, "d_m2": W.d_m, "m_mt": g.m_tm, "m_mn": g.m_nm,
        "h_am1": P.h_am, "h_am2": W.h_am, "h_fm1": P.h_fm, "h_fm2": W.h_fm,
        "h_m": P.h_am + P.h_fm, "c": P.h_fm - W.h_am,
    }


@pytest.mark.parametrize("key", sorted(ISO23509_P79))
def test_iso23509_spiral_example(key):
    value, tol = ISO23509_P79[key]
    assert _ours(_iso23509_p79())[key] == pytest.approx(value, abs=tol)


def test_iso23509_whole_depth_equal_for_both_members():
    g = _iso23509_p79()
    assert g.pinion.h_am + g.pinion.h_fm == pytest.approx(g.wheel.h_am + g.wheel.h_fm)


def _result(path):
    """The finished result of a bevel spec."""
    from geardesign.bevel.calculator import compute
    from geardesign.core.registry import load

    spec = load(path)[1]
    return compute(spec)


# ---------------------------------------------------------------------------------------
# [KHK]: the straight bevel examples of KHK's gear technical reference, m = 3 mm (outer),
# z = 20/40, b = 22 mm, α = 20°, Σ = 90°, in its two forms: "standard" (h_a = 1.00·m,
# h_f = 1.25·m, tip and root cones from the pitch apex: depth = "tapered") and "Gleason"
# (h_a2 = 0.54·m + 0.46·m/(u·cos δ1/cos δ2) = 1.965 mm, h_a1 = 2·m − h_a2 = 4.035 mm,
# whole depth 2.188·m: x1 = 0.345, c* = 0.188 in GOST terms, and the tip cone of each member
# parallel to the root cone of the other: depth = "constant_clearance", the form of
# [GOST19624]).  The printed values as transcribed by the open unit tests of
# [BolsoverBevel]; X = B (apex to the outer tip circle plane), X_b = b_ax, d_i = d_ai.
# (value, tolerance): half a unit of the last printed digit.

KHK_STANDARD = {
    "d_e1": (60.0, 5e-6), "d_e2": (120.0, 5e-6), "R_e": (67.08204, 5e-6),
    "delta1_deg": (26.56505, 5e-6), "delta2_deg": (63.43495, 5e-6),
    "h_ae1": (3.0, 5e-6), "h_ae2": (3.0, 5e-6), "h_fe1": (3.75, 5e-6), "h_fe2": (3.75, 5e-6),
    "theta_f1_deg": (3.19960, 5e-6), "theta_f2_deg": (3.19960, 5e-6),
    "theta_a1_deg": (2.56064, 5e-6), "theta_a2_deg": (2.56064, 5e-6),
    "delta_a1_deg": (29.12569, 5e-6), "delta_a2_deg": (65.99559, 5e-6),
    "delta_f1_deg": (23.36545, 5e-6), "delta_f2_deg": (60.23535, 5e-6),
    "d_ae1": (65.3666, 5e-5), "d_ae2": (122.6833, 5e-5),
    "B1": (58.6584, 5e-5), "B2": (27.3167, 5e-5),
    "b_ax1": (19.2374, 5e-5), "b_ax2": (8.9587, 5e-5),
    "d_ai1": (43.9292, 5e-5), "d_ai2": (82.4485, 5e-5),
    # Tredgold's back-cone gear: d_v = d_e/cos δ, z_v = z/cos δ (printed 22.3606 and
    # 268.3281: the transcription cuts 22.36068 and 268.32816 rather than rounding them, so
    # one unit of the last digit)
    "d_ve1": (67.082, 5e-4), "d_ve2": (268.3281, 1e-4),
    "z_v1": (22.3606, 1e-4), "z_v2": (89.4427, 5e-5),
}

KHK_GLEASON = {
    "R_e": (67.08204, 5e-6),
    "h_ae1": (4.035, 5e-6), "h_ae2": (1.965, 5e-6), "h_fe1": (2.529, 5e-6),
    "h_fe2": (4.599, 5e-6),
    "theta_f1_deg": (2.15903, 5e-6), "theta_f2_deg": (3.92194, 5e-6),
    "theta_a1_deg": (3.92194, 5e-6), "theta_a2_deg": (2.15903, 5e-6),
    "delta_a1_deg": (30.48699, 5e-6), "delta_a2_deg": (65.59398, 5e-6),
    "d_ae1": (67.21803, 5e-6), "d_ae2": (121.75755, 5e-6),
}


def _khk(gleason: bool):
    c, x, depth = (0.188, 0.345, "constant_clearance") if gleason else (0.25, 0.0, "tapered")
    return pair_geometry(Pair(False, 3.0, "outer", 20, 40, math.pi / 2, 22.0, 0.0, "right",
                              math.radians(20.0), 1.0, c, 0.2, x, 0.0, depth))


def _khk_ours(g) -> dict[str, float]:
    out = {"R_e": g.R_e}
    for i, m in enumerate(g.members, 1):
        for key in ("d_e", "h_ae", "h_fe", "d_ae", "B", "b_ax", "d_ai", "z_v"):
            out[f"{key}{i}"] = getattr(m, key)
        for key in ("delta", "theta_a", "theta_f", "delta_a", "delta_f"):
            out[f"{key}{i}_deg"] = math.degrees(getattr(m, key))
        out[f"d_ve{i}"] = m.d_e / math.cos(m.delta)
    return out


@pytest.mark.parametrize("key", sorted(KHK_STANDARD))
def test_khk_standard_straight_bevel(key):
    value, tol = KHK_STANDARD[key]
    assert _khk_ours(_khk(False))[key] == pytest.approx(value, abs=tol)


@pytest.mark.parametrize("key", sorted(KHK_GLEASON))
def test_khk_gleason_straight_bevel(key):
    value, tol = KHK_GLEASON[key]
    assert _khk_ours(_khk(True))[key] == pytest.approx(value, abs=tol)


@pytest.mark.parametrize("name", ["bevel_straight_gost.toml", "bevel_spiral_iso.toml"])
def test_every_bevel_result_says_what_is_not_verified(name):
    """Until a part is checked against a published example, the report says so: one
    METHOD_UNVERIFIED warning naming what is unchecked (the GOST route, the forces) and what
    is checked (the ISO 10300 method B1 chain by [ISOTR10300-30] sample 1)."""
    from pathlib import Path

    res = _result(Path(__file__).resolve().parent.parent / "specs" / name)
    found = [c for c in res.checks if c.code == "METHOD_UNVERIFIED"]
    assert len(found) == 1
    c = found[0]
    assert c.severity == "warning" and not c.passed
    assert "ISO 10300" in c.message and "GOST 21354" in c.message
    assert "forces" in c.message and "checked:" in c.message
    assert "ISOTR10300-30" in c.message


# ---------------------------------------------------------------------------------------
# [ISOTR10300-30] sample 1: the same spiral pair rated by ISO 10300 method B1, T1 = 300 N·m,
# n1 = 1 200 min⁻¹, K_A = 1.1, one member cantilever-mounted, contact pattern checked under a
# light test load, E = 210 000 MPa, ν = 0.3.  K_v = 1.020 and K_Hα = 1.161 are the printed
# results of its method B (given here, so that the stresses are checked on their own; the
# factors themselves are computed from the sample's pitch deviations and checked in
# tests/test_bevel_load.py).  The
# printed values as transcribed, with their inputs, in the open calculator [ISO10300Calc]
# (its self-test of sample 1).  The cutter edge radius (ρ_a0 = 0.8 mm pinion, 1.2 mm wheel)
# and the thickness modification (x_sm = 0.036 pinion, −0.055 wheel) differ per member in
# the sample: entered per member (root_radius2, xt2 = 2·x_sm2), the pair is rated once.
# (value, tolerance): half a unit of the last printed digit unless noted.

TR_SAMPLE1 = {
    # virtual cylindrical gears, [ISO10300-1] annex A
    "d_v1": (58.350, 0.0005), "d_v2": (452.804, 0.0005), "alpha_vet": (23.957, 0.0005),
    "z_v1": (14.875, 0.0005), "z_v2": (115.431, 0.0005), "beta_vb": (32.615, 0.0005),
    # d_va1 printed 68.023 from h_am1 = 4.837 (printed to 3 decimals); ours 68.0216 from
    # h_am1 = 4.8360 (the [BevGear2023] value above): one unit of the input's last digit
    "d_va1": (68.023, 0.002), "d_va2": (455.984, 0.002),
    "d_vb1": (53.323, 0.0005), "d_vb2": (413.796, 0.0005), "p_vet": (11.262, 0.0005),
    "g_va": (13.120, 0.001), "eps_va": (1.165, 0.0005), "b_eff": (21.590, 0.0005),
    "eps_vb": (1.227, 0.0005), "eps_vg": (2.392, 0.0005), "rho_rel": (12.459, 0.001),
    "z_vn1": (25.594, 0.0005), "z_vn2": (198.613, 0.0005), "l_bm": (22.442, 0.002),
    # forces and factors, [ISO10300-1] §6, §8
    "F_mt": (10925.3, 0.05 + 0.06),   # printed from d_m1 = 54.918, ours 54.9185
    "F_n": (14193.3, 0.05 + 0.08), "K_Hbeta": (1.650, 0.0005),
    # contact, [ISO10300-2] method B1: Z_LS 0.9339 against 0.935 and σ_H0 0.07 % low,
    # the same 0.1 % the transcribing calculator reports for its own run
    "Z_MB": (0.916, 0.0005), "Z_LS": (0.935, 0.0012), "Z_E": (191.646, 0.0005),
    "sigma_H0": (1168.5, 1.0), "sigma_H": (1712.8, 1.5),
    # bending, [ISO10300-3] method B1
    "Y_LS": (0.873, 0.0012), "Y_eps": (0.625, 0.0005), "Y_BS": (1.054, 0.0005),
    "Y_Fa1": (2.033, 0.002), "Y_Sa1": (2.022, 0.001), "Y_Fa2": (2.480, 0.0012),
    "Y_Sa2": (1.706, 0.001),
    # σ_F02 0.17 % low: the printed factors Y_Fa2·Y_Sa2·Y_ε·Y_BS·Y_LS (each to 3 decimals)
    # fix the product only to ±0.2 %, and ours match each at its printed precision
    "sigma_F01": (316.5, 0.4), "sigma_F02": (325.9, 0.6),
    "sigma_F1": (680.1, 0.9), "sigma_F2": (700.1, 0.9),
}


def _tr_sample1():
    from geardesign.bevel import rating as R
    from geardesign.bevel.forces import forces
    from geardesign.bevel.inputs import Inputs, Load, Material, Rating

    m_mn = 3.2133
    pair = Pair(True, 176.893 / 39, "outer", 14, 39, math.pi / 2, 25.4, math.radians(35.0),
                "left", math.radians(20.0), 1.0, 0.25, 0.8 / m_mn, 0.505, 2.0 * 0.036,
                "constant_clearance", xt2=2.0 * -0.055, rho_a02=1.2 / m_mn)
    inp = Inputs(pair, Load(300e3, 1200.0, "cw", "pinion", 1.1, 1.020, "one_straddle", 1.161),
                 Material((1500.0, 1500.0), (480.0, 480.0), "both_hard", 210000.0, 0.3),
                 Rating("iso10300", 1.0, 1.3))
    g = pair_geometry(pair)
    f = forces(inp, g)
    return g, f, R.iso_rating(inp, g, f)


def _tr_ours() -> dict[str, float]:
    g, f, r = _tr_sample1()
    P, W = g.members
    return {
        "d_v1": P.d_v, "d_v2": W.d_v, "alpha_vet": math.degrees(g.alpha_vt), "z_v1": P.z_v,
        "z_v2": W.z_v, "beta_vb": math.degrees(g.beta_vb), "d_va1": P.d_va, "d_va2": W.d_va,
        "d_vb1": P.d_vb, "d_vb2": W.d_vb, "p_vet": g.p_vet, "g_va": g.g_va,
        "eps_va": g.eps_va, "b_eff": g.b_eff, "eps_vb": g.eps_vb, "eps_vg": g.eps_vg,
        "rho_rel": g.rho_rel, "z_vn1": P.z_vn, "z_vn2": W.z_vn, "l_bm": r.l_bm,
        "F_mt": f.F_mt, "F_n": r.F_n, "K_Hbeta": r.K_Hbeta, "Z_MB": r.Z_MB, "Z_LS": r.Z_LS,
        "Z_E": r.Z_E, "sigma_H0": r.sigma_H0, "sigma_H": r.sigma_H, "Y_LS": r.Y_LS,
        "Y_eps": r.Y_eps, "Y_BS": r.Y_BS, "Y_Fa1": r.pinion.Y_Fa, "Y_Sa1": r.pinion.Y_Sa,
        "Y_Fa2": r.wheel.Y_Fa, "Y_Sa2": r.wheel.Y_Sa, "sigma_F01": r.pinion.sigma_F0,
        "sigma_F02": r.wheel.sigma_F0, "sigma_F1": r.pinion.sigma_F,
        "sigma_F2": r.wheel.sigma_F,
    }


@pytest.mark.parametrize("key", sorted(TR_SAMPLE1))
def test_iso_tr_10300_30_sample1(key):
    value, tol = TR_SAMPLE1[key]
    assert _tr_ours()[key] == pytest.approx(value, abs=tol)
