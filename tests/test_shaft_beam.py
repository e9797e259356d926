"""The beam model's linear algebra: the vectorised assembly equals adding the element
matrices one by one, and the critical speed by power iteration equals the dense symmetric
eigenvalue problem ([GolubVanLoan] §8.2) over random stepped shafts."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.shaft import beam


def _shaft(seed: int, n: int):
    rng = np.random.default_rng(seed)
    x = np.concatenate([[0.0], np.cumsum(rng.uniform(0.5, 8.0, n - 1))])
    d = rng.uniform(15.0, 90.0, n - 1)
    EI = 2.06e5 * np.pi / 64.0 * d ** 4
    mass = 7.85e-6 * np.pi / 4.0 * d ** 2 * np.diff(x)
    pm = np.where(rng.uniform(size=n) < 0.1, rng.uniform(0.0, 50.0, n), 0.0)
    a, b = sorted(rng.choice(n, 2, replace=False))
    k = None if rng.uniform() < 0.5 else float(rng.uniform(1e4, 1e7))
    return x, EI, mass, pm, [(int(a), None), (int(b), k)]


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10 ** 6), st.integers(3, 120))
def test_assembly_equals_the_element_sum(seed, n):
    x, EI, mass, _, _ = _shaft(seed, n)
    K, M = beam.assemble(x, EI, mass)
    K1, M1 = np.zeros_like(K), np.zeros_like(M)
    for e in range(n - 1):
        s = slice(2 * e, 2 * e + 4)
        K1[s, s] += beam.element_stiffness(EI[e], x[e + 1] - x[e])
        M1[s, s] += beam.element_mass(mass[e], x[e + 1] - x[e])
    assert np.array_equal(K, K1) and np.array_equal(M, M1)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10 ** 6), st.integers(4, 120))
def test_power_iteration_equals_the_dense_eigenvalue(seed, n):
    x, EI, mass, pm, sup = _shaft(seed, n)
    _, omega = beam.solve(x, EI, mass, pm, [(np.zeros(n), np.zeros(n))], sup)
    K, M = beam.assemble(x, EI, mass)
    M[0::2, 0::2] += np.diag(pm)
    free = beam._supported(K, sup)
    L = np.linalg.cholesky(K[np.ix_(free, free)])
    C = np.linalg.solve(L, np.linalg.solve(L, M[np.ix_(free, free)]).T)
    mu = np.linalg.eigvalsh(0.5 * (C + C.T))[-1]
    assert abs(omega / np.sqrt(1000.0 / mu) - 1.0) < 1e-9
