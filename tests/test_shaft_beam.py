"""The beam model's banded linear algebra against dense numpy over random stepped shafts:
the banded assembly equals adding the element matrices one by one, the banded Cholesky
solution equals the dense solve, and the critical speed by power iteration equals the dense
symmetric eigenvalue problem ([GolubVanLoan] §4.3.5, §8.2).  Two roundings of one model
agree to its conditioning (a soft spring beside a stiff shaft conditions K worst)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.shaft import beam


def _shaft(seed: int, n: int):
    rng = np.random.default_rng(seed)
    x = np.concatenate([[0.0], np.cumsum(rng.uniform(0.5, 8.0, n - 1))]).tolist()
    d = rng.uniform(15.0, 90.0, n - 1)
    EI = (2.06e5 * np.pi / 64.0 * d ** 4).tolist()
    mass = (7.85e-6 * np.pi / 4.0 * d ** 2 * np.diff(x)).tolist()
    pm = np.where(rng.uniform(size=n) < 0.1, rng.uniform(0.0, 50.0, n), 0.0).tolist()
    a, b = sorted(rng.choice(n, 2, replace=False))
    k = None if rng.uniform() < 0.5 else float(rng.uniform(1e5, 1e7))   # bearings
    return x, EI, mass, pm, [(int(a), None), (int(b), k)]


def _dense_model(x, EI, mass, pm, sup):
    n = len(x)
    K, M = np.zeros((2 * n, 2 * n)), np.zeros((2 * n, 2 * n))
    for e in range(n - 1):
        s = slice(2 * e, 2 * e + 4)
        K[s, s] += beam.element_stiffness(EI[e], x[e + 1] - x[e])
        M[s, s] += beam.element_mass(mass[e], x[e + 1] - x[e])
    M[0::2, 0::2] += np.diag(pm)
    K0 = K.copy()
    for node, k in sup:
        if k is not None:
            K[2 * node, 2 * node] += k
    free = [i for i in range(2 * n) if i not in {2 * nd for nd, k in sup if k is None}]
    return K0, K[np.ix_(free, free)], M[np.ix_(free, free)], free


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10 ** 6), st.integers(3, 120))
def test_band_assembly_equals_the_element_sum(seed, n):
    x, EI, mass, pm, sup = _shaft(seed, n)
    K, M = beam.assemble(x, EI, mass)
    n2 = 2 * n
    K1, M1 = np.zeros((n2, n2)), np.zeros((n2, n2))
    for e in range(n - 1):
        s = slice(2 * e, 2 * e + 4)
        K1[s, s] += beam.element_stiffness(EI[e], x[e + 1] - x[e])
        M1[s, s] += beam.element_mass(mass[e], x[e + 1] - x[e])
    assert np.array_equal(np.array(beam.dense(K)), K1)
    assert np.array_equal(np.array(beam.dense(M)), M1)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10 ** 6), st.integers(4, 120))
def test_banded_solution_equals_the_dense_one(seed, n):
    x, EI, mass, pm, sup = _shaft(seed, n)
    rng = np.random.default_rng(seed + 1)
    F, C = rng.uniform(-1e4, 1e4, n), rng.uniform(-1e5, 1e5, n)
    K0, Kf, Mf, free = _dense_model(x, EI, mass, pm, sup)
    try:
        (p,), omega = beam.solve(x, EI, mass, pm, [(F.tolist(), C.tolist())], sup)
    except beam.NotPositiveDefinite:
        # refused as singular to working precision: only a model that is nearly so
        assert np.linalg.cond(Kf) > 1e13
        return
    rhs = np.zeros(2 * n)
    rhs[0::2], rhs[1::2] = F, C
    u = np.zeros(2 * n)
    u[free] = np.linalg.solve(Kf, rhs[free])
    tol = max(1e-12, 1e-15 * np.linalg.cond(Kf))     # forward error ≲ κ(K)·ε
    assert np.allclose(p.w, u[0::2], rtol=tol, atol=tol * np.abs(u[0::2]).max())
    assert np.allclose(p.theta, u[1::2], rtol=tol, atol=tol * np.abs(u[1::2]).max())
    L = np.linalg.cholesky(Kf)
    Cm = np.linalg.solve(L, np.linalg.solve(L, Mf).T)
    mu = np.linalg.eigvalsh(0.5 * (Cm + Cm.T))[-1]
    assert omega == pytest.approx(np.sqrt(1000.0 / mu), rel=tol)


def test_a_shaft_not_held_is_not_positive_definite():
    x, EI, mass, pm, _ = _shaft(3, 20)
    with pytest.raises(beam.NotPositiveDefinite):
        beam.solve(x, EI, mass, pm, [([0.0] * 20, [0.0] * 20)], [(5, None)])
