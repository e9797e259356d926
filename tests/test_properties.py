"""Geometry identities over random valid pairs (hypothesis)."""

import math

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from geardesign.involute import inv, inv_inverse
from geardesign.gears.geometry import (
    BasicRack,
    GeometryError,
    PairInput,
    pair_geometry,
    shift_sum_for_center_distance,
)
from geardesign.spur.kinematics import balanced_shift_split, sliding_at_ends

pairs = st.builds(
    lambda m, z1, z2, beta, x1, x2, b, alpha: PairInput(
        m, z1, z2, x1, x2, math.radians(beta), b, BasicRack(math.radians(alpha))),
    m=st.floats(0.5, 25.0), z1=st.integers(8, 150), z2=st.integers(8, 300),
    beta=st.floats(0.0, 40.0), x1=st.floats(-0.5, 1.0), x2=st.floats(-0.5, 1.0),
    b=st.floats(5.0, 200.0), alpha=st.floats(14.5, 30.0),
)


def geometry(p):
    try:
        return pair_geometry(p)
    except GeometryError:
        assume(False)


@settings(max_examples=300, deadline=None)
@given(pairs)
def test_line_of_action_identities(p):
    g = geometry(p)
    # N1N2 = a_w sin α_tw = ρ_w1 + ρ_w2 = (d_b1 + d_b2)/2 · tan α_tw
    rho_w = [0.5 * gear.d_w * math.sin(g.alpha_tw) for gear in g.gears]
    assert math.isclose(g.g_w, sum(rho_w), rel_tol=1e-12)
    assert math.isclose(g.g_w, 0.5 * (g.g1.d_b + g.g2.d_b) * math.tan(g.alpha_tw), rel_tol=1e-12)
    # the lower active point of one gear is the tip of the other, on the same line
    assert math.isclose(g.g1.rho_p + g.g2.rho_a, g.g_w, rel_tol=1e-12)
    # working circles roll: a_w = (d_w1 + d_w2)/2, d_b = d_w cos α_tw
    assert math.isclose(g.a_w, 0.5 * (g.g1.d_w + g.g2.d_w), rel_tol=1e-12)
    for gear in g.gears:
        assert math.isclose(gear.d_b, gear.d_w * math.cos(g.alpha_tw), rel_tol=1e-12)


@settings(max_examples=300, deadline=None)
@given(pairs)
def test_contact_ratio_two_ways(p):
    g = geometry(p)
    assert math.isclose(g.eps_alpha, g.eps_alpha_z, rel_tol=1e-10, abs_tol=1e-12)


@settings(max_examples=300, deadline=None)
@given(pairs)
def test_working_angle_and_reverse_task(p):
    g = geometry(p)
    lhs = inv(g.alpha_tw)
    rhs = 2 * g.x_sum * math.tan(p.rack.alpha_n) / (p.z1 + p.z2) + inv(g.alpha_t)
    assert abs(lhs - rhs) < 1e-13
    x_sum, alpha_tw = shift_sum_for_center_distance(g.a_w, p.m_n, p.z1, p.z2, p.rack.alpha_n,
                                                    p.beta)
    assert abs(x_sum - g.x_sum) < 1e-9
    assert abs(alpha_tw - g.alpha_tw) < 1e-12


@settings(max_examples=300, deadline=None)
@given(st.floats(1e-9, 5.0))
def test_inverse_involute(v):
    theta = inv_inverse(v)
    assert abs(inv(theta) - v) <= 1e-12 * max(1.0, v) + 1e-15


@settings(max_examples=60, deadline=None)
@given(pairs)
def test_balanced_split_equalises_sliding(p):
    g = geometry(p)
    try:
        x1 = balanced_shift_split(p, g.x_sum)
    except GeometryError:
        assume(False)
    q = PairInput(p.m_n, p.z1, p.z2, x1, g.x_sum - x1, p.beta, p.b_w, p.rack)
    s = sliding_at_ends(pair_geometry(q))
    assert math.isclose(s.theta1_A, s.theta2_E, rel_tol=1e-6, abs_tol=1e-6)
