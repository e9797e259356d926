"""The exact solution of the three-mass start-up model between two events when it is linear
(a constant motor torque, rising linearly or not; the model and its events:
:mod:`geardesign.pzdn.simulate`): ż = Ã·z over z = (φ1, ω1, φ2, ω2, φ3, ω3, t, 1), so
z(t) = exp(Ã(t − t0))·z0, with the matrix exponential by scaling and squaring (numpy).
"""

from __future__ import annotations

import math

from geardesign.pzdn.startup import ThreeMass


_PADE6 = (1.0, 1.0 / 2.0, 5.0 / 44.0, 1.0 / 66.0, 1.0 / 792.0, 1.0 / 15840.0, 1.0 / 665280.0)
"""Coefficients c_k = (2q − k)!·q!/((2q)!·k!·(q − k)!) of the diagonal [6/6] Padé
approximant of eˣ."""


def expm(x):
    """Matrix exponential of a square matrix, or of a stack of them (numpy array (..., n, n)).

    Scaling and squaring with the diagonal [6/6] Padé approximant: X/2ˢ with
    ‖X/2ˢ‖∞ <= 1/2, r(X) = D(X)⁻¹N(X), N = Σ c_k X^k, D = Σ (−1)^k c_k X^k, then squared s
    times.  The relative error of the approximant is below
    2^(3−2q)·(q!)²/((2q)!·(2q+1)!) = 3.4e-16 for q = 6 (Moler & Van Loan's bound), the
    rounding of a double.

    References
    ----------
    [Moler2003] §3 (method 3: Padé approximation with scaling and squaring, the error bound
    and its table of (p, q)).

    Example: exp(0) = I (identity):

    >>> import numpy as np
    >>> expm(np.zeros((2, 2))).tolist()
    [[1.0, 0.0], [0.0, 1.0]]
    """
    import numpy as np

    x = np.asarray(x, dtype=float)
    norm = float(np.abs(x).sum(axis=-1).max()) if x.size else 0.0
    s = max(0, math.ceil(math.log2(norm / 0.5))) if norm > 0.5 else 0
    x = x / 2.0 ** s
    eye = np.broadcast_to(np.eye(x.shape[-1]), x.shape)
    num, den, power = eye * _PADE6[0], eye * _PADE6[0], eye
    for k, c in enumerate(_PADE6[1:], start=1):
        power = power @ x
        num = num + c * power
        den = den + (-c if k % 2 else c) * power
    r = np.linalg.solve(den, num)
    for _ in range(s):
        r = r @ r
    return r


def linear_system(m: ThreeMass, c: tuple[float, float], moving, torque: tuple[float, float]):
    """The model between two events as ż = Ã·z, z = (φ1, ω1, φ2, ω2, φ3, ω3, t, 1), for a
    motor torque T_m = torque[0] + torque[1]·t (an 8×8 numpy array): the equations of the
    module docstring with the masses that are not ``moving`` at rest."""
    import numpy as np

    a = np.zeros((8, 8))
    a[6, 7] = 1.0                                  # ṫ = 1
    a[0, 1] = 1.0
    a[1, 7], a[1, 6] = torque[0] / m.J1, torque[1] / m.J1
    for j, (C, cj, J, T) in enumerate(((m.C12, c[0], m.J2, m.T2), (m.C13, c[1], m.J3, m.T3))):
        link = link_row(C, cj, j)                     # T_1j = link·z
        a[1] -= link / m.J1
        if moving[j]:
            a[2 + 2 * j, 3 + 2 * j] = 1.0
            a[3 + 2 * j] = link / J
            a[3 + 2 * j, 7] -= T / J
    return a


def link_row(C: float, cj: float, j: int):
    """T_1j = C(φ1 − φj) + c(ω1 − ωj) as a row over z (j = 0: link 1-2, j = 1: link 1-3)."""
    import numpy as np

    row = np.zeros(8)
    row[0], row[1], row[2 + 2 * j], row[3 + 2 * j] = C, cj, -C, -cj
    return row


class _Exact:
    """One segment of the linear model: z(t) = exp(Ã·(t − t0))·z0, evaluated at a sorted
    array of times by one matrix exponential per distinct spacing (a uniform grid: a few)."""

    def __init__(self, a, t0: float, z0):
        self.a, self.t0, self.z0 = a, t0, z0

    def __call__(self, t):
        import numpy as np

        t = np.atleast_1d(np.asarray(t, dtype=float))
        order = np.argsort(t, kind="stable")
        steps = np.diff(np.concatenate(([self.t0], t[order])))
        unique, which = np.unique(steps, return_inverse=True)
        e = expm(self.a[None] * unique[:, None, None])
        out = np.empty((6, t.size))
        z = self.z0
        for i, k in zip(order, which):
            z = e[k] @ z
            out[:, i] = z[:6]
        return out


def _crossed(g0: float, g1: float, direction: float) -> bool:
    """An event between two steps, as scipy's ``solve_ivp`` detects it: up g0 <= 0 <= g1
    (direction > 0), down g0 >= 0 >= g1 (direction < 0)."""
    return (g0 <= 0.0 <= g1) if direction > 0 else (g0 >= 0.0 >= g1)


def exact_segment(a, t0: float, t1: float, z0, events, step: float):
    """Advance z0 from t0 towards t1 exactly in steps of at most ``step`` until one of the
    ``events`` (row over z, direction) fires: (t, z, index of the event or None, solution).
    The event's time is refined to ~4 ulp by the Illinois regula falsi on the exact solution
    (:func:`geardesign.core.roots.bracket_root`)."""
    import numpy as np

    from geardesign.core.roots import bracket_root

    n = max(1, math.ceil((t1 - t0) / step - 1e-9))
    h = (t1 - t0) / n
    e = expm(a * h)
    z, g = z0, [float(row @ z0) for row, _ in events]
    for k in range(n):
        tk = t0 + k * h
        z_new = e @ z if k < n - 1 else expm(a * (t1 - tk)) @ z
        g_new = [float(row @ z_new) for row, _ in events]
        fired = []
        for i, (row, direction) in enumerate(events):
            if _crossed(g[i], g_new[i], direction):
                def f(tau, row=row, z=z, sign=direction):
                    return sign * float(row @ (expm(a * tau) @ z))
                tau = bracket_root(f, h if k < n - 1 else t1 - tk, 0.0,
                                   4.0 * np.finfo(float).eps * max(1.0, abs(t1)), closed=True)
                fired.append((tau, i))
        if fired:
            tau, i = min(fired)
            return tk + tau, expm(a * tau) @ z, i, _Exact(a, t0, z0)
        z, g = z_new, g_new
    return t1, z, None, _Exact(a, t0, z0)


