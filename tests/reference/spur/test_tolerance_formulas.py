"""Tolerance formulas of the standards, each value worked out by hand from the printed
formula (not from our code):

* ISO 1328-1:2013 5.3 ([ISO1328-1]) flank tolerances for class A, with the step factor
  √2^(A − 5) and the rounding of 5.2; the arithmetic is written out beside each value.
  Tolerance: exact after rounding (0.05 µm for the 0.1-µm values).
* ISO 1328-1:1995 ([ISO1328-1-1995] clause 6, annex B) at the geometric means of the size
  ranges, either side of a range bound; exact after rounding.
* GOST 1643-81 ([GOST1643]) guaranteed backlash j_n min: the standard prints, for a centre
  distance over 125 up to 180 mm, H 0, E 40, D 63, C 100, B 160, A 250 µm (= IT7…IT11 of
  the interval, [ISO286] table 1), and over 250 up to 315 mm E 52, D 81, C 130, B 210, A 320.
  Tolerance: exact (integers).
* ISO/TR 10064-2:1996 ([ISO10064-2]) least backlash j_bn min = ⅔(0.06 + 0.0005 a + 0.03 m_n).
"""

import math

import pytest

from geardesign.spur.tolerances import gost1643, iso1328

# d = 100 mm, m_n = 4 mm, b = 40 mm
# class 5 (step 1):
#   f_pT  = 0.1 + 1.6 + 5                      = 6.7    → 6.5 (5…10: 0.5 µm)
#   F_pT  = 0.2 + 5.5 + 2.8 + 12               = 20.5   → 21  (> 10: 1 µm; 20.5 rounds up)
#   f_HαT = 1.6 + 0.1 + 4                      = 5.7    → 5.5
#   f_fαT = 2.2 + 5                            = 7.2    → 7.0
#   F_αT  = √(5.7² + 7.2²) = √(32.49 + 51.84)  = 9.183  → 9.0
#   f_HβT = 0.05·10 + 0.35·√40 + 4 = 0.5 + 2.2136 + 4 = 6.7136 → 6.5
#   f_fβT = 0.07·10 + 0.45·√40 + 4 = 0.7 + 2.8460 + 4 = 7.5460 → 7.5   (eq. (11))
#   F_βT  = √(6.7136² + 7.5460²) = √102.014    = 10.100 → 10  (eq. (12), unrounded parts)
#   F_rT  = 0.9 · 20.5                         = 18.45  → 18
# class 8 (step 2√2 = 2.828427):
#   f_pT  = 6.7 · 2.828427 = 18.9505 → 19;  F_pT = 20.5 · 2.828427 = 57.983 → 58
#   F_αT  = 9.1833 · 2.828427 = 25.974 → 26;  F_βT = 10.100 · 2.828427 = 28.568 → 29
# class 2 (step 2^-1.5 = 0.353553):
#   f_pT  = 6.7 · 0.353553 = 2.3688 → 2.4;  f_fαT = 7.2 · 0.353553 = 2.5456 → 2.5
CASES = {
    5: {"f_pT": 6.5, "F_pT": 21.0, "f_HalphaT": 5.5, "f_falphaT": 7.0, "F_alphaT": 9.0,
        "f_HbetaT": 6.5, "f_fbetaT": 7.5, "F_betaT": 10.0, "F_rT": 18.0},
    8: {"f_pT": 19.0, "F_pT": 58.0, "F_alphaT": 26.0, "F_betaT": 29.0},
    2: {"f_pT": 2.4, "f_falphaT": 2.5},
}


@pytest.mark.parametrize("grade", sorted(CASES))
def test_iso1328_flank_tolerances_by_hand(grade):
    t = iso1328.flank_tolerances(grade, 100.0, 4.0, 40.0)
    for key, expected in CASES[grade].items():
        assert getattr(t, key) == pytest.approx(expected, abs=0.05), f"class {grade} {key}"


def test_iso1328_rounding_rule():
    r = iso1328.round_tolerance
    assert (r(10.6), r(10.4), r(9.74), r(9.76), r(5.2), r(4.96), r(4.94)) == (
        11.0, 10.0, 9.5, 10.0, 5.0, 5.0, 4.9)


@pytest.mark.parametrize("a_w, expected", [
    (160.0, {"H": 0, "E": 40, "D": 63, "C": 100, "B": 160, "A": 250}),
    (300.0, {"H": 0, "E": 52, "D": 81, "C": 130, "B": 210, "A": 320}),
])
def test_gost1643_guaranteed_backlash(a_w, expected):
    for mating, value in expected.items():
        assert gost1643.jn_min(mating, a_w) == value, mating


def test_gost1643_centre_distance_classes():
    """±f_a is half of IT6…IT11 of a_w; the classes paired with the types of mating."""
    assert [gost1643.mating(m)["fa_class"] for m in "HEDCBA"] == [
        "II", "II", "III", "IV", "V", "VI"]
    assert gost1643.fa("V", 160.0) == 80.0      # ½·IT10(125…180) = ½·160
    assert gost1643.fa("II", 100.0) == 17.5     # ½·IT7(80…125) = ½·35


def test_gost_rack_shift_and_thickness():
    """E_cs = 2·E_Hs·tan α: a rack shift of 100 µm thins the tooth by 72.794 µm (α = 20°)."""
    assert gost1643.thickness_from_rack_shift(100.0, math.radians(20.0)) == pytest.approx(
        -72.794, abs=1e-3)


def test_iso10064_least_backlash():
    # ⅔·(0.06 + 0.0005·250 + 0.03·4) mm = ⅔·0.305 mm = 203.33 µm
    assert iso1328.jbn_min(250.0, 4.0) == pytest.approx(203.333, abs=1e-3)


# ISO 1328-1:1995, worked by hand from the printed formulas at the geometric means of the
# size ranges (a range holds its upper bound: "6 < m ≤ 10", "10 < m ≤ 16"):
# d = 100 in 50 < d ≤ 125: √(50·125) = 79.057, √ = 8.8914; b = 40 in 20 < b ≤ 40: √800
# = 28.284, √ = 5.3183.
# m = 10 in 6 < m ≤ 10: √60 = 7.7460, √ = 2.7832; class 5:
#   f_pt = 0.3(7.7460 + 0.4·8.8914) + 4 = 7.3908 → 7.5
#   F_p  = 0.3·7.7460 + 1.25·8.8914 + 7 = 20.4380 → 20
#   f_fα = 2.5·2.7832 + 0.17·8.8914 + 0.5 = 8.9695 → 9.0
#   F_β  = 0.1·8.8914 + 0.63·5.3183 + 4.2 = 8.4397 → 8.5
#   f_Hβ = 0.07·8.8914 + 0.45·5.3183 + 3 = 6.0156 → 6.0
#   F_r  = 0.8·20.4380 = 16.350 → 16
# m = 10.01 in 10 < m ≤ 16: √160 = 12.649; f_pt = 0.3(12.649 + 3.5566) + 4 = 8.8617 → 9.0
# class 8 at m = 10 (step 2√2): f_pt = 7.3908·2.8284 = 20.905 → 21
CASES_1995 = [
    (10.0, 5, {"f_pT": 7.5, "F_pT": 20.0, "f_falphaT": 9.0, "F_betaT": 8.5, "f_HbetaT": 6.0,
               "f_fbetaT": 6.0, "F_rT": 16.0}),
    (10.01, 5, {"f_pT": 9.0}),
    (10.0, 8, {"f_pT": 21.0}),
]


@pytest.mark.parametrize("m_n, grade, expected", CASES_1995)
def test_iso1328_1995_by_hand(m_n, grade, expected):
    t = iso1328.flank_tolerances(grade, 100.0, m_n, 40.0, iso1328.STANDARD_1995)
    for key, value in expected.items():
        assert getattr(t, key) == value, f"m_n {m_n} grade {grade} {key}"
