"""Internal pairs in the spur calculator (``gear.internal = true``) against published
geometry of internal pairs.

1. KHK Gear Technical Reference / SDP/SI "Elements of Metric Gear Technology", Table 5-1
   (profile-shifted internal gear and external gear: m = 3, α = 20°, z1 = 16, z2 = 24,
   x1 = 0, x2 = +0.5, a_x = 13.1683 mm), as reproduced in the public NUnit tests of GitHub
   ``bolsover/UtilitiesForAlibre`` (commit 1308ff3a66b719434834b8b3668b7ae25f07648d),
   ``UnitTests/Involute/Calculator/ProfileShiftedIntExtSpurGearCalculatorTest.cs``
   ([KHK]; [SDPSI] table 5-1; [UtilitiesForAlibre]).  KHK's internal-gear shift has the GOST 19274-73 sign
   (h_a2 = (1 − x2)m), and KHK shortens no tip, as the spur calculator's internal pair
   does not.  Tolerance: one unit of the printed last digit; α_w ±0.0004°, as the test
   computes it from the printed a_x = 13.1683 mm, whose rounding (±0.00005 mm) moves
   α_w by up to 0.00036° and y by up to 0.000017 (tolerance 0.00002).
2. KISSsoft Release 03/2017 A, NREL 5 MW planetary stage 1, planet–ring mesh
   (``@NREL_5MW/stage_01.rtf`` of GitHub ``gfsReboucas/Drivetrain``, commit
   4a88df348fc70d04254c84bd375bb2bab0d15d0d; [KISSsoft2017]): planet z = 17, ring
   z = −56 (ISO), m = 45, a = 863 mm, ring cut by a shaper z0 = 36 with ρ_a0* = 0.30.
   The planet's shift follows from the sun–planet mesh (x_sun = 0.6170 given, x_Σ from
   a = 863 mm), as in KISSsoft.  The planet's tip in KISSsoft carries the Δy shortening of
   its sun mesh, a single internal pair's pinion does not: only quantities that do not
   depend on the pinion tip are compared.  Tolerances as in
   ``tests/reference/planetary/test_kisssoft_nrel_stages.py``.
"""

import math

from geardesign.gears.geometry import shift_sum_for_center_distance
from tests.conftest import assert_ref, flat, spur

KHK = {"internal": True, "module": 3.0, "z1": 16, "z2": 24, "x1": 0.0, "x2": 0.5,
       "face_width": 20.0}
KHK_EXPECTED = {  # key: (printed, tolerance)
    "a": (12.0, 0.001), "a_w": (13.1683, 0.00005), "alpha_tw": (31.0938, 0.0004),
    "y": (0.38943, 0.00002), "x_diff": (0.5, 1e-12),
    "d1": (48.0, 0.001), "d2": (72.0, 0.001), "d_b1": (45.1052, 0.0001),
    "d_b2": (67.6578, 0.0001), "d_w1": (52.6731, 0.0001), "d_w2": (79.0097, 0.0001),
    "d_a1": (54.0, 0.001), "d_a2": (69.0, 0.001), "d_f1": (40.5, 0.001), "d_f2": (82.5, 0.001),
    "eps_alpha": (1.6795, 0.0001),
}


def test_khk_internal_gear_table_5_1():
    v = flat(spur(KHK))
    for key, (expected, tol) in KHK_EXPECTED.items():
        assert_ref(v[key], expected, tol, f"KHK table 5-1: {key}")
    # KHK's inv α_w = 0.060401 and its addenda h_a1 = 3, h_a2 = 1.5, dedenda 3.75, 5.25
    a_w = math.radians(v["alpha_tw"])
    assert_ref(math.tan(a_w) - a_w, 0.060401, 0.0000005, "KHK: inv α_w")
    assert_ref(0.5 * (v["d_a1"] - v["d1"]), 3.0, 0.001, "KHK: h_a1")
    assert_ref(0.5 * (v["d2"] - v["d_a2"]), 1.5, 0.001, "KHK: h_a2")
    assert_ref(0.5 * (v["d_f2"] - v["d2"]), 5.25, 0.001, "KHK: h_f2")


# KHK helical internal pair (normal system), the same source's
# ``ProfileShiftedIntExtHelicalGearCalculatorTest.cs`` (commit
# e2439210dac6746f4cd3c35a70266585daebde34): m_n = 3, β = 30°, z1 = 16, z2 = 24, x1 = 0,
# x2 = 0.04263, a = 14 mm, b = 20 mm (from the printed ε_β).  The printed a = 14 mm and
# x_n2 = 0.04263 do not agree in the normal system: a = 14 mm needs x_n2 − x_n1 =
# (z2 − z1)(inv α_wt − inv α_t)/(2 tan α_n) = 0.0492 (0.042633 is what 2 tan α_t in the
# denominator gives); the example's tip and root use x2 = 0.04263.  Compared: the
# quantities that do not depend on the centre distance, with x2 = 0.04263.  Tolerance: one
# unit of the last printed digit (the source truncates).
KHK_HELICAL = {"internal": True, "module": 3.0, "z1": 16, "z2": 24, "helix_angle": 30.0,
               "face_width": 20.0, "x1": 0.0, "x2": 0.04263}
KHK_HELICAL_EXPECTED = {
    "a": (13.8564, 0.0001), "alpha_t": (22.79587, 0.00001),
    "d1": (55.4256, 0.0001), "d2": (83.1384, 0.0001), "d_b1": (51.0963, 0.0001),
    "d_b2": (76.6445, 0.0001), "d_a1": (61.4256, 0.0001), "d_a2": (77.3942, 0.0001),
    "d_f1": (47.9256, 0.0001), "d_f2": (90.8942, 0.0001), "eps_beta": (1.0610, 0.0001),
}


def test_khk_internal_helical_pair():
    v = flat(spur(KHK_HELICAL))
    for key, (expected, tol) in KHK_HELICAL_EXPECTED.items():
        assert_ref(v[key], expected, tol, f"KHK helical internal: {key}")
    assert_ref(0.5 * (v["d2"] - v["d_a2"]), 2.872, 0.0005, "KHK helical internal: h_a2")
    assert_ref(0.5 * (v["d_f2"] - v["d2"]), 3.8778, 0.0001, "KHK helical internal: h_f2")
    # the printed working angle is that of the printed a = 14 mm: cos α_wt = (d_b2 − d_b1)/2a
    a_wt = math.acos((v["d_b2"] - v["d_b1"]) / 28.0)
    assert_ref(math.degrees(a_wt), 24.1558, 0.0001, "KHK helical internal: α_wt")
    assert_ref(math.tan(a_wt) - a_wt, 0.0268929, 0.00000005, "KHK helical internal: inv α_wt")


def _nrel_planet_shift() -> float:
    x_sum, _ = shift_sum_for_center_distance(863.0, 45.0, 19, 17, math.radians(20.0), 0.0)
    return x_sum - 0.6170


NREL = {"internal": True, "module": 45.0, "z1": 17, "z2": 56, "face_width": 491.0,
        "center_distance": 863.0, "cutter_teeth": 36, "cutter_tip_radius_coef": 0.30}
NREL_EXPECTED = {  # key: (printed, tolerance)
    "u": (3.294, 0.0006), "a": (877.500, 0.0006), "alpha_tw": (17.161, 0.0006),
    "x1": (0.8021, 0.00006), "x2_iso": (-0.5013, 0.00006),
    "d_b1": (718.865, 0.0006), "d_b2": (2368.025, 0.0006),
    "d_a2": (2475.118, 0.002), "d_f1": (724.692, 0.002), "d_f2": (2677.618, 0.002),
    "d_w1": (752.359, 0.0006), "d_w2": (2478.359, 0.0006),
    "c_21": (12.213, 0.002),                     # ring tip to planet root
    "d_p1": (749.170, 0.002),                    # dNf of the planet in the ring mesh
    "d_l1": (748.795, 0.002), "d_l2": (2662.682, 0.002),   # dFf (rack; shaper z0 = 36)
    "s_n1": (96.962, 0.002), "s_n2": (54.264, 0.002), "s_an2": (38.407, 0.002),
    "k2": (8, 0), "W2": (1047.070, 0.002),
    "theta1_A": (-0.037, 0.0006),                # zetaf, planet (ring mesh)
    "theta2_A": (0.035, 0.0006),                 # zetaa, ring
}


def test_kisssoft_nrel_stage1_planet_ring_as_a_spur_internal_pair():
    v = flat(spur({**NREL, "x1": _nrel_planet_shift()}))
    assert v["internal"] is True
    for key, (expected, tol) in NREL_EXPECTED.items():
        assert_ref(v[key], expected, tol, f"KISSsoft NREL stage 1 planet–ring: {key}")
