"""Chordal tooth thickness and height: the worked examples of SDP/SI "Elements of Metric
Gear Technology", section 10 "Tooth thickness" (the same examples as the KHK Gear
Technical Reference), table 10-1 (spur gear) and table 10-3 (helical gear, normal system),
as printed on the public copies of page T-81 ([SDPSI]; [KHK]).

Table 10-1, m = 10, α = 20°, z = 12, x = +0.3, h_a = 13.000: s = 17.8918, s̄ = 17.8256,
h̄ = 13.6657.  Our chordal() is the same relation (ψ = s/d): tolerance one unit of the
last printed digit.

Table 10-3, m_n = 5, α_n = 20°, β = 25°, z = 16, x_n = +0.2, h_a = 6.0000: s_n = 8.5819,
z_v = 21.4928, s̄ = 8.5728, h̄ = 6.1712.  SDP/SI takes the virtual spur gear with
z_v = z/cos³β; chordal() takes the exact one of ISO 21771 / DIN 3960, d_n = d/cos²β_b
(z_n = 21.4714), as KISSsoft does (``test_measurement_kisssoft.py``).  The test shows both:
SDP's relation reproduces SDP's numbers, and ours differs from them by what the two virtual
gears give (s̄ 0.0005 mm, h̄ 0.0044 mm).
"""

import math

from geardesign.spur.measurement import Tooth, chordal
from tests.conftest import assert_ref

A20 = math.radians(20.0)


def test_sdp_table_10_1_spur():
    m, z, x = 10.0, 12, 0.3
    s = m * (0.5 * math.pi + 2 * x * math.tan(A20))
    assert_ref(s, 17.8918, 0.00005, "SDP/SI 10-1: s")
    c = chordal(Tooth(z, m, A20, 0.0, s, z * m + 2 * 13.0, 0.0))
    assert_ref(c.s_c, 17.8256, 0.00005, "SDP/SI 10-1: chordal thickness")
    assert_ref(c.h_c, 13.6657, 0.00005, "SDP/SI 10-1: chordal height")


def test_sdp_table_10_3_helical_normal_system():
    m_n, z, beta, x_n, h_a = 5.0, 16, math.radians(25.0), 0.2, 6.0
    s_n = m_n * (0.5 * math.pi + 2 * x_n * math.tan(A20))
    assert_ref(s_n, 8.5819, 0.00005, "SDP/SI 10-3: s_n")
    # SDP/SI's own relation, z_v = z/cos³β
    z_v = z / math.cos(beta) ** 3
    assert_ref(z_v, 21.4928, 0.00005, "SDP/SI 10-3: z_v")
    psi = s_n / (z_v * m_n)
    assert_ref(math.degrees(psi), 4.57556, 0.000005, "SDP/SI 10-3: θ_v")
    assert_ref(z_v * m_n * math.sin(psi), 8.5728, 0.00005, "SDP/SI 10-3: s̄ (z_v)")
    assert_ref(0.5 * z_v * m_n * (1 - math.cos(psi)) + h_a, 6.1712, 0.00005,
               "SDP/SI 10-3: h̄ (z_v)")
    # ours, with the exact virtual gear d_n = d/cos²β_b
    d = z * m_n / math.cos(beta)
    c = chordal(Tooth(z, m_n, A20, beta, s_n, d + 2 * h_a, 0.0))
    assert_ref(c.s_c, 8.5728, 0.0006, "SDP/SI 10-3: s̄ (d/cos²β_b)")
    assert_ref(c.h_c, 6.1712, 0.0045, "SDP/SI 10-3: h̄ (d/cos²β_b)")
