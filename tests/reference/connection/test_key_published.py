"""Parallel keys against published worked examples (values this code did not produce).

* [StudylibKey]: D. Martin, "Shaft Key Calculations" (Mathcad sheet). T = 150 N·m with the
  service factor K_s = K_a·K_d/K_f = 1/0.3; key w × h × l = 12.5 × 10 × 50 mm; the force acts
  on the reduced diameter d_re = d − h/2 = 45 mm of the 50 mm shaft; bearing on h/2 = 5 mm.
  Printed: τ = 35.556 MPa, σ_c = 88.889 MPa.  In the calculator: a key not from the table
  (width 12.5, height 10, shaft_depth 5, so k = h − t1 = 5 mm), form B (l_p = l), shaft
  diameter 45 mm (the sheet's lever arm), K_A = 1/0.3.  Tolerance: half a unit of the third
  printed decimal.
* [Holooly] Q. 8.6: shaft 2r = 50 mm, square key a = 12.5 mm, length 37.5 mm, τ_max =
  200 MPa; printed T_max = 2.344 kN·m.  The shear formula τ = 2T/(d·b·l_p) at the printed
  torque must give 200 MPa within the rounding of the printed torque (±0.0005 kN·m, i.e.
  ±0.043 MPa).
* [WikiPassfeder]: for the shaft diameter 40 mm the key section is 12 × 8 mm (the row of
  [GOST23360] / [DIN6885-1] table 1 in ``keys.csv``).
"""

from geardesign.connection import key as K
from geardesign.connection import tables
from geardesign.core.registry import run_data
from tests.conftest import assert_ref


def test_studylib_key_sheet_through_the_calculator():
    data = {"kind": "connection",
            "load": {"torque": 150.0, "application_factor": 1.0 / 0.3},
            "key": {"shaft_diameter": 45.0, "length": 50.0, "form": "B", "width": 12.5,
                    "height": 10.0, "shaft_depth": 5.0}}
    r = run_data(data).document()["results"]
    assert_ref(r["strength"]["T_d"], 500.0, 1e-9, "T·K_s")
    assert_ref(r["strength"]["tau"], 35.556, 0.0005, "[StudylibKey] τ")
    assert_ref(r["strength"]["p_hub"], 88.889, 0.0005, "[StudylibKey] σ_c")


def test_holooly_square_key_shear():
    tau = K.shear(2.344e6, 50.0, 12.5, K.bearing_length(37.5, 12.5, "B"))
    assert_ref(tau, 200.0, 200.0 * 0.0005 / 2.344, "[Holooly] τ at T_max = 2.344 kN·m")


def test_key_section_for_a_40_mm_shaft():
    k = tables.key_for_diameter(40.0)
    assert (k.b, k.h) == (12.0, 8.0)   # [WikiPassfeder]
