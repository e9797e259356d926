"""The clutch spring against published textbook examples (values this code did not produce).

Source: the FOSSEE Scilab Textbook Companion, book 764, chapter 10 "Springs" (GitHub
``FOSSEE/Scilab-TBC-Uploads``, commit b1f5c3f8d6671b4331cef1dcebdf63b7a43a3a2b), which
reproduces the worked examples of a machine-design textbook (the chapter cites "Fig. 10.16
on page 408", G = 81 370 N/mm², Wahl factor; very probably V. B. Bhandari, "Design of
Machine Elements"; the book's title is not named in the files) and prints the results in
``764/CH10/EX10.*.b/result10_*.txt``.

* Example 10.1 (helical compression spring, square and ground ends): P = 1250 N, C = 6,
  S_ut = 1090 N/mm², permissible τ = 0.5·S_ut = 545 N/mm², G = 81 370 N/mm², gap 1 mm.
  Printed: wire diameter d = 6.625083 mm (from τ = K·8PC/(πd²) = 545), rounded to 7 mm;
  D = 42 mm; N = 8 active coils; N_t = 10 total coils; free length 109.337611 mm
  = solid length N_t·d (70) + gaps (N_t − 1)·1 (9) + deflection at P, so the deflection is
  30.337611 mm.  Tolerance: one unit of the sixth printed decimal.
* Example 10.4 (valve spring): P = 150...300 N over 5 mm (rate 30 N/mm), d = 4 mm,
  D = 24 mm, G = 81 370 N/mm²: printed N = 6.278549 active coils.
"""

from geardesign.ball_clutch import spring as SP
from geardesign.core.registry import run_data
from tests.conftest import assert_ref

G = 81370.0


def test_example_10_1_wahl_stress_gives_the_printed_wire():
    d = 6.625083
    assert_ref(SP.shear_stress(1250.0, d, 6.0 * d), 545.0, 545.0 * 2 * 1e-6 / 6.6,
               "τ(d = 6.625083 mm, C = 6, P = 1250 N) = 0.5·1090")


def test_example_10_1_deflection_and_solid_length():
    c = SP.rate(G, 7.0, 42.0, 8)
    assert_ref(1250.0 / c, 109.337611 - 70.0 - 9.0, 1e-6, "deflection at 1250 N")
    assert SP.total_coils(8, "closed_ground") == 10
    assert_ref(SP.solid_length(8, 7.0, "closed_ground"), 70.0, 1e-12, "solid length N_t·d")


def test_example_10_4_active_coils():
    assert_ref(SP.active_coils(G, 4.0, 24.0, (300.0 - 150.0) / 5.0), 6.278549, 1e-6,
               "N for 30 N/mm")


def test_example_10_1_through_the_clutch_calculator():
    """The same spring as the clutch spring: the calculator reports the textbook's rate
    and, at the force 1250 N (preload 30.337611 mm less the smallest socket lift the spec
    allows, 0.001 mm, so that the lifted spring carries 1250 N), its stress."""
    c = SP.rate(G, 7.0, 42.0, 8)
    y0 = 1250.0 / c
    data = {
        "kind": "ball_clutch",
        "operation": {"torque": 10.0, "speed": 0.0},
        "safety": {"balls": 6, "ball_diameter": 16.0, "ball_circle": 200.0,
                   "socket_angle": 45.0, "socket_depth": 1e-3},
        "spring": {"wire_diameter": 7.0, "coil_diameter": 42.0, "active_coils": 8.0,
                   "shear_modulus": G, "preload": y0 - 1e-3, "free_length": 109.337611},
    }
    r = run_data(data).document()["results"]
    assert_ref(r["safety"]["c"], 1250.0 / 30.337611, 1e-5, "rate")
    assert_ref(r["spring"]["L_s"], 70.0, 1e-12, "solid length")
    assert_ref(r["spring"]["L1"], 109.337611 - (30.337611 - 1e-3), 1e-5,
               "installed length = s + gaps")
    assert_ref(r["spring"]["tau_max"], SP.shear_stress(1250.0, 7.0, 42.0), 1e-6, "τ at 1250 N")
