"""KHK "Gear Technical Reference" worked example of an axial-module worm pair (also in
SDP/SI "Elements of Metric Gear Technology", worm mesh geometry section): m_x = 3,
α_n = 20°, z1 = 2, z2 = 30, d1 = 44, x = 0, clearance 0.25·m.

The published values are read from two public transcriptions, neither produced by this
code:

* the printed output of the public C program GitHub ``systbs/formula`` (README, commit
  2162eeaada7c402d067b23c98b4d7916cf373da9), which reproduces the SDP/SI example;
* the "Worm Gear Formula-Master" sheet (REF. KHK / Niemann-DIN; scribd document 418425143):
  a = 67, d_a1 = 50, throat diameter 96, d_f = 36.5 / 82.5, throat radius 19,
  lead angle 7.7651660184°, m_n = 2.97249050413290.

In GOST terms: q = 44/3 (not a standard q: a STANDARD_PAIR warning), a worm with a normal
basic profile (ZN1), h_a* = 1, c* = 0.25.  Tolerances are one unit of the printed last
digit, except where the program printed π as 3.1416 (lead, pitch, thickness: 1e-4 mm,
and 2e-5° on the lead angle).

Not compared (definitions differ, not misprints): KHK's chordal addendum of the worm
3.002303 = h_a + (s_n·tan γ)²/(4 d1) against GOST 19650's measuring height
h_a + 0.5·s_n·tan(0.5·arcsin(s_n·sin²γ/d1)) = 3.002261; KHK's wheel "outside diameter" 99
(a blank dimension) against GOST's d_aM2 <= d_a2 + 6m/(z1 + 2).  Misprints of the
``systbs/formula`` output (copy slips in its print statements): "Throat Diameter 50" (the
worm's tip; KHK: 96) and "Root Diameter-Gear 36.5" (the worm's root; KHK: 82.5).
"""

from geardesign.core.registry import run_data
from tests.conftest import assert_ref, flat

SPEC = {
    "kind": "worm",
    "gear": {"module": 3.0, "diameter_factor": 44.0 / 3.0, "z1": 2, "z2": 30,
             "worm_type": "ZN1", "profile_angle": 20.0},
    "basic_worm": {"clearance_coef": 0.25},
    "load": {"torque2": 20.0, "speed1": 1500.0},
    "wheel": {"material": "BrO10N1F1_centrifugal"},
}

EXPECTED = {  # key: (published value, tolerance, source)
    "q": (14.666667, 1e-6, "systbs: Diameter Factor 14.666667"),
    "gamma": (7.7651660184, 1e-9, "KHK sheet: lead angle 7.7651660184°"),
    "alpha_x": (20.170236, 1e-6, "systbs: Pressure Angle, axial 20.170236"),
    "alpha_n": (20.0, 1e-9, "systbs: Pressure Angle, normal 20"),
    "m_n": (2.97249050413290, 1e-12, "KHK sheet: module (normal)"),
    "p_x": (9.4248, 1e-4, "systbs: Pitch, axial 9.424800 (π = 3.1416)"),
    "p_z1": (18.8495559215, 1e-9, "KHK sheet: axial pitch / lead 18.8495559215"),
    "d1": (44.0, 5e-7, "systbs: Pitch Diameter-Worm 44"),
    "d2": (90.0, 5e-7, "systbs: Pitch Diameter-Gear 90"),
    "a_w": (67.0, 5e-7, "KHK sheet and systbs: centre distance 67"),
    "d_a1": (50.0, 5e-7, "KHK sheet and systbs: outside diameter, worm 50"),
    "d_a2": (96.0, 5e-7, "KHK sheet: throat diameter 96"),
    "d_f1": (36.5, 5e-7, "KHK sheet and systbs: root diameter, worm 36.5"),
    "d_f2": (82.5, 5e-7, "KHK sheet: root diameter, wheel 82.5"),
    "R_throat": (19.0, 5e-7, "KHK sheet: throat radius 19; systbs: throat surface radius 19"),
    "s_n1": (4.669188, 2e-5, "systbs: circular tooth thickness, worm, normal 4.669188 "
                            "(π = 3.1416)"),
    "c": (0.75, 5e-7, "systbs: top clearance 0.75"),
}


def test_khk_axial_module_worm_pair():
    doc = run_data(SPEC).document()
    values = flat(doc)
    for key, (expected, tol, source) in EXPECTED.items():
        assert_ref(values[key], expected, tol, f"KHK worm example {key} ({source})")
    # whole depth 6.75 and working depth 6 (systbs): (d_a1 − d_f1)/2 and d_a1 − d1
    assert_ref((values["d_a1"] - values["d_f1"]) / 2, 6.75, 5e-7, "KHK: whole depth")
    assert_ref(values["d_a2"] - values["d2"], 6.0, 5e-7, "KHK: working depth 2·h_a")
    checks = {c["code"]: c for c in doc["checks"]}
    assert not checks["STANDARD_PAIR"]["passed"]  # q = 14.667 is not a GOST q
    assert checks["STANDARD_PAIR"]["severity"] == "warning"
