"""The built-in catalogue against the values read in its sources.

* Deep groove ball bearings: NTN CAT. No. 2202/E bearing tables, pp. B-8…B-13 (C_r, C_0r in
  kN), transcribed in ``ArtemFilin1990/Mar``; 6208 also in the worked examples (p. A-26:
  C_r = 29.1 kN, C_0r = 17.8 kN).  Boundary dimensions: ISO 15 as listed for GB/T 276-2013
  (60/62/63 series, d 10–50).
* Tapered roller bearings: SKF data as tabulated in ``gumyr/bd_warehouse``
  ``src/bd_warehouse/data/single_row_tapered_roller_bearing_parameters.csv`` (d, D, T, C, C0,
  Pu, e, Y).
"""

import pytest

from geardesign.bearing import catalogue as CAT

NTN = {  # designation: (d, D, B, C_r kN, C_0r kN) as read in the sources
    "6003": (17, 35, 10, 6.80, 3.35), "6005": (25, 47, 12, 10.1, 5.85),
    "6007": (35, 62, 14, 16.0, 10.3), "6009": (45, 75, 16, 21.0, 15.1),
    "6010": (50, 80, 16, 21.8, 16.6), "6203": (17, 40, 12, 9.60, 4.60),
    "6204": (20, 47, 14, 12.8, 6.65), "6205": (25, 52, 15, 14.0, 7.85),
    "6207": (35, 72, 17, 25.7, 15.3), "6208": (40, 80, 18, 29.1, 17.8),
    "6209": (45, 85, 19, 32.5, 20.4), "6303": (17, 47, 14, 13.5, 6.55),
    "6304": (20, 52, 15, 15.9, 7.90), "6305": (25, 62, 17, 21.2, 10.9),
    "6306": (30, 72, 19, 26.7, 15.0), "6307": (35, 80, 21, 33.5, 19.1),
    "6309": (45, 100, 25, 53.0, 32.0),
}
SKF = {  # designation: (d, D, T, C kN, C0 kN, Pu kN, e, Y)
    "30203": (17, 40, 13.25, 19.0, 18.6, 1.83, 0.35, 1.7),
    "30204": (20, 47, 15.25, 27.5, 28.0, 3.0, 0.35, 1.7),
    "30205": (25, 52, 16.25, 30.8, 33.5, 3.45, 0.37, 1.6),
    "30206": (30, 62, 17.25, 40.2, 44.0, 4.8, 0.37, 1.6),
    "30306": (30, 72, 20.75, 56.1, 56.0, 6.4, 0.31, 1.9),
}


@pytest.mark.parametrize("des", NTN)
def test_deep_groove_rows(des):
    b = CAT.find(des)
    d, D, B, cr, c0 = NTN[des]
    assert (b.d, b.D, b.B) == (d, D, B)
    assert (round(b.C_r), round(b.C_0r)) == (round(cr * 1000), round(c0 * 1000))
    assert b.note == ""


@pytest.mark.parametrize("des", SKF)
def test_tapered_rows(des):
    b = CAT.find(des)
    d, D, T, c, c0, pu, e, Y = SKF[des]
    assert (b.d, b.D, b.B, b.e, b.Y) == (d, D, T, e, Y)
    assert (round(b.C_r), round(b.C_0r), round(b.C_u)) == (round(c * 1000), round(c0 * 1000),
                                                           round(pu * 1000))


def test_gost_designations_and_unverified_rows():
    assert CAT.find("208").designation == "6208"
    assert CAT.find("7206").designation == "30206"
    assert CAT.find("106").designation == "6006"
    flagged = {b.designation for b in CAT.bearings() if b.note}
    assert flagged == {"6004", "6006", "6008", "6206", "6210", "6308", "6310"}
