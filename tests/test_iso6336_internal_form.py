"""ISO 6336-3 method B for internal gears cut by a shaper (``part3.internal_tooth_form``):
finite and positive over random internal gears and cutters, and in the limit of a large
gear cut by a large cutter the root chord and fillet of the rack (a circle of radius ρ_a0
tangent to the root line and the straight flank, the critical point at the 60° tangent).
The published values (KISSsoft NREL rings) are in ``tests/reference/planetary``."""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from geardesign.spur.strength.iso6336 import part3 as P3

A = math.radians(20.0)


def _form(z, x, z0, x0, rho, eps=1.6, m=1.0, h_a=1.0, h_f=1.25):
    d = z * m
    return P3.internal_tooth_form(z, x, m, A, 0.0, 0.0, d, d - 2.0 * (h_a + x) * m,
                                  d + 2.0 * (h_f - x) * m, eps, z0, x0, rho * m)


@settings(max_examples=150, deadline=None)
@given(z=st.integers(40, 400), x=st.floats(-0.6, 0.6), dz=st.integers(8, 200),
       x0=st.floats(-0.2, 0.3), rho=st.floats(0.0, 0.38), eps=st.floats(1.05, 1.9))
def test_internal_form_finite_and_positive(z, x, dz, x0, rho, eps):
    z0 = z - dz
    assume(z0 >= 12)
    tf = _form(z, x, z0, x0, rho, eps)
    if tf is None:        # no such cutter (its rounding inside its base circle): rack used
        return
    assert tf.rho_F > 0.0
    for value in (tf.Y_F, tf.Y_S, tf.s_Fn, tf.h_Fe, tf.q_s):
        assert math.isfinite(value) and value > 0.0
    assert tf.rho_F >= rho * (1.0 - 1e-9)        # the rounding plus its path's curvature
    assert tf.Y_F * tf.Y_S > 0.5          # a sharp cutter (ρ_a0 → 0) gives a large Y_S


def _rack_60(x, rho, m=1.0, h_f=1.25):
    """Closed form of the rack: the fillet circle tangent to the root line (h_f − x m below
    the reference line) and to the flank (thickness m(π/2 + 2x tan α) at the reference
    line); the point where its tangent makes 60° with the centre line, its normal 30° from
    the root line's normal: u = u_c − ρ sin 30°."""
    s = m * (0.5 * math.pi + 2.0 * x * math.tan(A))
    depth = (h_f - x) * m
    u_c = 0.5 * s + (depth - rho) * math.tan(A) + rho / math.cos(A)
    return 2.0 * (u_c - rho * math.sin(math.pi / 6.0))


def test_internal_form_tends_to_the_rack():
    for x, rho in ((0.0, 0.25), (0.3, 0.3), (-0.3, 0.2)):
        tf = _form(200000, x, 100000, 0.0, rho)
        assert tf.s_Fn == pytest.approx(_rack_60(x, rho), rel=2e-4)
        assert tf.rho_F == pytest.approx(rho, rel=2e-4)
        far = _form(400000, x, 200000, 0.0, rho)
        assert far.Y_F * far.Y_S == pytest.approx(tf.Y_F * tf.Y_S, rel=1e-3)
