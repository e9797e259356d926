"""Regression values: our recomputation of [Tkachenko2017] eqs. (4), (5): K_zh of the five test
racks of Tkachenko et al.
([Tkachenko2017]) from eqs. (4)-(5), GOST 13755 rack, the height correction α_h and the
predicted cantilever forces.  The paper prints no numeric K_zh (its Fig. 3-4 ordinates are
not legible), so these are not published values; the slice-beam reconstruction of eq. (5)
is the hand calculation's.
"""

import math

import pytest

from geardesign.core.registry import run_data
from geardesign.wave_gear import rim as R

RACK = R.rack_space(math.radians(20.0))

# H0/m: (a0 full, K_zh full, a0(0.45), K_zh(0.45), K_zh(0.35), α_h(0.45))
TABLE = {
    1.12: (0.3171, 3.153, 0.5044, 1.983, 1.787, 1.591),
    1.55: (0.3643, 2.745, 0.5871, 1.703, 1.560, 1.612),
    2.06: (0.4130, 2.422, 0.6563, 1.524, 1.416, 1.589),
    2.50: (0.4498, 2.223, 0.7000, 1.428, 1.340, 1.556),
    4.00: (0.5484, 1.823, 0.7913, 1.264, 1.209, 1.443),
}
ALPHA_H = {  # H0/m: α_h at h = 0.25, 0.45, 0.5, 0.75, 1.0, 1.5, 2.0 (× m)
    1.12: (2.001, 1.591, 1.521, 1.285, 1.159, 1.048, 1.009),
    1.55: (1.949, 1.612, 1.550, 1.326, 1.194, 1.064, 1.013),
    2.06: (1.858, 1.589, 1.537, 1.338, 1.211, 1.075, 1.015),
    2.50: (1.781, 1.556, 1.511, 1.334, 1.215, 1.080, 1.017),
    4.00: (1.582, 1.443, 1.413, 1.289, 1.198, 1.081, 1.019),
}
FORCES = {  # H0 mm: (δ mm, P smooth N, P toothed N), E = 206 GPa, b = 10 mm, L = 100 mm
    1.12: (1.8, 1.302, 2.582),
    1.55: (1.8, 3.452, 5.880),
    2.06: (1.8, 8.104, 12.347),
    2.50: (1.8, 14.484, 20.691),
    4.00: (1.0, 32.960, 41.655),
}


def close(actual, printed):
    decimals = len(repr(printed).split(".")[1])
    return abs(actual - printed) <= 0.51 * 10 ** -decimals


def test_rack_space_profile():
    assert close(RACK.x_c, 0.0644)
    assert close(RACK.y_t, 0.25)


@pytest.mark.parametrize("nu", TABLE)
def test_b24_stiffness_factor(nu):
    a0f, kf, a045, k045, k035, ah = TABLE[nu]
    assert close(R.mean_cube(nu, RACK, 2.25), a0f)
    assert close(R.stiffness_factor(nu, RACK, 2.25), kf)
    assert close(R.mean_cube(nu, RACK, 0.45), a045)
    assert close(R.stiffness_factor(nu, RACK, 0.45), k045)
    assert close(R.stiffness_factor(nu, RACK, 0.35), k035)
    assert close(R.mean_cube(nu, RACK, 0.45) / R.mean_cube(nu, RACK, 2.25), ah)


@pytest.mark.parametrize("nu", ALPHA_H)
def test_b24_height_correction(nu):
    full = R.mean_cube(nu, RACK, 2.25)
    for h, printed in zip((0.25, 0.45, 0.5, 0.75, 1.0, 1.5, 2.0), ALPHA_H[nu]):
        assert close(R.mean_cube(nu, RACK, h) / full, printed), (nu, h)


@pytest.mark.parametrize("H0", FORCES)
def test_b24_cantilever_forces(H0):
    delta, p_smooth, p_tooth = FORCES[H0]
    smooth = 3 * 206000.0 * (10.0 * H0 ** 3 / 12.0) * delta / 100.0 ** 3
    assert close(smooth, p_smooth)
    assert close(smooth * R.stiffness_factor(H0, RACK, 0.45), p_tooth)


def test_calculator_reports_the_same_k_zh():
    r = run_data({"kind": "wave_gear",
                  "gear": {"module": 1.0, "flex_teeth": 200, "rim_thickness": 2.06},
                  "material": {"sigma_m1": 450.0, "K_sigma": 1.6}}).document()["results"]
    assert close(r["rim"]["K_zh"], 1.524)
    assert r["rim"]["K0"] == pytest.approx(1.6 * r["rim"]["K_zh"], rel=1e-12)
    assert r["rim"]["alpha_x"] == 1.0
