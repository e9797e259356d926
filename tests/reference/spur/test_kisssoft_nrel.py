"""Helical pair from a printed KISSsoft report (DIN 3960:1987 geometry).

Source: KISSsoft Release 03/2017 A, "CALCULATION OF A HELICAL GEAR PAIR", NREL 5 MW
drivetrain stage 3, GitHub ``gfsReboucas/Drivetrain``, file ``@NREL_5MW/stage_03.rtf``,
commit 2a41bf1ce829b76800693e2b52c91e5f74d074d4.  Reference profile 1.25/0.38/1.0
(ISO 53 profile A = GOST 13755-81 rack), a = 861 mm given, x1 = 0.48, x2 derived.

KISSsoft rounds the tip alteration to k·m_n = −0.938 mm before computing d_a (exact:
−0.93760), so d_a, and the values that depend on it (s_an, the start of active profile
d_Nf = our d_p of the mate), carry up to 0.0015 mm of that rounding: tolerance 0.002 mm.
Other lengths: printed to 0.001 mm, tolerance 0.0006 mm.  "dMWk.m" (calliper contact
diameter) is printed for the mean W with tooth-thickness allowances; the test feeds that W
to the same relation.
"""

import math

from geardesign.gears.span import base_tangent_length
from tests.conftest import assert_ref, flat, spur

GEAR = {"module": 14.0, "z1": 24, "z2": 95, "helix_angle": 10.0, "face_width": 360.0,
        "center_distance": 861.0, "x1": 0.48}

EXPECTED = {  # key: (printed value, tolerance)
    "u": (3.958, 0.0006), "m_t": (14.216, 0.0006), "alpha_t": (20.284, 0.0006),
    "alpha_tw": (22.856, 0.0006), "beta_b": (9.391, 0.0006), "a": (845.850, 0.0006),
    "x_sum": (1.1491, 0.00006), "x2": (0.6691, 0.00006),
    "d1": (341.183, 0.0006), "d2": (1350.517, 0.0006),
    "d_b1": (320.026, 0.0006), "d_b2": (1266.770, 0.0006),
    "d_w1": (347.294, 0.0006), "d_w2": (1374.706, 0.0006),
    "d_f1": (319.623, 0.0006), "d_f2": (1334.252, 0.0006),
    "d_a1": (380.747, 0.002), "d_a2": (1395.376, 0.002),
    "c_12": (3.500, 0.0006), "c_21": (3.500, 0.0006),
    "h1": (30.562, 0.002), "h2": (30.562, 0.002),
    "s_an1": (8.800, 0.002), "s_an2": (11.034, 0.002),
    "d_p1": (330.798, 0.002), "d_p2": (1348.584, 0.002),
    "p_bt": (41.891, 0.0006), "g_alpha": (61.276, 0.002), "g_w": (334.426, 0.0006),
    "eps_alpha": (1.463, 0.0006), "eps_beta": (1.421, 0.0006), "eps_gamma": (2.884, 0.0006),
    "k1": (4, 0), "k2": (13, 0), "W1": (154.167, 0.0006), "W2": (542.490, 0.0006),
    "s_n1": (26.883, 0.0006), "s_n2": (28.810, 0.0006),
}


def test_kisssoft_report_values():
    values = flat(spur(GEAR))
    for key, (expected, tol) in EXPECTED.items():
        assert_ref(values[key], expected, tol, f"KISSsoft NREL stage 3: {key}")


def test_kisssoft_calliper_contact_diameter():
    v = flat(spur(GEAR))
    for i, (w_lo, w_hi, d_mw) in ((1, (154.045, 153.989, 354.269)),
                                  (2, (542.264, 542.171, 1375.092))):
        k = v[f"k{i}"]
        W_mean = 0.5 * (w_lo + w_hi)
        # the relation tan α_W = W cos²β_b/(z m_n cos α) at KISSsoft's mean W
        tan_aw = W_mean * math.cos(math.radians(v["beta_b"])) ** 2 / (
            GEAR[f"z{i}"] * 14.0 * math.cos(math.radians(20.0)))
        d = v[f"d_b{i}"] * math.sqrt(1 + tan_aw ** 2)
        assert_ref(d, d_mw, 0.0006, f"KISSsoft dMWk.m{i}")
        # and at the nominal W, the same relation gives our d_W
        _, W, d_W = base_tangent_length(GEAR[f"z{i}"], v[f"x{i}"], 14.0, math.radians(20.0),
                                        math.radians(v["alpha_t"]), math.radians(v["beta_b"]),
                                        v[f"d{i}"], v[f"d_b{i}"], k)
        assert abs(d_W - v[f"d_W{i}"]) < 1e-9 and abs(W - v[f"W{i}"]) < 1e-9
