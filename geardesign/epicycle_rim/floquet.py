"""Numerical Floquet check of the Mathieu bands of the ring (paper B): the trace of the
monodromy matrix of Mathieu's equation by a sixth-order Magnus integrator over half a period
(numpy), and the band edges as the roots of |tr| = 2 near the characteristic values of
:mod:`geardesign.epicycle_rim.mathieu`.
"""

from __future__ import annotations

import math

from geardesign.epicycle_rim.mathieu import Band


def _steps(a: float, q: float) -> int:
    """Steps of the half period for a relative error of the monodromy matrix below ~1e-13
    (sixth order: the error falls 64-fold per halving; measured over a = 0.5…900,
    q = 0.05…400 against 8192 steps)."""
    return max(128, math.ceil(16.0 * math.sqrt(abs(a)) + 64.0 * math.sqrt(abs(q))))


def half_period_matrix(a: float, q: float, steps: int | None = None):
    """Transfer matrix of Mathieu's equation y'' + (a − 2q cos 2τ) y = 0 over τ ∈ [0, π/2]:
    columns (y, y') of the solutions with (y, y')(0) = (1, 0) and (0, 1) (a 2×2 numpy array).

    The equation is linear, y' = A(τ)y with A = [[0, 1], [−k(τ), 0]], so one step of length h
    is the exponential of the sixth-order Magnus series evaluated at the three Gauss points
    τ₀ + (1/2 ∓ √15/10)h, 1/2·h (A₁, A₂, A₃):

    .. math::
        α_1 = hA_2,\\quad α_2 = \\tfrac{\\sqrt{15}h}{3}(A_3 − A_1),\\quad
        α_3 = \\tfrac{10h}{3}(A_3 − 2A_2 + A_1),\\quad C_1 = [α_1, α_2],\\quad
        C_2 = −\\tfrac{1}{60}[α_1, 2α_3 + C_1],

        Ω = α_1 + \\tfrac{1}{12}α_3 + \\tfrac{1}{240}[−20α_1 − α_3 + C_1,\\ α_2 + C_2]

    Here A_i = [[0, 1], [−k_i, 0]] and every α, C and Ω is a traceless 2×2 matrix
    [[p, q], [r, −p]], whose commutator is [X, Y] = (q₁r₂ − q₂r₁, 2(p₁q₂ − p₂q₁),
    2(p₂r₁ − p₁r₂)).  Written out: α₁ = (0, h, −hk₂), α₂ = (0, 0, β), α₃ = (0, 0, γ) with
    β = −(√15h/3)(k₃ − k₁), γ = −(10h/3)(k₃ − 2k₂ + k₁); C₁ = (hβ, 0, 0), so the last
    commutator is [X, Y] with X = (hβ, −20h, 20hk₂ − γ), Y = (−hγ/30, h²β/30,
    β(1 + h²k₂/30)).  Ω being traceless, Ω² = (p² + qr)·I = s·I and
    exp Ω = cos θ·I + (sin θ/θ)·Ω with θ = √−s (cosh, sinh for s > 0) exactly.  All steps
    are computed at once (numpy) and multiplied pairwise.  Fixed step count
    :func:`_steps` (error ~1e-13 of the matrix).

    References
    ----------
    [Blanes2009] (the sixth-order Magnus integrator at three Gauss points); Floquet
    theory (monodromy matrix).
    """
    import numpy as np

    n = steps or _steps(a, q)
    h = 0.5 * math.pi / n
    t0 = h * np.arange(n)
    g = math.sqrt(15.0) / 10.0
    k1, k2, k3 = (a - 2.0 * q * np.cos(2.0 * (t0 + c * h)) for c in (0.5 - g, 0.5, 0.5 + g))
    beta = (-math.sqrt(15.0) * h / 3.0) * (k3 - k1)
    gamma = (-10.0 * h / 3.0) * (k3 - 2.0 * k2 + k1)
    px, qx, rx = h * beta, -20.0 * h, 20.0 * h * k2 - gamma
    py, qy, ry = (-h / 30.0) * gamma, (h * h / 30.0) * beta, beta * (1.0 + (h * h / 30.0) * k2)
    p = (qx * ry - qy * rx) / 240.0                       # Ω = α₁ + α₃/12 + [X, Y]/240
    qq = h + (px * qy - py * qx) / 120.0
    r = gamma / 12.0 - h * k2 + (py * rx - px * ry) / 120.0
    s = p * p + qq * r
    theta = np.sqrt(np.abs(s))
    osc = s < 0.0
    cos = np.where(osc, np.cos(theta), np.cosh(theta))
    sinc = np.where(theta > 0.0, np.where(osc, np.sin(theta), np.sinh(theta))
                    / np.where(theta > 0.0, theta, 1.0), 1.0)
    m = np.empty((n, 2, 2))
    m[:, 0, 0], m[:, 0, 1] = cos + sinc * p, sinc * qq
    m[:, 1, 0], m[:, 1, 1] = sinc * r, cos - sinc * p
    while len(m) > 1:            # later steps on the left: M = E_n ⋯ E_2 E_1
        if len(m) % 2:
            m = np.concatenate([m, np.eye(2)[None]])
        m = m[1::2] @ m[0::2]
    return m[0]


def floquet_trace(a: float, q: float) -> float:
    """Trace of the monodromy matrix of Mathieu's equation over τ ∈ [0, π].

    The coefficient a − 2q cos 2τ is even, so the even and odd solutions y₁, y₂ over the
    half period give the whole period: y₁(π) = y₂'(π) = 2y₁(π/2)·y₂'(π/2) − 1, hence

    .. math:: \\operatorname{tr} M = 2\\,(2\\,y_1(π/2)\\,y_2'(π/2) − 1)

    (:func:`half_period_matrix`).  |tr| < 2 stable, > 2 unstable; tr = ±2 exactly on the
    characteristic curves.

    References
    ----------
    [Magnus1966] §1.1 (Hill's equation with an even coefficient); Floquet theory;
    Yaglinskyi et al. 2017, eq. (6).
    """
    m = half_period_matrix(a, q)
    return float(2.0 * (2.0 * m[0, 0] * m[1, 1] - 1.0))


def floquet_band(order: int, mu: float, guess: Band) -> tuple[float, float] | None:
    """Region ``order`` along b = μa/2 located independently by the Floquet trace:
    roots of |tr M(a)| − 2 (:func:`floquet_trace`) bracketed around the edges of ``guess``
    and found to 1e-12 by :func:`geardesign.core.roots.bracket_root`.
    None if the region is too narrow to bracket (width < 1e-7 in a), or if an edge cannot
    be bracketed (the trace does not change sign within a quarter width of it, as at high
    orders where the region is extremely thin): the band is then not confirmed.

    The check runs without scipy: the equation is linear and periodic, so a fixed-step
    Magnus integrator of one half period (exact exponentials, all steps at once with
    numpy) gives the trace to ~1e-13 in a fraction of a millisecond, where an adaptive
    general-purpose integrator needs thousands of Python calls and the scipy import.
    """
    from geardesign.core.roots import bracket_root

    width = guess.a_hi - guess.a_lo
    if width < 1e-7:
        return None
    d = 0.25 * width

    def g(a: float) -> float:
        return abs(floquet_trace(a, 0.5 * mu * a)) - 2.0

    edges = []
    for edge in (guess.a_lo, guess.a_hi):
        a0, a1 = edge - d, edge + d
        g0, g1 = g(a0), g(a1)
        if g0 == 0.0 or g1 == 0.0 or (g0 < 0.0) == (g1 < 0.0):
            return None
        if g0 < 0.0:
            a0, a1 = a1, a0
        edges.append(bracket_root(g, a0, a1, 1e-12, closed=False))
    return edges[0], edges[1]
