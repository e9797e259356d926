"""The built-in catalogue against the values printed in its sources.

* SKF rows: SKF General Catalogue 6000, Russian edition ([SKF6000]), bearing tables; the
  values below were read by eye in the catalogue text (``ArtemFilin1990/Mar``,
  ``07_Бренды_и_каталоги/Бренды/каталоги/Общий_каталог_подшипников_SKF.md``), page by page:
  d, D, B (T of tapered, H of thrust), C, C0, Pu in kN; e, Y (Y2), Y0 (and Y1 of spherical
  roller bearings) from the facing page of calculation factors.  Exact: the file stores the
  printed digits.
* NTN rows: NTN CAT. No. 2202/E bearing tables, pp. B-8…B-13 (C_r, C_0r in kN), transcribed
  in the same repository; 6208 also in the worked examples (p. A-26: C_r = 29.1 kN,
  C_0r = 17.8 kN).
"""

import pytest

from geardesign.bearing import catalogue as CAT

SKF = {  # designation: (page, d, D, B, C kN, C0 kN, Pu kN, e, Y, Y0, Y1)
    "6208": (308, 40, 80, 18, 32.5, 19.0, 0.80, None, None, None, None),
    "6308": (308, 40, 90, 23, 42.3, 24.0, 1.02, None, None, None, None),
    "6408": (308, 40, 110, 27, 63.7, 36.5, 1.53, None, None, None, None),
    "6005": (306, 25, 47, 12, 11.9, 6.55, 0.275, None, None, None, None),
    "6307": (306, 35, 80, 21, 35.1, 19.0, 0.82, None, None, None, None),
    "6224": (314, 120, 215, 40, 146.0, 118.0, 3.9, None, None, None, None),
    "7208 B": (422, 40, 80, 18, 36.5, 26.0, 1.1, None, None, None, None),
    "7308 B": (422, 40, 90, 23, 50.0, 32.5, 1.37, None, None, None, None),
    "7210 B": (424, 50, 90, 20, 40.0, 31.0, 1.32, None, None, None, None),
    "7310 B": (424, 50, 110, 27, 75.0, 51.0, 2.16, None, None, None, None),
    "NU 208": (526, 40, 80, 18, 62.0, 53.0, 6.7, None, None, None, None),
    "NUP 2208": (526, 40, 80, 23, 81.5, 75.0, 9.65, None, None, None, None),
    "NJ 308": (526, 40, 90, 23, 93.0, 78.0, 10.2, None, None, None, None),
    "NU 310": (530, 50, 110, 27, 127.0, 112.0, 15.0, None, None, None, None),
    "30208": (620, 40, 80, 19.75, 61.6, 68.0, 7.65, 0.37, 1.6, 0.9, None),
    "32208": (620, 40, 80, 24.75, 74.8, 86.5, 9.8, 0.37, 1.6, 0.9, None),
    "31308": (620, 40, 90, 25.25, 85.0, 81.5, 9.5, 0.83, 0.72, 0.4, None),
    "30307": (620, 35, 80, 22.75, 72.1, 73.5, 8.3, 0.31, 1.9, 1.1, None),
    "32307": (620, 35, 80, 32.75, 95.2, 106.0, 12.2, 0.31, 1.9, 1.1, None),
    "22208": (716, 40, 80, 23, 96.5, 90.0, 9.8, 0.28, 3.6, 2.5, 2.4),
    "22308": (716, 40, 90, 33, 150.0, 140.0, 15.0, 0.37, 2.7, 1.8, 1.8),
    "22215": (718, 75, 130, 31, 212.0, 240.0, 26.5, None, None, None, None),
    "23024": (720, 120, 180, 46, 355.0, 510.0, 53.0, None, None, None, None),
    "51108": (844, 40, 60, 13, 26.0, 63.0, 2.32, None, None, None, None),
    "51208": (844, 40, 68, 19, 46.8, 106.0, 4.0, None, None, None, None),
    "51220": (846, 100, 150, 38, 124.0, 345.0, 11.4, None, None, None, None),
}

NTN = {  # designation: (d, D, B, C_r kN, C_0r kN)
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


@pytest.mark.parametrize("des", SKF)
def test_skf_rows(des):
    page, d, D, B, C, C0, Pu, e, Y, Y0, Y1 = SKF[des]
    b = CAT.find(des)
    assert b.maker == "SKF" and b.source == "SKF6000" and b.page == str(page)
    assert (b.d, b.D, b.B) == (d, D, B)
    assert (b.C_r, b.C_0r, b.C_u) == pytest.approx((C * 1000, C0 * 1000, Pu * 1000), rel=1e-12)
    if e is not None:
        assert (b.e, b.Y, b.Y0) == (e, Y, Y0)
    if Y1 is not None:
        assert b.Y1 == Y1
    assert b.note == ""


def test_at_least_twenty_rows_across_every_type_are_checked():
    kinds = {CAT.find(d).type for d in SKF}
    assert len(SKF) >= 20 and kinds == set(CAT.types())


@pytest.mark.parametrize("des", NTN)
def test_ntn_rows(des):
    b = CAT.find(des, "NTN")
    d, D, B, cr, c0 = NTN[des]
    assert b.maker == "NTN"
    assert (b.d, b.D, b.B) == (d, D, B)
    assert (round(b.C_r), round(b.C_0r)) == (round(cr * 1000), round(c0 * 1000))


def test_names_makers_and_gost():
    assert CAT.find("NU208") is CAT.find("nu 208") is CAT.find("NU 208 ECP")
    assert CAT.find("7208B") is CAT.find("7208 BECBP")
    assert CAT.find("208").designation == "6208" and CAT.find("208").maker == "SKF"
    assert CAT.find("208", "NTN").C_r == 29100.0
    assert CAT.find("7506").designation == "32206"
    assert CAT.find("27308").designation == "31308"
    assert CAT.find("8208").designation == "51208"
    assert CAT.find("6208", "FAG") is None


def test_bare_72xx_is_ambiguous():
    with pytest.raises(CAT.AmbiguousDesignation, match="7208 B.*30208"):
        CAT.find("7208")


def test_rows_without_a_full_source_are_flagged():
    flagged = {b.designation for b in CAT.bearings() if b.note}
    assert flagged == {"6006", "6008", "6206", "6210", "6308", "6310"}
    assert all(b.maker == "NTN" for b in CAT.bearings() if b.note)


def test_every_series_of_the_issue_spans_10_to_200_mm_where_the_maker_makes_it():
    have = {(b.type, b.series) for b in CAT.bearings()}
    for kind, series in (("deep_groove_ball", "60"), ("deep_groove_ball", "62"),
                         ("deep_groove_ball", "63"), ("deep_groove_ball", "64"),
                         ("angular_contact_ball", "72"), ("angular_contact_ball", "73"),
                         ("cylindrical_roller", "2"), ("cylindrical_roller", "3"),
                         ("cylindrical_roller", "22"), ("cylindrical_roller", "23"),
                         ("tapered_roller", "302"), ("tapered_roller", "303"),
                         ("tapered_roller", "313"), ("tapered_roller", "322"),
                         ("tapered_roller", "323"), ("spherical_roller", "222"),
                         ("spherical_roller", "223"), ("spherical_roller", "230"),
                         ("spherical_roller", "231"), ("thrust_ball", "511"),
                         ("thrust_ball", "512")):
        assert (kind, series) in have
    assert min(CAT.bores("deep_groove_ball")) == 10 and max(CAT.bores("deep_groove_ball")) == 200


def test_catalogue_is_read_only_on_demand():
    import subprocess
    import sys

    code = ("import sys, geardesign.cli; "
            "print(any(m.endswith('bearing.catalogue') for m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == "False"
