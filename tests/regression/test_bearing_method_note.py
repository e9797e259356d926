"""Regression values: the synthetic cases S1–S12 and the a_ISO table ([ISO281] formulas), recomputed
with the
same formulas.  They are not published numbers; they guard against unintended changes.  The
published references are in ``tests/reference/bearing``."""

import pytest

from geardesign.bearing import life as L
from geardesign.bearing import load_factors as LF
from geardesign.bearing import a_iso as AI
from tests.conftest import flat
from geardesign.core.registry import run_data


def run(method, bearing, load, **tables):
    data = {"kind": "bearing", "method": method, "bearing": bearing, "load": load}
    data.update(tables)
    return flat(run_data(data).document())


def close(a, b, digits):
    return abs(a - b) <= 1.01 * 10 ** -digits


BASE = {"type": "deep_groove_ball", "C_r": 32500.0, "C_0r": 19000.0}
LOAD = {"F_r": 3000.0, "F_a": 1000.0, "speed": 1000.0}


def test_s1_s3_iso_basic_and_modified():
    v = run("iso281_2007", {**BASE, "f0": 14.0, "D_pw": 60.0, "C_u": 800.0}, LOAD,
            lubrication={"viscosity": 20.0, "e_C": 0.5}, requirements={"reliability": 95.0})
    assert close(v["entry"], 0.7368, 4) and close(v["e"], 0.2628, 4) and close(v["Y"], 1.6876, 4)
    assert close(v["P"], 3367.6, 1) and close(v["L10"], 898.9, 1) and close(v["L10h"], 14982, 0)
    assert close(v["nu1"], 18.371, 3) and close(v["kappa"], 1.0887, 4)
    assert close(v["eC_Cu_P"], 0.11878, 5) and close(v["a_ISO"], 3.284, 3)
    assert close(v["L_nmh"], 31487, 0)          # a1 = 0.64 (R = 95 %)


def test_s2_gost_with_russian_factors():
    v = run("gost18855_94", BASE, LOAD, factors={"K_b": 1.3, "a23": 0.75},
            requirements={"reliability": 95.0})
    assert close(v["e"], 0.2552, 4) and close(v["Y"], 1.7437, 4)
    assert close(v["P"], 4450.8, 1) and close(v["L10"], 389.35, 2)
    assert close(v["L10h"], 6489, 0) and close(v["L_sah"], 3017, 0)
    iso_table = run("gost18855_94", {**BASE, "f0": 14.0}, LOAD, factors={"K_b": 1.3, "a23": 0.75},
                    requirements={"reliability": 95.0})
    assert close(iso_table["P"], 4377.8, 1) and close(iso_table["L10h"], 6819, 0)
    assert close(iso_table["L_sah"], 3171, 0)


def test_s4_s5_s6_rating_from_geometry():
    g = L.dynamic_rating("deep_groove_ball", 9, 12.7, 60.0)
    assert close(g.gamma, 0.21167, 5) and close(g.f_c, 59.725, 3) and close(g.C_r, 32592, 0)
    big = L.dynamic_rating("deep_groove_ball", 12, 30.0, 300.0)
    assert close(big.C_r, 161286, 0)
    lo = L.dynamic_rating("deep_groove_ball", 12, 25.4, 254.0).C_r
    hi = 3.647 * 1.3 * 55.5 * 12 ** (2 / 3) * 25.4 ** 1.4
    assert close(lo, 127758.9, 1) and close(hi, 127759.6, 1)
    r = L.dynamic_rating("cylindrical_roller", 14, 11.0, 65.0, L_we=11.0)
    assert close(r.gamma, 0.16923, 5) and close(r.f_c, 88.685, 3) and close(r.C_r, 59888, 0)


def test_s7_spectrum_and_miner():
    v = run("gost18855_94", {"type": "deep_groove_ball", "C_r": 32500.0},
            {"spectrum": [{"F_r": 4000.0, "speed": 1000.0, "time_share": 0.3},
                          {"F_r": 2500.0, "speed": 1500.0, "time_share": 0.5},
                          {"F_r": 6000.0, "speed": 500.0, "time_share": 0.2}]},
            factors={"a23": 1.0})
    assert close(v["P_m"], 3574.4, 1) and close(v["n_m"], 1150, 0)
    assert close(v["L10"], 751.68, 2) and close(v["L10h"], 10894, 0)
    lives = [L.hours(L.basic_life(32500.0, P, 3), n) for P, n in ((4000, 1000), (2500, 1500),
                                                                  (6000, 500))]
    assert close(L.miner_hours(lives, [0.3, 0.5, 0.2]), 10894, 0)


@pytest.mark.parametrize("regime, hours", [("0", 4577), ("I", 8940), ("II", 18305),
                                           ("III", 26063), ("IV", 36617), ("V", 71517)])
def test_s8_typical_regimes(regime, hours):
    v = run("gost18855_94", {"type": "deep_groove_ball", "C_r": 32500.0},
            {"F_r": 5000.0, "speed": 1000.0, "regime": regime}, factors={"a23": 1.0})
    assert close(v["L10h"], hours, 0)


def test_s10_tapered_equivalent_load():
    lf = LF.load_factors("tapered_roller", 3000.0, 2535.5, e_given=0.37, Y_given=1.6)
    assert close(LF.equivalent_load(3000.0, 2535.5, lf), 5256.8, 1)


def test_s11_required_rating():
    assert close(L.required_rating(3367.6, 20000.0, 1000.0, 3.0), 35786, 0)
    assert close(L.required_rating(3367.6, 20000.0, 1000.0, 3.0, 0.62 * 0.75), 46192, 0)


def test_s12_system_life():
    assert close(L.system_life([14982.0, 30000.0], 1.5), 12248, 0)
    assert close(L.system_life([14982.0, 30000.0], 10 / 9), 10642, 0)


@pytest.mark.parametrize("kind, kappa, r, expected", [
    ("deep_groove_ball", 0.2, 0.1, 0.188), ("deep_groove_ball", 0.5, 0.2, 0.862),
    ("deep_groove_ball", 1.0, 0.1, 2.43), ("deep_groove_ball", 2.0, 0.05, 1.70),
    ("deep_groove_ball", 4.0, 0.2, 33.3), ("cylindrical_roller", 0.5, 0.5, 0.374),
    ("cylindrical_roller", 1.0, 1.0, 5.31), ("cylindrical_roller", 4.0, 0.1, 0.664)])
def test_a_iso_synthetic_table(kind, kappa, r, expected):
    value = AI.a_iso(kind, kappa, 1.0, r * 1000.0, 1000.0).value
    assert abs(value / expected - 1.0) < 0.006, (value, expected)
