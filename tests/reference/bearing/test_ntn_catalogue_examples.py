"""Worked examples of the NTN catalogue "Ball and Roller Bearings", CAT. No. 2202-II/E
(2001), section 4.6 "Bearing rated life and load calculation examples", pp. A-26/A-27, as
transcribed in the public repository ``ArtemFilin1990/Mar``
(``90_Приложения_таблицы_БД/Таблицы/Шариковые-и-роликовые-подшипники-NTN.md``).

NTN works with the speed factor f_n = (33.3/n)^(1/p) and the life factor f_h = f_n·C/P,
both rounded to 2–3 digits, and reads the life from a chart (Fig. 3.1).  The tolerances
below allow for that rounding (stated per value).  The X/Y table of Example 2 is the
Fa/C0r ("textbook") column, which the tool uses when f0 is not given.

Misprints found (the tool computes the correct value, the tests name them):

* Example 4, bearing 2: "Pr2 = 0.4×4.18 + 1.67×1.87 = 4.66 kN" -- the sum with the printed
  Y = 1.67 is 4.80 kN; 4.66 kN is the sum with Y = 1.60 (the Y of bearing 1, 4T-32206), and
  the printed lives follow 4.66 kN.
* Example 6: "L10h = 500×3.63 ≈ 24,000" for a cylindrical roller bearing -- 500·f_h^3 (the
  ball exponent) gives 23,916 h; with the roller exponent 10/3, 500·3.63^(10/3) = 36,756 h.
"""

import pytest

from geardesign.bearing import life as L
from tests.conftest import assert_ref
from tests.reference.bearing._util import bearing

GOST = "gost18855_94"
NO_A23 = {"factors": {"a23": 1.0}}          # NTN's basic rating life: a1 = a23 = 1


def test_example_1_6208_radial_load():
    # 6208, Fr = 3.2 kN, 650 min^-1: f_h = 3.36, "approximately 19,000 hours" (chart).
    v = bearing(GOST, {"designation": "6208", "maker": "NTN"}, {"F_r": 3200.0, "speed": 650.0}, **NO_A23)
    assert_ref(v["C_r"], 29100.0, 0.0, "6208 C_r from the bearing table")
    assert_ref(v["P"], 3200.0, 1e-9, "Ex. 1 P_r = F_r")
    assert_ref(v["L10h"], 19000.0, 0.02 * 19000.0, "Ex. 1 L10h (chart read, ±2 %)")


def test_example_2_6208_with_axial_load():
    # Same bearing and speed plus Fa = 1.8 kN: Cor = 17.8 kN, Fa/Cor = 0.10 -> e = 0.29;
    # Fa/Fr = 0.56 > e -> X = 0.56, Y = 1.48; Pr = 4.46 kN; f_h = 2.41 -> about 7,000 h.
    v = bearing(GOST, {"designation": "6208", "maker": "NTN"}, {"F_r": 3200.0, "F_a": 1800.0, "speed": 650.0},
                **NO_A23)
    assert_ref(v["C_0r"], 17800.0, 0.0, "6208 C_0r from the bearing table")
    assert_ref(v["entry"], 0.10, 0.0015, "Ex. 2 Fa/Cor (printed to 2 digits)")
    assert_ref(v["e"], 0.29, 0.005, "Ex. 2 e (printed to 2 digits)")
    assert_ref(v["ratio"], 0.56, 0.0025, "Ex. 2 Fa/Fr")
    assert_ref(v["X"], 0.56, 0.0, "Ex. 2 X")
    assert_ref(v["Y"], 1.48, 0.005, "Ex. 2 Y (printed to 2 digits)")
    assert_ref(v["P"], 4460.0, 5.0, "Ex. 2 P_r = 4.46 kN (NTN uses the rounded Y = 1.48)")
    f_h = (33.3 / 650.0) ** (1.0 / 3.0) * v["C_r"] / v["P"]
    assert_ref(f_h, 2.41, 0.02, "Ex. 2 f_h (NTN rounds f_n to 0.37)")
    assert_ref(v["L10h"], 7000.0, 0.02 * 7000.0, "Ex. 2 L10h (chart read, ±2 %)")


def test_example_3_required_rating_cylindrical_roller():
    # Cylindrical roller, 450 min^-1, Fr = 200 kN, over 20,000 h: f_h = 3.02, f_n = 0.46 ->
    # Cr = 1,313 kN, so NU2336 (Cr = 1,380 kN) is chosen.
    v = bearing(GOST, {"type": "cylindrical_roller", "C_r": 1380000.0},
                {"F_r": 200000.0, "speed": 450.0}, requirements={"life": 20000.0}, **NO_A23)
    assert_ref(v["C_req"], 1313000.0, 0.01 * 1313000.0,
               "Ex. 3 required Cr (from f_h, f_n rounded to 3 and 2 digits: ±1 %)")
    assert v["L10h"] >= 20000.0


def test_example_4_tapered_pair_and_system_life():
    # Spur gear shaft, 2,000 min^-1: bearing 1 4T-32206 (Cr = 54.5 kN), Fr1 = 5.98 kN;
    # bearing 2 4T-32205 (Cr = 42.0 kN), Fr2 = 4.18 kN, Fa2 = 0.5·Fr1/Y1 = 1.87 kN, X = 0.4.
    # Pr1 = Fr1 = 5.98 kN, Pr2 = 4.66 kN; f_h1 = 2.67, f_h2 = 2.64 -> 13,200 and 12,700 h
    # (chart); with a2 = 1.4 (4T material): 18,480 and 17,780 h; system 9,780 h (e = 9/8).
    b1 = bearing(GOST, {"type": "tapered_roller", "C_r": 54500.0, "e": 0.37, "Y": 1.60},
                 {"F_r": 5980.0, "F_a": 1870.0, "speed": 2000.0}, factors={"a23": 1.4},
                 requirements={"system_lives": [17780.0]})
    assert b1["ratio"] <= b1["e"]
    assert_ref(b1["P"], 5980.0, 1e-9, "Ex. 4 Pr1 = Fr1")
    assert_ref(b1["L10h"], 13200.0, 0.01 * 13200.0, "Ex. 4 Lh1 (chart read, ±1 %)")
    assert_ref(b1["L_sah"], 18480.0, 0.01 * 18480.0, "Ex. 4 a2·Lh1 (a2 as a23)")
    assert_ref(b1["L_system"], 9780.0, 30.0, "Ex. 4 system life from 18,480/17,780 h")

    b2 = bearing(GOST, {"type": "tapered_roller", "C_r": 42000.0, "e": 0.37, "Y": 1.60},
                 {"F_r": 4180.0, "F_a": 1870.0, "speed": 2000.0}, factors={"a23": 1.4})
    assert_ref(b2["X"], 0.4, 0.0, "Ex. 4 X of bearing 2")
    assert_ref(b2["P"], 4660.0, 5.0, "Ex. 4 Pr2 = 4.66 kN (with Y = 1.60)")
    assert_ref(b2["L10h"], 12700.0, 0.01 * 12700.0, "Ex. 4 Lh2 (chart read, ±1 %)")
    assert_ref(b2["L_sah"], 17780.0, 0.01 * 17780.0, "Ex. 4 a2·Lh2")

    # the printed system life follows from the printed bearing lives
    assert_ref(L.system_life([18480.0, 17780.0], 9.0 / 8.0), 9780.0, 10.0, "Ex. 4 (3.6)")


def test_example_4_misprint_in_pr2():
    # Printed "0.4×4.18 + 1.67×1.87 = 4.66": the sum is 4.80 kN with Y = 1.67.
    b2 = bearing(GOST, {"type": "tapered_roller", "C_r": 42000.0, "e": 0.37, "Y": 1.67},
                 {"F_r": 4180.0, "F_a": 1870.0, "speed": 2000.0}, **NO_A23)
    assert_ref(b2["P"], 0.4 * 4180.0 + 1.67 * 1870.0, 1e-6, "Ex. 4 Pr2 with the printed Y")
    assert abs(b2["P"] - 4660.0) > 100.0, "misprint: 4.66 kN is not 0.4×4.18 + 1.67×1.87"


@pytest.mark.parametrize("what", ["tool", "misprint"])
def test_example_6_cylindrical_roller_life(what):
    # Cylindrical roller, Cr = 124 kN, Fr = 10 kN, 2,000 min^-1: f_n = 0.293, f_h = 3.63.
    v = bearing(GOST, {"type": "cylindrical_roller", "C_r": 124000.0},
                {"F_r": 10000.0, "speed": 2000.0}, **NO_A23)
    if what == "tool":
        assert_ref(v["L10h"], 500.0 * 3.63 ** (10.0 / 3.0), 0.005 * 36756.0,
                   "Ex. 6 L10h = 500·f_h^(10/3) (f_h = 3.63 rounded: ±0.5 %)")
    else:
        # the printed 24,000 h is 500·3.63^3: the ball exponent used for a roller bearing
        assert_ref(500.0 * 3.63 ** 3, 24000.0, 100.0, "Ex. 6 printed value")
        assert v["L10h"] > 1.5 * 24000.0
