"""K_Hβ by method C takes the manufacturing misalignment f_ma = 1.0·f_Hβ for gears without
provision for adjustment ([ISO6336-1] 7.6.2.4; DIN 3990-1 §3.4.2.4 says the same, as do the
public implementations GitHub hanslhansl/din3990 ``din3990_11.f_ma`` and
gfsReboucas/Drivetrain ``MATISO_6336.m``).  f_Hβ is the helix slope tolerance, smaller than
the total helix tolerance F_β that also holds the form deviation."""

from __future__ import annotations

from geardesign.spur.strength.iso6336 import iso1328
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
    """ISO 1328-1:2013 f_HβT = (0.07√d + 0.45√b + 3)·√2^(A−5), rounded as the standard
    rounds (d = 60 mm, b = 30 mm, class 8: 0.542 + 2.465 + 3 = 6.007 → 16.99 µm)."""
    assert abs(iso1328.helix_slope(60.0, 30.0, 8) - 17.0) <= 0.5
