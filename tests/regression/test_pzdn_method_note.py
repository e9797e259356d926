"""Our recomputations of [Lopukhov] (values the thesis does not print). Regression values, not
truth: the hand calculation computed them with the same formulas (pure python, explicit integration
with dt = 10 µs); tolerances as in the hand calculation.
"""

import math

import pytest

from geardesign.core.registry import run_data
from geardesign.pzdn import spring as SP
from geardesign.pzdn.simulate import Motor, simulate
from geardesign.pzdn.startup import ThreeMass, solve
from tests.conftest import assert_ref

D1 = dict(T1=26.5, T2=4.4, T3=17.7, J1=0.038, J2=0.026, J3=0.021)


def pzdn(**tables) -> dict:
    return run_data({"kind": "pzdn", **tables}).document()["results"]


def test_s1_single_spring():
    """PZDN-S1: d_min = 5.88 mm, J = 63.62 mm⁴, C = EJ/L = 18.14 N·m/rad, twist at
    22.1 N·m = 1.218 rad, σ = 1129 MPa with k = 1.0833."""
    v = pzdn(spring=[{"torque": 22.1, "wire_diameter": 6.0, "index": 10.0,
                      "coil_diameter": 60.0, "coils": 4, "pitch": 8.0, "E": 215000.0,
                      "sigma_allow": 1200.0}])["spring1"]
    assert_ref(v["d_min"], 5.88, 0.005, "d_min")
    assert_ref(v["J"], 63.62, 0.005, "J")
    assert_ref(v["C"], 18.14, 0.005, "C")
    assert_ref(math.radians(v["phi_T"]), 1.218, 0.006, "twist at T")
    assert_ref(v["sigma"], 1129.0, 0.5, "σ with k = 1.0833")


@pytest.mark.parametrize("T, c, d, D, i, expected", [
    (30.0, 8, 6.5, 60.0, 4, dict(k=1.1071, d_min=6.09, J=87.62, L=753.98, phi=1.2007,
                                 C=24.99, sigma=1232.0)),
    (7.5, 12, 4.5, 55.0, 3, dict(k=1.0682, d_min=3.79, J=20.13, L=518.4, phi=0.898,
                                 C=8.35, sigma=896.0)),
])
def test_s2_two_springs(T, c, d, D, i, expected):
    """PZDN-S2a/S2b (±0.5 %)."""
    s = SP.design(SP.SpringInput(T=T, E=2.15e5, sigma_allow=1500.0, d=d, c=c, D=D, i=i))
    got = dict(k=s.k, d_min=s.d_min, J=s.J, L=s.L, phi=s.phi_T, C=s.C, sigma=s.sigma)
    for key, value in expected.items():
        assert_ref(got[key], value, 0.005 * abs(value), key)


def test_curvature_factors_at_c10():
    """[Lopukhov] §2.1: 1.0833 (thesis), 1.0806 (Wahl K_i), 1.0886 (EN 13906-3 q)."""
    assert_ref(SP.curvature_factor(10.0, "thesis"), 1.0833, 0.00005, "(4c − 1)/(4c − 4)")
    assert_ref(SP.curvature_factor(10.0, "wahl"), 1.0806, 0.00005, "K_i")
    assert_ref(SP.curvature_factor(10.0, "en13906"), 1.0886, 0.00005, "q")


def test_mean_vs_outer_diameter():
    """[Lopukhov] §2.2: with the mean diameter D − d the stiffness rises about 12 %:
    spring 10 (i = 4) 28.0 instead of 25.0 N·m/rad, spring 11 (i = 3) 9.09 instead of 8.34."""
    a = pzdn(spring=[{"torque": 30.0, "wire_diameter": 6.5, "index": 8.0,
                      "coil_diameter": 60.0, "diameter_basis": "outer", "coils": 4,
                      "E": 215000.0, "sigma_allow": 1500.0}])["spring1"]
    b = pzdn(spring=[{"torque": 7.5, "wire_diameter": 4.5, "index": 12.0,
                      "coil_diameter": 55.0, "diameter_basis": "outer", "coils": 3,
                      "E": 215000.0, "sigma_allow": 1500.0}])["spring1"]
    assert_ref(a["C"], 28.0, 0.05, "spring 10, mean diameter")
    assert_ref(b["C"], 9.09, 0.01, "spring 11, mean diameter")


def test_d1_stage_details():
    """PZDN-D1 ([Lopukhov] appendix B): amplitudes with the corrected signs."""
    cf = solve(ThreeMass(**D1, C12=8.33, C13=25.0), 2.0)
    s2, s3 = cf.stages[1], cf.stages[2]
    a2, a3 = s2.amplitudes(), s3.amplitudes()
    for got, exp in ((a2[0][0], -2.537), (a2[1][0], 2.537), (a2[0][3], -5.132),
                     (a2[1][3], -3.763), (a2[0][1], 7.537), (a2[1][1], -3.520),
                     (a2[0][4], 15.247), (a2[1][4], 5.221)):
        assert_ref(got, exp, 0.001, "stage 2 amplitude")
    for got, exp in ((a3[0][0], -0.148), (a3[1][0], 0.294), (a3[0][3], -0.950),
                     (a3[1][3], -0.137), (a3[0][1], 2.215), (a3[1][1], 4.557),
                     (a3[0][4], 14.255), (a3[1][4], -2.125), (a3[0][2], 2.220),
                     (a3[1][2], 4.566), (a3[0][5], 14.287), (a3[1][5], 2.129)):
        assert_ref(got, exp, 0.001, "stage 3 amplitude")
    x, dx = s2.torques(s2.t1), s2.rates(s2.t1)
    assert_ref(x[0], 5.893, 0.001, "T12(τ2)")
    assert_ref(dx[0], 193.1, 0.05, "T12'(τ2)")
    assert_ref(dx[1], 585.1, 0.05, "T13'(τ2)")


def test_d1_integration_with_and_without_stick():
    """PZDN-D1, 0…2 s: without sticking 12.44 / 35.03 N·m, with sticking 11.87 / 33.72 N·m
    (±1 %); mass 3 runs backwards to about −2.3 rad/s in the linear solution."""
    m = ThreeMass(**D1, C12=8.33, C13=25.0)
    free = simulate(m, Motor(T1=26.5), 2.0, stick=False)
    assert_ref(free.T12_max, 12.44, 0.12, "T12max, no stick")
    assert_ref(free.T13_max, 35.03, 0.35, "T13max, no stick")
    assert_ref(free.w_min[1], -2.3, 0.05, "lowest speed of mass 3")
    stuck = simulate(m, Motor(T1=26.5), 2.0, stick=True)
    assert_ref(stuck.T12_max, 11.87, 0.12, "T12max, stick")
    assert_ref(stuck.T13_max, 33.72, 0.34, "T13max, stick")
    assert_ref(stuck.t_break[1], 0.04933, 0.00001, "break-away of mass 3")


def test_d2_mass_three_first():
    """PZDN-D2 (text variant 6.25 / 33.3): mass 3 breaks away first (0.0422 s), mass 2 at
    0.0503 s; integration over 2 s 11.42 / 35.45 N·m."""
    m = ThreeMass(**D1, C12=6.25, C13=33.3)
    cf = solve(m, 2.0)
    assert cf.order == "3 first"
    assert_ref(cf.t_break[1], 0.0422, 0.00005, "mass 3")
    assert_ref(cf.t_break[0], 0.0503, 0.00005, "mass 2")
    sim = simulate(m, Motor(T1=26.5), 2.0, stick=True)
    assert_ref(sim.T12_max, 11.42, 0.12, "T12max")
    assert_ref(sim.T13_max, 35.45, 0.36, "T13max")


@pytest.mark.parametrize("C", [100.0, 1940.0, 5000.0])
def test_d3_scaling_property(C):
    """PZDN-D3: with a step torque and no damping k12 = 4.670, k13 = 1.922 for any common
    stiffness."""
    cf = solve(ThreeMass(**D1, C12=C, C13=C), 2.0)
    p = cf.peak()
    assert_ref(p[0] / 4.4, 4.670, 0.001, "k12")
    assert_ref(p[1] / 17.7, 1.922, 0.001, "k13")


def test_ramp_soft_vs_stiff():
    """[Lopukhov] appendix B: with a 15 ms torque ramp the stiff variant (833 / 2500 N·m/rad)
    gives k12 = 1.82, k13 = 1.39 within 1 s; the soft PZDN springs (8.33 / 25) k12 = 2.65."""
    ramp = Motor(T1=26.5, rise_time=0.015)
    stiff = simulate(ThreeMass(**D1, C12=833.0, C13=2500.0), ramp, 1.0, stick=False)
    soft = simulate(ThreeMass(**D1, C12=8.33, C13=25.0), ramp, 1.0, stick=False)
    assert_ref(stiff.T12_max / 4.4, 1.82, 0.01, "k12 stiff")
    assert_ref(stiff.T13_max / 17.7, 1.39, 0.01, "k13 stiff")
    assert_ref(soft.T12_max / 4.4, 2.65, 0.01, "k12 soft")


def test_r1_regression_table():
    """[Lopukhov] §2.3 (±0.1 %)."""
    res = pzdn(regression={"C12": 24.7, "sweep": [24.7, 100.0, 500.0, 1000.0, 1940.0,
                                                  2730.0]})["regression_sweep"]
    exp12 = [79.906, 79.884, 79.796, 79.752, 79.873, 80.180]
    exp23 = [48.093, 48.852, 52.526, 56.269, 60.747, 61.927]
    for got, exp in zip(res["T12max"], exp12):
        assert_ref(got, exp, 0.001 * exp, "T12max")
    for got, exp in zip(res["T23max"], exp23):
        assert_ref(got, exp, 0.001 * exp, "T23max")
    assert_ref(res["k23"][4], 3.432, 0.001, "k23 without the PZDN")
