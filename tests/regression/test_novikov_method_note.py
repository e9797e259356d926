"""Regression values: our own evaluations of [Korotkin2017] and [Matyushenko2017], not published
numbers. The published references are in
``tests/reference/novikov``."""

import math

import pytest

from geardesign.core.registry import run
from geardesign.novikov.factors import k_f, k_h, k_psi, k_w
from geardesign.novikov.rack import standard_rack
from geardesign.novikov.stress import (
    ellipse_coefficient,
    force_for_sigma_F,
    force_for_sigma_H,
    reduced_modulus,
)
from geardesign.novikov.tables import KH_PSI, KH_ROWS
from tests.conftest import SPECS, flat

PSI = (0.05, 0.10, 0.15, 0.20, 0.25)
# [Korotkin2017] tables 2-4: K_W(t, ψ) and K_F(t, ψ), our evaluation of polynomials (1), (6)
KW = {
    0.0: (1.002, 0.998, 1.000, 1.005, 1.010), 0.1: (1.004, 1.007, 1.004, 1.006, 1.011),
    0.2: (1.004, 1.006, 1.010, 1.023, 1.040), 0.25: (1.013, 1.015, 1.028, 1.050, 1.075),
    0.3: (1.033, 1.042, 1.067, 1.098, 1.131), 0.35: (1.069, 1.098, 1.135, 1.175, 1.213),
    0.4: (1.149, 1.202, 1.247, 1.287, 1.322), 0.45: (1.373, 1.398, 1.421, 1.441, 1.458),
    0.475: (1.602, 1.556, 1.541, 1.536, 1.533), 0.5: (1.967, 1.776, 1.691, 1.642, 1.609),
}
KF = {
    0.0: (1.002, 1.008, 0.994, 1.005, 1.032), 0.1: (1.025, 1.020, 0.999, 1.011, 1.043),
    0.2: (1.003, 1.007, 0.994, 1.021, 1.072), 0.25: (1.027, 1.022, 1.009, 1.043, 1.104),
    0.3: (1.054, 1.050, 1.042, 1.086, 1.157), 0.35: (1.066, 1.085, 1.095, 1.154, 1.239),
    0.4: (1.167, 1.183, 1.200, 1.268, 1.360), 0.45: (1.556, 1.442, 1.408, 1.449, 1.525),
    0.475: (1.849, 1.615, 1.530, 1.543, 1.601), 0.5: (2.065, 1.726, 1.597, 1.586, 1.627),
}


@pytest.mark.parametrize("t", KW)
def test_kw_kf_test_vectors(t):
    for psi, w, f in zip(PSI, KW[t], KF[t]):
        assert abs(k_w(t, psi) - w) <= 1.01e-3, (t, psi)
        assert abs(k_f(t, psi) - f) <= 1.01e-3, (t, psi)


def test_k_psi_nodes():
    for psi, value in zip(PSI, (0.724, 0.936, 0.923, 0.878, 0.794)):
        assert abs(k_psi(psi) - value) < 5e-4


def test_k_h_reproduces_table4_at_its_nodes():
    for t, row in KH_ROWS:
        for psi, value in zip(KH_PSI, row):
            assert abs(k_h(t, psi) - value) < 1e-12


def test_factors_clamp_psi_and_t():
    assert k_w(0.5, 0.0) == k_w(0.5, 0.05) and k_w(0.5, 0.4) == k_w(0.5, 0.25)
    assert k_f(0.7, 0.1) == k_f(0.5, 0.1)
    assert k_psi(0.0) == k_psi(0.05) and k_psi(0.3) == k_psi(0.25)
    assert k_h(0.5, 0.01) == k_h(0.5, 0.05)


@pytest.fixture(scope="module")
def v():
    return flat(run(SPECS / "novikov_korotkin2017.toml").document())


def test_derived_geometry_of_the_example(v):
    """[Korotkin2017] fig. 1, "derived quantities for the same example"."""
    expected = {"d1": 130.120, "d2": 769.880, "a_w": 450.000, "u": 5.9167, "p_x": 81.249,
                "z_v1": 15.2995, "z_v2": 90.522, "l_k": 8.59, "rho_p": 819.9,
                "d_a1": 148.12, "d_f1": 109.12, "d_a2": 787.88, "d_f2": 748.88}
    for key, value in expected.items():
        decimals = len(repr(value).split(".")[1])
        assert abs(v[key] - value) <= 1.01 * 10 ** -decimals, (key, v[key], value)


def test_first_points_of_the_phase_groups(v):
    """[Korotkin2017] fig. 1: b at phases 1, 9, 16."""
    for k, expected in ((1, (0, 0.2753, 0.4276, 0.7029, 0.8553)),
                        (9, (0.0106, 0.1629, 0.4382, 0.5905, 0.8658)),
                        (16, (0.1531, 0.3054, 0.5807, 0.7331))):
        got = v["b"][k - 1]
        assert len(got) == len(expected)
        assert all(abs(a - b) < 6e-5 for a, b in zip(got, expected)), (k, got)


def test_error_free_maxima(v):
    """[Korotkin2017] fig. 1: error-free, linear compliance: σ_F,max ≈ 254 MPa, σ_H,max ≈ 504."""
    assert abs(v["sigma_F_max_ideal"] - 254.0) < 1.0
    assert abs(v["sigma_H_max_ideal"] - 504.0) < 1.0


def test_back_solved_forces():
    """[Korotkin2017] fig. 1: F ≈ 75.7 kN from σ_H = 1111.429, ≈ 71.5 kN from σ_F = 662.003
    (±2 %)."""
    r = standard_rack()
    beta = math.radians(22.747)
    a_w, u = 830 / (2 * math.cos(beta)), 71 / 12
    rho_p = a_w * u / ((u + 1) ** 2 * math.sin(beta) ** 2 * math.sin(r.alpha_k))
    k_a = ellipse_coefficient(rho_p, 8.59, r.alpha_k, reduced_modulus(2.1e5, 0.3))
    F_H = force_for_sigma_H(1111.429, 0.5 - 0.010552, 8.59, rho_p, r.alpha_k, k_a, 190.0)
    F_F = force_for_sigma_F(662.003, 0.5 - 0.030915, 10.0, 0.520, k_a, 190.0)
    assert abs(F_H.F / 75.7e3 - 1) < 0.02 and abs(F_H.psi - 0.050) < 0.002
    assert abs(F_F.F / 71.5e3 - 1) < 0.02 and abs(F_F.psi - 0.048) < 0.002


def test_own_model_on_the_example(v):
    """This tool's design values for the printed example (regression of our model)."""
    assert abs(v["sigma_F_max"] - 562.93) < 0.01
    assert abs(v["sigma_H_max"] - 872.27) < 0.01
    assert abs(v["c_p"] - 735.15) < 0.01
    assert abs(v["e_p"] - 65.326) < 0.001 and abs(v["e_l"] - 29.497) < 0.001
