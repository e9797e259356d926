"""Identities of the epicycle_rim functions over random inputs (hypothesis)."""

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.epicycle_rim import floquet as F
from geardesign.epicycle_rim import mathieu as M
from geardesign.epicycle_rim import mesh


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.0, 0.999), min_size=2, max_size=8), st.floats(1.01, 2.99))
def test_pair_count(phases, eps):
    p = mesh.pulsation(phases, eps)
    assert math.isclose(sum(w for w, _ in p.segments), 1.0, abs_tol=1e-12)
    assert math.isclose(p.mean, len(phases) * eps, rel_tol=1e-9)
    assert p.n_min <= p.mean <= p.n_max
    assert math.floor(eps) * len(phases) <= p.n_min
    assert p.n_max <= math.ceil(eps) * len(phases)
    assert all(m >= 0.0 for m in p.mu_h)


@settings(max_examples=40, deadline=None)
@given(st.integers(2, 8), st.integers(3, 40))
def test_equal_spacing_phases(n, k):
    """z_r a multiple of n_p: in phase; otherwise the first harmonic cancels."""
    z = n * k
    assert mesh.mesh_phases([360.0 * i / n for i in range(n)], z) == [0.0] * n
    p = mesh.pulsation(mesh.mesh_phases([360.0 * i / n for i in range(n)], z + 1), 1.5)
    assert p.mu_h[0] == 0.0


@settings(max_examples=40, deadline=None)
@given(st.floats(0.0, 30.0))
def test_characteristic_values_interlace(q):
    """a_0 < b_1 < a_1 < b_2 < a_2 < … for q > 0 (equal at q = 0)."""
    seq = [M.characteristic_value("a", 0, q)]
    for n in range(1, 6):
        seq += [M.characteristic_value("b", n, q), M.characteristic_value("a", n, q)]
    assert all(x <= y + 1e-9 for x, y in zip(seq, seq[1:]))
    if q == 0.0:
        assert seq == [0.0, 1.0, 1.0, 4.0, 4.0, 9.0, 9.0, 16.0, 16.0, 25.0, 25.0] or all(
            abs(a - b) < 1e-9 for a, b in zip(seq, [0, 1, 1, 4, 4, 9, 9, 16, 16, 25, 25]))


@settings(max_examples=40, deadline=None)
@given(st.floats(0.1, 5.0))
def test_constant_stiffness_trace(r):
    assert math.isclose(M.stepwise_trace([(1.0, 3)], r), 2.0 * math.cos(2 * math.pi / r),
                        abs_tol=1e-9)


@settings(max_examples=30, deadline=None)
@given(st.floats(-5.0, 900.0), st.floats(0.0, 30.0))
def test_floquet_trace_equals_an_adaptive_integration(a, q):
    """The Magnus half-period trace (numpy, fixed step, symmetry of the even coefficient)
    equals scipy's DOP853 over the whole period at rtol 1e-12, relative to the size of the
    monodromy matrix (whose growth sets what the trace can resolve)."""
    import numpy as np
    from scipy.integrate import solve_ivp

    def rhs(t, y):
        k = a - 2.0 * q * math.cos(2.0 * t)
        return [y[1], -k * y[0], y[3], -k * y[2]]

    y = solve_ivp(rhs, (0.0, math.pi), np.array([1.0, 0.0, 0.0, 1.0]), method="DOP853",
                  rtol=1e-12, atol=1e-13).y[:, -1]
    scale = max(1.0, float(np.abs(y).max()))
    assert abs(F.floquet_trace(a, q) - (y[0] + y[3])) <= 1e-8 * scale


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 30), st.floats(0.0, 20.0))
def test_floquet_trace_is_two_on_the_characteristic_curves(order, q):
    """|tr M| = 2 on a_r(q) and b_r(q) (periodic for even r, antiperiodic for odd r): the
    integrator and the eigenvalue route agree wherever the solutions stay moderate."""
    sign = 1.0 if order % 2 == 0 else -1.0
    kinds = ("a", "b") if order else ("a",)
    for kind in kinds:
        a = M.characteristic_value(kind, order, q)
        m = F.half_period_matrix(a, q)
        scale = max(1.0, float(abs(m).max()) ** 2)
        assert abs(F.floquet_trace(a, q) - 2.0 * sign) <= 1e-10 * scale


def test_magnus_integrator_is_of_sixth_order():
    """Halving the step divides the error of the half-period matrix by about 2⁶ = 64."""
    import numpy as np

    ref = F.half_period_matrix(16.5, 3.0, steps=4096)
    e = [float(np.abs(F.half_period_matrix(16.5, 3.0, steps=n) - ref).max())
         for n in (16, 32, 64)]
    assert 40.0 < e[0] / e[1] < 100.0 and 40.0 < e[1] / e[2] < 100.0
