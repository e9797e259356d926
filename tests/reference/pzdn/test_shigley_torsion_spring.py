"""Helical torsion spring of Shigley's Example 10-8 in metric units, as printed by the
public program MEtoolbox (GitHub OmriStein/MEtoolbox,
examples/springs_examples/HelicalToresionSpring_example.ipynb, commit 064ecbbb):
music wire d = 1.829 mm, OD = 15.081 mm (D = 13.25 mm), N_b = 4.25 body turns, two legs of
25.4 mm.  Printed: R_m = 2025.67 MPa (Table 10-4, A = 2211 MPa·mm^m, m = 0.145),
S_y = 0.45/0.577·R_m = 1579.81 MPa, active turns N_a = 4.66 (legs l/3 each), and a static
safety factor of 1.00 at M = 851.27 N·mm (σ = K_i·32M/(πd³), Wahl's inner-fibre K_i).

This checks the library strength law and the torsion-spring bending allowable added to
``geardesign/materials/spring_steel.py``, the "wahl" curvature factor and the "shigley"
leg model of the pzdn spring module.  The notebook's loaded diameter (9.83 mm) and free
length (7.77 mm) are not used: they take the twist in radians where turns are meant, and
the body as d·N_b.
"""

import math

from geardesign.materials import spring_steel
from geardesign.pzdn import spring as SP
from tests.conftest import assert_ref

d = 1.829
D = 15.081 - d


def test_strength_and_bending_allowable():
    wire = spring_steel.get("music_wire")
    assert_ref(wire.tensile_strength(d), 2025.67, 0.01, "S_ut, printed 2025.67 MPa")
    assert_ref(spring_steel.bending_allowable(wire, d), 1579.81, 0.05,
               "S_y = 0.45/0.577·S_ut, printed 1579.81 MPa")


def test_active_turns_with_legs():
    L_legs = 2 * SP.leg_length(25.4, D, "shigley")
    assert_ref(4.25 + L_legs / (math.pi * D), 4.66, 0.005, "N_a, printed 4.66")


def test_moment_at_static_safety_factor_one():
    wire = spring_steel.get("music_wire")
    k = SP.curvature_factor(D / d, "wahl")
    M = SP.allowable_torque(spring_steel.bending_allowable(wire, d), k, d)
    # printed M = 851.27 N·mm gives "static safety factor = 1.00" (two decimals)
    assert_ref(M, 851.27, 0.5, "M at n_s = 1, printed 851.27 N·mm")
    assert_ref(M / 851.27, 1.00, 0.005, "static safety factor, printed 1.00")

