"""K_Hβ by method C takes the manufacturing misalignment f_ma = 1.0·f_Hβ for gears without
provision for adjustment ([ISO6336-1] 7.6.2.4; DIN 3990-1 §3.4.2.4 says the same, as do the
public implementations GitHub hanslhansl/din3990 ``din3990_11.f_ma`` and
gfsReboucas/Drivetrain ``MATISO_6336.m``).  f_Hβ is the helix slope tolerance, smaller than
the total helix tolerance F_β that also holds the form deviation."""

from __future__ import annotations

from geardesign.spur.tolerances import iso1328
from tests.test_iso6336_inputs import _run


def test_f_ma_is_the_helix_slope_tolerance():
    f = _run()["results"]["iso6336_factors"]
    assert f["f_ma"] == f["f_Hbeta"]
    assert f["f_Hbeta"] < f["F_beta"]


def test_f_ma_given_wins_and_lowers_K_Hbeta():
    base = _run()["results"]["iso6336_factors"]
    half = _run(iso={"f_ma": 0.5 * base["f_Hbeta"]})["results"]["iso6336_factors"]
    assert half["f_ma"] == 0.5 * base["f_Hbeta"]
    assert half["K_Hbeta"] < base["K_Hbeta"]


def test_helix_slope_tolerance_formula():
    """f_HβT of class 8 at d = 60 mm, b = 30 mm, worked by hand from the printed formulas:
    ISO 1328-1:2013 eq. (10) (0.05√d + 0.35√b + 4)·2√2 = (0.3873 + 1.9170 + 4)·2.8284
    = 17.83 → 18 µm; ISO 1328-1:1995 B.2.3 (0.07√d + 0.45√b + 3)·2√2 at the range means
    d = √(50·125) = 79.06, b = √(20·40) = 28.28: (0.6224 + 2.3931 + 3)·2.8284 = 17.01 → 17."""
    assert iso1328.tolerances(60.0, 2.0, 30.0, 8)["f_HbetaT"] == 18.0
    assert iso1328.tolerances(60.0, 2.0, 30.0, 8, iso1328.STANDARD_1995)["f_HbetaT"] == 17.0
