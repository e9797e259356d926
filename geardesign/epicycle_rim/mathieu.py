"""Parametric resonance of the ring: the Mathieu equation, its Ince-Strutt stability chart,
and Floquet checks (paper B).

Pure functions on plain data (floats, lists); the optional numerical Floquet check is
:mod:`geardesign.epicycle_rim.floquet`.

Paper B writes the ring's motion as q̈ + k0²(1 − μ cos Ωt) q = 0 (eq. (5)) and, with τ = Ωt/2,

.. math:: \\frac{d^2 q}{dτ^2} + (a - 2b\\cos 2τ)\\, q = 0,\\qquad a = \\frac{4k_0^2}{Ω^2},\\quad
          b = \\frac{μ a}{2}                                            \\qquad (6)

which is Mathieu's equation in the standard form with q ≡ b.  For b > 0 the n-th region of
instability lies between the characteristic values b_n(b) and a_n(b); a system with pulsation
depth μ moves along the straight line b = μa/2, so the n-th resonance (a ≈ n², Ω ≈ 2k0/n)
is unstable for a between the crossings of that line with b_n and a_n.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass

# ----------------------------------------------------------------- series (8) of paper B


def series_boundaries(order: int, b: float) -> tuple[float, float]:
    """Boundaries (lower, upper) of the instability region ``order`` by paper B's series.

    .. math::
        a_1^{(∓)} = 1 ∓ b - \\frac{b^2}{8} ± \\frac{b^3}{64} - \\frac{b^4}{1536},\\quad
        a_2^{(-)} = 4 - \\frac{b^2}{12} + \\frac{5 b^4}{13824},\\quad
        a_2^{(+)} = 4 + \\frac{5 b^2}{12} - \\frac{763 b^4}{13824},\\quad
        a_3^{(∓)} = 9 + \\frac{b^2}{16} ∓ \\frac{b^3}{64} + \\frac{13 b^4}{20480}

    (order 0: the single boundary a_0 = −b²/2 + 7b⁴/128, returned twice).  Small b only.

    References
    ----------
    Yaglinskyi et al. 2017, eq. (8) (first terms: (7), a = 1 ± b by harmonic balance);
    identical to Abramowitz & Stegun 20.2.25 with q ≡ b.
    """
    if order == 0:
        a0 = -b * b / 2.0 + 7.0 * b ** 4 / 128.0
        return a0, a0
    if order == 1:
        return (1.0 - b - b * b / 8.0 + b ** 3 / 64.0 - b ** 4 / 1536.0,
                1.0 + b - b * b / 8.0 - b ** 3 / 64.0 - b ** 4 / 1536.0)
    if order == 2:
        return (4.0 - b * b / 12.0 + 5.0 * b ** 4 / 13824.0,
                4.0 + 5.0 * b * b / 12.0 - 763.0 * b ** 4 / 13824.0)
    if order == 3:
        return (9.0 + b * b / 16.0 - b ** 3 / 64.0 + 13.0 * b ** 4 / 20480.0,
                9.0 + b * b / 16.0 + b ** 3 / 64.0 + 13.0 * b ** 4 / 20480.0)
    raise ValueError("paper B's series (8) covers orders 0 to 3 only")


SERIES_ORDERS = (1, 2, 3)


# ----------------------------------------------------------------- exact characteristic values


def _count_below(diag: list[float], off2: list[float], x: float) -> int:
    """Eigenvalues < x of a symmetric tridiagonal matrix (Sturm sequence, LDLᵀ pivots)."""
    count = 0
    p = diag[0] - x
    if p < 0.0:
        count += 1
    for d, e2 in zip(diag[1:], off2):
        if p == 0.0:
            p = 1e-300
        p = d - x - e2 / p
        if p < 0.0:
            count += 1
    return count


def characteristic_value(kind: str, order: int, q: float, tol: float = 1e-13) -> float:
    """Mathieu characteristic value a_r(q) (``kind="a"``, even solutions) or b_r(q)
    (``kind="b"``, odd solutions) for q >= 0.

    They are the eigenvalues of the symmetric tridiagonal matrices of the recurrences of the
    Fourier coefficients (cos 2mτ, cos (2m+1)τ, sin (2m+1)τ, sin (2m+2)τ series):

    ==================  =============================  ===========================
    value               diagonal                        off-diagonal
    ==================  =============================  ===========================
    a_{2m}              0, 4, 16, 36, …                 √2·q, q, q, …
    a_{2m+1}            1 + q, 9, 25, …                 q, q, …
    b_{2m+1}            1 − q, 9, 25, …                 q, q, …
    b_{2m+2}            4, 16, 36, …                    q, q, …
    ==================  =============================  ===========================

    the m-th smallest eigenvalue, found by bisection on the Sturm count to ``tol``.

    References
    ----------
    DLMF §28.4(ii) (recurrences); Abramowitz & Stegun 20.2.5-20.2.11; checked against the
    printed output of Zhang & Jin, Computation of Special Functions (1996), program MCVA2.

    Example: at q = 0 the characteristic values are a_r = b_r = r² (identity):

    >>> round(characteristic_value("a", 2, 0.0), 9), round(characteristic_value("b", 1, 0.0), 9)
    (4.0, 1.0)
    """
    if q < 0.0:
        raise ValueError("q must be >= 0")
    if kind == "b" and order < 1:
        raise ValueError("b_r starts at r = 1")
    n = order // 2 + 14 + int(3.0 * math.sqrt(q))
    if kind == "a" and order % 2 == 0:
        diag = [float((2 * k) ** 2) for k in range(n)]
        off2 = [2.0 * q * q] + [q * q] * (n - 2)
        index = order // 2
    elif order % 2 == 1:
        diag = [float((2 * k + 1) ** 2) for k in range(n)]
        diag[0] += q if kind == "a" else -q
        off2 = [q * q] * (n - 1)
        index = order // 2
    else:  # b, even
        diag = [float((2 * k + 2) ** 2) for k in range(n)]
        off2 = [q * q] * (n - 1)
        index = order // 2 - 1
    lo = diag[index] - 2.0 * q - 2.0
    hi = diag[index] + 2.0 * q + 2.0
    while _count_below(diag, off2, lo) > index:
        lo -= 2.0 * q + 2.0
    while _count_below(diag, off2, hi) <= index:
        hi += 2.0 * q + 2.0
    while hi - lo > tol * max(1.0, abs(lo)):
        mid = 0.5 * (lo + hi)
        if _count_below(diag, off2, mid) > index:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def boundaries(order: int, q: float) -> tuple[float, float]:
    """(lower, upper) boundary of the instability region ``order`` >= 1 at q >= 0:
    (b_n(q), a_n(q)).  Order 0: (a_0(q), a_0(q))."""
    if order == 0:
        a0 = characteristic_value("a", 0, q)
        return a0, a0
    return characteristic_value("b", order, q), characteristic_value("a", order, q)


# ----------------------------------------------------------------- the working line b = μa/2


def _on_line(curve, order: int, mu: float) -> float:
    """Solve a = curve(μa/2) near a = order² by fixed-point iteration (|μ/2·dc/dq| < 1)."""
    a = float(order * order)
    for _ in range(200):
        new = curve(0.5 * mu * a)
        if abs(new - a) <= 1e-13 * max(1.0, abs(a)):
            return new
        a = new
    return a


@dataclass(frozen=True)
class Band:
    """Instability region ``order`` crossed by the line b = μa/2.

    ``a_lo``/``a_hi`` bound it in a; ``ratio_lo``/``ratio_hi`` = Ω/k0 = 2/√a (so ratio_lo
    comes from a_hi).
    """

    order: int
    a_lo: float
    a_hi: float

    @property
    def ratio_lo(self) -> float:
        return 2.0 / math.sqrt(self.a_hi)

    @property
    def ratio_hi(self) -> float:
        return 2.0 / math.sqrt(self.a_lo)


def band_exact(order: int, mu: float) -> Band:
    """Region ``order`` along b = μa/2 from the exact characteristic values.

    References
    ----------
    Yaglinskyi et al. 2017, eq. (6) and Fig. 7 (segments M1M2, L1L2 read graphically);
    characteristic values: :func:`characteristic_value`.
    """
    lo = _on_line(lambda q: characteristic_value("b", order, q), order, mu)
    hi = _on_line(lambda q: characteristic_value("a", order, q), order, mu)
    return Band(order, lo, hi)


def band_series(order: int, mu: float) -> Band:
    """Region ``order`` (1 to 3) along b = μa/2 from paper B's series (8)."""
    lo = _on_line(lambda q: series_boundaries(order, q)[0], order, mu)
    hi = _on_line(lambda q: series_boundaries(order, q)[1], order, mu)
    return Band(order, lo, hi)


def band_linear(mu: float) -> Band:
    """First region by the two-term harmonic balance a = 1 ± b on b = μa/2:
    a = 1/(1 + μ/2) … 1/(1 − μ/2).

    References
    ----------
    Yaglinskyi et al. 2017, eq. (7) and the boundaries a^П = 1 + b, a^Л = 1 − b.
    """
    return Band(1, 1.0 / (1.0 + 0.5 * mu), 1.0 / (1.0 - 0.5 * mu))


def stability_chart(max_order: int, b_max: float, points: int) -> dict[str, list[float]]:
    """Ince-Strutt chart as data: the b grid and, for each order, the boundary curves.

    Returns ``{"b": [...], "a0": [...], "b1": [...], "a1": [...], …}`` where ``b<n>`` and
    ``a<n>`` are the characteristic values b_n, a_n on the grid (region n lies between them).

    References
    ----------
    Mathieu characteristic values (:func:`characteristic_value`); Yaglinskyi et al. 2017,
    Fig. 7.
    """
    grid = [b_max * i / (points - 1) for i in range(points)]
    chart: dict[str, list[float]] = {"b": grid,
                                     "a0": [characteristic_value("a", 0, q) for q in grid]}
    for n in range(1, max_order + 1):
        chart[f"b{n}"] = [characteristic_value("b", n, q) for q in grid]
        chart[f"a{n}"] = [characteristic_value("a", n, q) for q in grid]
    return chart


# ----------------------------------------------------------------- Floquet: stepwise stiffness


def _segment_matrix(theta: float, w: float) -> tuple[float, float, float, float]:
    c, s = math.cos(theta), math.sin(theta)
    return c, s / w, -w * s, c


def stepwise_trace(segments: list[tuple[float, float]], ratio: float) -> float:
    """Trace of the monodromy matrix of q̈ + k0²·N(t)/N̄·q = 0 over one mesh period, for a
    piecewise-constant pair count N(t).

    Within a segment of duration w·T (T = 1/f_m) the solution is harmonic with
    ω_j = 2πk0·√(N_j/N̄); the transfer matrix is [[cos θ, sin θ/ω], [−ω sin θ, cos θ]] with
    θ_j = ω_j w_j T = 2π w_j √(N_j/N̄)/r, r = f_m/k0.  The motion is unstable where
    |tr M| > 2.  For two levels this is the Meissner equation (paper B, eq. (9)).

    Parameters
    ----------
    segments : (w_j, N_j) pieces of one period (Σw = 1); ratio : r = f_m/k0 [-].

    References
    ----------
    Yaglinskyi et al. 2017, eq. (9) ("method of matching" the piecewise solutions); Floquet
    theory (monodromy matrix).
    """
    mean = sum(w * n for w, n in segments)
    m00, m01, m10, m11 = 1.0, 0.0, 0.0, 1.0
    for w, n in segments:
        om = math.sqrt(n / mean)
        a, b, c, d = _segment_matrix(2.0 * math.pi * w * om / ratio, om)
        m00, m01, m10, m11 = (a * m00 + b * m10, a * m01 + b * m11,
                              c * m00 + d * m10, c * m01 + d * m11)
    return m00 + m11


def stepwise_band(segments: list[tuple[float, float]], ratio0: float, width: float,
                  samples: int = 400) -> tuple[float, float] | None:
    """Unstable interval of r = f_m/k0 near ``ratio0`` for a stepwise stiffness.

    Samples r over ratio0·(1 ± width), takes the unstable run (|tr M| > 2) nearest to ratio0
    and refines both ends by bisection.  None when no sample is unstable (the region, if
    any, is narrower than the sampling step).
    """
    lo_r, hi_r = ratio0 * (1.0 - width), ratio0 * (1.0 + width)
    rs = [lo_r + (hi_r - lo_r) * i / (samples - 1) for i in range(samples)]
    unstable = [abs(stepwise_trace(segments, r)) > 2.0 for r in rs]
    idx = [i for i, u in enumerate(unstable) if u]
    if not idx:
        return None
    centre = min(idx, key=lambda i: abs(rs[i] - ratio0))
    i0 = centre
    while i0 > 0 and unstable[i0 - 1]:
        i0 -= 1
    i1 = centre
    while i1 < samples - 1 and unstable[i1 + 1]:
        i1 += 1

    def edge(stable: float, unst: float) -> float:
        for _ in range(60):
            mid = 0.5 * (stable + unst)
            if abs(stepwise_trace(segments, mid)) > 2.0:
                unst = mid
            else:
                stable = mid
        return 0.5 * (stable + unst)

    left = rs[i0] if i0 == 0 else edge(rs[i0 - 1], rs[i0])
    right = rs[i1] if i1 == samples - 1 else edge(rs[i1 + 1], rs[i1])
    return left, right
