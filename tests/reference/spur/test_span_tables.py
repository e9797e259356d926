"""Base tangent length (span) of a single gear from a published calculator.

* MESYS online helical-gear calculator, default output (z = 20, m = 1, α = 20°, x = 0):
  k = 2, W_k = 4.7083 mm, span contact diameter d_MSpan = 19.3746 mm, s_an = 0.6949 mm
  (https://www.mesys.ag/calc/helicalgear.fcgi?lang=en).  MESYS spans 2 teeth where the
  classic rule (and geardesign) spans 3; the test checks W and d_W at MESYS's k.
"""

import math

from geardesign.gears.span import base_tangent_length
from tests.conftest import assert_ref, flat, spur

A20 = math.radians(20.0)


def test_mesys_default_gear():
    v = flat(spur({"module": 1.0, "z1": 20, "z2": 40, "face_width": 10.0}))
    _, W, d_W = base_tangent_length(20, 0.0, 1.0, A20, A20, 0.0, 20.0, v["d_b1"], 2)
    assert_ref(W, 4.7083, 0.00005, "MESYS W_2")
    assert_ref(d_W, 19.3746, 0.00005, "MESYS d_MSpan")
    assert_ref(v["s_an1"], 0.6949, 0.00005, "MESYS s_an")
    assert_ref(v["d_b1"], 18.7939, 0.00005, "MESYS d_b")
