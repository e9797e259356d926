"""The spline flank-pressure formula against a published worked example.

[MetizBearing]: the allowable torque of a spline on d = 100 mm, hub length l = 150 mm,
[σсм] = 1000 kgf/cm²: straight-sided spline of the medium series, z = 10, D = 102 mm,
d = 92 mm, chamfer f = 0.5 mm; the page computes [T] = [σсм]·K·z·h·l·r_ср =
1000·0.8·10·0.4·15·4.8 ≈ 230 000 kgf·cm with the load-share factor K = 0.8, the bearing
height h = (D − d)/2 − 2f = 0.4 cm and the mean radius r_ср = 4.8 cm (printed; (D + d)/4 =
4.85 cm exactly).  The example is a straight-sided spline: the involute geometry of
[DIN5480] is not part of it, only the mean-pressure formula p = 2T/(d_m·z·h_w·l·ψ)
([DIN5466]; [Ivanov] ch. 6), which is the same for both profiles.

* at the printed product T = 230 400 kgf·cm and the printed r_ср the formula gives
  p = 1000 kgf/cm² = 98.0665 MPa exactly (tolerance 1e-9 MPa);
* with the exact mean radius the least length at 230 000 kgf·cm stays within the rounding
  of the printed "≈ 230 000" (the page rounds to two digits: ±1.5 %).

[InventorSplines] prints the permissible flank pressures in kgf/mm² (ranges by connection
type, conditions and hardness).  ``tables.toml`` holds the lower end of each range in MPa with
1 kgf/mm² taken as 10 MPa, as [Ivanov] does: every value must be ten times the printed lower
end.  Exact.
"""

import pytest

from geardesign.connection import spline as SP
from geardesign.connection import tables
from tests.conftest import assert_ref

KGF_CM = 98.0665          # N·mm per kgf·cm
KGF_CM2 = 0.0980665       # MPa per kgf/cm²


def test_metiz_spline_pressure_at_the_printed_torque():
    T = 1000 * 0.8 * 10 * 0.4 * 15 * 4.8 * KGF_CM
    p = SP.pressure(T, 2 * 48.0, 10, 4.0, 150.0, 0.8)
    assert_ref(p, 1000 * KGF_CM2, 1e-9, "[MetizBearing] [σсм]")


def test_metiz_spline_length_with_the_exact_mean_radius():
    l = SP.required_length(230000 * KGF_CM, (102 + 92) / 2, 10, 4.0, 0.8, 1000 * KGF_CM2)
    assert_ref(l, 150.0, 150.0 * 0.015, "[MetizBearing] l at ≈230 000 kgf·cm")


# [InventorSplines], lower ends [kgf/mm²]: (use, hardness) -> (unfavourable, medium, favourable)
INVENTOR = {("fixed", "soft"): (3.5, 6, 8), ("fixed", "hardened"): (4, 10, 12),
            ("sliding_unloaded", "soft"): (1.5, 2, 2.5),
            ("sliding_unloaded", "hardened"): (2, 3, 4),
            ("sliding_loaded", "hardened"): (0.3, 0.5, 1)}


@pytest.mark.parametrize("use, hardness", sorted(INVENTOR))
def test_permissible_pressures_are_the_published_lower_ends(use, hardness):
    row = tables.toml()["spline_pressure"][use][hardness]
    got = tuple(row[c] for c in ("poor", "average", "good"))
    assert got == pytest.approx(tuple(10 * v for v in INVENTOR[(use, hardness)]), abs=1e-12)


def test_no_soft_teeth_sliding_under_load():
    assert "soft" not in tables.toml()["spline_pressure"]["sliding_loaded"]
