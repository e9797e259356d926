"""Identities of the epicycle_rim functions over random inputs (hypothesis)."""

import math

from hypothesis import given, settings
from hypothesis import strategies as st

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
