"""KHK Gear Technical Reference worked examples (also printed in SDP/SI "Elements of
Metric Gear Technology"), as reproduced in the public NUnit tests of GitHub
``bolsover/UtilitiesForAlibre`` (commit e2439210dac6746f4cd3c35a70266585daebde34):
``UnitTests/Involute/Calculator/ProfileShiftedExternalSpurGearCalculatorTest.cs`` and
``ProfileShiftedExternalHelicalGearCalculatorTest.cs``; the helical page is
http://bolsover.com/utilitiesforalibre/profile-shifted-external-helical-gear-normal.html.

KHK's addendum h_a1 = (1 + y − x2)m is the GOST tip diameter with the Δy shortening, so
the values compare directly.  Tolerances: one unit of the printed last digit (the sources
truncate as often as they round), 0.001 mm on d_f1 (KHK adds rounded h_f to rounded d).
"""

from tests.conftest import assert_ref, flat, spur

SPUR = {  # m = 3, z = 12/24, x = 0.6/0.36: the classic profile-shifted spur example
    "gear": {"module": 3.0, "z1": 12, "z2": 24, "x1": 0.6, "x2": 0.36, "face_width": 20.0},
    "expected": {
        "x_sum": (0.96, 1e-9), "a": (54.000, 0.0005), "alpha_tw": (26.0886, 0.00005),
        "y": (0.83329, 0.000005), "a_w": (56.4999, 0.00005),
        "d1": (36.000, 0.0005), "d2": (72.000, 0.0005),
        "d_w1": (37.667, 0.0005), "d_w2": (75.333, 0.0005),
        "h1": (6.369, 0.001), "h2": (6.369, 0.001),
        "d_f1": (32.100, 0.0005), "d_f2": (66.660, 0.0005),
    },
}

HELICAL = {  # m_n = 3, β = 30°, z = 12/60, a = 125 given, x_n1 = 0.09809
    "gear": {"module": 3.0, "z1": 12, "z2": 60, "helix_angle": 30.0, "face_width": 20.0,
             "center_distance": 125.0, "x1": 0.09809},
    "expected": {
        "x_sum": (0.098089, 1e-06), "x2": (0.0, 1e-01), "m_t": (3.46410, 1e-05),
        "a": (124.70765, 1e-05), "alpha_t": (22.79588, 1e-05),
        "alpha_tw": (23.11263, 1e-05), "y": (0.097447, 1e-06),
        "d1": (41.5692, 1e-04), "d2": (207.8460, 1e-04),
        "d_b1": (38.3222, 1e-04), "d_b2": (191.6114, 1e-04),
        "d_w1": (41.6666, 1e-04), "d_w2": (208.3333, 1e-04),
        "d_a1": (48.1539, 1e-04), "d_a2": (213.8422, 1e-04),
        "d_f1": (34.657, 0.001), "d_f2": (200.346, 1e-03),
        "h1": (6.7480, 1e-04),
        "eps_alpha": (1.2939, 1e-04), "eps_beta": (1.061, 1e-03),
    },
}


def test_khk_profile_shifted_spur():
    values = flat(spur(SPUR["gear"]))
    for key, (expected, tol) in SPUR["expected"].items():
        assert_ref(values[key], expected, tol, f"KHK spur: {key}")
    # KHK h_a = (1 + y − x_mate)m
    assert_ref(values["d_a1"], 36 + 2 * (1 + 0.83329 - 0.36) * 3, 0.001, "KHK spur: d_a1")


def test_khk_helical_normal_system():
    values = flat(spur(HELICAL["gear"]))
    for key, (expected, tol) in HELICAL["expected"].items():
        assert_ref(values[key], expected, tol, f"KHK helical: {key}")
