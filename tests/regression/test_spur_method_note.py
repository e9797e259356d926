"""Regression values: our recomputations of the published methods, not published numbers. They guard
against unintended changes;
the published references are in ``tests/reference/spur``."""

import pytest

from tests.conftest import flat, spur

CASES = {
    "V1 Ishin 13/69 (S)": (
        {"module": 6.5, "z1": 13, "z2": 69, "x1": 0.3077, "face_width": 44.0},
        {"alpha_tw": 21.1125, "a_w": 268.448, "y": 0.2996, "delta_y": 0.0081, "d_w1": 85.118,
         "d_w2": 451.778, "d_a1": 101.395, "d_a2": 461.395, "d_f1": 72.250, "d_f2": 432.250,
         "eps_alpha": 1.497, "s_an1": 3.041, "s_an2": 5.197, "x_min1": 0.2396, "rho_l1": 1.293,
         "rho_p1": 2.802, "theta1_A": -5.31, "theta2_E": -1.57},
    ),
    "V5 Dobrov 18/34 (S)": (
        {"module": 1.0, "z1": 18, "z2": 34, "face_width": 10.0},
        {"eps_alpha": 1.6052, "g_w": 8.8925, "rho_p1": 0.5976, "rho_a1": 5.3362,
         "theta1_A": -6.349, "theta2_E": -1.834, "sigma12_A": -0.864, "sigma12_E": 0.647},
    ),
    "V6 helical 21/79 (S)": (
        {"module": 3.0, "z1": 21, "z2": 79, "helix_angle": 12.0, "x1": 0.3, "face_width": 50.0},
        {"alpha_t": 20.4103, "alpha_tw": 21.2735, "beta_b": 11.2665, "a": 153.351,
         "a_w": 154.233, "y": 0.2940, "delta_y": 0.0060, "d1": 64.407, "d2": 242.295,
         "d_w1": 64.778, "d_a1": 72.172, "d_a2": 248.259, "d_f1": 58.707, "d_f2": 234.795,
         "eps_alpha": 1.5486, "eps_beta": 1.1030, "s_an1": 1.815},
    ),
}


@pytest.mark.parametrize("name", CASES)
def test_method_note_recomputation(name):
    gear, expected = CASES[name]
    v = flat(spur(gear))
    for key, value in expected.items():
        decimals = len(repr(value).split(".")[1]) if "." in repr(value) else 0
        assert abs(v[key] - value) <= 1.01 * 10 ** -decimals, (name, key, v[key], value)


def test_v5_velocities_per_rad_s():
    """V5: sliding velocities for ω1 = 1 rad/s (n1 = 30/π min⁻¹), in mm/s."""
    import math

    v = flat(spur({"module": 1.0, "z1": 18, "z2": 34, "face_width": 10.0},
                  load={"speed1": 30.0 / math.pi}))
    assert abs(v["v_s_A"] * 1000 - (-3.794)) < 0.0006
    assert abs(v["v_s_E"] * 1000 - 3.453) < 0.0006
