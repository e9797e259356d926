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


def orbit(e, z, n: int, block: int = 64):
    """The states eᵏ·z for k = 1 … n as the rows of an (n, len(z)) array: the repeated step
    of a linear system (e the exponential of one step), in blocks of ``block`` steps, each
    the stacked powers e¹ … e^block times the block's first state (one numpy product a
    block instead of one a step; the powers by doubling).  Equal to n successive products
    e·z to the rounding of a few steps.

    >>> import numpy as np
    >>> orbit(np.array([[2.0]]), np.array([1.0]), 5).ravel().tolist()
    [2.0, 4.0, 8.0, 16.0, 32.0]
    """
    import numpy as np

    out = np.empty((n, z.size))
    b = min(block, n)
    if b <= 0:
        return out
    powers = np.empty((b,) + e.shape)
    powers[0] = e
    k = 1
    while k < b:                      # e^(j+1)·e^k = e^(j+1+k): the powers by doubling
        m = min(k, b - k)
        powers[k:k + m] = powers[:m] @ powers[k - 1]
        k += m
    i = 0
    while i < n:
        size = min(b, n - i)
        out[i:i + size] = powers[:size] @ z
        z = out[i + size - 1]
        i += size
    return out


class _Exact:
    """One segment of the linear model: z(t) = exp(Ã·(t − t0))·z0, evaluated at a sorted
    array of times.  Times on a uniform grid (to a few ulp, as ``numpy.linspace`` writes
    them) are stepped by one exponential (:func:`orbit`); any others by one matrix
    exponential per distinct spacing."""

    def __init__(self, a, t0: float, z0):
        self.a, self.t0, self.z0 = a, t0, z0

    def __call__(self, t):
        import numpy as np

        t = np.atleast_1d(np.asarray(t, dtype=float))
        order = np.argsort(t, kind="stable")
        ts = t[order]
        out = np.empty((6, t.size))
        grid = _uniform(ts)
        if grid is not None:
            first, h = grid
            z = expm(self.a * (first - self.t0)) @ self.z0
            states = np.vstack((z, orbit(expm(self.a * h), z, ts.size - 1)))
            out[:, order] = states[:, :6].T
            return out
        steps = np.diff(np.concatenate(([self.t0], ts)))
        unique, which = np.unique(steps, return_inverse=True)
        e = expm(self.a[None] * unique[:, None, None])
        z = self.z0
        for i, k in zip(order, which):
            z = e[k] @ z
            out[:, i] = z[:6]
        return out


def _uniform(ts):
    """(first time, step) when the sorted times ``ts`` (at least 8) lie on a uniform grid
    to 16 ulp of the largest, else None."""
    import numpy as np

    n = ts.size
    if n < 8:
        return None
    h = (ts[-1] - ts[0]) / (n - 1)
    if not h > 0.0:
        return None
    dev = np.abs(ts - (ts[0] + np.arange(n) * h)).max()
    scale = max(abs(float(ts[0])), abs(float(ts[-1])))
    return (float(ts[0]), float(h)) if dev <= 16.0 * np.finfo(float).eps * scale else None


def _crossed(g0: float, g1: float, direction: float) -> bool:
    """An event between two steps, as scipy's ``solve_ivp`` detects it: up g0 <= 0 <= g1
    (direction > 0), down g0 >= 0 >= g1 (direction < 0)."""
    return (g0 <= 0.0 <= g1) if direction > 0 else (g0 >= 0.0 >= g1)


_CHUNK = 4096
"""Steps of :func:`exact_segment` stepped and tested in one go (32 kB of states each)."""


def exact_segment(a, t0: float, t1: float, z0, events, step: float):
    """Advance z0 from t0 towards t1 exactly in steps of at most ``step`` until one of the
    ``events`` (row over z, direction) fires: (t, z, index of the event or None, solution).
    The steps are taken a block at a time (:func:`orbit`), the event rows over each
    block's states in one product; the first step with a sign change in the direction asked
    for (:func:`_crossed`) is the event's, and its time is refined to ~4 ulp by the Illinois
    regula falsi on the exact solution (:func:`geardesign.core.roots.bracket_root`)."""
    import numpy as np

    from geardesign.core.roots import bracket_root

    n = max(1, math.ceil((t1 - t0) / step - 1e-9))
    h = (t1 - t0) / n
    rows = np.array([row for row, _ in events], dtype=float).reshape(len(events), z0.size)
    up = np.array([direction > 0 for _, direction in events], dtype=bool)
    tol = 4.0 * np.finfo(float).eps * max(1.0, abs(t1))

    def fired(k: int, z, g0, g1, length: float):
        """The earliest event between step k's start z and its end (None: none)."""
        out = []
        for i, (row, direction) in enumerate(events):
            if _crossed(g0[i], g1[i], direction):
                def f(tau, row=row, z=z, sign=direction):
                    return sign * float(row @ (expm(a * tau) @ z))
                out.append((bracket_root(f, length, 0.0, tol, closed=True), i))
        if not out:
            return None
        tau, i = min(out)
        return t0 + k * h + tau, expm(a * tau) @ z, i, _Exact(a, t0, z0)

    z, g = z0, rows @ z0
    e = expm(a * h) if n > 1 else None
    done = 0                                  # steps 0 … n − 2 end on the grid, a chunk
    while done < n - 1:                       # at a time (bounded memory)
        size = min(_CHUNK, n - 1 - done)
        states = orbit(e, z, size)
        values = states @ rows.T
        before = np.vstack((g, values[:-1]))
        hits = np.where(up, (before <= 0.0) & (values >= 0.0),
                        (before >= 0.0) & (values <= 0.0)).any(axis=1)
        if hits.any():
            j = int(np.argmax(hits))
            return fired(done + j, z if j == 0 else states[j - 1], before[j], values[j], h)
        z, g = states[-1], values[-1]
        done += size
    tk = t0 + (n - 1) * h                                  # the last step ends at t1
    z_new = expm(a * (t1 - tk)) @ z
    g_new = rows @ z_new
    hit = fired(n - 1, z, g, g_new, t1 - tk)
    if hit is not None:
        return hit
    return t1, z_new, None, _Exact(a, t0, z0)
