"""Thin-ring hoop-stress estimate against the classical closed ring in diametral loading.

Source: S. Timoshenko, Strength of Materials, Part I (3rd ed., 1955), thin ring compressed by
two equal and opposite forces P along a diameter: bending moment at the loads
M1 = P·R/π = 0.318·P·R and at 90° from them M0 = P·R(1/2 − 1/π) = 0.182·P·R; normal force
N0 = P/2 at 90° and 0 at the loads.  (Outward forces change only the signs.)  Tolerance:
the three printed digits.
"""

import math

from geardesign.epicycle_rim.stress import thin_ring_hoop_stress
from tests.conftest import assert_ref


def test_two_radial_loads():
    # choose the torque so that F_r = 1000 N with two "planets", α = 45°: F_t = F_r
    m, z, n, b, delta = 2.0, 100, 2, 10.0, 5.0
    d = m * z
    torque = 1000.0 * d * n / 2000.0
    h = thin_ring_hoop_stress(torque, m, z, n, b, delta, math.radians(45.0))
    assert math.isclose(h.F_r, 1000.0)
    R = h.R_m
    assert_ref(h.M_load / (h.F_r * R), 0.318, 0.0005, "M1/(PR) at the loads")
    assert_ref(h.M_between / (h.F_r * R), 0.182, 0.0005, "M0/(PR) at 90°")
    assert abs(h.N_load) < 1e-9 and math.isclose(h.N_between, 500.0)
